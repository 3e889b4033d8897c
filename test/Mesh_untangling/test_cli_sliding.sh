#!/usr/bin/env bash
# --slide-boundary (issue 36, item 1).  On make_tangled_mesh's grids of the
# unit square and cube (hexahedra, tetrahedra, quadrilaterals, triangles)
# whose boundary vertices were moved along their faces and edges far enough
# to fold the boundary facets over, the fixed boundary cannot be untangled
# and the sliding one is: every face vertex keeps its face's coordinate,
# every edge vertex its edge's two, the corners theirs bit for bit, and the
# report counts them (surfaces, curves, corners) and gives a distance to the
# target below 1e-12.  On the data of ../shared (a CuboidBlocks hexahedral
# mesh whose fixed boundary leaves an inverted cell, its features found on
# its rest cuboid, and a real hexahedral mesh from a published pipeline),
# every boundary vertex of the result is within 1e-9 of the diagonal from
# the input's boundary surface; a block that is not untangled in the time
# given is never written worse than it came.  Bad options are refused with
# the reason.
# usage: test_cli_sliding.sh UNTANGLE_MESH MAKE_TANGLED_MESH MAKE_BLOCK_HEX_MESH [DATA_DIR]
set -u
. "$(dirname "${BASH_SOURCE[0]}")/cli_test_harness.sh" test_cli_sliding "$@"
MAKE_BLOCK=$(absolute "$3")
DATA=${4:-}

: > none.txt

# fold IN OUT: IN's boundary vertices on [0, 1]^D moved along their faces
# (edges, sides) by up to 0.9 grid cells, so that boundary facets fold
# over; the interior left as tangled as it is; the file's fixed flags dropped
fold() {
  python3 - "$@" << 'EOF'
import random, sys
import legacy_vtk
path, out = sys.argv[1], sys.argv[2]
lines, i, points = legacy_vtk.read(path)
dims = 2 if all(p[2] == 0 for p in points) else 3
n = round(1 / min(p[0] for p in points if p[0] > 0))
random.seed(11)
for p in points:
    on = [c for c in range(dims) if p[c] in (0.0, 1.0)]
    if not on or len(on) == dims:
        continue   # interior or corner
    for c in range(dims):
        if c not in on:
            p[c] = min(max(p[c] + 0.9 / n * random.choice((-1, 1)), 0.1 / n), 1 - 0.1 / n)
lines = legacy_vtk.with_points(lines, i, points)
end = next((k for k, l in enumerate(lines) if l.startswith('POINT_DATA')), len(lines))
open(out, 'w').write('\n'.join(lines[:end]) + '\n')
EOF
}
# on_faces IN OUT: every coordinate of an IN vertex at 0 or 1 is in OUT within 1e-12, corners bit for bit
on_faces() {
  python3 - "$@" << 'EOF'
import sys
from legacy_vtk import points
a, b = points(sys.argv[1]), points(sys.argv[2])
dims = 2 if all(p[2] == 0 for p in a) else 3
bad = 0
for p, q in zip(a, b):
    on = [c for c in range(dims) if p[c] in (0.0, 1.0)]
    if len(on) == dims and p != q: bad += 1
    bad += sum(abs(p[c] - q[c]) > 1e-12 for c in on)
sys.exit(1 if bad else 0)
EOF
}
# near_boundary IN OUT TOLERANCE: every vertex on IN's boundary surface ends within
# TOLERANCE times IN's bounding box diagonal of it (hexahedra)
near_boundary() {
  /usr/bin/python3 - "$@" << 'EOF'
import sys
import legacy_vtk
from surface_distance import boundary_faces, diagonal, farthest, triangles
lines, _, a = legacy_vtk.read(sys.argv[1])
faces = boundary_faces(legacy_vtk.cells(lines))
worst = farthest(legacy_vtk.points(sys.argv[2]), sorted({v for f in faces for v in f}), a, triangles(faces))
print('farthest boundary vertex from the input boundary:', worst)
sys.exit(0 if worst <= float(sys.argv[3]) * diagonal(a) else 1)
EOF
}

for kind in hexcube mixedcube cube quadsquare square; do
  "$MAKE" $kind 4 0.6 1 $kind.vtk > /dev/null
  fold $kind.vtk $kind-folded.vtk
  rc=0
  "$UNTANGLE" $kind-folded.vtk --rest $kind-rest.vtk --fix-boundary -o $kind-fixed.vtk --threads 1 --quiet --time-limit 20 2> /dev/null || rc=$?
  check "$kind: the folded boundary fixed is not untangled (exit $rc)" test $rc -ne 0
  rc=0
  "$UNTANGLE" $kind-folded.vtk --rest $kind-rest.vtk --slide-boundary -o $kind-out.vtk --report $kind.json --threads 1 \
    --quiet 2> $kind.err || rc=$?
  check "$kind: sliding, exit 0 ($rc: $(cat $kind.err))" test $rc -eq 0
  check "$kind: locally invertible" test "$(json $kind.json locally_invertible)" = True
  check "$kind: every vertex on its face, edge or corner" on_faces $kind.vtk $kind-out.vtk
  case $kind in
    hexcube | mixedcube | cube) surfaces=54 curves=36 corners=8 ;;
    *) surfaces=0 curves=12 corners=4 ;;
  esac
  check "$kind: $surfaces vertices on surfaces" test "$(json $kind.json vertices_sliding_on_surfaces)" = $surfaces
  check "$kind: $curves on curves" test "$(json $kind.json vertices_sliding_on_curves)" = $curves
  check "$kind: $corners corners held" test "$(json $kind.json corner_vertices_held)" = $corners
  check "$kind: on the target" python3 -c "import json; import sys; sys.exit(0 if 0 <= json.load(open('$kind.json'))['max_distance_to_target'] <= 1e-12 else 1)"
done
check "the summary tells the sliding boundary" grep -q "^sliding boundary: 54 vertices on surface patches, 36 on feature curves, 8 corners held" <(
  "$UNTANGLE" hexcube-folded.vtk --rest hexcube-rest.vtk --slide-boundary -o again.vtk --threads 1 2>&1)

# a fixed vertex stays fixed: the file's flags (every boundary vertex) leave nothing to slide
"$MAKE" hexcube 3 0.6 1 small.vtk > /dev/null
"$UNTANGLE" small.vtk --rest small-rest.vtk --slide-boundary -o small-out.vtk --report small.json --quiet --threads 1 2> /dev/null
check "fixed vertices do not slide" test "$(json small.json vertices_sliding_on_surfaces)/$(json small.json vertices_sliding_on_curves)" = 0/0
check "with the option the distance is a number" test "$(python3 -c "import json; print(json.load(open('hexcube.json'))['max_distance_to_target'] is None)")" = False
"$UNTANGLE" small.vtk --rest small-rest.vtk -o plain.vtk --report plain.json --quiet --threads 1 2> /dev/null
check "without the option the report's distance is null" test "$(json plain.json max_distance_to_target)" = None

# bad options
refused() {   # refused EXIT PHRASE ARGS...: the run exits EXIT and says PHRASE
  local code=$1 phrase=$2 rc=0
  shift 2
  "$UNTANGLE" "$@" > out.txt 2>&1 || rc=$?
  [ $rc -eq "$code" ] && grep -q -- "$phrase" out.txt
}
check "--feature-angle needs --slide-boundary" refused 2 "requires --slide-boundary" small.vtk --feature-angle 20 -o x.vtk
check "--feature-angle 0 is refused" refused 2 "feature-angle" small.vtk --slide-boundary --feature-angle 0 -o x.vtk
check "--feature-angle 120 is refused" refused 2 "feature-angle" small.vtk --slide-boundary --feature-angle 120 -o x.vtk
check "--slide-boundary excludes --fix-boundary" refused 2 "excludes" small.vtk --slide-boundary --fix-boundary -o x.vtk
"$MAKE" cube 3 0.6 1 tets.vtk > /dev/null
check "--slide-boundary with --refine is refused" refused 2 "refinement is not offered with a sliding boundary" \
  tets.vtk --rest tets-rest.vtk --slide-boundary --refine -o x.vtk
"$MAKE" torus 6 0.3 1 torus.obj > /dev/null
check "a seamless map refuses --slide-boundary" refused 2 "not offered for seamless" torus.obj --slide-boundary -o x.obj
check "no output was written by a refused run" test ! -e x.vtk -a ! -e x.obj

if [ -n "$DATA" ] && [ -d "$DATA/cuboidblocks/rockerarm.hexex_block344" ]; then
  # CuboidBlocks: a column of 16 cells whose boundary fixed leaves a cell
  # inverted (issue 36); sliding, none.  Its folded boundary, read for
  # features, held 18 corners and left the cell inverted: the rest (the
  # cuboid) shows its 8
  "$MAKE_BLOCK" "$DATA/cuboidblocks/rockerarm.hexex_block344" 8 column.vtk > /dev/null
  rc=0
  "$UNTANGLE" column.vtk --rest column-rest.vtk -o column-fixed.vtk --threads 1 --quiet --time-limit 30 2> /dev/null || rc=$?
  check "block 344 with its boundary fixed is not untangled (exit $rc)" test $rc -ne 0
  rc=0
  "$UNTANGLE" column.vtk --rest column-rest.vtk --slide-boundary --fixed none.txt -o column-out.vtk \
    --report column.json --threads 1 --quiet --time-limit 60 2> column.err || rc=$?
  check "block 344 sliding: exit 0 ($rc: $(cat column.err))" test $rc -eq 0
  check "block 344: the features of the rest, its cuboid's 8 corners held" test "$(json column.json corner_vertices_held)" = 8
  check "block 344: on the input's boundary" near_boundary column.vtk column-out.vtk 1e-9
fi
if [ -n "$DATA" ] && [ -d "$DATA/cuboidblocks/rockerarm.hexex_block348" ]; then
  # a block that is not untangled in 20 s: what is written is never worse
  # than the input (stage 1 let the sliding vertices move freely, and the
  # projection after it left 142 cells inverted of 56, reported as
  # unrepairable and written)
  "$MAKE_BLOCK" "$DATA/cuboidblocks/rockerarm.hexex_block348" 8 hard.vtk > /dev/null
  "$UNTANGLE" hard.vtk --rest hard-rest.vtk --slide-boundary --fixed none.txt -o hard-out.vtk --report hard.json \
    --threads 1 --quiet --time-limit 20 2> /dev/null
  check "block 348: no more inverted cells than given" \
    test "$(json hard.json inverted_after)" -le "$(json hard.json inverted_before)"
  check "block 348: not called unrepairable" test "$(json hard.json status)" != \
    "inverted elements or over-wound stars whose vertices are all fixed are left: nothing can repair them"
fi
if [ -n "$DATA" ] && [ -f "$DATA/hex/fandisk-input.vtk" ]; then
  rc=0
  "$UNTANGLE" "$DATA/hex/fandisk-input.vtk" --slide-boundary --fixed none.txt -o fandisk-out.vtk --report fandisk.json --threads 1 \
    --quiet --time-limit 60 2> fandisk.err || rc=$?
  check "fandisk sliding: exit 0 ($rc: $(cat fandisk.err))" test $rc -eq 0
  check "fandisk: every cell positive" test "$(json fandisk.json inverted_after)" = 0
  check "fandisk: on the input's boundary" near_boundary "$DATA/hex/fandisk-input.vtk" fandisk-out.vtk 1e-9
fi
if [ -n "$DATA" ] && [ -f "$DATA/hex/bird-input.vtk" ]; then
  # a published pipeline's tangled bird (16,934 hexahedra, 288 inverted):
  # two boundary quadrilaterals have a reflex corner on a "curve" of 39-47
  # degree edges, which held each corner flat (2 cells left after 120 s);
  # no feature is found by angle at a folded corner, and it untangles in
  # about 5 s with the other features kept
  rc=0
  "$UNTANGLE" "$DATA/hex/bird-input.vtk" --slide-boundary -o bird-out.vtk --report bird.json --threads 1 --quiet \
    --time-limit 60 2> bird.err || rc=$?
  check "bird sliding: exit 0 ($rc: $(cat bird.err))" test $rc -eq 0
  check "bird: every cell positive" test "$(json bird.json inverted_after)" = 0
  check "bird: the other features kept" test "$(json bird.json vertices_sliding_on_curves)" -gt 100
  check "bird: on the input's boundary" near_boundary "$DATA/hex/bird-input.vtk" bird-out.vtk 1e-9
fi

echo "$checks checks, $failures failures"
[ "$failures" -eq 0 ]
