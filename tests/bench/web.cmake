# benchmarks for web: build, settle and solve the default orb web and their speed targets.
creaturelab_bench(bench_web
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_web.cpp
  LIBS cl_web
)
