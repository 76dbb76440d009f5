#include "tiny_model.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/csv.hpp"
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
        std::ofstream(dir + "/texts/c" + std::to_string(k) + ".txt")
            << "a person walks forward slowly##0.0#0.0\nsomeone walks##0.0#0.0\n";
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

void add_capture_copies(const std::string& dir, const std::vector<std::string>& ids) {
    CsvTable clips;
    if (fs::exists(dir + "/clips.csv")) {
        clips = read_csv(dir + "/clips.csv");
    } else {
        clips.header = {"id", "activity_tags", "split"};
        std::ifstream train(dir + "/train.txt");
        for (std::string id; std::getline(train, id);) clips.rows.push_back({id, "walking", "train"});
    }
    clips.header.insert(clips.header.end(), {"capture_fps", "capture_start_s"});
    fs::create_directories(dir + "/capture_joints");
    for (auto& row : clips.rows) {
        const bool copy = std::find(ids.begin(), ids.end(), row[0]) != ids.end();
        row.insert(row.end(), {copy ? "60" : "", copy ? "0" : ""});
        if (!copy) continue;
        const std::string file = dir + "/new_joint_vecs/" + row[0] + ".npy";
        const JointSequence clip = recover_from_ric(feature_matrix_from_array(read_npy(file), file));
        JointSequence up(3 * (clip.num_frames - 1) + 1, 22, 60);
        auto at = [&](int k, int j) { return clip.at(std::clamp(k, 0, clip.num_frames - 1), j); };
        for (int g = 0; g < up.num_frames; ++g)
            for (int j = 0; j < 22; ++j) {  // Catmull-Rom: through every frame, with continuous velocity
                const int k = std::min(g / 3, clip.num_frames - 2);
                const double t = g / 3.0 - k;
                const Eigen::Vector3d p0 = at(k - 1, j), p1 = at(k, j), p2 = at(k + 1, j), p3 = at(k + 2, j);
                up.at(g, j) = 0.5 * (2 * p1 + (p2 - p0) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t * t +
                                     (3 * p1 - p0 - 3 * p2 + p3) * t * t * t);
            }
        write_npy(dir + "/capture_joints/" + row[0] + ".npy", joint_sequence_to_array(up));
    }
    write_csv(dir + "/clips.csv", clips);
}

std::string write_tiny_train_config(const std::string& dir, const std::string& data, const std::string& out,
                                    const std::string& extra) {
    const std::string path = dir + "/" + fs::path(out).filename().string() + ".toml";
    std::ofstream(path)
        << "out = \"" << out << "\"\n[data]\ndataset = \"" << data << "\"\nvocab = \"" << data
        << "/vocab.safetensors\"\n"
        << "[model]\nlatent_dim = 32\nff_size = 64\nnum_layers = 2\nnum_heads = 2\ndropout = 0.0\n"
        << "[text]\nmodel_dim = 16\nlayers = 1\nheads = 2\nff_size = 32\n[diffusion]\nsteps = 50\n"
        << "[train]\nbatch = 4\nsteps = 40\nlearning_rate = 1e-3\nseed = 3\nsave_every = 10\nlog_every = 5\n"
        << extra;
    return path;
}

}  // namespace t2imu::test
