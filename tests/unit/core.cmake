# tests for unit/core
creaturelab_test(core_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/core_sha256.cpp
    ${CMAKE_CURRENT_LIST_DIR}/core_rng.cpp
    ${CMAKE_CURRENT_LIST_DIR}/core_text.cpp
    ${CMAKE_CURRENT_LIST_DIR}/core_improved_noise.cpp
  LIBS cl_core
)
# The sanitizer tree's probes: undefined behaviour on purpose, so only where the sanitizers stop it.
if(CREATURELAB_SANITIZE)
  target_sources(core_test PRIVATE ${CMAKE_CURRENT_LIST_DIR}/core_sanitizer_probe.cpp)
endif()
