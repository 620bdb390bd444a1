# tests for unit/kinds: parameters declared once (kinds/describe.hpp) and the kinds built on them
# (no solver runs; each well under 1 s; also run under ASan/UBSan).
creaturelab_test(kinds_unit_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/kinds_describe_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/kinds_membrane_test.cpp
  LIBS cl_kinds
)
