"""Writes docs/validation/<system>.md from run folders: per claim or study, its checks (expected,
measured, verdict) and the sweep table of the metrics its checks read, with units; and
docs/validation/values.json, the same checks machine-readable (per run folder name: commit, setting,
each check's got, passed and status), which analysis/report.py compares a QUICK run with.

    /usr/bin/python3 analysis/validation.py RUNS [RUNS ...] [--out docs/validation]

RUNS are folders holding run folders (results/runs/reproduce_full) or run folders themselves. The
system of a run is the folder of its experiment file (experiments/<system>/ or studies/<system>/).
Every table in the pages comes from the runs' index.h5 files; nothing is typed by hand.
"""
import argparse
import json
import math
import os
import sys
import tomllib

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import report_provenance as P  # noqa: E402
import report_units as U  # noqa: E402
from report_text import md_cell as cell  # noqa: E402
from report_text import write_atomically  # noqa: E402
from figures import runs as R  # noqa: E402

VERDICT = {"ok": "reproduced", "KNOWN": "deviates", "FAILED": "FAILED", "inconclusive": "inconclusive"}

SYSTEM_OF_KIND = {"oscillator": "oscillator", "strand": "web", "web": "web", "charlotte": "web",
                  "fluid": "fluid", "membrane": "jellyfish", "jellyfish": "jellyfish", "control": "control",
                  "control_fluid": "control", "fish": "fish"}


def significant(x, digits=4):
    """A number with `digits` significant digits; integers and text unchanged."""
    if isinstance(x, str):
        return x
    if isinstance(x, bool):
        return "yes" if x else "no"
    if isinstance(x, int):
        return str(x)
    try:
        v = float(x)
    except (TypeError, ValueError):
        return str(x)
    if math.isnan(v):
        return "nan"
    if v == 0 or math.isinf(v):
        return f"{v:g}"
    return f"{v:.{digits}g}"


def system_of(run):
    parts = os.path.normpath(run.experiment).split(os.sep) if run.experiment else []
    for top in ("experiments", "studies"):
        if top in parts and parts.index(top) + 1 < len(parts) - 1:
            return parts[parts.index(top) + 1]
    return SYSTEM_OF_KIND.get(run.kind, run.kind or "other")


def provenance(run):
    """(commit, finished) of the run's first point file, as recorded at write time."""
    for path in run.point_paths[:1]:
        with h5py.File(path, "r") as f:
            return R.text(f.attrs.get("git_commit", "")), R.text(f.attrs.get("finished", ""))
    return "", ""


def checks_table(checks, units):
    if not checks:
        return ["No checks: this run records data for a figure only.", ""]
    lines = ["| verdict | check | expected | measured | known deviation |", "|---|---|---|---|---|"]
    for c in checks:
        expected, got = U.check_texts(c, units)
        # A known deviation that passes on this setting is the converged model's finding, not a reproduction.
        verdict = ("deviates (passes on this setting)" if c["status"] == "ok" and c.get("known_deviation")
                   else VERDICT[c["status"]])
        lines.append(f"| {verdict} | {cell(c['name'])} | {cell(expected)} | "
                     f"{cell(got)} | {cell(c.get('known_deviation', ''))} |")
    return lines + [""]


def metrics_of_checks(run):
    """The metric columns the run's checks read (from the experiment text index.h5 records), in the
    order they first appear."""
    try:
        with h5py.File(os.path.join(run.folder, "index.h5"), "r") as idx:
            source = tomllib.loads(R.text(idx.attrs.get("experiment_toml", "")))
    except (OSError, ValueError):
        source = {}
    names = []
    for c in source.get("check", []):
        for key in ("metric", "numerator_metric", "denominator_metric", "relative_metric"):
            m = c.get(key)
            if m and m not in names and m in run.sweep:
                names.append(m)
    return names


def sweep_table(run, metrics):
    n = len(run.sweep.get("point_index", []))
    if n == 0 or not metrics:
        return []
    labels = run.labels()
    head = ["point"] + [f"{m} ({run.units.get(m) or '-'})" for m in metrics]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for k in range(n):
        row = [cell(labels[k])] + [significant(run.sweep[m][k]) for m in metrics]
        lines.append("| " + " | ".join(row) + " |")
    return lines + [""]


def section(run):
    commit, finished = provenance(run)
    lines = [f"## {run.title}", "",
             f"Experiment `{run.experiment}` ({P.setting(run)} setting)" + (f", run folder `{run.name}`" if run.name else "") +
             (f"; commit `{commit}`" if commit else "") + (f", finished {finished}" if finished else "") + ".", ""]
    if run.overrides:
        lines += ["Overrides: " + ", ".join(f"`{o}`" for o in run.overrides) + ".", ""]
    lines += checks_table(run.checks, run.units)
    lines += sweep_table(run, metrics_of_checks(run))
    return lines


def values_entry(run):
    """values.json's record of one run: what analysis/report.py needs to compare a QUICK run with it."""
    return {"experiment": run.experiment, "setting": P.setting(run), "commit": P.provenance(run)["git_commit"],
            "checks": [{"name": c["name"], "got": c.get("got", ""), "passed": c["passed"], "status": c["status"]}
                       for c in run.checks]}


def write_values(values, out, sources):
    text = json.dumps({"generated_from": list(sources), "runs": values}, indent=1, sort_keys=True) + "\n"
    return write_atomically(os.path.join(out, "values.json"), text)


def write(pages, out, sources):
    os.makedirs(out, exist_ok=True)
    written = []
    for system, sections in sorted(pages.items()):
        path = os.path.join(out, system + ".md")
        lines = [f"# Validation: {system}", "",
                 "Generated by `analysis/validation.py` from the run folders " +
                 ", ".join(f"`{s}`" for s in sources) + "; do not edit by hand. Each section is one "
                 "claim (experiments/) or study (studies/): its checks with the measured value and "
                 "the sweep table of the metrics they read.", ""]
        for s in sections:
            lines += s
        written.append(write_atomically(path, "\n".join(lines).rstrip() + "\n"))
    return written


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--out", default="docs/validation")
    args = ap.parse_args(argv)
    pages, values = {}, {}
    for root in args.runs:
        for folder in R.runs_under(root):
            if not os.path.exists(os.path.join(folder, "index.h5")):
                continue
            with R.Run(folder) as run:
                pages.setdefault(system_of(run), []).append(section(run))
                values[run.name] = values_entry(run)
    if not pages:
        print(f"validation.py: no run folder with an index.h5 under {', '.join(args.runs)}", file=sys.stderr)
        return 2
    for path in write(pages, args.out, args.runs) + [write_values(values, args.out, args.runs)]:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
