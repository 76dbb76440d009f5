// The main job end to end on a tiny model: a dataset the HAR loader accepts, resume that redoes only
// unfinished jobs, shards that add up to the whole run, refusal of a folder made with other settings, the
// quality filter, and the retrieval baseline.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "diffusion/trainer.hpp"
#include "imu/imu_dataset.hpp"
#include "imu/realism.hpp"
#include "imu/sensor_noise.hpp"
#include "motion/joint_sequence.hpp"
#include "motion/motion_activity.hpp"
#include "pipeline/synth.hpp"
#include "test_util.hpp"
#include "tiny_model.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {

struct TinySetup {
    std::string dir, data, model, prompts;
};

// Trains the tiny model once per test process (10 steps, about a second). ctest runs each test in its own
// process, several at once, so the folder is named after the test: a shared one would be wiped by a neighbour.
const TinySetup& tiny() {
    static const TinySetup s = [] {
        torch::set_num_threads(1);
        TinySetup t;
        const std::string test_name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        t.dir = test::scratch_dir("synth_model_" + test_name);
        t.data = test::make_tiny_motion_dataset(t.dir + "/data");
        t.model = t.dir + "/model";
        train_mdm(read_train_config(test::write_tiny_train_config(t.dir, t.data, t.model)), false, "", 10);
        t.prompts = t.dir + "/prompts.tsv";
        std::ofstream(t.prompts)
            << "# two activities\nwalking\ta person walks forward slowly\nrunning\tsomeone walks\n";
        return t;
    }();
    return s;
}

SynthOptions tiny_options(const std::string& out) {
    SynthOptions o;
    o.prompts = tiny().prompts;
    o.model = tiny().model;
    o.samples_per_prompt = 2;
    o.sampling.sampler = Sampler::dpmpp;
    o.sampling.steps = 5;
    o.sampling.seed = 11;
    o.sampling.batch = 3;
    o.seconds = 2;
    o.bodies = "preset:male_average+preset:female_short";
    o.sensors = "sisfall";
    o.filter = false;  // the tiny model's motions are not plausible; the filter has its own test
    o.out = out;
    return o;
}

std::string csv_of(const std::string& out, const std::string& job, const std::string& body) {
    return out + "/recordings/" + job + "/" + body + "/waist.csv";
}

// Largest difference between two recordings of the same length (m/s^2 or rad/s); +inf when the shapes differ.
// Jobs sampled in batches of other compositions agree up to float rounding of the batched products, which the
// second derivative of position amplifies to ~1e-5 m/s^2.
double max_difference(const std::string& a, const std::string& b) {
    const CsvTable x = read_csv(a), y = read_csv(b);
    if (x.rows.size() != y.rows.size() || x.header != y.header) return INFINITY;
    double worst = 0;
    for (size_t r = 0; r < x.rows.size(); ++r)
        for (size_t c = 0; c < x.header.size(); ++c)
            worst = std::max(worst, std::fabs(x.number(r, c) - y.number(r, c)));
    return worst;
}

}  // namespace

TEST(Synth, WritesAnImuDatasetWithItsMotions) {
    const std::string out = test::scratch_dir("synth_full");
    const nlohmann::json r = synth_report_json(run_synth(plan_synth(tiny_options(out))));
    EXPECT_EQ(r["jobs"], 4);
    EXPECT_EQ(r["motions_kept"], 4);
    const std::vector<ImuRecording> recs = read_imu_dataset(out);  // loads and checks every CSV
    ASSERT_EQ(recs.size(), 8u);                                    // 2 prompts x 2 samples x 2 bodies x 1 sensor
    int walking = 0;
    for (const ImuRecording& rec : recs) {
        EXPECT_EQ(rec.dataset, "t2imu");
        EXPECT_EQ(rec.position, "waist");
        EXPECT_EQ(rec.subject, rec.extra.at("body"));
        EXPECT_DOUBLE_EQ(rec.rate_hz, 50);
        EXPECT_EQ(rec.t.size(), 98u);  // 40 frames at 20 fps span 1.95 s: samples at 0, 0.02, ..., 1.94 s
        walking += rec.activity == "walking";
        if (rec.activity == "walking") {
            EXPECT_EQ(rec.extra.at("prompt"), "a person walks forward slowly");
        }
    }
    EXPECT_EQ(walking, 4);
    // Job k draws from seed + k; the motion and its BVH are kept.
    const nlohmann::json j3 = nlohmann::json::parse(read_file_text(out + "/jobs/j00003.json"));
    EXPECT_EQ(j3["seed"], 14);
    EXPECT_EQ(j3["activity"], "running");
    EXPECT_EQ(j3["sample"], 1);
    EXPECT_EQ(read_npy(out + "/motions/j00003_joints.npy").shape, (std::vector<int64_t>{40, 22, 3}));
    EXPECT_TRUE(fs::exists(out + "/motions/j00003.bvh"));
}

TEST(Synth, APromptTheCaptionsDoNotCoverIsRecordedAndOnRequestRefusedBeforeAnyOutput) {
    // The tiny model's captions are walking ones ("a person walks forward slowly"): ironing is an activity they lack.
    const std::string dir = test::scratch_dir("synth_coverage");
    SynthOptions o = tiny_options(dir + "/out");
    o.prompts = dir + "/prompts.tsv";
    o.samples_per_prompt = 1;
    std::ofstream(o.prompts) << "walking\ta person walks forward slowly\nironing\tsomeone irons a shirt\n";
    run_synth(plan_synth(o));
    const std::vector<JobMarker> markers = read_job_markers(o.out);
    ASSERT_EQ(markers.size(), 2u);
    ASSERT_TRUE(markers[0].coverage && markers[1].coverage);
    EXPECT_TRUE(markers[0].coverage->covered);
    EXPECT_EQ(markers[0].coverage->nearest.front(), "a person walks forward slowly");
    EXPECT_FALSE(markers[1].coverage->covered);
    EXPECT_EQ(markers[1].coverage->summary, "activity 'ironing' has no training captions");
    SynthOptions strict = o;
    strict.out = dir + "/strict";
    strict.require_coverage = true;
    try {
        run_synth(plan_synth(strict));
        ADD_FAILURE() << "an uncovered prompt was accepted with require_coverage";
    } catch (const Error& e) {
        EXPECT_TRUE(test::contains(e.what(), "prompt 2")) << e.what();
        EXPECT_TRUE(test::contains(e.what(), "--require-coverage")) << e.what();
    }
    EXPECT_FALSE(fs::exists(strict.out));
}

TEST(Synth, ResumeRedoesOnlyUnfinishedJobs) {
    const std::string out = test::scratch_dir("synth_resume");
    run_synth(plan_synth(tiny_options(out)));
    const std::string before = test::scratch_dir("synth_resume_before") + "/waist.csv";
    fs::copy_file(csv_of(out, "j00002", "female_short"), before);
    const auto untouched = fs::last_write_time(csv_of(out, "j00001", "male_average"));
    fs::remove(out + "/jobs/j00002.json");  // as if killed before job 2 finished
    fs::remove(csv_of(out, "j00002", "female_short"));
    const std::string temporary =
        fs::path(csv_of(out, "j00002", "male_average")).parent_path().string() + "/.waist.csv.tmp999999999";
    std::ofstream(temporary) << "t,acc_x\n0,";  // a write the kill cut short
    const nlohmann::json r = synth_report_json(run_synth(plan_synth(tiny_options(out))));
    EXPECT_EQ(r["this_run"]["jobs_run"], 1);
    // Redone in its own batch (jobs 0-2, drawn whole), so with the very bytes of the uninterrupted run.
    EXPECT_EQ(read_file_text(csv_of(out, "j00002", "female_short")), read_file_text(before));
    EXPECT_FALSE(fs::exists(temporary));
    EXPECT_EQ(fs::last_write_time(csv_of(out, "j00001", "male_average")), untouched);
    EXPECT_EQ(read_imu_dataset(out, false).size(), 8u);
}

TEST(Synth, ResumeRedoesFinishedJobsWhoseFilesWentMissingOrWereCut) {
    const std::string out = test::scratch_dir("synth_resume_damaged");
    SynthOptions o = tiny_options(out);
    o.bodies = "preset:male_average";
    run_synth(plan_synth(o));
    const std::string cut = csv_of(out, "j00001", "male_average");
    const std::string before = test::scratch_dir("synth_resume_damaged_before") + "/waist.csv";
    fs::copy_file(cut, before);
    fs::resize_file(cut, fs::file_size(cut) / 2);       // a copy that broke off
    fs::remove(csv_of(out, "j00002", "male_average"));  // a lost file
    const auto untouched = fs::last_write_time(csv_of(out, "j00003", "male_average"));
    const nlohmann::json r = synth_report_json(run_synth(plan_synth(o)));
    EXPECT_EQ(r["this_run"]["jobs_run"], 2);
    EXPECT_EQ(read_file_text(cut), read_file_text(before));  // redone in its own batch: the same bytes
    EXPECT_TRUE(fs::exists(csv_of(out, "j00002", "male_average")));
    EXPECT_EQ(fs::last_write_time(csv_of(out, "j00003", "male_average")), untouched);
    EXPECT_EQ(read_imu_dataset(out).size(), 4u);
}

TEST(Synth, ResumeRedoesJobsWhoseMotionOrMarkerWasDamagedAndNamesABadSettingsFile) {
    const std::string out = test::scratch_dir("synth_resume_motions");
    SynthOptions o = tiny_options(out);
    o.bodies = "preset:male_average";
    run_synth(plan_synth(o));
    fs::remove(out + "/motions/j00000.bvh");  // deleted by hand
    fs::resize_file(out + "/motions/j00001_joints.npy",
                    fs::file_size(out + "/motions/j00001_joints.npy") - 8);      // cut short
    std::ofstream(out + "/jobs/j00002.json") << "{\"job\": \"j00002\", \"kept";  // a marker cut short
    const auto untouched = fs::last_write_time(out + "/motions/j00003.bvh");
    EXPECT_EQ(run_synth(plan_synth(o)).this_run.jobs_run, 3);
    EXPECT_TRUE(fs::exists(out + "/motions/j00000.bvh"));
    EXPECT_EQ(read_npy(out + "/motions/j00001_joints.npy").shape[1], 22);
    EXPECT_EQ(fs::last_write_time(out + "/motions/j00003.bvh"), untouched);
    // A marker of another shard's job is not redone here: read for the manifest, its fault is named.
    std::ofstream(out + "/jobs/j00009.json") << R"({"job": 5})";
    try {
        run_synth(plan_synth(o));
        FAIL() << "a damaged marker was read";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("j00009.json: job: expected a string"), std::string::npos) << e.what();
    }
    fs::remove(out + "/jobs/j00009.json");
    std::ofstream(out + "/synth.json") << "{\"seed\": ";
    try {
        run_synth(plan_synth(o));
        FAIL() << "a damaged synth.json was read";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("synth.json: json: expected a JSON document (got parse error at line 1"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Synth, ShardsAddUpToTheWholeRun) {
    const std::string whole = test::scratch_dir("synth_whole"), sharded = test::scratch_dir("synth_sharded");
    run_synth(plan_synth(tiny_options(whole)));
    for (int i = 0; i < 2; ++i) {
        SynthOptions o = tiny_options(sharded);
        o.shard = i;
        o.shards = 2;
        EXPECT_EQ(run_synth(plan_synth(o)).this_run.jobs_run, 2);
    }
    const nlohmann::json merged =
        synth_report_json(run_synth(plan_synth(tiny_options(sharded))));  // nothing left to do: rebuilds the manifest
    EXPECT_EQ(merged["this_run"]["jobs_run"], 0);
    EXPECT_EQ(read_file_text(sharded + "/manifest.csv"), read_file_text(whole + "/manifest.csv"));
    for (const char* job : {"j00000", "j00003"})
        EXPECT_LT(max_difference(csv_of(sharded, job, "male_average"), csv_of(whole, job, "male_average")), 1e-3)
            << job;
    // The same run twice gives the same bytes.
    const std::string again = test::scratch_dir("synth_whole_again");
    run_synth(plan_synth(tiny_options(again)));
    EXPECT_TRUE(read_file_bytes(csv_of(again, "j00003", "female_short")) ==
                read_file_bytes(csv_of(whole, "j00003", "female_short")));
}

TEST(Synth, RefusesAFolderMadeWithOtherSettings) {
    const std::string out = test::scratch_dir("synth_settings");
    SynthOptions o = tiny_options(out);
    o.samples_per_prompt = 1;
    run_synth(plan_synth(o));
    o.seconds = 3;
    try {
        run_synth(plan_synth(o));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("seconds"), std::string::npos) << e.what();
    }
    o.seconds = 2;
    o.shard = 0;
    o.shards = 3;  // a shard of the same synthesis is welcome
    EXPECT_NO_THROW(run_synth(plan_synth(o)));
    o.shards = 1;
    // A folder from when the sensor model had an option of its own ("noise" in synth.json) resumes when it said
    // none, and is refused when it named a sensor model.
    const std::string settings_path = out + "/synth.json";
    nlohmann::json settings = nlohmann::json::parse(read_file_text(settings_path));
    settings["noise"] = "none";
    write_file_atomic(settings_path, settings.dump(1));
    EXPECT_NO_THROW(run_synth(plan_synth(o)));
    settings["noise"] = "smartphone";
    write_file_atomic(settings_path, settings.dump(1));
    EXPECT_TRUE(test::contains(test::error_message([&] { run_synth(plan_synth(o)); }), "noise"));
    settings.erase("noise");
    write_file_atomic(settings_path, settings.dump(1));
    o.realism = "sisfall";  // so is another sensor realism model: refused like any other setting
    EXPECT_THROW(run_synth(plan_synth(o)), Error);
}

TEST(Synth, RecordsTheRealismModelAndEachRecordingsDraws) {
    const std::string out = test::scratch_dir("synth_realism");
    SynthOptions o = tiny_options(out);
    o.samples_per_prompt = 1;
    o.filter = false;  // every motion kept, so every job has recordings
    o.realism = "sisfall";
    const int64_t realism_parses = realism_parse_count(), sensor_parses = noise_model_parse_count();
    const nlohmann::json report = synth_report_json(run_synth(plan_synth(o)));
    // The realism spelling and its sensor model's are parsed once for the whole job (2 jobs x 2 bodies x 3 sensors).
    EXPECT_EQ(realism_parse_count() - realism_parses, 1);
    EXPECT_EQ(noise_model_parse_count() - sensor_parses, 1);
    EXPECT_EQ(report["realism"]["name"], "sisfall");
    EXPECT_EQ(report["realism"]["tilt_deg"], 7.5);
    size_t recordings = 0;
    for (const auto& e : fs::directory_iterator(out + "/jobs")) {
        const nlohmann::json marker = nlohmann::json::parse(read_file_text(e.path().string()));
        for (const nlohmann::json& r : marker["recordings"]) {
            EXPECT_EQ(r["tempo"], 1.0);  // the preset plays motions at their own tempo
            EXPECT_TRUE(r["tilt_deg"].is_number());
            ++recordings;
        }
    }
    EXPECT_GT(recordings, 0u);
    // A folder recorded before a lever existed (its keys absent) resumes while that lever stays off...
    const std::string settings_path = out + "/synth.json";
    nlohmann::json settings = nlohmann::json::parse(read_file_text(settings_path));
    settings["realism"].erase("strap_hz");
    settings["realism"].erase("strap_damping");
    std::ofstream(settings_path) << settings.dump(1);
    EXPECT_NO_THROW(run_synth(plan_synth(o)));
    // ...and is refused when this run turns it on: absent reads as off.
    const std::string strap = out + "_strap.toml";
    std::ofstream(strap) << "base = \"sisfall\"\nstrap_hz = 6\nstrap_damping = 0.25\n";
    const std::string strap_out = test::scratch_dir("synth_realism_strap");
    o.out = strap_out;
    o.realism = strap;
    run_synth(plan_synth(o));
    settings = nlohmann::json::parse(read_file_text(strap_out + "/synth.json"));
    settings["realism"].erase("strap_hz");
    settings["realism"].erase("strap_damping");
    std::ofstream(strap_out + "/synth.json") << settings.dump(1);
    try {
        run_synth(plan_synth(o));
        FAIL() << "a strap asked for, none recorded: expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("realism"), std::string::npos) << e.what();
    }
}

// The plan is made once at the door and holds every parsed spelling: the prompt set and a realism file can go
// before the run, which reads neither; a bad value of each kind is refused by plan_synth, naming it, before any
// folder exists.
TEST(Synth, ThePlanHoldsEverySpellingParsedAndRefusesBadOnesBeforeAnyFolder) {
    const std::string dir = test::scratch_dir("synth_plan");
    const std::string out = dir + "/out", prompts = dir + "/prompts.tsv", realism = dir + "/r.toml";
    fs::copy_file(tiny().prompts, prompts);
    std::ofstream(realism) << "base = \"sisfall\"\nsensor = \"sisfall,bits=0\"\n";
    SynthOptions o = tiny_options(out);
    o.prompts = prompts;
    o.realism = realism;
    const SynthPlan plan = plan_synth(o);
    EXPECT_EQ(plan.prompts.size(), 2u);
    EXPECT_EQ(plan.bodies.size(), 2u);
    EXPECT_EQ(plan.frames, 40);  // 2 s at 20 fps
    EXPECT_EQ(plan.imu.sensor_model().name, "sisfall");
    EXPECT_EQ(plan.imu.sensor_model().bits, 0);
    EXPECT_EQ(std::get<ModelFolderSpec>(plan.source).folder, tiny().model);
    fs::remove(prompts);
    fs::remove(realism);
    EXPECT_EQ(synth_report_json(run_synth(plan))["jobs_done"], 4);
    const nlohmann::json settings = nlohmann::json::parse(read_file_text(out + "/synth.json"));
    EXPECT_EQ(settings["realism"]["sensor"], "sisfall,bits=0");

    const std::vector<std::pair<std::function<void(SynthOptions&)>, std::string>> bad = {
        {[](SynthOptions& x) { x.model = "hybrid:m,d,2"; }, "--model"},
        {[](SynthOptions& x) { x.bodies = "preset:nobody"; }, "preset"},
        {[](SynthOptions& x) { x.sensors = "nowhere"; }, "nowhere"},
        {[](SynthOptions& x) { x.realism = "sisfal"; }, "sisfal"},
        {[](SynthOptions& x) { x.realism = "sisfall+sensor=smartphone,bitz=3"; }, "bitz"},
        {[](SynthOptions& x) { x.prompts = "no-such-prompts.tsv"; }, "no-such-prompts.tsv"},
        {[](SynthOptions& x) { x.seconds = 0; }, "--seconds"},
        {[](SynthOptions& x) { x.rate_hz = -1; }, "--rate"},
        {[](SynthOptions& x) { x.max_retries = -1; }, "--retries"},
    };
    for (const auto& [spoil, named] : bad) {
        SynthOptions x = tiny_options(dir + "/never");
        spoil(x);
        const std::string message = test::error_message([&] { plan_synth(x); });
        EXPECT_TRUE(test::contains(message, named)) << named << ": " << message;
        EXPECT_FALSE(fs::exists(dir + "/never"));
    }
}

TEST(Synth, RetrievalGivesCapturedMotionThatPassesTheFilter) {
    const std::string out = test::scratch_dir("synth_retrieval");
    SynthOptions o = tiny_options(out);
    o.model = "retrieval:" + tiny().data;
    o.vocab = tiny().data + "/vocab.safetensors";
    o.filter = true;
    const nlohmann::json r = synth_report_json(run_synth(plan_synth(o)));
    EXPECT_EQ(r["motions_kept"], 4);
    EXPECT_EQ(r["jobs_regenerated"], 0);
    // A slow captured walk: its fastest joint and worst skating are far inside the thresholds.
    EXPECT_LT(r["quality_median"]["max_speed_m_s"].get<double>(), 5.0);
    EXPECT_LT(r["quality_median"]["foot_skate_m_s"].get<double>(), 0.5);
    // The clips are 60 frames; time-warped by at most 10 % and cropped to the 40 asked for.
    EXPECT_EQ(read_npy(out + "/motions/j00000_joints.npy").shape, (std::vector<int64_t>{40, 22, 3}));
}

// capture_rate (on by default): the sensors see the retrieved clip's capture-rate copy (here 60 fps, the clip's frames
// joined by Catmull-Rom curves: test::add_capture_copies), recorded in synth.json and each marker; the recordings keep
// their rate and length, and differ from the 20 fps ones (the same motion, sampled otherwise) by less than the signal.
TEST(Synth, CaptureRateCopiesReachTheSensors) {
    const std::string data = test::scratch_dir("synth_capture_rate_data");
    fs::remove_all(data);
    fs::copy(tiny().data, data, fs::copy_options::recursive);
    test::add_capture_copies(data, {"c0", "c1", "c2", "c3", "c4", "c5"});
    const std::string out20 = test::scratch_dir("synth_capture_rate_20"),
                      out60 = test::scratch_dir("synth_capture_rate_60");
    SynthOptions o = tiny_options(out20);
    o.model = "retrieval:" + data;
    o.vocab = data + "/vocab.safetensors";
    o.capture_rate = false;
    run_synth(plan_synth(o));
    o.out = out60;
    o.capture_rate = true;
    run_synth(plan_synth(o));
    const nlohmann::json settings = nlohmann::json::parse(read_file_text(out60 + "/synth.json"));
    EXPECT_TRUE(settings["capture_rate"].get<bool>());
    EXPECT_FALSE(nlohmann::json::parse(read_file_text(out20 + "/synth.json")).contains("capture_rate"));
    for (const char* job : {"j00000", "j00003"}) {
        const nlohmann::json m60 = nlohmann::json::parse(read_file_text(out60 + "/jobs/" + job + ".json"));
        const nlohmann::json m20 = nlohmann::json::parse(read_file_text(out20 + "/jobs/" + job + ".json"));
        EXPECT_DOUBLE_EQ(m60["sensor_motion_fps"].get<double>(), 60);
        EXPECT_FALSE(m20.contains("sensor_motion_fps"));
        EXPECT_EQ(m60["source_draw"], m20["source_draw"]);
        const CsvTable a = read_csv(csv_of(out20, job, "male_average")),
                       b = read_csv(csv_of(out60, job, "male_average"));
        ASSERT_EQ(a.rows.size(), b.rows.size());
        double diff = 0, signal = 0;  // vertical acceleration (SisFall's y): rms of the difference and of the signal
        for (size_t r = 0; r < a.rows.size(); ++r) {
            diff += std::pow(a.number(r, a.column("acc_y")) - b.number(r, b.column("acc_y")), 2);
            signal += std::pow(a.number(r, a.column("acc_y")) - a.number(0, a.column("acc_y")), 2);
        }
        EXPECT_GT(diff, 0) << job;
        EXPECT_LT(diff, 0.5 * signal) << job;
    }
    // A resume that asks for the other rate is refused: the folder holds one synthesis.
    o.capture_rate = false;
    EXPECT_THROW(run_synth(plan_synth(o)), Error);
}

TEST(Synth, FilterRegeneratesThenDropsWhatNeverPasses) {
    const std::string out = test::scratch_dir("synth_filter");
    SynthOptions o = tiny_options(out);
    o.samples_per_prompt = 1;
    o.filter = true;
    o.max_retries = 1;
    o.thresholds = {0, 0, 0, 0, 0, 0};  // every motion moves, so every attempt fails
    const nlohmann::json r = synth_report_json(run_synth(plan_synth(o)));
    EXPECT_EQ(r["motions_dropped"], 2);
    EXPECT_EQ(r["jobs_regenerated"], 2);
    const nlohmann::json j = nlohmann::json::parse(read_file_text(out + "/jobs/j00001.json"));
    ASSERT_EQ(j["attempts"].size(), 2u);
    EXPECT_EQ(j["attempts"][1]["seed"], 11 + 1 + kSeedStridePerAttempt);
    EXPECT_FALSE(j["kept"].get<bool>());
    EXPECT_TRUE(read_imu_dataset(out, false).empty());
}

TEST(Synth, CommandLineRunsAndRefusesABadShard) {
    const std::string out = test::scratch_dir("synth_cli");
    const auto bad =
        test::run_cli("synth --prompts " + tiny().prompts + " --model " + tiny().model + " --shard 3/2 --out " + out);
    EXPECT_NE(bad.exit_code, 0);
    EXPECT_NE(bad.output.find("--shard"), std::string::npos) << bad.output;
    const auto ok =
        test::run_cli("--threads 1 synth --prompts " + tiny().prompts + " --model " + tiny().model +
                      " --steps 3 --seconds 1 --bodies preset:male_tall --sensors umafall --no-filter --out " + out);
    ASSERT_EQ(ok.exit_code, 0) << ok.output;
    EXPECT_EQ(read_imu_dataset(out, true).size(), 8u);  // 2 jobs x 1 body x 4 UMAFall sensors
    // The flags of pipeline/synth_keys.hpp reach the options: --no-filter turns the filter off.
    const nlohmann::json settings = nlohmann::json::parse(read_file_text(out + "/synth.json"));
    EXPECT_EQ(settings.at("filter"), false);
    EXPECT_EQ(settings.at("source").at("steps"), 3) << settings.dump();
}

TEST(Synth, ActivityCheckKeepsTheBestDrawOrDropsMotionsThatShowAnotherActivity) {
    // Both prompts retrieve the tiny set's slow walk. The reference says walking looks like those very
    // motions and running like them shifted by 10 units in every descriptor, so the walking prompt's motions
    // agree fully with their activity and the running prompt's still walk after every redraw: by default they
    // keep their best-agreeing draw, with --drop-activity-failures they are dropped.
    const std::string dir = test::scratch_dir("synth_activity");
    SynthOptions o = tiny_options(dir + "/unchecked");
    o.model = "retrieval:" + tiny().data;
    o.vocab = tiny().data + "/vocab.safetensors";
    o.filter = true;
    o.max_retries = 2;
    run_synth(plan_synth(o));
    std::vector<ActivityExample> reference;
    for (int k = 0; k < 4; ++k) {
        const std::string file = o.out + "/motions/j0000" + std::to_string(k) + "_joints.npy";
        const MotionDescriptors d = describe_motion(joint_sequence_from_array(read_npy(file), file));
        MotionDescriptors far = d;
        for (double& x : far) x += 10;
        reference.push_back({"walking", "w" + std::to_string(k), d});
        reference.push_back({"running", "r" + std::to_string(k), far});
    }
    o.activity_reference = dir + "/reference.csv";
    write_csv(o.activity_reference, MotionActivityClassifier(reference).reference_table());

    o.out = dir + "/kept";
    const nlohmann::json kept = synth_report_json(run_synth(plan_synth(o)));
    EXPECT_EQ(kept["motions_kept"], 4);
    EXPECT_EQ(kept["motions_kept_below_activity_agreement"], 2);
    EXPECT_EQ(kept["per_activity"]["walking"]["shown"], nlohmann::json({{"walking", 2}}));
    EXPECT_EQ(kept["per_activity"]["running"]["shown"], nlohmann::json({{"walking", 2}}));
    const nlohmann::json walk = nlohmann::json::parse(read_file_text(o.out + "/jobs/j00000.json"));
    EXPECT_EQ(walk["activity_check"]["shown"], "walking");
    EXPECT_DOUBLE_EQ(walk["activity_check"]["agreement"].get<double>(), 1.0);
    EXPECT_TRUE(walk["activity_check"]["passed"].get<bool>());
    for (const char* job : {"j00002", "j00003"}) {
        const nlohmann::json run = nlohmann::json::parse(read_file_text(o.out + "/jobs/" + job + ".json"));
        EXPECT_TRUE(run["kept"].get<bool>());
        EXPECT_FALSE(run["activity_check"]["passed"].get<bool>());
        ASSERT_EQ(run["attempts"].size(), static_cast<size_t>(o.max_retries + 1));  // every draw spent
        double best = -1;
        uint64_t best_seed = 0;
        for (const auto& attempt : run["attempts"]) {
            EXPECT_EQ(attempt["failures"], nlohmann::json::array({"activity"}));
            if (attempt["activity_agreement"].get<double>() > best) {
                best = attempt["activity_agreement"].get<double>();
                best_seed = attempt["seed"].get<uint64_t>();
            }
        }
        EXPECT_LT(best, o.min_activity_agreement);
        EXPECT_EQ(run["seed"].get<uint64_t>(), best_seed);
        EXPECT_DOUBLE_EQ(run["activity_check"]["agreement"].get<double>(), best);
        EXPECT_EQ(run["recordings"].size(), walk["recordings"].size());
    }

    o.out = dir + "/dropped";
    o.drop_activity_failures = true;
    const nlohmann::json dropped = synth_report_json(run_synth(plan_synth(o)));
    EXPECT_EQ(dropped["motions_kept"], 2);
    EXPECT_EQ(dropped["motions_dropped"], 2);
    EXPECT_EQ(dropped["motions_kept_below_activity_agreement"], 0);
    const nlohmann::json run = nlohmann::json::parse(read_file_text(o.out + "/jobs/j00002.json"));
    EXPECT_FALSE(run["kept"].get<bool>());
    EXPECT_EQ(run["activity_check"]["shown"], "walking");
    EXPECT_LT(run["activity_check"]["agreement"].get<double>(), o.min_activity_agreement);
    EXPECT_TRUE(run["recordings"].empty());
}
