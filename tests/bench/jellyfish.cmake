# Google Benchmark programs for the swimming jellyfish
creaturelab_bench(bench_jellyfish SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_jellyfish.cpp LIBS cl_kinds cl_jellyfish)
