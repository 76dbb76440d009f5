#include "core/ndarray.hpp"

#include <cmath>

namespace t2imu {

size_t dtype_size(DType t) {
    switch (t) {
        case DType::f16:
        case DType::bf16: return 2;
        case DType::f32:
        case DType::i32: return 4;
        case DType::f64:
        case DType::i64: return 8;
        case DType::u8:
        case DType::boolean: return 1;
    }
    return 0;
}

const char* dtype_name(DType t) {
    switch (t) {
        case DType::f16: return "float16";
        case DType::bf16: return "bfloat16";
        case DType::f32: return "float32";
        case DType::f64: return "float64";
        case DType::i32: return "int32";
        case DType::i64: return "int64";
        case DType::u8: return "uint8";
        case DType::boolean: return "bool";
    }
    return "?";
}

int64_t NdArray::size() const {
    int64_t n = 1;
    for (int64_t d : shape) {
        if (d < 0) throw Error("", "shape", "non-negative dimensions", shape_str());
        if (__builtin_mul_overflow(n, d, &n))
            throw Error("", "shape", "an element count that fits in 64 bits", shape_str());
    }
    return n;
}

std::string NdArray::shape_str() const {
    std::string s = "(";
    for (size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
    if (shape.size() == 1) s += ",";
    return s + ")";
}

float half_to_float(uint16_t h) {
    const uint32_t sign = (h >> 15) & 1, exp = (h >> 10) & 0x1f, mant = h & 0x3ff;
    float v;
    if (exp == 0)
        v = std::ldexp(static_cast<float>(mant), -24);  // subnormal
    else if (exp == 31)
        v = mant ? NAN : INFINITY;
    else
        v = std::ldexp(static_cast<float>(mant | 0x400), static_cast<int>(exp) - 25);
    return sign ? -v : v;
}

float bfloat16_to_float(uint16_t b) {
    uint32_t u = static_cast<uint32_t>(b) << 16;
    float f;
    std::memcpy(&f, &u, 4);
    return f;
}

uint16_t float_to_bfloat16(float f) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    if (std::isnan(f)) return static_cast<uint16_t>((u >> 16) | 0x40);
    u += 0x7fff + ((u >> 16) & 1);
    return static_cast<uint16_t>(u >> 16);
}

uint16_t float_to_half(float f) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    const uint16_t sign = static_cast<uint16_t>((u >> 16) & 0x8000);
    if (std::isnan(f)) return sign | 0x7e00;
    const float a = std::fabs(f);
    if (a >= 65520.0f) return sign | 0x7c00;              // rounds to infinity
    if (a < 6.103515625e-05f) {                           // subnormal half: multiples of 2^-24
        const float q = std::nearbyint(a * 16777216.0f);  // round-half-even under the default mode
        return sign | static_cast<uint16_t>(q);
    }
    int e;
    const float m = std::frexp(a, &e);  // a = m * 2^e, m in [0.5, 1)
    float mant = std::nearbyint((m * 2.0f - 1.0f) * 1024.0f);
    int exp = e - 1 + 15;
    if (mant >= 1024.0f) {
        mant = 0;
        ++exp;
    }
    if (exp >= 31) return sign | 0x7c00;
    return sign | static_cast<uint16_t>(exp << 10) | static_cast<uint16_t>(mant);
}

template <class T>
std::vector<T> NdArray::to() const {
    const int64_t n = size();
    std::vector<T> out(static_cast<size_t>(n));
    const uint8_t* p = bytes.data();
    auto load = [p](size_t i, auto tag) {
        decltype(tag) v;
        std::memcpy(&v, p + i * sizeof(v), sizeof(v));
        return v;
    };
    for (int64_t i = 0; i < n; ++i) {
        const size_t k = static_cast<size_t>(i);
        switch (dtype) {
            case DType::f16: out[k] = static_cast<T>(half_to_float(load(k, uint16_t{}))); break;
            case DType::bf16: out[k] = static_cast<T>(bfloat16_to_float(load(k, uint16_t{}))); break;
            case DType::f32: out[k] = static_cast<T>(load(k, float{})); break;
            case DType::f64: out[k] = static_cast<T>(load(k, double{})); break;
            case DType::i32: out[k] = static_cast<T>(load(k, int32_t{})); break;
            case DType::i64: out[k] = static_cast<T>(load(k, int64_t{})); break;
            case DType::u8: out[k] = static_cast<T>(p[k]); break;
            case DType::boolean: out[k] = static_cast<T>(p[k] != 0); break;
        }
    }
    return out;
}

template std::vector<float> NdArray::to<float>() const;
template std::vector<double> NdArray::to<double>() const;
template std::vector<int32_t> NdArray::to<int32_t>() const;
template std::vector<int64_t> NdArray::to<int64_t>() const;
template std::vector<uint8_t> NdArray::to<uint8_t>() const;

}  // namespace t2imu
