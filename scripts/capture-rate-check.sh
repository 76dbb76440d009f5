#!/usr/bin/env bash
# Does the 20 fps motion chain lose the texture real belt sensors show? The same captured clips put through the
# same body and virtual waist sensor twice: once imported at 20 fps (HumanML3D's rate, what every source gives
# the sensors), once at the capture's native rate (Bandai Namco 30 fps walks, HDM05 120 fps jogs); each set's
# catch22 windows against the real SisFall walking / jogging windows (classifier two-sample test within the
# class) and its signal statistics beside the real ones.
# Usage: bash scripts/capture-rate-check.sh OUT   (needs cache/mocap, cache/imu/sisfall and the real features
# out/coverage-v5/features/real-sisfall.csv that `t2imu experiment --config experiments/coverage.toml` writes)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: capture-rate-check.sh OUT}
real_features=${REAL_FEATURES:-out/coverage-v5/features/real-sisfall.csv}
t2imu="build/t2imu --threads 1"
[ -f "$real_features" ] || { echo "$real_features: missing (the real SisFall catch22 table; set REAL_FEATURES)" >&2; exit 2; }
[ -f cache/imu/sisfall/manifest.csv ] || { echo "cache/imu/sisfall/manifest.csv: missing (unpack ../shared/data/imu/sisfall)" >&2; exit 2; }
mkdir -p "$out"
# The real windows of each class, once for both rates.
for activity in walking running; do
  head -1 "$real_features" > "$out/real-$activity.csv"
  awk -F, -v a="$activity" 'NR > 1 && $3 == a' "$real_features" >> "$out/real-$activity.csv"
done

# clip|activity|native fps|import options
clips() {
  for f in cache/mocap/bandai_bvh/dataset-*_walk_{normal,active}_*.bvh; do echo "$f|walking|30|"; done
  for f in cache/mocap/hdm05_amc/HDM_*_jogLeftCircle*_120.amc; do echo "$f|running|120|--source-fps 120"; done
}

for rate in 20 native; do
  set_dir="$out/fps-$rate"
  mkdir -p "$set_dir/recordings"
  manifest="$set_dir/manifest.csv.part"
  echo "path,dataset,subject,activity,position,rate_hz,n_samples,units" > "$manifest"
  i=0
  while IFS='|' read -r file activity native opts; do
    fps=$([ "$rate" = native ] && echo "$native" || echo 20)
    job=$(printf 'j%03d' $i); i=$((i + 1))
    # shellcheck disable=SC2086
    $t2imu motion import "$file" --fps "$fps" $opts --out "$set_dir/recordings/$job.npy"
    $t2imu imu synth --joints "$set_dir/recordings/$job.npy" --fps "$fps" --body preset:male_average --sensors sisfall \
      --rate 50 --out "$set_dir/recordings/$job" >/dev/null
    n=$(($(wc -l < "$set_dir/recordings/$job/male_average/waist.csv") - 1))
    echo "recordings/$job/male_average/waist.csv,t2imu,$job,$activity,waist,50,$n,acc=m/s^2(incl. gravity);gyr=rad/s;t=s" >> "$manifest"
  done < <(clips)
  mv "$manifest" "$set_dir/manifest.csv"
  $t2imu features catch22 --dataset "$set_dir" --out "$set_dir/features.csv"
  $t2imu analysis signal-stats --real cache/imu/sisfall --synthetic "$set_dir" --position waist --out "$set_dir/signal-stats.json"
  for activity in walking running; do
    head -1 "$set_dir/features.csv" > "$set_dir/syn-$activity.csv"
    awk -F, -v a="$activity" 'NR > 1 && $3 == a' "$set_dir/features.csv" >> "$set_dir/syn-$activity.csv"
    $t2imu analysis domain-gap --real "$out/real-$activity.csv" --synthetic "$set_dir/syn-$activity.csv" --out "$set_dir/gap-$activity.json"
  done
done
