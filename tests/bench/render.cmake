# Google Benchmark programs for the jellyfish's render model
creaturelab_bench(bench_render SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_render.cpp LIBS cl_jellyfish cl_render)
