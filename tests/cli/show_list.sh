#!/usr/bin/env bash
# `run --dry-run` writes nothing; `show FILE` prints the resolved parameters and the expanded
# points; `list` mentions every kind (and each parameter with its unit and range).
# usage: show_list.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

exp=tests/cli/strand_sweep.toml

# --dry-run: exit 0, the plan on stdout, no folder, no files anywhere under results/runs.
stem_dir=results/runs/strand_sweep
[[ -e $stem_dir ]] && existed=1 || existed=0
"$bin" run "$exp" --dry-run --out "$scratch/dry" >"$scratch/dry.stdout" 2>"$scratch/dry.stderr" || fail "dry run failed"
[[ ! -e $scratch/dry ]] || fail "--dry-run created $scratch/dry"
grep -qF "would write 6 point file(s) to $scratch/dry" "$scratch/dry.stdout" || fail "$(cat "$scratch/dry.stdout")"
grep -q "done in" "$scratch/dry.stderr" && fail "--dry-run ran points"
"$bin" run "$exp" --dry-run >"$scratch/dry2.stdout" 2>&1 || fail "dry run (default folder) failed"
grep -qF "would write 6 point file(s) to $stem_dir" "$scratch/dry2.stdout" || fail "$(cat "$scratch/dry2.stdout")"
((existed)) || [[ ! -e $stem_dir ]] || fail "--dry-run created $stem_dir"
# A dry run still checks the file.
rc=0
"$bin" run "$exp" params.n_springs=-3 --dry-run --out "$scratch/dry" >/dev/null 2>&1 || rc=$?
[[ $rc == 2 ]] || fail "--dry-run with a bad override: exit code $rc, expected 2"

# show: title, kind, resolved parameters (* = set by the file), the swept ones marked, every point.
"$bin" show "$exp" >"$scratch/show.stdout" || fail "show failed"
out=$scratch/show.stdout
grep -qF "cli test: strand cases x spring constant" "$out" || fail "show: no title"
grep -q "^kind: strand" "$out" || fail "show: no kind"
grep -qE '^  \* n_springs = 12$' "$out" || fail "show: n_springs not marked as set: $(cat "$out")"
grep -qE '^    mass_kg = 1e-08 kg$' "$out" || fail "show: default mass_kg with unit: $(cat "$out")"
grep -qE '^    spring_k_n_per_m = \(swept\) N/m$' "$out" || fail "show: swept parameter: $(cat "$out")"
grep -qF "sweep: 6 point(s)" "$out" || fail "show: point count"
grep -qF '  point 0 (rest, layout="rest", overextension=0, spring_k_n_per_m=0.01)' "$out" || fail "show: point 0: $(cat "$out")"
grep -qF '  point 5 (over-extended 150%, layout="overextended", overextension=1.5, spring_k_n_per_m=0.04)' "$out" ||
  fail "show: point 5: $(cat "$out")"
[[ $(grep -c '^  point [0-9]' "$out") == 6 ]] || fail "show: expected 6 point lines"
grep -qF "checks: 1" "$out" || fail "show: checks"
# Overrides and ranges are expanded.
"$bin" show "$exp" "sweep.spring_k_n_per_m=0.1:0.3:0.1" params.n_springs=7 >"$scratch/show2.stdout" || fail "show with overrides"
grep -qF "sweep: 6 point(s)" "$scratch/show2.stdout" || fail "show overrides: count"
grep -qF "spring_k_n_per_m=0.3)" "$scratch/show2.stdout" || fail "show overrides: range: $(cat "$scratch/show2.stdout")"
grep -qE '^  \* n_springs = 7$' "$scratch/show2.stdout" || fail "show overrides: n_springs"

# list: every kind, each parameter with unit, default, range; `list KIND` only that kind.
"$bin" list >"$scratch/list.stdout" || fail "list failed"
kinds=$(find experiments tests/cli -name '*.toml' -exec sed -n 's/^kind *= *"\([^"]*\)".*/\1/p' {} + | sort -u)
for k in oscillator strand $kinds; do
  grep -q "^$k: " "$scratch/list.stdout" || fail "list does not mention kind $k"
done
grep -qE '^  spring_k_n_per_m +N/m +default 0.01 +range \[1e-09, 1e\+06\]' "$scratch/list.stdout" ||
  fail "list: spring_k_n_per_m line: $(grep spring_k "$scratch/list.stdout")"
grep -qE '^  integrator +- +default "rk4" +range "euler" \| "symplectic_euler" \| "rk4" \| "implicit_euler"' \
  "$scratch/list.stdout" || fail "list: integrator choices"
grep -q "metrics:" "$scratch/list.stdout" || fail "list: no metrics"
"$bin" list strand >"$scratch/list_strand.stdout" || fail "list strand failed"
grep -q "^oscillator: " "$scratch/list_strand.stdout" && fail "list strand shows oscillator"
grep -q "^strand: " "$scratch/list_strand.stdout" || fail "list strand"
rc=0
"$bin" list no_such_kind >/dev/null 2>"$scratch/list_bad.stderr" || rc=$?
[[ $rc == 2 ]] || fail "list no_such_kind: exit code $rc, expected 2"
grep -qF "unknown kind 'no_such_kind'" "$scratch/list_bad.stderr" || fail "$(cat "$scratch/list_bad.stderr")"

echo "dry run, show and list behave"
