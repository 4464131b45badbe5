#!/usr/bin/env bash
# Builds gearloss with its tests and runs them all through ctest; then builds
# again with AddressSanitizer + UndefinedBehaviorSanitizer (any report fails)
# and runs the suite once more, all but the envelope sweeps (label envelope: the same code
# paths over many more points, about 4 minutes under the sanitizers). `--quick` skips that pass.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
(cd "${BUILD_DIR:-build}" && ctest --output-on-failure -j "$(nproc)")
if [ "${1:-}" != "--quick" ]; then
    echo "== again with AddressSanitizer + UBSan"
    BUILD_DIR=build-asan BUILD_TYPE=RelWithDebInfo CMAKE_EXTRA="-DGEARLOSS_SANITIZE=ON" scripts/build.sh
    (cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
        ctest --output-on-failure -j "$(nproc)" --label-exclude envelope)
fi
