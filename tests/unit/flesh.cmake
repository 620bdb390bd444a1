# tests for unit/flesh: the flesh's mesh, its backward Euler step against held, free and MuJoCo-driven
# skeletons, and its .glb skin. Each program well under 1 s; also run under ASan/UBSan.
creaturelab_test(flesh_unit_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/flesh_mesh_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/flesh_dynamics_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/flesh_export_test.cpp
  LIBS cl_flesh cl_render
)
