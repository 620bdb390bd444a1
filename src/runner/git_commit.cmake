# Writes OUT, a header naming the commit the build is made from: the checkout's HEAD, with "+dirty"
# when tracked files differ from it, or "unknown" without git. cl_git_commit runs this at every build
# (src/runner/CMakeLists.txt) and the header changes only when that name does, so a point file's
# git_commit (provenance.cpp) is the binary's commit, not whatever the checkout holds when it runs.
execute_process(COMMAND git -C "${SOURCE_DIR}" rev-parse HEAD
                OUTPUT_VARIABLE commit RESULT_VARIABLE failed OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(failed OR commit STREQUAL "")
  set(commit "unknown")
else()
  execute_process(COMMAND git -C "${SOURCE_DIR}" status --porcelain --untracked-files=no
                  OUTPUT_VARIABLE changes RESULT_VARIABLE failed ERROR_QUIET)
  if(failed)
    set(commit "${commit}+unknown-status")
  elseif(NOT changes STREQUAL "")
    set(commit "${commit}+dirty")
  endif()
endif()
file(WRITE "${OUT}.tmp" "#pragma once\n#define CREATURELAB_GIT_COMMIT \"${commit}\"\n")
execute_process(COMMAND "${CMAKE_COMMAND}" -E copy_if_different "${OUT}.tmp" "${OUT}")
file(REMOVE "${OUT}.tmp")
