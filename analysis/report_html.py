"""report.html from the report's model (analysis/report.py): provenance, headline, contents, the
summary table (paper x figure -> verdict), one section per figure, Lentine's timing tables, other
runs, and the runs' settings and wall times."""
import html
import os

import report_provenance as P
import report_text as T

STATUS_CLASS = {"ok": "ok", "FAILED": "failed", "KNOWN": "known", "inconclusive": "inconclusive"}
VERDICT_CLASS = {"reproduced": "ok", "deviates": "known", "FAILED": "failed",
                 "inconclusive on the quick setting": "inconclusive", "not run in this list": "missing",
                 "figure only": "neutral"}
CSS = """body{font-family:sans-serif;max-width:1200px;margin:1em auto;padding:0 1em;color:#222}
h1{font-size:1.5em}h2{font-size:1.25em;border-bottom:1px solid #ccc;margin-top:2em}h3{font-size:1.05em;margin-bottom:.2em}
table{border-collapse:collapse;font-size:.85em;margin:.4em 0}td,th{border:1px solid #ddd;padding:2px 6px;text-align:left;vertical-align:top}
.ok{color:#176f2c;font-weight:bold}.failed{color:#b00020;font-weight:bold}.known{color:#a05a00;font-weight:bold}
.inconclusive{color:#5a4fb0;font-weight:bold}.missing{color:#666;font-weight:bold}.neutral{color:#444}
.claim{font-style:italic}.cmd{font-family:monospace;font-size:.8em;background:#f4f4f4;padding:4px;word-break:break-all}
.setting{font-weight:bold}img{max-width:100%;border:1px solid #eee;margin:4px 0}.thumbs img{width:300px}"""


def e(s):
    return html.escape(str(s))


def rel(path, root):
    return os.path.relpath(path, root)


def table(header, rows, classes=None):
    out = ["<table><tr>" + "".join(f"<th>{e(h)}</th>" for h in header) + "</tr>"]
    for k, r in enumerate(rows):
        cls = (classes or [None] * len(rows))[k]
        cells = [f"<td class=\"{cls}\">{r[0]}</td>" if cls else f"<td>{r[0]}</td>"] + [f"<td>{c}</td>" for c in r[1:]]
        out.append("<tr>" + "".join(cells) + "</tr>")
    return "".join(out) + "</table>"


def checks_html(s):
    if not s.checks:
        return ""
    quick = s.setting == "QUICK"
    header = ["status", "check", "expected", "measured"] + (["default setting"] if quick else [])
    rows, classes = [], []
    for c in s.checks:
        row = [e(c["status"]), e(c["name"]), e(c["expected_u"]), e(c["got_u"])]
        rows.append(row + ([e(c["default_note"])] if quick else []))
        classes.append(STATUS_CLASS[c["status"]])
    return table(header, rows, classes)


def run_line(s, root):
    p = s.prov
    return (f"<p>run: <code>{e(rel(s.run.folder, root))}</code>, setting <span class=\"setting\">{e(s.setting)}</span>"
            f" — {e(s.run.title)}<br><small>commit {e(p['git_commit'])}, build {e(p['build_type'])}, started "
            f"{e(p['started_utc'])}, wall time {e(P.duration(P.seconds(p['wall_s'])))}</small></p>")


def section(s, root, level="h3"):
    out = [f"<{level} id=\"{s.anchor}\">{e(s.title)}: <span class=\"{VERDICT_CLASS.get(s.verdict, 'neutral')}\">"
           f"{e(s.verdict)}</span></{level}>", f"<p class=\"claim\">{e(s.claim)}</p>"]
    if s.notes:
        out.append("<ul>" + "".join(f"<li>{e(n)}</li>" for n in s.notes) + "</ul>")
    if s.run is not None:
        out.append(run_line(s, root))
        out.append(checks_html(s))
        if s.figures_with is not None:
            out.append(f"<p>figures: with <a href=\"#{s.figures_with.anchor}\">{e(s.figures_with.title)}</a></p>")
        elif not s.pngs:
            out.append("<p class=\"missing\">no figure was drawn</p>")
        for p in s.pngs:
            r = e(rel(p, root))
            out.append(f"<a href=\"{r}\"><img src=\"{r}\" alt=\"{e(os.path.basename(p))}\"></a>")
    if s.command:
        out.append(f"<p class=\"cmd\">{e(s.command)}</p>")
    return "\n".join(out)


def timing(t, k):
    caption, header, rows, note = t
    return (f"<h3 id=\"lentine-timing-{k}\">{e(caption)}</h3>" + table(header, [[e(c) for c in r] for r in rows]) +
            f"<p><small>{e(note)}</small></p>")


def write(m):
    root, papers, others = m["root"], m["papers"], m["others"]
    parts = ["<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>creaturelab reproduction report</title>"
             f"<style>{CSS}</style></head><body>", "<h1>creaturelab: reproduced paper figures</h1>",
             table(["provenance", ""], [[e(k), e(v)] for k, v in m["provenance"]]),
             f"<details id=\"runs\"><summary>each run: setting, commit, build, start and wall time "
             f"({len(m['found'])} runs)</summary>" + table(*runs_table(m["found"])) + "</details>",
             f"<p><b>{e(m['headline'][0])}</b>.<br>{e(m['headline'][1])}. Every figure is drawn from the run "
             "folders' HDF5 files alone; each section ends with the command that remakes it (from the repository "
             "root).</p>", "<h2 id=\"contents\">Contents</h2><ul>"]
    for paper, _ in papers:
        parts.append(f"<li><a href=\"#paper-{paper.key}\">{e(paper.title)}</a></li>")
        if paper.key == "lentine":
            parts += [f"<li><a href=\"#lentine-timing-{k}\">{e(t[0])}</a></li>" for k, t in enumerate(m["tables"])]
    if others:
        parts.append("<li><a href=\"#other-runs\">Other runs</a></li>")
    parts.append("</ul>")
    parts.append("<h2 id=\"summary\">Summary</h2>")
    rows, classes = [], []
    for paper, sections in papers:
        for s in sections:
            rows.append([e(s.verdict), e(paper.title.split(",")[0]), f"<a href=\"#{s.anchor}\">{e(s.title)}</a>",
                         e(s.setting or "-")])
            classes.append(VERDICT_CLASS.get(s.verdict, "neutral"))
    parts.append(table(["verdict", "paper", "figure or claim", "setting"], rows, classes))
    for paper, sections in papers:
        parts.append(f"<h2 id=\"paper-{paper.key}\">{e(paper.title)}</h2><p><small>{e(paper.reference)}</small></p>")
        parts += [section(s, root) for s in sections]
        if paper.key == "lentine":
            parts += [timing(t, k) for k, t in enumerate(m["tables"])]
    if others:
        parts.append("<h2 id=\"other-runs\">Other runs</h2><p>Runs no paper figure claims: their checks and every "
                     "figure their kind drew.</p>")
        parts += [section(s, root) for s in others]
    if m["extra"]:
        parts.append("<h2>More figures of the reproduced runs</h2><p>What each kind's plotter drew besides the "
                     "paper figures (per point, per sweep).</p>")
        for name, pngs in m["extra"].items():
            parts.append(f"<details><summary>{e(name)}: {len(pngs)} figure(s)</summary><div class=\"thumbs\">")
            for p in pngs:
                r = e(rel(p, root))
                parts.append(f"<a href=\"{r}\"><img src=\"{r}\" loading=\"lazy\" alt=\"{e(os.path.basename(p))}\"></a>")
            parts.append("</div></details>")
    parts.append("</body></html>\n")
    return T.write_atomically(os.path.join(root, "report.html"), "\n".join(parts))


def runs_table(found):
    """(header, rows) of every run: setting, commit, build, start, wall time (escaped cells)."""
    rows = []
    for name, run in sorted(found.items()):
        p = P.provenance(run)
        rows.append([e(name), e(P.setting(run)), e(p["git_commit"]), e(p["build_type"]), e(p["started_utc"]),
                     e(P.duration(P.seconds(p["wall_s"]))), e(run.experiment or run.title)])
    return ["run", "setting", "commit", "build", "started (UTC)", "wall time", "experiment"], rows
