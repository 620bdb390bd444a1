#pragma once
// Move-only owner of one HDF5 identifier.

#include <hdf5.h>

namespace creaturelab::io {

// Owns an hid_t and closes it with the matching H5?close for its type (file, group,
// dataset, dataspace, datatype, attribute, property list). Never wrap library constants
// such as H5T_NATIVE_DOUBLE or H5P_DEFAULT.
class Handle {
public:
  Handle() noexcept = default;
  explicit Handle(hid_t id) noexcept : id_(id) {}
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(other.release()) {}
  Handle& operator=(Handle&& other) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t id() const noexcept { return id_; }
  bool valid() const noexcept { return id_ >= 0; }
  explicit operator bool() const noexcept { return valid(); }
  hid_t release() noexcept {
    const hid_t id = id_;
    id_ = H5I_INVALID_HID;
    return id;
  }
  void reset() noexcept;  // closes (errors ignored: destructors must not throw)

private:
  hid_t id_ = H5I_INVALID_HID;
};

}  // namespace creaturelab::io
