# tests for physics/springs: analytic answers and thesis claims (whole set well under 60 s in Release).
creaturelab_test(springs_physics_test physics
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/springs_convergence.cpp
    ${CMAKE_CURRENT_LIST_DIR}/springs_long_run.cpp
    ${CMAKE_CURRENT_LIST_DIR}/springs_divergence.cpp
    ${CMAKE_CURRENT_LIST_DIR}/springs_simulate.cpp
    ${CMAKE_CURRENT_LIST_DIR}/springs_equilibrium_settle.cpp
  LIBS cl_springs
)
