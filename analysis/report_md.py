"""REPORT.md from the report's model (analysis/report.py): the same content as report.html
(report_html.py) in Markdown."""
import os

import report_provenance as P
import report_text as T
from report_text import md_cell as cell


def rel(path, root):
    return os.path.relpath(path, root)


def table(header, rows):
    out = ["| " + " | ".join(cell(h) for h in header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(cell(c) for c in r) + " |" for r in rows]
    return out + [""]


def section(s, root, level="###"):
    out = [f"{level} {s.title}: {s.verdict}", "", f"*{s.claim}*", ""]
    if s.notes:
        out += [f"- {n}" for n in s.notes] + [""]
    if s.run is not None:
        p = s.prov
        wall = P.duration(P.seconds(p["wall_s"]))
        out += [f"run: `{rel(s.run.folder, root)}`, setting **{s.setting}** — {s.run.title}; commit "
                f"{p['git_commit']}, build {p['build_type']}, started {p['started_utc']}, wall time {wall}", ""]
        if s.checks:
            quick = s.setting == "QUICK"
            header = ["status", "check", "expected", "measured"] + (["default setting"] if quick else [])
            rows = []
            for c in s.checks:
                rows.append([c["status"], c["name"], c["expected_u"], c["got_u"]] +
                            ([c["default_note"]] if quick else []))
            out += table(header, rows)
        if s.figures_with is not None:
            out += [f"figures: with {s.figures_with.title}", ""]
        else:
            out += [f"![{os.path.basename(p)}]({rel(p, root)})" for p in s.pngs] or ["**no figure was drawn**"]
            out.append("")
    if s.command:
        out += ["```", s.command, "```", ""]
    return out


def write(m):
    root, papers, others = m["root"], m["papers"], m["others"]
    lines = ["# creaturelab: reproduced paper figures", ""]
    lines += table(["provenance", ""], m["provenance"])
    lines += ["Each run: setting, commit, build, start and wall time.", ""]
    rows = []
    for name, run in sorted(m["found"].items()):
        p = P.provenance(run)
        rows.append([name, P.setting(run), p["git_commit"], p["build_type"], p["started_utc"],
                     P.duration(P.seconds(p["wall_s"])), run.experiment or run.title])
    lines += table(["run", "setting", "commit", "build", "started (UTC)", "wall time", "experiment"], rows)
    lines += [f"**{m['headline'][0]}**.", "", f"{m['headline'][1]}. Every figure is drawn from the run folders' HDF5 "
              "files alone; each section ends with the command that remakes it.", "", "## Contents", ""]
    for paper, _ in papers:
        lines += [f"- {paper.title}"] + ([f"- {t[0]}" for t in m["tables"]] if paper.key == "lentine" else [])
    lines += ["- Other runs"] if others else []
    lines += ["", "## Summary", ""]
    lines += table(["verdict", "paper", "figure or claim", "setting"],
                   [[s.verdict, paper.title.split(",")[0], s.title, s.setting or "-"]
                    for paper, secs in papers for s in secs])
    for paper, sections in papers:
        lines += [f"## {paper.title}", "", paper.reference, ""]
        for s in sections:
            lines += section(s, root)
        if paper.key == "lentine":
            for caption, header, rows, note in m["tables"]:
                lines += [f"### {caption}", ""] + table(header, rows) + [note, ""]
    if others:
        lines += ["## Other runs", ""]
        for s in others:
            lines += section(s, root)
    if m["extra"]:
        lines += ["## More figures of the reproduced runs", ""]
        for name, pngs in m["extra"].items():
            lines += [f"- {name}: " + ", ".join(f"[{os.path.basename(p)}]({rel(p, root)})" for p in pngs)]
        lines.append("")
    return T.write_atomically(os.path.join(root, "REPORT.md"), "\n".join(lines))
