#include "core/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/output_path.hpp"

namespace t2imu {

namespace fs = std::filesystem;

std::string temporary_path_for(const std::string& path) {
    const fs::path p(path);
    if (p.has_parent_path()) make_directories(p.parent_path().string(), "folder");
    return (p.parent_path() / ("." + p.filename().string() + ".tmp" + std::to_string(getpid()))).string();
}

void commit_temporary(const std::string& tmp, const std::string& path) {
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::remove(tmp.c_str());
        throw Error(path, "rename", "a writable destination", why);
    }
}

void write_file_atomic(const std::string& path, const void* data, size_t size) {
    const std::string tmp = temporary_path_for(path);
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw Error(path, "open", "a writable file", std::strerror(errno));
        out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
        out.flush();
        if (!out) {
            std::remove(tmp.c_str());
            throw Error(path, "write", "room to write " + std::to_string(size) + " bytes");
        }
    }
    commit_temporary(tmp, path);
}

void write_file_atomic(const std::string& path, const std::string& text) {
    write_file_atomic(path, text.data(), text.size());
}

std::vector<uint8_t> read_file_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path, "open", "a readable file", std::strerror(errno));
    in.seekg(0, std::ios::end);
    const std::streamoff n = in.tellg();
    if (n < 0) throw Error(path, "read", "a regular file");
    in.seekg(0);
    std::vector<uint8_t> bytes(static_cast<size_t>(n));
    in.read(reinterpret_cast<char*>(bytes.data()), n);
    if (!in) throw Error(path, "read", std::to_string(n) + " bytes");
    return bytes;
}

std::string read_file_text(const std::string& path) {
    const std::vector<uint8_t> b = read_file_bytes(path);
    return std::string(b.begin(), b.end());
}

}  // namespace t2imu
