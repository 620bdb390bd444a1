# Google Benchmark program for the 3-D coupling: one coupled step at 32³ and 64³; the projected and the
# coupled forcing on a free sphere at 32³
creaturelab_bench(bench_coupling3d SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_coupling3d.cpp LIBS cl_coupling3d)
