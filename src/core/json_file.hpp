// Reading JSON that t2imu or a user wrote (synth.json, job markers, model.json, HAR results) so that any fault
// is one Error naming the file and the key: "out/jobs/j00003.json: json: expected a JSON document (got parse
// error at line 1, column 17: syntax error ...)", "...: recordings.2.n_samples: expected a whole number from 0
// (got "x")". Never the parser's raw "[json.exception.parse_error.101]".
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace t2imu {

// The document in `path`; Error(path, "json", ...) when it does not parse (invalid UTF-8 included).
nlohmann::json read_json_file(const std::string& path);
// The same for text already read from `path` (or from a named source).
nlohmann::json parse_json_text(const std::string& text, const std::string& path);

// The value at `key` of the object `doc` (read from `path`), converted; `where` prefixes the key in messages
// ("recordings.2"). Error(path, where.key, ...) when `doc` is not an object, the key is missing, or the
// value has another type.
std::string json_string(const nlohmann::json& doc, const std::string& key, const std::string& path,
                        const std::string& where = "");
double json_number(const nlohmann::json& doc, const std::string& key, const std::string& path,
                   const std::string& where = "");
int64_t json_integer(const nlohmann::json& doc, const std::string& key, const std::string& path,
                     const std::string& where = "");
uint64_t json_count(const nlohmann::json& doc, const std::string& key, const std::string& path,
                    const std::string& where = "");  // >= 0
bool json_bool(const nlohmann::json& doc, const std::string& key, const std::string& path,
               const std::string& where = "");
const nlohmann::json& json_array(const nlohmann::json& doc, const std::string& key, const std::string& path,
                                 const std::string& where = "");
const nlohmann::json& json_object(const nlohmann::json& doc, const std::string& key, const std::string& path,
                                  const std::string& where = "");

}  // namespace t2imu
