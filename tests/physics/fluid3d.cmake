# tests for physics/fluid3d (label physics: analytic claims of the 3-D solver)
creaturelab_test(fluid3d_physics_tests physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/fluid3d_abc_test.cpp ${CMAKE_CURRENT_LIST_DIR}/fluid3d_inflow_channel_test.cpp
  LIBS cl_fluid3d)
