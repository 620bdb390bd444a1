#pragma once
// The verbs of the creaturelab command line. Each returns the process exit code.
#include <functional>
#include <toml++/toml.h>
#include <string>
#include <vector>

#include "kinds/kind.hpp"
#include "runner/cluster.hpp"
#include "runner/run.hpp"

namespace creaturelab::cli {

struct RunArgs {
  runner::RunOptions options;
  std::string slice;  // "i/N"
};

struct CompareArgs {
  std::string run, baseline;
  double rtol = 1e-9, atol = 0;
  bool all = false;
  bool no_verify = false;  // trust index.h5 without checking the point files against it
};

struct BaselineArgs {
  std::string run, output;
  double rtol = 1e-9, atol = 0;
};

struct ReproduceArgs {
  std::string list = "experiments/reproduce.toml";
  std::string out_root = "results/runs/reproduce";  // each experiment runs into OUT_ROOT/<name>
  int jobs = 0;
};

class Commands {
 public:
  explicit Commands(const runner::Cluster& cluster);
  // Runs a verb; a user error (bad file, bad folder) is printed and becomes exit code 2.
  int guard(const std::function<int()>& verb) const;

  int run(const RunArgs& args) const;
  int list(const std::string& kind) const;
  int show(const std::string& file, const std::vector<std::string>& overrides) const;
  int check(const std::string& run_dir, bool verify) const;
  int compare(const CompareArgs& args) const;
  int baseline(const BaselineArgs& args) const;
  int digest(const std::string& run_dir) const;
  int reproduce(const ReproduceArgs& args) const;

 private:
  bool primary() const { return cluster_.rank() == 0; }
  void printReport(const runner::RunReport& report) const;
  int reproduceRenders(const toml::table& list, const std::string& file, const std::string& out_root) const;

  const runner::Cluster& cluster_;
  kinds::Registry registry_;
};

}  // namespace creaturelab::cli
