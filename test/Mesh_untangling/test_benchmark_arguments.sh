#!/usr/bin/env bash
# Bad arguments of the benchmark programs: exit 2, a message that names the
# argument, nothing on stdout and no run started.
#
# usage: test_benchmark_arguments.sh BENCHMARK_UNTANGLE ENERGY_BANDWIDTH BENCHMARK_FREE_BOUNDARY [BENCHMARK_CAVITIES]
# (the last is built only with TetGen)
set -u
if [ $# -lt 3 ]; then
  echo "usage: $0 BENCHMARK_UNTANGLE ENERGY_BANDWIDTH BENCHMARK_FREE_BOUNDARY [BENCHMARK_CAVITIES]" >&2
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

F=$3
refused "benchmark_free_boundary: unknown family" "--family: unknown family 'blob'" "$F" --family blob
refused "benchmark_free_boundary: empty family list" "--family needs at least one family name" "$F" --family ,
refused "benchmark_free_boundary: family without value" "--family needs a value" "$F" --family
refused "benchmark_free_boundary: time limit 0" "--time-limit: '0' is not a positive number of seconds" "$F" --time-limit 0
refused "benchmark_free_boundary: time limit 5s" "--time-limit: '5s' is not a positive number of seconds" "$F" --time-limit 5s
refused "benchmark_free_boundary: threads 1.5" "--threads: '1.5' is not a positive number of threads" "$F" --threads 1.5
refused "benchmark_free_boundary: quick and large" "--quick and --large exclude each other" "$F" --quick --large
refused "benchmark_free_boundary: unknown instance" "--instance: no instance of the selected families has that name" "$F" --instance nothing-like-this
refused "benchmark_free_boundary: unknown argument" "unknown argument '--fast'" "$F" --fast
refused "benchmark_free_boundary: data without value" "--data needs a value" "$F" --data
refused "benchmark_free_boundary: real meshes without their data" "no instance to run: the selected families have none here" "$F" --family real-meshes --data "$T/no-such-folder"
# the instances it lists are the ones --instance selects; --write saves them for the command-line tool
checks=$((checks + 1))
if ! "$F" --quick --family twelve-star --instance twelve-star-fixed1-tilt80-noise0.09-s1 --write "$T/w" > "$T/out" 2> "$T/err" \
   || [ "$(ls "$T/w")" != "twelve-star-fixed1-tilt80-noise0.09-s1.input" ] \
   || ! "$F" --quick --list | grep -Fqx "  twelve-star-fixed1-tilt80-noise0.09-s1"; then
  failures=$((failures + 1))
  echo "FAIL: benchmark_free_boundary --write/--list: $(cat "$T/err")" >&2
fi

if [ $# -ge 4 ] && [ -n "$4" ]; then
  B=$4
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
