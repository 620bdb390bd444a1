#pragma once
// An open HDF5 file.

#include "io/hdf5_handle.hpp"
#include "io/hdf5_object.hpp"

#include <filesystem>
#include <string>

namespace creaturelab::io {

class File {
public:
  // Creates a file for writing, replacing (unlinking) one of that name and never following a
  // symbolic link. Groups and datasets carry no creation or modification times, so identical
  // content gives identical bytes; the format is that of HDF5 1.8 or later (library version
  // bounds V18..latest). The file starts with a 512-byte user block that close() fills with its
  // seal (io/file_seal.hpp).
  static File create(const std::filesystem::path& path);
  // Both refuse a file whose seal is broken (Hdf5Error naming it) before libhdf5 reads it.
  // openReadWrite keeps a sealed file sealed: close() writes its seal again.
  static File openReadOnly(const std::filesystem::path& path);
  static File openReadWrite(const std::filesystem::path& path);

  File() = default;
  File(File&&) noexcept = default;
  File& operator=(File&&) noexcept = default;
  // Closes a file still open; one that would be sealed by close() is closed and sealed the same
  // way, quietly (a file whose groups or datasets are still open is left unsealed).
  ~File();
  Group root() const;
  void flush() const;
  // Closes the file now. Throws if groups, datasets or attributes of it are still open
  // (HDF5 would otherwise keep the file open behind the caller's back, e.g. across a
  // rename). A file created here (or opened read-write with a seal) is sealed after it is
  // closed.
  void close();

  const std::filesystem::path& path() const noexcept { return path_; }
  hid_t id() const noexcept { return handle_.id(); }
  bool isOpen() const noexcept { return handle_.valid(); }

private:
  File(Handle handle, std::filesystem::path path, bool seal_on_close = false)
      : handle_(std::move(handle)), path_(std::move(path)), seal_on_close_(seal_on_close) {}

  Handle handle_;
  std::filesystem::path path_;
  bool seal_on_close_ = false;
};

}  // namespace creaturelab::io
