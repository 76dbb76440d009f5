#!/usr/bin/env bash
# The main job on the shipped defaults: the RealWorld prompt set (8 activities x 10 prompts) -> models/default
# (DPM-Solver++, 50 steps, 6 s motions, quality filter on) -> the paper's eight bodies -> RealWorld's seven
# sensors at 50 Hz -> an IMU dataset in out/main-job/ (manifest.csv, recordings/, motions/ with BVH, report/).
# Interrupted, it resumes where it stopped. Usage: bash scripts/main-job.sh [OUT] [extra t2imu synth options]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/main-job}
shift || true
build/t2imu synth --prompts prompts/realworld.tsv --model models/default --bodies paper8 --sensors realworld --rate 50 --out "$out" "$@"
build/t2imu report --in "$out" --out "$out/report" >/dev/null
echo "main job: wrote $out (manifest.csv, recordings/, motions/, synth_report.json, report/index.html)"
