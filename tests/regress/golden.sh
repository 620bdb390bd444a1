#!/usr/bin/env bash
# Golden digests: each tests/regress/golden/NAME.toml is a short run whose `creaturelab digest` (a
# SHA-256 of every dataset and non-provenance attribute of each point file and of index.h5) is
# committed as tests/regress/golden/NAME.digest. One changed byte of any dataset fails the test. A
# run with several points must give the same digest with --jobs 1 and --jobs 2.
#
# index.h5 also holds the experiment file's text: editing NAME.toml (a comment too) changes its digest.
#
# A change that moves results updates the .digest in the same commit and says why in the message:
#   UPDATE_GOLDEN=1 ctest --test-dir build -R regress_golden
#   UPDATE_GOLDEN=1 bash tests/regress/golden.sh build/creaturelab . build/regress/golden [NAME...]
#
# usage: golden.sh CREATURELAB SOURCE_DIR SCRATCH_DIR [NAME...]   (no NAME: every golden file)
set -euo pipefail
bin=$1 src=$2 scratch=$3
shift 3
cd "$src"
dir=tests/regress/golden
names=("$@")
if [[ ${#names[@]} == 0 ]]; then
  for f in "$dir"/*.toml; do names+=("$(basename "$f" .toml)"); done
fi
rm -rf "$scratch"
mkdir -p "$scratch"

# digest_of NAME JOBS: runs NAME with --jobs JOBS into the scratch folder; prints the digest file.
digest_of() {
  local name=$1 jobs=$2 out=$scratch/${1}_jobs$2 rc=0
  "$bin" run "$dir/$name.toml" --out "$out" --force --jobs "$jobs" >"$out.stdout" 2>"$out.stderr" || rc=$?
  if [[ $rc != 0 ]]; then
    cat "$out.stderr" >&2
    echo "FAIL: $name: creaturelab run exited $rc (--jobs $jobs)" >&2
    exit 1
  fi
  "$bin" digest "$out" >"$out.digest" || { echo "FAIL: $name: creaturelab digest $out exited $?" >&2; exit 1; }
  echo "$out.digest"
}

failed=0
for name in "${names[@]}"; do
  [[ -f $dir/$name.toml ]] || { echo "FAIL: no $dir/$name.toml" >&2; exit 1; }
  start=$SECONDS
  got=$(digest_of "$name" 1)
  if (($(grep -c ' point_' "$got") > 1)); then
    got2=$(digest_of "$name" 2)
    if ! diff -u --label "$name --jobs 1" --label "$name --jobs 2" "$got" "$got2"; then
      echo "FAIL: $name: --jobs 1 and --jobs 2 give different datasets (determinism across threads)" >&2
      failed=1
      continue
    fi
  fi
  golden=$dir/$name.digest
  if [[ ${UPDATE_GOLDEN:-0} == 1 ]]; then
    cp "$got" "$golden"
    echo "updated $golden ($((SECONDS - start)) s): commit it with the change and say why in the message"
  elif [[ ! -f $golden ]]; then
    echo "FAIL: $name: no $golden; write it with UPDATE_GOLDEN=1 (see the head of $0)" >&2
    failed=1
  elif diff -u --label "$golden (committed)" --label "$name (this build)" "$golden" "$got"; then
    echo "ok   $name: the same digests ($((SECONDS - start)) s)"
  else
    echo "FAIL: $name: the run's digests differ from $golden (lines above: - committed, + this build)." >&2
    echo "  The run folder is $scratch/${name}_jobs1. If the change of results is intended, rewrite the" >&2
    echo "  golden file with UPDATE_GOLDEN=1 (see the head of $0), commit it with the change and say why." >&2
    failed=1
  fi
done
exit $failed
