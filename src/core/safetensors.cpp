#include "core/safetensors.hpp"

#include <algorithm>
#include <cstring>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace t2imu {

namespace {

constexpr uint64_t kMaxHeader = 100000000;  // bytes: the reference (Rust) implementation's MAX_HEADER_SIZE

const struct {
    const char* name;
    DType dtype;
} kDtypes[] = {{"F16", DType::f16}, {"BF16", DType::bf16}, {"F32", DType::f32}, {"F64", DType::f64},
               {"I64", DType::i64}, {"I32", DType::i32},   {"U8", DType::u8},   {"BOOL", DType::boolean}};

DType parse_dtype(const std::string& s, const std::string& source, const std::string& key) {
    for (const auto& d : kDtypes)
        if (s == d.name) return d.dtype;
    throw Error(source, key + ".dtype", "one of F16 BF16 F32 F64 I64 I32 U8 BOOL", s);
}

const char* dtype_tag(DType t) {
    for (const auto& d : kDtypes)
        if (d.dtype == t) return d.name;
    return "?";
}

struct Span {
    uint64_t begin, end;
    std::string name;
};

}  // namespace

SafeTensors parse_safetensors(const uint8_t* data, size_t size, const std::string& source) {
    if (size < 8) throw Error(source, "header length", "8 bytes", std::to_string(size) + " bytes");
    uint64_t n = 0;
    for (int k = 7; k >= 0; --k) n = (n << 8) | data[k];
    if (n > kMaxHeader || n > size - 8)
        throw Error(source, "header length", "at most the file size and 100 MB", std::to_string(n));
    // The reference refuses a header that does not open with '{' (leading spaces included).
    if (n == 0 || data[8] != '{') throw Error(source, "header", "a JSON object starting with '{'");
    nlohmann::json h;
    try {
        h = nlohmann::json::parse(data + 8, data + 8 + n);
    } catch (const nlohmann::json::exception& e) {
        throw Error(source, "header", "valid JSON", e.what());
    }
    if (!h.is_object()) throw Error(source, "header", "a JSON object");
    const uint8_t* body = data + 8 + n;
    const uint64_t body_size = size - 8 - n;
    SafeTensors st;
    std::vector<Span> spans;
    for (auto it = h.begin(); it != h.end(); ++it) {
        const std::string& key = it.key();
        const nlohmann::json& v = it.value();
        if (key == "__metadata__") {
            if (!v.is_object()) throw Error(source, key, "an object of strings");
            for (auto m = v.begin(); m != v.end(); ++m) {
                if (!m.value().is_string()) throw Error(source, "__metadata__." + m.key(), "a string");
                st.metadata[m.key()] = m.value().get<std::string>();
            }
            continue;
        }
        if (!v.is_object() || !v.contains("dtype") || !v.contains("shape") || !v.contains("data_offsets") ||
            !v["dtype"].is_string() || !v["shape"].is_array() || !v["data_offsets"].is_array() ||
            v["data_offsets"].size() != 2)
            throw Error(source, key, "{dtype, shape, data_offsets: [begin, end]}");
        NdArray a;
        a.dtype = parse_dtype(v["dtype"].get<std::string>(), source, key);
        // Dimensions other than zeros must multiply to a size that fits, as in .npy.
        uint64_t nonzero = 1;
        bool empty = false;
        for (const auto& d : v["shape"]) {
            if (!d.is_number_unsigned()) throw Error(source, key + ".shape", "non-negative integers");
            const uint64_t dim = d.get<uint64_t>();
            if (dim == 0)
                empty = true;
            else if (__builtin_mul_overflow(nonzero, dim, &nonzero) || nonzero > (uint64_t(1) << 58))
                throw Error(source, key + ".shape", "a size that fits in memory");
            a.shape.push_back(static_cast<int64_t>(dim));
        }
        const uint64_t count = empty ? 0 : nonzero;
        const auto& off = v["data_offsets"];
        if (!off[0].is_number_unsigned() || !off[1].is_number_unsigned())
            throw Error(source, key + ".data_offsets", "two non-negative integers");
        const uint64_t begin = off[0].get<uint64_t>(), end = off[1].get<uint64_t>();
        if (begin > end || end > body_size)
            throw Error(source, key + ".data_offsets", "0 <= begin <= end <= " + std::to_string(body_size),
                        "[" + std::to_string(begin) + ", " + std::to_string(end) + "]");
        if (end - begin != count * dtype_size(a.dtype))
            throw Error(
                source, key + ".data_offsets",
                std::to_string(count * dtype_size(a.dtype)) + " bytes for " + a.shape_str() + " " + dtype_tag(a.dtype),
                std::to_string(end - begin));
        a.bytes.assign(body + begin, body + end);
        spans.push_back({begin, end, key});
        st.tensors[key] = std::move(a);
    }
    // The tensors must tile the data exactly: no overlaps, no gaps, nothing after the last one.
    std::sort(spans.begin(), spans.end(),
              [](const Span& a, const Span& b) { return a.begin < b.begin || (a.begin == b.begin && a.end < b.end); });
    uint64_t at = 0;
    for (const Span& s : spans) {
        if (s.begin != at)
            throw Error(source, s.name + ".data_offsets",
                        "to start at byte " + std::to_string(at) + " (no gaps or overlaps)", std::to_string(s.begin));
        at = s.end;
    }
    if (at != body_size)
        throw Error(source, "data", std::to_string(at) + " bytes covered by tensors", std::to_string(body_size));
    return st;
}

SafeTensors read_safetensors(const std::string& path) {
    const std::vector<uint8_t> bytes = read_file_bytes(path);
    return parse_safetensors(bytes.data(), bytes.size(), path);
}

std::vector<uint8_t> serialize_safetensors(const SafeTensors& st) {
    nlohmann::json h = nlohmann::json::object();
    if (!st.metadata.empty()) h["__metadata__"] = st.metadata;
    uint64_t at = 0;
    for (const auto& [name, a] : st.tensors) {  // std::map: name order
        if (name == "__metadata__") throw Error(name, "tensor name", "a name other than __metadata__");
        if (static_cast<size_t>(a.size()) * dtype_size(a.dtype) != a.bytes.size())
            throw Error(name, "bytes", std::to_string(a.size() * static_cast<int64_t>(dtype_size(a.dtype))),
                        std::to_string(a.bytes.size()));
        h[name] = {{"dtype", dtype_tag(a.dtype)}, {"shape", a.shape}, {"data_offsets", {at, at + a.bytes.size()}}};
        at += a.bytes.size();
    }
    std::string header;
    try {
        header = h.dump();
    } catch (const nlohmann::json::exception& e) {  // a name or metadata string that is not UTF-8
        throw Error("", "header", "UTF-8 tensor names and metadata", e.what());
    }
    header.append((8 - header.size() % 8) % 8, ' ');  // 8-byte alignment of the data, as the reference writes
    std::vector<uint8_t> out(8 + header.size() + at);
    for (size_t k = 0; k < 8; ++k)
        out[k] = static_cast<uint8_t>((static_cast<uint64_t>(header.size()) >> (8 * k)) & 0xff);
    std::memcpy(out.data() + 8, header.data(), header.size());
    size_t pos = 8 + header.size();
    for (const auto& [name, a] : st.tensors) {
        if (!a.bytes.empty()) std::memcpy(out.data() + pos, a.bytes.data(), a.bytes.size());
        pos += a.bytes.size();
    }
    return out;
}

void write_safetensors(const std::string& path, const SafeTensors& st) {
    const std::vector<uint8_t> bytes = serialize_safetensors(st);
    write_file_atomic(path, bytes.data(), bytes.size());
}

}  // namespace t2imu
