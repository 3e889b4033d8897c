#!/usr/bin/env bash
# Set-up (scripts/setup.sh --sample: the packages, then only the tool and
# the sample maker are built), then the main job on generated samples: a
# tangled 2D square (40 x 40 grid, 3,200 triangles) and a tangled cube
# (8 x 8 x 8 grid, 3,072 tetrahedra), both with a fixed boundary, untangled
# by build/bin/untangle_mesh.  Results and JSON reports go to build/sample/.
# Exit status: 0 if both results are locally invertible, else non-zero.
#
# usage: scripts/run_sample.sh [--python]
#   --python  also build the Python module and untangle the same samples
#             from Python (examples/Mesh_untangling/python/untangle_file.py):
#             the results must be the command-line tool's, bit for bit
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
python=0
for arg in "$@"; do
  case $arg in
    --python) python=1 ;;
    *) echo "run_sample.sh: unknown argument '$arg' (usage: scripts/run_sample.sh [--python])" >&2; exit 2 ;;
  esac
done
if [ "$python" = 1 ]; then "$ROOT/scripts/setup.sh" --sample --python; else "$ROOT/scripts/setup.sh" --sample; fi

BIN=$ROOT/build/bin
SAMPLE=$ROOT/build/sample
mkdir -p "$SAMPLE"
"$BIN/make_tangled_mesh" square 40 2 1 "$SAMPLE/square.input"
"$BIN/make_tangled_mesh" cube 8 1.0 1 "$SAMPLE/cube.input"

# figure REPORT KEY: one value of a JSON report written by untangle_mesh.
figure() {
  sed -nE "s/^  \"$2\": (.*)\$/\1/p" "$1" | sed -E 's/,$//; s/^"(.*)"$/\1/'
}

status=0
summary=()
for name in square cube; do
  echo
  echo "== untangle_mesh $SAMPLE/$name.input"
  rc=0
  "$BIN/untangle_mesh" "$SAMPLE/$name.input" -o "$SAMPLE/$name-untangled.input" \
    --report "$SAMPLE/$name.json" || rc=$?
  if [ "$rc" != 0 ]; then
    echo "run_sample.sh: untangle_mesh failed on $name (exit code $rc)" >&2
    status=1
  fi
  if [ -f "$SAMPLE/$name.json" ]; then
    r=$SAMPLE/$name.json
    summary+=("$(printf '%-7s %8s %9s %7s %9s %8s %10s %12s %6s %8s' "$name" \
      "$(figure "$r" vertices)" "$(figure "$r" elements)" "$(figure "$r" fixed_vertices)" \
      "$(figure "$r" inverted_before)" "$(figure "$r" inverted_after)" "$(figure "$r" locally_invertible)" \
      "$(figure "$r" min_scaled_det_after | cut -c1-10)" "$(figure "$r" outer_iterations)" \
      "$(figure "$r" seconds | cut -c1-6)")")
  fi
done

echo
printf '%-7s %8s %9s %7s %9s %8s %10s %12s %6s %8s\n' sample vertices elements fixed "inverted" "inverted" "locally" "min scaled" "eps" seconds
printf '%-7s %8s %9s %7s %9s %8s %10s %12s %6s %8s\n' "" "" "" "" before after invertible "det J after" steps ""
for line in "${summary[@]}"; do echo "$line"; done
echo
echo "results and reports: $SAMPLE/{square,cube}-untangled.input, $SAMPLE/{square,cube}.json"

if [ "$python" = 1 ]; then
  for name in square cube; do
    echo
    echo "== python3 untangle_file.py $SAMPLE/$name.input (PYTHONPATH=$ROOT/build/python)"
    PYTHONPATH=$ROOT/build/python /usr/bin/python3 "$ROOT/examples/Mesh_untangling/python/untangle_file.py" \
      "$SAMPLE/$name.input" "$SAMPLE/$name-python.input" || status=1
    if cmp -s "$SAMPLE/$name-python.input" "$SAMPLE/$name-untangled.input"; then
      echo "$name: the Python result is the command-line tool's, bit for bit"
    else
      echo "run_sample.sh: $name: the Python result differs from the command-line tool's" >&2
      status=1
    fi
  done
fi
exit $status
