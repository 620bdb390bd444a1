#pragma once
// Internal helpers shared by the hdf5_*.cpp files; not part of the public API.
// Every function here expects the caller to hold lockHdf5().

#include "io/hdf5_error.hpp"
#include "io/hdf5_handle.hpp"

#include <hdf5.h>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace creaturelab::io::detail {

// Switches off HDF5's automatic error printing (once per process).
void silenceHdf5Errors();

// HDF5's innermost error description from the default stack, then clears the stack.
std::string takeHdf5Message();

std::string fileNameOf(hid_t id);    // "" when unknown
std::string objectPathOf(hid_t id);  // "/a/b"; "" when unknown
std::string childPath(hid_t parent, std::string_view name);  // objectPathOf(parent) + "/" + name

// Throws Hdf5Error: `HDF5: cannot <what> "<object>" in file "<file>": <hdf5 message>`,
// or `HDF5: cannot <what> file "<file>": ...` when object is empty.
[[noreturn]] void fail(std::string_view what, std::string_view object, std::string_view file);
// As fail(), naming the child `name` of `parent` (parent itself when name is empty) and
// parent's file. A non-empty `reason` replaces HDF5's message (for our own checks).
[[noreturn]] void failAt(hid_t parent, std::string_view name, std::string_view what, std::string_view reason = {});

// Returns `result` when it is non-negative, else failAt(parent, name, what).
template <class T>
T check(T result, hid_t parent, std::string_view name, std::string_view what) {
  if (result < 0) failAt(parent, name, what);
  return result;
}

// Property lists with object time tracking off (reproducible files).
Handle groupCreateProps();
Handle datasetCreateProps();
Handle linkCreateProps();       // UTF-8 link names
Handle attributeCreateProps();  // UTF-8 attribute names

// Datatypes: variable-length UTF-8 string; h5py's boolean enum (int8, FALSE=0, TRUE=1).
Handle utf8StringType();
Handle boolEnumType();
bool isBoolEnum(hid_t type);

Handle dataspaceOf(const std::vector<hsize_t>& dims);  // scalar when dims is empty
std::vector<hsize_t> extentOf(hid_t dataspace);      // empty for scalar
hsize_t elementCount(const std::vector<hsize_t>& dims);

// Reads all strings of a dataset or attribute whose file type is a string (variable or
// fixed length). `read(memory_type, buffer)` performs the H5Dread/H5Aread and throws on
// failure.
std::vector<std::string> readStrings(hid_t file_type, hid_t space, const std::function<void(hid_t, void*)>& read);

}  // namespace creaturelab::io::detail
