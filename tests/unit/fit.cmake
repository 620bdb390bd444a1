# tests for unit/fit: the contraction-spline fit (recovery, coverage of the reported uncertainty,
# robust losses, period detection, bad input) and the controller fit on a cheap closed-form kind
# (optimum, determinism across thread counts, resume, bad controller files). A few seconds in all.
creaturelab_test(fit_unit_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/fit_spline_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fit_controller_test.cpp
  LIBS cl_fit cl_runner
)
target_include_directories(fit_unit_test PRIVATE ${CMAKE_CURRENT_LIST_DIR})
target_compile_definitions(fit_unit_test PRIVATE CREATURELAB_TEST_SOURCE_DIR="${PROJECT_SOURCE_DIR}")

# physics: fitting the curve to a simulated jellyfish (one short run on the 100² grid, about 1 s).
creaturelab_test(fit_jellyfish_test physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/fit_jellyfish_test.cpp
  LIBS cl_fit
)

# cli: tests/cli/fit.sh drives `creaturelab fit spline` and `fit controller` end to end (~20 s).
add_test(NAME cli_fit COMMAND bash ${PROJECT_SOURCE_DIR}/tests/cli/fit.sh $<TARGET_FILE:creaturelab>
                              ${PROJECT_SOURCE_DIR} ${CMAKE_BINARY_DIR}/cli/fit)
set_tests_properties(cli_fit PROPERTIES LABELS cli TIMEOUT 300)
