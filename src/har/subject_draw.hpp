// Training on several data sets (har/nn/har_training.hpp) without torch: which subjects of a real set a training
// draws, and how many windows of each set each batch takes when the sets have shares of a batch.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace t2imu {

// `count` of `subjects` (a set's subject ids; repeats are ignored), drawn by a seeded shuffle of the sorted ids
// with the seed derived from (seed, repeat); returned sorted. Throws Error when an id is empty or ends in ':' (a data
// set without subject ids; windows name theirs "dataset:subject"), or when count is negative or leaves no subject to
// test on.
std::vector<std::string> draw_subjects(const std::vector<std::string>& subjects, int count, uint64_t seed, int repeat);

// Refuses, before any training, a subject of the test set that a training set other than `test_set` (the one the
// training subjects are drawn from; -1: none) also holds, naming that set (`names`, in order); with test_set >= 0,
// also a draw of `count` subjects that draw_subjects would refuse.
void check_subject_split(const std::vector<std::vector<std::string>>& train_subjects,
                         const std::vector<std::string>& names, const std::vector<std::string>& test_subjects,
                         int test_set, int count);

// Shares of a batch, one per training set: each above 0, together 1, each at least one window of a `batch`;
// Error naming `option` otherwise (an empty list is valid: the sets in proportion to their windows).
void check_shares(const std::vector<double>& shares, size_t sets, int batch, const std::string& option);

// The windows one epoch takes from each set, batch by batch, when set i fills shares[i] of every batch: an epoch
// is the most windows in which no set is used up (min over i of windows[i] / shares[i]), cut into whole batches of
// `batch` (one short batch when it is shorter); every set but the last takes round(share x windows so far) in total
// after each batch, the last the rest, so each set's count stays within one window of its share (with two sets, half a
// window).
std::vector<std::vector<size_t>> batch_counts(const std::vector<double>& shares, const std::vector<size_t>& windows,
                                              int batch);

}  // namespace t2imu
