# Sourced first by every CLI test (usage: SCRIPT CREATURELAB SOURCE_DIR SCRATCH_DIR): strict mode;
# bin, src and scratch from the arguments; the source tree as the working folder (experiment files
# are named from it); an empty scratch folder; fail MESSAGE.
set -euo pipefail
bin=$1 src=$2 scratch=$3
cd "$src"
rm -rf "$scratch"
mkdir -p "$scratch"
fail() { echo "FAIL: $*" >&2; exit 1; }
