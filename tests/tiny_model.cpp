#include "tiny_model.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/npy.hpp"
#include "motion/humanml3d.hpp"
#include "motion/mocap_import.hpp"
#include "test_util.hpp"
#include "text/word_vectors.hpp"

namespace t2imu::test {

namespace fs = std::filesystem;

std::string make_tiny_motion_dataset(const std::string& dir) {
    fs::create_directories(dir + "/new_joint_vecs");
    fs::create_directories(dir + "/texts");
    const FeatureMatrix f = joints_to_features(import_motion(source_dir() + "/examples/cmu_07_05_slow_walk.bvh"));
    std::ofstream train(dir + "/train.txt");
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(263), sq = Eigen::VectorXd::Zero(263);
    for (int k = 0; k < 6; ++k) {
        const FeatureMatrix clip = f.middleRows(k * 4, 60);
        write_npy(dir + "/new_joint_vecs/c" + std::to_string(k) + ".npy", feature_matrix_to_array(clip));
        std::ofstream(dir + "/texts/c" + std::to_string(k) + ".txt") << "a person walks forward slowly##0.0#0.0\nsomeone walks##0.0#0.0\n";
        train << "c" << k << "\n";
        mean += clip.colwise().mean().transpose() / 6;
        sq += clip.array().square().colwise().mean().matrix().transpose() / 6;
    }
    const Eigen::VectorXd sd = (sq - mean.cwiseProduct(mean)).cwiseMax(1e-4).cwiseSqrt();
    write_npy(dir + "/Mean.npy", NdArray::from(std::vector<double>(mean.data(), mean.data() + 263), {263}));
    write_npy(dir + "/Std.npy", NdArray::from(std::vector<double>(sd.data(), sd.data() + 263), {263}));
    const std::vector<std::string> words = {"a", "person", "walks", "forward", "slowly", "someone"};
    std::vector<float> v(words.size() * 100);
    for (size_t i = 0; i < v.size(); ++i) v[i] = static_cast<float>(std::cos(0.3 * static_cast<double>(i)));
    WordVectors(words, v).save(dir + "/vocab.safetensors");
    return dir;
}

std::string write_tiny_train_config(const std::string& dir, const std::string& data, const std::string& out, const std::string& extra) {
    const std::string path = dir + "/" + fs::path(out).filename().string() + ".toml";
    std::ofstream(path) << "out = \"" << out << "\"\n[data]\ndataset = \"" << data << "\"\nvocab = \"" << data << "/vocab.safetensors\"\n"
                        << "[model]\nlatent_dim = 32\nff_size = 64\nnum_layers = 2\nnum_heads = 2\ndropout = 0.0\n"
                        << "[text]\nmodel_dim = 16\nlayers = 1\nheads = 2\nff_size = 32\n[diffusion]\nsteps = 50\n"
                        << "[train]\nbatch = 4\nsteps = 40\nlearning_rate = 1e-3\nseed = 3\nsave_every = 10\nlog_every = 5\n" << extra;
    return path;
}

}  // namespace t2imu::test
