// diffusion/lacc_evaluation.cpp: per-clip L_acc and L_simple of a model over a split. On a tiny trained model:
// one row per clip of the split, finite non-negative losses, the same draws (so the same bytes) for the same
// seed, other draws for another seed; an absent split is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>

#include "core/error.hpp"
#include "diffusion/lacc_evaluation.hpp"
#include "diffusion/trainer.hpp"
#include "test_util.hpp"
#include "tiny_model.hpp"

using namespace t2imu;

TEST(LaccEvaluation, OneRowPerClipSeededDrawsAndFiniteLosses) {
    torch::set_num_threads(1);
    const std::string dir = test::scratch_dir("lacc_evaluation");
    const std::string data = test::make_tiny_motion_dataset(dir + "/data");
    train_mdm(read_train_config(test::write_tiny_train_config(dir, data, dir + "/model")), false, "", 10);
    std::unique_ptr<MotionModel> model = load_motion_model(dir + "/model");

    std::set<std::string> clips;
    {
        std::ifstream in(data + "/train.txt");
        for (std::string id; std::getline(in, id);)
            if (!id.empty()) clips.insert(id);
    }
    const CsvTable a = evaluate_lacc(*model, data, "train", 7), b = evaluate_lacc(*model, data, "train", 7),
                   c = evaluate_lacc(*model, data, "train", 8);
    EXPECT_EQ(a.header, (std::vector<std::string>{"id", "caption", "t", "l_acc", "l_simple"}));
    ASSERT_EQ(a.rows.size(), clips.size());
    std::set<std::string> seen;
    for (size_t r = 0; r < a.rows.size(); ++r) {
        seen.insert(a.rows[r][0]);
        for (size_t col : {size_t{3}, size_t{4}}) {
            const double v = a.number(r, col);
            EXPECT_TRUE(std::isfinite(v) && v >= 0) << a.rows[r][col];
        }
    }
    EXPECT_EQ(seen, clips);
    EXPECT_EQ(a.rows, b.rows);  // the same seed: the same steps and noise, the same numbers
    EXPECT_NE(a.rows, c.rows);  // another seed: other draws
    EXPECT_THROW(evaluate_lacc(*model, data, "nosuchsplit", 7), Error);
}
