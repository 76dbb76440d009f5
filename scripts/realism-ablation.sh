#!/usr/bin/env bash
# The sensor-realism ablation (README, "Sensor realism"): the same retrieved motions for a data set's prompts,
# rendered with no realism model, each lever of the data set's preset alone, and the whole preset; per variant
# the signal statistics against the real data, the classifier two-sample test on catch22 windows, and
# synthetic-only HAR tested on the real recordings.
# Needs cache/dataset (t2imu data build), the GloVe vocabulary and the real set unpacked (scripts/paper-experiment.sh).
# Usage: bash scripts/realism-ablation.sh [OUT=out/realism-sisfall] [SET=sisfall] [REPEATS=3] [VARIANTS="none tilt ..."]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/realism-sisfall}
set=${2:-sisfall}
repeats=${3:-3}
variants=${4:-"none tilt landings landings+tissue tempo device all"}
real=cache/imu/$set
t2imu="build/t2imu --threads ${THREADS:-1}"
mkdir -p "$out/levers"

# One TOML per variant: the preset with the levers not named in the variant switched off. Variants name
# levers joined by "+": tilt, landings, tissue, tempo, device; "none" and "all" are the presets none and SET.
declare -A off=(
  [tilt]=$'tilt_deg = 0\ntilt_sd_deg = 0'
  [landings]='impact_gain = 0'
  [tissue]='tissue_hz = 0'
  [tempo]='tempo_sd = 0'
  [device]='device = "none"'
)
variant_file() {  # VARIANT -> path of its TOML
  local file="$out/levers/$1.toml"
  {
    echo "base = \"$set\""
    for lever in tilt landings tissue tempo device; do
      case "+$1+" in *"+$lever+"*) ;; *) echo "${off[$lever]}" ;; esac
    done
  } > "$file"
  echo "$file"
}

[ -f "$out/real-catch22.csv" ] || $t2imu features catch22 --dataset "$real" --positions waist --out "$out/real-catch22.csv"
for v in $variants; do
  case $v in
    none) realism=none ;;
    all) realism=$set ;;
    *) realism=$(variant_file "$v") ;;
  esac
  dir="$out/$v"
  mkdir -p "$dir"
  # As experiments/coverage.toml: 2 motions per prompt, no quality filter, the activity check's reference.
  $t2imu synth --prompts "prompts/$set.tsv" --model retrieval:cache/dataset --vocab cache/text/glove-100k.safetensors \
    --activity-reference models/motion-activity.csv --samples-per-prompt 2 --no-filter --sensors "$set" \
    --realism "$realism" --out "$dir/synth" > "$dir/synth.log"
  $t2imu analysis signal-stats --real "$real" --synthetic "$dir/synth" --position waist --out "$dir/signal-stats.json"
  [ -f "$dir/catch22.csv" ] || $t2imu features catch22 --dataset "$dir/synth" --positions waist --out "$dir/catch22.csv"
  $t2imu analysis domain-gap --real "$out/real-catch22.csv" --synthetic "$dir/catch22.csv" --out "$dir/gap.json"
  [ -f "$dir/har.json" ] || $t2imu har run --train "$dir/synth" --test "$real" --positions waist --repeats "$repeats" --out "$dir/har.json"
done
echo "realism ablation: $out"
