# tests for the driven flyer (Lentine et al. 2010 §7.1): the stroke-following sense, the
# PD-driven wings in the coupled step, strength 0 holding, cycle means. Each test under a second.
creaturelab_test(flyer_unit_test unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/control_flyer_test.cpp
  LIBS cl_kinds
)
target_compile_definitions(flyer_unit_test PRIVATE CREATURELAB_TEST_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
