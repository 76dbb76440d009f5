// NumPy .npz archives (zip of .npy members, stored or deflated), read and written with libzip.
// Member names are given without the ".npy" suffix, as numpy.load presents them.
#pragma once
#include <map>
#include <string>

#include "core/ndarray.hpp"

namespace t2imu {

std::map<std::string, NdArray> read_npz(const std::string& path);
std::map<std::string, NdArray> parse_npz(const uint8_t* data, size_t size, const std::string& source);
// The member `name` (without ".npy") of an archive read from `source`; an Error names both when it is absent.
const NdArray& npz_member(const std::map<std::string, NdArray>& npz, const std::string& name,
                          const std::string& source);
// compress: deflate members (numpy.savez_compressed) or store them (numpy.savez). Atomic.
void write_npz(const std::string& path, const std::map<std::string, NdArray>& arrays, bool compress = true);

}  // namespace t2imu
