#!/usr/bin/env bash
# Redraws the figures of the manual (doc/Mesh_untangling/fig/*.svg) from real
# runs of the command-line tool untangle_mesh; figure_tool
# (doc/Mesh_untangling/figures/) writes the inputs and draws the cuts of 3D
# maps.  Needs a configured build (scripts/setup.sh); builds the two programs.
# Deterministic: a second run gives the same files.  Fails, replacing
# nothing, when a run fails or a figure exceeds 100 KB.
#
# usage: scripts/make_figures.sh         Environment: BUILD_DIR (default build/), JOBS
set -euo pipefail
trap 'echo "make_figures.sh: FAILED (line $LINENO: $BASH_COMMAND)" >&2' ERR

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${BUILD_DIR:-$ROOT/build}
FIG=$ROOT/doc/Mesh_untangling/fig
cmake --build "$BUILD" -j "${JOBS:-2}" --target untangle_mesh_cli figure_tool make_tangled_mesh > /dev/null
UNTANGLE=$BUILD/bin/untangle_mesh
TOOL=$BUILD/bin/figure_tool
MAKE=$BUILD/bin/make_tangled_mesh
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"

# untangle EXPECTED_STATUS ARGS...: untangle_mesh, whose exit status must be
# EXPECTED_STATUS (1: the published scheme is meant to fail here).
untangle() {
  local expected=$1 rc=0
  shift
  "$UNTANGLE" --quiet "$@" || rc=$?
  if [ "$rc" != "$expected" ]; then
    echo "make_figures.sh: untangle_mesh $* exited with $rc, not $expected" >&2
    exit 1
  fi
}

# 1. A 2D map with a free boundary, nothing fixed: a ruffled disk (centre of
#    valence 72, two rings) seen through a projection tilted by 70 degrees,
#    from the free-boundary stress families.  The published scheme ends in a
#    k-covering, the default does not.
"$TOOL" instance ruffled-disk ruffled-disk-v72-r2-k6-a0.37-tilt70-s4 disk.input
untangle 1 disk.input -o disk-published.input --no-phantoms --continuation never \
  --svg-input free_boundary_input.svg --svg free_boundary_published.svg
untangle 0 disk.input -o disk-default.input --svg free_boundary_default.svg

# 2. A flattening: the surface of examples/Mesh_untangling/flatten_surface.cpp
#    (on a 14 x 14 grid instead of 24 x 24, for small pictures), projected on
#    its best-fit plane (folded), then untangled, all vertices free.
"$TOOL" rolled-surface 14 strip.off
untangle 0 strip.off --init project -o strip-flat.off --svg-input flattening_input.svg --svg flattening_result.svg

# 3. The rotated cavities (untangle_cavities.cpp at mesh size 0.7): a horizontal
#    cut just above the cavities' mid-plane of the input, the published
#    scheme's result and the default's.
"$TOOL" cavities 0.7 cavities.input
untangle 1 cavities.input -o cavities-published.input --no-phantoms --continuation never
untangle 0 cavities.input -o cavities-default.input
for run in input published default; do
  mesh=cavities-$run.input
  [ "$run" = input ] && mesh=cavities.input
  "$TOOL" cut "$mesh" 1.03 "rotated cavities, cut z = 1.03, $run" "cavities_$run.svg" > /dev/null
done

# 4. A seamless parameterization: a cube with one chart per face (8 cones of
#    3 pi / 2), the uv of half of the vertices off the seams moved by up to
#    1.5 cells, untangled with its seams kept.
"$MAKE" seamcube 6 1.5 3 seamcube.obj > /dev/null
untangle 0 seamcube.obj -o seamcube-untangled.obj --svg-input seams_cube_input.svg --svg seams_cube_result.svg
for svg in *.svg; do
  size=$(stat -c %s "$svg")
  if [ "$size" -ge 102400 ]; then
    echo "make_figures.sh: $svg has $size bytes (at most 100 KB)" >&2
    exit 1
  fi
done
mkdir -p "$FIG"
cp ./*.svg "$FIG/"
ls -l "$FIG"
