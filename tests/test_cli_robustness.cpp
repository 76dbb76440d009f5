// Bad input never crashes t2imu, never leaves a half-made output, and every refusal is one line naming what to
// fix. One row per case: the arguments, the input files the row writes, the exit code (2: a flag or option value
// refused before any work; 1: an input refused or the work failed), a fragment of the message and the paths that
// must not exist afterwards. Each row runs in its own folder; {D} in arguments stands for it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "body/procedural_body.hpp"
#include "core/npy.hpp"
#include "test_util.hpp"

using namespace t2imu;
using namespace std::string_literals;
namespace fs = std::filesystem;

namespace {

using Files = std::map<std::string, std::string>;  // path relative to the row's folder -> content

struct Row {
    std::string name;
    std::string args;
    Files files;
    int exit_code;
    std::string fragment;
    std::vector<std::string> absent;
};

// gtest names a failing row by this instead of dumping its bytes.
void PrintTo(const Row& row, std::ostream* os) { *os << row.name; }

Files operator+(Files a, const Files& b) {
    a.insert(b.begin(), b.end());
    return a;
}

// A tiny data set in the IMU dataset layout (imu/imu_dataset.hpp): two subjects walking and running, chest,
// 6 s at 20 Hz. `bad_cell` replaces the first acc_x value of the first recording.
Files imu_dataset(const std::string& dir, const std::string& bad_cell = "") {
    Files f;
    std::string manifest = "path,dataset,subject,activity,position,rate_hz,n_samples,units\n";
    int k = 0;
    for (const char* subject : {"s1", "s2"})
        for (const auto& [activity, hz] :
             std::vector<std::pair<std::string, double>>{{"walking", 1.0}, {"running", 3.0}}) {
            const std::string path = subject + ("_" + activity) + "_chest.csv";
            std::string csv = "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n";
            for (int i = 0; i <= 120; ++i) {
                const double t = i / 20.0, a = std::sin(2 * M_PI * hz * t);
                const std::string x = k == 0 && i == 0 && !bad_cell.empty() ? bad_cell : std::to_string(a);
                csv += std::to_string(t) + "," + x + ",9.81," + std::to_string(0.5 * a) + ",0,0,0\n";
            }
            f[dir + "/" + path] = csv;
            manifest += path + ",t2imu," + subject + "," + activity + ",chest,20,121,-\n";
            ++k;
        }
    f[dir + "/manifest.csv"] = manifest;
    return f;
}

// A standing average man, 2 s at 20 fps: joints .npy [41, 22, 3].
Files standing_joints(const std::string& path) {
    const ProceduralBody body(paper_bodies()[2]);
    std::vector<float> v;
    for (int f = 0; f < 41; ++f)
        for (const Eigen::Vector3d& j : body.rest_joints())
            for (int c = 0; c < 3; ++c) v.push_back(static_cast<float>(j[c]));
    const std::vector<uint8_t> bytes = serialize_npy(NdArray::from(v, {41, 22, 3}));
    return {{path, std::string(bytes.begin(), bytes.end())}};
}

// model.json of a small GloVe-encoder model, `num_layers` written as given; nothing else of the folder exists.
Files model_json(const std::string& num_layers) {
    return {{"model/model.json", R"({"mdm": {"latent_dim": 32, "ff_size": 64, "num_layers": )" + num_layers +
                                     R"(, "num_heads": 2, "dropout": 0.0, "text_dim": 16, "mask_frames": false},
                                   "text_encoder": {"kind": "glove_transformer", "vocab": "vocab.safetensors", "model_dim": 16,
                                                    "layers": 1, "heads": 2, "ff_size": 32, "out_dim": 16},
                                   "diffusion": {"steps": 50}})"}};
}

const Files kPrompts = {{"p.tsv", "walking\tA man walks forward\n"}};
const Files kFile = {{"file", "a regular file, not a folder\n"}};
const std::string kSynth = "synth --prompts {D}/p.tsv --activity-reference '' --model {D}/no-model ";
const std::string kHar =
    "har run --train {D}/imu --train-subjects 1 --test {D}/imu --positions chest ";  // trains on one subject, tests the
                                                                                     // other
const std::string kSample = "sample --model {D} --prompt 'a man walks' ";
const std::string kImuSynth = "imu synth --joints {D}/j.npy --body preset:male_average ";

std::vector<Row> rows() {
    return {
        // 1: HAR trainings with no epoch crashed restoring the best one; no run is not a result.
        {"HarZeroEpochs",
         kHar + "--repeats 1 --epochs 0 --out {D}/o.json",
         imu_dataset("imu"),
         2,
         "--epochs",
         {"o.json"}},
        {"HarNegativeEpochs",
         kHar + "--repeats 1 --epochs -1 --out {D}/o.json",
         imu_dataset("imu"),
         2,
         "--epochs",
         {"o.json"}},
        {"HarZeroRepeats", kHar + "--repeats 0 --out {D}/o.json", imu_dataset("imu"), 2, "--repeats", {"o.json"}},
        {"HarOneEpochRuns",
         kHar + "--repeats 1 --epochs 1 --out {D}/o.json",
         imu_dataset("imu"),
         0,
         "balanced accuracy",
         {}},
        // 2, 11: prompts are UTF-8 text without control characters; synth needs each line's activity. The prompt set
        // is read at the door (plan_synth), so a bad one is refused like an option: exit 2.
        {"SynthInvalidUtf8Prompt",
         kSynth + "--out {D}/o",
         {{"p.tsv", "walking\tA man \xff\xfe walks\n"}},
         2,
         "p.tsv: line 1: expected UTF-8",
         {"o"}},
        {"SynthNulInPrompt",
         kSynth + "--out {D}/o",
         {{"p.tsv", "# walks\nwalking\tA man \0 walks\n"s}},
         2,
         "p.tsv: line 2: expected text without control characters (got U+0000)",
         {"o"}},
        {"SynthPromptWithoutTab",
         kSynth + "--out {D}/o",
         {{"p.tsv", "A man walks\n"}},
         2,
         "p.tsv: line 1: expected activity<TAB>prompt",
         {"o"}},
        {"SampleInvalidUtf8Prompt",
         "sample --model {D} --prompt 'walks \xff' --out {D}/o",
         {},
         2,
         "--prompt: text: expected UTF-8",
         {"o"}},
        // 3: an output that cannot be made is refused, naming the option, before any work.
        {"ExportOutBelowFile",
         "motion export {D}/j.npy --out {D}/file/o.bvh",
         standing_joints("j.npy") + kFile,
         2,
         "--out: ",
         {}},
        {"ExportOutInProc",
         "motion export {D}/j.npy --out /proc/x/o.bvh",
         standing_joints("j.npy"),
         2,
         "--out: /proc/x/o.bvh",
         {}},
        {"ImuSynthOutInProc", kImuSynth + "--out /proc/x/o", standing_joints("j.npy"), 2, "--out: /proc/x/o", {}},
        {"ImuSynthOutBelowFile", kImuSynth + "--out {D}/file/o", standing_joints("j.npy") + kFile, 2, "is a file", {}},
        {"SynthOutInProc", kSynth + "--out /proc/x/o", kPrompts, 2, "--out: /proc/x/o", {}},
        {"SampleOutBelowFile", kSample + "--out {D}/file/o", kFile, 2, "--out: ", {}},
        {"HarOutInProc", kHar + "--repeats 1 --out /proc/x/o.json", imu_dataset("imu"), 2, "--out: /proc/x/o.json", {}},
        {"DataBuildNegativeCap",
         "data build --mocap {D} --out {D}/o --max-seconds-per-file -1",
         kFile,
         2,
         "--max-seconds-per-file",
         {"o"}},
        {"DataBuildShortChunks",
         "data build --mocap {D} --out {D}/o --max-seconds 1",
         kFile,
         2,
         "--max-seconds: expected 2 s (40 frames) to 3600 s",
         {"o"}},
        {"DataBuildTurnsWithoutDerived",
         "data build --mocap {D} --out {D}/o --no-derived --lying-turns",
         kFile,
         2,
         "--lying-turns: expected the derived clips",
         {"o"}},
        {"DataBuildRestsWithoutDerived",
         "data build --mocap {D} --out {D}/o --no-derived --lie-down-rests",
         kFile,
         2,
         "--lie-down-rests: expected the derived clips",
         {"o"}},
        {"DataBuildRoundTripsWithoutDerived",
         "data build --mocap {D} --out {D}/o --no-derived --stairs-round-trips",
         kFile,
         2,
         "--stairs-round-trips: expected the derived clips",
         {"o"}},
        // Every other command that writes checks its --out before any work too.
        {"ImportImuOutInProc",
         "data import-imu --format sisfall {D} --out /proc/x/o",
         kFile,
         2,
         "--out: /proc/x/o",
         {}},
        {"DomainGapOutInProc",
         "analysis domain-gap --real {D}/f.csv --synthetic {D}/f.csv --out /proc/x/g.json",
         {{"f.csv", "activity,f1\nwalking,1\n"}},
         2,
         "--out: /proc/x/g.json",
         {}},

        {"TsneOutInProc",
         "tsne --in {D}/x.csv --out /proc/x/y.csv",
         {{"x.csv", "a,b\n1,2\n3,4\n"}},
         2,
         "--out: /proc/x/y.csv",
         {}},
        {"ReportOutBelowFile", "report --in {D} --out {D}/file/r", kFile, 2, "--out: ", {}},
        {"FeaturesOutInProc",
         "features catch22 --dataset {D}/imu --out /proc/x/f.csv",
         imu_dataset("imu"),
         2,
         "--out: /proc/x/f.csv",
         {}},
        {"ExperimentHarSettingsCheckedOnRead",
         "experiment --config {D}/e.toml --out {D}/o",
         {{"e.toml",
           "[[source]]\nname = \"r\"\nmodel = \"retrieval:x\"\n[[real]]\nname = \"s\"\ndataset = \"x\"\nprompts = "
           "\"p\"\nsensors = \"sisfall\"\n[har]\nmax_epochs = 0\n"}},
         1,
         "e.toml: har: expected valid HAR settings",
         {"o"}},
        // The check creates missing folders to prove it can, and removes them: a run refused later leaves none.
        {"HarCheckedOutFoldersRemoved",
         "har run --train {D}/imu --train-subjects 1 --test {D}/imu --positions tentacle --repeats 1 --out "
         "{D}/a/b/o.json",
         imu_dataset("imu"),
         1,
         "tentacle",
         {"a"}},
        // 4: model.json's fields are read by name with their range.
        {"ModelLayersNotANumber",
         "sample --model {D}/model --prompt walks --out {D}/o",
         model_json(R"("four")"),
         1,
         "mdm.num_layers: expected an integer from 1",
         {"o"}},
        {"ModelLayersNegative",
         "sample --model {D}/model --prompt walks --out {D}/o",
         model_json("-3"),
         1,
         "mdm.num_layers: expected an integer from 1 to 256 (got -3)",
         {"o"}},
        // 5: sensor sets are read strictly, at the door (exit 2).
        {"SensorTomlMisspeltKey",
         kImuSynth + "--sensors {D}/s.toml --out {D}/o",
         standing_joints("j.npy") + Files{{"s.toml",
                                           "[[sensor]]\nposition = \"wrist\"\nsegment = \"right_elbow\"\naroud = "
                                           "-90\nx = \"distal\"\nz = \"out\"\n"}},
         2,
         "s.toml: sensor[0].aroud: expected a known key",
         {"o"}},
        {"SensorTomlWrongType",
         kImuSynth + "--sensors {D}/s.toml --out {D}/o",
         standing_joints("j.npy") + Files{{"s.toml",
                                           "[[sensor]]\nposition = \"wrist\"\nsegment = \"right_elbow\"\nalong = "
                                           "\"far\"\nx = \"distal\"\nz = \"out\"\n"}},
         2,
         "s.toml: sensor[0].along: expected",
         {"o"}},
        // 6, 7: option values are checked before any work or output.
        {"SynthGuidanceNan",
         kSynth + "--guidance nan --out {D}/o",
         kPrompts,
         2,
         "--guidance: expected a scale from 0 to 100",
         {"o"}},
        {"SampleGuidanceInf",
         kSample + "--guidance inf --out {D}/o",
         {},
         2,
         "--guidance: expected a scale from 0 to 100",
         {"o"}},
        // Round two (2026-12-04): a scale whose features overflow float32 (1e20) is refused, not sampled into NaN.
        {"SampleGuidanceHuge",
         kSample + "--guidance 1e20 --out {D}/o",
         {},
         2,
         "--guidance: expected a scale from 0 to 100 (got 100000000000000000000",
         {"o"}},
        {"SynthGuidanceHuge",
         kSynth + "--guidance 1e300 --out {D}/o",
         kPrompts,
         2,
         "--guidance: expected a scale from 0 to 100",
         {"o"}},
        {"SynthRateZero", kSynth + "--rate 0 --out {D}/o", kPrompts, 2, "--rate", {"o"}},
        {"SynthRateNegative", kSynth + "--rate -5 --out {D}/o", kPrompts, 2, "--rate", {"o"}},
        {"SynthStepsZero", kSynth + "--steps 0 --out {D}/o", kPrompts, 2, "--steps", {"o"}},
        {"SynthAgreementAboveOne",
         kSynth + "--min-activity-agreement 2 --out {D}/o",
         kPrompts,
         2,
         "--min-activity-agreement",
         {"o"}},
        {"SynthBatchZero", kSynth + "--batch 0 --out {D}/o", kPrompts, 2, "--batch", {"o"}},
        {"ImuSynthRateAboveTheLimit",
         kImuSynth + "--rate 5000 --out {D}/o",
         standing_joints("j.npy"),
         2,
         "--rate",
         {"o"}},
        // Sensor realism (imu/realism.hpp): presets by name, TOML files strictly, one device model at a time.
        {"ImuSynthUnknownRealism",
         kImuSynth + "--realism sisfal --out {D}/o",
         standing_joints("j.npy"),
         2,
         "--realism",
         {"o"}},
        {"ImuSynthRealismTomlUnknownKey",
         kImuSynth + "--realism {D}/r.toml --out {D}/o",
         standing_joints("j.npy") + Files{{"r.toml", "base = \"sisfall\"\ntilt_dg = 3\n"}},
         2,
         "r.toml: tilt_dg",
         {"o"}},
        {"ImuSynthRealismTomlOutOfRange",
         kImuSynth + "--realism {D}/r.toml --out {D}/o",
         standing_joints("j.npy") + Files{{"r.toml", "tissue_hz = 0.5\n"}},
         2,
         "tissue_hz",
         {"o"}},
        {"ImuSynthRealismTomlUnknownBase",
         kImuSynth + "--realism {D}/r.toml --out {D}/o",
         standing_joints("j.npy") + Files{{"r.toml", "base = \"tentacle\"\n"}},
         2,
         "r.toml: base: expected none, realworld, sisfall",
         {"o"}},
        {"ImuSynthRealismTomlUnknownDevice",
         kImuSynth + "--realism {D}/r.toml --out {D}/o",
         standing_joints("j.npy") + Files{{"r.toml", "sensor = \"tentacle\"\n"}},
         2,
         "r.toml: sensor: model: expected none, smartphone",
         {"o"}},
        {"ImuSynthUnknownSensorModel",
         kImuSynth + "--realism sisfall+sensor=tentacle --out {D}/o",
         standing_joints("j.npy"),
         2,
         "sensor: model: expected none, smartphone",
         {"o"}},
        {"ImuSynthRealismRuns",
         kImuSynth + "--realism sisfall --sensors sisfall --out {D}/o",
         standing_joints("j.npy"),
         0,
         "1 bodies x 1 sensors",
         {}},
        {"SignalStatsRateOutOfRange",
         "analysis signal-stats --real {D}/imu --rate 2 --out {D}/o.json",
         imu_dataset("imu"),
         2,
         "--rate",
         {"o.json"}},
        // Reframing (imu/reframe.hpp): sets by name, positions each set places, a source convention to start from.
        {"DataReframeUnknownSet",
         "data reframe {D}/imu --from realworld --to sisfal --out {D}/o",
         imu_dataset("imu"),
         2,
         "--to: set: expected realworld, sisfall",
         {"o"}},
        {"DataReframeOutInProc",
         "data reframe {D}/imu --from realworld --to umafall --out /proc/x/o",
         imu_dataset("imu"),
         2,
         "--out: /proc/x/o",
         {}},
        {"DataReframePositionNotPlaced",
         "data reframe {D}/imu --from realworld --to sisfall --out {D}/o",
         imu_dataset("imu"),
         1,
         "--to: chest: expected a position the set sisfall places (waist)",
         {"o"}},
        {"DataReframeSyntheticNeedsFrom",
         "data reframe {D}/imu --to umafall --out {D}/o",
         imu_dataset("imu"),
         1,
         "dataset: expected a data set's name",
         {"o"}},
        {"DataReframeUnknownPosition",
         "data reframe {D}/imu --from realworld --to umafall --positions tentacle --out {D}/o",
         imu_dataset("imu"),
         1,
         "--positions: tentacle: expected a position the data set holds",
         {"o"}},
        {"DataReframeRuns",
         "data reframe {D}/imu --from realworld --to umafall --out {D}/o",
         imu_dataset("imu"),
         0,
         "4 recordings in the axes of umafall",
         {}},
        // Round two: no path read from a manifest leads outside its folder; no --out replaces a user's file or folder.
        {"DataReframeManifestLeavesTheFolder",
         "data reframe {D}/imu --from realworld --to umafall --out {D}/o",
         Files{{"imu/manifest.csv",
                "path,dataset,subject,activity,position,rate_hz,n_samples,units\n../"
                "x.csv,t2imu,s1,walking,chest,20,2,-\n"},
               {"x.csv", "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n0,0,9.81,0,0,0,0\n0.05,0,9.81,0,0,0,0\n"}},
         1,
         "manifest.csv row 2 column 'path': ../x.csv: expected a relative path inside",
         {"o"}},
        {"DataReframeOutIsAFile",
         "data reframe {D}/imu --from realworld --to umafall --out {D}/file",
         imu_dataset("imu") + kFile,
         2,
         "an existing file",
         {}},
        {"ImuSynthOutIsAFile",
         kImuSynth + "--out {D}/file",
         standing_joints("j.npy") + kFile,
         2,
         "an existing file",
         {}},
        {"ImportImuOutIsAFile",
         "data import-imu --format sisfall {D}/imu --out {D}/file",
         imu_dataset("imu") + kFile,
         2,
         "an existing file",
         {}},
        {"ImuSynthOutIsAUserFolder",
         kImuSynth + "--out {D}/mine",
         standing_joints("j.npy") + Files{{"mine/notes.txt", "mine\n"}},
         2,
         "a folder t2imu did not make",
         {}},
        {"HarManifestNegativeCount",
         kHar + "--repeats 1 --out {D}/o.json",
         Files{{"imu/manifest.csv",
                "path,dataset,subject,activity,position,rate_hz,n_samples,units\na.csv,t2imu,s1,walking,chest,20,-1,-"
                "\n"}},
         2,
         "manifest.csv: row 2 column 'n_samples': expected a whole number of samples from 0 (got '-1')",
         {"o.json"}},
        {"HarManifestNanCount",
         kHar + "--repeats 1 --out {D}/o.json",
         Files{{"imu/manifest.csv",
                "path,dataset,subject,activity,position,rate_hz,n_samples,units\na.csv,t2imu,s1,walking,chest,20,nan,-"
                "\n"}},
         2,
         "column 'n_samples'",
         {"o.json"}},
        {"HarManifestNotUtf8",
         kHar + "--repeats 1 --out {D}/o.json",
         Files{{"imu/manifest.csv",
                "path,dataset,subject,activity,position,rate_hz,n_samples,units\na.csv,t2imu,s\xff,walking,chest,20,2,-"
                "\n"}},
         2,
         "row 2 column 'subject': expected UTF-8 text",
         {"o.json"}},
        // 10: HAR names the position, the window and the damaged cell.
        {"HarUnknownPosition",
         "har run --train {D}/imu --train-subjects 1 --test {D}/imu --positions tentacle --repeats 1 --out {D}/o.json",
         imu_dataset("imu"),
         1,
         "--positions: tentacle: expected a position the data set holds (chest)",
         {"o.json"}},
        {"HarWindowLongerThanTrials",
         kHar + "--window 100 --repeats 1 --out {D}/o.json",
         imu_dataset("imu"),
         1,
         "--window: expected at most the longest trial",
         {"o.json"}},
        {"MotionImportNegativeFps",
         "motion import {D}/j.npy --fps -5 --out {D}/o.npy",
         standing_joints("j.npy"),
         2,
         "--fps: rate: expected 0 (the capture rate) to 1000 fps",
         {"o.npy"}},
        {"MotionImportNanFps",
         "motion import {D}/j.npy --fps nan --out {D}/o.npy",
         standing_joints("j.npy"),
         2,
         "--fps",
         {"o.npy"}},
        {"TextVocabZeroWords",
         "text vocab --from {D}/v.json --words 0 --out {D}/v.safetensors",
         {{"v.json", "{}"}},
         2,
         "--words: count: expected at least 1 word",
         {"v.safetensors"}},
        {"TextVocabMissingOnlyIn",
         "text vocab --from {D}/v.json --only-words-in {D}/nothing --out {D}/v.safetensors",
         {{"v.json", "{}"}},
         2,
         "--only-words-in: ",
         {"v.safetensors"}},
        {"TextVocabOutInProc",
         "text vocab --from {D}/v.json --out /proc/x/v.safetensors",
         {{"v.json", "{}"}},
         2,
         "--out: /proc/x/v.safetensors",
         {}},
        {"HarWindowTooShort",
         kHar + "--window 0.5 --repeats 1 --out {D}/o.json",
         imu_dataset("imu"),
         2,
         "--window: 0.500000 s: expected at least 17 samples at --rate",
         {"o.json"}},
        {"HarUnknownTestPosition",
         kHar + "--test-positions tentacle --repeats 1 --out {D}/o.json",
         imu_dataset("imu"),
         1,
         "--test-positions: tentacle: expected a position the data set holds",
         {"o.json"}},
        {"HarUnknownClass",
         kHar + "--classes walking,tentacle --repeats 1 --out {D}/o.json",
         imu_dataset("imu"),
         2,
         "--classes: tentacle: expected a class of the training set",
         {"o.json"}},
        {"HarNanCell",
         kHar + "--repeats 1 --out {D}/o.json",
         imu_dataset("imu", "nan"),
         1,
         "s1_walking_chest.csv: row 2 column 'acc_x': expected a finite number",
         {"o.json"}},
        // Round two (issue 45): unknown positions, windows too short for catch22, imports with nothing usable.
        {"SignalStatsUnknownPosition",
         "analysis signal-stats --real {D}/imu --position tentacle --out {D}/o.json",
         imu_dataset("imu"),
         1,
         "--position: tentacle: expected a position the data set holds (chest)",
         {"o.json"}},
        {"StaticNoiseUnknownPosition",
         "analysis static-noise --real {D}/imu --position tentacle --out {D}/o.json",
         imu_dataset("imu"),
         1,
         "--position: tentacle: expected a position the data set holds (chest)",
         {"o.json"}},
        {"Catch22WindowTooShort",
         "features catch22 --dataset {D}/imu --window-s 0.1 --out {D}/o.csv",
         imu_dataset("imu"),
         2,
         "--window-s: 0.100000 s: expected at least 10 samples at --rate",
         {"o.csv"}},
        {"ImportSisfallNothingUsable",
         "data import-imu --format sisfall {D}/in --out {D}/o",
         Files{{"in/SA01/D01_SA01_R01.txt", "nan, 1, 2, 3, 4, 5, 6, 7, 8;\n"}},
         1,
         "recordings: expected at least one usable recording among 1",
         {"o"}},
        {"ImportUmafallHugeSensorId",
         "data import-imu --format umafall {D}/in --out {D}/o",
         Files{{"in/UMAFall_Subject_01_ADL_Walking_1_2017-04-14_23-38-23.csv",
                "% C4:BE:84:70:64:8A; 99999999999999; WAIST; SensorTag\n"}},
         1,
         "sensor id: expected a whole number from 0 to 999999",
         {"o"}},
        // Round three (issue 64): an importer refuses a sensor id listed twice and a sample past any sensor's range.
        {"ImportUmafallDuplicateSensorId",
         "data import-imu --format umafall {D}/in --out {D}/o",
         Files{
             {"in/UMAFall_Subject_01_ADL_Walking_1_2017-04-14_23-38-23.csv",
              "% C4:BE:84:70:64:8A; 1; WAIST; SensorTag\n% C4:BE:84:70:64:8B; 1; WRIST; SensorTag\n100;1;0;1;0;0;1\n"}},
         1,
         "line 2 sensor id: expected an id listed once",
         {"o"}},
        {"ImportUmafallHugeSample",
         "data import-imu --format umafall {D}/in --out {D}/o",
         Files{{"in/UMAFall_Subject_01_ADL_Walking_1_2017-04-14_23-38-23.csv",
                "% C4:BE:84:70:64:8A; 1; WAIST; SensorTag\n100;1;1e20;1;0;0;1\n"}},
         1,
         "line 2: expected a sample within ±10^4 (g, °/s) (got 1e20)",
         {"o"}},
        // Prompts: blank text and bidi controls refused naming the line; a file that never ends refused at its cap.
        {"SynthBlankPrompt",
         kSynth + "--out {D}/o",
         {{"p.tsv", "walking\t   \n"}},
         2,
         "p.tsv: line 1: expected a prompt after the tab (not blank)",
         {"o"}},
        {"SynthBidiPrompt",
         kSynth + "--out {D}/o",
         {{"p.tsv", "walking\ta man \xE2\x80\xAEsklaw\n"}},
         2,
         "p.tsv: line 1: expected text without bidirectional control characters (got U+202E)",
         {"o"}},
        {"SynthEndlessPrompts",
         "synth --prompts /dev/zero --activity-reference '' --model {D}/no-model --out {D}/o",
         {},
         2,
         "/dev/zero: size: expected a prompts file of at most 16 MiB",
         {"o"}},
        // What an error quotes of its input is cut after its head and made printable.
        {"SynthGuidance301Digits",
         kSynth + "--guidance 1" + std::string(300, '0') + " --out {D}/o",
         kPrompts,
         2,
         "(got 100000000000...(301 digits).000000)",
         {"o"}},
        {"UnknownOptionWithEscapes",
         "synth --prompts {D}/p.tsv --out {D}/o '--bad\x1b[2J\xe2\x80\xaex'",
         kPrompts,
         2,
         "not expected: --bad\\x1B[2J\\u202Ex",
         {"o"}},
        // text vocab: JSON errors and values float16 cannot hold, named by field.
        {"TextVocabJsonSyntax",
         "text vocab --from {D}/v.json --out {D}/v.safetensors",
         {{"v.json", "{\"words\": [}"}},
         1,
         "v.json: json: expected valid JSON (got a syntax error at byte 12)",
         {"v.safetensors"}},
        {"TextVocabWordNotAString",
         "text vocab --from {D}/v.json --out {D}/v.safetensors",
         {{"v.json", "{\"words\": [1], \"vectors\": {}, \"dimensions\": 100}"}},
         1,
         "v.json: words[0]: expected a word (a string)",
         {"v.safetensors"}},
        {"TextVocabDimensionsNotANumber",
         "text vocab --from {D}/v.json --out {D}/v.safetensors",
         {{"v.json", "{\"words\": [], \"vectors\": {}, \"dimensions\": \"100\"}"}},
         1,
         "v.json: header: expected an object with words",
         {"v.safetensors"}},
        {"TextVocabInfiniteVector",
         "text vocab --from {D}/v.json --out {D}/v.safetensors",
         {{"v.json",
           "{\"words\": [\"walk\"], \"vectors\": {\"walk\": "
           "[1e39,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,"
           "0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0]}, "
           "\"dimensions\": 100}"}},
         1,
         "v.json: vectors.walk[0]: expected a finite number within ±65504 (float16)",
         {"v.safetensors"}},
        // An attachment the integration cannot follow is refused when validated (docs/realism.md: the stability bound).
        {"ImuSynthRealismUnstableTissue",
         kImuSynth + "--realism {D}/r.toml --out {D}/o",
         standing_joints("j.npy") + Files{{"r.toml", "tissue_hz = 150\ntissue_damping = 2\n"}},
         2,
         "r.toml: tissue_hz with tissue_damping: expected 2 pi tissue_hz",
         {"o"}},
        // har run never writes over one of its inputs.
        {"HarOutIsTheTrainingSet",
         kHar + "--repeats 1 --out {D}/imu",
         imu_dataset("imu"),
         2,
         "expected an output apart from the inputs (got it is the input",
         {}},
        // Usage errors are one line with exit code 2.
        {"MissingRequiredOption", "synth", {}, 2, "--prompts is required", {}},
        {"UnknownFlag", kImuSynth + "--out {D}/o --no-such-flag", standing_joints("j.npy"), 2, "--no-such-flag", {"o"}},
        // 8: a folder a killed run left behind is removed by the next run; the output appears whole.
        {"ImuSynthRemovesStalePartials",
         kImuSynth + "--out {D}/o",
         standing_joints("j.npy") + Files{{"o.partial-999999999/x.csv", "t\n"}},
         0,
         "1 bodies",
         {"o.partial-999999999"}},
        // Already refused before this suite: content errors of an input exit 1 and leave nothing.
        {"ImuSynthShortJoints", "imu synth --joints {D}/p.tsv --out {D}/o", kPrompts, 1, "p.tsv", {"o"}},
    };
}

std::string with_dir(std::string s, const std::string& dir) {
    for (size_t at; (at = s.find("{D}")) != std::string::npos;) s.replace(at, 3, dir);
    return s;
}

// Every row's folder, files and outcome: the rows run together through test::run_cli_each, once per process.
struct Outcome {
    std::string dir;
    test::CliResult result;
};
const std::map<std::string, Outcome>& outcomes() {
    static const std::map<std::string, Outcome> all = [] {
        std::vector<std::string> calls, dirs;
        for (const Row& row : rows()) {
            const std::string dir = test::scratch_dir("cli_robustness/" + row.name);
            for (const auto& [path, content] : row.files) {
                fs::create_directories((fs::path(dir) / path).parent_path());
                std::ofstream(dir + "/" + path, std::ios::binary) << content;
            }
            calls.push_back("--threads 1 " + with_dir(row.args, dir));
            dirs.push_back(dir);
        }
        const std::vector<test::CliResult> results = test::run_cli_each(calls);
        std::map<std::string, Outcome> by_name;
        for (size_t i = 0; i < results.size(); ++i) by_name.emplace(rows()[i].name, Outcome{dirs[i], results[i]});
        return by_name;
    }();
    return all;
}

class CliRobustnessTable : public testing::TestWithParam<Row> {};

TEST_P(CliRobustnessTable, Row) {
    const Row& row = GetParam();
    const test::CliResult& r = outcomes().at(row.name).result;
    const std::string& dir = outcomes().at(row.name).dir;
    EXPECT_EQ(r.exit_code, row.exit_code) << r.output;
    EXPECT_NE(r.output.find(row.fragment), std::string::npos) << "expected \"" << row.fragment << "\" in: " << r.output;
    if (row.exit_code != 0) {
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        EXPECT_EQ(r.output.rfind("t2imu: ", 0), 0u) << r.output;
    }
    for (const std::string& path : row.absent) EXPECT_FALSE(fs::exists(dir + "/" + path)) << path;
    // A run never changes or removes the files it was given (an --out naming one among them included).
    for (const auto& [path, content] : row.files) {
        const bool expected_gone = std::any_of(row.absent.begin(), row.absent.end(),
                                               [&](const std::string& a) { return path.rfind(a, 0) == 0; });
        if (expected_gone) continue;
        std::ifstream in(dir + "/" + path, std::ios::binary);
        EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), content) << path << " changed";
    }
}

INSTANTIATE_TEST_SUITE_P(CliRobustness, CliRobustnessTable, testing::ValuesIn(rows()),
                         [](const testing::TestParamInfo<Row>& info) { return info.param.name; });

}  // namespace
