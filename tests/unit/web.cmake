# tests for unit/web: the orb-web construction (each test well under 1 s), also run under ASan/UBSan.
creaturelab_test(web_unit_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/web_geometry_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/web_params_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/web_build_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/web_sweeps_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/web_run_test.cpp
  LIBS cl_web
)
