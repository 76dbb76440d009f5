// The IMU dataset format: one on-disk layout for any labelled IMU dataset, real or synthetic, and the one
// reader and writer of it (the real-data importers, t2imu synth and t2imu imu synth all write through here).
//   DIR/manifest.csv   path,dataset,subject,activity,position,rate_hz,n_samples,units[,source,prompt,body,...]
//   DIR/<path>         one CSV per recording and position: t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z
//                      (t in s from the recording's start; acc in m/s^2 including gravity, sensor frame; gyr rad/s)
// Canonical activity names: walking, running, jogging, jumping, sitting, standing, lying, stairs_up,
// stairs_down (others keep their own); canonical positions (chest, forearm, head, shin, thigh, upperarm, waist,
// foot, wrist, ankle) with left_/right_ where the side is known.
// Numbers are written with at most `decimals` digits after the point, trailing zeros dropped ("0", "0.05",
// "-9.8066"): 4 for the shared real copies (their sensors resolve no finer), 6 for synthetic signals. Before a
// row is written every value is checked: finite, samples within ±1e6 (m/s², rad/s), time within 1e9 s; else an
// Error names the file, row and column (a value past that is a numerical failure upstream, not motion).
#pragma once
#include <array>
#include <map>
#include <string>
#include <vector>

#include "imu/imu_synthesis.hpp"

namespace t2imu {

constexpr const char* kImuUnits = "acc=m/s^2(incl. gravity);gyr=rad/s;t=s";

// The recording file's columns, in order: t, acc_x, acc_y, acc_z, gyr_x, gyr_y, gyr_z.
const std::vector<std::string>& imu_sample_columns();

struct ImuRecording {
    std::string path;  // relative to the dataset folder
    std::string dataset, subject, activity, position;
    double rate_hz = 0;
    std::map<std::string, std::string> extra;    // optional manifest columns (source, prompt, body, gyro_flag, ...)
    size_t n_samples = 0;                        // the manifest's count; samples.size() wherever samples are held
    std::vector<double> t;                       // seconds
    std::vector<std::array<double, 6>> samples;  // acc xyz, gyr xyz
};

// Reads the manifest and, when load_samples, every recording's CSV (checking n_samples and monotonic time).
std::vector<ImuRecording> read_imu_dataset(const std::string& dir, bool load_samples = true);

// Writes the recordings' CSVs and the manifest, each atomically; the manifest last, so a folder with a
// manifest is complete.
// Error(option, position, "a position the data set holds (LIST)") when no recording is at `position`; with
// `sided`, left_POSITION and right_POSITION count as POSITION. A wanted position nothing matches is a typo or
// the wrong data set, never an empty result.
void check_position_held(const std::vector<ImuRecording>& recordings, const std::string& position,
                         const std::string& option, bool sided = false);

void write_imu_dataset(const std::string& dir, const std::vector<ImuRecording>& recordings, int decimals = 4);

// One recording's CSV from virtual sensor signals (atomic), for writers that produce recordings one at a time
// and the manifest at the end.
void write_imu_recording(const std::string& path, const ImuSignals& signals, int decimals = 6);

// The manifest alone (atomic), from the recordings' fields and n_samples; their CSVs must already be written.
// Extra columns are the union of the recordings' `extra` keys, in `extra_order` first, then alphabetically.
void write_imu_manifest(const std::string& dir, const std::vector<ImuRecording>& recordings,
                        const std::vector<std::string>& extra_order = {});

}  // namespace t2imu
