# tests for unit/coupling3d: the 3-D immersed-boundary transfer (exact linear interpolation, force and
# torque kept, adjointness), surface markers, and MuJoCo bodies coupled to the 3-D fluid (momentum
# balance, Galilean invariance, the leak through a moving body). Also run under ASan/UBSan.
creaturelab_test(coupling3d_unit_tests unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/coupling3d_transfer_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/coupling3d_markers_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/coupling3d_coupling_test.cpp
  LIBS cl_coupling3d)
# the controller over the 3-D fluid with the coupled solve (Forcing3::coupled): servo held, passive joint
# free, bitwise the same for 1 and 2 evaluation threads (Release only: coupled 3-D steps)
creaturelab_test(coupling3d_controller_test physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/coupling3d_controller_test.cpp
  LIBS cl_control)
