// REXS XML (.rexs) into the model, with pugixml (reader.hpp).
// <model version=.. applicationId=..><relations><relation id type [order]><ref id role [hint]/>...
// <components><component id name type><attribute id unit>value | <array><c>..</c></array> |
// <matrix><r><c>..</c></r></matrix> | <array_of_arrays><array>..</array></array_of_arrays>
// <load_spectrum id><load_case id><component id><attribute ../>...
#include <pugixml.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/rexs/reader.hpp"

namespace gearloss::rexs {
namespace {

class XmlReader {
public:
    XmlReader(std::string_view text, std::string shown) : text_(text), shown_(std::move(shown)) {
        line_starts_.push_back(0);
        for (size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n') line_starts_.push_back(i + 1);
    }

    Model read() {
        // No DOCTYPE is kept and no entity is expanded beyond the five of XML (pugixml knows no DTDs).
        const unsigned options = pugi::parse_default & ~pugi::parse_doctype;
        const pugi::xml_parse_result r = doc_.load_buffer(text_.data(), text_.size(), options, pugi::encoding_utf8);
        if (!r) throw InputError(shown_, line_of(r.offset), 0, "", std::string("not well-formed XML: ") + r.description());
        check_depth();
        const pugi::xml_node root = doc_.child("model");
        if (!root) throw InputError(shown_, 0, 0, "", "not a REXS model: the root element is not <model>");
        Model m;
        m.file = shown_;
        m.version = root.attribute("version").as_string();
        check_version(m.version, shown_);
        m.application_id = root.attribute("applicationId").as_string();
        m.application_version = root.attribute("applicationVersion").as_string();
        m.date = root.attribute("date").as_string();
        for (const auto& rel : root.child("relations").children("relation")) m.relations.push_back(relation(rel));
        for (const auto& c : root.child("components").children("component")) m.components.push_back(component(c));
        for (const auto& lc : root.child("load_spectrum").children("load_case")) {
            LoadCase l;
            l.id = id_of(lc, "load case");
            for (const auto& c : lc.children("component")) l.components.push_back(component(c));
            m.load_cases.push_back(std::move(l));
        }
        m.index();
        return m;
    }

private:
    int line_of(std::ptrdiff_t offset) const {
        if (offset < 0) return 0;
        const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), static_cast<size_t>(offset));
        return static_cast<int>(it - line_starts_.begin());
    }
    int line_of(const pugi::xml_node& n) const { return line_of(n.offset_debug()); }

    // The nesting, walked without recursion: a hostile file cannot overflow the stack here.
    void check_depth() const {
        pugi::xml_node n = doc_.first_child();
        int depth = 1;
        while (n) {
            if (depth > kMaxRexsDepth)
                throw InputError(shown_, line_of(n), 0, "", "elements nested deeper than " + std::to_string(kMaxRexsDepth) +
                                                                " levels; refused");
            if (n.first_child()) {
                n = n.first_child();
                ++depth;
                continue;
            }
            while (n && !n.next_sibling()) {
                n = n.parent();
                --depth;
            }
            if (n) n = n.next_sibling();
        }
    }

    [[noreturn]] void fail(const pugi::xml_node& n, const std::string& key, const std::string& msg) const {
        throw InputError(shown_, line_of(n), 0, key, msg);
    }

    std::int64_t id_of(const pugi::xml_node& n, const std::string& what) const {
        const pugi::xml_attribute a = n.attribute("id");
        if (!a) fail(n, "", what + " without an id");
        const std::string s = a.as_string();
        std::int64_t v = 0;
        const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
        if (r.ec != std::errc() || r.ptr != s.data() + s.size())
            fail(n, "", what + " id '" + io::excerpt(s) + "' is not an integer");
        return v;
    }

    Relation relation(const pugi::xml_node& n) const {
        Relation r;
        r.line = line_of(n);
        r.id = n.attribute("id") ? id_of(n, "relation") : 0;
        r.type = n.attribute("type").as_string();
        if (r.type.empty()) fail(n, "relation " + std::to_string(r.id), "relation without a type");
        if (n.attribute("order")) r.order = n.attribute("order").as_int();
        for (const auto& x : n.children("ref")) {
            Ref ref;
            ref.id = id_of(x, "ref of relation " + std::to_string(r.id));
            ref.role = x.attribute("role").as_string();
            ref.hint = x.attribute("hint").as_string();
            if (ref.role.empty()) fail(x, "relation " + std::to_string(r.id), "ref without a role");
            r.refs.push_back(ref);
        }
        return r;
    }

    static bool to_number(const std::string& s, double& v) {
        const char* b = s.data();
        const char* e = s.data() + s.size();
        if (b < e && *b == '+') ++b;
        const auto r = std::from_chars(b, e, v);
        return r.ec == std::errc() && r.ptr == e && std::isfinite(v);
    }

    // The texts of the <c> children of an <array> or <r>.
    void cells(const pugi::xml_node& n, Attribute& a, std::vector<double>& values, bool& numeric) const {
        if (n.attribute("code")) {
            const std::string code = n.attribute("code").as_string();
            const auto v = decode_coded_array(code, n.text().as_string());
            if (!v)
                fail(n, a.id, "coded values (code=\"" + io::excerpt(code) +
                                  "\") are not int32, float32 or float64 base64 of whole values");
            values.insert(values.end(), v->begin(), v->end());
            return;
        }
        for (const auto& c : n.children("c")) {
            std::string s = c.text().as_string();
            double v = 0;
            if (to_number(s, v)) values.push_back(v);
            else numeric = false;
            a.texts.push_back(std::move(s));
        }
    }

    Attribute attribute(const pugi::xml_node& n, const std::string& where) const {
        Attribute a;
        a.line = line_of(n);
        a.id = n.attribute("id").as_string();
        if (a.id.empty()) fail(n, where, "attribute without an id");
        a.unit = n.attribute("unit").as_string();
        bool numeric = true;
        if (const auto arr = n.child("array")) {
            cells(arr, a, a.numbers, numeric);
            a.kind = numeric ? ValueKind::floating_point_array : ValueKind::string_array;
            if (!numeric) a.numbers.clear();
        } else if (const auto mat = n.child("matrix"); mat && mat.attribute("code")) {
            // A coded matrix: rows x columns values, row by row.
            std::vector<double> all;
            cells(mat, a, all, numeric);
            const long rows = mat.attribute("rows").as_llong(-1), cols = mat.attribute("columns").as_llong(-1);
            if (rows < 0 || cols < 0 || static_cast<size_t>(rows) * static_cast<size_t>(cols) != all.size())
                fail(n, where + "." + a.id, "a coded matrix holds rows x columns values");
            for (long r = 0; r < rows; ++r)
                a.rows.emplace_back(all.begin() + r * cols, all.begin() + (r + 1) * cols);
            a.kind = ValueKind::floating_point_matrix;
        } else if (mat) {
            for (const auto& r : mat.children("r")) {
                std::vector<double> row;
                cells(r, a, row, numeric);
                a.rows.push_back(std::move(row));
            }
            if (!numeric) fail(n, where + "." + a.id, "a matrix cell is not a number");
            a.kind = ValueKind::floating_point_matrix;
        } else if (const auto aoa = n.child("array_of_arrays")) {
            for (const auto& r : aoa.children("array")) {
                std::vector<double> row;
                cells(r, a, row, numeric);
                a.rows.push_back(std::move(row));
            }
            if (!numeric) fail(n, where + "." + a.id, "an array_of_arrays cell is not a number");
            a.kind = ValueKind::array_of_integer_arrays;
        } else {
            a.text = n.text().as_string();
            // Surrounding blanks are layout, not value.
            const auto b = a.text.find_first_not_of(" \t\r\n");
            const auto e = a.text.find_last_not_of(" \t\r\n");
            a.text = b == std::string::npos ? "" : a.text.substr(b, e - b + 1);
            a.kind = ValueKind::unknown;
        }
        return a;
    }

    Component component(const pugi::xml_node& n) const {
        Component c;
        c.line = line_of(n);
        c.id = id_of(n, "component");
        c.type = n.attribute("type").as_string();
        c.name = n.attribute("name").as_string();
        const std::string where = "component " + std::to_string(c.id);
        for (const auto& a : n.children("attribute")) c.attributes.push_back(attribute(a, where));
        return c;
    }

    std::string_view text_;
    std::string shown_;
    std::vector<size_t> line_starts_;
    pugi::xml_document doc_;
};

}  // namespace

Model parse_xml(std::string_view text, const std::string& shown) {
    if (text.size() > kMaxRexsBytes)
        throw InputError(shown, 0, 0, "", "more than " + std::to_string(kMaxRexsBytes >> 20) + " MiB; refused");
    return XmlReader(text, shown).read();
}

}  // namespace gearloss::rexs
