#!/usr/bin/env bash
# The training step's two precisions trained side by side for their first 300 steps (experiments/train-default.toml,
# batch 64, from scratch, seed 0: the same batches, t and noise in both). Compared per window of 50 steps: the mean
# logged loss of bf16 against fp32's, and that gap against the noise of fp32's own curve, the standard error of its
# window mean (the sd of its per-step losses in the window over sqrt(50)). Equal results: in every window the gap
# is within two standard errors. Writes cache/loss-curves/{fp32-s0,bf16-s0}/ (a stopped run resumes) and prints
# one row per window; exits 1 when a window differs. Usage: bash bench/loss-curves.sh [STEPS] (default 300)
set -euo pipefail
cd "$(dirname "$0")/.."
steps=${1:-300}
out=cache/loss-curves
mkdir -p "$out"
for run in fp32-s0 bf16-s0; do
  precision=${run%-*} seed=${run#*-s}
  sed -e "s|^out = .*|out = \"$out/$run\"|" -e "s|^seed = .*|seed = $seed\nprecision = \"$precision\"|" \
      -e "s|^log_every = .*|log_every = 1|" -e "s|^save_every = .*|save_every = 50|" experiments/train-default.toml > "$out/$run.toml"
  resume=""
  [ -f "$out/$run/checkpoint.pt" ] && resume=--resume
  build/t2imu train --config "$out/$run.toml" --steps "$steps" $resume --profile > "$out/$run.log"
done
# step loss, one line per step of a run's metrics.jsonl
losses() { sed -n 's/.*"loss":\([0-9.e+-]*\).*"step":\([0-9]*\).*/\2 \1/p' "$out/$1/metrics.jsonl" | sort -n -u; }
join <(losses fp32-s0) <(losses bf16-s0) |
  awk 'BEGIN { print "steps      fp32 mean  bf16 mean   gap      fp32 s.e.  equal"; bad = 0 }
       { w = int(($1 - 1) / 50); n[w]++; a[w] += $2; aa[w] += $2 * $2; b[w] += $3 }
       END { for (w = 0; w in n; w++) {
               ma = a[w] / n[w]; mb = b[w] / n[w]; sd = sqrt((aa[w] - n[w] * ma * ma) / (n[w] - 1)); se = sd / sqrt(n[w])
               gap = mb - ma; ok = (gap < 0 ? -gap : gap) <= 2 * se; bad += !ok
               printf "%4d-%-4d %9.5f %9.5f %+9.5f %9.5f  %s\n", w * 50 + 1, w * 50 + n[w], ma, mb, gap, se, ok ? "yes" : "NO" }
             exit bad > 0 }'
