// NumPy .npy files (format versions 1.0, 2.0 and 3.0): little-endian float16/32/64, int32/64, uint8 and bool.
// Fortran-ordered files (NumPy writes them for transposed views and column slices) are read into C order;
// big-endian data, object and structured arrays and truncated data are refused with an Error naming the source
// and the header field. Files are written in C order.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/ndarray.hpp"

namespace t2imu {

NdArray parse_npy(const uint8_t* data, size_t size, const std::string& source);
NdArray read_npy(const std::string& path);

std::vector<uint8_t> serialize_npy(const NdArray& a);       // version 1.0 (2.0 when the header needs it)
void write_npy(const std::string& path, const NdArray& a);  // atomic (temporary name + rename)

}  // namespace t2imu
