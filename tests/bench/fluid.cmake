# Google Benchmark programs for the fluid solver
creaturelab_bench(bench_fluid SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_fluid.cpp LIBS cl_fluid)
