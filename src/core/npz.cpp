#include "core/npz.hpp"

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "core/parse.hpp"
#include "core/zip_archive.hpp"

namespace t2imu {

std::map<std::string, NdArray> parse_npz(const uint8_t* data, size_t size, const std::string& source) {
    // The end-of-central-directory record alone is 22 bytes; libzip would take an empty buffer for an empty
    // archive, which numpy.load refuses too.
    if (size < 22) throw Error(source, "zip", "a zip archive", std::to_string(size) + " bytes");
    std::map<std::string, NdArray> out;
    for (const auto& [member, bytes] : parse_zip(data, size, source)) {
        std::string name = member;
        if (name.size() > 4 && ends_with(name, ".npy")) name.resize(name.size() - 4);
        if (out.count(name)) throw Error(source, member, "member names that differ without .npy", name + " twice");
        out[name] = parse_npy(bytes.data(), bytes.size(), source + ":" + member);
    }
    return out;
}

const NdArray& npz_member(const std::map<std::string, NdArray>& npz, const std::string& name,
                          const std::string& source) {
    const auto it = npz.find(name);
    if (it != npz.end()) return it->second;
    std::string present;
    size_t listed = 0;
    for (const auto& [member, array] : npz) {
        if (listed++ == 10) {
            present += " ...";
            break;
        }  // one line, however large the archive
        present += (present.empty() ? "" : " ") + member;
    }
    throw Error(source, name, "a member named '" + name + "'",
                present.empty() ? "an empty archive" : "only " + present);
}

std::map<std::string, NdArray> read_npz(const std::string& path) {
    const std::vector<uint8_t> bytes = read_file_bytes(path);
    return parse_npz(bytes.data(), bytes.size(), path);
}

void write_npz(const std::string& path, const std::map<std::string, NdArray>& arrays, bool compress) {
    ZipMembers members;
    for (const auto& [name, array] : arrays) members[name + ".npy"] = serialize_npy(array);
    write_zip(path, members, compress);
}

}  // namespace t2imu
