#!/usr/bin/env bash
# Fuzzes the YAML case loader, the recordings reader and the solver on
# arbitrary-but-valid cases with libFuzzer (clang), ASan and UBSan, then the whole
# command line (every subcommand, hostile case/oil files and output paths) with the
# crash, hang, NaN, damage and message oracles of scripts/fuzz-cli.py, on the same
# sanitized build.
# Usage: scripts/fuzz.sh SECONDS   (a quarter to each libFuzzer target, a quarter to the CLI)
# New corpus entries go to build-fuzz/corpus/; crash inputs to
# build-fuzz/artifacts/ (copy them to tests/fuzz/regressions/<target>/ once fixed).
set -euo pipefail
cd "$(dirname "$0")/.."
total=${1:-300}
per=$((total / 4))
scripts/install-deps.sh
pkgs=(clang libclang-rt-14-dev libomp-14-dev)
missing=()
for p in "${pkgs[@]}"; do dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p"); done
if [ ${#missing[@]} -gt 0 ]; then
    sudo_cmd=""
    [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
    $sudo_cmd apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq "${missing[@]}" > /dev/null
fi
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DGEARLOSS_FUZZ=ON -DBUILD_TESTING=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
cmake --build build-fuzz -j "$(nproc)" --target fuzz_config fuzz_recordings fuzz_map gearloss > /dev/null
mkdir -p build-fuzz/artifacts
status=0
execs=0
for t in config recordings map; do
    mkdir -p "build-fuzz/corpus/$t"
    log="build-fuzz/fuzz-$t.log"
    set +e
    build-fuzz/tests/fuzz/fuzz_$t -max_total_time="$per" -timeout=20 -rss_limit_mb=4096 -print_final_stats=1 \
        -artifact_prefix="build-fuzz/artifacts/$t-" "build-fuzz/corpus/$t" "tests/fuzz/corpus/$t" > "$log" 2>&1
    rc=$?
    set -e
    n=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
    execs=$((execs + n))
    if [ $rc -ne 0 ]; then
        status=1
        echo "fuzz_$t: FINDING (exit $rc), see $log and build-fuzz/artifacts/"
        grep -m5 -E "ERROR|FUZZ FINDING|runtime error|deadly signal|timeout" "$log" || true
    else
        echo "fuzz_$t: $n executions in ${per} s, no crash, no sanitizer report, no hang"
    fi
done
echo "total libFuzzer executions: $execs"
# A sanitizer report ends the program with a code of its own (86/87), which the CLI
# fuzzer's crash oracle counts as undocumented.
set +e
ASAN_OPTIONS=exitcode=86:detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:exitcode=87:print_stacktrace=1 \
    python3 scripts/fuzz-cli.py --binary build-fuzz/app/gearloss --seconds "$per" --jobs "$(nproc)" \
    --timeout 120 --out build-fuzz/cli --report build-fuzz/fuzz-cli.json | tail -n 20
rc=${PIPESTATUS[0]}
set -e
if [ "$rc" -ne 0 ]; then
    status=1
    echo "fuzz-cli: FINDINGS, see build-fuzz/fuzz-cli.json and build-fuzz/cli/"
fi
exit $status
