# tests for unit/jellyfish: the activation curve, the parameters, the bell network and the body's
# forces and stiffness (Rudolf & Mould 2009 §3.1-3.3). Each test well under 1 s; also run under ASan/UBSan.
creaturelab_test(jellyfish_unit_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/jellyfish_curve_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/jellyfish_bell_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/jellyfish_body_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/jellyfish_active_test.cpp
  LIBS cl_jellyfish
)

# the jellyfish kind's parameters (kinds/jellyfish.hpp: declared once, read into the swimmer's structs,
# the rules across them) and its render settings. No solver runs; well under 1 s.
creaturelab_test(jellyfish_kind_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/jellyfish_kind_test.cpp
  LIBS cl_kinds
)
