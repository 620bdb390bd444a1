#include "io/hdf5_error.hpp"

#include "io/hdf5_detail.hpp"

#include <hdf5.h>

namespace creaturelab::io {

std::unique_lock<std::recursive_mutex> lockHdf5() {
  static std::recursive_mutex mutex;
  std::unique_lock<std::recursive_mutex> lock(mutex);
  detail::silenceHdf5Errors();
  return lock;
}

namespace detail {

void silenceHdf5Errors() {
  static bool silenced = false;  // guarded by the HDF5 lock
  if (!silenced) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    silenced = true;
  }
}

}  // namespace detail
}  // namespace creaturelab::io
