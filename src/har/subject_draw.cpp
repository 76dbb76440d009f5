#include "har/subject_draw.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "core/error.hpp"
#include "core/hash.hpp"

namespace t2imu {

std::vector<std::string> draw_subjects(const std::vector<std::string>& subjects, int count, uint64_t seed, int repeat) {
    const std::set<std::string> unique(subjects.begin(), subjects.end());
    for (const std::string& id : unique)  // a window's subject is "dataset:subject" (har/windowing.hpp)
        if (id.empty() || id.back() == ':')
            throw Error("--train-subjects", "subjects", "a data set whose recordings name their subject");
    if (count < 0 || static_cast<size_t>(count) >= unique.size())
        throw Error("--train-subjects", std::to_string(count),
                    "from 0 to " + std::to_string(static_cast<long>(unique.size()) - 1) + " (the set holds " +
                        std::to_string(unique.size()) + " subjects; at least one is left to test on)");
    std::vector<std::string> order(unique.begin(), unique.end());
    std::mt19937_64 rng(derived_seed(seed, {"train subjects", std::to_string(repeat)}));
    std::shuffle(order.begin(), order.end(), rng);
    order.resize(static_cast<size_t>(count));
    std::sort(order.begin(), order.end());
    return order;
}

void check_subject_split(const std::vector<std::vector<std::string>>& train_subjects,
                         const std::vector<std::string>& names, const std::vector<std::string>& test_subjects,
                         int test_set, int count) {
    const std::set<std::string> tested(test_subjects.begin(), test_subjects.end());
    for (size_t i = 0; i < train_subjects.size(); ++i) {
        if (static_cast<int>(i) == test_set) continue;
        for (const std::string& s : train_subjects[i])
            if (!s.empty() && tested.count(s))
                throw Error(
                    "--train", names[i],
                    "no subject of the --test set (" + s + " is in both; draw real subjects with --train-subjects)");
    }
    if (test_set >= 0) draw_subjects(test_subjects, count, 0, 0);
}

void check_shares(const std::vector<double>& shares, size_t sets, int batch, const std::string& option) {
    if (shares.empty()) return;
    if (shares.size() != sets)
        throw Error(option, std::to_string(shares.size()) + " shares",
                    std::to_string(sets) + " shares, one per --train");
    double total = 0;
    for (double s : shares) {
        if (!(s > 0 && s <= 1) || s * batch < 1)
            throw Error(option, std::to_string(s),
                        "a share above 0 and at most 1, at least one window of a batch of " + std::to_string(batch));
        total += s;
    }
    if (std::abs(total - 1) > 1e-6) throw Error(option, std::to_string(total), "shares that add up to 1");
}

std::vector<std::vector<size_t>> batch_counts(const std::vector<double>& shares, const std::vector<size_t>& windows,
                                              int batch) {
    double epoch = INFINITY;
    for (size_t i = 0; i < shares.size(); ++i)
        epoch = std::min(epoch, std::floor(static_cast<double>(windows[i]) / shares[i]));
    // Whole batches only (one short batch when the epoch is shorter than a batch).
    const size_t whole = static_cast<size_t>(epoch) / static_cast<size_t>(batch) * static_cast<size_t>(batch);
    const size_t total = whole > 0 ? whole : static_cast<size_t>(epoch);
    std::vector<std::vector<size_t>> counts;
    std::vector<size_t> before(shares.size(), 0);
    for (size_t done = 0; done < total;) {
        const size_t now = std::min(total, done + static_cast<size_t>(batch));
        std::vector<size_t> take(shares.size(), 0);
        size_t placed = 0;
        for (size_t i = 0; i + 1 < shares.size(); ++i) {
            const size_t cumulative = static_cast<size_t>(std::llround(shares[i] * static_cast<double>(now)));
            take[i] = cumulative - before[i];
            before[i] = cumulative;
            placed += take[i];
        }
        for (size_t i = 0; placed > now - done;
             i = (i + 1) % (shares.size() - 1))  // rounding up in 3+ sets overfilled it
            if (take[i] > 0) --take[i], --before[i], --placed;
        take.back() = now - done - placed;
        before.back() += take.back();
        counts.push_back(take);
        done = now;
    }
    return counts;
}

}  // namespace t2imu
