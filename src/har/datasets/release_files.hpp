// Walks a dataset release folder: every file under it whose name matches, in sorted order, read by a
// per-format reader. A file the reader refuses (t2imu::Error) is skipped and its message kept in `skipped`, so
// one damaged file does not stop an import of thousands.
#pragma once
#include <functional>
#include <regex>
#include <string>
#include <vector>

#include "imu/imu_dataset.hpp"

namespace t2imu {

using ReleaseFileReader = std::function<std::vector<ImuRecording>(const std::string& path)>;

std::vector<ImuRecording> import_release_files(const std::string& dir, const std::regex& file_name,
                                               const std::string& expected, const ReleaseFileReader& read,
                                               std::vector<std::string>* skipped);

}  // namespace t2imu
