// The synthesis folder's schema (imu/synth_folder): a job marker and a synthesis report read back as written,
// to the byte; markers from before a field existed read with the stated defaults; a broken field is refused by its
// dotted key.
#include <gtest/gtest.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "imu/synth_folder.hpp"
#include "test_util.hpp"

using namespace t2imu;
using nlohmann::json;

namespace {

// A marker as t2imu synth writes one for a kept job with an activity check, a retrieval draw, the capture rate and
// a prompt the source's captions do not cover.
const char* kMarker = R"({
 "activity": "walking",
 "activity_check": {"agreement": 0.8, "passed": true, "shown": "walking"},
 "attempts": [{"activity_agreement": 0.3, "failures": ["activity"], "seed": 7}, {"activity_agreement": 0.8, "failures": [], "seed": 1007}],
 "coverage": {"covered": false, "nearest": ["a person walks forward"], "similarity": [0.75], "summary": "the training captions of 'walking' never name: pace_slow",
              "uncovered": ["pace_slow"]},
 "frames": 120,
 "index": 7,
 "job": "j00007",
 "kept": true,
 "motions": [{"bytes": 8768, "path": "motions/j00007_joints.npy"}, {"bytes": 30561, "path": "motions/j00007.bvh"}],
 "prompt": "A person walks.",
 "quality": {"foot_skating": 0.12, "jerk": 3.5},
 "recordings": [{"body": "male_average", "bytes": 20013, "n_samples": 300, "path": "recordings/j00007/male_average/waist.csv",
                 "position": "waist", "tempo": 1.0, "tilt_deg": 4.25}],
 "sample": 1,
 "seed": 1007,
 "sensor_motion_fps": 30.0,
 "source_draw": {"clip": "walk_03", "tags_show_activity": true}
})";

}  // namespace

TEST(SynthFolder, AJobMarkerReadsBackAsWrittenToTheByte) {
    const json doc = json::parse(kMarker);
    const JobMarker m = parse_job_marker(doc, "m.json");
    EXPECT_EQ(m.job, "j00007");
    EXPECT_EQ(m.index, 7);
    ASSERT_EQ(m.attempts.size(), 2u);
    EXPECT_EQ(m.attempts[0].failures, (std::vector<std::string>{"activity"}));
    EXPECT_EQ(*m.attempts[1].activity_agreement, 0.8);
    ASSERT_EQ(m.recordings.size(), 1u);
    EXPECT_EQ(m.recordings[0].mount_tilt_deg, 4.25);
    EXPECT_EQ(m.recordings[0].bytes, 20013);
    ASSERT_TRUE(m.motions && m.activity_check && m.sensor_motion_fps);
    EXPECT_EQ(m.motions->at(1).path, "motions/j00007.bvh");
    EXPECT_EQ(m.activity_check->shown, "walking");
    ASSERT_TRUE(m.coverage);
    EXPECT_FALSE(m.coverage->covered);
    EXPECT_EQ(m.coverage->uncovered, (std::vector<std::string>{"pace_slow"}));
    EXPECT_EQ(m.coverage->similarity, (std::vector<double>{0.75}));
    EXPECT_EQ(job_marker_json(m).dump(1), doc.dump(1));
    // Through a folder: jobs/<job>.json, and read_job_markers in job order.
    const std::string dir = test::scratch_dir("synth_folder");
    JobMarker second = m;
    second.job = "j00002";
    write_job_marker(dir, m);
    write_job_marker(dir, second);
    const std::vector<JobMarker> back = read_job_markers(dir);
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back[0].job, "j00002");
    EXPECT_EQ(job_marker_json(back[1]), doc);
    EXPECT_TRUE(read_job_markers(dir + "/absent").empty());
}

TEST(SynthFolder, AJobsFilesAreNamedInOnePlace) {
    EXPECT_EQ(job_name(7), "j00007");
    EXPECT_EQ(job_name(123456), "j123456");
    EXPECT_EQ(job_joints_file(job_name(7)), "motions/j00007_joints.npy");
    EXPECT_EQ(job_bvh_file("j00007"), "motions/j00007.bvh");
    EXPECT_EQ(job_recordings_dir("j00007"), "recordings/j00007");
    EXPECT_EQ(job_marker_path("out", "j00007"), "out/jobs/j00007.json");
    // The marker fixture above lists the motion files under these names.
    const JobMarker m = parse_job_marker(json::parse(kMarker), "m.json");
    EXPECT_EQ(m.motions->at(0).path, job_joints_file(m.job));
    EXPECT_EQ(m.motions->at(1).path, job_bvh_file(m.job));
}

TEST(SynthFolder, AnOlderMarkerReadsWithTheStatedDefaults) {
    // Before index, sample, frames, file sizes and the realism draws were recorded.
    const json old = json::parse(R"({"job": "j00001", "prompt": "p", "activity": "running", "seed": 1, "kept": false,
                                     "attempts": [{"seed": 1, "failures": ["jerk"]}], "quality": {"jerk": 9},
                                     "recordings": [{"path": "r.csv", "body": "b", "position": "waist", "n_samples": 5}]})");
    const JobMarker m = parse_job_marker(old, "old.json");
    EXPECT_EQ(m.index, -1);
    EXPECT_EQ(m.frames, -1);
    EXPECT_EQ(m.recordings[0].bytes, -1);
    EXPECT_EQ(m.recordings[0].tempo, 1);
    EXPECT_FALSE(m.coverage);  // recorded since prompts are checked against the source's captions
    EXPECT_EQ(m.recordings[0].mount_tilt_deg, 0);
    EXPECT_FALSE(m.motions || m.activity_check || m.sensor_motion_fps);
    EXPECT_TRUE(m.source_draw.is_null());
    const json back = job_marker_json(m);  // fields not recorded stay absent
    EXPECT_FALSE(back.contains("index") || back["recordings"][0].contains("bytes"));
}

TEST(SynthFolder, ABrokenFieldIsRefusedByItsDottedKey) {
    const std::pair<const char*, const char*> cases[] = {
        {R"("n_samples": 300)", R"("n_samples": "many")"},
        {R"("kept": true)", R"("kept": 1)"},
        {R"("failures": ["activity"])", R"("failures": [3])"},
        {R"("jerk": 3.5)", R"("jerk": "high")"},
        {R"("shown": "walking")", R"("shown": 2)"},
        {R"("job": "j00007",)", ""},
    };
    const std::string keys[] = {"recordings.0.n_samples", "kept", "attempts.0.failures", "quality.jerk",
                                "activity_check.shown",   "job"};
    for (size_t i = 0; i < std::size(cases); ++i) {
        std::string text = kMarker;
        text.replace(text.find(cases[i].first), std::string(cases[i].first).size(), cases[i].second);
        const std::string e = test::error_message([&] { parse_job_marker(json::parse(text), "broken.json"); });
        EXPECT_TRUE(test::contains(e, "broken.json: " + keys[i])) << keys[i] << ": " << e;
    }
}

TEST(SynthFolder, ASynthesisReportReadsBackAsWritten) {
    SynthReport r;
    r.jobs = 4, r.jobs_done = 3, r.motions_kept = 2, r.motions_dropped = 1, r.motions_kept_below_activity_agreement = 1;
    r.jobs_regenerated = 1, r.recordings = 14;
    r.per_activity["walking"] = {2, 1, 0, {{"walking", 1}, {"sitting", 1}}, 1, 2};
    r.per_activity["running"] = {0, 0, 1, {}, std::nullopt, std::nullopt};
    r.failed_attempts_by_score = {{"jerk", 2}};
    r.quality_median = {{"jerk", 3.25}};
    r.this_run = {3, 2, 0.5, 10.25, 0.125, 2.5, 0.0625, 13.5, "cpu"};
    r.realism = {{"name", "sisfall"}};
    const std::string dir = test::scratch_dir("synth_folder_report");
    write_synth_report(dir, r);
    const SynthReport back = read_synth_report(dir);
    EXPECT_EQ(synth_report_json(back), synth_report_json(r));
    EXPECT_FALSE(synth_report_json(back)["per_activity"]["running"].contains("shown"));  // no activity check there
    EXPECT_EQ(back.per_activity.at("walking").shows_activity_by_tags, 2);
    EXPECT_EQ(back.this_run.device, "cpu");
    write_file_atomic(dir + "/synth_report.json", R"({"jobs": 1})");
    EXPECT_TRUE(test::contains(test::error_message([&] { read_synth_report(dir); }), "synth_report.json: jobs_done"));
}
