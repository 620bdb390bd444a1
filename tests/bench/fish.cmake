# Google Benchmark programs for Tu's artificial fish: the step, the skin, a school.
creaturelab_bench(bench_fish SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_fish.cpp LIBS cl_fish)
