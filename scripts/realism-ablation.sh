#!/usr/bin/env bash
# The sensor-realism ablation (README, "Sensor realism"): the same retrieved motions for a data set's prompts,
# rendered with no realism model, each lever alone, all of them and the data set's preset; per variant
# the signal statistics against the real data, the classifier two-sample test on catch22 windows, and
# synthetic-only HAR tested on the real recordings.
# Needs cache/dataset (t2imu data build), the GloVe vocabulary and the real set unpacked (scripts/paper-experiment.sh).
# Usage: bash scripts/realism-ablation.sh [OUT=out/realism-sisfall] [SET=sisfall] [REPEATS=3] [VARIANTS="none tilt ..."]
# BODIES=SPEC (environment) renders other bodies than the paper's eight, e.g. BODIES=population:8,seed=1;
# ROLL_GAIN=G the device roll lever's gain when on (default 0: the device does not roll with the pelvis's sway);
# CAPTURE_RATE=off renders retrieved clips at 20 fps (t2imu synth --no-capture-rate), as every run before
# 2026-12-03 did; by default the sensors see captured clips at their capture rate.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/realism-sisfall}
set=${2:-sisfall}
repeats=${3:-3}
variants=${4:-"none tilt landings landings+tissue tempo device all preset"}
real=cache/imu/$set
t2imu="${T2IMU_BIN:-build/t2imu} --threads ${THREADS:-1}"
mkdir -p "$out/levers"

# One TOML per variant, every lever set explicitly: on as below, off as 0 ("none" for the device). Tilt and
# device take the preset's values (src/imu/realism.cpp); the levers the presets leave off take the values they
# were measured with: landings calibrated on SisFall walking (share of power above 3 Hz 0.30 -> 0.47), soft tissue
# from the wobbling-mass literature (imu/soft_tissue.hpp), the strap mode calibrated on SisFall walking's lateral
# spectrum (6 Hz, damping 0.25: the real belt board's hump at 4-7 Hz, README "The belt's strap"), tempo 8 %, device roll gain 0 (imu/device_roll.hpp), the trunk's pitch and yaw
# sway at 0.35 and 0.6 (imu/trunk_sway.hpp: calibrated on SisFall walking's gyroscope), landings spread
# in size (log sd 0.3) and direction (horizontal sd 0.8 of the vertical; heel_strike.hpp) when "spread" is on, the
# device's own sample rate (imu/device_rate.hpp: UMAFall's tags log at 20 Hz, SisFall's board at 200 Hz,
# a phone at 50 Hz) when "rate" is on, body vibration at 0.15 of the motion's rms level in 5-12 Hz
# (imu/body_vibration.hpp: calibrated on SisFall's 5-10 Hz band) when "vibration" is on. Variants name levers joined by "+";
# "none" is no realism model, "all" every lever, "preset" the preset SET by name. (The strap and the trunk sway
# joined "all" on 2026-12-03, body vibration on 2026-12-04: results folders older than that hold "all" without them.)
declare -A on_off=(
  [tilt]=$'# preset tilt\n|tilt_deg = 0\ntilt_sd_deg = 0'
  [landings]="impact_gain = $([ "$set" = sisfall ] && echo 0.8 || echo 1.0)|impact_gain = 0"
  [tissue]=$'tissue_hz = 10\ntissue_damping = '"$([ "$set" = sisfall ] && echo 0.5 || echo 0.3)"'|tissue_hz = 0'
  [strap]=$'strap_hz = 6\nstrap_damping = 0.25|strap_hz = 0'
  [trunk]=$'trunk_pitch_gain = 0.35\ntrunk_yaw_gain = 0.6|trunk_pitch_gain = 1\ntrunk_yaw_gain = 1'
  [tempo]='tempo_sd = 0.08|tempo_sd = 0'
  [roll]="roll_gain = ${ROLL_GAIN:-0}|roll_gain = 1"
  [spread]=$'impact_size_sd = 0.3\nimpact_horizontal_sd = 0.8|impact_size_sd = 0\nimpact_horizontal_sd = 0'
  [device]=$'# preset device\n|device = "none"'
  [vibration]='vibration_gain = 0.15|vibration_gain = 0'
  [rate]="device_rate_hz = $(case $set in umafall) echo 20 ;; sisfall) echo 200 ;; *) echo 50 ;; esac)|device_rate_hz = 0"
)
variant_file() {  # VARIANT -> path of its TOML
  local file="$out/levers/$1.toml" lever pair
  {
    echo "base = \"$set\""
    for lever in tilt landings spread tissue strap trunk tempo roll vibration device rate; do
      pair=${on_off[$lever]}
      case "+$1+" in *"+$lever+"*|+all+) echo "${pair%%|*}" ;; *) echo "${pair#*|}" ;; esac
    done
  } > "$file"
  echo "$file"
}

[ -f "$out/real-catch22.csv" ] || $t2imu features catch22 --dataset "$real" --positions waist --out "$out/real-catch22.csv"
for v in $variants; do
  case $v in
    none) realism=none ;;
    preset) realism=$set ;;
    *) realism=$(variant_file "$v") ;;
  esac
  dir="$out/$v"
  mkdir -p "$dir"
  # As experiments/coverage.toml: 2 motions per prompt, no quality filter, the activity check's reference.
  $t2imu synth --prompts "prompts/$set.tsv" --model retrieval:cache/dataset --vocab cache/text/glove-100k.safetensors \
    --activity-reference models/motion-activity.csv --samples-per-prompt 2 --no-filter --sensors "$set" \
    --realism "$realism" --bodies "${BODIES:-paper8}" $([ "${CAPTURE_RATE:-on}" = off ] && echo --no-capture-rate) \
    --out "$dir/synth" > "$dir/synth.log"
  $t2imu analysis signal-stats --real "$real" --synthetic "$dir/synth" --position waist --out "$dir/signal-stats.json"
  [ -f "$dir/catch22.csv" ] || $t2imu features catch22 --dataset "$dir/synth" --positions waist --out "$dir/catch22.csv"
  $t2imu analysis domain-gap --real "$out/real-catch22.csv" --synthetic "$dir/catch22.csv" --out "$dir/gap.json"
  [ -f "$dir/har.json" ] || $t2imu har run --train "$dir/synth" --test "$real" --positions waist --repeats "$repeats" --out "$dir/har.json"
done
echo "realism ablation: $out"
