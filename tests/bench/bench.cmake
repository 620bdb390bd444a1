# Google Benchmark programs: speed targets live here, never in timed unit tests.
function(creaturelab_bench name)
  cmake_parse_arguments(B "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${B_SOURCES})
  target_link_libraries(${name} PRIVATE ${B_LIBS} benchmark::benchmark_main)
endfunction()
include(bench/springs.cmake OPTIONAL)
include(bench/fluid.cmake OPTIONAL)
include(bench/web.cmake OPTIONAL)
