#!/usr/bin/env bash
# Reproduces the shipped text-to-motion models from the open motion capture:
#   models/base             MDM (4 layers x 256) + the GloVe text encoder trained from scratch
#                           (experiments/train-default.toml; ../shared/models/v5-gpu-b64 ran 11,262 steps on an H200)
#   models/default          the base fine-tuned with the default's recipe (experiments/default.toml)
#   models/lacc-sweep/*     the L_acc sweep from the base: lambda_acc 0.01, 0.1, 1 and a control without L_acc
#                           (experiments/lacc-sweep/*.toml); models/default-lacc is the sweep's best, copied
# and their per-sample L_acc on the test split (cache/lacc/*.csv; `t2imu analysis lacc` aggregates them).
# Usage: bash scripts/train-default.sh [--device cuda] [--base-steps N] [--finetune-steps N] [--mocap DIR]
#        [--max-minutes N]  (each training stops at that wall-time budget, saved, and the script with it, exit
#        75: the next training must not start from an unfinished one; rerun with the same options to continue)
set -euo pipefail
cd "$(dirname "$0")/.."
device=cpu base_steps=12000 finetune_steps="" mocap="../shared/data/mocap" budget=0
# Options are checked before anything runs: a step count of 0 would mean "the config's" to t2imu (100,000 steps).
usage() { echo "scripts/train-default.sh: $1" >&2; exit 2; }
steps() { [[ "$2" =~ ^[1-9][0-9]{0,8}$ ]] || usage "$1: expected a whole number of steps from 1 (got '$2')"; }
while [ $# -gt 0 ]; do
  case "$1" in
    --device | --base-steps | --finetune-steps | --mocap | --max-minutes)
      [ $# -ge 2 ] && [ -n "$2" ] || usage "$1: expected a value" ;;&
    --device) device=$2; shift 2 ;;
    --base-steps) steps "$1" "$2"; base_steps=$2; shift 2 ;;
    --finetune-steps) steps "$1" "$2"; finetune_steps=$2; shift 2 ;;
    --mocap) mocap=$2; shift 2 ;;
    --max-minutes)
      [[ "$2" =~ ^[0-9]+(\.[0-9]+)?$ ]] || usage "$1: expected minutes from 0 (got '$2')"
      budget=$2; shift 2 ;;
    *) usage "unknown option $1" ;;
  esac
done
t2imu="build/t2imu --device $device"
[ -f cache/text/glove-100k.safetensors ] || { echo "run scripts/setup.sh first (GloVe vocabulary)" >&2; exit 1; }
[ -f cache/mocap/manifest.csv ] || bash scripts/unpack-mocap.sh "$mocap" cache/mocap
# The base and the L_acc sweep train on the default build, the default's fine-tuning on it plus the lie-down rests.
[ -f cache/dataset/summary.json ] || build/t2imu data build --mocap cache/mocap --mirror --out cache/dataset
[ -f cache/dataset-lie-down/summary.json ] ||
  build/t2imu data build --mocap cache/mocap --mirror --lie-down-rests --out cache/dataset-lie-down
resume() { [ -f "$1/checkpoint.pt" ] && echo --resume || true; }
# Runs one training; when it stopped before its last step (the budget or a signal: `t2imu train` then says "stopped
# early"), so does the script, so no fine-tuning starts from a half-trained base.
log=$(mktemp)
trap 'rm -f "$log"' EXIT
training() {
  "$@" | tee "$log"
  if grep -q "stopped early" "$log"; then
    echo "scripts/train-default.sh: stopped early, saved; run it again with the same options to continue" >&2
    exit 75
  fi
}
training $t2imu train --config experiments/train-default.toml --steps "$base_steps" --max-minutes "$budget" \
  $(resume models/base)
training $t2imu finetune --from models/base --config experiments/default.toml ${finetune_steps:+--steps $finetune_steps} \
  --max-minutes "$budget" $(resume models/default)
for run in control lambda-0.01 lambda-0.1 lambda-1; do
  training $t2imu finetune --from models/base --config experiments/lacc-sweep/$run.toml \
    ${finetune_steps:+--steps $finetune_steps} --max-minutes "$budget" $(resume models/lacc-sweep/$run)
done
mkdir -p cache/lacc
for model in base default lacc-sweep/control lacc-sweep/lambda-0.01 lacc-sweep/lambda-0.1 lacc-sweep/lambda-1; do
  $t2imu eval-lacc --model models/$model --dataset cache/dataset --split test --seed 0 --out cache/lacc/${model//\//_}.csv
done
