// Data-parallel training: torchrun's variables, equal batch shares, gradient averaging over two ranks (two
// threads of this process), and two t2imu processes on loopback training the same weights as one process
// with the combined batch, also when stopped and resumed.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/safetensors.hpp"
#include "diffusion/trainer.hpp"
#include "nn/distributed.hpp"
#include "test_util.hpp"
#include "tiny_model.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {

// A port on 127.0.0.1 that nothing listens on now (0 when loopback cannot be bound).
int free_loopback_port() {
    const int s = socket(AF_INET, SOCK_STREAM, 0);
    if (s < 0) return 0;
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = 0;
    socklen_t len = sizeof a;
    int port = 0;
    if (bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 &&
        getsockname(s, reinterpret_cast<sockaddr*>(&a), &len) == 0)
        port = ntohs(a.sin_port);
    close(s);
    return port;
}

#define LOOPBACK_PORT_OR_SKIP(port)        \
    const int port = free_loopback_port(); \
    if (port == 0) GTEST_SKIP() << "cannot bind a TCP socket on 127.0.0.1, which Gloo's rendezvous needs"

ProcessGroupEnv two_ranks(int rank, int port) {
    ProcessGroupEnv e;
    e.rank = rank;
    e.world_size = 2;
    e.master_addr = "127.0.0.1";
    e.master_port = port;
    return e;
}

std::map<std::string, std::vector<float>> tensors(const std::string& path) {
    std::map<std::string, std::vector<float>> out;
    for (const auto& [name, a] : read_safetensors(path).tensors) out[name] = a.to<float>();
    return out;
}

std::vector<double> logged_losses(const std::string& metrics) {
    std::ifstream in(metrics);
    std::vector<double> v;
    for (std::string line; std::getline(in, line);) v.push_back(nlohmann::json::parse(line)["loss"].get<double>());
    return v;
}

// Runs `t2imu train` as ranks 0 and 1 of two processes meeting on 127.0.0.1:port, in `dir`; the failing rank's log
// when one fails, else empty.
std::string train_two_processes(const std::string& dir, const std::string& config, int port,
                                const std::string& args = "") {
    // SIGKILL: t2imu train takes SIGTERM as "save and stop after this step", which a rank waiting for the other
    // never reaches.
    std::string s = "cd '" + dir + "' && { ";
    for (int r = 0; r < 2; ++r)
        s += "(RANK=" + std::to_string(r) + " WORLD_SIZE=2 MASTER_ADDR=127.0.0.1 MASTER_PORT=" + std::to_string(port) +
             " timeout -s KILL 120 '" + T2IMU_BINARY + "' --threads 1 train --config '" + config + "' " + args +
             " > rank" + std::to_string(r) + ".log 2>&1; echo $? > rank" + std::to_string(r) + ".rc) & ";
    if (std::system((s + "wait; }").c_str()) != 0) return "the shell could not start both ranks";
    for (int r = 0; r < 2; ++r)
        if (read_file_text(dir + "/rank" + std::to_string(r) + ".rc") != "0\n")
            return "rank " + std::to_string(r) + " failed:\n" +
                   read_file_text(dir + "/rank" + std::to_string(r) + ".log");
    return "";
}

// How far two model folders' weights (both weight files) lie apart: the largest |a - b| / (1 + |a|), and the
// root mean square of a - b.
struct WeightDifference {
    double largest_relative = 0, rms = 0;
};
WeightDifference weight_difference(const std::string& a_dir, const std::string& b_dir) {
    WeightDifference d;
    double squares = 0;
    size_t count = 0;
    for (const char* file : {"weights.safetensors", "text_encoder.safetensors"}) {
        const auto a = tensors(a_dir + "/" + file), b = tensors(b_dir + "/" + file);
        EXPECT_EQ(a.size(), b.size()) << file;
        for (const auto& [name, va] : a) {
            const std::vector<float>& vb = b.at(name);
            EXPECT_EQ(va.size(), vb.size()) << name;
            for (size_t i = 0; i < std::min(va.size(), vb.size()); ++i) {
                const double e = double(va[i]) - vb[i];
                d.largest_relative = std::max(d.largest_relative, std::fabs(e) / (1 + std::fabs(double(va[i]))));
                squares += e * e;
                ++count;
            }
        }
    }
    d.rms = std::sqrt(squares / static_cast<double>(std::max<size_t>(count, 1)));
    return d;
}

// The same weights up to float summation order: the one-process gradients sum over 4 samples at once, the two
// ranks' over 2 each and then average, which rounds differently in the last bits. Measured here (12 steps): rms
// 3e-7, largest 2.5e-5, the largest in the attention's key bias, whose gradient is zero but for rounding (softmax
// ignores a shift common to a query's logits) and which AdamW's division by sqrt(v) turns into steps of up to
// lr * |g| / eps. With the gradients not averaged (each rank stepping on its own share) they are rms 2e-3,
// largest 1.3e-2.
void expect_same_weights(const std::string& a_dir, const std::string& b_dir) {
    const WeightDifference d = weight_difference(a_dir, b_dir);
    EXPECT_LT(d.rms, 1e-5) << b_dir;
    EXPECT_LT(d.largest_relative, 1e-3) << b_dir;
}

}  // namespace

TEST(Distributed, ReadsTorchrunVariablesAndRefusesBadOnes) {
    std::map<std::string, std::string> vars;
    const auto env = [&](const char* name) -> const char* {
        const auto it = vars.find(name);
        return it == vars.end() ? nullptr : it->second.c_str();
    };
    EXPECT_EQ(read_process_group_env(env).world_size, 1);  // nothing set: one process
    vars = {
        {"RANK", "1"}, {"WORLD_SIZE", "2"}, {"LOCAL_RANK", "1"}, {"MASTER_ADDR", "10.0.0.5"}, {"MASTER_PORT", "29501"}};
    const ProcessGroupEnv e = read_process_group_env(env);
    EXPECT_EQ(e.rank, 1);
    EXPECT_EQ(e.world_size, 2);
    EXPECT_EQ(e.local_rank, 1);
    EXPECT_EQ(e.master_addr, "10.0.0.5");
    EXPECT_EQ(e.master_port, 29501);
    vars["RANK"] = "2";  // ranks are 0 .. WORLD_SIZE-1
    EXPECT_THROW(read_process_group_env(env), Error);
    vars["RANK"] = "one";
    EXPECT_THROW(read_process_group_env(env), Error);
    vars["RANK"] = "0";
    vars.erase("MASTER_PORT");
    EXPECT_THROW(read_process_group_env(env), Error);
}

TEST(Distributed, RefusesABatchTheRanksCannotShareEqually) {
    EXPECT_THROW(batch_share(5, 0, 2), Error);
    EXPECT_THROW(batch_share(4, 0, 3), Error);
    const BatchShare s = batch_share(6, 2, 3);
    EXPECT_EQ(s.begin, 4);
    EXPECT_EQ(s.size, 2);
    EXPECT_EQ(batch_share(7, 0, 1).size, 7);
    // The CLI refuses it before waiting for the other rank, with the field named.
    const std::string dir = test::scratch_dir("distributed_refused");
    const std::string data = test::make_tiny_motion_dataset(dir + "/data");
    std::string config = read_file_text(test::write_tiny_train_config(dir, data, dir + "/m"));
    config.replace(config.find("batch = 4"), 9, "batch = 5");
    write_file_atomic(dir + "/odd.toml", config);
    const std::string cmd = "cd '" + dir +
                            "' && RANK=0 WORLD_SIZE=2 MASTER_ADDR=127.0.0.1 MASTER_PORT=1 timeout -s KILL 60 '" +
                            T2IMU_BINARY + "' --threads 1 train --config odd.toml > out.log 2>&1";
    const int status = std::system(cmd.c_str());
    EXPECT_EQ(WEXITSTATUS(status), 1) << read_file_text(dir + "/out.log");
    EXPECT_NE(read_file_text(dir + "/out.log").find("train.batch"), std::string::npos)
        << read_file_text(dir + "/out.log");
}

TEST(Distributed, TwoRanksAverageGradientsAndShareRankZerosWeights) {
    LOOPBACK_PORT_OR_SKIP(port);
    // Rank r: weights filled with r, gradient of the first parameter 2 + 2r (mean 3); the second parameter has
    // a gradient on rank 1 only (mean 0.5 x 4 = 2); the third on no rank (stays undefined).
    torch::Tensor riders[2];
    torch::Tensor params[2][3];
    std::string failure[2];
    const auto rank = [&](int r) {
        try {
            const DataParallel group(two_ranks(r, port), torch::Device(torch::kCPU), std::chrono::seconds(30));
            EXPECT_EQ(group.backend(), "gloo");
            for (int i = 0; i < 3; ++i) params[r][i] = torch::full({3, 2}, static_cast<float>(r)).requires_grad_(true);
            group.broadcast_from_main({params[r][0], params[r][1], params[r][2]});
            (params[r][0] * (2.0f + 2.0f * static_cast<float>(r))).sum().backward();
            if (r == 1) (params[r][1] * 4.0f).sum().backward();
            riders[r] = group.average_gradients({params[r][0], params[r][1], params[r][2]},
                                                torch::tensor({1.0f + static_cast<float>(r), 0.0f}));
            group.barrier();
        } catch (const std::exception& e) {
            failure[r] = e.what();
        }
    };
    std::thread other(rank, 1);
    rank(0);
    other.join();
    ASSERT_TRUE(failure[0].empty() && failure[1].empty()) << failure[0] << " | " << failure[1];
    for (int r = 0; r < 2; ++r) {
        EXPECT_TRUE(torch::equal(params[r][0].detach(), torch::zeros({3, 2})))
            << "rank " << r << " got rank 0's weights";
        EXPECT_TRUE(torch::allclose(params[r][0].grad(), torch::full({3, 2}, 3.0f)));
        ASSERT_TRUE(params[r][1].grad().defined());
        EXPECT_TRUE(torch::allclose(params[r][1].grad(), torch::full({3, 2}, 2.0f)));
        EXPECT_FALSE(params[r][2].grad().defined());
        EXPECT_TRUE(torch::allclose(riders[r], torch::tensor({1.5f, 0.0f})));
    }
}

TEST(Distributed, TwoProcessesTrainTheSameWeightsAsOneWithTheWholeBatch) {
    LOOPBACK_PORT_OR_SKIP(port);
    torch::set_num_threads(1);
    const std::string dir = test::scratch_dir("distributed_train");
    const std::string data = test::make_tiny_motion_dataset(dir + "/data");
    // Condition dropout on (0.25, so captions are dropped in both shares), the text encoder's own dropout off: its
    // masks are drawn per rank (trainer.hpp), so with it the two runs would agree only in distribution.
    const auto config = [&](const std::string& name) {
        std::string text =
            read_file_text(test::write_tiny_train_config(dir, data, dir + "/" + name, "cond_dropout = 0.25\n"));
        text.replace(text.find("[text]\n"), 7, "[text]\ndropout = 0.0\n");
        text.replace(text.find("steps = 40"), 10, "steps = 12");
        write_file_atomic(dir + "/" + name + ".toml", text);
        return dir + "/" + name + ".toml";
    };
    const std::string one = config("one"), two = config("two");
    ASSERT_EQ(read_train_config(one).batch, 4);
    EXPECT_EQ(train_mdm(read_train_config(one), false).step, 12);
    const std::string failed = train_two_processes(dir, two, port);
    ASSERT_TRUE(failed.empty()) << failed;

    expect_same_weights(dir + "/one", dir + "/two");
    // The log of the two processes is the global batch's loss, as in one process.
    const std::vector<double> la = logged_losses(dir + "/one/metrics.jsonl"),
                              lb = logged_losses(dir + "/two/metrics.jsonl");
    ASSERT_EQ(la.size(), lb.size());
    for (size_t i = 0; i < la.size(); ++i) EXPECT_NEAR(la[i], lb[i], 1e-4 * la[i]) << "log line " << i;
    // Only rank 0 wrote: one line per log step, not two.
    EXPECT_EQ(lb.size(), 3u);  // steps 5, 10, 12

    // And training moved the weights away from the seed's initialisation (so the comparison above can fail).
    const TrainConfig c = read_train_config(two);
    torch::manual_seed(c.seed);
    MdmConfig mc = c.mdm;
    mc.text_dim = c.text.out_dim;
    mc.mask_frames = true;
    const Mdm initial(mc);
    const auto trained = tensors(dir + "/two/weights.safetensors");
    double moved = 0;
    for (const auto& p : initial->named_parameters()) {
        const torch::Tensor w = p.value().detach().contiguous();
        const std::vector<float>& v = trained.at(p.key());
        for (int64_t i = 0; i < w.numel(); ++i)
            moved = std::max(moved, std::fabs(double(w.data_ptr<float>()[i]) - v[static_cast<size_t>(i)]));
    }
    EXPECT_GT(moved, 1e-3);  // 12 AdamW steps of 1e-3

    // Stopped after 6 steps and resumed, by two processes both times, or by one process first: the same weights.
    const std::string halves = config("halves"), switched = config("switched");
    std::string failed_half = train_two_processes(dir, halves, port, "--steps 6");
    ASSERT_TRUE(failed_half.empty()) << failed_half;
    failed_half = train_two_processes(dir, halves, port, "--resume");
    ASSERT_TRUE(failed_half.empty()) << failed_half;
    expect_same_weights(dir + "/one", dir + "/halves");
    EXPECT_EQ(train_mdm(read_train_config(switched), false, "", 6).step, 6);
    failed_half = train_two_processes(dir, switched, port, "--resume");
    ASSERT_TRUE(failed_half.empty()) << failed_half;
    expect_same_weights(dir + "/one", dir + "/switched");
}
