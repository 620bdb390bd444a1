#include "io/hdf5_handle.hpp"

#include "io/hdf5_error.hpp"

namespace creaturelab::io {

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    reset();
    id_ = other.release();
  }
  return *this;
}

void Handle::reset() noexcept {
  if (id_ < 0) return;
  try {
    auto lock = lockHdf5();
    switch (H5Iget_type(id_)) {
      case H5I_FILE: H5Fclose(id_); break;
      case H5I_GROUP: H5Gclose(id_); break;
      case H5I_DATASET: H5Dclose(id_); break;
      case H5I_DATASPACE: H5Sclose(id_); break;
      case H5I_DATATYPE: H5Tclose(id_); break;
      case H5I_ATTR: H5Aclose(id_); break;
      case H5I_GENPROP_LST: H5Pclose(id_); break;
      default: H5Idec_ref(id_); break;
    }
    H5Eclear2(H5E_DEFAULT);
  } catch (...) {
    // Locking cannot realistically fail; a destructor must not throw.
  }
  id_ = H5I_INVALID_HID;
}

}  // namespace creaturelab::io
