#!/usr/bin/env bash
# untangle_mesh_mpi on 1, 2 and 3 processes against untangle_mesh on the
# same problems (issue 38): a 2D and a 3D mesh with their boundary fixed,
# and a 3D mesh with a free boundary (phantoms).  Every run ends locally
# invertible with the serial run's verdict counts, and the fixed vertices
# bit for bit in place.  On the tangled inputs, judged as they are
# (--max-iterations 0), the distributed verdict counts what the serial
# tool's report counts before its run (inverted elements, over-wound
# stars and edge fans).  A time limit stops every process at once.  Bad
# files and options stop every process with the serial tool's message and
# exit code 2, and write nothing.
# usage: test_cli_mpi.sh UNTANGLE_MESH MAKE_TANGLED_MESH UNTANGLE_MESH_MPI MPIEXEC
set -u
if [ $# -ne 4 ] || [ ! -x "$3" ]; then
  echo "usage: test_cli_mpi.sh UNTANGLE_MESH MAKE_TANGLED_MESH UNTANGLE_MESH_MPI MPIEXEC" >&2
  exit 2
fi
. "$(dirname "${BASH_SOURCE[0]}")/cli_test_harness.sh" test_cli_mpi "$1" "$2"
MPI_TOOL=$(absolute "$3")
MPIEXEC=$4
# Open MPI refuses root without these, and more processes than cores without --oversubscribe.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1

# mpi NAME PROCESSES ARGUMENTS...: untangle_mesh_mpi on PROCESSES processes; NAME.out, NAME.rc.
mpi() {
  local name=$1 processes=$2
  shift 2
  timeout 600 "$MPIEXEC" -n "$processes" "$MPI_TOOL" "$@" > "$name.out" 2>&1
  echo $? > "$name.rc"
}
# same_counts SERIAL DISTRIBUTED [SUFFIX]: the verdict's counts agree (SUFFIX: the serial report's "_before" keys).
same_counts() {
  python3 - "$@" << 'PY'
import json, sys
s, m = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
suffix = sys.argv[3] if len(sys.argv) > 3 else ''
pairs = [('inverted_before', 'inverted_after') if suffix else ('inverted_after', 'inverted_after'),
         ('overwound_vertices' + suffix, 'overwound_vertices'), ('overwound_edges' + suffix, 'overwound_edges')]
if not suffix:
    pairs += [(k, k) for k in ('inverted_before', 'overwound_interior_vertices', 'overwound_boundary_vertices',
                               'overwound_interior_edges', 'overwound_boundary_edges', 'input_defects',
                               'non_manifold_stars', 'vertices', 'elements', 'fixed_vertices')]
wrong = [(a, s[a], b, m[b]) for a, b in pairs if s[a] != m[b]]
print('differ:', wrong) if wrong else None
sys.exit(1 if wrong else 0)
PY
}

# case NAME SERIAL_OPTIONS -- MPI_OPTIONS: serial once, then 1, 2, 3 processes.
run_case() {
  local name=$1 input=$2 fixed_in_file=$3
  shift 3
  "$UNTANGLE" "$input" -o "$name-serial.vtk" --report "$name-serial.json" --threads 1 -q "$@" > "$name-serial.out" 2>&1
  echo $? > "$name-serial.rc"
  check "$name: untangle_mesh exit 0" ran_well "$name-serial"
  for n in 1 2 3; do
    mpi "$name-$n" "$n" "$input" -o "$name-$n.vtk" --report "$name-$n.json" -q "$@"
    check "$name, $n processes: exit 0 ($(tail -n 2 "$name-$n.out" | head -c 300))" ran_well "$name-$n"
    [ -s "$name-$n.json" ] || continue
    check "$name, $n processes: tangled before" json_positive "$name-$n.json" inverted_before
    check "$name, $n processes: locally invertible" test "$(json "$name-$n.json" locally_invertible)" = True
    check "$name, $n processes: the serial run's counts" same_counts "$name-serial.json" "$name-$n.json"
    check "$name, $n processes: $n processes named" json_is "$name-$n.json" processes "$n"
    check "$name, $n processes: a peak memory per process" python3 -c "
import json, sys
m = json.load(open('$name-$n.json'))['peak_memory_bytes_per_process']
sys.exit(not (len(m) == $n and all(x > 0 for x in m)))"
    if [ "$fixed_in_file" = yes ]; then
      check "$name, $n processes: the fixed vertices bit for bit in place" same_fixed "$input" "$name-$n.vtk"
    fi
  done
}

"$MAKE" square 24 0.6 1 square.vtk > make-square.out 2>&1
check "make_tangled_mesh square: exit 0" test $? -eq 0
run_case square square.vtk yes --rest square-rest.vtk
"$MAKE" cube 6 0.6 1 cube.vtk > make-cube.out 2>&1
check "make_tangled_mesh cube: exit 0" test $? -eq 0
run_case cube cube.vtk yes --rest cube-rest.vtk
: > none.txt
run_case free-cube cube.vtk no --rest cube-rest.vtk --fixed none.txt
check "free-cube: no vertex fixed" json_is free-cube-2.json fixed_vertices 0
check "free-cube: phantoms" json_positive free-cube-serial.json phantom_elements

# The tangled inputs as they are: the serial tool's counts before its run.
for input in square cube; do
  for n in 1 2 3; do
    mpi "$input-judged-$n" "$n" "$input.vtk" --rest "$input-rest.vtk" -o "judged-$n.vtk" --report "$input-judged-$n.json" \
      --max-iterations 0 -q
    check "$input judged as given, $n processes: exit 1 (tangled)" test "$(cat "$input-judged-$n.rc")" = 1
    check "$input judged as given, $n processes: the serial counts before its run" \
      same_counts "$input-serial.json" "$input-judged-$n.json" _before
  done
done
check "the tangled cube has over-wound stars to count" json_positive cube-serial.json overwound_vertices_before

# A time limit stops every process at once, and the result says so.
mpi time-limit 2 cube.vtk --rest cube-rest.vtk -o time-limit.vtk --report time-limit.json --time-limit 0 -q
check "--time-limit 0: exit 1" test "$(cat time-limit.rc)" = 1
check "--time-limit 0: the status says why" json_is time-limit.json status \
  '"the time limit was reached before the map became locally invertible"'
check "--time-limit 0: one eps step" json_is time-limit.json eps_steps 1

# --stop first-valid: every process stops at the first map with every
# tetrahedron positive, in fewer evaluations than the settled run, with the
# fixed vertices in place; from that valid map, no eps step at all.
mpi first-valid 2 cube.vtk --rest cube-rest.vtk -o first-valid.vtk --report first-valid.json --stop first-valid -q
check "--stop first-valid, 2 processes: exit 0" ran_well first-valid
check "--stop first-valid: reported" json_is first-valid.json stop '"first-valid"'
check "--stop settled (the default): reported" json_is cube-2.json stop '"settled"'
check "--stop first-valid: locally invertible" test "$(json first-valid.json locally_invertible)" = True
check "--stop first-valid: fewer evaluations than settled" \
  test "$(json first-valid.json energy_evaluations)" -lt "$(json cube-2.json energy_evaluations)"
check "--stop first-valid: the fixed vertices bit for bit in place" same_fixed cube.vtk first-valid.vtk
mpi first-valid-again 2 first-valid.vtk --rest cube-rest.vtk -o again.vtk --report again.json --stop first-valid -q
check "--stop first-valid from a valid map: exit 0" ran_well first-valid-again
check "--stop first-valid from a valid map: no eps step" json_is again.json eps_steps 0

# Bad input: every process stops, process 0 says why, nothing is written.
# expect_refusal NAME MESSAGE ARGUMENTS...: with -o NAME-out.vtk added (unless NAME is no-output).
expect_refusal() {
  local name=$1 message=$2
  shift 2
  if [ "$name" = no-output ]; then mpi "$name" 2 "$@"; else mpi "$name" 2 "$@" -o "$name-out.vtk"; fi
  check "$name: exit 2" test "$(cat "$name.rc")" = 2
  check "$name: says '$message'" grep -qF -- "$message" "$name.out"
  check "$name: no output written" test ! -e "$name-out.vtk"
}
expect_refusal missing "missing.vtk: file not found" missing.vtk
head -c 300 cube.vtk > truncated.vtk
expect_refusal truncated "truncated.vtk:15: truncated: the POINTS block ends" truncated.vtk
expect_refusal rest-size "square-rest.vtk: 625 vertices, but cube.vtk has 343" cube.vtk --rest square-rest.vtk
"$MAKE" quadsquare 4 0.2 1 quads.vtk > make-quads.out 2>&1
expect_refusal quads "no triangle or tetrahedron" quads.vtk
expect_refusal theta "theta must be in [0, 1]" cube.vtk --theta 3
expect_refusal stop "--stop: never not in {settled,first-valid}" cube.vtk --stop never
expect_refusal no-output "--output is required" cube.vtk
printf '0\n9999\n' > far.txt
expect_refusal far-id "far.txt" cube.vtk --fixed far.txt

echo "$((checks - failures)) of $checks checks passed"
[ "$failures" = 0 ]
