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
    ${CMAKE_CURRENT_LIST_DIR}/fluid_recorder_test.cpp
  LIBS cl_fluid)

# The sampler's two-, four- and eight-lane interpolations against its scalar path, bit for bit: built with the
# fluid library's instruction set (src/fluid/CMakeLists.txt), so that the four- and eight-lane halves are the code
# advection runs.
creaturelab_test(fluid_sampler_test unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/fluid_sampler_test.cpp
  LIBS cl_fluid)
target_compile_options(fluid_sampler_test PRIVATE ${CREATURELAB_FLUID_SIMD_FLAGS})
