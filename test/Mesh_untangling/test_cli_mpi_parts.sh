#!/usr/bin/env bash
# A mesh given in parts (issue 38): mesh_parts split writes one part file
# per process, untangle_mesh_mpi --parts has each process read, untangle
# and write its own (no process holds the whole mesh), and mesh_parts join
# puts the results together.  On 1, 2 and 3 processes, a 2D and a 3D mesh
# with a fixed boundary end locally invertible with the serial run's
# verdict counts and the fixed vertices bit for bit in place, and the same
# meshes with a free boundary with the serial run's phantoms too.  Bad parts
# (no global ids, parts that disagree on a vertex, more
# part files than processes, a missing part) stop every process with a
# message that names the file or the vertex, exit 2, and write nothing.
# usage: test_cli_mpi_parts.sh UNTANGLE_MESH MAKE_TANGLED_MESH UNTANGLE_MESH_MPI MESH_PARTS MPIEXEC
set -u
if [ $# -ne 5 ] || [ ! -x "$3" ] || [ ! -x "$4" ]; then
  echo "usage: test_cli_mpi_parts.sh UNTANGLE_MESH MAKE_TANGLED_MESH UNTANGLE_MESH_MPI MESH_PARTS MPIEXEC" >&2
  exit 2
fi
. "$(dirname "${BASH_SOURCE[0]}")/cli_test_harness.sh" test_cli_mpi_parts "$1" "$2"
MPI_TOOL=$(absolute "$3")
PARTS=$(absolute "$4")
MPIEXEC=$5
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1

# mpi NAME PROCESSES ARGUMENTS...: untangle_mesh_mpi on PROCESSES processes; NAME.out, NAME.rc.
mpi() {
  local name=$1 processes=$2
  shift 2
  timeout 600 "$MPIEXEC" -n "$processes" "$MPI_TOOL" "$@" > "$name.out" 2>&1
  echo $? > "$name.rc"
}
# parts NAME ARGUMENTS...: mesh_parts; NAME.out, NAME.rc.
parts() {
  local name=$1
  shift
  timeout 600 "$PARTS" "$@" > "$name.out" 2>&1
  echo $? > "$name.rc"
}
# same_counts SERIAL DISTRIBUTED: the verdict's counts agree.
same_counts() {
  python3 - "$@" << 'PY'
import json, sys
s, m = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
keys = ('inverted_before', 'inverted_after', 'overwound_interior_vertices', 'overwound_boundary_vertices',
        'overwound_interior_edges', 'overwound_boundary_edges', 'input_defects', 'non_manifold_stars',
        'vertices', 'elements', 'fixed_vertices')
wrong = [(k, s[k], m[k]) for k in keys if s[k] != m[k]]
print('differ:', wrong) if wrong else None
sys.exit(1 if wrong else 0)
PY
}

# same_phantoms SERIAL DISTRIBUTED: as many phantom elements and vertices, as many stars left unprotected.
same_phantoms() {
  python3 - "$@" << 'PY'
import json, sys
s, m = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
keys = ('phantom_elements', 'phantom_vertices', 'incomplete_phantom_stars')
wrong = [(k, s.get(k), m.get(k)) for k in keys if s.get(k) != m.get(k)]
print('differ:', wrong) if wrong else None
sys.exit(1 if wrong else 0)
PY
}

# run_case NAME INPUT REST [FIXED]: serial once, then split, untangled in parts and joined on 1, 2, 3
# processes (FIXED: a file of fixed vertex ids, given to the serial run and to the split).
run_case() {
  local name=$1 input=$2 rest=$3
  local fixed=()
  [ $# -gt 3 ] && fixed=(--fixed "$4")
  "$UNTANGLE" "$input" --rest "$rest" "${fixed[@]}" -o "$name-serial.vtk" --report "$name-serial.json" --threads 1 -q \
    > "$name-serial.out" 2>&1
  echo $? > "$name-serial.rc"
  check "$name: untangle_mesh exit 0" ran_well "$name-serial"
  for n in 1 2 3; do
    parts "$name-split-$n" split "$input" "$n" "$name-$n.%.vtk" --rest "$rest" --rest-output "$name-rest-$n.%.vtk" \
      "${fixed[@]}"
    check "$name: split into $n parts" ran_well "$name-split-$n"
    mpi "$name-$n" "$n" --parts "$name-$n.%.vtk" --rest "$name-rest-$n.%.vtk" -o "$name-out-$n.%.vtu" \
      --report "$name-$n.json" -q
    check "$name, $n processes: exit 0 ($(tail -n 2 "$name-$n.out" | head -c 300))" ran_well "$name-$n"
    check "$name, $n processes: locally invertible" test "$(json "$name-$n.json" locally_invertible)" = True
    check "$name, $n processes: the serial run's counts" same_counts "$name-serial.json" "$name-$n.json"
    check "$name, $n processes: the serial run's phantoms" same_phantoms "$name-serial.json" "$name-$n.json"
    parts "$name-join-$n" join "$name-out-$n.%.vtu" "$n" "$name-joined-$n.vtk"
    check "$name, $n processes: joined" ran_well "$name-join-$n"
    [ $# -gt 3 ] ||
      check "$name, $n processes: the fixed vertices bit for bit in place" same_fixed "$input" "$name-joined-$n.vtk"
    "$UNTANGLE" "$name-joined-$n.vtk" --rest "$rest" --max-iterations 1 -o "$name-judged-$n.vtk" \
      --report "$name-judged-$n.json" -q > "$name-judged-$n.out" 2>&1
    check "$name, $n processes: the joined mesh locally invertible for the serial tool" python3 -c "
import json, sys
r = json.load(open('$name-judged-$n.json'))
sys.exit(sum(r[k] for k in ('inverted_before', 'overwound_vertices_before', 'overwound_edges_before')) != 0)"
  done
}

"$MAKE" square 20 0.6 1 square.vtk > make-square.out 2>&1
check "make_tangled_mesh square: exit 0" test $? -eq 0
run_case square square.vtk square-rest.vtk
"$MAKE" cube 6 0.6 1 cube.vtk > make-cube.out 2>&1
check "make_tangled_mesh cube: exit 0" test $? -eq 0
run_case cube cube.vtk cube-rest.vtk
# A free boundary given in parts: each process protects its own stars with the serial construction's phantoms.
: > none.txt
# (the distributed scheme, L-BFGS alone, does not untangle the 20 x 20 square with a free boundary; the serial
# driver's Newton does: a smaller one)
"$MAKE" square 12 0.6 1 small-square.vtk > make-small-square.out 2>&1
check "make_tangled_mesh square 12: exit 0" test $? -eq 0
run_case free-square small-square.vtk small-square-rest.vtk none.txt
check "free-square: the serial run has phantoms" json_positive free-square-serial.json phantom_elements
run_case free-cube cube.vtk cube-rest.vtk none.txt
check "free-cube: the serial run has phantoms" json_positive free-cube-serial.json phantom_elements
check "free-cube: no vertex fixed on 3 processes" json_is free-cube-3.json fixed_vertices 0
# Without a rest shape (regular targets) no phantom tetrahedron can be built: every boundary star is
# counted unprotected, as the serial run counts them, and the result is the serial run's verdict.
"$UNTANGLE" cube.vtk --fixed none.txt -o regular-serial.vtk --report regular-serial.json --threads 1 -q \
  > regular-serial.out 2>&1
echo $? > regular-serial.rc
check "regular targets, free boundary: untangle_mesh exit 0" ran_well regular-serial
parts regular-split split cube.vtk 3 regular.%.vtk --fixed none.txt
mpi regular-3 3 --parts regular.%.vtk -o regular-out.%.vtu --report regular-3.json -q
check "regular targets, free boundary, 3 processes: exit 0" ran_well regular-3
check "regular targets, free boundary, 3 processes: the serial run's counts" same_counts regular-serial.json regular-3.json
check "regular targets, free boundary, 3 processes: the serial run's unprotected stars" \
  same_phantoms regular-serial.json regular-3.json
check "regular targets, free boundary: every boundary star unprotected" \
  json_positive regular-serial.json incomplete_phantom_stars

# Bad parts: every process stops, process 0 says why, nothing is written.
# expect_refusal NAME MESSAGE ARGUMENTS...: on 2 processes, with -o NAME-out.%.vtk added.
expect_refusal() {
  local name=$1 message=$2
  shift 2
  mpi "$name" 2 "$@" -o "$name-out.%.vtk"
  check "$name: exit 2" test "$(cat "$name.rc")" = 2
  check "$name: says '$message'" grep -qF -- "$message" "$name.out"
  check "$name: no output written" test ! -e "$name-out.0.vtk" -a ! -e "$name-out.1.vtk"
}
cp cube.vtk plain.0.vtk
cp cube.vtk plain.1.vtk
expect_refusal no-ids "plain.0.vtk: no point field 'global_id'" --parts plain.%.vtk
expect_refusal missing-part "cube-1.1.vtk: file not found" --parts cube-1.%.vtk
expect_refusal more-files "3 part files" --parts cube-3.%.vtk
expect_refusal fix-boundary "--fix-boundary takes a whole mesh" --parts cube-2.%.vtk --fix-boundary
expect_refusal no-percent "needs one '%'" --parts cube.vtk
# a vertex that the two parts share, moved in part 1 only
python3 - << 'PY'
import legacy_vtk
def ids(lines):
    p = next(i for i, l in enumerate(lines) if l.startswith('POINT_DATA'))
    k = next(i for i, l in enumerate(lines) if i > p and l.startswith('SCALARS global_id'))
    n = int(next(l for l in lines if l.startswith('POINTS')).split()[1])
    return [int(float(x)) for l in lines[k + 2:k + 2 + n] for x in l.split()][:n]
a, _, _ = legacy_vtk.read('cube-2.0.vtk')
b, i, points = legacy_vtk.read('cube-2.1.vtk')
shared = sorted(set(ids(a)) & set(ids(b)))
local = ids(b).index(shared[0])
points[local] = [c + 0.01 for c in points[local]]
open('moved.1.vtk', 'w').write('\n'.join(legacy_vtk.with_points(b, i, points)) + '\n')
print(shared[0])
PY
cp cube-2.0.vtk moved.0.vtk
expect_refusal disagree "the parts must agree on every vertex they share" --parts moved.%.vtk
# an element that both parts list, and one part's two elements of one id
python3 - << 'PY'
import legacy_vtk
def cell_ids(lines):   # (the line of the cell field global_id's first value, the number of cells, the lines they take)
    c = next(i for i, l in enumerate(lines) if l.startswith('CELL_DATA'))
    k = next(i for i, l in enumerate(lines) if i > c and l.startswith('SCALARS global_id')) + 2
    n, words, end = int(lines[c].split()[1]), [], k
    while len(words) < n:
        words += lines[end].split()
        end += 1
    return k, end, [int(float(x)) for x in words]
def first_ids(lines, count):
    return cell_ids(lines)[2][:count]
def with_ids(lines, ids):
    k, end, values = cell_ids(lines)
    values[:len(ids)] = ids
    return lines[:k] + [str(g) for g in values] + lines[end:]
a, _, _ = legacy_vtk.read('cube-2.0.vtk')
b, _, _ = legacy_vtk.read('cube-2.1.vtk')
taken = first_ids(a, 1)[0]
open('twice.1.vtk', 'w').write('\n'.join(with_ids(b, [taken])) + '\n')
mine = first_ids(b, 1)[0]
open('again.1.vtk', 'w').write('\n'.join(with_ids(b, [mine, mine])) + '\n')
PY
cp cube-2.0.vtk twice.0.vtk
cp cube-2.0.vtk again.0.vtk
expect_refusal element-twice "is listed by processes 0 and 1: each element must be one process's" --parts twice.%.vtk
expect_refusal element-id-again "process 1: tetrahedra 0 and 1 have the same global id" --parts again.%.vtk
parts join-missing join cube-2.%.vtk 3 joined-missing.vtk
check "join of a missing part: exit 2" test "$(cat join-missing.rc)" = 2
check "join of a missing part: names the file" grep -qF "cube-2.2.vtk: file not found" join-missing.out
check "join of a missing part: nothing written" test ! -e joined-missing.vtk
parts split-format split cube.vtk 2 cube.%.off
check "split to .off parts: exit 2" test "$(cat split-format.rc)" = 2
check "split to .off parts: says why" grep -qF "a part file is .vtk or .vtu" split-format.out

echo "$((checks - failures)) of $checks checks passed"
[ "$failures" = 0 ]
