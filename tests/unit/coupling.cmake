# tests for unit/coupling: MuJoCo bodies coupled to the 2-D fluid: momentum and angular
# momentum balance of the exchange, the leak through a held body in a stream, bad input; the
# controller in the fluid, bitwise the same for any thread count. Each test well under a few
# seconds; also run under ASan/UBSan.
creaturelab_test(coupling_unit_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/coupling_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/control_fluid_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/coupling_mouth_test.cpp
  LIBS cl_control
)
