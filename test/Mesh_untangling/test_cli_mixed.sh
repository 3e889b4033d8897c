#!/usr/bin/env bash
# untangle_mesh on hex-dominant meshes that mix tetrahedra, pyramids, prisms
# and hexahedra (issue 36, item 3).  make_tangled_mesh's mixedcube (a grid
# of hexahedra with a slab of prisms and one of pyramids around cell
# centres, tetrahedra where a pyramid's base is on the boundary), its
# interior tangled and its boundary fixed, is untangled through each format
# that holds such cells (.vtk, .vtu, .mesh, .msh): every corner of every
# cell ends positive, the fixed vertices bit for bit in place, the result
# reads back untangled; the report counts the cells by kind, and names the
# kind of each inverted cell left when none may move.  --optimize-quality
# never lowers the worst scaled Jacobian.  Gmsh's extruded plate of
# hexahedra and prisms reads valid and untangles once tangled.  Formats
# without 3D cells and phantoms are refused with the reason.
# usage: test_cli_mixed.sh UNTANGLE_MESH MAKE_TANGLED_MESH
set -u
GMSH_DATA=$(cd "$(dirname "${BASH_SOURCE[0]}")/data/gmsh" && pwd)
. "$(dirname "${BASH_SOURCE[0]}")/cli_test_harness.sh" test_cli_mixed "$@"

"$MAKE" mixedcube 4 0.8 3 mixed.vtk > make.out 2>&1
echo $? > make.rc
check "make_tangled_mesh mixedcube: exit 0" ran_well make
check "make_tangled_mesh mixedcube: it says what it wrote" grep -q "cells (tetrahedra, pyramids, prisms, hexahedra)" make.out
check "mixed.vtk: VTK cell types 10, 12, 13 and 14" has_VTK_cell_types mixed.vtk 10 12 13 14
"$MAKE" mixedcube 2 0.8 3 small.vtk > small.out 2>&1
check "make_tangled_mesh mixedcube 2: refused (a slab of each needs 3 cells a side)" test $? -eq 2

"$UNTANGLE" mixed.vtk --rest mixed-rest.vtk -o out.vtk --report out.json --threads 1 > out.out 2>&1
echo $? > out.rc
check "mixed.vtk: exit 0 ($(tail -n 3 out.out))" ran_well out
check "mixed.vtk: tangled before" json_positive out.json inverted_before
check "mixed.vtk: no inverted cell after" json_is out.json inverted_after 0
check "mixed.vtk: locally invertible" test "$(json out.json locally_invertible)" = True
check "mixed.vtk: the cells by kind" python3 -c "
import json, sys
sys.exit(json.load(open('out.json'))['cells_by_kind'] != {'hexahedron': 32, 'prism': 32, 'pyramid': 80, 'tetrahedron': 32})"
check "mixed.vtk: the fixed vertices bit for bit in place" same_fixed mixed.vtk out.vtk
check "mixed.vtk: the summary tells the kind of mesh" grep -q "^3D cells: inverted cells [1-9][0-9]* -> 0" out.out

for ext in vtu mesh msh; do
  "$MAKE" mixedcube 4 0.8 3 "mixed.$ext" > "make-$ext.out" 2>&1
  fixed=()
  [ "$ext" = mesh ] && fixed=(--fixed mixed-fixed.txt)
  "$UNTANGLE" "mixed.$ext" --rest "mixed-rest.$ext" "${fixed[@]}" -o "out.$ext" --report "$ext.json" --threads 1 \
    -q > "$ext.out" 2>&1
  rc=$?
  check "mixed.$ext: exit 0 ($rc: $(tail -n 2 $ext.out))" test $rc -eq 0
  check "mixed.$ext: as tangled as mixed.vtk" test "$(json $ext.json inverted_before)" = "$(json out.json inverted_before)"
  check "mixed.$ext: no inverted cell after" json_is "$ext.json" inverted_after 0
  check "mixed.$ext: the fixed vertices of the file" test "$(json $ext.json fixed_vertices)" = "$(json out.json fixed_vertices)"
  "$UNTANGLE" "out.$ext" --rest "mixed-rest.$ext" -o "again.vtk" --report "again-$ext.json" --threads 1 -q > /dev/null 2>&1
  check "out.$ext read back: no inverted cell" json_is "again-$ext.json" inverted_before 0
done

# every vertex fixed: the inverted cells stay, each named by its kind
python3 -c "print('\n'.join(str(v) for v in range(len(__import__('legacy_vtk').points('mixed.vtk')))))" > all.txt
rc=0
"$UNTANGLE" mixed.vtk --rest mixed-rest.vtk --fixed all.txt -o stuck.vtk --report stuck.json --threads 1 > stuck.out 2>&1 || rc=$?
check "every vertex fixed: exit not 0 ($rc)" test $rc -ne 0
check "every vertex fixed: the kinds of the inverted cells, one per id" python3 -c "
import json, sys
r = json.load(open('stuck.json'))
ids, kinds = r['inverted_cell_ids'], r['inverted_cell_kinds']
sys.exit(0 if ids and len(ids) == len(kinds) and set(kinds) <= {'tetrahedron', 'pyramid', 'prism', 'hexahedron'} else 1)"
check "every vertex fixed: the summary names them by kind and id" grep -Eq "^inverted cells left: (tetrahedron|pyramid|prism|hexahedron) [0-9]+" stuck.out

"$UNTANGLE" mixed.vtk --rest mixed-rest.vtk --optimize-quality -o quality.vtk --report quality.json --threads 1 -q \
  > quality.out 2>&1
check "--optimize-quality: exit 0" test $? -eq 0
check "--optimize-quality: never lowers the worst scaled Jacobian" python3 -c "
import json, sys
r = json.load(open('quality.json'))
b, a = r['min_quality_before_optimization'], r['min_quality_after_optimization']
print('worst scaled Jacobian', b, '->', a)
sys.exit(0 if r['inverted_after'] == 0 and 0 < b <= a <= 1 else 1)"

# A mesh made by another tool: Gmsh 4.8.4's plate with a hole, extruded
# (data/gmsh/plate.geo: 700 hexahedra, 635 prisms), valid as read in our
# vertex orders; its interior moved, its boundary fixed, it untangles.
# (as its own rest, its boundary fixed: the same mesh, written as legacy .vtk)
"$UNTANGLE" "$GMSH_DATA/plate-41.msh" --rest "$GMSH_DATA/plate-41.msh" --fix-boundary -o plate.vtk --report plate.json \
  --threads 1 -q > plate.out 2>&1
check "Gmsh's plate: read, no inverted cell ($(tail -n 2 plate.out))" json_is plate.json inverted_before 0
check "Gmsh's plate: its kinds" python3 -c "
import json, sys
sys.exit(json.load(open('plate.json'))['cells_by_kind'] != {'hexahedron': 700, 'prism': 635})"
python3 - << 'PY'
import math, random
import legacy_vtk
lines, i, points = legacy_vtk.read('plate.vtk')
end = next((k for k, l in enumerate(lines) if l.startswith('POINT_DATA')), len(lines))
random.seed(5)
for p in points:
    on = p[0] in (0, 2) or p[1] in (0, 1) or abs(p[2]) < 1e-12 or abs(p[2] - 0.6) < 1e-12 or \
         abs(math.hypot(p[0] - 0.7, p[1] - 0.5) - 0.25) < 1e-9
    if not on:
        p[0] += random.uniform(-0.08, 0.08)
        p[1] += random.uniform(-0.08, 0.08)
        p[2] += random.uniform(-0.03, 0.03)
open('plate-tangled.vtk', 'w').write('\n'.join(legacy_vtk.with_points(lines, i, points)[:end]) + '\n')
PY
"$UNTANGLE" plate-tangled.vtk --rest plate.vtk --fix-boundary -o plate-out.vtk --report plate-out.json --threads 1 -q \
  > plate-out.out 2>&1
check "Gmsh's plate tangled: exit 0 ($(tail -n 2 plate-out.out))" test $? -eq 0
check "Gmsh's plate tangled: inverted cells before" json_positive plate-out.json inverted_before
check "Gmsh's plate tangled: none after" json_is plate-out.json inverted_after 0

for ext in off obj; do
  msg=$("$UNTANGLE" mixed.vtk -o "x.$ext" 2>&1)
  check "a .$ext output is refused" grep -q "3D cells cannot be written as .$ext" <<< "$msg"
done
msg=$("$UNTANGLE" mixed.vtk -o x.vtk --phantoms p.vtk 2>&1)
check "--phantoms is refused" grep -q "no phantom element protects 3D cells" <<< "$msg"

echo "$checks checks, $failures failed"
[ "$failures" = 0 ]
