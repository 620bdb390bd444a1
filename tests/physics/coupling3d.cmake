# tests for physics/coupling3d: MuJoCo bodies in the 3-D fluid against published and analytic cases
# (Stokes drag of a periodic array of spheres; the leak through a moving sphere).
creaturelab_test(coupling3d_physics_tests physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/coupling3d_sphere_test.cpp
  LIBS cl_coupling3d)
# the added-mass limit: a free sphere thrown through a closed box at density ratios 1 and 10, projected
# against coupled forcing (Lentine et al. 2010 Eq. 9)
creaturelab_test(coupling3d_added_mass_tests physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/coupling3d_added_mass_test.cpp
  LIBS cl_coupling3d)
# the retracted surface markers (marker_retraction_cells): a sphere's added mass against potential flow
creaturelab_test(coupling3d_retraction_tests physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/coupling3d_retraction_test.cpp
  LIBS cl_coupling3d)
