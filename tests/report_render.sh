#!/usr/bin/env bash
# Renders a `gearloss report` page in headless Chromium (Debian package `chromium`) and checks
# that it loads without errors: the page's own script records script and console errors and
# sets #gl-status to data-status="ok" data-errors="0" (lib/gearloss/report/html_report.hpp).
# Also: a copy of the page with a deliberate script error must be reported as broken (the
# check can fail), and a screenshot is taken and must be a non-empty PNG.
# Usage: report_render.sh GEARLOSS SOURCE_DIR [KEEP_DIR]  (KEEP_DIR: keep the page and the PNG)
# Exit 77 (ctest SKIP_RETURN_CODE) only when no chromium is installed.
source "$(dirname "$0")/cli_common.sh" "$@"
keep=${3:-}
browser=${CHROMIUM:-}
for c in chromium chromium-browser google-chrome; do
    [ -n "$browser" ] && break
    command -v "$c" > /dev/null && browser=$(command -v "$c")
done
if [ -z "$browser" ]; then
    echo "SKIPPED: no chromium installed (Debian package 'chromium'; scripts/install-deps.sh installs it)"
    exit 77
fi

# chromium --headless: one run, a private profile, no network, a deadline.
render() {  # render OUT_STDOUT OUT_STDERR ARGS...
    local out=$1 err=$2
    shift 2
    timeout 90 "$browser" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --no-first-run \
        --user-data-dir="$tmp/profile" --disable-extensions --virtual-time-budget=5000 "$@" > "$out" 2> "$err"
}

# A shipped case on a modest grid, with the spread and an oil comparison: every section drawn.
"$bin" report "$src/configs/transfer-box.yaml" --speed 500,1000,2000,3000,4000rpm --torque 0,50,100,200,400Nm \
    --oil "$src/configs/oils/75W140-A.yaml" --spread-axes mesh.friction --threads 2 -o "$tmp/report.html" 2> "$tmp/gen.err"
check "report written" test -s "$tmp/report.html"

render "$tmp/dom.html" "$tmp/dom.err" --dump-dom "file://$tmp/report.html"
check "chromium dumped the page" test -s "$tmp/dom.html"
check "page status ok" grep -q 'id="gl-status" data-status="ok" data-errors="0"' "$tmp/dom.html"
check "no uncaught error in the browser log" bash -c "! grep -Eq 'Uncaught|CONSOLE.*[Ee]rror' '$tmp/dom.err'"
if ! grep -q 'data-status="ok"' "$tmp/dom.html"; then
    grep -o '<p id="gl-status"[^<]*' "$tmp/dom.html" | head -3
    tail -20 "$tmp/dom.err"
fi

# The same check on a page with a deliberate error must fail (the recorder works).
sed 's|</header>|</header><script>no_such_function();</script>|' "$tmp/report.html" > "$tmp/broken.html"
render "$tmp/broken.dom" "$tmp/broken.err" --dump-dom "file://$tmp/broken.html"
check "a broken page is reported" grep -q 'data-status="error"' "$tmp/broken.dom"

# A screenshot: a PNG (signature) of some size.
render "$tmp/shot.out" "$tmp/shot.err" --hide-scrollbars --window-size=1280,2400 --screenshot="$tmp/shot.png" \
    "file://$tmp/report.html"
check "screenshot written" test -s "$tmp/shot.png"
check "screenshot is a PNG" bash -c "head -c 8 '$tmp/shot.png' | od -An -tx1 | tr -d ' \n' | grep -q '^89504e470d0a1a0a'"
check "screenshot is not trivially small" test "$(stat -c %s "$tmp/shot.png" 2> /dev/null || echo 0)" -gt 20000
if [ -n "$keep" ]; then
    mkdir -p "$keep"
    cp "$tmp/report.html" "$tmp/shot.png" "$keep/" 2> /dev/null
fi

echo "report_render: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
