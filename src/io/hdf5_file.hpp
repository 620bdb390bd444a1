#pragma once
// An open HDF5 file.

#include "io/hdf5_handle.hpp"
#include "io/hdf5_object.hpp"

#include <filesystem>
#include <string>

namespace creaturelab::io {

class File {
public:
  // Creates (truncating) a file for writing. Groups and datasets carry no creation or
  // modification times, so identical content gives identical bytes; the format is that of
  // HDF5 1.8 or later (library version bounds V18..latest).
  static File create(const std::filesystem::path& path);
  static File openReadOnly(const std::filesystem::path& path);
  static File openReadWrite(const std::filesystem::path& path);

  File() = default;
  Group root() const;
  void flush() const;
  // Closes the file now. Throws if groups, datasets or attributes of it are still open
  // (HDF5 would otherwise keep the file open behind the caller's back, e.g. across a
  // rename). The destructor closes quietly.
  void close();

  const std::filesystem::path& path() const noexcept { return path_; }
  hid_t id() const noexcept { return handle_.id(); }
  bool isOpen() const noexcept { return handle_.valid(); }

private:
  File(Handle handle, std::filesystem::path path) : handle_(std::move(handle)), path_(std::move(path)) {}

  Handle handle_;
  std::filesystem::path path_;
};

}  // namespace creaturelab::io
