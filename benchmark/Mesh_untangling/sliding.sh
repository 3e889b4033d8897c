#!/usr/bin/env bash
# --slide-boundary on meshes made by other groups (manual, "Sliding
# Boundaries"), one thread: the hexahedral meshes of published pipelines in
# ../shared/data/hex with their boundary as produced, then the 14
# CuboidBlocks hexahedral meshes (make_block_hex_mesh N = 8, no padding)
# with their boundary fixed (the file's flags) and sliding.  Prints markdown
# tables: cells inverted before and after, min scaled Jacobian after, the
# farthest sliding vertex from its target, seconds (the library's), exit code.
# usage: sliding.sh [UNTANGLE_MESH [MAKE_BLOCK_HEX_MESH [DATA_DIR [TIME_LIMIT]]]]
set -eu
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
untangle=${1:-$here/../../build/bin/untangle_mesh}
make_block=${2:-$here/../../build/bin/make_block_hex_mesh}
data=${3:-$here/../../../shared/data}
limit=${4:-200}
work=$(mktemp -d "${TMPDIR:-/tmp}/sliding.XXXXXX")
trap 'rm -rf "$work"' EXIT
: > "$work/none.txt"
row() {   # row NAME REPORT EXIT
  python3 - "$@" << 'PY'
import json, sys
name, path, rc = sys.argv[1:]
r = json.load(open(path))
figure = lambda v, f: '' if v is None else f % v
print('| %s | %d | %d | %d | %s | %s | %.2f | %s |' % (name, r['elements'], r['inverted_before'], r['inverted_after'],
      figure(r.get('min_scaled_jacobian_after'), '%.3f'), figure(r['max_distance_to_target'], '%.1e'), r['seconds'], rc))
PY
}
header() { echo "| $1 | hexahedra | inverted before | after | min SJ after | farthest from target | s | exit |"
           echo "| :-- | --: | --: | --: | --: | --: | --: | --: |"; }
header mesh
for mesh in fandisk airplane1_octree kitty bird airplane1; do
  [ -f "$data/hex/$mesh-input.vtk" ] || { echo "| $mesh | missing | | | | | | |"; continue; }
  rc=0
  "$untangle" "$data/hex/$mesh-input.vtk" --slide-boundary --fixed "$work/none.txt" -o "$work/x.vtk" \
    --report "$work/r.json" --quiet --threads 1 --time-limit "$limit" || rc=$?
  row "$mesh" "$work/r.json" $rc
done
echo
header "block (fixed / sliding)"
for dir in "$data"/cuboidblocks/*/; do
  name=$(basename "$dir")
  "$make_block" "$dir" 8 "$work/b.vtk" > /dev/null
  for mode in fixed sliding; do
    rc=0
    if [ $mode = fixed ]; then options=(); else options=(--slide-boundary --fixed "$work/none.txt"); fi
    "$untangle" "$work/b.vtk" --rest "$work/b-rest.vtk" "${options[@]}" -o "$work/x.vtk" --report "$work/r.json" \
      --quiet --threads 1 --time-limit 60 || rc=$?
    row "$name $mode" "$work/r.json" $rc
  done
done
