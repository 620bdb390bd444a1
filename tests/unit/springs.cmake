# tests for unit/springs: fast checks (each well under 1 s), also run under ASan/UBSan.
creaturelab_test(springs_unit_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/springs_network.cpp
    ${CMAKE_CURRENT_LIST_DIR}/springs_forces_fd.cpp
    ${CMAKE_CURRENT_LIST_DIR}/springs_stability.cpp
    ${CMAKE_CURRENT_LIST_DIR}/springs_settling.cpp
    ${CMAKE_CURRENT_LIST_DIR}/springs_provot.cpp
    ${CMAKE_CURRENT_LIST_DIR}/springs_unary_forces.cpp
    ${CMAKE_CURRENT_LIST_DIR}/springs_equilibrium_small.cpp
  LIBS cl_springs
)
