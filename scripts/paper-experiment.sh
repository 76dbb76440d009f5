#!/usr/bin/env bash
# The paper's experiment on the open data we hold (SisFall waist, UMAFall waist): for each motion source —
# models/default (MDM), models/default-lacc (MDM fine-tuned with L_acc) and the retrieval baseline over the
# training set — synthesise the data set's own prompt set on the eight bodies at that data set's sensor, train
# DeepConvLSTM only on the synthetic data and test it on every real recording (balanced accuracy, REPEATS
# trainings); catch22 features of real and synthetic windows -> two-sample test and t-SNE; L_acc before/after
# per activity category on the test split; then the HTML report.
# Usage: bash scripts/paper-experiment.sh [RESULTS=out/experiment] [REPEATS=10] [SAMPLES_PER_PROMPT=2]
# Needs ../shared/data/imu (the real data) and, for the retrieval row and L_acc, cache/dataset
# (bash scripts/unpack-mocap.sh ../shared/data/mocap cache/mocap && build/t2imu data build --mocap cache/mocap --mirror --out cache/dataset).
set -euo pipefail
cd "$(dirname "$0")/.."
results=${1:-out/experiment} repeats=${2:-10} samples=${3:-2}
shared=${T2IMU_SHARED_DATA:-../shared/data}
t2imu=build/t2imu
mkdir -p "$results"/{synth,har,features,lacc} cache/imu
for set in sisfall umafall; do
  if [ ! -f cache/imu/$set/manifest.csv ]; then
    mkdir -p cache/imu/$set && tar -xJf "$shared/imu/$set/$set.tar.xz" -C cache/imu/$set
  fi
done
sources="default:models/default lacc:models/default-lacc"
[ -f cache/dataset/summary.json ] && sources="$sources retrieval:retrieval:cache/dataset"
for set in sisfall umafall; do
  $t2imu features catch22 --dataset cache/imu/$set --positions waist --out "$results/features/real-$set.csv"
  for s in $sources; do
    name=${s%%:*} model=${s#*:}
    out="$results/synth/$name-$set"
    $t2imu synth --prompts prompts/$set.tsv --samples-per-prompt "$samples" --model "$model" --sensors $set --out "$out"
    $t2imu har run --train "$out" --test cache/imu/$set --positions waist --repeats "$repeats" --out "$results/har/$name-$set.json"
    $t2imu features catch22 --dataset "$out" --positions waist --out "$results/features/$name-$set.csv"
    $t2imu analysis domain-gap --real "$results/features/real-$set.csv" --synthetic "$results/features/$name-$set.csv" \
      --out "$results/features/gap-$name-$set.json"
  done
done
if [ -f cache/dataset/summary.json ]; then
  for m in default default-lacc; do
    $t2imu eval-lacc --model models/$m --dataset cache/dataset --split test --seed 0 --out "$results/lacc/$m.csv"
  done
  $t2imu analysis lacc --before "$results/lacc/default.csv" --after "$results/lacc/default-lacc.csv" \
    --vocab cache/text/glove-100k.safetensors --tau 0.45 --out "$results/lacc/change.csv"
fi
$t2imu report --in "$results" --out "$results/report"
