// A job marker of a synthesis folder (t2imu synth's jobs/<job>.json, written by src/pipeline/synth.cpp): the
// one statement of the fields later stages read (the manifest, synth_report.json, resume), with their types.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace t2imu {

// Error naming `path` and the dotted key ("recordings.3.n_samples") when a field is missing or mistyped:
// job, prompt, activity (strings), seed (whole, >= 0), kept (bool), attempts[].failures[] (strings), quality
// (object of numbers), recordings[] {path, body, position, n_samples, bytes?}, motions[]? {path, bytes},
// activity_check? {shown, passed}, source_draw? (object). A marker passing it can be read without checks.
void check_job_marker(const nlohmann::json& marker, const std::string& path);

}  // namespace t2imu
