#!/usr/bin/env bash
# catch22 windows of a synthetic data set against the real ones, two-sample test pooled and within each class.
# Usage (repository root): bash .../two_sample.sh SYNTHETIC REAL_FEATURES.csv WORKDIR
set -euo pipefail
syn=$1 real=$2 work=$3
mkdir -p "$work"
build/t2imu features catch22 --dataset "$syn" --positions waist --out "$work/features.csv" >/dev/null
line="pooled $(build/t2imu analysis domain-gap --real "$real" --synthetic "$work/features.csv" --out "$work/pooled.json" | grep -o '[0-9.]* (0.5' | cut -d' ' -f1)"
for c in walking running stairs sit_down_stand_up lying; do
  line="$line, $c $(build/t2imu analysis domain-gap --real "$real" --synthetic "$work/features.csv" --classes $c --out "$work/$c.json" | grep -o '[0-9.]* (0.5' | cut -d' ' -f1)"
done
echo "$line"
