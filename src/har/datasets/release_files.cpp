#include "har/datasets/release_files.hpp"

#include <algorithm>
#include <filesystem>

#include "core/error.hpp"

namespace t2imu {

std::vector<ImuRecording> import_release_files(const std::string& dir, const std::regex& file_name,
                                               const std::string& expected, const ReleaseFileReader& read,
                                               std::vector<std::string>* skipped) {
    namespace fs = std::filesystem;
    std::vector<std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() && std::regex_match(e.path().filename().string(), file_name)) files.push_back(e.path().string());
    if (files.empty()) throw Error(dir, "files", expected);
    std::sort(files.begin(), files.end());
    std::vector<ImuRecording> out;
    for (const std::string& f : files) {
        try {
            std::vector<ImuRecording> r = read(f);
            out.insert(out.end(), std::make_move_iterator(r.begin()), std::make_move_iterator(r.end()));
        } catch (const Error& e) {
            if (!skipped) throw;
            skipped->push_back(e.what());
        }
    }
    return out;
}

}  // namespace t2imu
