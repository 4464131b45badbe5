#pragma once
// `gearloss report --pdf FILE`: the page printed to PDF by headless Chromium
// (`chromium --headless --print-to-pdf`), which lays the page out with its print style
// (@media print in html_report.cpp). gearloss does not link a browser: it runs the one
// installed, in a private temporary profile, without network, with a deadline.
#include <string>

namespace gearloss::report {

// The browser to print with: $CHROMIUM when set (a path or a name on PATH), else the first of
// chromium, chromium-browser, google-chrome, google-chrome-stable on PATH; empty when none.
std::string find_chromium();

// The PDF (its bytes) of the page `html`. `option` names the command-line option in errors.
// Throws InputError naming `option` when no Chromium is found, IoError when Chromium fails,
// times out (`timeout_s`) or writes no PDF (the message ends with the last lines it printed).
std::string print_pdf(const std::string& html, const std::string& option, double timeout_s = 180);

}  // namespace gearloss::report
