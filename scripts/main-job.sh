#!/usr/bin/env bash
# The main job on the shipped defaults. Until the text-to-motion model ships (issue: main job), it runs the
# motion and IMU stages on a shipped CMU walk: BVH import -> SMPL-22 joints -> HumanML3D 263-dim features ->
# joints -> BVH export, and the joints on the paper's eight bodies with RealWorld's seven sensors.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/main-job}
mkdir -p "$out"
t2imu=build/t2imu
$t2imu motion import examples/cmu_07_05_slow_walk.bvh --out "$out/joints.npy"
$t2imu motion features --joints "$out/joints.npy" --out "$out/features.npy"
$t2imu motion joints --features "$out/features.npy" --out "$out/recovered_joints.npy"
$t2imu motion export "$out/recovered_joints.npy" --out "$out/recovered.bvh"
$t2imu imu synth --joints "$out/recovered_joints.npy" --body paper8 --sensors realworld --rate 50 --out "$out/imu"
echo "main job: wrote $out/{joints.npy,features.npy,recovered_joints.npy,recovered.bvh,imu/}"
