#!/usr/bin/env bash
# The reproduction report, end to end on quick runs: `creaturelab reproduce --list --out`
# runs a list (a path and an {file, set, name} entry); a fit folder beside them; analysis/draw_runs.py
# draws them; analysis/report.py writes report.html and REPORT.md and names them last.
# tests/cli/check_report.py then parses report.html with html.parser: every image exists and is a
# valid PNG, every check of every run is in a row with its status (ok, FAILED and KNOWN all occur
# here), the four papers have sections, the headline's verdict counts equal the figures' verdicts, no
# path into the seed papers, a QUICK run is labelled. A run the catalog does not know (an oscillator
# with a made-up name, QUICK by its `set`) appears under "Other runs" with the figures its kind's
# plotter drew; its distance from a default's values (values.json) is shown; an /checks/inconclusive
# column makes its verdict "inconclusive on the quick setting". A bad list entry exits 2.
# usage: report.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
py=/usr/bin/python3

# An oscillator run with one check that passes, one that fails and one known deviation.
cat >"$scratch/osc.toml" <<'TOML'
kind = "oscillator"
title = "three statuses"
[params]
end_time_s = 2.0
[sweep]
integrator = ["symplectic_euler", "rk4"]
[[check]]
name = "rk4 is the most accurate"
type = "argmin"
metric = "max_abs_error_m"
axis = "integrator"
expect = "rk4"
[[check]]
name = "symplectic Euler is the most accurate (it is not)"
type = "argmin"
metric = "max_abs_error_m"
axis = "integrator"
expect = "symplectic_euler"
[[check]]
name = "a deviation we know about"
type = "argmin"
metric = "max_abs_error_m"
axis = "integrator"
expect = "symplectic_euler"
known_deviation = "rk4 is more accurate; kept to show KNOWN in the report"
TOML
cat >"$scratch/list.toml" <<TOML
experiments = [
  "experiments/web/strand_layouts.toml",
  { file = "$scratch/osc.toml", name = "made_up_oscillator", set = ["params.end_time_s=1.5"] },
  { file = "experiments/control/parallel_dofs.toml", set = ["params.frames=20"] },
]
TOML
rc=0
"$bin" reproduce --list "$scratch/list.toml" --out "$scratch/root" --jobs 2 >"$scratch/reproduce.stdout" 2>/dev/null || rc=$?
[[ $rc == 1 ]] || fail "reproduce exit code $rc, expected 1 (one check fails)"
[[ -f $scratch/root/strand_layouts/index.h5 && -f $scratch/root/made_up_oscillator/index.h5 ]] ||
  fail "run folders not named as the list says: $(ls "$scratch/root")"
grep -q "made_up_oscillator: a deviation we know about" "$scratch/reproduce.stdout" || fail "check table lacks the run name"

# A fit folder: the spline fitted to a CSV over 3 periods.
$py - "$scratch/profile.csv" <<'PY'
import sys, math
with open(sys.argv[1], "w") as out:
    out.write("time_s,value\n")
    for i in range(200):
        t = 3.6 * i / 199
        out.write(f"{t!r},{0.78 + 0.22 * math.cos(2 * math.pi * t / 1.2)!r}\n")
PY
"$bin" fit spline "$scratch/profile.csv" --knots 4 --period 1.2 --out "$scratch/root/fit_spline" >/dev/null ||
  fail "fit spline failed"

$py analysis/draw_runs.py "$scratch/root" >"$scratch/draw.stdout" 2>&1 || { cat "$scratch/draw.stdout" >&2; fail "draw_runs failed"; }
grep -q "figures ok: .*strand_layouts (figures/mehla_fig5_2.py)" "$scratch/draw.stdout" || fail "Fig. 5.2 not drawn"
grep -q "figures ok: .*fit_spline (figures/fit_spline.py)" "$scratch/draw.stdout" || fail "fit figure not drawn"
$py analysis/report.py "$scratch/root" >"$scratch/report.stdout" || fail "report.py failed"
[[ $(tail -n 1 "$scratch/report.stdout") == "report: $scratch/root/REPORT.md" ]] ||
  fail "the last line does not name the report: $(tail -n 2 "$scratch/report.stdout")"
tail -n 2 "$scratch/report.stdout" | head -n 1 | grep -qF "report: $scratch/root/report.html" || fail "report.html not named"

$py tests/cli/check_report.py "$scratch/root" || fail "report.html does not show every figure and check"
grep -q "<h2 id=\"other-runs\">Other runs</h2>" "$scratch/root/report.html" || fail "no Other runs section"
grep -q "made_up_oscillator/figures/integrators.png" "$scratch/root/report.html" ||
  fail "the uncatalogued run's figures are not in the report"
grep -q "mehla_fig5_2.png" "$scratch/root/report.html" || fail "Fig. 5.2 is not in the report"
grep -q 'class="known">KNOWN</td>' "$scratch/root/report.html" || fail "no KNOWN row"
grep -q 'class="failed">FAILED</td>' "$scratch/root/report.html" || fail "no FAILED row"
grep -q "rk4 is more accurate; kept to show KNOWN" "$scratch/root/report.html" || fail "the KNOWN reason is missing"
grep -q "not run in this list" "$scratch/root/report.html" || fail "catalogued figures without runs are not marked"
grep -q "runs in make reproduce" "$scratch/root/report.html" || fail "a figure not run does not name the list that runs it"
grep -q '<code>made_up_oscillator</code>, setting <span class="setting">QUICK</span>' "$scratch/root/report.html" ||
  fail "the run with set overrides is not labelled QUICK"
grep -q '<code>strand_layouts</code>, setting <span class="setting">default</span>' "$scratch/root/report.html" ||
  fail "the claim run is not labelled default"
grep -q "distance from default not measured" "$scratch/root/report.html" || fail "a QUICK run without default values says nothing"
grep -q "mid_sag_m strictly decreasing in overextension</td><td>[0-9.]*, [0-9.]*, [0-9.]*, [0-9.]* mm</td>" \
  "$scratch/root/report.html" || fail "Fig. 5.2's sags are not in mm"

# Lentine Fig. 10 as a table: the paper's seconds per frame beside ours (the QUICK parallel_dofs).
grep -q '<td>1</td><td>14 s</td><td>14 s</td><td>[0-9.]* [µm]*s</td><td>[0-9.]* [µm]*s</td><td>not run</td>' \
  "$scratch/root/report.html" || fail "no Fig. 10 table with our seconds per frame"
grep -q '<td>Human minimizing effort on back (gravity)</td><td>0.26 s</td><td>not run</td>' "$scratch/root/report.html" ||
  fail "no Fig. 14 table"

# The default's values (values.json): the QUICK run's distance from them, in its unit.
$py - "$scratch/root/made_up_oscillator" "$scratch/values.json" <<'PY'
import json, re, sys
sys.path.insert(0, "analysis")
from figures import runs
with runs.Run(sys.argv[1]) as r:
    checks = [{"name": c["name"], "got": re.sub(r"=([0-9.e+-]+)", lambda m: "=" + repr(float(m.group(1)) * 1.1), c["got"]),
               "passed": c["passed"], "status": c["status"]} for c in r.checks]
json.dump({"runs": {"made_up_oscillator": {"setting": "default", "commit": "abc1234", "checks": checks}}}, open(sys.argv[2], "w"))
PY
$py analysis/report.py "$scratch/root" --values "$scratch/values.json" >/dev/null || fail "report.py --values failed"
grep -q "default: integrator=&quot;rk4&quot; (max_abs_error_m=[0-9.]* [nµm]*m) (default setting, commit abc1234), distance [0-9.]* [nµm]*m (9.1 %)" \
  "$scratch/root/report.html" || fail "the QUICK run's distance from the default is not shown"

# Every check of the QUICK run inconclusive but the first: the verdict says so, and the checker agrees.
mkdir "$scratch/root2" && cp -r "$scratch/root/made_up_oscillator" "$scratch/root2/"
$py - "$scratch/root2/made_up_oscillator/index.h5" <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r+") as f:
    if "inconclusive" in f["checks"]:  # the runner writes the column (all 0 here)
        del f["checks"]["inconclusive"]
    f["checks"].create_dataset("inconclusive", data=np.array([0, 1, 1], dtype=np.int8))
PY
# ... and the provenance the runner records (index.h5's root attributes) at the top.
$py - "$scratch/root2/made_up_oscillator/index.h5" <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r+") as f:
    f.attrs.update({"build_type": "Release", "cpu_model": "Test CPU", "cpu_cores": np.int64(2),
                    "started_utc": "at the start", "wall_s": 75.5})
PY
$py analysis/report.py "$scratch/root2" >/dev/null || fail "report.py failed on an inconclusive run"
$py tests/cli/check_report.py "$scratch/root2" >/dev/null || fail "the inconclusive report does not check"
grep -q '<h3 id="run-made-up-oscillator">made_up_oscillator: <span class="inconclusive">inconclusive on the quick setting</span>' \
  "$scratch/root2/report.html" || fail "no inconclusive verdict"
grep -q '<td class="inconclusive">inconclusive</td><td>symplectic Euler is the most accurate' "$scratch/root2/report.html" ||
  fail "the inconclusive check's status"
for row in "<td>build type</td><td>Release</td>" "<td>machine</td><td>Test CPU, 2 cores</td>" \
  "<td>date</td><td>at the start</td>" "<td>wall time, all runs</td><td>1 min 15 s</td>"; do
  grep -qF "$row" "$scratch/root2/report.html" || fail "provenance: no $row"
done
grep -q "<td>build type</td><td>" "$scratch/root/report.html" || fail "no build type in the provenance"
grep -q "0 reproduced, 0 deviates, 0 FAILED, 0 inconclusive on the quick setting, [0-9]* not run in this list" \
  "$scratch/root2/report.html" || fail "a folder without paper runs: every figure not run"

# The checker fails on a broken image and on a missing check.
cp "$scratch/root/report.html" "$scratch/report.good"
png=$(ls "$scratch"/root/strand_layouts/figures/mehla_fig5_2.png)
printf 'not a png' >"$png"
! $py tests/cli/check_report.py "$scratch/root" >"$scratch/bad.stdout" || fail "a broken PNG passed"
grep -q "mehla_fig5_2.png: not a PNG" "$scratch/bad.stdout" || fail "the broken PNG is not named: $(cat "$scratch/bad.stdout")"
$py analysis/figures/mehla_fig5_2.py "$scratch/root/strand_layouts" >/dev/null
sed 's/rk4 is the most accurate/rk4 is accurate/' "$scratch/report.good" >"$scratch/root/report.html"
! $py tests/cli/check_report.py "$scratch/root" >"$scratch/bad.stdout" || fail "a missing check passed"
grep -q 'check "rk4 is the most accurate" (ok) is not in report.html' "$scratch/bad.stdout" || fail "missing check not named"
# ... on a headline that miscounts, a path into the seeds, a QUICK run unlabelled, a paper missing.
sed -E 's/([0-9]+) not run in this list/1\1 not run in this list/' "$scratch/report.good" >"$scratch/root/report.html"
! $py tests/cli/check_report.py "$scratch/root" >"$scratch/bad.stdout" || fail "a miscounting headline passed"
grep -q "headline: 1[0-9]* not run in this list, the summary table" "$scratch/bad.stdout" || fail "miscount not named"
sed 's|</body>|<p>../shared/seeds/x.txt</p></body>|' "$scratch/report.good" >"$scratch/root/report.html"
! $py tests/cli/check_report.py "$scratch/root" >/dev/null || fail "a path into the seeds passed"
sed 's|setting <span class="setting">QUICK</span>|setting default|' "$scratch/report.good" >"$scratch/root/report.html"
! $py tests/cli/check_report.py "$scratch/root" >"$scratch/bad.stdout" || fail "an unlabelled QUICK run passed"
grep -q "made_up_oscillator: a QUICK run not labelled QUICK" "$scratch/bad.stdout" || fail "unlabelled QUICK run not named"
sed 's|<h2 id="paper-tu">Tu 1996|<h2 id="paper-tu">T. 1996|' "$scratch/report.good" >"$scratch/root/report.html"
! $py tests/cli/check_report.py "$scratch/root" >"$scratch/bad.stdout" || fail "a missing paper section passed"
grep -q "no section for Tu 1996" "$scratch/bad.stdout" || fail "the missing paper not named"
cp "$scratch/report.good" "$scratch/root/report.html"

# Numbers with units: SI prefixes, three significant digits, or the digits a standard error resolves.
$py - <<'PY' || fail "report_units formats numbers wrongly"
import sys
sys.path.insert(0, "analysis")
import report_units as U
cases = [(U.quantity(0.00106039, "m/s"), "1.06 mm/s"), (U.quantity(0.65, "Hz"), "0.650 Hz"),
         (U.quantity(3333, ""), "3333"), (U.quantity(1.0261e-6, "rad"), "1.03 µrad"),
         (U.quantity(0.0547852, "m", uncertainty=0.0004), "54.8 mm"), (U.quantity(2.33988e-16, ""), "2.34e-16"),
         (U.got_text("[0.0309, 0.00713] over 2 points", "m", {}), "[30.9, 7.13] mm over 2 points"),
         (U.got_text("0.0151378 +- 0.00213 (2 s.e.: [0.0108, 0.0194])", "m", {}), "15.1 ± 2.1 mm (2 s.e.: [10.8, 19.4] mm)"),
         (U.got_text("0.0151378 +- 0.00213 (95%, 1 dof: [-0.0119, 0.0422])", "m", {}),
          "15.1 ± 2.1 mm (95%, 1 dof: [-11.9, 42.2] mm)"),
         (U.got_text("1.3 +- 0.1 (no interval: 0 dof)", "", {}), "1.30 ± 0.10 (no interval: 0 dof)"),
         (U.got_text('integrator="rk4" (max_abs_error_m=1.90882e-09)', "", {"max_abs_error_m": "m"}),
          'integrator="rk4" (max_abs_error_m=1.91 nm)'),
         (U.expected_text("hub_rms_displacement_m in [0.05, 0.06]", "m", [0.0547852]), "hub_rms_displacement_m in [50, 60] mm"),
         (U.expected_text("mean_up_force_n ratio in [1, 1e+09]", ""), "mean_up_force_n ratio ≥ 1"),
         # a value just past a bound keeps the digits that show it is past: a fail never reads as a pass
         (U.check_texts({"type": "ratio", "expected": "d ratio in [0.95, 1.05]", "got": "1.0506"}, {})[1], "1.051"),
         (U.check_texts({"type": "ratio", "expected": "d ratio in [0.95, 1.05]", "got": "0.94996"}, {})[1], "0.94996"),
         (U.check_texts({"type": "ratio", "expected": "d ratio in [0.95, 1.05]", "got": "1.03214"}, {})[1], "1.03")]
bad = [(got, want) for got, want in cases if got != want]
assert not bad, bad
PY

# A bad list entry: exit 2, nothing run.
printf 'experiments = [{ file = "experiments/web/default.toml", sett = [] }]\n' >"$scratch/bad.toml"
rc=0
"$bin" reproduce --list "$scratch/bad.toml" --out "$scratch/bad_root" >/dev/null 2>"$scratch/bad.stderr" || rc=$?
[[ $rc == 2 ]] || fail "bad list: exit $rc, expected 2"
grep -q 'unknown key "sett"' "$scratch/bad.stderr" || fail "bad list: $(cat "$scratch/bad.stderr")"
[[ ! -e $scratch/bad_root ]] || fail "bad list: something was written"

# Every figure module draw_runs.py runs exists; the 3-D renders' rows (drawn by `creaturelab render
# --figures`, no module) are not run as modules (draw_runs.py would fail on them and
# make reproduce exit 4).
$py - <<'PY' || fail "the catalog names figure modules draw_runs.py cannot run"
import sys
sys.path.insert(0, "analysis")
from figures import catalog
missing = [(f.run, m) for f in catalog.FIGURES for m in catalog.module_of_run(f.run) if not catalog.has_module(m)]
assert not missing, missing
assert catalog.module_of_run("render_swim") == [], catalog.module_of_run("render_swim")
PY
echo "ok"
