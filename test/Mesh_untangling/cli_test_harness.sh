# What the command-line tests (test_cli.sh, test_cli_files.sh) share, sourced
# after `set -u` with the test's name and its arguments:
#   . cli_test_harness.sh NAME UNTANGLE_MESH MAKE_TANGLED_MESH [...]
# It checks the two programs and makes their paths absolute (UNTANGLE, MAKE),
# moves into a temporary folder that is removed at exit (read-only folders
# included), and defines `check DESCRIPTION COMMAND...` with its counters.

harness_name=$1
if [ $# -lt 3 ] || [ ! -x "$2" ] || [ ! -x "$3" ]; then
  echo "usage: $harness_name.sh UNTANGLE_MESH MAKE_TANGLED_MESH ..." >&2
  exit 2
fi
absolute() { case $1 in /*) echo "$1" ;; *) echo "$PWD/$1" ;; esac; }
# (the tests' Python helpers, legacy_vtk.py)
PYTHONPATH="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)${PYTHONPATH:+:$PYTHONPATH}"
export PYTHONPATH
UNTANGLE=$(absolute "$2")
MAKE=$(absolute "$3")

T=$(mktemp -d "${TMPDIR:-/tmp}/$harness_name.XXXXXX") || exit 2
trap 'chmod -R u+w "$T" 2> /dev/null; rm -rf "$T"' EXIT
cd "$T" || exit 2

failures=0
checks=0
# check DESCRIPTION COMMAND...: the command must succeed.  One command: in
# "check D A && B", B runs outside the check and its failure is not counted.
check() {
  local what=$1
  shift
  checks=$((checks + 1))
  if ! "$@"; then
    failures=$((failures + 1))
    echo "FAIL: $what" >&2
  fi
}
