#!/usr/bin/env bash
# Runs one libFuzzer target of this folder on its seed corpus, dictionary
# and saved regression inputs.
#
# usage: run_fuzzer.sh test|campaign FUZZ_BUILD_DIR FORMAT [libFuzzer options...]
#   test      a fresh working corpus each time, so that -runs=N -seed=1 repeats
#             exactly (ctest); prints SKIPPED and exits 77 without the target
#   campaign  keeps FUZZ_BUILD_DIR/corpus/FORMAT across runs
# FORMAT is obj, off, stl, vtk, vtu, medit, gmsh, input, handles, parts or untangle (target fuzz_FORMAT).
# New inputs go to the build folder, never to the seed corpus in the sources;
# crashes and mismatches are saved as FUZZ_BUILD_DIR/artifacts/FORMAT-*.
set -euo pipefail
if [ $# -lt 3 ]; then
  sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
fi
mode=$1 build=$2 format=$3
shift 3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
target=$build/fuzz_$format
if [ ! -x "$target" ]; then
  echo "SKIPPED: $target was not built (clang, libFuzzer or, for untangle, CGAL missing: see the fuzz_build test)"
  exit 77
fi
case $mode in
  test) corpus=$build/test-corpus/$format; rm -rf "$corpus" ;;
  campaign) corpus=$build/corpus/$format ;;
  *) echo "run_fuzzer.sh: mode must be test or campaign, not '$mode'" >&2; exit 2 ;;
esac
mkdir -p "$corpus" "$build/artifacts"
# The targets write each input to a file (the readers take paths): in memory
# that is about 20 times faster than on this machine's disk.
if [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then
  export TMPDIR=/dev/shm
fi
# (libFuzzer exits 77 on a finding by default: ctest would call that skipped)
options=(-artifact_prefix="$build/artifacts/$format-" -error_exitcode=1 -timeout_exitcode=1)
[ -f "$here/$format.dict" ] && options+=(-dict="$here/$format.dict")
seeds=("$here/$format/corpus")
[ -d "$here/$format/regressions" ] && seeds+=("$here/$format/regressions")
exec "$target" "${options[@]}" "$@" "$corpus" "${seeds[@]}"
