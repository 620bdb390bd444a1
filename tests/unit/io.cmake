# tests for unit/io
creaturelab_test(io_test unit
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/io_hdf5.cpp
    ${CMAKE_CURRENT_LIST_DIR}/io_hdf5_attribute.cpp
    ${CMAKE_CURRENT_LIST_DIR}/io_hdf5_digest.cpp
    ${CMAKE_CURRENT_LIST_DIR}/io_file_seal.cpp
    ${CMAKE_CURRENT_LIST_DIR}/io_hdf5_h5py.cpp
    ${CMAKE_CURRENT_LIST_DIR}/io_cairo_image.cpp
    ${CMAKE_CURRENT_LIST_DIR}/io_xdmf.cpp
  LIBS cl_io cl_core
)
