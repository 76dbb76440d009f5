#include "nn/threads.hpp"

#include <torch/torch.h>

namespace t2imu {

void set_torch_threads(int threads) { at::set_num_threads(threads); }
int torch_threads() { return at::get_num_threads(); }

}  // namespace t2imu
