# tests for unit/ib: immersed-boundary kernels and transfer (each test well under 1 s), also run under ASan/UBSan.
creaturelab_test(ib_unit_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/ib_kernel_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/ib_transfer_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/ib_coupling_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/ib_banded_lu_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/ib_reused_banded_solve_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/ib_membrane_run_test.cpp
  LIBS cl_ib
)
