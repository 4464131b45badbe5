#pragma once
// The in-memory model of a REXS file (Reusable Engineering EXchange Standard, FVA; versions 1.0
// to 1.6): components with typed attributes, relations between them and the load cases of its
// load spectrum. Physics-neutral: nothing here knows gearloss's case; the mapper
// (gearloss/rexs/case_mapper.hpp) reads this model. The readers (gearloss/rexs/reader.hpp) fill it
// from .rexs (XML), .rexsj (JSON) and .rexsz (a zip holding one of them).
//
// XML does not say which kind a value is (the data model of the version does); JSON does. An
// attribute keeps its text or numbers and the accessors below accept both spellings, so a model
// read from .rexs and from .rexsj of the same gearbox gives the same values.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gearloss::rexs {

enum class ValueKind {
    unknown,        // XML: a scalar text whose kind the data model knows (number, boolean, enum, string)
    floating_point,
    integer,
    boolean,
    string,
    enum_value,
    reference_component,
    file_reference,
    floating_point_array,
    integer_array,
    boolean_array,
    string_array,
    enum_array,
    reference_component_array,
    floating_point_matrix,
    integer_matrix,
    array_of_integer_arrays,
};
const char* to_string(ValueKind k);

struct Attribute {
    std::string id;
    std::string unit;                       // as written ("mm", "kg / dm^3", "" or "none" for none)
    ValueKind kind = ValueKind::unknown;
    std::string text;                       // scalar value as text ("117", "true", "radial_grooved_ball_bearing")
    std::vector<double> numbers;            // arrays (and a numeric scalar from JSON, also in text)
    std::vector<std::string> texts;         // string, boolean or enum arrays
    std::vector<std::vector<double>> rows;  // matrices and arrays of arrays
    int line = 0;                           // 1-based line in an XML file (0 when not known)
    // No value written: an XML attribute element with no text (`<attribute id="x" unit="mm"/>`),
    // a JSON value `null`, an empty enum. Exporters (FVA-Workbench) write every attribute of a
    // component's type this way when it has no value; it reads as absent.
    bool has_value() const;
};

struct Component {
    std::int64_t id = 0;
    std::string type, name;
    std::vector<Attribute> attributes;
    int line = 0;
    const Attribute* find(const std::string& attribute) const;  // nullptr when absent or without a value
    // "cylindrical_gear 15 'Cylindrical gear [27]'": how messages and comments name it.
    std::string label() const;
};

struct Ref {
    std::int64_t id = 0;
    std::string role, hint;
};

struct Relation {
    std::int64_t id = 0;  // 0 when the file gives none (allowed up to REXS 1.3)
    std::string type;
    std::optional<int> order;
    std::vector<Ref> refs;
    int line = 0;
    // The referenced component id of `role`, nullopt when the relation has no such role.
    std::optional<std::int64_t> ref(const std::string& role) const;
};

// One load case of the load spectrum: per component, the attributes it sets for that case.
struct LoadCase {
    std::int64_t id = 0;
    std::vector<Component> components;
    const Component* find(std::int64_t id) const;
};

struct Model {
    std::string file;  // as shown in messages (the path given, or "archive.rexsz:member.rexs")
    std::string version, application_id, application_version, date;
    std::vector<Component> components;
    std::vector<Relation> relations;
    std::vector<LoadCase> load_cases;

    const Component* find(std::int64_t id) const;
    const Component& at(std::int64_t id) const;  // InputError when missing
    std::vector<const Component*> of_type(const std::string& type) const;
    // Relations of `type` in which component `id` takes `role`.
    std::vector<const Relation*> relations_with(const std::string& type, const std::string& role, std::int64_t id) const;

    // Builds the id index; InputError for duplicate component ids, a relation to a missing
    // component and a load case naming a component the model does not have.
    void index();
    void check_assembly_loops() const;  // index(): no component is a part of itself

    // The errors of a model name the file, the line when known and the component.
    [[noreturn]] void fail(const Component& c, const std::string& message) const;
    [[noreturn]] void fail(const Component& c, const Attribute& a, const std::string& message) const;
    [[noreturn]] void fail(const Relation& r, const std::string& message) const;
    [[noreturn]] void fail(const std::string& message) const;

private:
    std::map<std::int64_t, size_t> by_id_;
};

// Typed reads of one attribute of a component; they throw InputError naming the file,
// component and attribute when the attribute is missing (required_*) or has the wrong kind.
// Quantities are converted from the attribute's REXS unit to SI (gearloss/rexs/units.hpp).
std::optional<double> number(const Model& m, const Component& c, const std::string& attribute);
std::optional<std::int64_t> integer(const Model& m, const Component& c, const std::string& attribute);
std::optional<bool> boolean(const Model& m, const Component& c, const std::string& attribute);
std::optional<std::string> text(const Model& m, const Component& c, const std::string& attribute);
std::optional<std::vector<double>> numbers(const Model& m, const Component& c, const std::string& attribute);

// The values of a coded array (REXS "code" int32, float32 or float64: base64 of the values in
// little-endian byte order); nullopt when the code is unknown, the text is not base64, its length
// is not a whole number of values or a value is not finite.
std::optional<std::vector<double>> decode_coded_array(const std::string& code, const std::string& base64);

}  // namespace gearloss::rexs
