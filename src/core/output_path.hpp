// Output paths checked before any work: a job that cannot write its result should say so at once, naming the
// option, not after minutes of work with a raw std::filesystem message. Also the clean-up of folders that killed
// runs left behind.
#pragma once
#include <string>

namespace t2imu {

// Throws Error naming `option` and `path` unless `path` (a file or folder to be written) can be made: the folders
// above it exist or can be created, none of them is a file, and the nearest existing one is writable. Missing
// folders are created to prove it and removed again, so a refused run leaves nothing behind.
void check_output_path(const std::string& path, const std::string& option);

// For a command that writes a folder: check_output_path, and refuses an existing `path` that is not a folder (a
// user's file is never replaced by a folder).
void check_output_folder(const std::string& path, const std::string& option);

// For a command that replaces its output folder whole (publish_partial): check_output_folder, and refuses an
// existing non-empty folder that t2imu did not publish (no kOutputMarker in it): a user's folder is never
// removed because --out named it.
void check_replaceable_folder(const std::string& path, const std::string& option);
constexpr const char* kOutputMarker = ".t2imu-output";  // written into every folder publish_partial puts in place

// `relative` (a path read from a manifest or another input) below `folder`: refused with an Error naming `field`
// and the path when it is absolute, empty, or leaves the folder after normalisation ("../x", "a/../../x"), or
// when an existing part of it below `folder` is a symbolic link (which could lead anywhere).
std::string confined_path(const std::string& folder, const std::string& relative, const std::string& field);

// create_directories with an Error naming `path` and what it is for (`field`) instead of std::filesystem_error.
void make_directories(const std::string& path, const std::string& field);

// Removes `<path>.partial-<pid>` folders beside `path` whose process is gone (killed runs): a partial folder of a
// live process (a concurrent run) is left alone.
void remove_stale_partials(const std::string& path);
// The folder a run of this process builds before renaming it onto `path`.
std::string partial_path_for(const std::string& path);
// Puts the finished folder `partial` in the place of `path`, replacing a previous output whole: the old one is
// moved aside first and removed last, so `path` holds either the old result or the new one, never a mix. An
// Error names `path` and where the result is when a rename fails (the old output is put back), or when `path`
// is not replaceable (check_replaceable_folder's rule, checked again here in case it changed since). Writes
// kOutputMarker into the published folder.
void publish_partial(const std::string& partial, const std::string& path);

}  // namespace t2imu
