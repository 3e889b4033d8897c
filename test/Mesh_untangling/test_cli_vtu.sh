#!/usr/bin/env bash
# untangle_mesh on .vtu files: a tangled cube of tetrahedra that
# make_tangled_mesh writes as .vtu (its fixed vertices in the point array
# 'fixed', its rest grid in NAME-rest.vtu) is untangled into a .vtu with no
# inverted tetrahedron, which reads back with the same fixed vertices.
#
# usage: test_cli_vtu.sh UNTANGLE_MESH MAKE_TANGLED_MESH
set -u
. "$(dirname "$0")/cli_test_harness.sh" test_cli_vtu "$@"

cube_make vtu
check "make_tangled_mesh cube.vtu: the point array 'fixed'" grep -q 'Name="fixed"' cube.vtu
check "make_tangled_mesh cube.vtu: the rest grid" grep -q 'type="UnstructuredGrid"' cube-rest.vtu

cube_untangle vtu "the array"
check "untangle_mesh cube.vtu: its output names the inverted count" grep -Eq 'inverted' out.out
check "untangle_mesh cube.vtu: the result is a .vtu of appended raw data" grep -q '<AppendedData encoding="raw">' out.vtu

cube_read_back vtu

# The same cube as meshio writes it to .vtk by default (VTK 5.1: OFFSETS and
# CONNECTIVITY arrays, binary), as a user converting a mesh hands it over:
# the same run as from the .vtu.
if /usr/bin/python3 -c "import meshio" 2> /dev/null; then
  /usr/bin/python3 -c "import meshio, sys; meshio.write(sys.argv[2], meshio.read(sys.argv[1]))" \
    cube.vtu cube51.vtk > meshio.out 2>&1
  check "meshio wrote cube.vtu as VTK 5.1" grep -q "OFFSETS vtktypeint64" cube51.vtk
  "$UNTANGLE" cube51.vtk --rest cube-rest.vtu -o out51.vtk --report out51.json > out51.out 2>&1
  echo $? > out51.rc
  check "untangle_mesh on VTK 5.1: exit 0" ran_well out51
  check "untangle_mesh on VTK 5.1: the fixed vertices of the point FIELD 'fixed'" json_is out51.json fixed_vertices 98
  check "untangle_mesh on VTK 5.1: the run of the .vtu" python3 - out.json out51.json << 'PY'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:])
keys = ["inverted_before", "inverted_after", "energy_evaluations", "final_energy", "locally_invertible"]
sys.exit(0 if all(a[k] == b[k] for k in keys) else 1)
PY
else
  echo "meshio is absent (Debian python3-meshio): the VTK 5.1 case is not run"
fi

echo "$checks checks, $failures failed"
[ "$failures" = 0 ]
