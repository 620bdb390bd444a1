# tests for physics/jellyfish: the swimmer (bell + muscles + fluid, immersed-boundary coupled) on
# short runs: determinism, mirror symmetry, contraction depth, energy, stability, step convergence.
# About 40 s in Release on one core.
creaturelab_test(jellyfish_physics_test physics
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/jellyfish_swim_test.cpp
  LIBS cl_jellyfish
)
