#pragma once
// creaturelab::io HDF5 wrapper: include this for the whole API.
//
//   auto file = io::File::create("point_0003.h5.tmp");
//   io::Group series = file.root().requireGroup("timeseries");
//   io::setAttr(io::writeVector(series, "time_s", times), "unit", "s");
//   io::setAttr(file.root(), "kind", "jellyfish");
//   file.close();                                   // then rename
//
// Thread safety: Debian's HDF5 1.10 is serial and not thread-safe. Every function here
// (and every handle close) holds the process-wide lock from lockHdf5(), so the wrapper
// may be used from several threads; code that calls the HDF5 C API directly on an id()
// must hold lockHdf5() itself.
//
// Const-ness: File, Group and Dataset are handles, like pointers; `const` protects the
// handle, not the file contents, so writers accept `const Group&` (and temporaries).

#include "io/hdf5_attribute.hpp"  // IWYU pragma: export
#include "io/hdf5_columns.hpp"    // IWYU pragma: export
#include "io/hdf5_dataset.hpp"    // IWYU pragma: export
#include "io/hdf5_digest.hpp"     // IWYU pragma: export
#include "io/hdf5_error.hpp"      // IWYU pragma: export
#include "io/hdf5_file.hpp"       // IWYU pragma: export
#include "io/hdf5_handle.hpp"     // IWYU pragma: export
#include "io/hdf5_object.hpp"     // IWYU pragma: export
