// Files written by the wrapper read in h5py (the analysis side) with the right Python types.
#include "io/hdf5.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace io = creaturelab::io;
namespace fs = std::filesystem;

namespace {

constexpr const char* kPython = "/usr/bin/python3";  // DESIGN.md: Debian's python3 sees h5py

// Runs a shell command; returns its exit status and combined output.
std::pair<int, std::string> run(const std::string& command) {
  std::string output;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return {-1, "popen failed"};
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = ::pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

constexpr const char* kCheckScript = R"PY(
import sys
import h5py
import numpy as np

with h5py.File(sys.argv[1], "r") as f:
    a = f.attrs
    assert isinstance(a["title"], str) and a["title"] == "µg of jelly", repr(a["title"])
    assert isinstance(a["ok"], np.bool_) and bool(a["ok"]) is True, repr(type(a["ok"]))
    assert isinstance(a["off"], np.bool_) and bool(a["off"]) is False, repr(type(a["off"]))
    assert isinstance(a["n"], np.int64) and a["n"] == 7, repr(a["n"])
    assert isinstance(a["x"], np.float64) and a["x"] == 0.25, repr(a["x"])
    names = f["names"]
    info = h5py.check_string_dtype(names.dtype)
    assert info is not None and info.encoding == "utf-8" and info.length is None, repr(info)
    values = list(names.asstr()[()])
    assert values == ["distance_m", "µg", ""], repr(values)
    assert all(isinstance(v, str) for v in values)
    assert f["field"].shape == (2, 1, 3) and f["field"].chunks == (1, 1, 3), repr(f["field"].chunks)
    assert f["linked/x"][()].tolist() == [1.0, 2.0]
print("h5py ok")
)PY";

}  // namespace

TEST(Hdf5H5py, StringsAreStrAndBoolsAreNumpyBool) {
  if (run(std::string(kPython) + " -c 'import h5py, numpy'").first != 0) {
    GTEST_SKIP() << kPython << " cannot import h5py";
  }
  const fs::path dir = fs::temp_directory_path() / ("creaturelab_io_h5py_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    auto target = io::File::create(dir / "target.h5");
    io::writeVector(target.root(), "x", std::vector<double>{1.0, 2.0});
  }
  {
    auto f = io::File::create(dir / "check.h5");
    io::Group root = f.root();
    io::setAttr(root, "title", "µg of jelly");
    io::setAttr(root, "ok", true);
    io::setAttr(root, "off", false);
    io::setAttr(root, "n", std::int64_t{7});
    io::setAttr(root, "x", 0.25);
    io::writeVector(root, "names", std::vector<std::string>{"distance_m", "µg", ""});
    const double field[6] = {1, 2, 3, 4, 5, 6};
    io::writeArray(root, "field", field, {2, 1, 3}, std::vector<hsize_t>{1, 1, 3});
    io::createExternalLink(root, "linked", "target.h5", "/");
  }
  {
    std::ofstream script(dir / "check.py");
    script << kCheckScript;
  }
  const auto [status, output] = run(std::string(kPython) + " '" + (dir / "check.py").string() + "' '" +
                                    (dir / "check.h5").string() + "'");
  EXPECT_EQ(status, 0) << output;
  EXPECT_NE(output.find("h5py ok"), std::string::npos) << output;
  fs::remove_all(dir);
}
