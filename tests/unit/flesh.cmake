# tests for unit/flesh: the flesh's mesh, its backward Euler step against held, free and MuJoCo-driven
# skeletons, and its .glb skin. Each program well under 1 s; also run under ASan/UBSan.
creaturelab_test(flesh_unit_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/flesh_mesh_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/flesh_dynamics_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/flesh_export_test.cpp
  LIBS cl_flesh cl_render
)
# The flesh as the 3-D fluid's boundary (coupling3d/flesh_fluid_coupling3.hpp): momentum of fluid, flesh
# and bone, energy in a still fluid, bitwise snapshots, bad input. About 2 s of CPU in all.
creaturelab_test(flesh_fluid_unit_test unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/flesh_fluid_test.cpp
  LIBS cl_coupling3d cl_flesh
)
# The controller with the creature in flesh in the 3-D fluid: bitwise the same frames for any evaluation
# and fluid thread count, moved and placed perturbations. Seconds of coupled 3-D steps, so labelled
# physics (Release only), as control_fluid3_unit_test.
creaturelab_test(control_flesh_unit_test physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/control_flesh_test.cpp
  LIBS cl_control
)
# The flesh in the coupled solve (Forcing3::coupled): flesh as dense as the water stable where the staggered
# forcing grows, momentum of fluid, flesh and bone, bitwise snapshots and fluid threads, a flesh too thick
# refused. About 12 s of CPU, so labelled physics (Release only).
creaturelab_test(flesh_fluid_coupled_test physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/flesh_fluid_coupled_test.cpp
  LIBS cl_coupling3d cl_flesh
)
# The controller with the creature in flesh in the coupled solve: bitwise the same frames for any evaluation
# and fluid thread count. Seconds of coupled 3-D steps, so labelled physics (Release only).
creaturelab_test(control_flesh_coupled_test physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/control_flesh_coupled_test.cpp
  LIBS cl_control
)
