# tests for physics/flesh: the flesh as the 3-D fluid's boundary, the leak through a moving flesh-wrapped
# sphere (and its breaking test without forcing). About 5 s of CPU.
creaturelab_test(flesh_physics_tests physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/flesh_fluid_leak_test.cpp
  LIBS cl_coupling3d cl_flesh)
