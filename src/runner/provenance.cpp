// Provenance attributes of result files (DESIGN.md): version, commit, compiler, libraries, host.
#include <hdf5.h>
#include <unistd.h>

#include <Eigen/Core>
#include <string>
#include <toml++/toml.h>

#include "runner/git_commit.hpp"
#include "runner/store.hpp"

namespace creaturelab::runner {
namespace {

// Baked in at build time (git_commit.cmake): reading the checkout's HEAD when a point runs named
// whatever commit the checkout had moved to since the build, and never said that it was modified.
std::string gitCommit() { return CREATURELAB_GIT_COMMIT; }

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
  static const std::vector<std::string> names = {"creaturelab_version", "git_commit", "compiler", "libraries",
                                                 "host", "started", "finished", "wall_time_s", "experiment"};
  return names;
}

}  // namespace creaturelab::runner
