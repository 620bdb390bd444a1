#!/usr/bin/python3
"""Writes report.html and REPORT.md for the runs under a folder (`make reproduce`:
results/runs/reproduce): provenance first (commit, build, date, machine, wall time), then per paper
and per figure one verdict (reproduced, deviates, FAILED, inconclusive on the quick setting, not run
in this list, figure only), the paper's claim, what we measured (each check's values with units),
the run's setting (default, QUICK with its distance from the default, study), the figures and the
command that remakes them. Runs the catalog (analysis/figures/catalog.py) does not name are listed
under "Other runs" with their checks and every PNG drawn for them, so new kinds are reported without
an edit here. Everything is read from the run folders' HDF5 files and PNGs, plus the default
setting's values (docs/validation/values.json) a QUICK run is compared with.

usage: /usr/bin/python3 analysis/report.py ROOT [--values values.json]   (prints the two paths written)
"""
import argparse
import glob
import os
import re
import shlex
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import report_html  # noqa: E402
import report_md  # noqa: E402
import report_provenance as P  # noqa: E402
import report_timing  # noqa: E402
import report_units as U  # noqa: E402
from figures import catalog, runs  # noqa: E402

# The verdicts of a paper figure, in the order the headline counts them.
VERDICTS = ["reproduced", "deviates", "FAILED", "inconclusive on the quick setting", "not run in this list",
            "figure only"]
STATUSES = ["ok", "KNOWN", "FAILED", "inconclusive"]


class Section:
    """One reported figure (a catalog row) or uncatalogued run: its claim, run, checks (with units),
    PNGs, remaking command and verdict."""

    def __init__(self, title, claim, run, checks, pngs, command, paper=None):
        self.title, self.claim, self.run, self.checks, self.pngs = title, claim, run, checks, pngs
        self.command, self.paper = command, paper
        self.verdict, self.notes, self.figures_with, self.module = "", [], None, None
        self.setting = P.setting(run) if run else ""
        self.prov = P.provenance(run) if run else {}
        self.anchor = slug((paper.key + "-" if paper else "run-") + title)


def slug(s):
    return re.sub(r"[^a-z0-9]+", "-", s.lower()).strip("-")


def regenerate(run, root, module, row_command=None):
    folder = os.path.join(root, run.name) if run else os.path.join(root, "RUN")
    draw = (f"/usr/bin/python3 analysis/figures/{module}.py {shlex.quote(folder)}" if module
            else f"/usr/bin/python3 analysis/draw_runs.py {shlex.quote(folder)}")
    # A figure another tool draws (the 3-D renders: `creaturelab render --figures`) has no module.
    if module and not catalog.has_module(module):
        draw = None
    if row_command:
        command = row_command.replace("RUN", shlex.quote(folder))
        return command if draw is None else command + " && " + draw
    if run is None or not run.experiment:
        return draw
    make = ["build/creaturelab", "run", run.experiment, *run.overrides, "--out", folder, "--force"]
    return " ".join(shlex.quote(x) for x in make) + " && " + draw


def claimed_checks(run, rows):
    """Splits a run's checks between the catalog rows drawn from it (in order): a row takes the
    checks whose names contain one of its substrings, or with checks=None all not yet taken."""
    taken, out = set(), []
    for row in rows:
        mine = []
        for i, c in enumerate(run.checks if run else []):
            if i in taken:
                continue
            if row.checks is None or any(s in c["name"] for s in row.checks):
                mine.append(c)
                taken.add(i)
        out.append(mine)
    rest = [c for i, c in enumerate(run.checks if run else []) if i not in taken]
    return out, rest


def experiment_file(run_name):
    """experiments/*/<run_name>.toml when there is one (the run folder is named by its stem)."""
    found = sorted(glob.glob(os.path.join(P.REPO, "experiments", "*", run_name + ".toml")))
    return os.path.relpath(found[0], P.REPO) if found else None


def finder(found):
    """find(claim) -> the run folder of a catalog row's claim: the folder of that name, else a run of
    the claim's QUICK version (P.claim_key)."""
    by_key = {}
    for run in found.values():
        by_key.setdefault(P.claim_key(run), run)
    return lambda key: found.get(key) or by_key.get(key)


def annotate(section, key, values, lists):
    """Each check's expected and measured texts with units; for a QUICK run its default's value and
    the distance (values.json); then the section's verdict."""
    units = section.run.units if section.run else {}
    for c in section.checks:
        c["default_note"] = ""
        uncertainty = None
        if section.setting == "QUICK":
            d = P.default_of(values, key, c["name"])
            if d is None:
                c["default_note"] = "distance from default not measured"
            else:
                got, commit = d
                dist = P.distance(str(c.get("got", "")), got)
                exp_u, got_u = U.check_texts({**c, "got": got}, units)
                full = P.where_run(key, lists)[0]
                where = (full[0] if full else "default setting") + (f", commit {commit[:10]}" if commit else "")
                if dist is None:
                    c["default_note"] = f"default: {got_u} ({where}); distance not comparable"
                else:
                    unit = U.unit_of_number(c, units, dist[2])
                    uncertainty = dist[0] or None
                    c["default_note"] = (f"default: {got_u} ({where}), distance {U.quantity(dist[0], unit)} "
                                         f"({U.number(100 * dist[1], 2)} %)")
        c["expected_u"], c["got_u"] = U.check_texts(c, units, uncertainty)
    verdict(section)


def verdict(s):
    """The section's verdict, by priority: not run, figure only, FAILED, inconclusive, deviates,
    reproduced; its notes say why, for every check that did not simply pass."""
    # A known deviation that passes on this setting still deviates: its text says where the converged model does.
    st = ["KNOWN" if c["status"] == "ok" and c.get("known_deviation") else c["status"] for c in s.checks]
    if s.run is None:
        s.verdict = "not run in this list"
        return
    if not st:
        s.verdict = "figure only"
        s.notes = ["no check decides this claim: the figure shows it"]
        return
    s.verdict = ("FAILED" if "FAILED" in st else "inconclusive on the quick setting" if "inconclusive" in st
                 else "deviates" if "KNOWN" in st else "reproduced")
    why = {"FAILED": "FAILED", "inconclusive": "inconclusive (the quick setting cannot resolve it)",
           "KNOWN": "known deviation", "ok": "known deviation (passes on this setting)"}
    s.notes = [f"{why[c['status']]}: {c['name']}: measured {c['got_u']}, the claim {c['expected_u']}" +
               (f". Why: {' '.join(c['known_deviation'].split())}" if k == "KNOWN" and c["known_deviation"] else "")
               for want in ("FAILED", "inconclusive", "KNOWN") for k, c in zip(st, s.checks) if k == want]


def build(root, values):
    found = {os.path.basename(p): runs.Run(p) for p in runs.runs_under(root)}
    find = finder(found)
    lists = P.list_entries()
    # Each catalogued run's checks, split between the rows drawn from it.
    checks_of, used_runs = {}, set()
    for key in dict.fromkeys(f.run for f in catalog.FIGURES):
        rows = catalog.figures_of_run(key)
        per_row, rest = claimed_checks(find(key), rows)
        if rest:  # checks no row names: shown with the run's last row
            per_row[-1] = per_row[-1] + rest
        checks_of.update({id(r): [dict(c) for c in cs] for r, cs in zip(rows, per_row)})
    papers, used_pngs = [], set()
    for paper in catalog.PAPERS:
        sections = []
        for row in (f for f in catalog.FIGURES if f.paper == paper.key):
            run = find(row.run)
            if run is not None:
                used_runs.add(run.name)
            pngs = ([p for p in run.figures() if os.path.basename(p).startswith(row.module)]
                    if run and row.module else [])
            used_pngs.update(pngs)
            if run is None and not row.command and experiment_file(row.run):
                folder = shlex.quote(os.path.join(root, row.run))
                draw = (f"/usr/bin/python3 analysis/figures/{row.module}.py {folder}" if row.module
                        else f"/usr/bin/python3 analysis/draw_runs.py {folder}")
                command = f"build/creaturelab run {experiment_file(row.run)} --out {folder} && {draw}"
            else:
                command = regenerate(run, root, row.module, row.command)
            s = Section(row.figure, row.claim, run, checks_of[id(row)], pngs, command, paper)
            s.module = row.module
            annotate(s, row.run, values, lists)
            if run is None:
                s.notes = [P.not_run_text(row.run, lists, experiment_file(row.run))]
                if row.command and not any(P.where_run(row.run, lists)):
                    s.notes = ["made by the command below (make reproduce and make reproduce-full run it after "
                               "the experiments)"]
            sections.append(s)
        papers.append((paper, sections))
    # Rows drawn by the kind's plotter (module None): the run's first such row shows its other PNGs.
    first = {}
    for _, sections in papers:
        for s in sections:
            if s.run is None or s.module is not None:
                continue
            if s.run.name in first:
                s.figures_with = first[s.run.name]
                continue
            first[s.run.name] = s
            s.pngs = [p for p in s.run.figures() if p not in used_pngs]
            used_pngs.update(s.pngs)
    others = []
    for name, run in found.items():
        if name in used_runs:
            continue
        pngs = run.figures()
        used_pngs.update(pngs)
        s = Section(name, run.title, run, [dict(c) for c in run.checks], pngs, regenerate(run, root, None))
        annotate(s, P.claim_key(run), values, lists)
        others.append(s)
    # PNGs the kinds' plotters drew for catalogued runs beside the paper figures.
    extra = {}
    for name, run in found.items():
        if name in used_runs:
            rest = [p for p in run.figures() if p not in used_pngs]
            if rest:
                extra[name] = rest
    tables = timing_tables(find, found)
    return papers, others, extra, found, tables


def cores_text(found):
    provs = [P.provenance(r) for r in found.values()]
    machines = sorted({f"{p['cpu_model']} ({p['cpu_cores']} cores)" for p in provs if p["cpu_cores"] != P.NOT_RECORDED})
    return "our machine: " + ("; ".join(machines) if machines else "CPU and cores not recorded")


def timing_tables(find, found):
    """Lentine Figs. 10 and 14 when the folder holds any of their runs."""
    if not any(find(k) for k in ("parallel_dofs", "parallel_dofs_fluid", "block_flow", "human_wind")):
        return []
    cores = cores_text(found)
    return [report_timing.fig10(find("parallel_dofs"), find("parallel_dofs_fluid"), cores),
            report_timing.fig14(find, cores)]


def counts(papers, others):
    """(verdicts over the paper figures, check statuses over every run shown)."""
    v = {k: 0 for k in VERDICTS}
    n = {k: 0 for k in STATUSES}
    for _, secs in papers:
        for s in secs:
            v[s.verdict] += 1
    for s in [s for _, secs in papers for s in secs] + others:
        for c in s.checks:
            n[c["status"]] += 1
    return v, n


def headline(papers, others):
    v, n = counts(papers, others)
    figs = ", ".join(f"{v[k]} {k}" for k in VERDICTS)
    checks = ", ".join(f"{n[k]} {k}" for k in STATUSES)
    return f"{sum(v.values())} paper figures and claims: {figs}", f"checks over every run: {checks}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("root")
    ap.add_argument("--values", default=None, help="the default setting's values (docs/validation/values.json)")
    a = ap.parse_args()
    if not os.path.isdir(a.root):
        print(f"report.py: {a.root}: no such folder", file=sys.stderr)
        return 2
    values = P.load_values(a.values)
    papers, others, extra, found, tables = build(a.root, values)
    provs = [P.provenance(r) for r in found.values()]
    model = dict(root=a.root, papers=papers, others=others, extra=extra, found=found, tables=tables,
                 headline=headline(papers, others), provenance=P.summary(provs))
    h = report_html.write(model)
    m = report_md.write(model)
    for r in found.values():
        r.close()
    print(f"report: {model['headline'][0]}; {model['headline'][1]} ({len(found)} runs)")
    print(f"report: {h}")
    print(f"report: {m}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
