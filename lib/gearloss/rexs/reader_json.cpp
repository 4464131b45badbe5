// REXS JSON (.rexsj) into the model, with nlohmann-json (reader.hpp).
// {"model": {"version", "applicationId", "relations": [{"id", "type", "refs": [{"id", "role", "hint"}]}],
//  "components": [{"id", "type", "name", "attributes": [{"id", "unit", "<kind>": value}]}],
//  "load_spectrum": {"load_cases": [{"id", "components": [...]}]}}}
#include <nlohmann/json.hpp>

#include <cmath>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/rexs/reader.hpp"

namespace gearloss::rexs {
namespace {

using json = nlohmann::json;

class JsonReader {
public:
    explicit JsonReader(std::string shown) : shown_(std::move(shown)) {}

    Model read(std::string_view text) {
        json doc;
        try {
            // The callback sees every value as it is parsed: nesting is refused before it grows.
            doc = json::parse(text, [this](int depth, json::parse_event_t, json&) {
                if (depth > kMaxRexsDepth)
                    throw InputError(shown_, 0, 0, "", "values nested deeper than " + std::to_string(kMaxRexsDepth) +
                                                           " levels; refused");
                return true;
            });
        } catch (const json::parse_error& e) {
            throw InputError(shown_, 0, 0, "", std::string("not valid JSON: ") + e.what());
        } catch (const json::out_of_range& e) {  // a number beyond a double (1e400): not a value of any model
            throw InputError(shown_, 0, 0, "", std::string("not a valid REXS value: ") + e.what());
        }
        if (!doc.is_object() || !doc.contains("model") || !doc["model"].is_object())
            fail("", "not a REXS model: no \"model\" object at the top");
        const json& root = doc["model"];
        Model m;
        m.file = shown_;
        m.version = str(root, "version", "model");
        check_version(m.version, shown_);
        m.application_id = opt_str(root, "applicationId");
        m.application_version = opt_str(root, "applicationVersion");
        m.date = opt_str(root, "date");
        for (const auto& r : list(root, "relations", "model")) m.relations.push_back(relation(r));
        for (const auto& c : list(root, "components", "model")) m.components.push_back(component(c));
        if (root.contains("load_spectrum") && root["load_spectrum"].is_object()) {
            const json& ls = root["load_spectrum"];
            if (ls.contains("load_cases"))
                for (const auto& lc : list(ls, "load_cases", "load_spectrum")) {
                    LoadCase l;
                    l.id = id(lc, "load case");
                    for (const auto& c : list(lc, "components", "load case " + std::to_string(l.id)))
                        l.components.push_back(component(c));
                    m.load_cases.push_back(std::move(l));
                }
        }
        m.index();
        return m;
    }

private:
    [[noreturn]] void fail(const std::string& key, const std::string& msg) const { throw InputError(shown_, 0, 0, key, msg); }

    const json& list(const json& o, const char* key, const std::string& where) const {
        if (!o.contains(key)) {
            static const json empty = json::array();
            return empty;
        }
        const json& v = o[key];
        if (!v.is_array()) fail(where + "." + key, "expected a list");
        return v;
    }
    std::string str(const json& o, const char* key, const std::string& where) const {
        if (!o.is_object() || !o.contains(key) || !o[key].is_string()) fail(where + "." + key, "expected a string");
        return o[key].get<std::string>();
    }
    static std::string opt_str(const json& o, const char* key) {
        return o.contains(key) && o[key].is_string() ? o[key].get<std::string>() : "";
    }
    std::int64_t id(const json& o, const std::string& what) const {
        if (!o.is_object() || !o.contains("id") || !o["id"].is_number_integer()) fail(what, what + " without an integer id");
        return o["id"].get<std::int64_t>();
    }

    Relation relation(const json& o) const {
        Relation r;
        r.id = o.is_object() && o.contains("id") ? id(o, "relation") : 0;
        const std::string where = "relation " + std::to_string(r.id);
        r.type = str(o, "type", where);
        if (o.contains("order") && o["order"].is_number_integer()) r.order = o["order"].get<int>();
        for (const auto& x : list(o, "refs", where)) {
            Ref ref;
            ref.id = id(x, where + " ref");
            ref.role = str(x, "role", where);
            ref.hint = opt_str(x, "hint");
            r.refs.push_back(ref);
        }
        return r;
    }

    static std::string number_text(double v) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.17g", v);
        return buf;
    }

    void numeric_list(const json& v, std::vector<double>& out, const std::string& where) const {
        if (!v.is_array()) fail(where, "expected an array");
        for (const auto& x : v) {
            if (!x.is_number()) fail(where, "an array element is not a number");
            const double d = x.get<double>();
            if (!std::isfinite(d)) fail(where, "an array element is not finite");
            out.push_back(d);
        }
    }

    Attribute attribute(const json& o, const std::string& where) const {
        Attribute a;
        a.id = str(o, "id", where);
        const std::string key = where + "." + a.id;
        a.unit = opt_str(o, "unit");
        int kinds = 0;
        for (const auto& [k, v] : o.items()) {
            if (k == "id" || k == "unit") continue;
            ++kinds;
            if (v.is_null()) {
                // No value (REXS JSON writes `"enum": null` for an attribute left empty): absent.
                a.kind = ValueKind::unknown;
                continue;
            }
            if (k == "floating_point" || k == "integer" || k == "reference_component") {
                if (!v.is_number()) fail(key, k + " value is not a number");
                a.kind = k == "floating_point" ? ValueKind::floating_point
                         : k == "integer"      ? ValueKind::integer
                                               : ValueKind::reference_component;
                a.text = v.is_number_integer() ? std::to_string(v.get<std::int64_t>()) : number_text(v.get<double>());
            } else if (k == "boolean") {
                if (!v.is_boolean()) fail(key, "boolean value is not true or false");
                a.kind = ValueKind::boolean;
                a.text = v.get<bool>() ? "true" : "false";
            } else if (k == "string" || k == "enum" || k == "file_reference") {
                if (!v.is_string()) fail(key, k + " value is not a string");
                a.kind = k == "string" ? ValueKind::string : k == "enum" ? ValueKind::enum_value : ValueKind::file_reference;
                a.text = v.get<std::string>();
            } else if (k == "floating_point_array" || k == "integer_array" || k == "reference_component_array") {
                a.kind = k == "floating_point_array" ? ValueKind::floating_point_array
                         : k == "integer_array"      ? ValueKind::integer_array
                                                     : ValueKind::reference_component_array;
                numeric_list(v, a.numbers, key);
            } else if (k == "string_array" || k == "enum_array" || k == "boolean_array") {
                if (!v.is_array()) fail(key, "expected an array");
                a.kind = k == "string_array" ? ValueKind::string_array
                         : k == "enum_array" ? ValueKind::enum_array
                                             : ValueKind::boolean_array;
                for (const auto& x : v) {
                    if (x.is_string()) a.texts.push_back(x.get<std::string>());
                    else if (x.is_boolean()) a.texts.push_back(x.get<bool>() ? "true" : "false");
                    else fail(key, "an array element is not a string or boolean");
                }
            } else if (k == "floating_point_matrix" || k == "integer_matrix" || k == "array_of_integer_arrays") {
                if (!v.is_array()) fail(key, "expected an array of rows");
                a.kind = k == "floating_point_matrix" ? ValueKind::floating_point_matrix
                         : k == "integer_matrix"      ? ValueKind::integer_matrix
                                                      : ValueKind::array_of_integer_arrays;
                for (const auto& r : v) {
                    std::vector<double> row;
                    numeric_list(r, row, key);
                    a.rows.push_back(std::move(row));
                }
            } else if (k == "floating_point_array_coded" || k == "integer_array_coded" ||
                       k == "floating_point_matrix_coded" || k == "integer_matrix_coded") {
                if (!v.is_object() || !v.contains("code") || !v["code"].is_string() || !v.contains("value") ||
                    !v["value"].is_string())
                    fail(key, k + " is an object with a \"code\" and a base64 \"value\"");
                const auto values = decode_coded_array(v["code"].get<std::string>(), v["value"].get<std::string>());
                if (!values) fail(key, "coded values are not int32, float32 or float64 base64 of whole values");
                if (k.find("matrix") == std::string::npos) {
                    a.kind = k[0] == 'f' ? ValueKind::floating_point_array : ValueKind::integer_array;
                    a.numbers = *values;
                } else {
                    a.kind = k[0] == 'f' ? ValueKind::floating_point_matrix : ValueKind::integer_matrix;
                    const std::int64_t rows = v.value("rows", std::int64_t{-1}), cols = v.value("columns", std::int64_t{-1});
                    if (rows < 0 || cols < 0 || static_cast<size_t>(rows * cols) != values->size())
                        fail(key, "a coded matrix holds rows x columns values");
                    for (std::int64_t r = 0; r < rows; ++r)
                        a.rows.emplace_back(values->begin() + r * cols, values->begin() + (r + 1) * cols);
                }
            } else {
                fail(key, "value kind '" + io::excerpt(k) + "' is not read");
            }
        }
        if (kinds != 1) fail(key, "an attribute holds exactly one value (found " + std::to_string(kinds) + ")");
        return a;
    }

    Component component(const json& o) const {
        Component c;
        c.id = id(o, "component");
        const std::string where = "component " + std::to_string(c.id);
        c.type = opt_str(o, "type");
        c.name = opt_str(o, "name");
        for (const auto& a : list(o, "attributes", where)) c.attributes.push_back(attribute(a, where));
        return c;
    }

    std::string shown_;
};

}  // namespace

Model parse_json(std::string_view text, const std::string& shown) {
    if (text.size() > kMaxRexsBytes)
        throw InputError(shown, 0, 0, "", "more than " + std::to_string(kMaxRexsBytes >> 20) + " MiB; refused");
    return JsonReader(shown).read(text);
}

}  // namespace gearloss::rexs
