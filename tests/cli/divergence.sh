#!/usr/bin/env bash
# A diverging point: RK4 on an undamped oscillator with dt beyond its stability
# limit for one point and within it for the other. The run exits 3; the failed point's file
# exists with status "failed", a message naming the step and time, and the frames computed before
# the failure; the good point is complete; index.h5 records both.
# usage: divergence.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

run=$scratch/run
rc=0
"$bin" run tests/cli/diverge.toml --out "$run" --jobs 2 >"$scratch/stdout" 2>"$scratch/stderr" || rc=$?
cat "$scratch/stdout"
[[ $rc == 3 ]] || fail "exit code $rc, expected 3 (a point failed): $(cat "$scratch/stderr")"
grep -qF "2 point(s), 2 ran, 0 reused, 1 failed" "$scratch/stdout" || fail "summary: $(cat "$scratch/stdout")"
grep -q "point 1 (dt_s=0.5): simulation diverged at step .* FAILED" "$scratch/stderr" ||
  fail "progress does not report the failure: $(cat "$scratch/stderr")"
[[ -f $run/point_000000.h5 && -f $run/point_000001.h5 && -f $run/index.h5 ]] || fail "missing files: $(ls "$run")"

/usr/bin/python3 - "$run" <<'EOF'
import re, sys, h5py, numpy as np
run = sys.argv[1]

def check(cond, msg):
    if not cond:
        sys.exit("FAIL: " + msg)

with h5py.File(f"{run}/point_000001.h5", "r") as f:
    a = f.attrs
    check(a["status"] == "failed", f"bad point status {a['status']!r}")
    msg = a["message"]
    m = re.search(r"diverged at step (\d+) \(t = ([0-9.e+-]+) s\)", msg)
    check(m is not None, f"message does not name the step and time: {msg}")
    step, t_fail = int(m.group(1)), float(m.group(2))
    check(abs(t_fail - 0.5 * step) < 1e-9, f"step {step} at dt 0.5 s is not t = {t_fail} s")
    check("rk4" in msg and "omega_max*dt" in msg, f"message does not name the likely cause: {msg}")
    check(a["dt_s"] == 0.5, "dt_s attribute")
    t = f["timeseries/time_s"][()]
    check(0 < len(t) and t[-1] <= t_fail, f"partial series expected up to t = {t_fail} s, got {len(t)} frames")
    check("metrics" not in f or len(f["metrics"]) == 0, "a failed point has no metrics")

with h5py.File(f"{run}/point_000000.h5", "r") as f:
    check(f.attrs["status"] == "ok", "good point status")
    check(f.attrs["message"] == "", "good point message")
    t = f["timeseries/time_s"][()]
    check(abs(t[-1] - 200.0) < 1e-9, f"good point ends at {t[-1]}")
    # Stable: RK4 at omega*dt = 0.63 loses energy slowly, never gains it.
    e = f["metrics/final_energy_ratio"][()]
    check(0 < e <= 1, f"good point energy ratio {e}")

with h5py.File(f"{run}/index.h5", "r") as f:
    s = f["sweep"]
    check(list(s["status"].asstr()[()]) == ["ok", "failed"], "index statuses")
    check("diverged" in s["message"].asstr()[1], "index message")
    m = s["max_abs_error_m"][()]
    check(np.isfinite(m[0]) and np.isnan(m[1]), f"index metrics {m}")
    check(set(f["points"].keys()) == {"point_000000", "point_000001"}, "index links both points")
print("failed point recorded with its message; the good point is complete")
EOF

# Resume keeps the recorded failure (a point file that exists is whole) and says so again.
rc=0
"$bin" run tests/cli/diverge.toml --out "$run" --jobs 2 --resume >"$scratch/resume.stdout" 2>"$scratch/resume.stderr" || rc=$?
[[ $rc == 3 ]] || fail "--resume of a run with a failed point: exit code $rc, expected 3"
grep -qF "2 point file(s) already complete, 0 to run" "$scratch/resume.stderr" || fail "$(cat "$scratch/resume.stderr")"
echo "divergence recorded; exit code 3"
