# tests for unit/core
creaturelab_test(core_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/core_sha256.cpp
    ${CMAKE_CURRENT_LIST_DIR}/core_rng.cpp
    ${CMAKE_CURRENT_LIST_DIR}/core_text.cpp
    ${CMAKE_CURRENT_LIST_DIR}/core_improved_noise.cpp
  LIBS cl_core
)
