#include "gearloss/report/html.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gearloss::report {

std::string escape_html(std::string_view text) {
    std::string out;
    out.reserve(text.size() + text.size() / 8);
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string json_for_script(const nlohmann::ordered_json& j) {
    // Invalid UTF-8 in a user's string is replaced rather than thrown on.
    const std::string text = j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '<': out += "\\u003c"; break;
            case '>': out += "\\u003e"; break;
            case '&': out += "\\u0026"; break;
            default: out += c;
        }
    }
    return out;
}

std::string display_number(double v, int digits) {
    if (!std::isfinite(v)) return "\u2013";
    const double a = std::fabs(v);
    if (a != 0 && (a < 1e-3 || a >= 1e6)) return fmt::format("{:.{}e}", v, digits - 1);
    // Significant digits in fixed notation: the decimals follow the magnitude.
    const int magnitude = a == 0 ? 0 : static_cast<int>(std::floor(std::log10(a)));
    const int decimals = std::max(0, digits - 1 - magnitude);
    std::string s = fmt::format("{:.{}f}", v, decimals);
    if (s == "-0" || s.find_first_not_of("-0.") == std::string::npos) s = fmt::format("{:.{}f}", 0.0, decimals);
    return s;
}

}  // namespace gearloss::report
