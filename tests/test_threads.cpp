// nn/threads.cpp: the one place libtorch's intra-op thread count is set (main.cpp calls it from --threads).
#include <gtest/gtest.h>

#include <torch/torch.h>

#include "nn/threads.hpp"

using namespace t2imu;

TEST(TorchThreads, SetIsWhatLibtorchUses) {
    const int before = torch_threads();
    set_torch_threads(2);
    EXPECT_EQ(torch_threads(), 2);
    EXPECT_EQ(at::get_num_threads(), 2);
    set_torch_threads(1);
    EXPECT_EQ(at::get_num_threads(), 1);
    set_torch_threads(before);
}
