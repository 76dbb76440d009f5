// scripts/train-default.sh, run for real on the tiny training set: its trainings in order (the base, the default's
// fine-tuning from it, the L_acc sweep, then L_acc on the test split), and a stop at the time budget ending the
// script, so that no fine-tuning starts from an unfinished base; a rerun continues where it stopped.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "core/csv.hpp"
#include "test_util.hpp"
#include "tiny_model.hpp"

namespace fs = std::filesystem;
using namespace t2imu;

namespace {

// A copy of the script in `root` (it works from the folder above its own) beside this build's binary, the tiny data
// set as both builds it expects, and a tiny configuration at every path it names.
void make_project(const std::string& root) {
    fs::create_directories(root + "/scripts");
    fs::create_directories(root + "/build");
    fs::copy_file(test::source_dir() + "/scripts/train-default.sh", root + "/scripts/train-default.sh");
    fs::create_symlink(T2IMU_BINARY, root + "/build/t2imu");
    const std::string data = test::make_tiny_motion_dataset(root + "/cache/dataset");
    fs::copy_file(data + "/train.txt", data + "/test.txt");  // eval-lacc reads the test split
    std::ofstream(data + "/summary.json") << "{}\n";
    fs::create_directory_symlink(fs::absolute(data), root + "/cache/dataset-lie-down");
    fs::create_directories(root + "/cache/text");
    fs::copy_file(data + "/vocab.safetensors", root + "/cache/text/glove-100k.safetensors");
    fs::create_directories(root + "/cache/mocap");
    std::ofstream(root + "/cache/mocap/manifest.csv") << "file\n";
    fs::create_directories(root + "/experiments/lacc-sweep");
    const std::string scratch = root + "/configs";
    fs::create_directories(scratch);
    const auto config = [&](const std::string& path, const std::string& out, const std::string& extra) {
        fs::rename(test::write_tiny_train_config(scratch, data, out, extra), root + "/experiments/" + path);
    };
    config("train-default.toml", "models/base", "");
    config("default.toml", "models/default", "");
    config("lacc-sweep/control.toml", "models/lacc-sweep/control", "");
    for (const char* lambda : {"0.01", "0.1", "1"})
        config(std::string("lacc-sweep/lambda-") + lambda + ".toml", std::string("models/lacc-sweep/lambda-") + lambda,
               std::string("[loss]\nlambda_acc = ") + lambda + "\n");
}

test::CliResult run_script(const std::string& root, const std::string& options) {
    return test::run_shell("cd '" + root + "' && OPENBLAS_NUM_THREADS=1 bash scripts/train-default.sh " + options);
}

// The step a model folder's last metrics line records.
long long last_logged_step(const std::string& model) {
    std::ifstream f(model + "/metrics.jsonl");
    std::string line, last;
    while (std::getline(f, line)) last = line;
    const size_t at = last.find("\"step\":");
    return at == std::string::npos ? -1 : std::stoll(last.substr(at + 7));
}

}  // namespace

TEST(TrainDefaultScript, StopsAtTheBudgetAndARerunTrainsTheRestInOrder) {
    const std::string root = test::scratch_dir("train_default_script");
    make_project(root);
    const std::string steps = "--base-steps 10 --finetune-steps 5";

    // A budget that the first step exceeds: the base saves after step 1 and the script stops there, exit 75.
    const test::CliResult stopped = run_script(root, steps + " --max-minutes 0.000001");
    EXPECT_EQ(stopped.exit_code, 75) << stopped.output;
    EXPECT_TRUE(test::contains(stopped.output, "models/base: step 1,")) << stopped.output;
    EXPECT_TRUE(test::contains(stopped.output, "scripts/train-default.sh: stopped early")) << stopped.output;
    EXPECT_TRUE(fs::exists(root + "/models/base/checkpoint.pt"));
    EXPECT_FALSE(fs::exists(root + "/models/default")) << "a fine-tuning started from an unfinished base";
    EXPECT_FALSE(fs::exists(root + "/models/lacc-sweep"));

    // Without the budget the rerun resumes the base to its last step, then trains and evaluates the rest.
    const test::CliResult rest = run_script(root, steps);
    ASSERT_EQ(rest.exit_code, 0) << rest.output;
    const size_t base = rest.output.find("models/base: step 10,");
    const size_t tuned = rest.output.find("models/default: step 5,");
    ASSERT_NE(base, std::string::npos) << rest.output;
    ASSERT_NE(tuned, std::string::npos) << rest.output;
    EXPECT_LT(base, tuned);
    size_t previous = tuned;
    for (const char* run : {"control", "lambda-0.01", "lambda-0.1", "lambda-1"}) {
        const size_t at = rest.output.find(std::string("models/lacc-sweep/") + run + ": step 5,");
        ASSERT_NE(at, std::string::npos) << run << "\n" << rest.output;
        EXPECT_LT(previous, at) << run;
        previous = at;
    }
    EXPECT_EQ(last_logged_step(root + "/models/base"), 10);
    for (const char* model : {"base", "default", "lacc-sweep_control", "lacc-sweep_lambda-0.01",
                              "lacc-sweep_lambda-0.1", "lacc-sweep_lambda-1"}) {
        const std::string csv = root + "/cache/lacc/" + model + ".csv";
        ASSERT_TRUE(fs::exists(csv)) << csv;
        EXPECT_EQ(read_csv(csv).rows.size(), 6u) << csv;  // one row per clip of the test split
    }
}

// Options are checked before anything runs: --base-steps 0 once trained the config's 100,000 steps (0 means "the
// config's" to t2imu), and an option without its value was a bash error.
TEST(TrainDefaultScript, BadOptionsAreRefusedInOneLineBeforeAnyWork) {
    const std::string root = test::scratch_dir("train_default_script_options");
    fs::create_directories(root + "/scripts");
    fs::copy_file(test::source_dir() + "/scripts/train-default.sh", root + "/scripts/train-default.sh");
    const std::pair<const char*, const char*> bad[] = {
        {"--base-steps 0", "--base-steps: expected a whole number of steps from 1 (got '0')"},
        {"--base-steps", "--base-steps: expected a value"},
        {"--finetune-steps -5", "--finetune-steps: expected a whole number"},
        {"--base-steps 1e9", "--base-steps: expected a whole number"},
        {"--max-minutes soon", "--max-minutes: expected minutes from 0"},
        {"--device", "--device: expected a value"},
        {"--no-such-option", "unknown option --no-such-option"},
    };
    for (const auto& [options, message] : bad) {
        const test::CliResult r = run_script(root, options);
        EXPECT_EQ(r.exit_code, 2) << options << "\n" << r.output;
        EXPECT_EQ(r.output.rfind("scripts/train-default.sh: ", 0), 0u) << options << "\n" << r.output;
        EXPECT_TRUE(test::contains(r.output, message)) << options << "\n" << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << options << "\n" << r.output;
    }
    size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(root)) ++entries;
    EXPECT_EQ(entries, 1u);  // nothing but scripts/: no cache, no models
}
