#pragma once
// Minimal JSON writer for machine-readable summaries (no parsing needed).
#include <cmath>
#include <string>
#include <vector>

namespace gearloss::io {

class Json {
public:
    Json& begin_object() { sep(); out_ += '{'; first_.push_back(true); return *this; }
    Json& end_object() { out_ += '}'; first_.pop_back(); return *this; }
    Json& begin_array() { sep(); out_ += '['; first_.push_back(true); return *this; }
    Json& end_array() { out_ += ']'; first_.pop_back(); return *this; }
    Json& key(const std::string& k) { sep(); str(k); out_ += ':'; pending_value_ = true; return *this; }
    Json& value(double v) {
        sep();
        if (std::isfinite(v)) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.10g", v);
            out_ += buf;
        } else {
            out_ += "null";  // JSON has no NaN/inf
        }
        return *this;
    }
    Json& value(int v) { sep(); out_ += std::to_string(v); return *this; }
    Json& value(size_t v) { sep(); out_ += std::to_string(v); return *this; }
    Json& value(bool v) { sep(); out_ += v ? "true" : "false"; return *this; }
    Json& value(const std::string& s) { sep(); str(s); return *this; }
    Json& value(const char* s) { return value(std::string(s)); }
    Json& null() { sep(); out_ += "null"; return *this; }
    const std::string& str() const { return out_; }

private:
    std::string out_;
    std::vector<bool> first_;
    bool pending_value_ = false;
    void sep() {
        if (pending_value_) { pending_value_ = false; return; }
        if (!first_.empty()) {
            if (!first_.back()) out_ += ',';
            first_.back() = false;
        }
    }
    void str(const std::string& s) {
        out_ += '"';
        for (char c : s) {
            switch (c) {
                case '"': out_ += "\\\""; break;
                case '\\': out_ += "\\\\"; break;
                case '\n': out_ += "\\n"; break;
                case '\t': out_ += "\\t"; break;
                default:
                    if (static_cast<unsigned char>(c) < 0x20) {
                        char b[8];
                        std::snprintf(b, sizeof b, "\\u%04x", c);
                        out_ += b;
                    } else out_ += c;
            }
        }
        out_ += '"';
    }
};

}  // namespace gearloss::io
