# Google Benchmark program for the flesh: one backward Euler step of the swimmer's and the flyer's
# flesh at a few thousand vertices, with the skeleton in the solve and without.
creaturelab_bench(bench_flesh SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_flesh.cpp LIBS cl_flesh)
target_compile_definitions(bench_flesh PRIVATE CREATURELAB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
# The driven flyer wrapped in flesh in the 3-D fluid (flyer3d_flesh.toml's setting) against Fig. 14's 34 s
# per frame.
creaturelab_bench(bench_flesh_flyer3d SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_flesh_flyer3d.cpp LIBS cl_kinds cl_control)
target_compile_definitions(bench_flesh_flyer3d PRIVATE CREATURELAB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
# The aqueous swimmer wrapped in flesh in the 3-D fluid (swimmer3d.toml's setting, the flesh in the coupled solve)
# against Fig. 14's 83 s per frame.
creaturelab_bench(bench_flesh_swimmer3d SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_flesh_swimmer3d.cpp LIBS cl_kinds cl_control)
target_compile_definitions(bench_flesh_swimmer3d PRIVATE CREATURELAB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
