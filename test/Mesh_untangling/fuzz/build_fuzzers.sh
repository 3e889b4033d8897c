#!/usr/bin/env bash
# Configures and builds the libFuzzer targets of this folder with clang into
# FUZZ_BUILD_DIR (ctest's fixture test fuzz_build runs it; the main build may
# use g++).  Prints SKIPPED and exits 77 when clang++ or its libFuzzer
# runtime is missing (scripts/setup.sh installs both).
#
# usage: build_fuzzers.sh FUZZ_BUILD_DIR
# Environment: FUZZ_CXX (default clang++), JOBS (default 2),
#              CMAKE_CXX_COMPILER_LAUNCHER (ccache, as for the main build).
set -euo pipefail
if [ $# -ne 1 ]; then
  sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=$1
cxx=${FUZZ_CXX:-clang++}
if ! command -v "$cxx" > /dev/null 2>&1; then
  echo "SKIPPED: $cxx not found (Debian: clang)"
  exit 77
fi
mkdir -p "$build"
probe=$build/libfuzzer_probe
if ! echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' \
     | "$cxx" -x c++ -fsanitize=fuzzer - -o "$probe" > "$build/libfuzzer_probe.log" 2>&1; then
  echo "SKIPPED: $cxx cannot link libFuzzer (Debian: libclang-rt-dev); see $build/libfuzzer_probe.log"
  exit 77
fi
log=$build/build.log
if ! cmake -S "$here" -B "$build" -DCMAKE_CXX_COMPILER="$cxx" > "$log" 2>&1 \
   || ! cmake --build "$build" -j "${JOBS:-2}" >> "$log" 2>&1; then
  cat "$log"
  echo "build_fuzzers.sh: FAILED (log: $log)" >&2
  exit 1
fi
echo "fuzz targets built in $build:" $(cd "$build" && ls fuzz_* 2> /dev/null)
