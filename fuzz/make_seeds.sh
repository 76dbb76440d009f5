#!/usr/bin/env bash
# Writes small valid seed inputs for the fuzzers into fuzz/corpus-<target>/ (git-ignored), using the test
# binary's scratch outputs and the example BVH. Run after a normal build (build/t2imu_tests has run).
set -eu  # no pipefail: `find | head` ends find with SIGPIPE once head has its files
cd "$(dirname "$0")/.."
scratch=build/test-tmp/scratch
mkdir -p fuzz/corpus-npy fuzz/corpus-npz fuzz/corpus-safetensors fuzz/corpus-bvh
find "$scratch" -name '*.npy' -size -64k | head -20 | xargs -r -I{} cp {} fuzz/corpus-npy/
find "$scratch" -name '*.npz' -size -64k | head -5 | xargs -r -I{} cp {} fuzz/corpus-npz/
find "$scratch" -name '*.safetensors' -size -64k | head -5 | xargs -r -I{} cp {} fuzz/corpus-safetensors/
head -c 20000 examples/cmu_07_05_slow_walk.bvh > fuzz/corpus-bvh/walk_head.bvh
cp examples/cmu_07_05_slow_walk.bvh fuzz/corpus-bvh/
find "$scratch" -name '*.bvh' -size -64k | head -5 | xargs -r -I{} cp {} fuzz/corpus-bvh/
mkdir -p fuzz/corpus-prompt_set fuzz/corpus-sensor_toml
cp prompts/*.tsv fuzz/corpus-prompt_set/
find "$scratch" -name '*.toml' -size -16k | head -10 | xargs -r -I{} cp {} fuzz/corpus-sensor_toml/
printf 'name = "belt"\n[[sensor]]\nposition = "waist"\nsegment = "pelvis"\nalong = 0.5\naround = -90\nx = "distal"\nz = "out"\n' > fuzz/corpus-sensor_toml/belt.toml
