// Walks a dataset release folder: every file under it whose name matches, in sorted order, read by a
// per-format reader. A file the reader refuses (t2imu::Error) is skipped and its message kept in `skipped`, so
// one damaged file does not stop an import of thousands; when no file gives a recording, the import is refused
// (Error naming the folder, the number of files and the first reason).
#pragma once
#include <functional>
#include <regex>
#include <string>
#include <vector>

#include "imu/imu_dataset.hpp"

namespace t2imu {

using ReleaseFileReader = std::function<std::vector<ImuRecording>(const std::string& path)>;

// A sensor id, part or trial number written in a release file or its name: decimal digits, 0 to 999,999.
// Error(path, field, ...) for anything else (a huge number included, which must not wrap around).
int release_index(const std::string& text, const std::string& path, const std::string& field);

std::vector<ImuRecording> import_release_files(const std::string& dir, const std::regex& file_name,
                                               const std::string& expected, const ReleaseFileReader& read,
                                               std::vector<std::string>* skipped);

}  // namespace t2imu
