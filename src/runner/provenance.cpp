// Provenance attributes of result files (DESIGN.md): version, commit, compiler, libraries, host;
// and of a run folder's index.h5 (provenance.hpp): build type, machine, start and wall time.
#include "runner/provenance.hpp"

#include <hdf5.h>
#include <unistd.h>

#include <Eigen/Core>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <toml++/toml.h>

#include "core/text.hpp"
#include "io/hdf5.hpp"
#include "runner/git_commit.hpp"
#include "runner/store.hpp"

namespace creaturelab::runner {
namespace fs = std::filesystem;
namespace {

// Baked in at build time (git_commit.cmake): reading the checkout's HEAD when a point runs named
// whatever commit the checkout had moved to since the build, and never said that it was modified.
std::string gitCommit() { return CREATURELAB_GIT_COMMIT; }

// CMAKE_BUILD_TYPE, set on this file alone by src/runner/CMakeLists.txt.
std::string buildType() {
  const std::string type = CREATURELAB_BUILD_TYPE;
  return type.empty() ? "unknown" : type;
}

std::string readCpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::stringstream text;
  text << in.rdbuf();
  return cpuModelFromCpuinfo(text.str());
}

}  // namespace

Provenance collectProvenance() {
  unsigned h5_major = 0, h5_minor = 0, h5_release = 0;
  H5get_libversion(&h5_major, &h5_minor, &h5_release);
  char host[256] = "unknown";
  gethostname(host, sizeof host - 1);
  const std::string libraries = "hdf5 " + std::to_string(h5_major) + "." + std::to_string(h5_minor) + "." +
                                std::to_string(h5_release) + ", eigen " + std::to_string(EIGEN_WORLD_VERSION) + "." +
                                std::to_string(EIGEN_MAJOR_VERSION) + "." + std::to_string(EIGEN_MINOR_VERSION) +
                                ", toml++ " + std::to_string(TOML_LIB_MAJOR) + "." + std::to_string(TOML_LIB_MINOR) +
                                "." + std::to_string(TOML_LIB_PATCH);
  return {{"creaturelab_version", CREATURELAB_VERSION},
          {"git_commit", gitCommit()},
          {"compiler", std::string("gcc ") + __VERSION__},
          {"libraries", libraries},
          {"host", host}};
}

const std::vector<std::string>& provenanceAttributeNames() {
  // "experiment" is the path as typed (./x.toml and x.toml are the same experiment).
  static const std::vector<std::string> names = {
      "creaturelab_version", "git_commit", "compiler", "libraries", "host", "started", "finished", "wall_time_s",
      "experiment", "build_type", "cpu_model", "cpu_cores", "started_utc", "wall_s"};
  return names;
}

std::string cpuModelFromCpuinfo(const std::string& cpuinfo) {
  std::istringstream lines(cpuinfo);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    const auto begin = line.find_first_not_of(" \t", colon + 1);
    if (begin == std::string::npos) continue;
    return line.substr(begin, line.find_last_not_of(" \t\r") + 1 - begin);
  }
  return "unknown";
}

RunProvenance startRunProvenance() {
  RunProvenance p;
  p.build_type = buildType();
  p.cpu_model = readCpuModel();
  p.cpu_cores = int(std::thread::hardware_concurrency());
  p.started_utc = core::isoTimeUtcNow();
  p.start = std::chrono::steady_clock::now();
  return p;
}

void writeRunProvenance(const std::string& index_path, const RunProvenance& p) {
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - p.start).count();
  const std::string tmp_path = index_path + ".tmp";
  try {
    fs::copy_file(index_path, tmp_path, fs::copy_options::overwrite_existing);
    io::File file = io::File::openReadWrite(tmp_path);
    {
      const io::Group root = file.root();
      io::setAttr(root, "build_type", p.build_type);
      io::setAttr(root, "cpu_model", p.cpu_model);
      io::setAttr(root, "cpu_cores", std::int64_t(p.cpu_cores));
      io::setAttr(root, "started_utc", p.started_utc);
      io::setAttr(root, "wall_s", wall_s);
    }
    file.close();  // seals the copy
    fs::rename(tmp_path, index_path);
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp_path, ec);
    throw;
  }
}

}  // namespace creaturelab::runner
