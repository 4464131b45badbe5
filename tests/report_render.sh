#!/usr/bin/env bash
# Renders a `gearloss report` page in headless Chromium (Debian package `chromium`) and checks
# that it loads without errors: the page's own script records script and console errors and
# sets #gl-status to data-status="ok" data-errors="0" (lib/gearloss/report/html_report.hpp).
# Also: a copy of the page with a deliberate script error must be reported as broken (the
# check can fail), a screenshot is taken and must be a non-empty PNG, and `--pdf` prints the
# page with the same Chromium: a PDF of several pages whose first page carries the summary and
# whose text has the values printed in the map cells (pdftotext/pdfinfo of poppler-utils; the
# page count is read from the PDF itself when they are missing).
# Usage: report_render.sh GEARLOSS SOURCE_DIR [KEEP_DIR]  (KEEP_DIR: keep the page and the PNG)
# Chromium is installed on first use (scripts/install-deps.sh report); exit 77 (ctest
# SKIP_RETURN_CODE) only when it is missing and this user cannot run apt.
source "$(dirname "$0")/cli_common.sh" "$@"
keep=${3:-}
find_browser() {
    browser=${CHROMIUM:-}
    for c in chromium chromium-browser google-chrome; do
        [ -n "$browser" ] && break
        command -v "$c" > /dev/null && browser=$(command -v "$c")
    done
}
find_browser
# First use installs it (scripts/install-deps.sh report) where this user may run apt.
if [ -z "$browser" ] && { [ "$(id -u)" -eq 0 ] || sudo -n true 2> /dev/null; }; then
    "$src/scripts/install-deps.sh" report || echo "installing Chromium failed"
    find_browser
fi
if [ -z "$browser" ]; then
    echo "SKIPPED: no chromium installed and this user cannot install it (Debian package 'chromium': scripts/install-deps.sh report)"
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
    --oil "$src/configs/oils/75W140-A.yaml" --spread-axes mesh.friction --threads 2 -o "$tmp/report.html" \
    --pdf "$tmp/report.pdf" 2> "$tmp/gen.err"
check "report written" test -s "$tmp/report.html"
[ -s "$tmp/report.html" ] || cat "$tmp/gen.err"

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
# --pdf: Chromium's print of the page (its @media print style).
check "pdf written" test -s "$tmp/report.pdf"
check "pdf signature" bash -c "head -c 5 '$tmp/report.pdf' | grep -q '^%PDF-'"
if command -v pdfinfo > /dev/null; then
    pages=$(pdfinfo "$tmp/report.pdf" 2> /dev/null | sed -n 's/^Pages: *//p')
else  # page objects of the file (Chromium writes them uncompressed)
    pages=$(python3 -c "import re,sys; print(len(re.findall(rb'/Type\s*/Page(?![s\w])', open(sys.argv[1],'rb').read())))" "$tmp/report.pdf")
fi
check "pdf has several pages (got ${pages:-none})" test "${pages:-0}" -ge 3
if command -v pdftotext > /dev/null; then
    pdftotext -layout -f 1 -l 1 "$tmp/report.pdf" "$tmp/page1.txt"
    pdftotext "$tmp/report.pdf" "$tmp/all.txt"
    for text in "Summary" "Key points" "rated (highest input power)" "best efficiency" "thermal limit" \
        "permissible sump temperature" "windage: 0 W everywhere" "Oils ranked by mean total loss"; do
        check "pdf page 1 has '$text'" grep -qF "$text" "$tmp/page1.txt"
    done
    check "pdf page 1 has the ratio" grep -qE 'i = n ?in ?/n ?out ?= 2\.292' "$tmp/page1.txt"
    check "pdf page 1 counts both oils" grep -qE '2: 75W90-A' "$tmp/page1.txt"
    # The values printed in the efficiency map's cells are in the PDF's text.
    labels=$(python3 -c "
import re, sys
page = open(sys.argv[1], encoding='utf-8').read()
svg = re.search(r'<svg class=\"gl-map\" id=\"map-efficiency\".*?</svg>', page, re.S).group(0)
print(' '.join(re.findall(r'class=\"gl-cell\"[^>]*>([^<]+)</text>', svg)))" "$tmp/report.html")
    check "efficiency map has printed labels" test -n "$labels"
    missing=0
    for v in $labels; do grep -qF "$v" "$tmp/all.txt" || missing=$((missing + 1)); done
    check "every efficiency label is in the pdf text ($missing missing)" test "$missing" -eq 0
    check "the maps are in the pdf" grep -qF "Maps over the operating points" "$tmp/all.txt"
else
    echo "SKIPPED: the pdf's text (no pdftotext; Debian package 'poppler-utils')"
fi

if [ -n "$keep" ]; then
    mkdir -p "$keep"
    cp "$tmp/report.html" "$tmp/shot.png" "$tmp/report.pdf" "$keep/" 2> /dev/null
fi

echo "report_render: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
