#!/usr/bin/env bash
# untangle_mesh on Gmsh files: a tangled cube of tetrahedra that
# make_tangled_mesh writes as .msh (its fixed vertices in the physical group
# 'fixed', its rest grid in NAME-rest.msh) is untangled into a .msh with no
# inverted tetrahedron, which reads back with the same fixed vertices.
#
# usage: test_cli_gmsh.sh UNTANGLE_MESH MAKE_TANGLED_MESH
set -u
. "$(dirname "$0")/cli_test_harness.sh" test_cli_gmsh "$@"

cube_make msh
check "make_tangled_mesh cube.msh: the physical group 'fixed'" grep -q '^0 1 "fixed"$' cube.msh
check "make_tangled_mesh cube.msh: the rest grid" grep -q '^4.1 0 8$' cube-rest.msh

cube_untangle msh "the group" -q
check "untangle_mesh cube.msh: the result is MSH 4.1 ASCII" grep -q '^4.1 0 8$' out.msh

cube_read_back msh

echo "$checks checks, $failures failed"
[ "$failures" = 0 ]
