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

# Golden digests: each tests/regress/golden/*.toml, a few seconds, bitwise against its committed .digest
# (tests/regress/golden.sh; UPDATE_GOLDEN=1 rewrites them).
file(GLOB goldens CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/regress/golden/*.toml)
foreach(g ${goldens})
  get_filename_component(name ${g} NAME_WE)
  add_test(NAME regress_golden_${name}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/regress/golden.sh $<TARGET_FILE:creaturelab>
                   ${PROJECT_SOURCE_DIR} ${CMAKE_BINARY_DIR}/regress/golden_${name} ${name})
  set_tests_properties(regress_golden_${name} PROPERTIES LABELS regress TIMEOUT 120)
endforeach()
