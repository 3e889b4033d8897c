#!/usr/bin/env bash
# Installs the Debian packages that are missing, then configures and builds
# the project in build/ (Release).  Idempotent: quiet about packages unless
# one is missing; a second run only rebuilds what changed.
#
# usage: scripts/setup.sh [--sanitize] [--doc] [--sample] [--python] [--mpi]
#   --sanitize  build in build-asan/ instead: Debug, AddressSanitizer and
#               UndefinedBehaviorSanitizer (-DMESH_UNTANGLING_SANITIZE=ON)
#   --doc       also install doxygen, bibtex and MathJax, and build the
#               manual (HTML in BUILD/doc/Mesh_untangling/html)
#   --sample    build only the command-line tool and the sample maker
#               (scripts/run_sample.sh: about 3 minutes on 2 cores, where
#               the tests, fuzzers and benchmarks take about 30)
#   --python    with --sample: also build the Python module mesh_untangling
#               (BUILD/python; the full build always builds it)
#   --mpi       also install PETSc and Open MPI and build the distributed
#               untangling (untangle_mesh_mpi, ctest test_cli_mpi); a build
#               finds them by itself once they are installed
# Environment: JOBS (parallel build jobs, default 2).
set -euo pipefail
trap 'echo "setup.sh: FAILED (line $LINENO: $BASH_COMMAND)" >&2' ERR

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD_DIR=$ROOT/build
CMAKE_ARGS=(-DCMAKE_BUILD_TYPE=Release)
WITH_DOC=0
SAMPLE=0
WITH_PYTHON=0
WITH_MPI=0
for arg in "$@"; do
  case $arg in
    --sanitize)
      BUILD_DIR=$ROOT/build-asan
      CMAKE_ARGS=(-DCMAKE_BUILD_TYPE=Debug -DMESH_UNTANGLING_SANITIZE=ON) ;;
    --doc)
      WITH_DOC=1 ;;
    --sample)
      SAMPLE=1 ;;
    --python)
      WITH_PYTHON=1 ;;
    --mpi)
      WITH_MPI=1 ;;
    -h|--help)
      sed -n '2,19p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
      exit 0 ;;
    *)
      echo "setup.sh: unknown argument '$arg' (usage: scripts/setup.sh [--sanitize] [--doc] [--sample] [--python] [--mpi])" >&2
      exit 2 ;;
  esac
done
TARGETS=()
if [ "$SAMPLE" = 1 ]; then
  TARGETS=(--target untangle_mesh_cli make_tangled_mesh)
  [ "$WITH_PYTHON" = 1 ] && TARGETS+=(mesh_untangling_python)
else
  WITH_PYTHON=1
fi

# 1. Packages (Debian).
# libopenblas0-serial: CHOLMOD's supernodal factorization calls BLAS, and
# Debian's default is the reference BLAS (with OpenBLAS armadillo-598 is
# 1.25x faster, 100 x 100 and 150 x 150 grids by Newton 1.2-1.6x); the
# serial build, so that results stay the same bits with any number of threads
# (the pthread build with 2 threads gave armadillo-598 other bits than with 1).
# The serial build has no locking: two threads in it at once share buffers,
# so the Newton solver runs its BLAS calls (supernodal factorizations and
# solves) one at a time in the process (blas_mutex in Newton_solver.h).  The
# pthread build limited to 1 thread is safe too, but only if every
# application sets OPENBLAS_NUM_THREADS=1; the reference BLAS (libblas3) is
# safe but 8x slower (Newton on a 20^3 cube, AMD ordering: 67 s against 8.4 s).
# clang, libclang-rt-dev: the libFuzzer targets (test/Mesh_untangling/fuzz,
# ctest fuzz_*); libclang-rt-dev holds libclang_rt.fuzzer for Debian's clang.
# zlib1g-dev: the .vtu reader uncompresses vtkZLibDataCompressor data (what
# ParaView writes by default) with zlib (IO/VTU.h).
PACKAGES=(build-essential cmake clang libclang-rt-dev libcgal-dev libeigen3-dev libboost-dev libtbb-dev libtet1.5-dev
          libsuitesparse-dev libopenblas0-serial liblbfgspp-dev libcli11-dev nlohmann-json3-dev libgmp-dev
          libmpfr-dev zlib1g-dev)
# The Python module (front_ends/python/, built for /usr/bin/python3): pybind11 and
# numpy; meshio for the example that reads and writes other formats.
if [ "$WITH_PYTHON" = 1 ]; then
  PACKAGES+=(python3-dev python3-numpy pybind11-dev python3-meshio)
fi
# The manual (--doc only): doxygen; texlive-binaries for bibtex, which
# formats the references (doc/Mesh_untangling/references.bib); libjs-mathjax
# so that the formulas display without network access.
# The distributed untangling (--mpi only): PETSc (PT-Scotch partitions, star
# forests for the ghosts; Debian's petsc-dev, 3.18, pulls Open MPI in) and
# the mpiexec that runs it (openmpi-bin).
if [ "$WITH_MPI" = 1 ]; then
  PACKAGES+=(petsc-dev libopenmpi-dev openmpi-bin)
  CMAKE_ARGS+=(-DMESH_UNTANGLING_WITH_MPI=ON)
fi
if [ "$WITH_DOC" = 1 ]; then
  PACKAGES+=(doxygen texlive-binaries libjs-mathjax)
fi
installed() { [[ "$(dpkg -s "$1" 2> /dev/null)" == *"Status: install ok installed"* ]]; }
if ! command -v dpkg > /dev/null 2>&1; then
  echo "setup.sh: dpkg not found: this script installs Debian packages; install these by hand:" >&2
  echo "  ${PACKAGES[*]}" >&2
  exit 1
fi
missing=()
for package in "${PACKAGES[@]}"; do
  installed "$package" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup.sh: installing missing packages: ${missing[*]}"
  SUDO=()
  if [ "$(id -u)" != 0 ]; then
    if ! command -v sudo > /dev/null 2>&1; then
      echo "setup.sh: not root and no sudo: install these packages as root: ${missing[*]}" >&2
      exit 1
    fi
    SUDO=(sudo)
    [ -t 0 ] || SUDO=(sudo -n)   # no terminal (CI): never wait for a password
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${SUDO[@]}" apt-get update -qq
  "${SUDO[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
  for package in "${missing[@]}"; do
    if ! installed "$package"; then
      echo "setup.sh: package $package is still not installed" >&2
      exit 1
    fi
  done
fi

# 2. Configure (output kept in a log, shown on failure) and build.
mkdir -p "$BUILD_DIR"
if ! cmake -S "$ROOT" -B "$BUILD_DIR" "${CMAKE_ARGS[@]}" > "$BUILD_DIR/configure.log" 2>&1; then
  cat "$BUILD_DIR/configure.log" >&2
  echo "setup.sh: FAILED: cmake configuration (log: $BUILD_DIR/configure.log)" >&2
  exit 1
fi
cmake --build "$BUILD_DIR" -j "${JOBS:-2}" "${TARGETS[@]}"
if [ "$WITH_DOC" = 1 ]; then
  cmake --build "$BUILD_DIR" --target doc
  echo "setup.sh: manual in $BUILD_DIR/doc/Mesh_untangling/html/index.html"
fi
echo "setup.sh: built in $BUILD_DIR"
