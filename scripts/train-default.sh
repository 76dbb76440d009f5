#!/usr/bin/env bash
# Reproduces the shipped text-to-motion models from the open motion capture:
#   models/default          MDM (4 layers x 256) + the GloVe text encoder (experiments/train-default.toml)
#   models/default-lacc     the default model fine-tuned with the paper's L_acc added, λ_acc = 0.01 (finetune-lacc.toml)
#   models/default-lacc-1   the same with λ_acc = 1 (finetune-lacc-1.toml), for the comparison in its model card
#   models/default-control  the default model trained on for as many steps without L_acc (finetune-control.toml)
#   models/default-v5       the default model trained on over the shared mocap v5 and the derived clips
#                           (finetune-v5.toml; the main job's model; its model card says how many steps shipped)
# and their per-sample L_acc on the test split (cache/lacc/*.csv; `t2imu analysis lacc` aggregates them).
# Usage: bash scripts/train-default.sh [--device cuda] [--base-steps N] [--finetune-steps N] [--mocap DIR]
# The shipped models came from a GPU run of the same steps (their model cards say which hardware and steps).
set -euo pipefail
cd "$(dirname "$0")/.."
device=cpu base_steps="" finetune_steps="" mocap="../shared/data/mocap"
while [ $# -gt 0 ]; do
  case "$1" in
    --device) device=$2; shift 2 ;;
    --base-steps) base_steps=$2; shift 2 ;;
    --finetune-steps) finetune_steps=$2; shift 2 ;;
    --mocap) mocap=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
t2imu="build/t2imu --device $device"
[ -f cache/text/glove-100k.safetensors ] || { echo "run scripts/setup.sh first (GloVe vocabulary)" >&2; exit 1; }
if [ ! -f cache/dataset/summary.json ]; then
  bash scripts/unpack-mocap.sh "$mocap" cache/mocap
  build/t2imu data build --mocap cache/mocap --mirror --out cache/dataset
fi
$t2imu train --config experiments/train-default.toml ${base_steps:+--steps $base_steps}
for run in lacc lacc-1 control v5; do
  $t2imu finetune --from models/default --config experiments/finetune-$run.toml ${finetune_steps:+--steps $finetune_steps}
done
mkdir -p cache/lacc
for model in default default-lacc default-lacc-1 default-control; do
  $t2imu eval-lacc --model models/$model --dataset cache/dataset --split test --seed 0 --out cache/lacc/$model.csv
done
