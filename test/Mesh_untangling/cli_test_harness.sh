# What the command-line tests (test_cli.sh, test_cli_files.sh) share, sourced
# after `set -u` with the test's name and its arguments:
#   . cli_test_harness.sh NAME UNTANGLE_MESH MAKE_TANGLED_MESH [...]
# It checks the two programs and makes their paths absolute (UNTANGLE, MAKE),
# moves into a temporary folder that is removed at exit (read-only folders
# included), and defines `check DESCRIPTION COMMAND...` with its counters,
# the steps of the tangled cube's round trip (cube_make, cube_untangle,
# cube_read_back) with their JSON helpers, and checks on legacy .vtk files
# (same_fixed, has_VTK_cell_types).

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

# For the formats that hold the fixed vertices (test_cli_gmsh.sh,
# test_cli_vtu.sh): a tangled cube of tetrahedra, cube.EXT, with its rest
# grid, untangled into out.EXT, which reads back untangled.  Each program's
# output and exit status go to NAME.out and NAME.rc (make, out, again); the
# reports out.json and again.json are pretty-printed JSON (one top-level key
# a line).  test_cli.sh defines its own json_get, json_is and json_positive.
json_get() { grep -E "^  \"$2\": " "$1" 2> /dev/null | head -n 1 | sed -E 's/^  "[^"]*": //; s/,$//'; }
json_is() { [ "$(json_get "$1" "$2")" = "$3" ]; }
json_positive() { local v; v=$(json_get "$1" "$2"); [[ "$v" =~ ^[0-9]+$ ]] && [ "$v" -gt 0 ]; }
ran_well() { [ "$(cat "$1.rc")" = 0 ]; }
# json FILE KEY: the value of a top-level key of a JSON report, as Python prints it
json() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }

# cube_make EXT: make_tangled_mesh writes cube.EXT and cube-rest.EXT, the
# fixed vertices in the file (no cube-fixed.txt).
cube_make() {
  "$MAKE" cube 4 0.6 1 "cube.$1" > make.out 2>&1
  echo $? > make.rc
  check "make_tangled_mesh cube.$1: exit 0" ran_well make
  check "make_tangled_mesh cube.$1: the fixed vertices in the file, no cube-fixed.txt" [ ! -e cube-fixed.txt ]
}

# cube_untangle EXT WHERE [OPTION...]: untangle_mesh untangles cube.EXT into
# out.EXT, with the 98 fixed vertices of WHERE (in the messages).
cube_untangle() {
  local ext=$1 where=$2
  shift 2
  "$UNTANGLE" "cube.$ext" --rest "cube-rest.$ext" -o "out.$ext" --report out.json "$@" > out.out 2>&1
  echo $? > out.rc
  check "untangle_mesh cube.$ext: exit 0" ran_well out
  check "untangle_mesh cube.$ext: tangled before" json_positive out.json inverted_before
  check "untangle_mesh cube.$ext: no inverted tetrahedron after" json_is out.json inverted_after 0
  check "untangle_mesh cube.$ext: the fixed vertices of $where" json_is out.json fixed_vertices 98
}

# cube_read_back EXT: out.EXT, untangled again, has no inverted tetrahedron
# and the same fixed vertices.
cube_read_back() {
  "$UNTANGLE" "out.$1" --rest "cube-rest.$1" -o "again.$1" --report again.json -q > again.out 2>&1
  echo $? > again.rc
  check "the result read back: exit 0" ran_well again
  check "the result read back: no inverted tetrahedron" json_is again.json inverted_before 0
  check "the result read back: the same fixed vertices" json_is again.json fixed_vertices 98
}

# same_fixed IN OUT: the vertices that IN's point array 'fixed' flags (legacy
# .vtk files) have the same coordinates in OUT, bit for bit, and IN flags some.
same_fixed() {
  python3 - "$@" << 'PY'
import sys
import legacy_vtk
lines, _, a = legacy_vtk.read(sys.argv[1])
b = legacy_vtk.points(sys.argv[2])
k = next(i for i, l in enumerate(lines) if l.startswith('SCALARS fixed'))
n = len(a)
flags = [float(x) for l in lines[k + 2:] for x in l.split()][:n]
moved = [v for v in range(n) if flags[v] != 0 and a[v] != b[v]]
print('fixed vertices', sum(f != 0 for f in flags), 'moved', len(moved))
sys.exit(1 if moved or not any(flags) else 0)
PY
}

# has_VTK_cell_types FILE TYPE...: the cell types of the legacy .vtk FILE are these, no other.
has_VTK_cell_types() {
  python3 - "$@" << 'PY'
import sys
lines = open(sys.argv[1]).read().split('\n')
k = next(i for i, l in enumerate(lines) if l.startswith('CELL_TYPES'))
types = {int(t) for t in lines[k + 1:k + 1 + int(lines[k].split()[1])]}
sys.exit(0 if types == {int(t) for t in sys.argv[2:]} else 1)
PY
}
