# Regression baselines: each results/baselines/*.json names a quick experiment; its metrics must
# stay within the baseline's tolerances.
file(GLOB baselines CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/results/baselines/*.json)
foreach(b ${baselines})
  get_filename_component(name ${b} NAME_WE)
  add_test(NAME regress_${name}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/regress/regress.sh $<TARGET_FILE:creaturelab>
                   ${PROJECT_SOURCE_DIR} ${b} ${CMAKE_BINARY_DIR}/regress/${name})
  set_tests_properties(regress_${name} PROPERTIES LABELS regress TIMEOUT 600)
endforeach()
