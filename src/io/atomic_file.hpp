#pragma once
// Writing a whole file so that readers see the old file or the new one, never a part: the bytes
// go to PATH.tmp (created exclusively, never through a symbolic link), are synced, and the
// temporary is renamed over PATH. On failure the temporary is removed and PATH is unchanged.
#include <filesystem>
#include <string_view>

namespace creaturelab::io {

// Throws std::runtime_error "<path>: cannot write: <reason>" (e.g. "No space left on device").
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace creaturelab::io
