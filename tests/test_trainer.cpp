// Training MDM: configuration, the loss terms, a run whose loss falls, resume equal to an uninterrupted run,
// fine-tuning from a model folder, and weights that load by MDM's official names.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/npy.hpp"
#include "core/safetensors.hpp"
#include "diffusion/losses.hpp"
#include "diffusion/recover_from_ric_torch.hpp"
#include "diffusion/trainer.hpp"
#include "motion/humanml3d.hpp"
#include "motion/mocap_import.hpp"
#include "test_util.hpp"
#include "tiny_model.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {

std::vector<float> weights(const std::string& model_dir) {
    std::vector<float> all;
    for (const auto& [name, a] : read_safetensors(model_dir + "/weights.safetensors").tensors) {
        const std::vector<float> v = a.to<float>();
        all.insert(all.end(), v.begin(), v.end());
    }
    return all;
}

}  // namespace

TEST(Trainer, ConfigIsStrict) {
    const std::string dir = test::scratch_dir("trainer_config");
    const std::string good =
        test::write_tiny_train_config(dir, "/data", dir + "/m", "[loss]\nlambda_acc = 1.0\nacc_space = \"joints\"\n");
    const TrainConfig c = read_train_config(good);
    EXPECT_EQ(c.mdm.latent_dim, 32);
    EXPECT_DOUBLE_EQ(c.lambda_acc, 1.0);
    EXPECT_EQ(c.acc_space, "joints");
    EXPECT_EQ(c.batch, 4);
    EXPECT_FALSE(c.augment.enabled());
    std::ofstream(dir + "/augment.toml") << read_file_text(good)
                                         << "[augment]\nswap = 0.2\ndropout = 0.1\nneighbours = 4\n";
    const TrainConfig a = read_train_config(dir + "/augment.toml");
    EXPECT_DOUBLE_EQ(a.augment.swap, 0.2);
    EXPECT_DOUBLE_EQ(a.augment.dropout, 0.1);
    EXPECT_EQ(a.augment.neighbours, 4);
    std::ofstream(dir + "/bad.toml") << read_file_text(good) << "learnig_rate = 3\n";  // typo inside [loss]
    EXPECT_THROW(read_train_config(dir + "/bad.toml"), Error);
    std::ofstream(dir + "/bad2.toml") << read_file_text(good) << "[loss2]\n";
    EXPECT_THROW(read_train_config(dir + "/bad2.toml"), Error);
    // Each refusal names the file and the dotted field.
    const auto refused_field = [&](const std::string& extra) {
        std::ofstream(dir + "/r.toml") << read_file_text(good) << extra;
        try {
            read_train_config(dir + "/r.toml");
        } catch (const Error& e) {
            const std::string m = e.what();
            return m.find(dir + "/r.toml") != std::string::npos ? m : "(file not named) " + m;
        }
        return std::string("accepted");
    };
    EXPECT_NE(refused_field("lambda_vel = -1.0\n").find("loss.lambda_vel"), std::string::npos);
    EXPECT_NE(refused_field("lambda_pos = \"one\"\n").find("loss.lambda_pos"), std::string::npos);  // wrong type
    const std::string text = read_file_text(good);
    const auto replaced = [&](const std::string& from, const std::string& to) {
        std::string t = text;
        const size_t at = t.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) t.replace(at, from.size(), to);
        std::ofstream(dir + "/r2.toml") << t;
        try {
            read_train_config(dir + "/r2.toml");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(replaced("learning_rate = 1e-3\n", "learning_rate = 0.0\n").find("train.learning_rate"),
              std::string::npos);
    EXPECT_NE(replaced("[train]\n", "[train]\ncond_dropout = 1.5\n").find("train.cond_dropout"), std::string::npos);
    EXPECT_NE(replaced("seed = 3\n", "seed = -3\n").find("train.seed"), std::string::npos);
    EXPECT_NE(replaced("acc_space = \"joints\"", "acc_space = \"pose\"").find("loss.acc_space"), std::string::npos);
    EXPECT_NE(replaced("num_heads = 2\n", "num_heads = 3\n").find("model.num_heads"), std::string::npos);
    EXPECT_EQ(replaced("acc_space = \"joints\"", "acc_space = \"joints\"\nacc_joints = [\"pelvis\", \"left_foot\"]"),
              "accepted");
    for (const char* joints : {"[\"pelvis\", \"pelvis\"]", "[\"left_toe\"]"})
        EXPECT_NE(replaced("acc_space = \"joints\"", "acc_space = \"joints\"\nacc_joints = " + std::string(joints))
                      .find("loss.acc_joints"),
                  std::string::npos)
            << joints;
    EXPECT_NE(replaced("acc_space = \"joints\"", "acc_joints = [\"pelvis\"]").find("loss.acc_joints"),
              std::string::npos);  // in feature space there are no joints to pick
    EXPECT_NE(replaced("[train]\n", "[train]\nprecision = \"fp16\"\n").find("train.precision"), std::string::npos);
}

// The training configurations under experiments/ (those asked of a GPU elsewhere among them) read: a typo there
// would only show on the machine that runs them.
TEST(Trainer, EveryShippedTrainingConfigReads) {
    int read = 0;
    for (const auto& e : fs::recursive_directory_iterator(std::string(T2IMU_SOURCE_DIR) + "/experiments")) {
        if (e.path().extension() != ".toml" || read_file_text(e.path().string()).find("\n[train]") == std::string::npos)
            continue;
        EXPECT_NO_THROW(read_train_config(e.path().string())) << e.path();
        ++read;
    }
    EXPECT_GE(
        read,
        13);  // train-default, -augmented, -long, lacc-sweep/ 4, lacc-sweep-gpu/ 3, paraphrase-finetune/ 2, continue/
}

TEST(Trainer, EmaDecayWarmsUpSoTheInitialisationIsForgotten) {
    EXPECT_DOUBLE_EQ(ema_decay_at(0.9999, 0), 0.1);
    EXPECT_DOUBLE_EQ(ema_decay_at(0.9999, 90), 91.0 / 100.0);
    EXPECT_DOUBLE_EQ(ema_decay_at(0.9999, 1000000), 0.9999);
    // What remains of the starting weights after n updates: the product of the decays.
    double kept = 1;
    for (int64_t n = 0; n < 12000; ++n) kept *= ema_decay_at(0.9999, n);
    EXPECT_LT(kept, 1e-3);  // a plain 0.9999 would keep 0.9999^12000 = 0.30
}

TEST(Trainer, LossTermsVanishForAPerfectPredictionAndMatchTheirDefinitions) {
    torch::manual_seed(0);
    const FeatureMatrix f = joints_to_features(import_motion(test::source_dir() + "/examples/cmu_07_05_slow_walk.bvh"));
    torch::Tensor x = torch::zeros({2, 60, 263});
    for (int b = 0; b < 2; ++b)
        for (int t = 0; t < 60; ++t)
            for (int c = 0; c < 263; ++c) x[b][t][c] = static_cast<float>(f(t + b * 5, c));
    const torch::Tensor mean = torch::zeros({263}), std = torch::ones({263}), lengths = torch::tensor({60, 48});
    TrainConfig c;
    c.lambda_pos = c.lambda_vel = c.lambda_foot = c.lambda_acc = 1;
    const LossTerms same = mdm_loss_terms(x, x, lengths, mean, std, c);
    for (const torch::Tensor* term : {&same.simple, &same.pos, &same.vel, &same.acc})
        EXPECT_EQ(term->item<double>(), 0.0);
    // L_foot is no comparison: it penalises the prediction's own foot velocity during ground contact.
    EXPECT_NEAR(same.total.item<double>(), same.foot.item<double>(), 1e-12);
    // A constant offset on every feature: L_simple = offset^2, no velocity or acceleration error.
    const LossTerms shifted = mdm_loss_terms(x, x + 0.1, lengths, mean, std, c);
    EXPECT_NEAR(shifted.simple.item<double>(), 0.01, 1e-6);
    EXPECT_NEAR(shifted.acc.item<double>(), 0.0, 1e-9);
    EXPECT_GT(shifted.pos.item<double>(), 0.0);
    c.acc_space = "joints";
    const torch::Tensor predicted = x + 0.05 * torch::randn_like(x);
    const LossTerms noisy = mdm_loss_terms(x, predicted, lengths, mean, std, c);
    EXPECT_GT(noisy.acc.item<double>(), 0.0);
    EXPECT_GT(noisy.foot.item<double>(), 0.0);  // feet with contact move in the noisy prediction
    // acc_joints: L_acc of those joints' channels alone (pelvis = joint 0, right foot = joint 11).
    c.acc_joints = {"pelvis", "right_foot"};
    const auto picked = [](const torch::Tensor& features) {
        const torch::Tensor j = recover_from_ric_torch(features);  // [B, F, 22, 3]
        return torch::cat({j.select(2, 0), j.select(2, 11)}, 2);
    };
    const double expected =
        acceleration_loss(picked(x), picked(predicted), frame_mask(lengths, x.size(1))).mean().item<double>();
    EXPECT_NEAR(mdm_loss_terms(x, predicted, lengths, mean, std, c).acc.item<double>(), expected,
                1e-9 + 1e-6 * expected);
    EXPECT_GT(expected, 0.0);
}

TEST(Trainer, LossFallsResumeContinuesExactlyAndFinetuneStartsFromTheWeights) {
    torch::set_num_threads(1);
    const std::string dir = test::scratch_dir("trainer_run");
    const std::string data = test::make_tiny_motion_dataset(dir + "/data");
    const std::string straight =
        test::write_tiny_train_config(dir, data, dir + "/straight", "[loss]\nlambda_vel = 1.0\n");
    const TrainProgress full = train_mdm(read_train_config(straight), false);
    EXPECT_EQ(full.step, 40);
    // The loss falls: first logged total vs the mean of the last three.
    std::ifstream metrics(dir + "/straight/metrics.jsonl");
    std::vector<double> losses;
    for (std::string line; std::getline(metrics, line);)
        losses.push_back(nlohmann::json::parse(line)["loss"].get<double>());
    ASSERT_EQ(losses.size(), 8u);
    EXPECT_LT((losses[5] + losses[6] + losses[7]) / 3, 0.7 * losses[0]);
    for (const char* f :
         {"model.json", "weights.safetensors", "text_encoder.safetensors", "Mean.npy", "Std.npy", "checkpoint.pt"})
        EXPECT_TRUE(fs::exists(dir + "/straight/" + std::string(f))) << f;

    // The same run stopped after 20 steps and resumed: the same weights as the uninterrupted one.
    const std::string interrupted =
        test::write_tiny_train_config(dir, data, dir + "/resumed", "[loss]\nlambda_vel = 1.0\n");
    // A time budget stops after the step that reaches it (here the first), saved like a finished run.
    TrainConfig budget = read_train_config(interrupted);
    budget.out = dir + "/budget";
    budget.max_minutes = 1e-9;
    const TrainProgress budgeted = train_mdm(budget, false);
    EXPECT_EQ(budgeted.step, 1);
    EXPECT_TRUE(budgeted.stopped_early);
    EXPECT_TRUE(fs::exists(dir + "/budget/checkpoint.pt"));
    EXPECT_TRUE(fs::exists(dir + "/budget/weights.safetensors"));
    train_mdm(read_train_config(interrupted), false, "", 20);
    const TrainProgress resumed = train_mdm(read_train_config(interrupted), true);
    EXPECT_EQ(resumed.step, 40);
    const std::vector<float> a = weights(dir + "/straight"), b = weights(dir + "/resumed");
    ASSERT_EQ(a.size(), b.size());
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, static_cast<double>(std::fabs(a[i] - b[i])));
    EXPECT_LT(worst, 1e-6);

    // The official MDM loader accepts the weights by name.
    MdmConfig mc;
    mc.latent_dim = 32;
    mc.ff_size = 64;
    mc.num_layers = 2;
    mc.num_heads = 2;
    Mdm mdm(mc);
    EXPECT_NO_THROW(load_mdm_weights(mdm, dir + "/straight/weights.safetensors"));

    // Fine-tuning with L_acc from the trained model: step count restarts, starting loss already low. The dataset's
    // Mean/Std moved since (a rebuild with more clips): the fine-tuning keeps the base's feature space.
    const NdArray base_mean = read_npy(dir + "/straight/Mean.npy");
    std::vector<float> moved = base_mean.to<float>();
    for (float& m : moved) m += 0.5f;
    write_npy(data + "/Mean.npy", NdArray::from(moved, base_mean.shape));
    const std::string tune = test::write_tiny_train_config(dir, data, dir + "/tuned", "[loss]\nlambda_acc = 1.0\n");
    train_mdm(read_train_config(tune), false, dir + "/straight", 5);
    EXPECT_EQ(read_npy(dir + "/tuned/Mean.npy").to<float>(), base_mean.to<float>());
    train_mdm(read_train_config(tune), true, "", 8);  // resumed: its own saved space, still the base's
    EXPECT_EQ(read_npy(dir + "/tuned/Mean.npy").to<float>(), base_mean.to<float>());
    std::ifstream tuned(dir + "/tuned/metrics.jsonl");
    std::string first;
    std::getline(tuned, first);
    EXPECT_LT(nlohmann::json::parse(first)["l_simple"].get<double>(), losses[0]);
}

// bf16 autocast trains the tiny model on the same trajectory as fp32 within bf16's rounding: the logged losses
// fall alike, and the per-part profile accounts for every profiled step.
TEST(Trainer, Bf16FollowsFp32AndTheProfileCoversEveryPart) {
    torch::set_num_threads(1);
    const std::string dir = test::scratch_dir("trainer_bf16");
    const std::string data = test::make_tiny_motion_dataset(dir + "/data");
    std::map<std::string, std::vector<double>> losses;
    for (const std::string precision : {"fp32", "bf16"}) {
        const std::string config = test::write_tiny_train_config(dir, data, dir + "/" + precision, "");
        std::string text = read_file_text(config);
        text.replace(text.find("[train]\n"), 8, "[train]\nprecision = \"" + precision + "\"\n");
        std::ofstream(config) << text;
        const TrainProgress p = train_mdm(read_train_config(config), false);
        EXPECT_EQ(p.profile.steps, 39) << precision;  // all but the first
        for (const double part : {p.profile.data, p.profile.text, p.profile.forward, p.profile.backward,
                                  p.profile.optimiser, p.profile.log})
            EXPECT_GT(part, 0.0) << precision;
        EXPECT_EQ(nlohmann::json::parse(read_file_text(dir + "/" + precision + "/model.json"))["training"]["precision"],
                  precision);
        std::ifstream metrics(dir + "/" + precision + "/metrics.jsonl");
        for (std::string line; std::getline(metrics, line);)
            losses[precision].push_back(nlohmann::json::parse(line)["loss"].get<double>());
    }
    const std::vector<double>&a = losses["fp32"], &b = losses["bf16"];
    ASSERT_EQ(a.size(), 8u);
    ASSERT_EQ(b.size(), 8u);
    EXPECT_NEAR(b[0], a[0], 0.02 * a[0]);  // the same first batch through the same initial weights
    const double end_a = (a[5] + a[6] + a[7]) / 3, end_b = (b[5] + b[6] + b[7]) / 3;
    EXPECT_LT(end_b, 0.7 * b[0]);
    EXPECT_NEAR(end_b, end_a, 0.15 * end_a);
}

TEST(Trainer, SampleFromATrainedModelIsSeededAndBatchIndependent) {
    torch::set_num_threads(1);
    const std::string dir = test::scratch_dir("trainer_sample");
    const std::string data = test::make_tiny_motion_dataset(dir + "/data");
    train_mdm(read_train_config(test::write_tiny_train_config(dir, data, dir + "/model")), false, "", 10);
    std::ofstream(dir + "/prompts.txt")
        << "# activity<TAB>prompt\nwalking\ta person walks forward slowly\nwalking\tsomeone walks\n";
    const auto run = [&](const std::string& out, const std::string& extra) {
        const auto r = test::run_cli("--threads 1 sample --model " + dir + "/model --prompts " + dir +
                                     "/prompts.txt --frames 40 --seed 7 --out " + dir + "/" + out + " " + extra);
        EXPECT_EQ(r.exit_code, 0) << r.output;
    };
    run("a", "--sampler ddim --steps 5 --batch 2");
    run("b", "--sampler ddim --steps 5 --batch 1");
    run("c", "--sampler dpmpp --steps 5");
    run("d", "");  // DDPM, all 50 steps
    const NdArray f = read_npy(dir + "/a/0001_features.npy");
    EXPECT_EQ(f.shape, (std::vector<int64_t>{40, 263}));
    EXPECT_EQ(read_npy(dir + "/a/0001_joints.npy").shape, (std::vector<int64_t>{40, 22, 3}));
    // Batch size does not change a sample beyond float rounding (batched matrix products round differently).
    for (const char* s : {"0000_features.npy", "0001_features.npy"}) {
        const std::vector<double> x = read_npy(dir + "/a/" + s).to<double>(),
                                  y = read_npy(dir + "/b/" + s).to<double>();
        double worst = 0;
        for (size_t i = 0; i < x.size(); ++i) worst = std::max(worst, std::fabs(x[i] - y[i]) / (1 + std::fabs(x[i])));
        EXPECT_LT(worst, 1e-4) << s;
    }
    // The same call twice: the same bytes.
    run("a2", "--sampler ddim --steps 5 --batch 2");
    EXPECT_EQ(read_file_bytes(dir + "/a/0001_features.npy"), read_file_bytes(dir + "/a2/0001_features.npy"));
    EXPECT_NE(read_file_bytes(dir + "/a/0000_features.npy"), read_file_bytes(dir + "/a/0001_features.npy"));
    EXPECT_NE(read_file_bytes(dir + "/a/0000_features.npy"), read_file_bytes(dir + "/c/0000_features.npy"));
    const nlohmann::json rec = nlohmann::json::parse(read_file_text(dir + "/d/samples.json"));
    EXPECT_EQ(rec["sampler"], "ddpm");
    EXPECT_EQ(rec["steps"], 50);
    EXPECT_EQ(rec["samples"][1]["seed"], 8);
    EXPECT_EQ(rec["samples"][1]["activity"], "walking");
    for (double v : read_npy(dir + "/d/0000_joints.npy").to<double>()) ASSERT_TRUE(std::isfinite(v));
    // Per-sample L_acc: identical draws for the same seed, so two models compare on the same noise; the
    // analysis of a model against itself finds no change.
    for (const char* name : {"l1.csv", "l2.csv"}) {
        const auto r = test::run_cli("--threads 1 eval-lacc --model " + dir + "/model --dataset " + data +
                                     " --split train --seed 4 --out " + dir + "/" + name);
        ASSERT_EQ(r.exit_code, 0) << r.output;
    }
    EXPECT_EQ(read_file_text(dir + "/l1.csv"), read_file_text(dir + "/l2.csv"));
    const CsvTable lacc = read_csv(dir + "/l1.csv");
    ASSERT_EQ(lacc.rows.size(), 6u);
    for (size_t i = 0; i < lacc.rows.size(); ++i) {
        EXPECT_GE(lacc.number(i, lacc.column("l_acc")), 0.0);
        EXPECT_GT(lacc.number(i, lacc.column("l_simple")), 0.0);
    }
    const auto analysis =
        test::run_cli("analysis lacc --before " + dir + "/l1.csv --after " + dir + "/l2.csv --vocab " + data +
                      "/vocab.safetensors --tau 0.5 --out " + dir + "/change.csv");
    ASSERT_EQ(analysis.exit_code, 0) << analysis.output;
    EXPECT_NE(analysis.output.find("change 0.00 %"), std::string::npos) << analysis.output;
    const auto bad = test::run_cli("sample --model " + dir + "/model --prompt x --frames 500 --out " + dir + "/e");
    EXPECT_EQ(bad.exit_code, 2) << bad.output;  // an option value out of range is bad usage
}

// A checkpoint that is damaged (a block flipped, the size kept), cut, empty or of another model configuration is
// refused on resume in one line naming the file (and the field), and the model folder is left as it was; a
// non-finite loss stops training before anything is saved; a resume without a checkpoint names the checkpoint;
// a resume already at train.steps runs no step and says so.
TEST(Trainer, DamagedCheckpointsAndNonFiniteLossesNeverReachTheModel) {
    torch::set_num_threads(1);
    const std::string dir = test::scratch_dir("trainer_checkpoints");
    const std::string data = test::make_tiny_motion_dataset(dir + "/data");
    const std::string config = test::write_tiny_train_config(dir, data, dir + "/m", "");
    train_mdm(read_train_config(config), false, "", 5);  // the last step of a call is saved
    const std::string checkpoint = dir + "/m/checkpoint.pt";
    const std::vector<uint8_t> good = read_file_bytes(checkpoint),
                               model = read_file_bytes(dir + "/m/weights.safetensors");
    ASSERT_GT(good.size(), 20000u);
    const auto refused = [&](const std::vector<uint8_t>& bytes, const std::string& config_path,
                             const std::string& field) {
        write_file_atomic(checkpoint, bytes.data(), bytes.size());
        const std::string m = test::error_message([&] { train_mdm(read_train_config(config_path), true); });
        EXPECT_TRUE(test::contains(m, checkpoint) && test::contains(m, field)) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
        EXPECT_EQ(read_file_bytes(dir + "/m/weights.safetensors"), model);
    };
    std::vector<uint8_t> flipped = good;
    for (size_t i = flipped.size() / 2; i < flipped.size() / 2 + 4096; ++i) flipped[i] ^= 0x5a;
    refused(flipped, config, "damaged");  // the checksum's, or libtorch's own refusal of the archive
    refused(std::vector<uint8_t>(good.begin(), good.begin() + static_cast<long>(good.size() / 2)), config,
            "checkpoint");
    refused({}, config, "checkpoint");
    const std::string wider = test::write_tiny_train_config(dir + "/data", data, dir + "/m", "");
    std::string text = read_file_text(wider);
    text.replace(text.find("latent_dim = 32"), 15, "latent_dim = 48");
    write_file_atomic(wider, text);
    refused(good, wider, "shape");

    // Resumed at train.steps: nothing runs, nothing is written.
    write_file_atomic(checkpoint, good.data(), good.size());
    TrainConfig done = read_train_config(config);
    done.steps = 5;
    EXPECT_EQ(train_mdm(done, true).steps_run, 0);
    EXPECT_EQ(read_file_bytes(checkpoint), good);

    // No checkpoint: the message names it, not Mean.npy.
    TrainConfig fresh = read_train_config(config);
    fresh.out = dir + "/empty";
    fs::create_directories(fresh.out);
    const std::string m = test::error_message([&] { train_mdm(fresh, true); });
    EXPECT_TRUE(test::contains(m, dir + "/empty/checkpoint.pt") && !test::contains(m, "Mean.npy")) << m;

    // 1e30 in every frame of every clip (finite, so the loader takes it; its square overflows float): the first
    // step's loss is not finite, and nothing is saved.
    for (const auto& e : fs::directory_iterator(data + "/new_joint_vecs")) {
        NdArray a = read_npy(e.path().string());
        std::vector<float> v = a.to<float>();
        for (size_t i = 7; i < v.size(); i += 263) v[i] = 1e30f;  // feature 7 of every frame [F, 263]
        write_npy(e.path().string(), NdArray::from(v, a.shape));
    }
    TrainConfig poisoned = read_train_config(config);
    poisoned.out = dir + "/nan";
    const std::string n = test::error_message([&] { train_mdm(poisoned, false); });
    EXPECT_TRUE(test::contains(n, "step 1") && test::contains(n, "a finite loss") &&
                test::contains(n, "before anything was saved"))
        << n;
    EXPECT_FALSE(fs::exists(dir + "/nan/checkpoint.pt"));
    EXPECT_FALSE(fs::exists(dir + "/nan/weights.safetensors"));
}
