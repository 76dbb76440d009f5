#include "core/npy.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <limits>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace t2imu {

namespace {

constexpr uint8_t kMagic[6] = {0x93, 'N', 'U', 'M', 'P', 'Y'};

// NumPy's descr strings for the types we hold, exactly as NumPy writes them (one-byte types carry '|').
bool descr_to_dtype(const std::string& d, DType& out) {
    static const struct {
        const char* descr;
        DType dtype;
    } table[] = {{"<f2", DType::f16}, {"<f4", DType::f32}, {"<f8", DType::f64},    {"<i4", DType::i32},
                 {"<i8", DType::i64}, {"|u1", DType::u8},  {"|b1", DType::boolean}};
    for (const auto& e : table)
        if (d == e.descr) {
            out = e.dtype;
            return true;
        }
    return false;
}

const char* dtype_to_descr(DType t) {
    switch (t) {
        case DType::f16: return "<f2";
        case DType::f32: return "<f4";
        case DType::f64: return "<f8";
        case DType::i32: return "<i4";
        case DType::i64: return "<i8";
        case DType::u8: return "|u1";
        case DType::boolean: return "|b1";
        case DType::bf16: break;  // NumPy has no bfloat16
    }
    throw Error("", "dtype", "a dtype .npy can hold (not bfloat16)", dtype_name(t));
}

// A minimal reader for the Python dict literal of the header:
// {'descr': '<f4', 'fortran_order': False, 'shape': (3, 4), }
struct HeaderParser {
    const std::string& s;
    const std::string& source;
    size_t i = 0;

    void skip_space() {
        while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    }
    // The message quotes the header from the offending character on, at most 40 characters (a version-2.0
    // header may be megabytes), so a shape of (-1, 3) shows '-1, 3), }', not the text before it.
    [[noreturn]] void fail(const std::string& expected) const {
        std::string quoted = s.substr(std::min(i, s.size()), 40);
        quoted = quoted.substr(0, quoted.find('\n'));  // the header's padding ends in a newline: one line only
        quoted.erase(quoted.find_last_not_of(' ') + 1);
        throw Error(source, "npy header", expected, "'" + quoted + "' at header offset " + std::to_string(i));
    }
    void expect(char c) {
        skip_space();
        if (i >= s.size() || s[i] != c) fail(std::string("'") + c + "'");
        ++i;
    }
    bool accept(char c) {
        skip_space();
        if (i < s.size() && s[i] == c) {
            ++i;
            return true;
        }
        return false;
    }
    std::string string_literal() {
        skip_space();
        if (i >= s.size() || (s[i] != '\'' && s[i] != '"')) fail("a quoted string");
        const char q = s[i++];
        const size_t start = i;
        while (i < s.size() && s[i] != q) ++i;
        if (i >= s.size()) fail("a closing quote");
        return s.substr(start, i++ - start);
    }
    bool boolean_literal() {
        skip_space();
        if (s.compare(i, 4, "True") == 0) {
            i += 4;
            return true;
        }
        if (s.compare(i, 5, "False") == 0) {
            i += 5;
            return false;
        }
        fail("True or False");
    }
    std::vector<int64_t> shape_tuple() {
        expect('(');
        std::vector<int64_t> shape;
        while (!accept(')')) {
            skip_space();
            if (i >= s.size() || !std::isdigit(static_cast<unsigned char>(s[i]))) fail("a non-negative integer");
            int64_t v = 0;
            const size_t start = i;
            while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) {
                if (v > (std::numeric_limits<int64_t>::max() - 9) / 10) {
                    i = start;  // quote the number from its first digit, not its tail
                    fail("a dimension that fits in 64 bits");
                }
                v = v * 10 + (s[i++] - '0');
            }
            // NumPy writes an L suffix in Python 2 headers.
            if (i < s.size() && s[i] == 'L') ++i;
            shape.push_back(v);
            if (accept(',')) continue;
            // "(3)" is the Python int 3, not a tuple: NumPy refuses it too.
            if (shape.size() == 1) fail("a tuple (a single dimension needs its comma, as in (3,))");
            expect(')');
            break;
        }
        return shape;
    }
};

struct NpyHeader {
    DType dtype;
    bool fortran_order = false;
    std::vector<int64_t> shape;
};

NpyHeader parse_header_dict(const std::string& text, const std::string& source) {
    HeaderParser p{text, source};
    NpyHeader h{};
    bool have_descr = false, have_order = false, have_shape = false;
    p.expect('{');
    while (!p.accept('}')) {
        const std::string key = p.string_literal();
        p.expect(':');
        if ((key == "descr" && have_descr) || (key == "fortran_order" && have_order) || (key == "shape" && have_shape))
            p.fail("each key once (" + key + " repeats)");
        if (key == "descr") {
            p.skip_space();
            if (p.i < text.size() && (text[p.i] == '[' || text[p.i] == '{'))
                throw Error(source, "descr", "a simple dtype (structured arrays are not supported)");
            const std::string d = p.string_literal();
            if (!descr_to_dtype(d, h.dtype)) {
                std::string why = "one of <f2 <f4 <f8 <i4 <i8 |u1 |b1";
                if (!d.empty() && d[0] == '>') why = "little-endian data (big-endian is not supported)";
                if (d.find('O') != std::string::npos) why = "numbers (object arrays are not supported)";
                throw Error(source, "descr", why, "'" + d.substr(0, 40) + "'");
            }
            have_descr = true;
        } else if (key == "fortran_order") {
            h.fortran_order = p.boolean_literal();
            have_order = true;
        } else if (key == "shape") {
            h.shape = p.shape_tuple();
            have_shape = true;
        } else {
            p.fail("only the keys descr, fortran_order, shape");
        }
        if (!p.accept(',')) {
            p.expect('}');
            break;
        }
    }
    p.skip_space();  // NumPy pads with spaces and ends with '\n'; anything else after the dict is not a header
    if (p.i != text.size()) p.fail("only spaces after the closing brace");
    if (!have_descr || !have_order || !have_shape)
        throw Error(source, "npy header", "the keys descr, fortran_order and shape", text.substr(0, 80));
    return h;
}

// NumPy saves a Fortran-contiguous array (a transposed view, a column slice) with fortran_order True: the
// first index varies fastest. Reordered here, so every NdArray is C order.
std::vector<uint8_t> fortran_to_c_order(const std::vector<uint8_t>& f, const std::vector<int64_t>& shape, size_t item) {
    const size_t n = f.size() / item, dims = shape.size();
    std::vector<uint8_t> c(f.size());
    std::vector<int64_t> index(dims, 0);  // C-order multi-index of element k
    for (size_t k = 0; k < n; ++k) {
        size_t offset = 0, stride = 1;
        for (size_t d = 0; d < dims; ++d) {
            offset += static_cast<size_t>(index[d]) * stride;
            stride *= static_cast<size_t>(shape[d]);
        }
        std::memcpy(c.data() + k * item, f.data() + offset * item, item);
        for (size_t d = dims; d-- > 0;) {
            if (++index[d] < shape[d]) break;
            index[d] = 0;
        }
    }
    return c;
}

uint32_t read_le(const uint8_t* p, int bytes) {
    uint32_t v = 0;
    for (int k = bytes - 1; k >= 0; --k) v = (v << 8) | p[k];
    return v;
}

}  // namespace

NdArray parse_npy(const uint8_t* data, size_t size, const std::string& source) {
    if (size < 10 || !std::equal(kMagic, kMagic + 6, data))
        throw Error(source, "magic", "a .npy file starting with \\x93NUMPY");
    const int major = data[6], minor = data[7];
    if (major < 1 || major > 3 || minor != 0)
        throw Error(source, "version", "format version 1.0, 2.0 or 3.0",
                    std::to_string(major) + "." + std::to_string(minor));
    const int len_bytes = major == 1 ? 2 : 4;
    if (size < static_cast<size_t>(8 + len_bytes)) throw Error(source, "header length", "a complete header");
    const size_t header_len = read_le(data + 8, len_bytes);
    const size_t data_start = 8 + static_cast<size_t>(len_bytes) + header_len;
    if (data_start > size)
        throw Error(source, "header", std::to_string(header_len) + " header bytes", "truncated file");
    const std::string text(reinterpret_cast<const char*>(data) + 8 + len_bytes, header_len);
    const NpyHeader h = parse_header_dict(text, source);

    NdArray a;
    a.dtype = h.dtype;
    a.shape = h.shape;
    // Every dimension counts, zeros aside: NumPy cannot make an array whose other dimensions overflow either.
    const size_t item = dtype_size(a.dtype);
    size_t nonzero = item;
    bool empty = false;
    for (int64_t d : a.shape) {
        if (d == 0) {
            empty = true;
            continue;
        }
        if (__builtin_mul_overflow(nonzero, static_cast<size_t>(d), &nonzero) || nonzero > (size_t(1) << 62))
            throw Error(source, "shape", "a size that fits in memory", a.shape_str());
    }
    const size_t nbytes = empty ? 0 : nonzero;
    if (size - data_start < nbytes)
        throw Error(source, "data", std::to_string(nbytes) + " bytes of data for shape " + a.shape_str(),
                    std::to_string(size - data_start) + " bytes (truncated)");
    if (size - data_start > nbytes)  // NumPy's loader would ignore them; a file that long was not written whole
        throw Error(
            source, "data", std::to_string(nbytes) + " bytes of data for shape " + a.shape_str(),
            std::to_string(size - data_start) + " bytes (" + std::to_string(size - data_start - nbytes) + " trailing)");
    a.bytes.assign(data + data_start, data + data_start + nbytes);
    if (h.fortran_order) a.bytes = fortran_to_c_order(a.bytes, a.shape, item);
    return a;
}

NdArray read_npy(const std::string& path) {
    const std::vector<uint8_t> bytes = read_file_bytes(path);
    return parse_npy(bytes.data(), bytes.size(), path);
}

std::vector<uint8_t> serialize_npy(const NdArray& a) {
    if (a.bytes.size() != static_cast<size_t>(a.size()) * dtype_size(a.dtype))
        throw Error("", "bytes",
                    std::to_string(a.size()) + " elements of " + dtype_name(a.dtype) + " for shape " + a.shape_str(),
                    std::to_string(a.bytes.size()) + " bytes");
    std::string dict = std::string("{'descr': '") + dtype_to_descr(a.dtype) +
                       "', 'fortran_order': False, 'shape': " + a.shape_str() + ", }";
    // Version 1.0 has a 2-byte header length; NumPy switches to 2.0 when the header needs more.
    int major = 1;
    size_t prefix = 10;
    size_t total = prefix + dict.size() + 1;  // + '\n'
    if ((total + 63) / 64 * 64 - prefix > 65535) {
        major = 2;
        prefix = 12;
        total = prefix + dict.size() + 1;
    }
    const size_t padded = (total + 63) / 64 * 64;
    dict.append(padded - total, ' ');
    dict.push_back('\n');
    const size_t header_len = dict.size();

    std::vector<uint8_t> out;
    out.reserve(prefix + header_len + a.bytes.size());
    for (uint8_t b : kMagic) out.push_back(b);
    out.push_back(static_cast<uint8_t>(major));
    out.push_back(0);
    for (size_t k = 0; k < prefix - 8; ++k) out.push_back(static_cast<uint8_t>((header_len >> (8 * k)) & 0xff));
    out.insert(out.end(), dict.begin(), dict.end());
    out.insert(out.end(), a.bytes.begin(), a.bytes.end());
    return out;
}

void write_npy(const std::string& path, const NdArray& a) {
    const std::vector<uint8_t> bytes = serialize_npy(a);
    write_file_atomic(path, bytes.data(), bytes.size());
}

}  // namespace t2imu
