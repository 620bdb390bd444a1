# tests for unit/fluid3d (label unit: fast, also run under ASan/UBSan)
creaturelab_test(fluid3d_unit_tests unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/fluid3d_pressure_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fluid3d_stages_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fluid3d_threads_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fluid3d_inflow_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fluid3d_vorticity_test.cpp
  LIBS cl_fluid3d)
# the fluid3d kind on 8³ grids (about 0.1 s)
creaturelab_test(fluid3d_kind_tests unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/fluid3d_kind_test.cpp
  LIBS cl_kinds)
