#!/usr/bin/env bash
# The hexahedral meshes of the CuboidBlocks instances (manual, section
# "Quadrilateral and Hexahedral Meshes"): for every block, make_block_hex_mesh
# with the given options, then untangle_mesh with one thread; prints one row
# per block: inverted hexahedra before and after (inv_in, inv_out: those free
# vertices could repair; fixed_inv: those whose inverted corners have only
# fixed vertices, before and after alike), min scaled Jacobian before and
# after, seconds, exit code of untangle_mesh.
#
# usage: block_hexes.sh BUILD_DIR DATA_DIR/cuboidblocks N TIME_LIMIT WORK_DIR [make_block_hex_mesh options]
set -euo pipefail
if [ $# -lt 5 ]; then
  sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
fi
BUILD=$1 BLOCKS=$2 N=$3 LIMIT=$4 WORK=$5
shift 5
mkdir -p "$WORK"
field() { sed -n "s/^  \"$1\": \([^,]*\),\{0,1\}\$/\1/p" "$2"; }
printf '%-40s %6s %6s %7s %9s %9s %9s %8s %3s\n' block hexes inv_in inv_out fixed_inv sj_in sj_out seconds rc
for dir in "$BLOCKS"/*/; do
  name=$(basename "$dir")
  out=$WORK/$name.vtk
  if ! "$BUILD/bin/make_block_hex_mesh" "$@" "$dir" "$N" "$out" > /dev/null 2> "$WORK/$name.err"; then
    printf '%-40s %s\n' "$name" "not made: $(cat "$WORK/$name.err")"
    continue
  fi
  rc=0
  "$BUILD/bin/untangle_mesh" "$out" --rest "${out%.vtk}-rest.vtk" -o "${out%.vtk}-out.vtk" \
    --report "${out%.vtk}.json" --threads 1 --time-limit "$LIMIT" --quiet || rc=$?
  json=${out%.vtk}.json
  printf '%-40s %6s %6s %7s %9s %9.4f %9.4f %8.1f %3s\n' "$name" "$(field elements "$json")" \
    "$(field inverted_before "$json")" "$(field inverted_after "$json")" "$(field input_defects "$json")" \
    "$(field min_scaled_jacobian_before "$json")" "$(field min_scaled_jacobian_after "$json")" \
    "$(field seconds "$json")" "$rc"
done
