# Lints of the source tree (labels "lint" and "unit": cheap, they run in every tree).
# no_dates: no date in src/, tests/, experiments/; no ../shared path in src/, analysis/, experiments/.
add_test(NAME lint_no_dates COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/lint/no_dates.sh ${PROJECT_SOURCE_DIR})
# The lint can fail: it flags a date and a ../shared path in a scratch repository.
add_test(NAME lint_no_dates_self_test COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/lint/no_dates.sh --self-test)
set_tests_properties(lint_no_dates lint_no_dates_self_test PROPERTIES LABELS "lint;unit" TIMEOUT 60)
# docs/kinds.md is what `creaturelab list` prints now (scripts/kinds_doc.py --check prints the diff and how
# to regenerate it). Only where the tree builds the executable.
if(TARGET creaturelab)
  add_test(NAME lint_kinds_doc
           COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/kinds_doc.py $<TARGET_FILE:creaturelab>
                   --check ${PROJECT_SOURCE_DIR}/docs/kinds.md)
  set_tests_properties(lint_kinds_doc PROPERTIES LABELS lint TIMEOUT 60)
endif()
