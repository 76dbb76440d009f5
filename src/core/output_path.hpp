// Output paths checked before any work: a job that cannot write its result should say so at once, naming the
// option, not after minutes of work with a raw std::filesystem message. Also the clean-up of folders that killed
// runs left behind.
#pragma once
#include <string>
#include <vector>

namespace t2imu {

// What a command writes at --out: one file (replaced whole by a rename), or a folder (filled in place, or
// replaced whole by publish_partial).
enum class OutputKind { file, folder };

// The one output-path guard, called by every command that writes before any work; throws Error naming `option`
// and `path`. The path is resolved as the system resolves it (the nearest existing ancestor through realpath, so
// symbolic links and ".." after them count, then the rest), and refused when:
//  - `path` itself is a symbolic link (its target could be anything: /etc, a user's folder);
//  - it is one of `inputs`, or holds one (an input would be overwritten or replaced);
//  - for a file: it is an existing folder or a special file; for a folder: it is an existing file, or a non-empty
//    folder t2imu did not make (no kOutputMarker in it: a user's folder is never written over or replaced);
//  - the nearest existing folder cannot take a new entry: a probe folder is made there and removed again, which
//    proves what access() cannot (/proc and /sys say yes to root and refuse anyway). Missing folders above `path`
//    are made the same way and removed, so a refused or accepted check leaves nothing behind.
void check_output(const std::string& path, const std::string& option, OutputKind kind,
                  const std::vector<std::string>& inputs = {});
constexpr const char* kOutputMarker = ".t2imu-output";  // in every output folder t2imu made

// `path` absolute, symbolic links and ".." resolved as the system would, the last part kept as named (a link
// there is not followed): what check_output judges and what publish_partial renames onto.
std::string resolved_output_path(const std::string& path);

// For a command that fills its output folder in place (synth, report, experiment, sample, train): makes the
// folder after check_output passed and marks it as t2imu's, so a rerun may write into it again.
void claim_output_folder(const std::string& path);

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
// is not replaceable (check_output's rule for a folder, checked again here in case it changed since). `path` is
// resolved first (resolved_output_path), so a "LINK/../x" renames onto the x the guard judged. Writes
// kOutputMarker into the published folder.
void publish_partial(const std::string& partial, const std::string& path);

}  // namespace t2imu
