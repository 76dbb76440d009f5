#include "core/output_path.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "core/error.hpp"
#include "core/parse.hpp"

namespace t2imu {

namespace fs = std::filesystem;

namespace {

// `path` absolute, without a trailing separator, so that parent_path() and filename() mean what they say.
fs::path normalised(const std::string& path) {
    fs::path p = fs::absolute(fs::path(path)).lexically_normal();
    return p.has_filename() ? p : p.parent_path();
}

bool exists_no_throw(const fs::path& p) {
    std::error_code ec;
    return fs::exists(fs::symlink_status(p, ec));
}

// Best effort: a folder that cannot take the marker cannot be renamed into place either, and that error says so.
void write_marker(const std::string& folder) {
    std::error_code ec;
    if (fs::is_directory(folder, ec)) std::ofstream(folder + "/" + kOutputMarker) << "a folder t2imu published; t2imu may replace it whole\n";
}

}  // namespace

void check_output_path(const std::string& path, const std::string& option) {
    if (path.empty()) throw Error(option, "path", "an output path");
    const fs::path target = normalised(path);
    std::vector<fs::path> missing;  // the folders above `target` that do not exist yet, deepest first
    fs::path existing = target.parent_path();
    while (!exists_no_throw(existing)) {
        missing.push_back(existing);
        existing = existing.parent_path();
    }
    std::error_code ec;
    if (!fs::is_directory(existing, ec)) throw Error(option, path, "a path below folders", existing.string() + " is a file");
    if (::access(existing.c_str(), W_OK | X_OK) != 0)
        throw Error(option, path, "a writable folder to write into", existing.string() + ": " + std::strerror(errno));
    if (exists_no_throw(target) && fs::is_directory(target, ec) && ::access(target.c_str(), W_OK | X_OK) != 0)
        throw Error(option, path, "a writable folder", std::strerror(errno));
    if (missing.empty()) return;
    // access() says yes to root on filesystems that refuse anyway (/proc): only creating the folders proves it.
    fs::create_directories(missing.front(), ec);
    for (const fs::path& p : missing) {
        std::error_code ignored;  // deepest first, so each is empty when its turn comes; absent ones were never made
        fs::remove(p, ignored);
    }
    if (ec) throw Error(option, path, "folders that can be created", ec.message());
}

void check_output_folder(const std::string& path, const std::string& option) {
    check_output_path(path, option);
    std::error_code ec;
    const fs::path target = normalised(path);
    if (exists_no_throw(target) && !fs::is_directory(target, ec))
        throw Error(option, path, "a folder to write (t2imu never replaces a file with a folder)", "an existing file");
}

namespace {

// Empty "" when `folder` may be replaced, else why not.
std::string why_not_replaceable(const fs::path& folder) {
    std::error_code ec;
    if (!exists_no_throw(folder)) return "";
    if (fs::is_symlink(folder, ec) || !fs::is_directory(folder, ec)) return "an existing file";
    if (fs::exists(folder / kOutputMarker, ec) || fs::is_empty(folder, ec)) return "";
    return std::string("a folder t2imu did not make (no ") + kOutputMarker + "): remove it or choose another";
}

}  // namespace

void check_replaceable_folder(const std::string& path, const std::string& option) {
    check_output_folder(path, option);
    const std::string why = why_not_replaceable(normalised(path));
    if (!why.empty()) throw Error(option, path, "an output folder t2imu may replace", why);
}

std::string confined_path(const std::string& folder, const std::string& relative, const std::string& field) {
    const fs::path r(relative);
    if (relative.empty() || r.is_absolute() || r.has_root_name())
        throw Error(field, relative.empty() ? "''" : relative, "a relative path inside " + folder);
    const fs::path inside = r.lexically_normal();
    if (inside.empty() || *inside.begin() == ".." || inside == ".")
        throw Error(field, relative, "a relative path inside " + folder, "it leaves the folder");
    fs::path walk = fs::path(folder);
    std::error_code ec;
    for (const fs::path& part : inside) {
        walk /= part;
        if (fs::is_symlink(fs::symlink_status(walk, ec))) throw Error(field, relative, "a path without symbolic links", walk.string() + " is one");
    }
    return (fs::path(folder) / inside).string();
}

void make_directories(const std::string& path, const std::string& field) {
    std::error_code ec;
    fs::create_directories(path, ec);
    if (ec) throw Error(path, field, "a folder that can be created", ec.message());
}

std::string partial_path_for(const std::string& path) {
    return normalised(path).string() + ".partial-" + std::to_string(::getpid());
}

void publish_partial(const std::string& partial, const std::string& path) {
    const std::string why = why_not_replaceable(normalised(path));
    if (!why.empty()) throw Error(path, "output folder", "a folder t2imu may replace (the result is in " + partial + ")", why);
    write_marker(partial);
    const std::string old = normalised(path).string() + ".old-" + std::to_string(::getpid());
    std::error_code ec;
    fs::remove_all(old, ec);
    const bool replacing = fs::exists(path);
    if (replacing) fs::rename(path, old, ec);
    if (!ec) fs::rename(partial, path, ec);
    if (ec) {
        std::error_code ignored;
        if (replacing && !fs::exists(path)) fs::rename(old, path, ignored);
        throw Error(path, "rename", "a replaceable output folder (the result is in " + partial + ")", ec.message());
    }
    fs::remove_all(old, ec);
}

void remove_stale_partials(const std::string& path) {
    const fs::path target = normalised(path);
    const std::string prefix = target.filename().string() + ".partial-";
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(target.parent_path(), ec)) {
        const std::string name = e.path().filename().string();
        if (name.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string pid = name.substr(prefix.size());
        const std::optional<long long> id = parse_integer(pid);
        if (!id || *id < 1 || *id > 999999999) continue;
        if (::kill(static_cast<pid_t>(*id), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to judge
        std::error_code ignored;  // best effort: a folder we cannot remove only costs disk space
        fs::remove_all(e.path(), ignored);
    }
}

}  // namespace t2imu
