// Per-sample acceleration loss of a model over a dataset split, for the paper's before/after comparison
// (analysis/lacc_analysis.hpp aggregates two such files per activity category).
//
// Each clip of the split (whole, at most 196 frames, its first caption) is noised at a step t and with noise
// drawn from a generator seeded with seed + the clip's index, so two models see identical draws; the model's
// conditional x0 estimate is compared with the clip by L_acc on the normalised features (the paper's formula on
// x0), and by L_simple (masked MSE), the
// reconstruction a smoother model may give up. Output CSV: id, caption, t, l_acc, l_simple.
#pragma once
#include <cstdint>
#include <string>

#include "core/csv.hpp"
#include "diffusion/text_to_motion.hpp"

namespace t2imu {

CsvTable evaluate_lacc(MotionModel& model, const std::string& dataset, const std::string& split, uint64_t seed);

}  // namespace t2imu
