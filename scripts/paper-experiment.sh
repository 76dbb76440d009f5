#!/usr/bin/env bash
# The paper's experiment on the open data we hold: prepares the data experiments/paper.toml names, then runs
#   t2imu experiment --config experiments/paper.toml --out RESULTS [--repeats REPEATS]
# (what it computes: src/pipeline/experiment.hpp). Rerun with the same RESULTS to continue a stopped run or to
# add repeats; finished steps are skipped.
# Usage: bash scripts/paper-experiment.sh [RESULTS=out/experiment] [REPEATS=the config's, 10]
# Needs ../shared/data/imu (the real data sets) and ../shared/data/mocap (the retrieval source and the L_acc clips).
set -euo pipefail
cd "$(dirname "$0")/.."
results=${1:-out/experiment} repeats=${2:-0}
shared=${T2IMU_SHARED_DATA:-../shared/data}
for set in sisfall umafall; do
  if [ ! -f cache/imu/$set/manifest.csv ]; then
    mkdir -p cache/imu/$set && tar -xJf "$shared/imu/$set/$set.tar.xz" -C cache/imu/$set
  fi
done
if [ ! -f cache/dataset/summary.json ]; then
  bash scripts/unpack-mocap.sh "$shared/mocap" cache/mocap
  build/t2imu data build --mocap cache/mocap --mirror --out cache/dataset
fi
build/t2imu experiment --config experiments/paper.toml --out "$results" --repeats "$repeats"
