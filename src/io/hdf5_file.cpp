#include "io/hdf5_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/file_seal.hpp"
#include "io/hdf5_detail.hpp"
#include "io/hdf5_error.hpp"

namespace creaturelab::io {
namespace {

Handle openFile(const std::filesystem::path& path, unsigned flags, const char* what) {
  requireIntactSeal(path);  // before libhdf5 reads a byte of it
  auto lock = lockHdf5();
  const hid_t id = H5Fopen(path.c_str(), flags, H5P_DEFAULT);
  if (id < 0) detail::fail(what, "", path.string());
  return Handle(id);
}

}  // namespace

File File::create(const std::filesystem::path& path) {
  // A file (or a symbolic link) of that name is removed, never written through: the new file is
  // created exclusively (O_EXCL), so a link planted meanwhile makes this fail instead.
  if (::unlink(path.c_str()) != 0 && errno != ENOENT)
    throw Hdf5Error("HDF5: cannot create file \"" + path.string() + "\": cannot remove the old one: " +
                    std::strerror(errno));
  auto lock = lockHdf5();
  // The root group is created with the file, so its time tracking is set on the file
  // creation list (a specialisation of the group creation list).
  Handle create_props(H5Pcreate(H5P_FILE_CREATE));
  H5Pset_obj_track_times(create_props.id(), false);
  H5Pset_userblock(create_props.id(), kSealBlockBytes);  // sealed by close() (io/file_seal.hpp)
  // V18 as the low bound: compact link storage and 1.8-style object headers, readable by
  // any HDF5 >= 1.8 (h5py included); V110 (= latest for 1.10) as the high bound.
  Handle access_props(H5Pcreate(H5P_FILE_ACCESS));
  H5Pset_libver_bounds(access_props.id(), H5F_LIBVER_V18, H5F_LIBVER_LATEST);
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_EXCL, create_props.id(), access_props.id());
  if (id < 0) detail::fail("create", "", path.string());
  return File(Handle(id), path, true);
}

File File::openReadOnly(const std::filesystem::path& path) {
  return File(openFile(path, H5F_ACC_RDONLY, "open (read-only)"), path);
}

File File::openReadWrite(const std::filesystem::path& path) {
  const bool sealed = checkSeal(path).state == SealState::intact;
  return File(openFile(path, H5F_ACC_RDWR, "open (read-write)"), path, sealed);
}

File::~File() {
  if (!handle_ || !seal_on_close_) return;  // handle_ closes it
  try {
    close();
  } catch (...) {
    // A destructor must not throw: the file stays unsealed, and readers refuse it.
  }
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
  if (seal_on_close_) sealFile(path_);
}

}  // namespace creaturelab::io
