# benchmarks for springs: the 7,000-particle / 10,000-spring web (speed targets live here).
creaturelab_bench(bench_springs
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_springs.cpp
  LIBS cl_springs
)
