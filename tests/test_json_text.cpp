// The JSON text of the summaries (io::json_line over nlohmann-json): what JSON cannot hold.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "gearloss/io/json_text.hpp"

using namespace gearloss;

TEST_CASE("json_line: NaN and infinities are null, members in the order written", "[json]") {
    nlohmann::ordered_json j;
    j["z"] = std::numeric_limits<double>::quiet_NaN();
    j["a"] = std::numeric_limits<double>::infinity();
    j["m"] = -std::numeric_limits<double>::infinity();
    j["x"] = 0.1;
    // JSON has no NaN or infinity (RFC 8259, section 6); 0.1 is the shortest text that reads back as 0.1.
    CHECK(io::json_line(j) == "{\"z\":null,\"a\":null,\"m\":null,\"x\":0.1}\n");
    const auto back = nlohmann::json::parse(io::json_line(j));
    CHECK(back["z"].is_null());
    CHECK(back["x"].get<double>() == 0.1);
}

TEST_CASE("json_line: every double reads back exactly", "[json]") {
    for (double v : {1.0 / 3.0, 6.02214076e23, -2.5e-300, 1e300, 293.15 - 273.15}) {
        nlohmann::ordered_json j = {{"v", v}};
        CHECK(nlohmann::json::parse(io::json_line(j))["v"].get<double>() == v);
    }
}

TEST_CASE("json_line: bytes that are not UTF-8 become U+FFFD, never an exception", "[json]") {
    nlohmann::ordered_json j = {{"name", std::string("Rad_\xfc")}};  // Latin-1 u-umlaut
    std::string text;
    REQUIRE_NOTHROW(text = io::json_line(j));
    CHECK(text == "{\"name\":\"Rad_\xef\xbf\xbd\"}\n");
    CHECK(io::json_line(nlohmann::ordered_json{{"q", "a\"b\\c\n"}}) == "{\"q\":\"a\\\"b\\\\c\\n\"}\n");
}
