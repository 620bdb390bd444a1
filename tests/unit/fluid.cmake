# tests for unit/fluid (label unit: fast, also run under ASan/UBSan)
creaturelab_test(fluid_unit_tests unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/fluid_params_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fluid_pressure_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fluid_stages_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fluid_solver_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fluid_threads_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fluid_fast_diffusion_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fluid_inflow_test.cpp
  LIBS cl_fluid)
