// libtorch's intra-op thread count. Debian's libtorch starts with one thread unless told otherwise, so the CLI
// sets it from --threads (all cores by default). The header stays free of torch so main.cpp compiles fast.
#pragma once

namespace t2imu {

void set_torch_threads(int threads);
int torch_threads();

}  // namespace t2imu
