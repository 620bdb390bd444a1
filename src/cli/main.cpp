// creaturelab: the only main(). Parses the command line and hands each verb to the runner.
// Exit codes: 0 success; 1 a check failed or a comparison is outside tolerance; 2 bad input
// (nothing written); 3 some sweep points failed (the rest are written).
#include <CLI/CLI.hpp>
#include <cstdio>

#include "cli/commands.hpp"
#include "runner/cluster.hpp"
#include "runner/experiment.hpp"

int main(int argc, char** argv) {
  using namespace creaturelab;
  runner::Cluster cluster(&argc, &argv);
  cli::Commands commands(cluster);

  CLI::App app{"creaturelab: experiments in physically based animation of creatures"};
  app.require_subcommand(1);

  cli::RunArgs run_args;
  auto* run = app.add_subcommand("run", "run an experiment file (a sweep of points) into a run folder");
  run->add_option("file", run_args.options.experiment_path, "experiment TOML file")->required();
  run->add_option("overrides", run_args.options.overrides, "dotted.key=value overrides, e.g. params.dt_s=0.001");
  run->add_option("-j,--jobs", run_args.options.jobs, "points run in parallel (default: the cores)");
  run->add_option("-o,--out", run_args.options.out_dir, "run folder (default: results/runs/<file stem>)");
  run->add_flag("--resume", run_args.options.resume, "run only the points whose file is missing");
  run->add_flag("--force", run_args.options.force, "replace an earlier run in the folder");
  run->add_flag("--dry-run", run_args.options.dry_run, "check the file and print the plan; write nothing");
  run->add_option("--points", run_args.slice, "run only the share i of N (i/N: points with index % N == i)");

  std::string kind_name;
  auto* list = app.add_subcommand("list", "every kind and each parameter with unit, default, range and doc");
  list->add_option("kind", kind_name, "only this kind");

  std::string file;
  std::vector<std::string> overrides;
  auto* show = app.add_subcommand("show", "the resolved parameters and the expanded sweep of a file");
  show->add_option("file", file, "experiment TOML file")->required();
  show->add_option("overrides", overrides, "dotted.key=value overrides");

  std::string run_dir;
  auto* check = app.add_subcommand("check", "evaluate the experiment's checks on a finished run");
  check->add_option("run", run_dir, "run folder")->required();

  cli::CompareArgs cmp;
  auto* compare = app.add_subcommand("compare", "compare a run with a baseline (JSON or another run folder)");
  compare->add_option("run", cmp.run, "run folder")->required();
  compare->add_option("baseline", cmp.baseline, "results/baselines/NAME.json or a run folder")->required();
  compare->add_option("--rtol", cmp.rtol, "relative tolerance when the baseline is a run folder");
  compare->add_option("--atol", cmp.atol, "absolute tolerance when the baseline is a run folder");
  compare->add_flag("--all", cmp.all, "show every value, not only those outside tolerance");

  cli::BaselineArgs base;
  auto* baseline = app.add_subcommand("baseline", "write a run's metrics as a baseline JSON");
  baseline->add_option("run", base.run, "run folder")->required();
  baseline->add_option("-o,--output", base.output, "file to write (default: stdout)");
  baseline->add_option("--rtol", base.rtol, "default relative tolerance");
  baseline->add_option("--atol", base.atol, "default absolute tolerance");

  auto* digest = app.add_subcommand("digest", "SHA-256 of each point's datasets and parameters (no provenance)");
  digest->add_option("run", run_dir, "run folder")->required();

  cli::ReproduceArgs rep;
  auto* reproduce = app.add_subcommand("reproduce", "run the default experiments and print their checks");
  reproduce->add_option("--list", rep.list, "file listing the experiments")->capture_default_str();
  reproduce->add_option("-j,--jobs", rep.jobs, "points run in parallel (default: the cores)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }

  return commands.guard([&] {
    if (*run) return commands.run(run_args);
    if (*list) return commands.list(kind_name);
    if (*show) return commands.show(file, overrides);
    if (*check) return commands.check(run_dir);
    if (*compare) return commands.compare(cmp);
    if (*baseline) return commands.baseline(base);
    if (*digest) return commands.digest(run_dir);
    return commands.reproduce(rep);
  });
}
