// creaturelab: the only main(). Parses the command line and hands each verb to the runner.
// Exit codes: 0 success; 1 a check failed or a comparison is outside tolerance; 2 bad input
// (nothing written); 3 some sweep points failed (the rest are written).
#include <CLI/CLI.hpp>
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/creature_glb_command.hpp"
#include "cli/fit_commands.hpp"
#include "cli/render_commands.hpp"
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
  run->add_flag("--allow-long", run_args.options.allow_long,
                "run points estimated to take very many steps (explicit integrators with dt_s = \"auto\")");

  std::string kind_name;
  auto* list = app.add_subcommand("list", "every kind and each parameter with unit, default, range and doc");
  list->add_option("kind", kind_name, "only this kind; `render` for the settings of creaturelab render");

  std::string file;
  std::vector<std::string> overrides;
  auto* show = app.add_subcommand("show", "the resolved parameters and the expanded sweep of a file");
  show->add_option("file", file, "experiment TOML file")->required();
  show->add_option("overrides", overrides, "dotted.key=value overrides");

  std::string run_dir;
  auto* check = app.add_subcommand("check", "evaluate the experiment's checks on a finished run");
  check->add_option("run", run_dir, "run folder")->required();
  bool check_no_verify = false;
  check->add_flag("--no-verify", check_no_verify, "trust index.h5 without checking each point file against it");

  cli::CompareArgs cmp;
  auto* compare = app.add_subcommand("compare", "compare a run with a baseline (JSON or another run folder)");
  compare->add_option("run", cmp.run, "run folder")->required();
  compare->add_option("baseline", cmp.baseline, "results/baselines/NAME.json or a run folder")->required();
  compare->add_option("--rtol", cmp.rtol, "relative tolerance when the baseline is a run folder");
  compare->add_option("--atol", cmp.atol, "absolute tolerance when the baseline is a run folder");
  compare->add_flag("--all", cmp.all, "show every value, not only those outside tolerance");
  compare->add_flag("--no-verify", cmp.no_verify, "trust index.h5 without checking each point file against it");

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
  reproduce->add_option("-o,--out", rep.out_root, "folder holding one run folder per experiment")->capture_default_str();

  runner::RenderRunOptions ren;
  auto* render = app.add_subcommand("render", "a recorded jellyfish swim as a 3-D animated mesh: HDF5 + XDMF, .glb, "
                                              "OBJ frames; --figures draws Figs. 7, 9, 10 with POV-Ray");
  render->add_option("source", ren.source, "a jellyfish point file (.h5) or run folder")->required();
  render->add_option("settings", ren.overrides, "render settings key=value, e.g. rings=48 noise=false "
                                                "(`creaturelab list render`)");
  render->add_option("--point", ren.point, "point index when SOURCE is a run folder")->capture_default_str();
  render->add_option("--frames", ren.frames, "frames A:B or A:B:STEP (B exclusive), or one frame K (default: all)");
  render->add_option("-o,--out", ren.out_dir, "output folder (default: beside the point file, render_point_NNNNNN)");
  render->add_flag("--force", ren.force, "replace an existing output folder");
  render->add_flag("--figures", ren.figures, "also draw Figs. 7, 9, 10 (PNG, POV-Ray headless) into OUT/figures");
  render->add_option("--figure-scale", ren.figure_scale, "multiplies the figures' pixel sizes")->capture_default_str();
  bool no_obj = false, no_glb = false;
  render->add_flag("--no-obj", no_obj, "skip the OBJ frames");
  render->add_flag("--no-glb", no_glb, "skip the .glb");

  cli::FitSplineArgs fsa;
  cli::FitControllerArgs fca;
  cli::CreatureGlbArgs glb_args;
  auto* creature_glb = cli::addCreatureGlbCommand(app, glb_args);

  auto* fit = app.add_subcommand("fit", "fit the contraction spline to data, or tune controller parameters");
  fit->require_subcommand(1);
  auto* fit_spline = fit->add_subcommand("spline", "fit the jellyfish's Hermite contraction curve to a profile");
  fit_spline->add_option("data", fsa.data, "CSV (time_s,value[,weight]), point file .h5 or run folder")->required();
  fit_spline->add_option("-o,--out", fsa.out, "output folder (default: results/runs/fit/<data stem>_spline)");
  fit_spline->add_option("--knots", fsa.knots, "evenly spaced knots k/K (default 4)");
  fit_spline->add_option("--phases", fsa.phases, "knot phases, e.g. 0,0.3 (instead of --knots)");
  fit_spline->add_option("--period", fsa.period_s, "period in s (default: 1/contraction_hz of a point, else detected)");
  fit_spline->add_option("--phase-origin", fsa.phase_origin_s, "time in s at phase 0 (default 0)");
  fit_spline->add_option("--from", fsa.from_s, "ignore samples before this time in s (a warm-up)");
  fit_spline->add_option("--lower", fsa.lower, "lower bound on knot values")->capture_default_str();
  fit_spline->add_option("--upper", fsa.upper, "upper bound on knot values")->capture_default_str();
  fit_spline->add_option("--loss", fsa.loss, "none | huber | cauchy")->capture_default_str();
  fit_spline->add_option("--loss-scale", fsa.loss_scale, "residual beyond which the loss is robust")->capture_default_str();
  fit_spline->add_option("--start-values", fsa.start_values, "start knot values, e.g. 1,0.56 (default: from the data)");
  fit_spline->add_option("--dataset", fsa.dataset, "HDF5 value dataset")->capture_default_str();
  fit_spline->add_option("--time-dataset", fsa.time_dataset, "HDF5 time dataset")->capture_default_str();
  fit_spline->add_option("--weight-dataset", fsa.weight_dataset, "HDF5 weight dataset (default: all 1)");
  fit_spline->add_option("--point", fsa.point, "point index when DATA is a run folder")->capture_default_str();
  fit_spline->add_flag("--force", fsa.force, "replace an existing output folder");
  auto* fit_controller = fit->add_subcommand("controller", "tune parameters of a kind (experiments/fit/*.toml)");
  fit_controller->add_option("file", fca.file, "controller-fit TOML file")->required();
  fit_controller->add_option("-o,--out", fca.out, "output folder (default: results/runs/fit/<file stem>)");
  fit_controller->add_option("-j,--jobs", fca.jobs, "runs in parallel (default: the cores)");
  fit_controller->add_flag("--resume", fca.resume, "continue an interrupted fit from its record");
  fit_controller->add_flag("--force", fca.force, "replace an earlier fit in the folder");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }

  return commands.guard([&] {
    if (*run) return commands.run(run_args);
    if (*list) return commands.list(kind_name);
    if (*render) {
      ren.obj = !no_obj;
      ren.glb = !no_glb;
      return cli::render(ren);
    }
    if (*creature_glb) return cli::creatureGlb(glb_args);
    if (*show) return commands.show(file, overrides);
    if (*check) return commands.check(run_dir, !check_no_verify);
    if (*compare) return commands.compare(cmp);
    if (*baseline) return commands.baseline(base);
    if (*digest) return commands.digest(run_dir);
    if (*fit_spline) return cli::fitSpline(fsa);
    if (*fit_controller) return cli::fitController(fca, kinds::defaultRegistry());
    return commands.reproduce(rep);
  });
}
