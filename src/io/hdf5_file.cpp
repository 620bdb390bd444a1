#include "io/hdf5_file.hpp"

#include "io/hdf5_detail.hpp"
#include "io/hdf5_error.hpp"

namespace creaturelab::io {
namespace {

Handle openFile(const std::filesystem::path& path, unsigned flags, const char* what) {
  auto lock = lockHdf5();
  const hid_t id = H5Fopen(path.c_str(), flags, H5P_DEFAULT);
  if (id < 0) detail::fail(what, "", path.string());
  return Handle(id);
}

}  // namespace

File File::create(const std::filesystem::path& path) {
  auto lock = lockHdf5();
  // The root group is created with the file, so its time tracking is set on the file
  // creation list (a specialisation of the group creation list).
  Handle create_props(H5Pcreate(H5P_FILE_CREATE));
  H5Pset_obj_track_times(create_props.id(), false);
  // V18 as the low bound: compact link storage and 1.8-style object headers, readable by
  // any HDF5 >= 1.8 (h5py included); V110 (= latest for 1.10) as the high bound.
  Handle access_props(H5Pcreate(H5P_FILE_ACCESS));
  H5Pset_libver_bounds(access_props.id(), H5F_LIBVER_V18, H5F_LIBVER_LATEST);
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, create_props.id(), access_props.id());
  if (id < 0) detail::fail("create", "", path.string());
  return File(Handle(id), path);
}

File File::openReadOnly(const std::filesystem::path& path) {
  return File(openFile(path, H5F_ACC_RDONLY, "open (read-only)"), path);
}

File File::openReadWrite(const std::filesystem::path& path) {
  return File(openFile(path, H5F_ACC_RDWR, "open (read-write)"), path);
}

Group File::root() const {
  auto lock = lockHdf5();
  const hid_t id = H5Gopen2(handle_.id(), "/", H5P_DEFAULT);
  if (id < 0) detail::fail("open root group", "/", path_.string());
  return Group(Handle(id));
}

void File::flush() const {
  auto lock = lockHdf5();
  if (H5Fflush(handle_.id(), H5F_SCOPE_LOCAL) < 0) detail::fail("flush", "/", path_.string());
}

void File::close() {
  auto lock = lockHdf5();
  if (!handle_) return;
  const ssize_t still_open = H5Fget_obj_count(
      handle_.id(), H5F_OBJ_DATASET | H5F_OBJ_GROUP | H5F_OBJ_DATATYPE | H5F_OBJ_ATTR | H5F_OBJ_LOCAL);
  if (still_open > 0) {
    throw Hdf5Error("HDF5: cannot close file \"" + path_.string() + "\": " + std::to_string(still_open) +
                    " group/dataset/attribute handle(s) opened through it are still alive");
  }
  if (H5Fclose(handle_.release()) < 0) detail::fail("close", "", path_.string());
}

}  // namespace creaturelab::io
