#pragma once
// A content hash of an HDF5 file: equal for files holding equal data, whenever and
// however (contiguous or chunked, object times or not) they were written. The
// determinism tests compare it across --jobs and MPI rank counts.

#include <filesystem>
#include <string>
#include <vector>

namespace creaturelab::io {

// SHA-256 (hex) over, in sorted-name order from the root: every group (path, attributes),
// every dataset (path, type signature, shape, stored bytes; for variable-length strings
// their UTF-8 contents) and every attribute whose name is not in attr_names_to_skip
// (matched by name on any object: list the provenance attributes, e.g. "started").
// Soft and external links are hashed as their targets' names, not followed.
// Numbers are hashed as stored in the file (the file type, e.g. little-endian f64).
std::string contentDigest(const std::filesystem::path& path, const std::vector<std::string>& attr_names_to_skip);

}  // namespace creaturelab::io
