# tests for physics/web: the default orb web settles (thesis §5.1: "settling time ... around 5 to 10
# seconds") and its static equilibrium converges. The RK4 settle takes ~10 s of wall time in Release.
creaturelab_test(web_physics_test physics
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/web_settle_test.cpp
  LIBS cl_web
)
