// Dispatch by format, the version check and the .rexsz archive (reader.hpp).
#include "gearloss/rexs/reader.hpp"

#include <zip.h>

#include <memory>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_read.hpp"

namespace gearloss::rexs {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
    if (s.size() < tail.size()) return false;
    for (size_t i = 0; i < tail.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(s[s.size() - tail.size() + i])) != tail[i]) return false;
    return true;
}

enum class Format { xml, json, zip, unknown };

Format format_of_name(const std::string& name) {
    if (ends_with(name, ".rexs") || ends_with(name, ".xml")) return Format::xml;
    if (ends_with(name, ".rexsj") || ends_with(name, ".json")) return Format::json;
    if (ends_with(name, ".rexsz") || ends_with(name, ".zip")) return Format::zip;
    return Format::unknown;
}

Format format_of_bytes(std::string_view text) {
    size_t i = 0;
    if (text.substr(0, 3) == "\xEF\xBB\xBF") i = 3;  // UTF-8 byte-order mark
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n')) ++i;
    if (text.substr(0, 4) == std::string_view("PK\x03\x04", 4)) return Format::zip;
    if (i < text.size() && text[i] == '<') return Format::xml;
    if (i < text.size() && text[i] == '{') return Format::json;
    return Format::unknown;
}

Model parse_text(std::string_view text, Format f, const std::string& shown) {
    if (f == Format::unknown) f = format_of_bytes(text);
    switch (f) {
        case Format::xml: return parse_xml(text, shown);
        case Format::json: return parse_json(text, shown);
        default: throw InputError(shown, 0, 0, "", "not a REXS model: neither XML (.rexs) nor JSON (.rexsj)");
    }
}

struct ZipCloser {
    void operator()(zip_t* z) const { zip_discard(z); }
};
struct ZipFileCloser {
    void operator()(zip_file_t* f) const { zip_fclose(f); }
};

Model read_archive(const std::string& path, const std::string& shown) {
    int err = 0;
    std::unique_ptr<zip_t, ZipCloser> z(zip_open(path.c_str(), ZIP_RDONLY, &err));
    if (!z) {
        zip_error_t e;
        zip_error_init_with_code(&e, err);
        const std::string why = zip_error_strerror(&e);
        zip_error_fini(&e);
        throw InputError(shown, 0, 0, "", "not a readable zip archive (.rexsz): " + why);
    }
    const zip_int64_t n = zip_get_num_entries(z.get(), 0);
    if (n > kMaxRexsArchiveEntries)
        throw InputError(shown, 0, 0, "", "the archive has " + std::to_string(n) + " members; at most " +
                                              std::to_string(kMaxRexsArchiveEntries) + " are read");
    zip_int64_t chosen = -1;
    std::string member;
    for (zip_int64_t i = 0; i < n; ++i) {
        const char* name = zip_get_name(z.get(), static_cast<zip_uint64_t>(i), 0);
        if (!name) continue;
        const std::string s = name;
        if (s.empty() || s.back() == '/' || s.starts_with("__MACOSX/")) continue;
        const Format f = format_of_name(s);
        if (f != Format::xml && f != Format::json) continue;
        if (!(ends_with(s, ".rexs") || ends_with(s, ".rexsj"))) continue;
        if (chosen >= 0)
            throw InputError(shown, 0, 0, "", "the archive holds more than one REXS model ('" + io::excerpt(member) +
                                                  "' and '" + io::excerpt(s) + "'); a .rexsz holds exactly one");
        chosen = i;
        member = s;
    }
    if (chosen < 0) throw InputError(shown, 0, 0, "", "the archive holds no REXS model (.rexs or .rexsj member)");
    std::unique_ptr<zip_file_t, ZipFileCloser> f(zip_fopen_index(z.get(), static_cast<zip_uint64_t>(chosen), 0));
    if (!f) throw InputError(shown, 0, 0, "", "cannot read member '" + io::excerpt(member) + "': " + zip_strerror(z.get()));
    // Read at most one byte more than the limit: the size the archive states is not trusted.
    std::string text;
    char buf[65536];
    for (;;) {
        const zip_int64_t got = zip_fread(f.get(), buf, sizeof buf);
        if (got < 0)
            throw InputError(shown, 0, 0, "", "member '" + io::excerpt(member) + "' is damaged: " +
                                                  zip_file_strerror(f.get()));
        if (got == 0) break;
        text.append(buf, static_cast<size_t>(got));
        if (text.size() > kMaxRexsBytes)
            throw InputError(shown, 0, 0, "", "member '" + io::excerpt(member) + "' unpacks to more than " +
                                                  std::to_string(kMaxRexsBytes >> 20) + " MiB; refused");
    }
    return parse_text(text, format_of_name(member), shown + ":" + io::excerpt(member));
}

}  // namespace

void check_version(const std::string& version, const std::string& shown) {
    static const char* const known[] = {"1.0", "1.1", "1.2", "1.3", "1.4", "1.5", "1.6"};
    for (const char* k : known)
        if (version == k) return;
    throw InputError(shown, 0, 0, "model.version",
                     "REXS version '" + io::excerpt(version) + "' is not read; gearloss reads REXS 1.0 to 1.6");
}

Model read_model(const std::string& path, const std::string& shown_) {
    const std::string shown = shown_.empty() ? path : shown_;
    Format f = format_of_name(path);
    if (f == Format::zip) {
        (void)io::read_regular_file(path, kMaxRexsBytes);  // refuses FIFOs, devices and huge files by name
        return read_archive(path, shown);
    }
    const std::string text = io::read_regular_file(path, kMaxRexsBytes);
    if (f == Format::unknown) f = format_of_bytes(text);
    if (f == Format::zip) return read_archive(path, shown);
    return parse_text(text, f, shown);
}

}  // namespace gearloss::rexs
