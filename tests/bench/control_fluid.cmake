# Google Benchmark program for the controller in the coupled fluid: frames per second of
# the block in a 128^2 stream, of a chain with 1-4 controlled joints, serial and parallel, and of the
# swimmer (swimmer.toml).
creaturelab_bench(bench_control_fluid SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_control_fluid.cpp LIBS cl_control)
target_compile_definitions(bench_control_fluid PRIVATE CREATURELAB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
# The driven flyer in the 3-D fluid (flyer3d.toml's setting) against Fig. 14's 3.2 s per frame.
creaturelab_bench(bench_control_fluid3d SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_control_fluid3d.cpp LIBS cl_kinds cl_control)
target_compile_definitions(bench_control_fluid3d PRIVATE CREATURELAB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
