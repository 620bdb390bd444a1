# Unity builds: each target's sources compiled in batches of eight, so the templates they share
# (Eigen's decompositions and products, GoogleTest's) are instantiated once per batch rather than once
# per file. A batch is one translation unit: names in anonymous namespaces must differ across a
# target's files. Files with their own compile flags stay alone (CMake leaves them out itself).
# Arithmetic does not change: -ffp-contract=off holds in every batch; the golden digests check it.
option(CREATURELAB_UNITY "Compile each target's sources in batches (unity build)" ON)
if(CREATURELAB_UNITY)
  set(CMAKE_UNITY_BUILD ON)
  set(CMAKE_UNITY_BUILD_BATCH_SIZE 8)
  # gcc takes a batch's included .cpp files for headers and then warns that a class uses a type of
  # their anonymous namespace (-Wsubobject-linkage), which is right in a source file.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_compile_options(-Wno-subobject-linkage)
  endif()
endif()
