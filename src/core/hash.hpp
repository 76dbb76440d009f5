// The project's stable 64-bit hashes and seed derivations, in one place: the same on every platform and
// compiler (unlike std::hash), so that a seed names the same split, body, sensor draw or dropout mask anywhere.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <string>

namespace t2imu {

// FNV-1a (offset basis 0xcbf29ce484222325, prime 0x100000001b3) of the bytes of `s`.
uint64_t fnv1a64(const std::string& s);

// SplitMix64's output function (Steele et al. 2014) on `z`: the generator's n-th output is
// splitmix64(seed + n * 0x9E3779B97F4A7C15).
uint64_t splitmix64(uint64_t z);

// MurmurHash3's 64-bit finaliser (fmix64): spreads the few bits in which nearby keys' FNV-1a hashes differ.
uint64_t murmur3_fmix64(uint64_t h);

// A seed of its own for each (seed, names...) combination, e.g. (seed, body, position, "mounting"): FNV-1a over
// the names, each followed by a 0xff byte (which no UTF-8 text holds, so ("ab", "c") and ("a", "bc") differ),
// started from 1469598103934665603 XOR `seed`. That start is FNV's offset basis 14695981039346656037 with its last
// digit lost when it was first written; it stays, since every synthesis recorded so far drew its seeds from it.
uint64_t derived_seed(uint64_t seed, std::initializer_list<std::string> names);

}  // namespace t2imu
