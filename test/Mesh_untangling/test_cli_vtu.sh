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

echo "$checks checks, $failures failed"
[ "$failures" = 0 ]
