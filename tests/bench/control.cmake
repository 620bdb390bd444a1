# Google Benchmark programs for the creature controller: frames per second of the block
# and of a chain with 1-4 controlled joints, serial and parallel.
creaturelab_bench(bench_control SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_control.cpp LIBS cl_control)
target_compile_definitions(bench_control PRIVATE CREATURELAB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
