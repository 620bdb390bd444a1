"""Where a run came from, for the report: its setting (default, QUICK or study), the commit, build
and machine it ran on and its wall time (index.h5's root attributes; "not recorded" in run folders
written before the runner stored them), which reproduce list runs a claim, and the default setting's
values (docs/validation/values.json, written by analysis/validation.py from a make-reproduce-full
folder) a QUICK run is compared with.
"""
import json
import math
import os
import tomllib

import h5py

import report_units as U
from figures import runs as R

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NOT_RECORDED = "not recorded"
# index.h5 root attributes the runner writes (git_commit, build_type, cpu_model, cpu_cores,
# started_utc, wall_s: the run's wall seconds).
PROVENANCE = ("git_commit", "build_type", "cpu_model", "cpu_cores", "started_utc", "wall_s")
LISTS = [("make reproduce", "experiments/reproduce.toml"), ("make reproduce-full", "experiments/reproduce_full.toml")]


def stem(path):
    return os.path.splitext(os.path.basename(path))[0] if path else ""


def setting(run):
    """"QUICK" for a run of a *_quick.toml file or with `set` overrides, "default" for a claim file
    under experiments/, "study" otherwise (studies/, files elsewhere, fits)."""
    exp = getattr(run, "experiment", "") or ""
    if stem(exp).endswith("_quick") or run.overrides:
        return "QUICK"
    parts = os.path.normpath(exp).split(os.sep) if exp else []
    return "default" if "experiments" in parts else "study"


def claim_key(run):
    """The claim a run measures: its experiment file's stem without "_quick" when the file is a claim
    (experiments/), else the run folder's name."""
    exp = getattr(run, "experiment", "") or ""
    if exp and "experiments" in os.path.normpath(exp).split(os.sep):
        s = stem(exp)
        return s[:-len("_quick")] if s.endswith("_quick") else s
    return run.name


def provenance(run):
    """The run's provenance attributes as text (index.h5's, or a fit's record's; "not recorded"
    where the file has none)."""
    out = {k: NOT_RECORDED for k in PROVENANCE}
    path = next((p for p in (os.path.join(run.folder, n) for n in ("index.h5",) + R.FIT_FILES)
                 if os.path.exists(p)), None)  # a fit folder's record carries its own
    if path is None:
        return out
    with h5py.File(path, "r") as idx:
        for k in PROVENANCE:
            if k in idx.attrs:
                v = R.text(idx.attrs[k]).strip()
                out[k] = v or NOT_RECORDED
    return out


def seconds(text):
    """A wall time attribute as float seconds, or None."""
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def duration(s):
    """"1 h 02 min", "3 min 05 s", "12.3 s" for a wall time in seconds; "not recorded" for None."""
    if s is None:
        return NOT_RECORDED
    if s >= 3600:
        return f"{int(s // 3600)} h {int(s % 3600 // 60):02d} min"
    if s >= 60:
        return f"{int(s // 60)} min {int(s % 60):02d} s"
    return U.quantity(s, "s")


def summary(provs):
    """The report's provenance line items over every run: commits, build types, first start,
    machines, total wall time (with how many runs recorded it)."""
    def distinct(key):
        vals = sorted({p[key] for p in provs if p[key] != NOT_RECORDED})
        return ", ".join(vals) if vals else NOT_RECORDED

    machines = sorted({f"{p['cpu_model']}, {p['cpu_cores']} cores" for p in provs
                       if p["cpu_model"] != NOT_RECORDED})
    starts = sorted(p["started_utc"] for p in provs if p["started_utc"] != NOT_RECORDED)
    walls = [seconds(p["wall_s"]) for p in provs]
    known = [w for w in walls if w is not None]
    total = duration(sum(known)) if known else NOT_RECORDED
    if known and len(known) < len(walls):
        total += f" (over the {len(known)} of {len(walls)} runs that recorded it)"
    return [("commit", distinct("git_commit")), ("build type", distinct("build_type")),
            ("date", f"{starts[0]} to {starts[-1]}" if len(starts) > 1 else (starts[0] if starts else NOT_RECORDED)),
            ("machine", "; ".join(machines) if machines else NOT_RECORDED), ("wall time, all runs", total)]


def list_entries(repo=REPO):
    """{list label: {run name: file}} of the reproduce lists (an entry's `name`, else its file's stem)."""
    out = {}
    for label, rel in LISTS:
        try:
            with open(os.path.join(repo, rel), "rb") as fh:
                doc = tomllib.load(fh)
        except (OSError, tomllib.TOMLDecodeError):
            continue
        names = {}
        for e in doc.get("experiments", []):
            f = e if isinstance(e, str) else e.get("file", "")
            name = stem(f) if isinstance(e, str) else e.get("name") or stem(f)
            names[name] = f
        out[label] = names
    return out


def where_run(key, lists):
    """The reproduce lists that run the claim `key` at its default setting (an entry named key), or
    its QUICK version (an entry whose file is key_quick.toml)."""
    full = [label for label, names in lists.items() if key in names]
    quick = [label for label, names in lists.items()
             if any(stem(f) == key + "_quick" for f in names.values())]
    return full, quick


def not_run_text(key, lists, experiment=None):
    full, quick = where_run(key, lists)
    parts = (["runs in " + " and ".join(full)] if full else []) + \
        (["its QUICK version runs in " + " and ".join(quick)] if quick else [])
    if parts:
        return "; ".join(parts)
    return f"runs on demand: build/creaturelab run {experiment}" if experiment else "in no reproduce list"


def load_values(path=None):
    """docs/validation/values.json ({} when absent or unreadable)."""
    path = path or os.path.join(REPO, "docs", "validation", "values.json")
    try:
        with open(path, encoding="utf-8") as fh:
            return json.load(fh)
    except (OSError, ValueError):
        return {}


def default_of(values, key, check_name):
    """(got text, commit) of check `check_name` in the default-setting run `key` of values.json, or None."""
    run = values.get("runs", {}).get(key)
    if not run or run.get("setting") == "QUICK":
        return None
    for c in run.get("checks", []):
        if c.get("name") == check_name:
            return c.get("got", ""), run.get("commit", "")
    return None


def distance(got, default_got):
    """(|X - Y|, relative to |Y|, which number) over the numbers of two measured texts of one check
    (the largest element-wise difference), or None when they do not pair up."""
    x, y = U.numbers(got), U.numbers(default_got)
    if not x or len(x) != len(y):
        return None
    d, i = max((abs(a - b), k) for k, (a, b) in enumerate(zip(x, y)))
    rel = d / abs(y[i]) if y[i] != 0 else (0.0 if d == 0 else math.inf)
    return d, rel, i
