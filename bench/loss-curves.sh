#!/usr/bin/env bash
# The training step's two precisions trained side by side for their first 300 steps (experiments/train-default.toml,
# batch 64, from scratch): fp32 with seeds 0 and 1 (the loss curve's own noise: another seed draws other batches,
# t and noise) and bf16 with seed 0. Compared per window of 50 steps: the mean logged loss of bf16 against fp32's
# (same seed), and that gap against the gap between fp32's two seeds. Equal results: in every window the bf16
# gap is within the seed gap, or within 2 % of the loss. Writes cache/loss-curves/{fp32-s0,fp32-s1,bf16-s0}/ and
# prints one table row per window. Usage: bash bench/loss-curves.sh [STEPS] (default 300)
set -euo pipefail
cd "$(dirname "$0")/.."
steps=${1:-300}
out=cache/loss-curves
mkdir -p "$out"
for run in fp32-s0 fp32-s1 bf16-s0; do
  precision=${run%-*} seed=${run#*-s}
  sed -e "s|^out = .*|out = \"$out/$run\"|" -e "s|^seed = .*|seed = $seed\nprecision = \"$precision\"|" \
      -e "s|^log_every = .*|log_every = 1|" -e "s|^save_every = .*|save_every = 50|" experiments/train-default.toml > "$out/$run.toml"
  resume=""
  [ -f "$out/$run/checkpoint.pt" ] && resume=--resume
  build/t2imu train --config "$out/$run.toml" --steps "$steps" $resume --profile > "$out/$run.log"
done
# Mean loss per 50-step window of each run's metrics.jsonl (one line per step).
window() { sed -n 's/.*"loss":\([0-9.e+-]*\).*"step":\([0-9]*\).*/\2 \1/p' "$out/$1/metrics.jsonl" |
           awk '{ w = int(($1 - 1) / 50); s[w] += $2; n[w]++ } END { for (w in s) printf "%d %.6f\n", w, s[w] / n[w] }' | sort -n; }
join <(window fp32-s0) <(window fp32-s1) | join - <(window bf16-s0) |
  awk 'BEGIN { print "steps      fp32 s0   fp32 s1   bf16 s0   seed gap  bf16 gap  equal"; bad = 0 }
       { seed = $3 - $2; if (seed < 0) seed = -seed; gap = $4 - $2; if (gap < 0) gap = -gap;
         ok = (gap <= seed || gap <= 0.02 * $2); bad += !ok
         printf "%4d-%-4d %9.5f %9.5f %9.5f %9.5f %9.5f  %s\n", $1 * 50 + 1, $1 * 50 + 50, $2, $3, $4, seed, gap, ok ? "yes" : "NO" }
       END { exit bad > 0 }'
