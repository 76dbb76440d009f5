#include "har/datasets/release_files.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/error.hpp"
#include "core/parse.hpp"

namespace t2imu {

int release_index(const std::string& text, const std::string& path, const std::string& field) {
    return static_cast<int>(integer_in(text, 0, 999999, path, field));
}

std::vector<ImuRecording> import_release_files(const std::string& dir, const std::regex& file_name,
                                               const std::string& expected, const ReleaseFileReader& read,
                                               std::vector<std::string>* skipped) {
    namespace fs = std::filesystem;
    std::vector<std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() && std::regex_match(e.path().filename().string(), file_name))
            files.push_back(e.path().string());
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
    if (out.empty())
        throw Error(dir, "recordings",
                    "at least one usable recording among " + std::to_string(files.size()) + " " + expected,
                    skipped && !skipped->empty() ? "none; first refusal: " + skipped->front() : "none");
    return out;
}

}  // namespace t2imu
