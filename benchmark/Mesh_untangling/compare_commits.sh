#!/usr/bin/env bash
# The speed guard: the command-line tool of this checkout against the one
# built from another commit, on a fixed list of cases, in one run on the
# same machine, the two binaries alternating on each case.  Prints a
# markdown table with both library times (the report's "seconds"), wall
# times and peak memory, the ratios new / base, and whether the two wrote
# the same output file byte for byte (a change meant to keep the results
# says "same" on every case).  Not a ctest test: the
# machines are shared and noisy, so figures are reported, never enforced.
#
# usage: benchmark/Mesh_untangling/compare_commits.sh [options] BASE_COMMIT
#   --threads N       threads of every run (default 1)
#   --time-limit S    untangle_mesh --time-limit (default 120)
#   --repeat R        runs of each binary per case, alternating (default 2; the fastest counts)
#   --cases LIST      comma-separated subset of: cube55, square707, armadillo598, bars200k,
#                     cuboidblocks (default: all of them)
#   --data DIR        the external data (default ../shared/data beside the checkout)
#   --work DIR        where the worktree, its build and the generated cases go
#                     (default build-compare/ in the checkout)
# Environment: JOBS (parallel build jobs, default 2).
#
# Example (the issue-40 comparison):
#   benchmark/Mesh_untangling/compare_commits.sh --threads 1 12049a3
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
threads=1 time_limit=120 repeat=2 cases=cube55,square707,armadillo598,bars200k,cuboidblocks
data=$ROOT/../shared/data work=$ROOT/build-compare base=
usage() { sed -n '9,18p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case $1 in
    --threads) threads=$2; shift 2 ;;
    --time-limit) time_limit=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --cases) cases=$2; shift 2 ;;
    --data) data=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "compare_commits.sh: unknown option $1" >&2; usage >&2; exit 2 ;;
    *) [ -z "$base" ] || { echo "compare_commits.sh: one BASE_COMMIT only" >&2; exit 2; }; base=$1; shift ;;
  esac
done
[ -n "$base" ] || { usage >&2; exit 2; }
for number in "$threads" "$time_limit" "$repeat"; do
  [[ "$number" =~ ^[1-9][0-9]*$ ]] || { echo "compare_commits.sh: '$number' is not a whole number from 1" >&2; exit 2; }
done
sha=$(git -C "$ROOT" rev-parse --short "$base^{commit}" 2> /dev/null) ||
  { echo "compare_commits.sh: $base is not a commit of $ROOT" >&2; exit 2; }

# 1. Both tools: this checkout's (build/), the base's in a worktree.
mkdir -p "$work"
cmake --build "$ROOT/build" -j "${JOBS:-2}" --target untangle_mesh_cli make_tangled_mesh benchmark_free_boundary > /dev/null
tree=$work/tree-$sha
if [ ! -d "$tree" ]; then
  git -C "$ROOT" worktree add --detach "$tree" "$sha" > /dev/null 2>&1 ||
    { echo "compare_commits.sh: cannot make a worktree of $sha in $tree" >&2; exit 1; }
fi
if [ ! -x "$tree/build/bin/untangle_mesh" ]; then
  cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release > "$work/configure-$sha.log" 2>&1 ||
    { cat "$work/configure-$sha.log" >&2; exit 1; }
  cmake --build "$tree/build" -j "${JOBS:-2}" --target untangle_mesh_cli > "$work/build-$sha.log" 2>&1 ||
    { tail -30 "$work/build-$sha.log" >&2; exit 1; }
fi
NEW=$ROOT/build/bin/untangle_mesh
BASE=$tree/build/bin/untangle_mesh
MAKE=$ROOT/build/bin/make_tangled_mesh

# 2. The cases: NAME|ARGUMENTS (the input first), made once in $work/cases.
mkdir -p "$work/cases"
list=()
generated() {   # generated NAME KIND N AMPLITUDE: the generator prints the command to run
  local line
  line=$(cd "$work/cases" && "$MAKE" "$2" "$3" "$4" 1 "$1.vtk" | sed -n 's/^untangle the same problem with: untangle_mesh //p')
  list+=("$1|$(echo "$line" | sed "s|\([^ ]*\.vtk\)|$work/cases/\1|g")")
}
want() { [[ ",$cases," == *",$1,"* ]]; }
want cube55 && generated cube55 cube 55 0.6
want square707 && generated square707 square 707 2
if want armadillo598; then
  if [ -f "$data/lim/armadillo-598-init.vtk" ]; then
    list+=("armadillo598|$data/lim/armadillo-598-init.vtk --rest $data/lim/armadillo-598-rest.vtk --fix-boundary")
  else echo "compare_commits.sh: $data/lim absent: armadillo598 skipped" >&2; fi
fi
if want bars200k; then
  "$ROOT/build/bin/benchmark_free_boundary" --family bar --large --instance bar-200k-twist180,bar-200k-bend \
    --write "$work/cases" > /dev/null 2>&1 ||
    echo "compare_commits.sh: benchmark_free_boundary --write failed: bars200k skipped" >&2
  for file in "$work"/cases/bar-200k*.input; do
    [ -f "$file" ] && list+=("$(basename "$file" .input)|$file")
  done
fi
if want cuboidblocks; then
  if [ -d "$data/cuboidblocks" ]; then
    for block in "$data"/cuboidblocks/*/; do
      list+=("$(basename "$block")|${block}parameter.vtk --rest ${block}object.vtk --fixed ${block}handles.txt")
    done
  else echo "compare_commits.sh: $data/cuboidblocks absent: CuboidBlocks skipped" >&2; fi
fi

# 3. The runs.  run BINARY TAG ARGUMENTS: "library_s wall_s peak_MiB exit status";
# the output goes to $work/TAG.out.vtk (or .input).
figure() { sed -nE "s/^  \"$2\": (.*)\$/\1/p" "$1" | sed -E 's/,$//; s/^"(.*)"$/\1/'; }
run() {
  local binary=$1 tag=$2 rc=0; shift 2
  rm -f "$work/run.json" "$work/$tag.out.vtk" "$work/$tag.out.input"
  local out=$work/$tag.out.vtk
  [[ "$1" == *.input ]] && out=$work/$tag.out.input
  /usr/bin/time -f "%e %M" -o "$work/run.time" "$binary" "$@" -o "$out" --report "$work/run.json" \
    --threads "$threads" --time-limit "$time_limit" --quiet > /dev/null 2>&1 || rc=$?
  local seconds=nan status=none
  if [ -f "$work/run.json" ]; then
    seconds=$(figure "$work/run.json" seconds); status=$(figure "$work/run.json" locally_invertible)
  fi
  read -r wall kib < <(tail -1 "$work/run.time")
  echo "$seconds $wall $((kib / 1024)) $rc $status"
}
better() { awk -v a="$1" -v b="$2" 'BEGIN { print (b == "nan" || (a != "nan" && a + 0 < b + 0)) ? a : b }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if(a == "nan" || b == "nan" || b + 0 == 0) print "-"; else printf "%.2f", a / b }'; }

echo "new: $(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet HEAD || echo '+changes'), base: $sha;" \
     "$threads thread(s), best of $repeat alternating runs, $(date -u +%Y-%m-%d)"
echo
echo "| case | base s | new s | new/base | base wall | new wall | base MiB | new MiB | base exit | new exit | output |"
echo "|:--|--:|--:|--:|--:|--:|--:|--:|--:|--:|:--|"
for entry in "${list[@]}"; do
  name=${entry%%|*}
  read -r -a arguments <<< "${entry#*|}"
  best_base=(nan nan 0 - -) best_new=(nan nan 0 - -)
  for ((r = 0; r < repeat; ++r)); do
    read -r -a b <<< "$(run "$BASE" base "${arguments[@]}")"
    read -r -a n <<< "$(run "$NEW" new "${arguments[@]}")"
    [ "$(better "${b[0]}" "${best_base[0]}")" = "${b[0]}" ] && best_base=("${b[@]}")
    [ "$(better "${n[0]}" "${best_new[0]}")" = "${n[0]}" ] && best_new=("${n[@]}")
  done
  same=differs
  ls "$work"/base.out.* "$work"/new.out.* > /dev/null 2>&1 || same="no output"
  for extension in vtk input; do
    [ -f "$work/base.out.$extension" ] && cmp -s "$work/base.out.$extension" "$work/new.out.$extension" && same=same
  done
  echo "| $name | ${best_base[0]} | ${best_new[0]} | $(ratio "${best_new[0]}" "${best_base[0]}") |" \
       "${best_base[1]} | ${best_new[1]} | ${best_base[2]} | ${best_new[2]} | ${best_base[3]} | ${best_new[3]} | $same |"
done
