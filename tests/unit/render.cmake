# tests for unit/render: the jellyfish's render model (Rudolf & Mould 2009 §3.4-3.5): the 2-D slice
# (splines, thickness, degenerate outlines), the disc extrapolation (surfaces of revolution, closed
# oriented meshes), the variations of Eq. 2 and the exporters (.glb round trip with tinygltf, OBJ,
# XDMF, POV-Ray). Each test well under 1 s.
creaturelab_test(render_unit_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/render_slice_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/render_mesh_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/render_variation_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/render_export_test.cpp
  LIBS cl_render cl_io
)
# the render hook through the kind (kinds/render_hook.hpp): which kinds render, the jellyfish's hook
# against its renderer. Well under 1 s.
creaturelab_test(render_hook_test unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/render_hook_test.cpp
  LIBS cl_kinds cl_render
)
# A 3-D creature's render chain (Lentine et al. 2010 Figs. 11, 13): primitive geom meshes, the creature
# .glb reloaded by tinygltf. Well under 1 s.
creaturelab_test(render_creature_test unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/render_creature_test.cpp
  LIBS cl_render
)
# The 3-D run recorder's poses and Q against MuJoCo's and the fluid's: three coupled frames of a
# 16 x 8 x 12 box, about 1 s of CPU, so labelled physics (Release only) as control_fluid3_unit_test.
creaturelab_test(render_creature_record_test physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/render_creature_record_test.cpp
  LIBS cl_control
)
