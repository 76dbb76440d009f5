#!/usr/bin/env bash
# How far apart are two real data sets at one position? The scale for the realism tests: SisFall's belt board and
# UMAFall's waist tag, each put into the other's sensor axes (`t2imu data reframe`), compared on the classes both
# hold (walking, running, sitting down and standing up) as synthetic data is compared with real: the catch22
# classifier two-sample test within each class and pooled, and DeepConvLSTM trained on one real set and tested on
# the other, beside the same for a synthetic set of each (the results of `t2imu experiment`).
# Usage: bash scripts/cross-dataset-check.sh OUT SISFALL_RESULTS UMAFALL_RESULTS [REPEATS]
#   SISFALL_RESULTS, UMAFALL_RESULTS: `t2imu experiment` folders of one [[real]] set each (features/ and synth/);
#   needs cache/imu/sisfall and cache/imu/umafall (scripts/paper-experiment.sh unpacks them).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: cross-dataset-check.sh OUT SISFALL_RESULTS UMAFALL_RESULTS [REPEATS]}
sis=${2:?SISFALL_RESULTS}
uma=${3:?UMAFALL_RESULTS}
repeats=${4:-3}
t2imu="build/t2imu --threads ${THREADS:-2}"
classes=walking,running,sit_down_stand_up
for f in cache/imu/sisfall/manifest.csv cache/imu/umafall/manifest.csv "$sis/features/real-sisfall.csv" \
         "$uma/features/real-umafall.csv" "$sis/synth/retrieval-sisfall/manifest.csv" "$uma/synth/retrieval-umafall/manifest.csv"; do
  [ -f "$f" ] || { echo "$f: missing" >&2; exit 2; }
done
mkdir -p "$out"

$t2imu data reframe cache/imu/umafall --to sisfall --positions waist --out "$out/umafall-in-sisfall-axes"
$t2imu data reframe cache/imu/sisfall --to umafall --positions waist --out "$out/sisfall-in-umafall-axes"
$t2imu features catch22 --dataset "$out/umafall-in-sisfall-axes" --positions waist --out "$out/features-umafall-in-sisfall-axes.csv"

# The two-sample test, real SisFall against: real UMAFall, and the synthetic SisFall set; real UMAFall against
# its synthetic set.
$t2imu analysis domain-gap --real "$sis/features/real-sisfall.csv" --synthetic "$out/features-umafall-in-sisfall-axes.csv" \
  --classes $classes --out "$out/gap-sisfall-vs-umafall.json"
$t2imu analysis domain-gap --real "$sis/features/real-sisfall.csv" --synthetic "$sis/features/retrieval-sisfall.csv" \
  --classes $classes --out "$out/gap-sisfall-vs-synthetic.json"
$t2imu analysis domain-gap --real "$uma/features/real-umafall.csv" --synthetic "$uma/features/retrieval-umafall.csv" \
  --classes $classes --out "$out/gap-umafall-vs-synthetic.json"

# HAR on the shared classes: trained on the other real set, or on the synthetic set, tested on each real set.
har() { $t2imu har run --train "$1" --test "$2" --positions waist --classes $classes --repeats "$repeats" --out "$3"; }
har "$out/umafall-in-sisfall-axes" cache/imu/sisfall "$out/har-umafall-on-sisfall.json"
har "$sis/synth/retrieval-sisfall" cache/imu/sisfall "$out/har-synthetic-on-sisfall.json"
har "$out/sisfall-in-umafall-axes" cache/imu/umafall "$out/har-sisfall-on-umafall.json"
har "$uma/synth/retrieval-umafall" cache/imu/umafall "$out/har-synthetic-on-umafall.json"
