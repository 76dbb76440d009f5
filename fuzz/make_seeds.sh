#!/usr/bin/env bash
# Writes small valid seed inputs for the fuzzers into fuzz/corpus-<target>/ (git-ignored), using the test
# binary's scratch outputs and the example BVH. Run after the test suite has run (scripts/test.sh).
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
# Release files (shared/data/imu/*/raw-sample), the head of each (the fuzzer's inputs stay small), manifests and
# job markers from the tests' scratch folders.
shared=../shared/data/imu
mkdir -p fuzz/corpus-sisfall fuzz/corpus-umafall fuzz/corpus-hugadb fuzz/corpus-imu_manifest fuzz/corpus-job_marker
for f in "$shared"/sisfall/raw-sample/D*.txt; do [ -f "$f" ] && head -n 60 "$f" > "fuzz/corpus-sisfall/$(basename "$f")"; done
find "$shared"/umafall/raw-sample -name 'UMAFall_*.csv' | head -2 | while read -r f; do head -n 80 "$f" > "fuzz/corpus-umafall/$(basename "$f")"; done
for f in "$shared"/hugadb/raw-sample/HuGaDB_*.txt; do [ -f "$f" ] && head -n 40 "$f" > "fuzz/corpus-hugadb/$(basename "$f")"; done
find "$scratch" -name manifest.csv -size -16k | head -10 | while read -r f; do cp "$f" "fuzz/corpus-imu_manifest/$(echo "$f" | md5sum | cut -c1-8).csv"; done
find "$scratch" -path '*/jobs/*.json' -size -16k | head -10 | while read -r f; do cp "$f" "fuzz/corpus-job_marker/$(echo "$f" | md5sum | cut -c1-8).json"; done
# RealWorld sensor archives the tests wrote (test_realworld, test_release_importers, test_cli_imu_synth).
mkdir -p fuzz/corpus-realworld
find "$scratch" -path '*/proband*/data/acc_*_csv.zip' -size -64k | head -10 | while read -r f; do cp "$f" "fuzz/corpus-realworld/$(echo "$f" | md5sum | cut -c1-8).zip"; done
