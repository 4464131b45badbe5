#!/usr/bin/env bash
# Configures and builds gearloss (Release) into build/ (or $BUILD_DIR).
# Uses ccache when it is installed, so that the sanitizer build, the mutation
# check and extra build directories recompile only what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# Tests and the Python module on (a build folder configured by scripts/run-example.sh has them off).
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} -DBUILD_TESTING=ON -DGEARLOSS_PYTHON=ON "${launcher[@]}" ${CMAKE_EXTRA:-} > /dev/null
cmake --build "$build" -j "$(nproc)"
