# tests for physics/ib: the immersed-boundary membrane and the porous boundary (label physics; about 25 s in total on one core)
creaturelab_test(ib_physics_tests physics
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/ib_membrane_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/ib_porous_test.cpp
  LIBS cl_ib)
