#!/usr/bin/env bash
# Feature edges and corners a meshing tool wrote into the file (issue 36):
# with --slide-boundary, a MEDIT file's Edges are feature curves and its
# Corners stay, besides what --feature-angle finds (90: nothing).  A tangled
# tetrahedral grid of the unit cube whose box edges and a line across its
# bottom face (y = 0.5) are listed as Edges, its 8 corners as Corners, at
# --feature-angle 90: every vertex of a listed line ends on it, the line's
# ends where it meets the box's edges are held, the box's corners stay bit
# for bit, and the written file lists the same Edges and Corners.  Without
# the Edges the whole boundary is one patch (no curve); an edge inside the
# mesh is counted and is no feature; an index out of range is refused with
# its line.
# usage: test_cli_feature_edges.sh UNTANGLE_MESH MAKE_TANGLED_MESH
set -u
. "$(dirname "${BASH_SOURCE[0]}")/cli_test_harness.sh" test_cli_feature_edges "$@"

: > none.txt
"$MAKE" cube 4 0.6 1 cube.vtk > /dev/null

# medit IN REST OUT EDGES: IN (tetrahedra, .vtk) as MEDIT with the box's
# edges and the line y = 0.5, z = 0 as Edges (EDGES: box, line, inside,
# none or out-of-range), the box's corners as Corners; REST tells where each
# vertex is on the grid
medit() {
  python3 - "$@" << 'PY'
import sys
import legacy_vtk
lines, _, p = legacy_vtk.read(sys.argv[1])
r = legacy_vtk.points(sys.argv[2])
tets = legacy_vtk.cells(lines)
mesh_edges = {tuple(sorted((t[i], t[j]))) for t in tets for i in range(4) for j in range(i + 1, 4)}
def wanted(a, b):
    on_box = [c for c in range(3) if r[a][c] in (0.0, 1.0) and r[a][c] == r[b][c]]
    line = r[a][1] == r[b][1] == 0.5 and r[a][2] == r[b][2] == 0.0
    return len(on_box) >= 2 or (line and 'line' in sys.argv[4])
edges = sorted(e for e in mesh_edges if wanted(*e))
if 'inside' in sys.argv[4]:
    edges.append(next(e for e in sorted(mesh_edges) if all(0 < r[v][c] < 1 for v in e for c in range(3))))
if 'none' in sys.argv[4]:
    edges = []
if 'out-of-range' in sys.argv[4]:
    edges.append((0, len(p) + 7))
corners = [v for v in range(len(p)) if all(x in (0.0, 1.0) for x in r[v])]
with open(sys.argv[3], 'w') as f:
    f.write('MeshVersionFormatted 2\nDimension 3\nVertices\n%d\n' % len(p))
    f.write(''.join('%.17g %.17g %.17g 0\n' % tuple(q) for q in p))
    f.write('Tetrahedra\n%d\n' % len(tets) + ''.join('%d %d %d %d 1\n' % tuple(v + 1 for v in t) for t in tets))
    if edges:
        f.write('Edges\n%d\n' % len(edges) + ''.join('%d %d 1\n' % (a + 1, b + 1) for a, b in edges))
    f.write('Corners\n%d\n' % len(corners) + ''.join('%d\n' % (v + 1) for v in corners) + 'End\n')
PY
}
# kept REST OUT: every vertex of a listed line (of REST's grid) is on it in
# OUT (.mesh), within 1e-12, and the corners bit for bit
kept() {
  python3 - "$@" << 'PY'
import sys
import legacy_vtk
r = legacy_vtk.points(sys.argv[1])
words = open(sys.argv[2]).read().split()
at = words.index('Vertices')
n = int(words[at + 1])
q = [[float(x) for x in words[at + 2 + 4 * v:at + 5 + 4 * v]] for v in range(n)]
bad = 0
for v in range(n):
    fixed = {c for c in range(3) if r[v][c] in (0.0, 1.0)}
    if r[v][1] == 0.5 and r[v][2] == 0.0:
        fixed |= {1, 2}
    if len(fixed) >= 2:
        bad += sum(abs(q[v][c] - r[v][c]) > 1e-12 for c in fixed)
    if len(fixed) == 3:
        bad += q[v] != r[v]
print(bad, 'coordinates off their line')
sys.exit(1 if bad else 0)
PY
}
section() { python3 -c "import sys; w = open(sys.argv[1]).read().split(); print(w[w.index(sys.argv[2]) + 1] if sys.argv[2] in w else 0)" "$1" "$2"; }

medit cube.vtk cube-rest.vtk lined.mesh box,line
rc=0
"$UNTANGLE" lined.mesh --rest cube-rest.vtk --slide-boundary --feature-angle 90 --fixed none.txt -o lined-out.mesh \
  --report lined.json --threads 1 2> lined.err || rc=$?
check "the file's edges and corners: exit 0 ($rc: $(cat lined.err))" test $rc -eq 0
check "the file's edges and corners: locally invertible" test "$(json lined.json locally_invertible)" = True
check "37 on curves (the box's edges but 2, the line's 3), 2 held where the line meets them, 51 on surfaces" \
  test "$(json lined.json vertices_sliding_on_curves)/$(json lined.json corner_vertices_held)/$(json lined.json vertices_sliding_on_surfaces)" = 37/2/51
check "the report counts the file's edges, none inside" \
  test "$(json lined.json feature_edges_given)/$(json lined.json feature_edges_inside)" = "$(section lined.mesh Edges)/0"
check "the report names the file's corners as fixed" test "$(json lined.json fixed)" = "none.txt and lined.mesh's corners"
check "every vertex of a listed line on it, the corners where they were" kept cube-rest.vtk lined-out.mesh
check "the written file lists the same edges and corners" \
  test "$(section lined-out.mesh Edges)/$(section lined-out.mesh Corners)" = "$(section lined.mesh Edges)/8"
check "the summary tells the edges given" grep -q "^feature edges: $(section lined.mesh Edges) given by lined.mesh, 0 of them inside" lined.err

medit cube.vtk cube-rest.vtk plain.mesh none
rc=0
"$UNTANGLE" plain.mesh --rest cube-rest.vtk --slide-boundary --feature-angle 90 --fixed none.txt -o plain-out.mesh \
  --report plain.json --threads 1 --quiet 2> plain.err || rc=$?
check "no edge at 90 degrees: exit 0 ($rc: $(cat plain.err))" test $rc -eq 0
check "no edge at 90 degrees: one patch, no curve" test "$(json plain.json vertices_sliding_on_curves)" = 0

medit cube.vtk cube-rest.vtk inside.mesh box,inside
rc=0
"$UNTANGLE" inside.mesh --rest cube-rest.vtk --slide-boundary --fixed none.txt -o inside-out.mesh \
  --report inside.json --threads 1 --quiet 2> inside.err || rc=$?
check "an edge inside: exit 0 ($rc: $(cat inside.err))" test $rc -eq 0
check "an edge inside: counted" test "$(json inside.json feature_edges_inside)" = 1

medit cube.vtk cube-rest.vtk bad.mesh box,out-of-range
rc=0
"$UNTANGLE" bad.mesh --slide-boundary -o bad-out.mesh > bad.txt 2>&1 || rc=$?
check "an edge out of range: refused ($rc: $(cat bad.txt))" test $rc -ne 0
check "an edge out of range: its line is named" grep -q "bad.mesh:[0-9]" bad.txt
check "an edge out of range: nothing written" test ! -e bad-out.mesh

echo "$checks checks, $failures failures"
[ "$failures" -eq 0 ]
