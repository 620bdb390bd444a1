# benchmarks for ib: locate + spread + interpolate of 80 markers on a 100 × 100 grid, both kernels.
creaturelab_bench(bench_ib
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_ib.cpp
  LIBS cl_ib
)
