#!/usr/bin/env bash
# untangle_mesh on Gmsh files: a tangled cube of tetrahedra that
# make_tangled_mesh writes as .msh (its fixed vertices in the physical group
# 'fixed', its rest grid in NAME-rest.msh) is untangled into a .msh with no
# inverted tetrahedron, which reads back with the same fixed vertices.
#
# usage: test_cli_gmsh.sh UNTANGLE_MESH MAKE_TANGLED_MESH
set -u
. "$(dirname "$0")/cli_test_harness.sh" test_cli_gmsh "$@"

# (the report is pretty-printed JSON: one top-level key per line)
json_get() { grep -E "^  \"$2\": " "$1" 2> /dev/null | head -n 1 | sed -E 's/^  "[^"]*": //; s/,$//'; }
json_is() { [ "$(json_get "$1" "$2")" = "$3" ]; }
json_positive() { local v; v=$(json_get "$1" "$2"); [[ "$v" =~ ^[0-9]+$ ]] && [ "$v" -gt 0 ]; }
ran_well() { [ "$(cat "$1.rc")" = 0 ]; }

"$MAKE" cube 4 0.6 1 cube.msh > make.out 2>&1
echo $? > make.rc
check "make_tangled_mesh cube.msh: exit 0" ran_well make
check "make_tangled_mesh cube.msh: the fixed vertices in the file, no cube-fixed.txt" [ ! -e cube-fixed.txt ]
check "make_tangled_mesh cube.msh: the physical group 'fixed'" grep -q '^0 1 "fixed"$' cube.msh
check "make_tangled_mesh cube.msh: the rest grid" grep -q '^4.1 0 8$' cube-rest.msh

"$UNTANGLE" cube.msh --rest cube-rest.msh -o out.msh --report out.json -q > out.out 2>&1
echo $? > out.rc
check "untangle_mesh cube.msh: exit 0" ran_well out
check "untangle_mesh cube.msh: tangled before" json_positive out.json inverted_before
check "untangle_mesh cube.msh: no inverted tetrahedron after" json_is out.json inverted_after 0
check "untangle_mesh cube.msh: the fixed vertices of the group" json_is out.json fixed_vertices 98
check "untangle_mesh cube.msh: the result is MSH 4.1 ASCII" grep -q '^4.1 0 8$' out.msh

"$UNTANGLE" out.msh --rest cube-rest.msh -o again.msh --report again.json -q > again.out 2>&1
echo $? > again.rc
check "the result read back: exit 0" ran_well again
check "the result read back: no inverted tetrahedron" json_is again.json inverted_before 0
check "the result read back: the same fixed vertices" json_is again.json fixed_vertices 98

echo "$checks checks, $failures failed"
[ "$failures" = 0 ]
