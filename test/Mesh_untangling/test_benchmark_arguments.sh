#!/usr/bin/env bash
# Bad arguments of the benchmark programs: exit 2, a message that names the
# argument, nothing on stdout and no run started.
#
# usage: test_benchmark_arguments.sh BENCHMARK_UNTANGLE ENERGY_BANDWIDTH [BENCHMARK_CAVITIES]
# (the last is built only with TetGen)
set -u
if [ $# -lt 2 ]; then
  echo "usage: $0 BENCHMARK_UNTANGLE ENERGY_BANDWIDTH [BENCHMARK_CAVITIES]" >&2
  exit 2
fi
T=$(mktemp -d "${TMPDIR:-/tmp}/test_benchmark_arguments.XXXXXX") || exit 2
trap 'rm -rf "$T"' EXIT

failures=0
checks=0
# refused NAME PATTERN PROGRAM ARGS...: exit 2, stderr matches the fixed
# string PATTERN, stdout empty.
refused() {
  local name=$1 pattern=$2
  shift 2
  checks=$((checks + 1))
  timeout 120 "$@" > "$T/out" 2> "$T/err"   # (a program that ran instead would take minutes)
  local rc=$?
  if [ "$rc" != 2 ] || ! grep -Fq -- "$pattern" "$T/err" || [ -s "$T/out" ]; then
    failures=$((failures + 1))
    echo "FAIL: $name: exit $rc, stderr: $(head -c 300 "$T/err"), stdout: $(head -c 100 "$T/out")" >&2
  fi
}

refused "benchmark_untangle: bad N" "N must be an integer in [2, 4000]" "$1" generated:square:abc:2:1
refused "benchmark_untangle: time limit 0" "--time-limit" "$1" --time-limit 0 generated:square:10:2:1
refused "energy_bandwidth: 0 threads" "--threads needs a positive integer" "$2" --threads 0 generated:square:10:2:1
refused "energy_bandwidth: unknown shape" "unknown shape 'blob'" "$2" generated:blob:10:2:1

if [ $# -ge 3 ] && [ -n "$3" ]; then
  B=$3
  refused "benchmark_cavities: --degrees x" "--degrees needs a number, not 'x'" "$B" --degrees x 1
  refused "benchmark_cavities: --degrees 45abc" "--degrees needs a number, not '45abc'" "$B" --degrees 45abc 1
  refused "benchmark_cavities: --time-limit -5" "--time-limit needs a number of seconds above 0, not '-5'" "$B" --time-limit -5 1
  refused "benchmark_cavities: size 2" "'2' is not a mesh size in (0, 1]" "$B" 2
  refused "benchmark_cavities: size abc" "'abc' is not a mesh size in (0, 1]" "$B" abc
  refused "benchmark_cavities: --degrees without value" "--degrees needs a value" "$B" --degrees
  refused "benchmark_cavities: unknown option" "unknown option '--speed'" "$B" --speed 1
fi

echo "$checks checks, $failures failed"
[ "$failures" = 0 ]
