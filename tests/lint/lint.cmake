# Lints of the source tree (labels "lint" and "unit": cheap, they run in every tree).
# no_dates: no date in src/, tests/, experiments/; no ../shared path in src/, analysis/, experiments/.
add_test(NAME lint_no_dates COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/lint/no_dates.sh ${PROJECT_SOURCE_DIR})
# The lint can fail: it flags a date and a ../shared path in a scratch repository.
add_test(NAME lint_no_dates_self_test COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/lint/no_dates.sh --self-test)
set_tests_properties(lint_no_dates lint_no_dates_self_test PROPERTIES LABELS "lint;unit" TIMEOUT 60)
