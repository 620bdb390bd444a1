# tests for physics/jellyfish: the swimmer (bell + muscles + fluid, immersed-boundary coupled) on
# short runs: determinism, mirror symmetry, contraction depth, energy, stability, step convergence;
# the force at the step's middle over a whole window on 100²; and the stagger comparison on the
# resolved 200² grid. About 60 s in Release on one core.
creaturelab_test(jellyfish_physics_test physics
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/jellyfish_swim_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/jellyfish_stagger_test.cpp
  LIBS cl_jellyfish
)
