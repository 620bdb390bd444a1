# tests for unit/charlotte: the Charlotte's-web procedure of thesis ch. 6 on a small web (each test
# well under 1 s, also under ASan/UBSan): font, Netpbm reader, dilation, bands and scores, PNG,
# the inscription's properties, the kind's determinism and the runner writing its renders.
creaturelab_test(charlotte_unit_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/charlotte_image_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/charlotte_inscribe_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/charlotte_kind_test.cpp
  LIBS cl_charlotte cl_runner
)
