#include "runner/verify.hpp"

#include <filesystem>

#include "io/hdf5.hpp"

namespace creaturelab::runner {
namespace fs = std::filesystem;

std::vector<std::string> verifyPointFiles(const std::string& dir, const StoredRun& run) {
  std::vector<std::string> problems;
  for (const auto& row : run.table.rows) {
    if (row.status == "missing") continue;
    const std::string path = dir + "/" + pointFileName(row.index);
    if (!fs::is_regular_file(path)) {
      problems.push_back(path + ": listed in index.h5 but missing");
      continue;
    }
    std::string config, stored_index_text;
    std::int64_t stored_index = -1;
    try {
      const io::File file = io::File::openReadOnly(path);
      const io::Group root = file.root();
      stored_index = io::getAttrInt64(root, "point_index");
      config = io::getAttrString(root, "config_sha256");
    } catch (const std::exception& e) {
      problems.push_back(path + ": not a readable point file (truncated or damaged): " + e.what());
      continue;
    }
    if (stored_index != row.index) {
      problems.push_back(path + ": holds point " + std::to_string(stored_index) + ", but index.h5 lists it as point " +
                         std::to_string(row.index) + " (files swapped or copied in)");
      continue;
    }
    const auto seal = run.seals.find(row.index);
    if (seal == run.seals.end()) continue;  // an index written before seals existed: the id is all we can check
    if (config != seal->second.config_sha256) {
      problems.push_back(path + ": made by another configuration than index.h5 records (config_sha256 " + config +
                         ", expected " + seal->second.config_sha256 + ")");
      continue;
    }
    std::string digest;
    try {
      digest = io::contentDigest(path, provenanceAttributeNames());
    } catch (const std::exception& e) {
      problems.push_back(path + ": cannot be read whole (truncated or damaged): " + e.what());
      continue;
    }
    if (digest != seal->second.content_sha256)
      problems.push_back(path + ": its content differs from what index.h5 recorded (damaged or rewritten after the run)");
  }
  return problems;
}

void requireVerifiedRun(const std::string& dir, const StoredRun& run) {
  const auto problems = verifyPointFiles(dir, run);
  if (problems.empty()) return;
  std::string message = "run folder " + dir + ": " + std::to_string(problems.size()) +
                        " point file(s) do not match index.h5 (--no-verify skips this check):";
  for (const auto& p : problems) message += "\n  " + p;
  throw std::runtime_error(message);
}

}  // namespace creaturelab::runner
