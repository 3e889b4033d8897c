#!/usr/bin/env bash
# Bad arguments of the untangle_cavities example: exit 2 with a message
# naming them, never an uncaught exception.
#
# usage: test_untangle_cavities_arguments.sh UNTANGLE_CAVITIES
set -u
program=$1
T=$(mktemp -d "${TMPDIR:-/tmp}/test_untangle_cavities_arguments.XXXXXX") || exit 2
trap 'rm -rf "$T"' EXIT
failures=0
# refused PATTERN ARGS...: exit 2 and stderr holding the fixed string PATTERN
refused() {
  local pattern=$1
  shift
  timeout 120 "$program" "$@" > /dev/null 2> "$T/err"
  local rc=$?
  if [ "$rc" != 2 ] || ! grep -Fq -- "$pattern" "$T/err"; then
    failures=$((failures + 1))
    echo "FAIL: untangle_cavities $*: exit $rc, stderr: $(head -c 300 "$T/err")" >&2
  fi
}
refused "argument 2 ('abc') is not a number" 0.6 abc
refused "mesh size must be in" 2.5
echo "$((2 - failures)) passed, $failures failed"
[ "$failures" = 0 ]
