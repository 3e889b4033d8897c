#!/usr/bin/env bash
# The distributed untangling against the serial tool on generated tangled
# cubes (make_tangled_mesh cube N 0.6 1: 6 N^3 tetrahedra, the boundary
# fixed, the rest given): untangle_mesh (default, and --solver lbfgs: the
# published scheme with LBFGSpp) and untangle_mesh_mpi on each process
# count, one thread per process, the whole mesh read by process 0 and, with
# mesh_parts, split into part files that each process reads (--parts).
# Prints one row per run: seconds (and the
# eps loop's alone), eps steps, energy
# evaluations, the verdict, the peak memory of process 0 and of the
# largest other process, and bytes per tetrahedron per process.
# usage: benchmark/Mesh_untangling/mpi_scaling.sh BUILD_DIR "N..." "PROCESSES..."
#   e.g. mpi_scaling.sh build "30 55" "1 2"
set -euo pipefail
BUILD=$(cd "${1:?usage: mpi_scaling.sh BUILD_DIR \"N...\" \"PROCESSES...\"}" && pwd)
SIZES=${2:-55}
PROCESSES=${3:-"1 2"}
BIN=$BUILD/bin
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
T=$(mktemp -d "${TMPDIR:-/tmp}/mpi_scaling.XXXXXX")
trap 'rm -rf "$T"' EXIT
cd "$T"
row() {   # row N WHO JSON [PEAK0 PEAK_OTHER]
  python3 - "$@" << 'PY'
import json, sys
n, who, path = int(sys.argv[1]), sys.argv[2], sys.argv[3]
j = json.load(open(path))
tets = j['elements']
peaks = j.get('peak_memory_bytes_per_process') or [float(sys.argv[4]) * 1024]
first, other = peaks[0], max(peaks[1:], default=0)
steps = j.get('eps_steps', j.get('outer_iterations'))
loop = f"{j['eps_loop_seconds']:.2f}" if 'eps_loop_seconds' in j else ''
print(f"| {n} | {tets:,} | {who} | {j['seconds']:.2f} | {loop} | {steps} | {j['energy_evaluations']} | "
      f"{j['inverted_before']} -> {j['inverted_after']} | {first / 2**20:.0f} | "
      f"{other / 2**20:.0f} | {first / tets:.0f} | {other / tets:.0f} |")
PY
}
echo "| N | tetrahedra | run | seconds | eps loop s | eps steps | evaluations | inverted | process 0 MiB | largest other MiB | process 0 B/tet | other B/tet |"
echo "|--:|--:|:--|--:|--:|--:|--:|:--|--:|--:|--:|--:|"
for n in $SIZES; do
  "$BIN/make_tangled_mesh" cube "$n" 0.6 1 "cube$n.vtk" > /dev/null
  for solver in auto lbfgs; do
    /usr/bin/time -f %M -o serial.kb "$BIN/untangle_mesh" "cube$n.vtk" --rest "cube$n-rest.vtk" -o serial.vtk \
      --report serial.json --solver "$solver" --threads 1 -q > /dev/null 2>&1 || true
    row "$n" "untangle_mesh --solver $solver" serial.json "$(cat serial.kb)"
  done
  for p in $PROCESSES; do
    mpiexec --oversubscribe -n "$p" "$BIN/untangle_mesh_mpi" "cube$n.vtk" --rest "cube$n-rest.vtk" -o "mpi$p.vtk" \
      --report "mpi$p.json" -q > /dev/null 2>&1 || true
    row "$n" "untangle_mesh_mpi, $p processes" "mpi$p.json"
    if [ -x "$BIN/mesh_parts" ]; then   # (the mesh given in parts: no process reads it whole)
      "$BIN/mesh_parts" split "cube$n.vtk" "$p" "part$p.%.vtu" --rest "cube$n-rest.vtk" --rest-output "rest$p.%.vtu" \
        > /dev/null 2>&1
      mpiexec --oversubscribe -n "$p" "$BIN/untangle_mesh_mpi" --parts "part$p.%.vtu" --rest "rest$p.%.vtu" \
        -o "out$p.%.vtu" --report "parts$p.json" -q > /dev/null 2>&1 || true
      row "$n" "untangle_mesh_mpi --parts, $p processes" "parts$p.json"
      rm -f part$p.*.vtu rest$p.*.vtu out$p.*.vtu
    fi
  done
done
