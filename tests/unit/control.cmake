# tests for unit/rigid and unit/control: the MuJoCo face, Eq. 2 wind, the target servo under load,
# central-difference derivatives against an analytic objective, the strength limit, rigidified
# perturbations and determinism across thread counts. Each test well under 1 s; also
# run under ASan/UBSan.
creaturelab_test(control_unit_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/rigid_model_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/control_wind_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/control_controller_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/control_joints_test.cpp
  LIBS cl_control
)
# What a controller run measures in wind and fluid (control/run_measures.hpp, control/swimmer_run.hpp).
creaturelab_test(control_params_unit_test unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/control_run_measures_test.cpp
          ${CMAKE_CURRENT_LIST_DIR}/control_swimmer_run_test.cpp
  LIBS cl_control
)
# The controller over the 3-D coupled fluid (control/coupled_fluid3.hpp): determinism across thread
# counts with one fluid copy per evaluation, the snapshot's grid. Seconds of coupled 3-D steps, so
# labelled physics: Release only (the sanitizer tree's -O0 control library makes it 20 s).
creaturelab_test(control_fluid3_unit_test physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/control_fluid3_test.cpp
  LIBS cl_control
)
# The 3-D swimmer's rise (control/swimmer_run3.hpp): rise per cycle and its standard error, geom volumes.
creaturelab_test(control_swimmer3_unit_test unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/control_swimmer3_test.cpp
  LIBS cl_control
)
