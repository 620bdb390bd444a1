# tests for unit/fish: Tu's artificial fish (spring-mass body, semi-implicit step, water force,
# motor controllers, NURBS skin). Each test well under 1 s; also run under ASan/UBSan.
creaturelab_test(fish_unit_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/fish_solver_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fish_motor_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fish_measure_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fish_skin_test.cpp
  LIBS cl_fish
)
