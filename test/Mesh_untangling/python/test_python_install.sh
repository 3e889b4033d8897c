#!/usr/bin/env bash
# `cmake --install` puts the Python package where the interpreter finds it:
# installed into a temporary prefix, it is imported from there (and not from
# the build tree) and untangles a tangled square.
# usage: test_python_install.sh BUILD_DIR PYTHON WORK_DIR
set -u
build=$1 python=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
cmake --install "$build" --prefix "$work/prefix" --component Mesh_untangling_Python > "$work/install.log" 2>&1 || {
  cat "$work/install.log"; echo "FAIL: cmake --install --component Mesh_untangling_Python"; exit 1; }
init=$(find "$work/prefix" -path '*/mesh_untangling/__init__.py')
[ -n "$init" ] || { echo "FAIL: no mesh_untangling/__init__.py under $work/prefix"; exit 1; }
for f in __init__.pyi py.typed; do
  [ -f "$(dirname "$init")/$f" ] || { echo "FAIL: $f not installed beside $init"; exit 1; }
done
site=$(dirname "$(dirname "$init")")
cd "$work" && PYTHONPATH=$site "$python" - "$work/prefix" << 'PYTHON'
import sys
import numpy as np
import mesh_untangling as mu
assert mu.__file__.startswith(sys.argv[1]), "imported from " + mu.__file__ + ", not from the prefix"
vertices = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [1.5, 1.2]], float)
triangles = [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]
untangled, result = mu.untangle(vertices, triangles, fixed=[0, 1, 2, 3])
assert result.inverted_before > 0 and result.status == mu.Status.SUCCESS, result
print("installed module", mu.__version__, "at", mu.__file__, ":", result)
PYTHON
