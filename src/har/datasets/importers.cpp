#include "har/datasets/importers.hpp"

#include <map>

#include "core/error.hpp"
#include "har/datasets/hugadb.hpp"
#include "har/datasets/realworld.hpp"
#include "har/datasets/sisfall.hpp"
#include "har/datasets/umafall.hpp"

namespace t2imu {

namespace {

// The built-in data sets' readers, by profile name.
const std::map<std::string, ImuImporter>& builtin_importers() {
    static const std::map<std::string, ImuImporter> importers = {
        {"realworld", import_realworld},
        {"sisfall", import_sisfall},
        {"umafall", import_umafall},
        {"hugadb", [](const std::string& folder, std::vector<std::string>*) { return import_hugadb(folder); }},
    };
    return importers;
}

const ImuImporter* importer_of(const DatasetProfile& profile) {
    if (profile.importer) return &profile.importer;
    const auto it = builtin_importers().find(profile.name);
    return it == builtin_importers().end() ? nullptr : &it->second;
}

}  // namespace

bool has_importer(const DatasetProfile& profile) { return importer_of(profile) != nullptr; }

std::vector<ImuRecording> import_imu_dataset(const DatasetProfile& profile, const std::string& folder,
                                             std::vector<std::string>* skipped) {
    const ImuImporter* importer = importer_of(profile);
    if (!importer) throw Error("--format", profile.name, "a data set with a reader of its release format");
    std::vector<std::string> ignored;
    return (*importer)(folder, skipped ? skipped : &ignored);
}

}  // namespace t2imu
