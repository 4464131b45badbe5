#pragma once
// Text into HTML: escaping of every user-supplied string (case names, file names, YAML values,
// messages) and JSON embedded in a page so that no value can close the element it sits in.
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace gearloss::report {

// & < > " ' as character references: safe in element content and in quoted attribute values.
std::string escape_html(std::string_view text);

// `j` as JSON text for a <script type="application/json"> element: '<', '>' and '&' are
// written as \u003c, \u003e, \u0026 (they only occur inside JSON strings), so no value can
// end the element ("</script>") or open a comment; non-finite numbers are null (nlohmann).
std::string json_for_script(const nlohmann::ordered_json& j);

// A number for display with `digits` significant digits ("1.234e+05" only outside 1e-3..1e6);
// "–" for a value that is not a finite number.
std::string display_number(double v, int digits = 4);

}  // namespace gearloss::report
