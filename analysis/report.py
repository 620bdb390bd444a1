#!/usr/bin/python3
"""Writes report.html and REPORT.md for the runs under a folder (`make reproduce`:
results/runs/reproduce): per paper, per figure, the paper's figure number and claim, what we
measured (the checks' values), each check's status (ok / FAILED / KNOWN with the reason), the figure
and the command that remakes it. Runs the catalog (analysis/figures/catalog.py) does not name are
listed under "Other runs" with their checks and every PNG drawn for them, so new kinds are reported
without an edit here. Everything is read from the run folders' HDF5 files and PNGs.

usage: /usr/bin/python3 analysis/report.py ROOT    (prints the two paths written)
"""
import html
import os
import shlex
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from figures import catalog, runs  # noqa: E402

STATUS_CLASS = {"ok": "ok", "FAILED": "failed", "KNOWN": "known"}


class Section:
    """One reported figure: its catalog row (or None for an uncatalogued run), the run, its checks
    and its PNGs."""

    def __init__(self, title, claim, run, checks, pngs, command, paper=None):
        self.title, self.claim, self.run, self.checks, self.pngs = title, claim, run, checks, pngs
        self.command, self.paper = command, paper


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
    import glob

    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    found = sorted(glob.glob(os.path.join(here, "experiments", "*", run_name + ".toml")))
    return os.path.relpath(found[0], here) if found else None


def build(root):
    found = {os.path.basename(p): runs.Run(p) for p in runs.runs_under(root)}
    # Each catalogued run's checks, split between the rows drawn from it.
    checks_of = {}
    for name in dict.fromkeys(f.run for f in catalog.FIGURES):
        rows = catalog.figures_of_run(name)
        per_row, rest = claimed_checks(found.get(name), rows)
        if rest:  # checks no row names: shown with the run's last row
            per_row[-1] = per_row[-1] + rest
        checks_of.update({id(r): c for r, c in zip(rows, per_row)})
    papers = []
    used_pngs = set()
    for paper in catalog.PAPERS:
        sections = []
        for row in (f for f in catalog.FIGURES if f.paper == paper.key):
            run = found.get(row.run)
            pngs = [p for p in (run.figures() if run else []) if os.path.basename(p).startswith(row.module)]
            used_pngs.update(pngs)
            if run is None and not row.command and experiment_file(row.run):
                folder = shlex.quote(os.path.join(root, row.run))
                command = (f"build/creaturelab run {experiment_file(row.run)} --out {folder} && "
                           f"/usr/bin/python3 analysis/figures/{row.module}.py {folder}")
            else:
                command = regenerate(run, root, row.module, row.command)
            sections.append(Section(row.figure, row.claim, run, checks_of[id(row)], pngs, command, paper))
        papers.append((paper, sections))
    catalogued = {f.run for f in catalog.FIGURES}
    others = []
    for name, run in found.items():
        if name in catalogued:
            continue
        pngs = run.figures()
        used_pngs.update(pngs)
        others.append(Section(name, run.title, run, run.checks, pngs, regenerate(run, root, None)))
    # PNGs the kinds' plotters drew for catalogued runs beside the paper figures.
    extra = {}
    for name, run in found.items():
        if name in catalogued:
            rest = [p for p in run.figures() if p not in used_pngs]
            if rest:
                extra[name] = rest
    return papers, others, extra, found


def counts(papers, others):
    n = {"ok": 0, "FAILED": 0, "KNOWN": 0}
    for _, secs in papers:
        for s in secs:
            for c in s.checks:
                n[c["status"]] += 1
    for s in others:
        for c in s.checks:
            n[c["status"]] += 1
    return n


def rel(path, root):
    return os.path.relpath(path, root)


# --- HTML -------------------------------------------------------------------------------------
CSS = """body{font-family:sans-serif;max-width:1200px;margin:1em auto;padding:0 1em;color:#222}
h1{font-size:1.5em}h2{font-size:1.25em;border-bottom:1px solid #ccc;margin-top:2em}h3{font-size:1.05em;margin-bottom:.2em}
table{border-collapse:collapse;font-size:.85em;margin:.4em 0}td,th{border:1px solid #ddd;padding:2px 6px;text-align:left;vertical-align:top}
.ok{color:#176f2c;font-weight:bold}.failed{color:#b00020;font-weight:bold}.known{color:#a05a00;font-weight:bold}
.claim{font-style:italic}.cmd{font-family:monospace;font-size:.8em;background:#f4f4f4;padding:4px;word-break:break-all}
img{max-width:100%;border:1px solid #eee;margin:4px 0}.thumbs img{width:300px}.missing{color:#b00020}"""


def html_checks(checks):
    if not checks:
        return "<p>measured: figure only (no check decides this claim)</p>"
    rows = []
    for c in checks:
        status = c["status"]
        reason = f"<br><small>{html.escape(c['known_deviation'])}</small>" if status == "KNOWN" else ""
        rows.append(f"<tr><td class=\"{STATUS_CLASS[status]}\">{status}</td><td>{html.escape(c['name'])}{reason}</td>"
                    f"<td>{html.escape(c['expected'])}</td><td>{html.escape(c['got'])}</td></tr>")
    return ("<table><tr><th>status</th><th>check</th><th>expected</th><th>measured</th></tr>" + "".join(rows) +
            "</table>")


def html_section(s, root, level="h3"):
    out = [f"<{level}>{html.escape(s.title)}</{level}>", f"<p class=\"claim\">{html.escape(s.claim)}</p>"]
    if s.run is None:
        out.append("<p class=\"missing\">not reproduced: its run folder is missing under this root</p>")
    else:
        out.append(f"<p>run: <code>{html.escape(rel(s.run.folder, root))}</code> — {html.escape(s.run.title)}</p>")
        out.append(html_checks(s.checks))
        if not s.pngs:
            out.append("<p class=\"missing\">no figure was drawn</p>")
        for p in s.pngs:
            r = html.escape(rel(p, root))
            out.append(f"<a href=\"{r}\"><img src=\"{r}\" alt=\"{html.escape(os.path.basename(p))}\"></a>")
    out.append(f"<p class=\"cmd\">{html.escape(s.command)}</p>")
    return "\n".join(out)


def write_html(root, papers, others, extra):
    n = counts(papers, others)
    parts = [f"<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>creaturelab reproduction report</title>"
             f"<style>{CSS}</style></head><body>",
             "<h1>creaturelab: reproduced paper figures</h1>",
             f"<p>checks: <span class=\"ok\">{n['ok']} ok</span>, <span class=\"failed\">{n['FAILED']} FAILED</span>, "
             f"<span class=\"known\">{n['KNOWN']} KNOWN</span> (a known deviation from the paper, with its reason). "
             f"Every figure is drawn from the run folders' HDF5 files alone; each ends with the command that "
             f"remakes it (from the repository root).</p>"]
    for paper, sections in papers:
        parts.append(f"<h2>{html.escape(paper.title)}</h2><p><small>{html.escape(paper.reference)}</small></p>")
        parts += [html_section(s, root) for s in sections]
    if others:
        parts.append("<h2>Other runs</h2><p>Runs without a catalogued paper figure: their checks and every "
                     "figure their kind drew.</p>")
        parts += [html_section(s, root) for s in others]
    if extra:
        parts.append("<h2>More figures of the reproduced runs</h2><p>What each kind's plotter drew besides the "
                     "paper figures (per point, per sweep).</p>")
        for name, pngs in extra.items():
            parts.append(f"<details><summary>{html.escape(name)}: {len(pngs)} figure(s)</summary><div class=\"thumbs\">")
            for p in pngs:
                r = html.escape(rel(p, root))
                parts.append(f"<a href=\"{r}\"><img src=\"{r}\" loading=\"lazy\" "
                             f"alt=\"{html.escape(os.path.basename(p))}\"></a>")
            parts.append("</div></details>")
    parts.append("</body></html>\n")
    path = os.path.join(root, "report.html")
    with open(path + ".tmp", "w") as fh:
        fh.write("\n".join(parts))
    os.replace(path + ".tmp", path)
    return path


# --- Markdown ---------------------------------------------------------------------------------
def md_cell(s):
    return str(s).replace("|", "\\|").replace("\n", " ")


def md_section(s, root, level="###"):
    out = [f"{level} {s.title}", "", f"*{s.claim}*", ""]
    if s.run is None:
        out += ["**not reproduced**: its run folder is missing under this root", ""]
    else:
        out += [f"run: `{rel(s.run.folder, root)}` — {s.run.title}", ""]
        if s.checks:
            out += ["| status | check | expected | measured |", "|---|---|---|---|"]
            for c in s.checks:
                reason = f" — {c['known_deviation']}" if c["status"] == "KNOWN" else ""
                out.append(f"| {c['status']} | {md_cell(c['name'] + reason)} | {md_cell(c['expected'])} | "
                           f"{md_cell(c['got'])} |")
            out.append("")
        else:
            out += ["measured: figure only (no check decides this claim)", ""]
        out += [f"![{os.path.basename(p)}]({rel(p, root)})" for p in s.pngs] or ["**no figure was drawn**"]
        out.append("")
    out += ["```", s.command, "```", ""]
    return out


def write_md(root, papers, others, extra):
    n = counts(papers, others)
    lines = ["# creaturelab: reproduced paper figures", "",
             f"checks: {n['ok']} ok, {n['FAILED']} FAILED, {n['KNOWN']} KNOWN. Every figure is drawn from the run "
             f"folders' HDF5 files alone; each ends with the command that remakes it.", ""]
    for paper, sections in papers:
        lines += [f"## {paper.title}", "", paper.reference, ""]
        for s in sections:
            lines += md_section(s, root)
    if others:
        lines += ["## Other runs", ""]
        for s in others:
            lines += md_section(s, root)
    if extra:
        lines += ["## More figures of the reproduced runs", ""]
        for name, pngs in extra.items():
            lines += [f"- {name}: " + ", ".join(f"[{os.path.basename(p)}]({rel(p, root)})" for p in pngs)]
        lines.append("")
    path = os.path.join(root, "REPORT.md")
    with open(path + ".tmp", "w") as fh:
        fh.write("\n".join(lines))
    os.replace(path + ".tmp", path)
    return path


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    root = sys.argv[1]
    if not os.path.isdir(root):
        sys.exit(f"{root}: no such folder")
    papers, others, extra, found = build(root)
    h = write_html(root, papers, others, extra)
    m = write_md(root, papers, others, extra)
    for r in found.values():
        r.close()
    n = counts(papers, others)
    print(f"report: {n['ok']} ok, {n['FAILED']} FAILED, {n['KNOWN']} KNOWN checks over {len(found)} runs")
    print(f"report: {h}")
    print(f"report: {m}")


if __name__ == "__main__":
    main()
