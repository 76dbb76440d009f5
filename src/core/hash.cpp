#include "core/hash.hpp"

namespace t2imu {

namespace {
constexpr uint64_t kFnvOffsetBasis = 0xcbf29ce484222325ull, kFnvPrime = 0x100000001b3ull;
}

uint64_t fnv1a64(const std::string& s) {
    uint64_t h = kFnvOffsetBasis;
    for (unsigned char c : s) h = (h ^ c) * kFnvPrime;
    return h;
}

uint64_t splitmix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

uint64_t murmur3_fmix64(uint64_t h) {
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ull;
    h ^= h >> 33;
    return h;
}

uint64_t derived_seed(uint64_t seed, std::initializer_list<std::string> names) {
    uint64_t h = 1469598103934665603ull ^ seed;  // see hash.hpp
    for (const std::string& s : names) {
        for (unsigned char c : s) h = (h ^ c) * kFnvPrime;
        h = (h ^ 0xff) * kFnvPrime;
    }
    return h;
}

}  // namespace t2imu
