#include "data/splits.hpp"

#include <algorithm>
#include <vector>

#include "core/hash.hpp"

namespace t2imu {

namespace {

std::string source_of(const std::string& key) { return key.substr(0, key.find('/')); }

}  // namespace

std::map<std::string, Split> assign_splits(const std::map<std::string, int>& clips_per_key) {
    std::map<std::string, std::vector<std::pair<uint64_t, std::string>>> order;  // per source
    std::map<std::string, long> total;
    for (const auto& [key, n] : clips_per_key) {
        // Mixed: FNV-1a of keys that differ only in their last characters ("reactidle_000", "reactidle_001")
        // differ little in their high bits, so ordered by the raw hash they would be dealt into one split together.
        order[source_of(key)].push_back({murmur3_fmix64(fnv1a64(key)), key});
        total[source_of(key)] += n;
    }
    std::map<std::string, Split> out;
    for (auto& [source, keys] : order) {
        std::sort(keys.begin(), keys.end());
        long dealt = 0;
        for (const auto& [hash, key] : keys) {
            const double before = total[source] ? static_cast<double>(dealt) / static_cast<double>(total[source]) : 0.0;
            out[key] = before < 0.80 ? Split::train : before < 0.85 ? Split::val : Split::test;
            dealt += clips_per_key.at(key);
        }
    }
    return out;
}

const char* split_name(Split s) { return s == Split::train ? "train" : s == Split::val ? "val" : "test"; }

}  // namespace t2imu
