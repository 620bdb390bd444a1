# Google Benchmark program for the 3-D fluid solver
creaturelab_bench(bench_fluid3d SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_fluid3d.cpp LIBS cl_fluid3d)
