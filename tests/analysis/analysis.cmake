# tests for analysis/: the figures' house style (label "analysis"). figures.sh makes small runs with
# the built binary and checks every figure module and plotter of analysis/ drawn on them.
add_test(NAME analysis_figures
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/analysis/figures.sh $<TARGET_FILE:creaturelab> ${PROJECT_SOURCE_DIR}
                 ${CMAKE_BINARY_DIR}/analysis/figures)
set_tests_properties(analysis_figures PROPERTIES LABELS analysis TIMEOUT 600)
