# tests for physics/fluid (label physics: analytic and paper claims; < 90 s in total on one core)
creaturelab_test(fluid_physics_tests physics
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/fluid_taylor_green_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fluid_upwind_advection_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fluid_symmetry_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fluid_cavity_test.cpp
  LIBS cl_fluid)
