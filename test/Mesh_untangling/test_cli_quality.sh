#!/usr/bin/env bash
# --optimize-quality (issue 36, item 2): on valid but poorly shaped meshes
# (the interior vertices of make_tangled_mesh's rest grids moved at random)
# of hexahedra, tetrahedra, quadrilaterals and triangles, with the boundary
# fixed, the worst element's quality goes up by a clear margin, the map
# stays locally invertible, the boundary vertices keep their coordinates,
# and the figure the report gives is the verdict's own (min scaled
# Jacobian for cells); on a real hex mesh with the boundary of a published
# optimizer's output, above that optimizer's; from a tangled hex map whose
# rest shapes are poor, untangled first, and with a free boundary, it
# never goes down.  Without the option the report's figures are null; a
# seamless map refuses it.
# usage: test_cli_quality.sh UNTANGLE_MESH MAKE_TANGLED_MESH [DATA_DIR]
set -u
DATA=${3:-}
case $DATA in '' | /*) ;; *) DATA=$PWD/$DATA ;; esac
FIX_BOUNDARY="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../../benchmark/Mesh_untangling/fix_boundary_to.py"
. "$(dirname "${BASH_SOURCE[0]}")/cli_test_harness.sh" test_cli_quality "$@"

# gained REPORT MARGIN: the worst quality rose by MARGIN at least
gained() {
  python3 -c "import json,sys; r=json.load(open(sys.argv[1])); \
sys.exit(0 if r['min_quality_after_optimization'] >= r['min_quality_before_optimization'] + float(sys.argv[2]) else 1)" "$1" "$2"
}
# poor IN OUT AMPLITUDE: IN's interior vertices moved by up to AMPLITUDE times
# the grid spacing (make_tangled_mesh's rest grids have spacing 1 / N)
poor() {
  python3 - "$@" << 'EOF'
import random, sys
from collections import Counter
import legacy_vtk
path, out, amplitude, n = sys.argv[1], sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
lines, i, points = legacy_vtk.read(path)
cells = legacy_vtk.cells(lines)
faces = {3: [(0, 1), (1, 2), (2, 0)], 4: [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)],
         8: [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]}
if len(cells[0]) == 4 and all(p[2] == 0 for p in points):
    faces[4] = [(0, 1), (1, 2), (2, 3), (3, 0)]   # quadrilaterals
used = Counter(tuple(sorted(c[v] for v in f)) for c in cells for f in faces[len(cells[0])])
boundary = {v for f, k in used.items() if k == 1 for v in f}
random.seed(7)
flat = all(p[2] == 0 for p in points)
for v, p in enumerate(points):
    if v not in boundary:
        for c in range(2 if flat else 3):
            p[c] += amplitude / n * random.uniform(-1, 1)
open(out, 'w').write('\n'.join(legacy_vtk.with_points(lines, i, points)))
EOF
}
# same_boundary IN OUT N D: the points of IN on the boundary of [0, 1]^D (make_tangled_mesh's
# grids) are in OUT with the same coordinates, bit for bit
same_boundary() {
  python3 - "$@" << 'EOF'
import sys
from legacy_vtk import points
a, b = points(sys.argv[1]), points(sys.argv[2])
n = int(sys.argv[3])
on_boundary = [v for v, p in enumerate(a) if any(c in (0.0, 1.0) for c in p[:int(sys.argv[4])])]
sys.exit(0 if len(a) == len(b) and on_boundary and all(a[v] == b[v] for v in on_boundary) else 1)
EOF
}

for shape in hexcube:6:3:0.3 cube:6:3:0.3 quadsquare:8:2:0.3 square:8:2:0.3; do
  IFS=: read -r name n d amplitude <<< "$shape"
  "$MAKE" "$name" "$n" 0.6 1 "$name.vtk" > /dev/null
  poor "$name-rest.vtk" "$name-poor.vtk" "$amplitude" "$n"
  "$UNTANGLE" "$name-poor.vtk" --rest "$name-poor.vtk" --fix-boundary -o "$name-q.vtk" --report "$name-q.json" --optimize-quality --quiet
  code=$?
  check "$name: exit 0 (code $code)" [ "$code" = 0 ]
  check "$name: locally invertible" [ "$(json "$name-q.json" locally_invertible)" = True ]
  check "$name: the worst quality up by 0.05 at least" gained "$name-q.json" 0.05
  check "$name: the boundary kept bit for bit" same_boundary "$name-poor.vtk" "$name-q.vtk" "$n" "$d"
  if [ "$name" = hexcube ] || [ "$name" = quadsquare ]; then
    check "$name: the figure is the verdict's min scaled Jacobian" \
      [ "$(json "$name-q.json" min_quality_after_optimization)" = "$(json "$name-q.json" min_scaled_jacobian_after)" ]
  fi
done

# Real hex meshes (from ../shared/data/hex), their boundary fixed to a
# published local optimizer's output: the rounds alone leave a worst scaled
# Jacobian of 0.36 (kitty, 7,083 hexahedra) and 0.44 (airplane1, 17,913)
# against the optimizer's 0.652 and 0.731; the local pass that ends the rung
# lifts both past it (0.715, 0.747; airplane1 needs the pass to outlast the
# sweeps that raise nothing: 0.694 when the first such sweep ended it).
if [ -n "$DATA" ]; then
  for case in kitty:0.652 airplane1:0.731; do
    mesh=${case%%:*} optimizer=${case#*:}
    python3 "$FIX_BOUNDARY" "$DATA/hex/$mesh-input.vtk" "$DATA/hex/$mesh-result.vtk" $mesh.vtk > /dev/null
    check "$mesh: the boundary fixed to the optimizer's" [ -s $mesh.vtk ]
    "$UNTANGLE" $mesh.vtk --fix-boundary -o $mesh-q.vtk --report $mesh-q.json --optimize-quality --quiet
    code=$?
    check "$mesh: exit 0 (code $code)" [ "$code" = 0 ]
    check "$mesh: locally invertible" [ "$(json $mesh-q.json locally_invertible)" = True ]
    check "$mesh: the worst scaled Jacobian above the optimizer's $optimizer" \
      python3 -c "import json, sys; exit(0 if json.load(open(sys.argv[1]))['min_scaled_jacobian_after'] > float(sys.argv[2]) else 1)" \
      $mesh-q.json "$optimizer"
    check "$mesh: the boundary kept bit for bit" python3 - $mesh.vtk $mesh-q.vtk << 'EOF2'
import sys
from collections import Counter
from legacy_vtk import points, read, cells
faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
hexes = cells(read(sys.argv[1])[0])
count = Counter(tuple(sorted(c[i] for i in f)) for c in hexes for f in faces)
boundary = {v for f, k in count.items() if k == 1 for v in f}
a, b = points(sys.argv[1]), points(sys.argv[2])
sys.exit(0 if boundary and all(a[v] == b[v] for v in boundary) else 1)
EOF2
  done
fi

# tangled, toward poor rest shapes: untangled first, then never worse
"$UNTANGLE" hexcube.vtk --rest hexcube-poor.vtk -o tangled-q.vtk --report tangled-q.json --optimize-quality \
  2> tangled-q.err
code=$?
check "tangled hexcube: exit 0 (code $code)" [ "$code" = 0 ]
check "tangled hexcube: there were inverted cells" [ "$(json tangled-q.json inverted_before)" != 0 ]
check "tangled hexcube: locally invertible" [ "$(json tangled-q.json locally_invertible)" = True ]
check "tangled hexcube: never worse" gained tangled-q.json 0
check "tangled hexcube: the summary gives the figures" grep -q 'quality: the worst scaled Jacobian' tangled-q.err

# a free boundary (nothing fixed): never worse, still locally invertible
"$UNTANGLE" square-poor.vtk --rest square-poor.vtk -o free-q.vtk --report free-q.json --optimize-quality --quiet
check "free square: exit 0" [ $? = 0 ]
check "free square: locally invertible" [ "$(json free-q.json locally_invertible)" = True ]
check "free square: never worse" gained free-q.json 0

# not asked: no figure
"$UNTANGLE" hexcube-poor.vtk --rest hexcube-poor.vtk --fix-boundary -o plain.vtk --report plain.json --quiet
check "without the option: exit 0" [ $? = 0 ]
check "without the option: no figure before" [ "$(json plain.json min_quality_before_optimization)" = None ]
check "without the option: no figure after" [ "$(json plain.json min_quality_after_optimization)" = None ]

# a seamless parameterization refuses it
"$MAKE" torus 6 1.3 5 torus.obj > /dev/null
"$UNTANGLE" torus.obj -o torus-out.obj --optimize-quality --quiet 2> torus.err
check "seamless: exit 2" [ $? = 2 ]
check "seamless: why" grep -q -- '--optimize-quality is not offered for seamless parameterizations' torus.err
check "seamless: nothing written" [ ! -e torus-out.obj ]

echo "test_cli_quality: $checks checks, $failures failed"
[ "$failures" = 0 ]
