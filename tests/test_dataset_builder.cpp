// The builder on a few shared clips: layout, chunking, captions, mirroring, splits, Mean/Std.
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/npy.hpp"
#include "data/captions.hpp"
#include "data/dataset_builder.hpp"
#include "data/derived_clips.hpp"
#include "motion/humanml3d.hpp"
#include "motion/mocap_import.hpp"
#include "motion/motion_attributes.hpp"
#include "motion/skeleton.hpp"
#include "test_util.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {

// A mocap folder with two CMU clips (07_05: 87 frames; 60_01 salsa: long, gets cut) and a user captions CSV.
std::string make_mocap_folder(const std::string& name) {
    const std::string root = test::unpacked_shared_archive("mocap/cmu_daz_bvh_20fps.tar.xz");
    if (root.empty()) return "";
    const std::string dir = test::scratch_dir(name);
    fs::create_directories(dir + "/bvh20");
    for (const char* f : {"07_05.bvh", "60_01.bvh"}) fs::copy_file(root + "/bvh20/" + f, dir + "/bvh20/" + f);
    std::ofstream(dir + "/captions.csv") << "file,start_frame,end_frame,caption,subject,licence\n"
                                            "bvh20/07_05.bvh,0,87,a person walks slowly to the left,07,CMU\n"
                                            "bvh20/07_05.bvh,0,87,slow walk,07,CMU\n"
                                            "bvh20/60_01.bvh,0,100000,salsa dance,60,CMU\n"
                                            "bvh20/60_01.bvh,100,180,a dancer turns right,60,CMU\n";
    return dir;
}

// Copies `file` (a path under the unpacked archive `root`) to the same path under the mocap folder `dir`.
void copy_into(const std::string& dir, const std::string& root, const std::string& file) {
    fs::create_directories(fs::path(dir + "/" + file).parent_path());
    fs::copy_file(root + "/" + file, dir + "/" + file);
}

}  // namespace

TEST(DatasetBuilder, WritesTheHumanML3DLayout) {
    std::string manifest;
    SHARED_OR_SKIP(manifest, "mocap/manifest.csv");
    const std::string mocap = make_mocap_folder("builder_mocap_layout");
    const std::string out = test::scratch_dir("builder_out") + "/set";
    BuildOptions o;
    o.mocap_dir = mocap;
    o.out_dir = out;
    o.mirror = true;
    const BuildSummary s = build_dataset(o);

    const CsvTable clips = read_csv(out + "/clips.csv");
    const int salsa_frames = import_motion(mocap + "/bvh20/60_01.bvh").num_frames;
    const int chunks = (salsa_frames + 195) / 196;
    EXPECT_EQ(s.clips, 2 * (1 + chunks));
    EXPECT_EQ(static_cast<int>(clips.rows.size()), s.clips);
    for (const char* f : {"Mean.npy", "Std.npy", "train.txt", "val.txt", "test.txt", "all.txt", "summary.json"})
        EXPECT_TRUE(fs::exists(out + "/" + f)) << f;
    EXPECT_EQ(read_npy(out + "/Mean.npy").shape, (std::vector<int64_t>{263}));

    // 07_05: features have one frame fewer than the joints; new_joints = recover_from_ric(features).
    const NdArray vecs = read_npy(out + "/new_joint_vecs/000000.npy");
    EXPECT_EQ(vecs.shape, (std::vector<int64_t>{86, 263}));
    EXPECT_EQ(read_npy(out + "/new_joints/000000.npy").shape, (std::vector<int64_t>{86, 22, 3}));
    const auto texts = read_caption_file(out + "/texts/000000.txt");
    ASSERT_EQ(texts.size(), 2u);
    EXPECT_TRUE(texts[0].whole_clip());
    EXPECT_EQ(read_caption_file(out + "/texts/M000000.txt")[0].caption, "a person walks slowly to the right");

    // The mirrored clip's features are those of the mirrored joints.
    const JointSequence walk = import_motion(mocap + "/bvh20/07_05.bvh");
    JointSequence mirror = walk;
    for (int f = 0; f < walk.num_frames; ++f)
        for (int j = 0; j < 22; ++j) {
            mirror.at(f, j) = walk.at(f, smpl22::kMirror[static_cast<size_t>(j)]);
            mirror.at(f, j).x() *= -1;
        }
    const std::vector<double> expected = feature_matrix_to_array(joints_to_features(mirror)).to<double>();
    const std::vector<double> got = read_npy(out + "/new_joint_vecs/M000000.npy").to<double>();
    ASSERT_EQ(got.size(), expected.size());
    for (size_t i = 0; i < got.size(); ++i) ASSERT_NEAR(got[i], expected[i], 1e-6);

    // The segment caption (frames 100-180) lands in the first salsa chunk with its times in seconds.
    bool found = false;
    for (const CaptionLine& l : read_caption_file(out + "/texts/000001.txt"))
        if (l.caption == "a dancer turns right") {
            found = true;
            EXPECT_DOUBLE_EQ(l.start_s, 5.0);
            EXPECT_DOUBLE_EQ(l.end_s, 9.0);
        }
    EXPECT_TRUE(found);

    // Subject-disjoint splits: every clip of one subject, mirrored ones too, is in one split.
    std::map<std::string, std::set<std::string>> splits_of_subject;
    for (const auto& row : clips.rows)
        splits_of_subject[row[clips.column("subject")]].insert(row[clips.column("split")]);
    for (const auto& [subject, splits] : splits_of_subject) EXPECT_EQ(splits.size(), 1u) << subject;

    // A second build gives the same bytes.
    BuildOptions again = o;
    again.out_dir = out + "2";
    build_dataset(again);
    EXPECT_EQ(read_npy(out + "/Std.npy").bytes, read_npy(out + "2/Std.npy").bytes);
    EXPECT_EQ(read_csv(out + "/clips.csv").rows, read_csv(out + "2/clips.csv").rows);
}

TEST(DatasetBuilder, LicenceFilterAndMissingFiles) {
    std::string manifest;
    SHARED_OR_SKIP(manifest, "mocap/manifest.csv");
    const std::string mocap = make_mocap_folder("builder_mocap_filter");
    std::ofstream(mocap + "/captions.csv", std::ios::app) << "bvh20/missing.bvh,0,50,ghost,99,CMU\n";
    BuildOptions o;
    o.mocap_dir = mocap;
    o.out_dir = test::scratch_dir("builder_filter") + "/set";
    const BuildSummary s = build_dataset(o);
    EXPECT_EQ(s.skipped_files, 1);  // reported, not fatal
    o.strict = true;
    EXPECT_THROW(build_dataset(o), Error);
    o.strict = false;
    o.licences = {"HDM05"};  // none of these clips
    EXPECT_THROW(build_dataset(o), Error);
    EXPECT_FALSE(std::filesystem::exists(o.out_dir + ".partial-" + std::to_string(getpid())));
    // What a killed build left (a process id no process has) goes with the next build.
    const std::string stale = o.out_dir + ".partial-999999999";
    std::filesystem::create_directories(stale + "/texts");
    o.licences.clear();
    build_dataset(o);
    EXPECT_FALSE(std::filesystem::exists(stale));
}

namespace {

// Frame g of the capture-rate copy that falls on 20 fps frame f of the clip, or -1 between them.
int capture_frame_at(int f, double fps, double start_s) {
    const double s = (f / 20.0 - start_s) * fps;
    return std::fabs(s - std::round(s)) < 1e-3 ? static_cast<int>(std::lround(s)) : -1;
}

// Checks the capture-rate copy of clips.csv row `row` of the set in `dir` against its new_joints: it starts at or
// up to one capture frame before the clip, ends at or up to one capture frame after it, and where a captured frame
// falls on a 20 fps frame both show the same pose at the same place, within `tolerance_m`. Returns the copy's rate.
double expect_copy_is_the_clip(const std::string& dir, const CsvTable& clips, const std::vector<std::string>& row,
                               double tolerance_m) {
    const std::string id = row[clips.column("id")], copy_path = dir + "/capture_joints/" + id + ".npy";
    const double fps = std::stod(row[clips.column("capture_fps")]),
                 start_s = std::stod(row[clips.column("capture_start_s")]);
    EXPECT_GT(start_s, -1 / fps - 1e-9) << id;
    EXPECT_LE(start_s, 1e-9) << id;
    const JointSequence joints = joint_sequence_from_array(read_npy(dir + "/new_joints/" + id + ".npy"), id, 22, 1, 20);
    const JointSequence copy = joint_sequence_from_array(read_npy(copy_path), copy_path, 22, 1, fps);
    EXPECT_GE(start_s + (copy.num_frames - 1) / fps, (joints.num_frames - 1) / 20.0 - 1e-6) << id;
    EXPECT_LT(start_s + (copy.num_frames - 1) / fps, (joints.num_frames - 1) / 20.0 + 1 / fps) << id;
    double worst = 0;
    int compared = 0;
    for (int f = 0; f < joints.num_frames; ++f) {
        const int g = capture_frame_at(f, fps, start_s);
        if (g < 0) continue;
        ++compared;
        for (int j = 0; j < 22; ++j) worst = std::max(worst, (joints.at(f, j) - copy.at(g, j)).norm());
    }
    EXPECT_GE(compared, 10) << id;
    EXPECT_LT(worst, tolerance_m) << id;
    return fps;
}

}  // namespace

TEST(DatasetBuilder, DerivedClipsCarryTheirProvenanceCountApartAndCanBeLeftOut) {
    // A forward walk (one staircase clip) and a 92 s idle recording (capped at 60 s of captured chunks; six
    // sit-down/stand-up clips), with the shared manifest's tags and licences.
    std::string manifest;
    SHARED_OR_SKIP(manifest, "mocap/manifest.csv");
    const std::string bandai = test::unpacked_shared_archive("mocap/bandai_bvh_native.tar.xz");
    const std::string idle = test::unpacked_shared_archive("mocap/reactidle_bvh.tar.xz");
    const std::string dir = test::scratch_dir("builder_derived");
    const std::vector<std::string> files = {"bandai_bvh/dataset-2_walk_normal_001.bvh",
                                            "reactidle_bvh/000_genuine.bvh"};
    const CsvTable shared = read_csv(manifest);
    CsvTable m;
    m.header = shared.header;
    for (const auto& row : shared.rows)
        if (std::find(files.begin(), files.end(), row[shared.column("file")]) != files.end()) m.rows.push_back(row);
    ASSERT_EQ(m.rows.size(), 2u);
    write_csv(dir + "/manifest.csv", m);
    std::ofstream captions(dir + "/captions.csv");
    captions << "file,start_frame,end_frame,caption\n";
    for (const std::string& f : files) {
        copy_into(dir, f[0] == 'b' ? bandai : idle, f);
        captions << f << ",0,100000," << (f[0] == 'b' ? "a person walks forward" : "a person stands idle") << "\n";
    }
    captions.close();
    BuildOptions o;
    o.mocap_dir = dir;
    o.out_dir = dir + "/set";
    build_dataset(o);
    const CsvTable clips = read_csv(o.out_dir + "/clips.csv");
    std::map<std::string, int> per_source;
    for (const auto& row : clips.rows) {
        ++per_source[row[clips.column("source_dataset")] + "/" + row[clips.column("activity_tags")]];
        if (row[clips.column("source_dataset")] != "edited") {
            EXPECT_TRUE(row[clips.column("provenance")].empty());
            continue;
        }
        const nlohmann::json p = nlohmann::json::parse(row[clips.column("provenance")]);
        EXPECT_TRUE(p["derived_from"] == files[0] || p["derived_from"] == files[1]) << p;
        EXPECT_TRUE(p.contains("parameters") && p.contains("seed") && p.contains("method")) << p;
        // Made at the capture rate (Bandai Namco 30 fps, ReActIdle 24), which the sensors' copy keeps.
        const double made_at = p["made_at_fps"].get<double>();
        EXPECT_NEAR(made_at, p["derived_from"] == files[0] ? 30 : 24, 0.01) << p;
        // The dataset's 20 fps clip is the derived one resampled (Catmull-Rom), whose bones are up to 0.1 % short
        // between captured frames; process_file scales the skeleton by its first frame's legs, so a chunk that
        // starts between captured frames is scaled by up to 1.001 (measured on a third of the shared set's derived
        // clips: at most 1.8 mm).
        EXPECT_NEAR(expect_copy_is_the_clip(o.out_dir, clips, row, 3e-3), made_at, 1e-6);
        for (const auto& source : m.rows)  // an edit is bound by its source clip's licence
            if (source[m.column("file")] == p["derived_from"]) {
                EXPECT_EQ(row[clips.column("licence")], source[m.column("licence")]);
            }
    }
    EXPECT_EQ(per_source["ReActIdle/standing"], 6);  // 92 s in 10 chunks, 60 s of them kept
    // Every window of the idle stand is a sitting clip or counted as left out (the idle person steps away in some).
    const nlohmann::json derived = nlohmann::json::parse(read_file_text(o.out_dir + "/summary.json"))["derived"];
    EXPECT_GE(per_source["edited/sitting"], 2);
    EXPECT_EQ(per_source["edited/sitting"] + derived["edits_refused"].get<int>() + derived["failed_quality"].get<int>(),
              kSitsPerRecording);
    std::set<std::string> stair_recordings;  // one flight, maybe cut into two chunks
    for (const auto& row : clips.rows)
        if (row[clips.column("activity_tags")].rfind("stairs", 0) == 0)
            stair_recordings.insert(row[clips.column("file")]);
    EXPECT_EQ(stair_recordings.size(), 1u);
    const nlohmann::json summary = nlohmann::json::parse(read_file_text(o.out_dir + "/summary.json"));
    EXPECT_GT(summary["per_activity_tag"]["sitting"]["derived_minutes"].get<double>(), 0.5);
    EXPECT_DOUBLE_EQ(summary["per_activity_tag"]["standing"]["derived_minutes"].get<double>(), 0.0);

    o.capture_rate = false;  // --no-capture-rate: derived at 20 fps, no copies
    build_dataset(o);
    for (const auto& row : read_csv(o.out_dir + "/clips.csv").rows) {
        EXPECT_TRUE(row[clips.column("capture_fps")].empty());
        if (!row[clips.column("provenance")].empty()) {
            EXPECT_DOUBLE_EQ(nlohmann::json::parse(row[clips.column("provenance")])["made_at_fps"].get<double>(), 20.0);
        }
    }

    o.derive = false;  // --no-derived
    build_dataset(o);
    for (const auto& row : read_csv(o.out_dir + "/clips.csv").rows)
        EXPECT_NE(row[clips.column("source_dataset")], "edited");
}

TEST(DatasetBuilder, CapturedClipsKeepTheirCaptureRateWhereNew_jointsAre) {
    // An HDM05 jog (120 fps, kept at 60), a Bandai Namco walk (30 fps) and a CMU walk (20 fps files: no copy).
    std::string manifest;
    SHARED_OR_SKIP(manifest, "mocap/manifest.csv");
    const std::string hdm = test::unpacked_shared_archive("mocap/hdm05_amc_native.tar.xz");
    const std::string bandai = test::unpacked_shared_archive("mocap/bandai_bvh_native.tar.xz");
    const std::string cmu = test::unpacked_shared_archive("mocap/cmu_daz_bvh_20fps.tar.xz");
    ASSERT_FALSE(hdm.empty() || bandai.empty() || cmu.empty());
    const std::string dir = test::scratch_dir("builder_capture_rate");
    const std::vector<std::pair<std::string, std::string>> files = {
        {hdm, "hdm05_amc/HDM_bd_jogLeftCircle4StepsRstart_001_120.amc"},
        {hdm, "hdm05_amc/HDM_bd.asf"},
        {bandai, "bandai_bvh/dataset-2_walk_normal_001.bvh"},
        {cmu, "bvh20/07_05.bvh"}};
    std::ofstream captions(dir + "/captions.csv");
    captions << "file,start_frame,end_frame,caption,subject,licence\n";
    for (const auto& [root, f] : files) {
        copy_into(dir, root, f);
        if (f.find(".asf") == std::string::npos) captions << f << ",0,100000,a person moves,s" << f.size() << ",test\n";
    }
    captions.close();
    BuildOptions o;
    o.mocap_dir = dir;
    o.out_dir = dir + "/set";
    o.mirror = true;
    o.derive = false;
    build_dataset(o);

    const CsvTable clips = read_csv(o.out_dir + "/clips.csv");
    std::map<int, int> copies_at;  // by capture rate, mirrored clips included
    for (const auto& row : clips.rows) {
        const std::string id = row[clips.column("id")], fps_text = row[clips.column("capture_fps")];
        const std::string copy_path = o.out_dir + "/capture_joints/" + id + ".npy";
        if (row[clips.column("file")].rfind("bvh20/", 0) == 0) {  // already 20 fps: nothing to keep
            EXPECT_TRUE(fps_text.empty());
            EXPECT_FALSE(fs::exists(copy_path));
            continue;
        }
        // Resampled from the same local poses as the 20 fps clip: equal to float32 rounding (measured: 6e-8 m).
        ++copies_at[static_cast<int>(std::lround(expect_copy_is_the_clip(o.out_dir, clips, row, 1e-5)))];
    }
    EXPECT_EQ(copies_at[60], 2);  // the jog and its mirror
    EXPECT_GE(copies_at[30], 2);
    EXPECT_EQ(copies_at.size(), 2u);
    const nlohmann::json summary = nlohmann::json::parse(read_file_text(o.out_dir + "/summary.json"));
    EXPECT_GT(summary["capture_rate"]["minutes"].get<double>(), 0.1);

    o.capture_rate = false;  // --no-capture-rate
    build_dataset(o);
    EXPECT_TRUE(fs::is_empty(o.out_dir + "/capture_joints"));
    for (const auto& row : read_csv(o.out_dir + "/clips.csv").rows)
        EXPECT_TRUE(row[clips.column("capture_fps")].empty());
}

// summary.json's train_draw_share counts what the loader draws: train clips of 40 to 199 frames, so a 13-frame hop
// (HDM05's single hops, 0.65 s) and a test clip are not in it.
TEST(DatasetBuilder, TrainDrawShareCountsOnlyClipsTheLoaderKeeps) {
    CsvTable clips;
    clips.header = {"activity_tags", "frames", "split"};
    clips.rows = {{"walking", "84", "train"},  {"jumping", "13", "train"}, {"jumping", "60", "train"},
                  {"jumping", "200", "train"}, {"walking", "40", "train"}, {"running", "90", "test"}};
    const nlohmann::json share = train_draw_share(clips);
    EXPECT_EQ(share.size(), 2u);
    EXPECT_DOUBLE_EQ(share["walking"].get<double>(), 2.0 / 3.0);
    EXPECT_DOUBLE_EQ(share["jumping"].get<double>(), 1.0 / 3.0);
}

TEST(DatasetBuilder, MeasuredCaptionsSayTheClipsMeasuredTurnAndAreTaggedInCaptionsCsv) {
    // 07_05 tagged walking by a manifest; three measured captions each, beside its two human ones. The mirror
    // is measured as mirrored: a turn named on one side in a clip is named on the other in its mirror.
    const std::string mocap = make_mocap_folder("builder_mocap_measured");
    if (mocap.empty()) GTEST_SKIP() << "shared data not found: mocap/cmu_daz_bvh_20fps.tar.xz";
    std::ofstream(mocap + "/manifest.csv") << "file,subject,source_dataset,licence,activity_tags\n"
                                              "bvh20/07_05.bvh,07,CMU,CMU,walking\n"
                                              "bvh20/60_01.bvh,60,CMU,CMU,dancing\n";
    BuildOptions o;
    o.mocap_dir = mocap;
    o.out_dir = test::scratch_dir("builder_measured") + "/set";
    o.mirror = true;
    o.measured_captions = 3;
    o.derive = false;  // the walk's derived staircase would be captioned too
    const BuildSummary s = build_dataset(o);
    const CsvTable captions = read_csv(o.out_dir + "/captions.csv");
    std::map<std::string, std::vector<std::string>> measured;
    int human = 0;
    for (const auto& row : captions.rows) {
        if (row[2] == "measured") measured[row[0]].push_back(row[1]);
        human += row[2] == "human";
    }
    EXPECT_EQ(static_cast<int>(captions.rows.size()), s.captions);
    EXPECT_EQ(measured.size(), 2u);  // the walk and its mirror; the dance gets none
    ASSERT_EQ(measured["000000"].size(), 3u);
    ASSERT_EQ(measured["M000000"].size(), 3u);
    EXPECT_EQ(read_caption_file(o.out_dir + "/texts/000000.txt").size(), 5u);
    EXPECT_EQ(human, s.captions - 6);
    const MotionAttributes a =
        measure_attributes(joint_sequence_from_array(read_npy(o.out_dir + "/new_joints/000000.npy"), "walk"));
    const MotionAttributes b =
        measure_attributes(joint_sequence_from_array(read_npy(o.out_dir + "/new_joints/M000000.npy"), "mirror"));
    EXPECT_NEAR(a.heading_change_deg, -b.heading_change_deg, 0.1);  // features of the mirror, recovered in float32
    EXPECT_NEAR(a.ground_speed_m_s, b.ground_speed_m_s, 1e-4);
    for (const std::string& c : measured["000000"]) {
        const bool says_left = c.find("left") != std::string::npos, says_right = c.find("right") != std::string::npos;
        EXPECT_FALSE(says_left && a.heading_change_deg < 0) << c;
        EXPECT_FALSE(says_right && a.heading_change_deg > 0) << c;
    }
    EXPECT_EQ(nlohmann::json::parse(s.json)["measured_captions"], 6);
}
