#!/usr/bin/env bash
# untangle_mesh on an unstructured hex-dominant mesh as meshing pipelines
# make them: make_hex_dominant_mesh's hexahedral core, pyramids on it,
# TetGen's tetrahedra out to a sphere and prism layers outside, conforming,
# its inside tangled and its outermost surface fixed, is untangled as .vtk:
# every corner of every cell ends positive, the report counts the cells by
# kind as the generator made them, the fixed vertices stay bit for bit in
# place; with no fixed vertex and the boundary sliding, it untangles too.
#
# usage: test_cli_hex_dominant.sh UNTANGLE_MESH MAKE_TANGLED_MESH MAKE_HEX_DOMINANT_MESH
set -u
if [ $# -lt 3 ] || [ ! -x "$3" ]; then
  echo "usage: test_cli_hex_dominant.sh UNTANGLE_MESH MAKE_TANGLED_MESH MAKE_HEX_DOMINANT_MESH" >&2
  exit 2
fi
case $3 in /*) MAKE_HEX=$3 ;; *) MAKE_HEX=$PWD/$3 ;; esac   # (before the harness moves into its folder)
. "$(dirname "${BASH_SOURCE[0]}")/cli_test_harness.sh" test_cli_hex_dominant "$@"

"$MAKE_HEX" --core 3 --layers 2 0.8 5 hd.vtk > make.out 2>&1
echo $? > make.rc
check "make_hex_dominant_mesh: exit 0 ($(tail -n 3 make.out))" ran_well make
check "make_hex_dominant_mesh: the rest beside it" test -s hd-rest.vtk
check "make_hex_dominant_mesh: it prints the untangle_mesh command" grep -q "untangle_mesh hd.vtk --rest hd-rest.vtk" make.out
# the counts it printed: "cells: tetrahedra T, pyramids P, prisms R, hexahedra H"
read -r tets pyramids prisms hexes <<< "$(sed -nE 's/.*cells: tetrahedra ([0-9]+), pyramids ([0-9]+), prisms ([0-9]+), hexahedra ([0-9]+).*/\1 \2 \3 \4/p' make.out)"
check "make_hex_dominant_mesh: the counts by kind (${tets:-?} ${pyramids:-?} ${prisms:-?} ${hexes:-?})" \
  test "${tets:-0}" -gt 0 -a "${pyramids:-0}" -eq 54 -a "${prisms:-0}" -gt 0 -a "${hexes:-0}" -eq 27
inverted=$(sed -nE 's/^inverted cells after tangling: ([0-9]+)$/\1/p' make.out)
check "make_hex_dominant_mesh: tangled (${inverted:-?} inverted cells)" test "${inverted:-0}" -gt 0
check "hd.vtk: VTK cell types 10, 12, 13 and 14" has_VTK_cell_types hd.vtk 10 12 13 14

"$UNTANGLE" hd.vtk --rest hd-rest.vtk -o res.vtk --report r.json --threads 1 > out.out 2>&1
echo $? > out.rc
check "hd.vtk: exit 0 ($(tail -n 3 out.out))" ran_well out
check "hd.vtk: tangled before" json_positive r.json inverted_before
check "hd.vtk: as tangled as the generator said" json_is r.json inverted_before "${inverted:-?}"
check "hd.vtk: no inverted cell after" json_is r.json inverted_after 0
check "hd.vtk: the cells by kind as the generator made them" python3 -c "
import json, sys
kinds = json.load(open('r.json'))['cells_by_kind']
print(kinds)
sys.exit(kinds != {'tetrahedron': $tets, 'pyramid': $pyramids, 'prism': $prisms, 'hexahedron': $hexes})"
check "hd.vtk: the fixed vertices bit for bit in place" same_fixed hd.vtk res.vtk

# no fixed vertex, the boundary sliding on itself
: > empty.txt
"$UNTANGLE" hd.vtk --rest hd-rest.vtk --fixed empty.txt --slide-boundary -o slide.vtk --report s.json --threads 1 \
  > slide.out 2>&1
echo $? > slide.rc
check "--slide-boundary, nothing fixed: exit 0 ($(tail -n 3 slide.out))" ran_well slide
check "--slide-boundary, nothing fixed: no fixed vertex" json_is s.json fixed_vertices 0
check "--slide-boundary, nothing fixed: tangled before" json_is s.json inverted_before "${inverted:-?}"
check "--slide-boundary, nothing fixed: no inverted cell after" json_is s.json inverted_after 0

echo "$checks checks, $failures failed"
[ "$failures" = 0 ]
