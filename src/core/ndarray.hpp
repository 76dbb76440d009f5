// A typed, shaped, C-ordered block of numbers: what .npy, .npz and safetensors hold.
// The element type is kept as stored (no silent widening); `to<T>()` converts on request.
#pragma once
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace t2imu {

enum class DType { f16, bf16, f32, f64, i32, i64, u8, boolean };

size_t dtype_size(DType t);
const char* dtype_name(DType t);  // "float32", "int64", ... (NumPy names)

struct NdArray {
    DType dtype = DType::f32;
    std::vector<int64_t> shape;
    std::vector<uint8_t> bytes;  // size() * dtype_size(dtype) bytes, little-endian, C order

    int64_t size() const;           // number of elements (1 for a 0-d array)
    std::string shape_str() const;  // "(170, 22, 3)"

    // Every element converted to T (float16/bfloat16 decoded to float).
    template <class T>
    std::vector<T> to() const;

    template <class T>
    static NdArray from(const std::vector<T>& values, std::vector<int64_t> shape);
};

template <class T>
DType dtype_of();
template <>
inline DType dtype_of<float>() {
    return DType::f32;
}
template <>
inline DType dtype_of<double>() {
    return DType::f64;
}
template <>
inline DType dtype_of<int32_t>() {
    return DType::i32;
}
template <>
inline DType dtype_of<int64_t>() {
    return DType::i64;
}
template <>
inline DType dtype_of<uint8_t>() {
    return DType::u8;
}
template <>
inline DType dtype_of<bool>() {
    return DType::boolean;
}

template <class T>
NdArray NdArray::from(const std::vector<T>& values, std::vector<int64_t> shape) {
    NdArray a;
    a.dtype = dtype_of<T>();
    a.shape = std::move(shape);
    if (a.size() != static_cast<int64_t>(values.size()))
        throw Error("", "shape", a.shape_str() + " to hold " + std::to_string(a.size()) + " values",
                    std::to_string(values.size()));
    a.bytes.resize(values.size() * sizeof(T));
    if constexpr (std::is_same_v<T, bool>) {
        for (size_t i = 0; i < values.size(); ++i) a.bytes[i] = values[i] ? 1 : 0;
    } else if (!values.empty()) {
        std::memcpy(a.bytes.data(), values.data(), a.bytes.size());
    }
    return a;
}

float half_to_float(uint16_t h);
float bfloat16_to_float(uint16_t b);
uint16_t float_to_half(float f);      // round to nearest even
uint16_t float_to_bfloat16(float f);  // round to nearest even

}  // namespace t2imu
