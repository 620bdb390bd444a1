#!/usr/bin/python3
"""Checks a reproduction report (analysis/report.py) against its run folders.

usage: /usr/bin/python3 tests/cli/check_report.py ROOT

ROOT/report.html is parsed with Python's html.parser. Every image it shows (<img src>) and every PNG
it links (<a href>) must exist under ROOT and be a valid PNG: the signature, an IHDR of nonzero size
first, each chunk's CRC-32, an IEND last. Every check of every run folder under ROOT (index.h5's
/checks) must appear in a table row whose first cell is its status (ok, FAILED or KNOWN) and whose
second cell starts with its name. REPORT.md must exist and name every check too. The four papers
each have a section (an <h2> naming Mehla 2005, Rudolf & Mould 2009, Lentine et al. 2010, Tu 1996);
the headline's count of each verdict equals the summary table's rows with that verdict and the
figure sections' headings; neither file names a path into ../shared or the seed papers; every QUICK
run (an experiment file *_quick.toml, or `set` overrides) is labelled QUICK. Exits 1 with one line
per problem.
"""
import re
import html.parser
import os
import struct
import sys
import zlib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "analysis"))
from figures import runs  # noqa: E402


class Report(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.images, self.links, self.rows, self.h2, self.verdict_spans = [], [], [], [], []
        self._row, self._cell, self._h, self._span = None, None, None, None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "img" and "src" in a:
            self.images.append(a["src"])
        if tag == "a" and a.get("href", "").endswith(".png"):
            self.links.append(a["href"])
        if tag == "tr":
            self._row = []
        if tag in ("td", "th") and self._row is not None:
            self._cell = []
        if tag in ("h2", "h3"):
            self._h = (tag, [])
        if tag == "span" and self._h is not None and self._h[0] == "h3":
            self._span = []

    def handle_endtag(self, tag):
        if tag == "span" and self._span is not None:
            self.verdict_spans.append("".join(self._span).strip())
            self._span = None
        if tag in ("h2", "h3") and self._h is not None:
            if tag == "h2":
                self.h2.append("".join(self._h[1]).strip())
            self._h = None
        if tag in ("td", "th") and self._cell is not None:
            self._row.append("".join(self._cell).strip())
            self._cell = None
        if tag == "tr" and self._row is not None:
            self.rows.append(self._row)
            self._row = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)
        if self._h is not None:
            self._h[1].append(data)
        if self._span is not None:
            self._span.append(data)


def png_problem(path):
    """"" when path is a valid PNG of nonzero size, else what is wrong."""
    if not os.path.isfile(path):
        return "missing"
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        return "not a PNG (bad signature)"
    pos, chunks = 8, []
    while pos + 12 <= len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        if pos + 12 + length > len(data):
            return f"chunk {kind!r} runs past the end"
        (crc,) = struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])
        if zlib.crc32(kind + body) & 0xFFFFFFFF != crc:
            return f"chunk {kind!r}: bad CRC"
        chunks.append((kind, body))
        pos += 12 + length
    if not chunks or chunks[0][0] != b"IHDR" or chunks[-1][0] != b"IEND":
        return "no IHDR first or no IEND last"
    w, h = struct.unpack(">II", chunks[0][1][:8])
    if w == 0 or h == 0:
        return f"{w} x {h} pixels"
    if not any(k == b"IDAT" for k, _ in chunks):
        return "no image data"
    return ""


PAPERS = ("Mehla 2005", "Rudolf & Mould 2009", "Lentine et al. 2010", "Tu 1996")
VERDICTS = ("reproduced", "deviates", "FAILED", "inconclusive on the quick setting", "not run in this list",
            "figure only")


def verdict_problems(report, text):
    """The headline "N paper figures and claims: a reproduced, b deviates, ..." against the summary
    table's verdict cells and the figure headings' verdicts."""
    m = re.search(r"(\d+) paper figures and claims: ([^.<]*)", text)
    if not m:
        return ["no headline counting the figures' verdicts"]
    said = {v: int(n) for n, v in re.findall(r"(\d+) ([A-Za-z ]+?)(?:,|$)", m.group(2))}
    out = []
    if set(said) != set(VERDICTS):
        out.append(f"the headline counts {sorted(said)}, not every verdict {sorted(VERDICTS)}")
    summary = [r[0] for r in report.rows if len(r) == 4 and r[1] in PAPERS]
    headings = [v for v in report.verdict_spans if v in VERDICTS]
    for v in VERDICTS:
        if said.get(v, 0) != summary.count(v):
            out.append(f"headline: {said.get(v, 0)} {v}, the summary table: {summary.count(v)}")
    if sum(said.values()) != int(m.group(1)):
        out.append(f"headline: {m.group(1)} figures, its verdicts sum to {sum(said.values())}")
    if len(summary) != len(headings[:len(summary)]) or sorted(summary) != sorted(headings[:len(summary)]):
        out.append(f"the summary table's verdicts {sorted(summary)} differ from the sections' "
                   f"{sorted(headings[:len(summary)])}")
    return out


def is_quick(run):
    stem = os.path.splitext(os.path.basename(run.experiment or ""))[0]
    return stem.endswith("_quick") or bool(run.overrides)


def main():
    root = sys.argv[1]
    problems = []
    report = Report()
    with open(os.path.join(root, "report.html"), encoding="utf-8") as fh:
        text = fh.read()
    report.feed(text)
    md = open(os.path.join(root, "REPORT.md"), encoding="utf-8").read()
    for paper in PAPERS:
        if not any(h.startswith(paper) for h in report.h2):
            problems.append(f"no section for {paper} (sections: {report.h2})")
    problems += verdict_problems(report, text)
    for name, body in (("report.html", text), ("REPORT.md", md)):
        for bad in ("../shared", "shared/seeds", "seeds/"):
            if bad in body:
                problems.append(f"{name} names a path into the seed papers ({bad!r}): cite them by reference")
    if not report.images:
        problems.append("report.html shows no image")
    for src in sorted(set(report.images + report.links)):
        p = png_problem(os.path.join(root, src))
        if p:
            problems.append(f"{src}: {p}")
    checks = 0
    for folder in runs.runs_under(root):
        with runs.Run(folder) as run:
            label = f"<code>{run.name}</code>, setting <span class=\"setting\">QUICK</span>"
            if is_quick(run) and label not in text:
                problems.append(f"{run.name}: a QUICK run not labelled QUICK in report.html")
            for c in run.checks:
                checks += 1
                if not any(len(r) >= 2 and r[0] == c["status"] and r[1].startswith(c["name"]) for r in report.rows):
                    problems.append(f"{run.name}: check \"{c['name']}\" ({c['status']}) is not in report.html")
                if c["name"].replace("|", "\\|") not in md:
                    problems.append(f"{run.name}: check \"{c['name']}\" is not in REPORT.md")
    for p in problems:
        print(f"report: {p}")
    print(f"report: {len(set(report.images))} images, {checks} checks looked at, {len(problems)} problem(s)")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
