#pragma once
// Errors and locking for the HDF5 wrapper.

#include <mutex>
#include <stdexcept>
#include <string>

namespace creaturelab::io {

// Any failure of an HDF5 call. what() names the operation, the object path and the file,
// followed by HDF5's own innermost message, e.g.
//   HDF5: cannot open dataset "/metrics/speed" in file "run/p0.h5": object 'speed' doesn't exist
class Hdf5Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The process-wide lock that serialises all HDF5 calls (the library is not thread-safe).
// Recursive, so wrapper functions can call each other.
std::unique_lock<std::recursive_mutex> lockHdf5();

}  // namespace creaturelab::io
