// The REXS model (model.hpp): lookups, integrity checks and typed attribute reads.
#include "gearloss/rexs/model.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <map>
#include <set>

#include "gearloss/core/errors.hpp"

namespace gearloss::rexs {

const char* to_string(ValueKind k) {
    switch (k) {
        case ValueKind::unknown: return "text";
        case ValueKind::floating_point: return "floating_point";
        case ValueKind::integer: return "integer";
        case ValueKind::boolean: return "boolean";
        case ValueKind::string: return "string";
        case ValueKind::enum_value: return "enum";
        case ValueKind::reference_component: return "reference_component";
        case ValueKind::file_reference: return "file_reference";
        case ValueKind::floating_point_array: return "floating_point_array";
        case ValueKind::integer_array: return "integer_array";
        case ValueKind::boolean_array: return "boolean_array";
        case ValueKind::string_array: return "string_array";
        case ValueKind::enum_array: return "enum_array";
        case ValueKind::reference_component_array: return "reference_component_array";
        case ValueKind::floating_point_matrix: return "floating_point_matrix";
        case ValueKind::integer_matrix: return "integer_matrix";
        case ValueKind::array_of_integer_arrays: return "array_of_integer_arrays";
    }
    return "?";
}

bool Attribute::has_value() const {
    const bool scalar = kind == ValueKind::unknown || kind == ValueKind::enum_value;
    return !(scalar && text.empty() && numbers.empty() && texts.empty() && rows.empty());
}

const Attribute* Component::find(const std::string& attribute) const {
    for (const auto& a : attributes)
        if (a.id == attribute) return a.has_value() ? &a : nullptr;
    return nullptr;
}

std::string Component::label() const {
    return type + " " + std::to_string(id) + " '" + name + "'";
}

std::optional<std::int64_t> Relation::ref(const std::string& role) const {
    for (const auto& r : refs)
        if (r.role == role) return r.id;
    return std::nullopt;
}

const Component* LoadCase::find(std::int64_t cid) const {
    for (const auto& c : components)
        if (c.id == cid) return &c;
    return nullptr;
}

const Component* Model::find(std::int64_t id) const {
    const auto it = by_id_.find(id);
    return it == by_id_.end() ? nullptr : &components[it->second];
}

const Component& Model::at(std::int64_t id) const {
    const Component* c = find(id);
    if (!c) fail("no component with id " + std::to_string(id));
    return *c;
}

std::vector<const Component*> Model::of_type(const std::string& type) const {
    std::vector<const Component*> out;
    for (const auto& c : components)
        if (c.type == type) out.push_back(&c);
    return out;
}

std::vector<const Relation*> Model::relations_with(const std::string& type, const std::string& role,
                                                   std::int64_t id) const {
    std::vector<const Relation*> out;
    for (const auto& r : relations)
        if (r.type == type)
            for (const auto& x : r.refs)
                if (x.role == role && x.id == id) {
                    out.push_back(&r);
                    break;
                }
    return out;
}

void Model::index() {
    by_id_.clear();
    for (size_t i = 0; i < components.size(); ++i) {
        const auto& c = components[i];
        const auto [it, fresh] = by_id_.emplace(c.id, i);
        if (!fresh)
            fail(c, "duplicate component id " + std::to_string(c.id) + " (also " + components[it->second].label() +
                        (components[it->second].line ? ", line " + std::to_string(components[it->second].line) : "") + ")");
        std::set<std::string> seen;
        for (const auto& a : c.attributes)
            if (!seen.insert(a.id).second) fail(c, a, "attribute given twice");
    }
    std::set<std::int64_t> relation_ids;
    for (const auto& r : relations) {
        if (r.id != 0 && !relation_ids.insert(r.id).second) fail(r, "duplicate relation id");
        if (r.refs.empty()) fail(r, "a relation without refs");
        for (const auto& x : r.refs)
            if (!find(x.id))
                fail(r, "its ref (role '" + x.role + "'" + (x.hint.empty() ? "" : ", hint '" + x.hint + "'") +
                            ") names component " + std::to_string(x.id) + ", which the model does not have");
    }
    check_assembly_loops();
    for (const auto& lc : load_cases)
        for (const auto& c : lc.components)
            if (!find(c.id))
                fail(c, "load case " + std::to_string(lc.id) + " names component " + std::to_string(c.id) +
                            ", which the model does not have");
}

// A component that is, through assembly relations, a part of itself (a shaft in its own gear,
// a relation loop) describes no gearbox: an error at the relation that closes the loop.
void Model::check_assembly_loops() const {
    std::map<std::int64_t, std::vector<std::pair<std::int64_t, const Relation*>>> parts;  // assembly -> parts
    for (const auto& r : relations) {
        if (r.type != "assembly" && r.type != "ordered_assembly") continue;
        const auto a = r.ref("assembly");
        const auto p = r.ref("part");
        if (!a || !p) continue;
        if (*a == *p) fail(r, "component " + std::to_string(*a) + " is an assembly part of itself");
        parts[*a].emplace_back(*p, &r);
    }
    // Iterative depth-first search (no recursion on hostile depth): 1 = on the path, 2 = done.
    std::map<std::int64_t, int> state;
    for (const auto& [root, unused] : parts) {
        if (state[root]) continue;
        std::vector<std::pair<std::int64_t, size_t>> stack{{root, 0}};
        state[root] = 1;
        while (!stack.empty()) {
            auto& [id, next] = stack.back();
            const auto it = parts.find(id);
            if (it == parts.end() || next >= it->second.size()) {
                state[id] = 2;
                stack.pop_back();
                continue;
            }
            const auto [child, rel] = it->second[next++];
            if (state[child] == 1)
                fail(*rel, "assembly relations form a loop: component " + std::to_string(child) +
                               " is, through component " + std::to_string(id) + ", a part of itself");
            if (state[child] == 0) {
                state[child] = 1;
                stack.emplace_back(child, 0);
            }
        }
    }
}

void Model::fail(const Component& c, const std::string& message) const {
    throw InputError(file, c.line, 0, "component " + std::to_string(c.id) + " (" + c.type + " '" + c.name + "')", message);
}

void Model::fail(const Component& c, const Attribute& a, const std::string& message) const {
    throw InputError(file, a.line ? a.line : c.line, 0,
                     "component " + std::to_string(c.id) + " (" + c.type + " '" + c.name + "')." + a.id, message);
}

void Model::fail(const Relation& r, const std::string& message) const {
    throw InputError(file, r.line, 0, "relation " + std::to_string(r.id) + " (" + r.type + ")", message);
}

void Model::fail(const std::string& message) const { throw InputError(file, 0, 0, "", message); }

namespace {

std::optional<double> parse_double(const std::string& s) {
    double v = 0;
    const char* b = s.data();
    const char* e = s.data() + s.size();
    while (b < e && (*b == ' ' || *b == '\t' || *b == '\n' || *b == '\r')) ++b;
    while (e > b && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\n' || e[-1] == '\r')) --e;
    if (b < e && *b == '+') ++b;
    const auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e || !std::isfinite(v)) return std::nullopt;
    return v;
}

}  // namespace

std::optional<std::vector<double>> decode_coded_array(const std::string& code, const std::string& base64) {
    const size_t width = code == "int32" || code == "float32" ? 4 : code == "float64" ? 8 : 0;
    if (width == 0) return std::nullopt;
    std::vector<unsigned char> bytes;
    unsigned buffer = 0;
    int bits = 0, padding = 0;
    for (const char ch : base64) {
        int v;
        if (ch >= 'A' && ch <= 'Z') v = ch - 'A';
        else if (ch >= 'a' && ch <= 'z') v = ch - 'a' + 26;
        else if (ch >= '0' && ch <= '9') v = ch - '0' + 52;
        else if (ch == '+') v = 62;
        else if (ch == '/') v = 63;
        else if (ch == '=') {
            ++padding;
            continue;
        } else if (ch == ' ' || ch == '\n' || ch == '\r' || ch == '\t') continue;
        else return std::nullopt;
        if (padding) return std::nullopt;  // data after padding
        buffer = (buffer << 6) | static_cast<unsigned>(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            bytes.push_back(static_cast<unsigned char>((buffer >> bits) & 0xFF));
        }
    }
    if (bytes.size() % width != 0) return std::nullopt;
    std::vector<double> out;
    out.reserve(bytes.size() / width);
    for (size_t i = 0; i < bytes.size(); i += width) {
        std::uint64_t u = 0;
        for (size_t k = 0; k < width; ++k) u |= static_cast<std::uint64_t>(bytes[i + k]) << (8 * k);
        double v;
        if (code == "int32") v = static_cast<double>(static_cast<std::int32_t>(static_cast<std::uint32_t>(u)));
        else if (code == "float32") {
            float f;
            const auto u32 = static_cast<std::uint32_t>(u);
            std::memcpy(&f, &u32, 4);
            v = f;
        } else std::memcpy(&v, &u, 8);
        if (!std::isfinite(v)) return std::nullopt;
        out.push_back(v);
    }
    return out;
}

std::optional<double> number(const Model& m, const Component& c, const std::string& attribute) {
    const Attribute* a = c.find(attribute);
    if (!a) return std::nullopt;
    switch (a->kind) {
        case ValueKind::unknown:
        case ValueKind::floating_point:
        case ValueKind::integer: break;
        default: m.fail(c, *a, std::string("expected a number, found a value of kind ") + to_string(a->kind));
    }
    const auto v = parse_double(a->text);
    if (!v) m.fail(c, *a, "'" + a->text.substr(0, 40) + "' is not a finite number");
    return v;
}

std::optional<std::int64_t> integer(const Model& m, const Component& c, const std::string& attribute) {
    const Attribute* a = c.find(attribute);
    if (!a) return std::nullopt;
    const auto v = number(m, c, attribute);
    if (!(std::abs(*v) < 9e15) || *v != std::floor(*v)) m.fail(c, *a, "'" + a->text.substr(0, 40) + "' is not an integer");
    return static_cast<std::int64_t>(*v);
}

std::optional<bool> boolean(const Model& m, const Component& c, const std::string& attribute) {
    const Attribute* a = c.find(attribute);
    if (!a) return std::nullopt;
    if (a->kind != ValueKind::unknown && a->kind != ValueKind::boolean)
        m.fail(c, *a, std::string("expected a boolean, found a value of kind ") + to_string(a->kind));
    if (a->text == "true") return true;
    if (a->text == "false") return false;
    m.fail(c, *a, "'" + a->text.substr(0, 40) + "' is not a boolean (true or false)");
}

std::optional<std::string> text(const Model& m, const Component& c, const std::string& attribute) {
    const Attribute* a = c.find(attribute);
    if (!a) return std::nullopt;
    switch (a->kind) {
        case ValueKind::unknown:
        case ValueKind::string:
        case ValueKind::enum_value:
        case ValueKind::file_reference: return a->text;
        default: m.fail(c, *a, std::string("expected a string or enum, found a value of kind ") + to_string(a->kind));
    }
}

std::optional<std::vector<double>> numbers(const Model& m, const Component& c, const std::string& attribute) {
    const Attribute* a = c.find(attribute);
    if (!a) return std::nullopt;
    if (a->kind != ValueKind::floating_point_array && a->kind != ValueKind::integer_array)
        m.fail(c, *a, std::string("expected a numeric array, found a value of kind ") + to_string(a->kind));
    return a->numbers;
}

}  // namespace gearloss::rexs
