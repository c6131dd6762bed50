#!/usr/bin/env bash
# First run on a fresh Debian 12 machine: installs the dependencies (scripts/install-deps.sh,
# the project's only install script), builds the `ncc` command line and runs an example
# program end to end, printing its run summary.
#   scripts/demo.sh                 the example below
#   scripts/demo.sh path/to/part.nc any other program (options after it go to `ncc run`)
set -euo pipefail

EXAMPLE=examples/motion-basics.nc   # the example program run by default
BUILD_DIR=${BUILD_DIR:-build}       # build folder, relative to the repository

cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install-deps.sh
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DNCC_BUILD_TESTS=OFF -DNCC_BUILD_BENCH=OFF
cmake --build "$BUILD_DIR" --target ncc -j "${NCC_JOBS:-2}"

program=${1:-$EXAMPLE}
[ $# -gt 0 ] && shift
echo
echo "\$ $BUILD_DIR/tools/ncc/ncc run $program $*"
"$BUILD_DIR/tools/ncc/ncc" run "$program" "$@"
