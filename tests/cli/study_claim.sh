#!/usr/bin/env bash
# A refinement study's unrefined cases are its claim's points, parameter by parameter (study_claim.py):
# the project's 3-D flyer and swimmer studies against their claims. The check can fail: the flesh flyer's
# study without its forcing line (so with flyer3d_convergence.toml's projected forcing) is reported, with
# the key named.
# usage: study_claim.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()

/usr/bin/python3 tests/cli/study_claim.py "$bin" || fail "a refinement study differs from its claim (above)"

broken="$scratch/flesh_study_without_forcing.toml"
sed -e "s#^base = \"flyer3d_convergence.toml\"#base = \"$src/studies/control/flyer3d_convergence.toml\"#" \
    -e '/^forcing = "coupled"$/d' studies/control/flyer3d_flesh_convergence.toml >"$broken"
grep -q "^base = \"$src/" "$broken" || fail "the broken study's base was not rewritten"
if out=$(/usr/bin/python3 tests/cli/study_claim.py "$bin" "$broken" experiments/control/flyer3d_flesh.toml controlled,held); then
  fail "a study without the claim's forcing passed"
fi
grep -q "'held': forcing = 'projected'" <<<"$out" || fail "the difference was not named: $out"
echo "ok"
