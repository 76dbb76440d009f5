// core/json_file.hpp: every fault of a JSON file is one Error naming the file and the key, never the parser's
// own "[json.exception...]" text.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.hpp"
#include "core/json_file.hpp"
#include "test_util.hpp"

using namespace t2imu;

TEST(JsonFile, ASyntaxErrorNamesTheFileAndWhereItBroke) {
    const std::string path = test::scratch_dir("json_file") + "/cut.json";
    std::ofstream(path) << "{\"job\": \"j1\", \"kept";
    const std::string m = test::error_message([&] { read_json_file(path); });
    EXPECT_EQ(m.rfind(path + ": json: expected a JSON document (got parse error at line 1", 0), 0u) << m;
    EXPECT_EQ(m.find("json.exception"), std::string::npos) << m;
    EXPECT_NE(test::error_message([&] {
                  parse_json_text("{\"a\": \"\xff\"}", "x.json");
              }).find("x.json: json: expected a JSON document"),
              std::string::npos);
    EXPECT_NE(test::error_message([&] { read_json_file(path + ".missing"); }).find(path + ".missing"),
              std::string::npos);
    // A number beyond double's range (found by fuzz_job_marker: the parser throws out_of_range, not parse_error).
    EXPECT_NE(test::error_message([&] {
                  parse_json_text("{\"seed\": 0.1e1111111}", "big.json");
              }).find("big.json: json: expected a JSON document (got number overflow"),
              std::string::npos);
}

TEST(JsonFile, FieldsAreReadByTypeAndFaultsNameTheDottedKey) {
    const nlohmann::json doc = nlohmann::json::parse(R"({"name": "walk", "n": 12, "x": 0.5, "neg": -3, "ok": true,
        "list": [{"n_samples": "x"}], "sub": {"k": 1}})");
    EXPECT_EQ(json_string(doc, "name", "f.json"), "walk");
    EXPECT_EQ(json_count(doc, "n", "f.json"), 12u);
    EXPECT_EQ(json_integer(doc, "neg", "f.json"), -3);
    EXPECT_DOUBLE_EQ(json_number(doc, "x", "f.json"), 0.5);
    EXPECT_TRUE(json_bool(doc, "ok", "f.json"));
    EXPECT_EQ(json_object(doc, "sub", "f.json").size(), 1u);
    EXPECT_EQ(test::error_message([&] { json_string(doc, "n", "f.json"); }), "f.json: n: expected a string (got 12)");
    EXPECT_EQ(test::error_message([&] { json_count(doc, "neg", "f.json"); }),
              "f.json: neg: expected a whole number from 0 (got -3)");
    EXPECT_EQ(test::error_message([&] { json_integer(doc, "x", "f.json"); }),
              "f.json: x: expected a whole number (got 0.5)");
    EXPECT_EQ(test::error_message([&] { json_bool(doc, "missing", "f.json"); }),
              "f.json: missing: expected true or false (missing)");
    EXPECT_EQ(
        test::error_message([&] { json_count(json_array(doc, "list", "f.json")[0], "n_samples", "f.json", "list.0"); }),
        "f.json: list.0.n_samples: expected a whole number from 0 (got \"x\")");
    EXPECT_EQ(test::error_message([&] { json_string(nlohmann::json::array(), "k", "f.json"); }),
              "f.json: json: expected an object (got array)");
}
