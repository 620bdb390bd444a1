# tests for physics/web: the default orb web settles (thesis §5.1: "settling time ... around 5 to 10
# seconds") to its static equilibrium. The 20 s RK4 settle takes ~6 s of CPU time in Release.
creaturelab_test(web_physics_test physics
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/web_settle_test.cpp
  LIBS cl_web
)
