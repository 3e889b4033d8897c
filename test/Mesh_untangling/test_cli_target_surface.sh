#!/usr/bin/env bash
# --target-surface (issue 36, item 1): the boundary slides on a surface
# given instead of its own.  A tangled grid of the unit cube (hexahedra,
# tetrahedra) fitted to a box moved and stretched by less than half a grid
# cell: every face vertex ends on its face of the box, every edge vertex on
# its edge, every corner on its corner bit for bit.  The same cube fitted to
# a sphere (no feature: the cube's edges and corners slide on it).  A real
# hexahedral mesh of a published pipeline fitted to the boundary of the
# tetrahedral mesh it was made from (kitty: its own boundary has features
# that the shape has not).  Every boundary vertex of a result ends within
# 1e-9 of the diagonal from the target.  Bad options and files are refused
# with the reason, and nothing is written.
# usage: test_cli_target_surface.sh UNTANGLE_MESH MAKE_TANGLED_MESH [DATA_DIR]
set -u
. "$(dirname "${BASH_SOURCE[0]}")/cli_test_harness.sh" test_cli_target_surface "$@"
DATA=${3:-}

: > none.txt

# box LO HI OUT: the box [LO, HI] (x,y,z each) as an OFF of 12 triangles
box() {
  python3 - "$@" << 'PY'
import sys
lo, hi = [float(x) for x in sys.argv[1].split(',')], [float(x) for x in sys.argv[2].split(',')]
P = [[(hi if (i >> k) & 1 else lo)[k] for k in range(3)] for i in range(8)]
T = []
for a, b, c, d in ((0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)):
    T += [(a, b, c), (a, c, d)]
open(sys.argv[3], 'w').write('OFF\n8 %d 0\n' % len(T) + ''.join('%r %r %r\n' % tuple(p) for p in P) +
                             ''.join('3 %d %d %d\n' % t for t in T))
PY
}
# on_box IN OUT LO HI: every coordinate of an IN vertex at 0 or 1 is in OUT
# the box's (LO at 0, HI at 1) within 1e-12, the corners' bit for bit
on_box() {
  python3 - "$@" << 'PY'
import sys
from legacy_vtk import points
a, b = points(sys.argv[1]), points(sys.argv[2])
lo, hi = [float(x) for x in sys.argv[3].split(',')], [float(x) for x in sys.argv[4].split(',')]
bad = 0
for p, q in zip(a, b):
    on = [c for c in range(3) if p[c] in (0.0, 1.0)]
    want = [lo[c] if p[c] == 0.0 else hi[c] for c in range(3)]
    bad += sum(abs(q[c] - want[c]) > 1e-12 for c in on)
    bad += len(on) == 3 and q != want
sys.exit(1 if bad else 0)
PY
}
# on_target MESH TARGET TOLERANCE: every boundary vertex of MESH (.vtk of
# tetrahedra or hexahedra) is within TOLERANCE times its diagonal of the
# triangles of TARGET (.off, or the boundary of a .vtk of tetrahedra)
on_target() {
  /usr/bin/python3 - "$@" << 'PY'
import sys
import numpy as np
import legacy_vtk
from surface_distance import boundary_faces, diagonal, farthest, triangles
lines, _, p = legacy_vtk.read(sys.argv[1])
vertices = sorted({v for f in boundary_faces(legacy_vtk.cells(lines)) for v in f})
if sys.argv[2].endswith('.off'):
    words = open(sys.argv[2]).read().split()
    nv, nf = int(words[1]), int(words[2])
    q = np.array(words[4:4 + 3 * nv], float).reshape(nv, 3)
    tri = np.array(words[4 + 3 * nv:], int).reshape(nf, 4)[:, 1:]
else:
    target_lines, _, q = legacy_vtk.read(sys.argv[2])
    tri = triangles(boundary_faces(legacy_vtk.cells(target_lines)))
worst = farthest(p, vertices, q, tri)
print('farthest boundary vertex from the target:', worst)
sys.exit(0 if worst <= float(sys.argv[3]) * diagonal(p) else 1)
PY
}
figure() { python3 -c "import json, sys; print(json.load(open('$1'))['$2'])"; }

lo=-0.05,0.04,0.03
hi=1.06,0.95,1.04
box $lo $hi box.off
for kind in hexcube cube; do
  "$MAKE" $kind 4 0.6 1 $kind.vtk > /dev/null
  rc=0
  "$UNTANGLE" $kind.vtk --rest $kind-rest.vtk --slide-boundary --target-surface box.off --fixed none.txt -o $kind-box.vtk \
    --report $kind.json --threads 1 --quiet 2> $kind.err || rc=$?
  check "$kind onto the box: exit 0 ($rc: $(cat $kind.err))" test $rc -eq 0
  check "$kind onto the box: locally invertible" test "$(json $kind.json locally_invertible)" = True
  check "$kind onto the box: every vertex on its face, edge or corner of the box" on_box $kind.vtk $kind-box.vtk $lo $hi
  check "$kind onto the box: 54 on surfaces, 36 on curves, 8 corners" \
    test "$(json $kind.json vertices_sliding_on_surfaces)/$(json $kind.json vertices_sliding_on_curves)/$(json $kind.json corner_vertices_held)" = 54/36/8
  check "$kind onto the box: the report names the surface" test "$(json $kind.json target_surface)" = box.off
  check "$kind onto the box: the boundary was moved onto it" \
    python3 -c "import json, sys; r = json.load(open('$kind.json')); sys.exit(0 if r['boundary_moved_onto_target'] > 0.05 and 0 <= r['max_distance_to_target'] < 1e-12 else 1)"
done
check "the summary tells how far the boundary was moved" grep -q "^target surface box.off: the boundary was moved onto it by" <(
  "$UNTANGLE" hexcube.vtk --rest hexcube-rest.vtk --slide-boundary --target-surface box.off --fixed none.txt -o again.vtk --threads 1 2>&1)

# a sphere of radius 0.8 around the cube's centre, 24 x 48 quadrilaterals split in two
python3 - << 'PY'
import math
n, m, c, R = 24, 48, 0.5, 0.8
P = [(c, c, c + R)] + [(c + R * math.sin(math.pi * i / n) * math.cos(2 * math.pi * j / m),
                        c + R * math.sin(math.pi * i / n) * math.sin(2 * math.pi * j / m),
                        c + R * math.cos(math.pi * i / n)) for i in range(1, n) for j in range(m)] + [(c, c, c - R)]
at = lambda i, j: 1 + (i - 1) * m + j % m
T = [(0, at(1, j), at(1, j + 1)) for j in range(m)]
for i in range(1, n - 1):
    for j in range(m):
        T += [(at(i, j), at(i + 1, j), at(i + 1, j + 1)), (at(i, j), at(i + 1, j + 1), at(i, j + 1))]
T += [(at(n - 1, j), len(P) - 1, at(n - 1, j + 1)) for j in range(m)]
open('sphere.off', 'w').write('OFF\n%d %d 0\n' % (len(P), len(T)) + ''.join('%.17g %.17g %.17g\n' % p for p in P) +
                              ''.join('3 %d %d %d\n' % t for t in T))
PY
"$MAKE" cube 6 0.6 1 c6.vtk > /dev/null
rc=0
"$UNTANGLE" c6.vtk --rest c6-rest.vtk --slide-boundary --target-surface sphere.off --fixed none.txt -o c6-sphere.vtk \
  --report sphere.json --threads 1 --quiet 2> sphere.err || rc=$?
check "cube onto the sphere: exit 0 ($rc: $(cat sphere.err))" test $rc -eq 0
check "cube onto the sphere: locally invertible" test "$(json sphere.json locally_invertible)" = True
check "cube onto the sphere: no curve, no corner held (the sphere has none)" \
  test "$(json sphere.json vertices_sliding_on_curves)/$(json sphere.json corner_vertices_held)" = 0/0
check "cube onto the sphere: every boundary vertex on it" on_target c6-sphere.vtk sphere.off 1e-9

if [ -n "$DATA" ] && [ -f "$DATA/hex/kitty-input.vtk" ] && [ -f "$DATA/hex/kitty-ref.tet.vtk" ]; then
  rc=0
  "$UNTANGLE" "$DATA/hex/kitty-input.vtk" --slide-boundary --target-surface "$DATA/hex/kitty-ref.tet.vtk" --fixed none.txt \
    -o kitty-out.vtk --report kitty.json --threads 1 --quiet --time-limit 120 2> kitty.err || rc=$?
  check "kitty onto the shape it was made from: exit 0 ($rc: $(cat kitty.err))" test $rc -eq 0
  check "kitty: every cell positive" test "$(json kitty.json inverted_after)" = 0
  check "kitty: on the shape's boundary" on_target kitty-out.vtk "$DATA/hex/kitty-ref.tet.vtk" 1e-9
fi

# bad options and files
refused() {   # refused EXIT PHRASE ARGS...: the run exits EXIT and says PHRASE
  local code=$1 phrase=$2 rc=0
  shift 2
  "$UNTANGLE" "$@" > out.txt 2>&1 || rc=$?
  [ $rc -eq "$code" ] && grep -q -- "$phrase" out.txt
}
check "--target-surface needs --slide-boundary" refused 2 "requires --slide-boundary" cube.vtk --target-surface box.off -o x.vtk
check "a missing target surface is named" refused 2 "nowhere.off" cube.vtk --slide-boundary --target-surface nowhere.off -o x.vtk
"$MAKE" quadsquare 3 0.6 1 quads.vtk > /dev/null
check "a target of quadrilaterals is refused" refused 2 "a target surface is a mesh of triangles or of tetrahedra" \
  cube.vtk --slide-boundary --target-surface quads.vtk -o x.vtk
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n' > flat.off
check "a target of no area is refused" refused 2 "no triangle of non-zero area" \
  cube.vtk --slide-boundary --target-surface flat.off -o x.vtk
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n' > broken.off
check "a target file naming a vertex that is not there is refused with its line" refused 2 "broken.off" \
  cube.vtk --slide-boundary --target-surface broken.off -o x.vtk
"$MAKE" square 4 0.6 1 square.vtk > /dev/null
check "a 2D map refuses a target surface" refused 2 "a target surface is for 3D meshes" \
  square.vtk --slide-boundary --target-surface box.off -o x.vtk
check "no output was written by a refused run" test ! -e x.vtk

echo "$checks checks, $failures failures"
[ "$failures" -eq 0 ]
