#include "core/zip_archive.hpp"

#include <zip.h>

#include <cstdio>
#include <memory>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace t2imu {

namespace {

struct ZipDiscard {
    void operator()(zip_t* z) const { zip_discard(z); }
};

}  // namespace

ZipMembers parse_zip(const uint8_t* data, size_t size, const std::string& source) {
    zip_error_t err;
    zip_error_init(&err);
    zip_source_t* src = zip_source_buffer_create(data, size, 0, &err);
    if (!src) throw Error(source, "zip", "a readable buffer", zip_error_strerror(&err));
    std::unique_ptr<zip_t, ZipDiscard> z(zip_open_from_source(src, ZIP_RDONLY, &err));
    if (!z) {
        zip_source_free(src);
        const std::string why = zip_error_strerror(&err);
        zip_error_fini(&err);
        throw Error(source, "zip", "a zip archive", why);
    }
    ZipMembers out;
    const zip_int64_t n = zip_get_num_entries(z.get(), 0);
    for (zip_int64_t i = 0; i < n; ++i) {
        zip_stat_t st;
        if (zip_stat_index(z.get(), static_cast<zip_uint64_t>(i), 0, &st) != 0 || !(st.valid & ZIP_STAT_NAME) ||
            !(st.valid & ZIP_STAT_SIZE))
            throw Error(source, "member " + std::to_string(i), "a readable zip entry");
        const std::string name = st.name;
        if (!name.empty() && name.back() == '/') continue;
        // Deflate cannot expand data more than ~1032-fold, so no member can hold more than that many times the
        // archive's bytes: refuse larger claims before allocating, so a forged header cannot ask for gigabytes.
        if (st.size > 1100 * static_cast<zip_uint64_t>(size) + 4096)
            throw Error(source, name, "a size the archive can hold", std::to_string(st.size) + " bytes claimed");
        std::unique_ptr<zip_file_t, decltype(&zip_fclose)> f(zip_fopen_index(z.get(), static_cast<zip_uint64_t>(i), 0),
                                                             &zip_fclose);
        if (!f) throw Error(source, name, "a member that can be opened", zip_strerror(z.get()));
        std::vector<uint8_t> bytes(static_cast<size_t>(st.size));
        const zip_int64_t got = bytes.empty() ? 0 : zip_fread(f.get(), bytes.data(), st.size);
        if (got < 0 || static_cast<zip_uint64_t>(got) != st.size)
            throw Error(source, name, std::to_string(st.size) + " bytes", "a damaged or truncated member");
        out[name] = std::move(bytes);
    }
    return out;
}

ZipMembers read_zip(const std::string& path) {
    const std::vector<uint8_t> bytes = read_file_bytes(path);
    return parse_zip(bytes.data(), bytes.size(), path);
}

void write_zip(const std::string& path, const ZipMembers& members, bool compress) {
    const std::string tmp = temporary_path_for(path);
    int zerr = 0;
    zip_t* z = zip_open(tmp.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &zerr);
    if (!z) throw Error(path, "zip", "a writable archive", "libzip error " + std::to_string(zerr));
    for (const auto& [name, bytes] : members) {  // libzip reads the buffers at zip_close; they outlive it here
        zip_source_t* s = zip_source_buffer(z, bytes.data(), bytes.size(), 0);
        const zip_int64_t idx = s ? zip_file_add(z, name.c_str(), s, ZIP_FL_OVERWRITE) : -1;
        if (idx < 0) {
            if (s) zip_source_free(s);
            zip_discard(z);
            throw Error(path, name, "a member libzip can add");
        }
        zip_set_file_compression(z, static_cast<zip_uint64_t>(idx), compress ? ZIP_CM_DEFLATE : ZIP_CM_STORE, 0);
    }
    if (zip_close(z) != 0) {
        const std::string why = zip_strerror(z);
        zip_discard(z);
        std::remove(tmp.c_str());
        throw Error(path, "zip", "a written archive", why);
    }
    commit_temporary(tmp, path);
}

}  // namespace t2imu
