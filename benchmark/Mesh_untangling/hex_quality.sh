#!/usr/bin/env bash
# The quality rung on real hexahedral meshes (manual, "Quality After
# Untangling"): each tangled mesh of ../shared/data/hex with its boundary
# vertices moved to the published optimizer's output and fixed, untangled
# with and without --optimize-quality; the smallest scaled Jacobian of the
# optimizer's output, of each result, and the library's seconds.
# usage: hex_quality.sh [UNTANGLE_MESH [DATA_DIR [THREADS]]]
set -eu
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
untangle=${1:-$here/../../build/bin/untangle_mesh}
data=${2:-$here/../../../shared/data}/hex
threads=${3:-1}
work=$(mktemp -d "${TMPDIR:-/tmp}/hex_quality.XXXXXX")
trap 'rm -rf "$work"' EXIT
field() { python3 -c "import json,sys; print('%.3f' % json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }
echo "| mesh | hexahedra | optimizer's min SJ | untangled min SJ | s | --optimize-quality min SJ | s | locally invertible |"
echo "| :-- | --: | --: | --: | --: | --: | --: | :-- |"
for mesh in fandisk airplane1_octree kitty bird airplane1; do
  [ -f "$data/$mesh-input.vtk" ] || { echo "| $mesh | missing | | | | | | |"; continue; }
  python3 "$here/fix_boundary_to.py" "$data/$mesh-input.vtk" "$data/$mesh-result.vtk" "$work/fixed.vtk" > /dev/null
  "$untangle" "$data/$mesh-result.vtk" --fix-boundary --max-iterations 1 -o "$work/x.vtk" --report "$work/optimizer.json" \
    --quiet --threads "$threads" || true
  "$untangle" "$work/fixed.vtk" --fix-boundary -o "$work/u.vtk" --report "$work/u.json" --quiet --threads "$threads" || true
  "$untangle" "$work/fixed.vtk" --fix-boundary -o "$work/q.vtk" --report "$work/q.json" --quiet --threads "$threads" \
    --optimize-quality || true
  echo "| $mesh | $(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['elements'])" "$work/u.json") |" \
       "$(field "$work/optimizer.json" min_scaled_jacobian_before) | $(field "$work/u.json" min_scaled_jacobian_after) |" \
       "$(field "$work/u.json" seconds) | $(field "$work/q.json" min_scaled_jacobian_after) | $(field "$work/q.json" seconds) |" \
       "$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['locally_invertible'])" "$work/q.json") |"
done
