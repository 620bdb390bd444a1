# Precompiled headers: the standard library and Eigen (and GoogleTest for the test programs) are
# parsed once per build tree, by two owner targets compiled with the tree's common flags, instead
# of once per translation unit; every library and test program reuses them. Headers do not change
# arithmetic: results are those of a build without them (CREATURELAB_PCH=OFF).
#
# A target or source with its own instruction-set flags (-m..., e.g. the fluid library, the AVX2
# files of ib, the sampler test) takes none: a header precompiled without those flags is unusable
# there, and Eigen must not be compiled with them (CMakeLists.txt, AVX2). Nor does a target
# compiled with -pthread (charlotte, through pangocairo), whose _REENTRANT the compiler checks.
# This is decided when the directory is done, after its options and source properties are set.
option(CREATURELAB_PCH "Precompiled headers for the standard library, Eigen and GoogleTest" ON)

set(CREATURELAB_PCH_HEADERS
  <algorithm> <array> <cmath> <cstdint> <functional> <limits> <map> <memory> <optional> <set>
  <sstream> <stdexcept> <string> <string_view> <utility> <vector>
  <Eigen/Dense> <Eigen/SparseCore>)

if(CREATURELAB_PCH)
  set(anchor "${CMAKE_CURRENT_BINARY_DIR}/creaturelab_pch_anchor.cpp")
  if(NOT EXISTS "${anchor}")   # written once: a new time stamp would rebuild the owners
    file(WRITE "${anchor}" "// The precompiled headers' owner targets need one source.\n")
  endif()
  add_library(cl_pch_lib STATIC EXCLUDE_FROM_ALL "${anchor}")
  target_link_libraries(cl_pch_lib PRIVATE Eigen3::Eigen)
  target_precompile_headers(cl_pch_lib PRIVATE ${CREATURELAB_PCH_HEADERS})
  add_library(cl_pch_test STATIC EXCLUDE_FROM_ALL "${anchor}")
  target_link_libraries(cl_pch_test PRIVATE Eigen3::Eigen GTest::gtest)
  target_precompile_headers(cl_pch_test PRIVATE ${CREATURELAB_PCH_HEADERS} <gtest/gtest.h>)
  creaturelab_test_optimisation(cl_pch_test)  # as the test programs (CMakeLists.txt)
endif()

# True when compile options hold a flag the precompiled headers were not built with (-m..., -pthread).
function(_creaturelab_has_isa_flags out)
  set(found FALSE)
  foreach(option IN LISTS ARGN)
    if(option MATCHES "(^|[ ;>:])(-m|-pthread)")
      set(found TRUE)
    endif()
  endforeach()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

function(_creaturelab_apply_pch target kind)
  get_target_property(options ${target} COMPILE_OPTIONS)
  get_target_property(flags ${target} COMPILE_FLAGS)
  get_target_property(links ${target} LINK_LIBRARIES)
  foreach(link IN LISTS links)
    if(TARGET ${link})
      get_target_property(link_options ${link} INTERFACE_COMPILE_OPTIONS)
      list(APPEND options ${link_options})
    endif()
  endforeach()
  _creaturelab_has_isa_flags(isa "${options}" "${flags}")
  if(isa)
    return()
  endif()
  # A target compiled at the test programs' level (creaturelab_test_optimisation) takes their headers.
  get_target_property(test_opt ${target} CREATURELAB_TEST_OPT)
  if(kind STREQUAL "TEST" OR test_opt)
    target_precompile_headers(${target} REUSE_FROM cl_pch_test)
  else()
    target_precompile_headers(${target} REUSE_FROM cl_pch_lib)
  endif()
  # The precompiled headers' include paths, for a compiler that falls back to the header text.
  target_link_libraries(${target} PRIVATE Eigen3::Eigen)
  get_target_property(sources ${target} SOURCES)
  foreach(source IN LISTS sources)
    get_source_file_property(source_options ${source} COMPILE_OPTIONS)
    get_source_file_property(source_flags ${source} COMPILE_FLAGS)
    _creaturelab_has_isa_flags(isa "${source_options}" "${source_flags}")
    if(isa)
      set_source_files_properties(${source} PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
    endif()
  endforeach()
endfunction()

# creaturelab_precompile(TARGET LIB|TEST): reuse the precompiled headers, decided when the
# directory adding TARGET is done.
function(creaturelab_precompile target kind)
  if(CREATURELAB_PCH)
    cmake_language(EVAL CODE "cmake_language(DEFER CALL _creaturelab_apply_pch [[${target}]] [[${kind}]])")
  endif()
endfunction()
