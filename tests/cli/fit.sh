#!/usr/bin/env bash
# `creaturelab fit` end to end.
#  spline: fitted to a short jellyfish run's driving curve (exact knots) and its diameter_ratio
#          (the HDF5 output's datasets and shapes); the params.toml fragment, appended to an
#          experiment header, runs as it is and carries the fitted knots; a CSV with a detected
#          period; bad input (NaN row, too few samples, less than a period, bounds excluding the
#          start, unknown option values) exits 2 with one "error:" line and writes nothing.
#  controller: a tiny fit gives identical datasets with --jobs 1 and --jobs 2; killed with SIGKILL
#          0.4 s after its first record, --resume reuses the recorded runs and ends identical to an
#          uninterrupted fit; an existing record needs --resume or --force; a bad file exits 2.
# usage: fit.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
py=/usr/bin/python3

# expect_bad NAME PATTERN ARGS...: `creaturelab fit ARGS` exits 2, one error line naming the
# problem, nothing on stdout, $scratch/out_NAME not created.
expect_bad() {
  local name=$1 pattern=$2
  shift 2
  local out=$scratch/out_$name err=$scratch/$name.stderr std=$scratch/$name.stdout rc=0
  "$bin" fit "$@" --out "$out" >"$std" 2>"$err" || rc=$?
  [[ $rc == 2 ]] || { cat "$err" >&2; fail "$name: exit code $rc, expected 2"; }
  [[ $(wc -l <"$err") == 1 ]] || { cat "$err" >&2; fail "$name: expected one line on stderr"; }
  grep -q '^error: ' "$err" || fail "$name: stderr does not start with 'error: ': $(cat "$err")"
  grep -qF -- "$pattern" "$err" || fail "$name: stderr does not name the problem ('$pattern'): $(cat "$err")"
  [[ ! -s $std ]] || fail "$name: wrote to stdout: $(cat "$std")"
  [[ ! -e $out ]] || fail "$name: created $out"
  echo "ok   $name: $(cat "$err")"
}

# --- a short jellyfish run to fit: 2 cycles on the 50² grid
cat >"$scratch/swim.toml" <<TOML
kind = "jellyfish"
title = "two cycles"
[params]
cells = 50
$jellyfish_earlier_defaults
duration_s = 2.857142857142857
TOML
"$bin" run "$scratch/swim.toml" --out "$scratch/swim" --jobs 1 >/dev/null 2>&1 || fail "jellyfish run failed"

# The series of the driving curve gives back the default knots (1 at 0, 0.56 at 0.3, flat).
"$bin" fit spline "$scratch/swim" --dataset timeseries/aperture_muscle_factor --phases 0,0.3 \
  --out "$scratch/factor" >"$scratch/factor.stdout" || fail "fit spline (aperture_muscle_factor) failed"
grep -q "period 1.4285714285714286 s (1 / contraction_hz of the point)" "$scratch/factor.stdout" ||
  fail "the period was not taken from the point: $(cat "$scratch/factor.stdout")"
$py - "$scratch/factor/spline_fit.h5" <<'PY' || fail "driving-curve knots not recovered"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1])
v, t = f["knots/value"][:], f["knots/tangent"][:]
assert np.allclose(v, [1.0, 0.56], atol=1e-10, rtol=0), v
assert np.allclose(t, [0.0, 0.0], atol=1e-8, rtol=0), t
assert f["residual_rms"][()] < 1e-12
PY

# The bell's diameter_ratio, 4 knots: the output's datasets.
"$bin" fit spline "$scratch/swim/point_000000.h5" --knots 4 --out "$scratch/ratio" >"$scratch/ratio.stdout" ||
  fail "fit spline (diameter_ratio) failed"
$py - "$scratch/ratio/spline_fit.h5" <<'PY' || fail "spline_fit.h5 is not as documented"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1])
assert f["knots/phase"][:].tolist() == [0.0, 0.25, 0.5, 0.75]
for name in ["value", "tangent", "value_sigma", "tangent_sigma", "value_at_bound", "start_value", "start_tangent"]:
    assert f["knots/" + name].shape == (4,), name
assert f["covariance"].shape == (8, 8)
c = f["covariance"][:]
assert np.allclose(c, c.T) and np.all(np.diag(c) > 0)
n = f["data/value"].shape[0]
for name in ["time_s", "phase", "weight", "fitted", "residual"]:
    assert f["data/" + name].shape == (n,), name
r = f["data/fitted"][:] - f["data/value"][:]
assert abs(np.sqrt(np.mean(r * r)) - f["residual_rms"][()]) < 1e-12
assert f["curve/value"].shape == f["curve/phase"].shape == (501,)
assert f.attrs["period_s"] == 1 / 0.7 and f.attrs["loss"] == "none"
PY

# The fragment, appended to an experiment header (and followed by more [params] lines), runs.
{
  echo 'kind = "jellyfish"'
  echo 'title = "the fitted curve"'
  cat "$scratch/ratio/params.toml"
  echo 'cells = 50'
  echo 'duration_s = 1.0'
  echo "$jellyfish_earlier_defaults"  # the fitted knots drive the Hermite curve, as in the swim above
} >"$scratch/merged.toml"
"$bin" run "$scratch/merged.toml" --out "$scratch/merged" --jobs 1 >/dev/null 2>"$scratch/merged.stderr" ||
  fail "the merged fragment was not accepted: $(cat "$scratch/merged.stderr")"
$py - "$scratch/ratio/spline_fit.h5" "$scratch/merged/point_000000.h5" <<'PY' || fail "the run does not carry the fitted knots"
import sys, h5py
fit, point = h5py.File(sys.argv[1]), h5py.File(sys.argv[2])
assert point.attrs["contraction_knots"] == 4
for k in range(4):
    for field in ["phase", "value", "tangent"]:
        assert point.attrs[f"knot{k}_{field}"] == fit["knots/" + field][k], (k, field)
PY
echo "ok   spline: driving knots recovered; fragment accepted by run"

# A CSV over 3 periods of 1.2 s, period detected; weights column.
$py - "$scratch/profile.csv" <<'PY'
import sys, math
with open(sys.argv[1], "w") as out:
    out.write("time_s,value,weight\n")
    for i in range(300):
        t = 3.6 * i / 299
        out.write(f"{t!r},{0.78 + 0.22 * math.cos(2 * math.pi * t / 1.2)!r},1\n")
PY
"$bin" fit spline "$scratch/profile.csv" --knots 4 --out "$scratch/csv" >"$scratch/csv.stdout" ||
  fail "fit spline (csv) failed"
grep -q "detected (YIN" "$scratch/csv.stdout" || fail "no period detected: $(cat "$scratch/csv.stdout")"
$py -c "
import h5py; f = h5py.File('$scratch/csv/spline_fit.h5')
assert abs(f.attrs['period_s'] - 1.2) < 1e-3, f.attrs['period_s']" || fail "detected period is not 1.2 s"

# --- bad input
printf 'time_s,value\n0,1\n0.1,nan\n0.2,0.9\n' >"$scratch/nan.csv"
expect_bad nan_row "nan.csv:3: value is nan: remove the row" spline "$scratch/nan.csv" --period 1
head -n 10 "$scratch/profile.csv" >"$scratch/few.csv"
expect_bad too_few "too few samples" spline "$scratch/few.csv" --period 0.02
expect_bad short_period "less than one period" spline "$scratch/profile.csv" --period 5
expect_bad start_outside "exclude the start value 0.5 of knot 1" spline "$scratch/profile.csv" --period 1.2 \
  --phases 0,0.5 --start-values 1,0.5
expect_bad loss "--loss tukey: expected none | huber | cauchy" spline "$scratch/profile.csv" --period 1.2 --loss tukey
expect_bad no_dataset "no dataset 'timeseries/diameter'" spline "$scratch/swim" --dataset timeseries/diameter
sed 's/name = "stagger"/name = "stager"/' tests/cli/fit_controller_tiny.toml >"$scratch/bad_name.toml"
expect_bad unknown_param "unknown parameter 'stager' for kind 'jellyfish' (did you mean 'stagger'?)" \
  controller "$scratch/bad_name.toml"

# --- controller: --jobs 1 against --jobs 2
ctl=tests/cli/fit_controller_tiny.toml
"$bin" fit controller "$ctl" --out "$scratch/ctl1" --jobs 1 >"$scratch/ctl1.stdout" 2>/dev/null || fail "fit controller --jobs 1"
"$bin" fit controller "$ctl" --out "$scratch/ctl2" --jobs 2 >/dev/null 2>&1 || fail "fit controller --jobs 2"
same() {  # same A B: every dataset equal bitwise except the runs' wall times
  $py - "$1" "$2" <<'PY'
import sys, h5py, numpy as np
a, b = h5py.File(sys.argv[1]), h5py.File(sys.argv[2])
names = []
a.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
other = []
b.visititems(lambda n, o: other.append(n) if isinstance(o, h5py.Dataset) else None)
assert names == other, (names, other)
for n in names:
    if n == "evaluations/wall_s":
        continue
    x, y = a[n][()], b[n][()]
    if isinstance(x, (np.ndarray, np.floating)) and x.dtype.kind == "f":  # bitwise: NaN metrics compare too
        assert x.shape == y.shape and x.tobytes() == y.tobytes(), n
    else:
        assert np.array_equal(x, y), n
print(len(names), "datasets equal")
PY
}
same "$scratch/ctl1/controller_fit.h5" "$scratch/ctl2/controller_fit.h5" || fail "--jobs 1 and --jobs 2 differ"
grep -q "distance_per_cycle_m" "$scratch/ctl1.stdout" || fail "no objective in the summary: $(cat "$scratch/ctl1.stdout")"
rc=0
"$bin" fit controller "$ctl" --out "$scratch/ctl1" >/dev/null 2>"$scratch/exists.stderr" || rc=$?
[[ $rc == 2 ]] && grep -qF "exists: --resume to continue that fit or --force to start over" "$scratch/exists.stderr" ||
  fail "a second fit into a folder with a record: exit $rc, $(cat "$scratch/exists.stderr")"

# --- controller: SIGKILL after the first record, then --resume
run=$scratch/killed
"$bin" fit controller "$ctl" --out "$run" --jobs 1 >/dev/null 2>"$scratch/killed.stderr" &
pid=$!
deadline=$((SECONDS + 60))
while [[ ! -e $run/controller_fit.h5 ]]; do
  kill -0 "$pid" 2>/dev/null || fail "the fit ended before it could be killed ($(cat "$scratch/killed.stderr"))"
  ((SECONDS < deadline)) || { kill -9 "$pid"; fail "no record after 60 s"; }
  sleep 0.02
done
sleep 0.4  # a few batches more (the whole fit takes seconds)
kill -9 "$pid"
wait "$pid" 2>/dev/null || true
recorded=$($py -c "import h5py; print(h5py.File('$run/controller_fit.h5')['evaluations/x'].shape[0])")
complete=$($py -c "import h5py; print(bool(h5py.File('$run/controller_fit.h5').attrs['complete']))")
[[ $complete == False ]] || fail "the fit was complete before the kill: make it slower"
"$bin" fit controller "$ctl" --out "$run" --jobs 2 --resume >"$scratch/resume.stdout" 2>"$scratch/resume.stderr" ||
  fail "--resume failed: $(cat "$scratch/resume.stderr")"
grep -qF "$recorded recorded evaluation(s) to reuse" "$scratch/resume.stderr" ||
  fail "--resume did not load the record: $(cat "$scratch/resume.stderr")"
grep -qF "$recorded reused from the record" "$scratch/resume.stdout" ||
  fail "--resume did not reuse the $recorded recorded runs: $(cat "$scratch/resume.stdout")"
same "$scratch/ctl1/controller_fit.h5" "$run/controller_fit.h5" || fail "the resumed fit differs from an uninterrupted one"
cmp "$scratch/ctl1/params.toml" "$run/params.toml" || fail "params.toml differs after --resume"
echo "ok   controller: --jobs 1 == --jobs 2; killed after $recorded evaluations, --resume reused them and matches"
