// For the release-file fuzz targets: the readers take a path whose file name carries the subject, activity
// and trial, so each input is written to a file of that name in a folder of this process's own.
#pragma once
#include <unistd.h>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

inline std::string write_fuzz_file(const std::string& name, const uint8_t* data, size_t size) {
    static const std::string dir = [] {
        const std::string d =
            (std::filesystem::temp_directory_path() / ("t2imu-fuzz-" + std::to_string(getpid()))).string();
        std::filesystem::create_directories(d);
        return d;
    }();
    const std::string path = dir + "/" + name;
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path;
}
