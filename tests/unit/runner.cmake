# tests for unit/runner: experiment files, checks, baselines, the run folder on disk (no solver
# runs; each well under 1 s).
creaturelab_test(runner_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/runner_experiment.cpp
    ${CMAKE_CURRENT_LIST_DIR}/runner_experiment_base.cpp
    ${CMAKE_CURRENT_LIST_DIR}/runner_checks.cpp
    ${CMAKE_CURRENT_LIST_DIR}/runner_compare.cpp
    ${CMAKE_CURRENT_LIST_DIR}/runner_store.cpp
    ${CMAKE_CURRENT_LIST_DIR}/runner_lock.cpp
    ${CMAKE_CURRENT_LIST_DIR}/runner_sweep_size.cpp
  LIBS cl_runner
)
target_compile_definitions(runner_test PRIVATE CREATURELAB_TEST_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
