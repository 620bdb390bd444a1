#include "io/hdf5_error.hpp"

#include "io/hdf5_detail.hpp"

#include <hdf5.h>

namespace creaturelab::io {
namespace {
// No clean-up of HDF5 at exit. When H5Fclose fails (the disk fills while the file is flushed),
// HDF5 1.10 keeps a half-closed file identifier, and its exit handler closes it a second time and
// crashes (SIGSEGV, exit 139). Every file this program writes is closed explicitly (File::close,
// Handle), so the exit handler has nothing to flush. H5dont_atexit only works before the library
// starts, so it runs during static initialisation, before main and any HDF5 call (this file is
// always linked: every HDF5 call takes lockHdf5()).
const bool kNoHdf5AtExit = (H5dont_atexit(), true);
}  // namespace

std::unique_lock<std::recursive_mutex> lockHdf5() {
  static std::recursive_mutex mutex;
  std::unique_lock<std::recursive_mutex> lock(mutex);
  detail::silenceHdf5Errors();
  return lock;
}

namespace detail {

void silenceHdf5Errors() {
  // Per thread: a thread-safe HDF5 keeps error-printing settings per thread, so a thread that
  // never silenced its own (the runner's main thread writing the index after the workers wrote
  // the points) would print HDF5's error stack to stderr.
  thread_local bool silenced = false;
  if (!silenced) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    silenced = true;
  }
}

}  // namespace detail
}  // namespace creaturelab::io
