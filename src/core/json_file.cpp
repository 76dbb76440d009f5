#include "core/json_file.hpp"

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace t2imu {

namespace {

std::string dotted(const std::string& where, const std::string& key) { return where.empty() ? key : where + "." + key; }

// The member, or Error naming it when `doc` is no object or lacks it.
const nlohmann::json& member(const nlohmann::json& doc, const std::string& key, const std::string& path,
                             const std::string& where, const char* expected) {
    if (!doc.is_object()) throw Error(path, where.empty() ? "json" : where, "an object", doc.type_name());
    const auto it = doc.find(key);
    if (it == doc.end()) throw Error(path, dotted(where, key), std::string(expected) + " (missing)");
    return *it;
}

std::string shown(const nlohmann::json& v) {
    const std::string s = v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

}  // namespace

nlohmann::json parse_json_text(const std::string& text, const std::string& path) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception&
                 e) {  // parse_error, and out_of_range for a number like 1e1111 (fuzz_job_marker)
        // e.what() is "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ...": keep
        // the part after the library's tag.
        std::string why = e.what();
        const size_t tag = why.find("] ");
        if (tag != std::string::npos) why = why.substr(tag + 2);
        throw Error(path, "json", "a JSON document", why);
    }
}

nlohmann::json read_json_file(const std::string& path) { return parse_json_text(read_file_text(path), path); }

std::string json_string(const nlohmann::json& doc, const std::string& key, const std::string& path,
                        const std::string& where) {
    const nlohmann::json& v = member(doc, key, path, where, "a string");
    if (!v.is_string()) throw Error(path, dotted(where, key), "a string", shown(v));
    return v.get<std::string>();
}

double json_number(const nlohmann::json& doc, const std::string& key, const std::string& path,
                   const std::string& where) {
    const nlohmann::json& v = member(doc, key, path, where, "a number");
    if (!v.is_number()) throw Error(path, dotted(where, key), "a number", shown(v));
    return v.get<double>();
}

int64_t json_integer(const nlohmann::json& doc, const std::string& key, const std::string& path,
                     const std::string& where) {
    const nlohmann::json& v = member(doc, key, path, where, "a whole number");
    if (!v.is_number_integer()) throw Error(path, dotted(where, key), "a whole number", shown(v));
    if (v.is_number_unsigned() && v.get<uint64_t>() > static_cast<uint64_t>(INT64_MAX))
        throw Error(path, dotted(where, key), "a whole number below 2^63", shown(v));
    return v.get<int64_t>();
}

uint64_t json_count(const nlohmann::json& doc, const std::string& key, const std::string& path,
                    const std::string& where) {
    const nlohmann::json& v = member(doc, key, path, where, "a whole number from 0");
    if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<int64_t>() >= 0))
        throw Error(path, dotted(where, key), "a whole number from 0", shown(v));
    return v.get<uint64_t>();
}

bool json_bool(const nlohmann::json& doc, const std::string& key, const std::string& path, const std::string& where) {
    const nlohmann::json& v = member(doc, key, path, where, "true or false");
    if (!v.is_boolean()) throw Error(path, dotted(where, key), "true or false", shown(v));
    return v.get<bool>();
}

const nlohmann::json& json_array(const nlohmann::json& doc, const std::string& key, const std::string& path,
                                 const std::string& where) {
    const nlohmann::json& v = member(doc, key, path, where, "an array");
    if (!v.is_array()) throw Error(path, dotted(where, key), "an array", shown(v));
    return v;
}

const nlohmann::json& json_object(const nlohmann::json& doc, const std::string& key, const std::string& path,
                                  const std::string& where) {
    const nlohmann::json& v = member(doc, key, path, where, "an object");
    if (!v.is_object()) throw Error(path, dotted(where, key), "an object", shown(v));
    return v;
}

}  // namespace t2imu
