// safetensors files: 8-byte little-endian header length, a JSON header
// {"name": {"dtype": "F32", "shape": [..], "data_offsets": [begin, end]}, "__metadata__": {str: str}},
// then the data. F16, BF16, F32, F64, I64, I32, U8 and BOOL. Offsets are validated: in range, matching the
// dtype and shape, no overlaps, no gaps.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/ndarray.hpp"

namespace t2imu {

struct SafeTensors {
    std::map<std::string, NdArray> tensors;
    std::map<std::string, std::string> metadata;
};

SafeTensors parse_safetensors(const uint8_t* data, size_t size, const std::string& source);
SafeTensors read_safetensors(const std::string& path);
std::vector<uint8_t> serialize_safetensors(const SafeTensors& st);       // tensors in name order, 8-byte aligned header
void write_safetensors(const std::string& path, const SafeTensors& st);  // atomic

}  // namespace t2imu
