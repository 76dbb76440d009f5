#include "core/output_path.hpp"

#include <signal.h>
#include <sys/stat.h>
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

// `path` absolute, as the system resolves it: the longest existing prefix through realpath (symbolic links, and
// ".." after them, as the kernel follows them), then the rest lexically. The last part is kept as named, so a
// link there is judged as a link, not as its target; a last part "." or ".." is resolved with the rest.
fs::path resolved(const std::string& path) {
    fs::path p = fs::absolute(fs::path(path));
    while (!p.has_filename() && p.has_relative_path()) p = p.parent_path();  // "a/b/" -> "a/b"
    std::error_code ec;
    const fs::path name = p.filename();
    if (name.empty() || name == "." || name == "..") {
        const fs::path r = fs::weakly_canonical(p, ec);
        return ec ? p.lexically_normal() : r;
    }
    const fs::path parent = fs::weakly_canonical(p.parent_path(), ec);
    return (ec ? p.parent_path().lexically_normal() : parent) / name;
}

bool exists_no_throw(const fs::path& p) {
    std::error_code ec;
    return fs::exists(fs::symlink_status(p, ec));
}

// Best effort: a folder that cannot take the marker cannot be renamed into place either, and that error says so.
void write_marker(const std::string& folder) {
    std::error_code ec;
    if (fs::is_directory(folder, ec) && !fs::exists(fs::path(folder) / kOutputMarker, ec))
        std::ofstream(folder + "/" + kOutputMarker)
            << "a folder t2imu made; t2imu may write into it or replace it whole\n";
}

// Empty "" when `folder` may be written into or replaced, else why not.
std::string why_not_replaceable(const fs::path& folder) {
    std::error_code ec;
    if (!exists_no_throw(folder)) return "";
    if (fs::is_symlink(fs::symlink_status(folder, ec))) return "a symbolic link";
    if (!fs::is_directory(folder, ec)) return "an existing file";
    if (fs::exists(folder / kOutputMarker, ec) || fs::is_empty(folder, ec)) return "";
    return std::string("a folder t2imu did not make (no ") + kOutputMarker + "): choose another, or add " +
           kOutputMarker + " if an earlier t2imu made it";
}

// Whether `inner` is `outer` or lies below it (both resolved).
bool is_within(const fs::path& inner, const fs::path& outer) {
    auto i = inner.begin();
    for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
        if (i == inner.end() || *i != *o) return false;
    return true;
}

// Makes and removes a probe folder in `folder` (an existing one): "" when that worked, else the system's reason.
std::string probe_folder(const fs::path& folder) {
    const fs::path probe = folder / (".t2imu-probe-" + std::to_string(::getpid()));
    if (::mkdir(probe.c_str(), 0700) != 0) return folder.string() + ": " + std::strerror(errno);
    ::rmdir(probe.c_str());
    return "";
}

// Proves that `target`'s folders can be made and an entry written into the deepest, leaving nothing behind.
void check_creatable(const fs::path& target, const std::string& path, const std::string& option, OutputKind kind) {
    std::vector<fs::path> missing;  // the folders above `target` that do not exist yet, deepest first
    fs::path existing = target.parent_path();
    while (!exists_no_throw(existing)) {
        missing.push_back(existing);
        existing = existing.parent_path();
    }
    std::error_code ec;
    if (!fs::is_directory(existing, ec))
        throw Error(option, path, "a path below folders", existing.string() + " is a file");
    if (missing.empty()) {
        std::string why = probe_folder(existing);
        if (why.empty() && kind == OutputKind::folder && fs::is_directory(target, ec)) why = probe_folder(target);
        if (!why.empty()) throw Error(option, path, "a folder t2imu can write into", why);
        return;
    }
    fs::create_directories(missing.front(), ec);
    const std::string why = ec ? ec.message() : probe_folder(missing.front());
    for (const fs::path& p : missing) {
        std::error_code ignored;  // deepest first, so each is empty when its turn comes; absent ones were never made
        fs::remove(p, ignored);
    }
    if (!why.empty()) throw Error(option, path, "folders that can be created", missing.back().string() + ": " + why);
}

}  // namespace

std::string resolved_output_path(const std::string& path) { return resolved(path).string(); }

void check_output(const std::string& path, const std::string& option, OutputKind kind,
                  const std::vector<std::string>& inputs) {
    if (path.empty()) throw Error(option, "path", "an output path");
    const fs::path target = resolved(path);
    std::error_code ec;
    if (fs::is_symlink(fs::symlink_status(target, ec)))
        throw Error(option, path, "a path that is not a symbolic link (t2imu writes only where the path names)",
                    "a link to " + fs::read_symlink(target, ec).string());
    for (const std::string& input : inputs) {
        if (input.empty()) continue;
        const fs::path in = fs::weakly_canonical(fs::absolute(input), ec);
        if (!ec && is_within(in, target))
            throw Error(option, path, "an output apart from the inputs",
                        in == target ? "it is the input " + input : "it holds the input " + input);
    }
    if (exists_no_throw(target)) {
        if (kind == OutputKind::file && fs::is_directory(target, ec))
            throw Error(option, path, "a file to write (t2imu never replaces a folder with a file)",
                        "an existing folder");
        if (kind == OutputKind::file && !fs::is_regular_file(target, ec))
            throw Error(option, path, "a file to write", "an existing special file");
        if (kind == OutputKind::folder) {
            const std::string why = why_not_replaceable(target);
            if (!why.empty()) throw Error(option, path, "an output folder t2imu may write into", why);
        }
    }
    check_creatable(target, path, option, kind);
}

void claim_output_folder(const std::string& path) {
    make_directories(path, "output folder");
    write_marker(path);
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
        if (fs::is_symlink(fs::symlink_status(walk, ec)))
            throw Error(field, relative, "a path without symbolic links", walk.string() + " is one");
    }
    return (fs::path(folder) / inside).string();
}

void make_directories(const std::string& path, const std::string& field) {
    std::error_code ec;
    fs::create_directories(path, ec);
    if (ec) throw Error(path, field, "a folder that can be created", ec.message());
}

std::string partial_path_for(const std::string& path) {
    return resolved(path).string() + ".partial-" + std::to_string(::getpid());
}

void publish_partial(const std::string& partial, const std::string& path) {
    const fs::path target = resolved(path);  // the folder the guard judged, whatever links and ".." the path holds
    const std::string why = why_not_replaceable(target);
    if (!why.empty())
        throw Error(path, "output folder", "a folder t2imu may replace (the result is in " + partial + ")", why);
    write_marker(partial);
    const fs::path old = target.string() + ".old-" + std::to_string(::getpid());
    std::error_code ec;
    fs::remove_all(old, ec);
    const bool replacing = exists_no_throw(target);
    if (replacing) fs::rename(target, old, ec);
    if (!ec) fs::rename(partial, target, ec);
    if (ec) {
        std::error_code ignored;
        if (replacing && !exists_no_throw(target)) fs::rename(old, target, ignored);
        throw Error(path, "rename", "a replaceable output folder (the result is in " + partial + ")", ec.message());
    }
    fs::remove_all(old, ec);
}

void remove_stale_partials(const std::string& path) {
    const fs::path target = resolved(path);
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
