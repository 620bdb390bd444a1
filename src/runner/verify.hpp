#pragma once
// `check` and `compare` read index.h5; before they believe it, each point file it lists is checked
// against the seal the index recorded when it was written (/integrity: the point id, the
// configuration fingerprint and the content digest of each point file). A truncated, garbage,
// swapped or rewritten point file is named instead of silently trusted. `--no-verify` skips this.
#include <string>
#include <vector>

#include "runner/store.hpp"

namespace creaturelab::runner {

// One line per damaged or missing point file, naming it and what is wrong; empty when all agree.
std::vector<std::string> verifyPointFiles(const std::string& dir, const StoredRun& run);

// Throws std::runtime_error (exit code 2 in the CLI) listing every problem of verifyPointFiles.
void requireVerifiedRun(const std::string& dir, const StoredRun& run);

}  // namespace creaturelab::runner
