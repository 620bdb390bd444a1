# Google Benchmark program for the flesh: one backward Euler step of the swimmer's and the flyer's
# flesh at a few thousand vertices, with the skeleton in the solve and without.
creaturelab_bench(bench_flesh SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_flesh.cpp LIBS cl_flesh)
target_compile_definitions(bench_flesh PRIVATE CREATURELAB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
