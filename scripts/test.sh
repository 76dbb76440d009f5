#!/usr/bin/env bash
# Builds (if needed) and runs the whole test suite with CTest. Tests that need ../shared/data skip with a
# message when it is absent.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -f build/build.ninja ]; then cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release; fi
# The program and the test suite; the benchmarks (bench/README.md) build with `cmake --build build`.
cmake --build build --target t2imu t2imu_tests t2imu_torch_tests
jobs=$(nproc 2>/dev/null || echo 2)
ctest --test-dir build --output-on-failure -j "$jobs" "$@"
