#!/usr/bin/env bash
# The test suite built with AddressSanitizer + UndefinedBehaviorSanitizer in build-sanitize/ (a build folder of
# its own: build/ is untouched) and run, so a read past a buffer or undefined behaviour fails a test instead of
# writing garbage; with --fuzz, then the CSV writer's fuzz target (clang, libFuzzer, the same sanitizers, in
# build-fuzz/) for 1 M inputs. docs/build.md says what it costs.
#   bash scripts/sanitize.sh                          # every test
#   bash scripts/sanitize.sh -R '^test_imu_dataset$'  # CTest arguments pick tests
#   bash scripts/sanitize.sh --fuzz                   # every test, then the writer fuzz target
#   bash scripts/sanitize.sh --fuzz-only              # the fuzz target alone (builds the torch-free library only)
set -euo pipefail
cd "$(dirname "$0")/.."
tests=1 fuzz=0
case "${1:-}" in
  --fuzz) fuzz=1; shift ;;
  --fuzz-only) tests=0; fuzz=1; shift ;;
esac
# libtorch's static caches outlive main: leaks are not what these runs look for. vptr checks need RTTI of
# libtorch's own (uninstrumented) classes, so they stay off.
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
flags="-fsanitize=address,undefined -fno-sanitize=vptr -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
if [ "$tests" = 1 ]; then
  if [ ! -f build-sanitize/build.ninja ]; then
    cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DT2IMU_BENCH=OFF \
      -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined"
  fi
  cmake --build build-sanitize --target t2imu t2imu_tests t2imu_torch_tests
  ctest --test-dir build-sanitize --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" "$@"
fi
if [ "$fuzz" = 1 ]; then
  if [ ! -f build-fuzz/build.ninja ]; then
    CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DT2IMU_FUZZ=ON -DT2IMU_TESTS=OFF -DT2IMU_BENCH=OFF
  fi
  cmake --build build-fuzz --target fuzz_imu_writer
  mkdir -p fuzz/corpus-imu_writer
  ./build-fuzz/fuzz_imu_writer -runs=1000000 -max_len=4096 -rss_limit_mb=2048 fuzz/corpus-imu_writer
fi
