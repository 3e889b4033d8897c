#!/usr/bin/env bash
# Set-up (scripts/setup.sh), then the whole test suite with ctest in build/.
# Extra arguments go to ctest (e.g. -R test_cli, -V).
#
# usage: scripts/run_tests.sh [--sanitize] [--mpi] [CTEST ARGUMENTS...]
#   --sanitize  build and test in build-asan/ instead (Debug, AddressSanitizer
#               and UndefinedBehaviorSanitizer); slower.
#   --mpi       also install and test the distributed untangling
#               (scripts/setup.sh --mpi: PETSc, Open MPI; ctest test_cli_mpi).
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
sanitize=0
setup_args=()
ctest_args=()
for arg in "$@"; do
  case $arg in
    --sanitize) sanitize=1 ;;
    --mpi) setup_args+=(--mpi) ;;
    *) ctest_args+=("$arg") ;;
  esac
done

if [ "$sanitize" = 1 ]; then
  "$ROOT/scripts/setup.sh" --sanitize ${setup_args[@]+"${setup_args[@]}"}
  BUILD_DIR=$ROOT/build-asan
  export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:strict_string_checks=1}
  export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
else
  "$ROOT/scripts/setup.sh" ${setup_args[@]+"${setup_args[@]}"}
  BUILD_DIR=$ROOT/build
fi

cd "$BUILD_DIR"
exec ctest --output-on-failure -j "${JOBS:-2}" ${ctest_args[@]+"${ctest_args[@]}"}
