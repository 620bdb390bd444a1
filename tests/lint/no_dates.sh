#!/usr/bin/env bash
# The product is not a lab notebook: no calendar date (year-month-day) in any git-tracked file under
# src/, tests/ or experiments/, and no path into ../shared (it exists only on the developers' machines;
# papers are cited by reference) under src/, analysis/ or experiments/. Prints file:line:text of each
# hit and exits 1 if there is one.
# usage: no_dates.sh SOURCE_DIR      check the repository at SOURCE_DIR
#        no_dates.sh --self-test     check that both rules fire on a scratch repository, and only there
set -euo pipefail

# The patterns are built from pieces so that this file does not match them itself.
dd='[0-9][0-9]'
date_re="20${dd}-[01][0-9]-[0-3][0-9]"
shared_re='\.\./''shared'

# hits ROOT REGEX DIR...: file:line:text of every match in the tracked files under the DIRs (every
# file when ROOT is not a git work tree).
hits() {
  local root=$1 re=$2
  shift 2
  local dirs=()
  for d in "$@"; do [[ -e $root/$d ]] && dirs+=("$d"); done
  ((${#dirs[@]})) || return 0
  if git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    git -C "$root" grep -n -I -E -e "$re" -- "${dirs[@]}" || true
  else
    (cd "$root" && grep -rn -I -E -e "$re" -- "${dirs[@]}") || true
  fi
}

# check ROOT: prints the hits, returns 1 if any.
check() {
  local root=$1 dates shared
  dates=$(hits "$root" "$date_re" src tests experiments)
  shared=$(hits "$root" "$shared_re" src analysis experiments)
  [[ -z $dates && -z $shared ]] && return 0
  if [[ -n $dates ]]; then
    echo "a date in the product (history belongs in git and CHANGELOG.md, measurements in docs/validation):"
    echo "$dates"
  fi
  if [[ -n $shared ]]; then
    echo "a path into ../shared (cite the paper by authors, title and section instead):"
    echo "$shared"
  fi
  return 1
}

self_test() {
  local tmp
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' RETURN
  git -C "$tmp" init -q
  mkdir -p "$tmp/src" "$tmp/tests" "$tmp/experiments" "$tmp/analysis" "$tmp/docs"
  echo "// clean" >"$tmp/src/a.cpp"
  echo "# the changelog may carry dates: 20${dd:0:0}26-12-05" >"$tmp/docs/CHANGELOG.md"
  git -C "$tmp" add -A
  check "$tmp" >/dev/null || { echo "self-test: a clean tree was flagged"; return 1; }
  local day=05 out
  printf '// measured %s-12-%s\n' 2026 "$day" >"$tmp/tests/b.cpp"
  echo "// an untracked file is not the product: 2026-12-$day" >"$tmp/src/untracked.cpp"
  git -C "$tmp" add tests/b.cpp
  if out=$(check "$tmp"); then echo "self-test: a tracked date was not flagged"; return 1; fi
  grep -q '^tests/b.cpp:1:' <<<"$out" || { echo "self-test: no file:line for the date: $out"; return 1; }
  grep -q untracked <<<"$out" && { echo "self-test: an untracked file was flagged: $out"; return 1; }
  git -C "$tmp" rm -q --cached tests/b.cpp && rm "$tmp/tests/b.cpp"
  check "$tmp" >/dev/null || { echo "self-test: flagged after the date was removed"; return 1; }
  printf 'seed = "../%s/seeds/x.txt"\n' shared >"$tmp/analysis/c.py"
  git -C "$tmp" add analysis/c.py
  if out=$(check "$tmp"); then echo "self-test: a ../shared path was not flagged"; return 1; fi
  grep -q '^analysis/c.py:1:' <<<"$out" || { echo "self-test: no file:line for the path: $out"; return 1; }
  echo "self-test: dates and ../shared paths are found, with file and line"
}

case "${1:-}" in
  --self-test) self_test ;;
  "" | -h | --help) sed -n '2,7p' "$0" >&2; exit 2 ;;
  *)
    [[ -d $1 ]] || { echo "no_dates.sh: no such folder: $1" >&2; exit 2; }
    check "$1" || exit 1
    echo "no dates under src/, tests/, experiments/; no ../shared paths under src/, analysis/, experiments/"
    ;;
esac
