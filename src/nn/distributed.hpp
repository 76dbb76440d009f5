// Data-parallel training over processes with torch's c10d: one process per rank, configured like torchrun
// (RANK, WORLD_SIZE, MASTER_ADDR, MASTER_PORT, LOCAL_RANK). Rank 0 hosts the rendezvous (a c10d TCPStore at
// MASTER_ADDR:MASTER_PORT); the collectives run over ProcessGroupGloo on the CPU, or ProcessGroupNCCL for CUDA
// tensors where the libtorch was built with it (USE_C10D_NCCL).
//
// Every rank holds the same weights (broadcast from rank 0 at the start), computes the gradient of its share of
// the global batch, and the shares' gradients are averaged before each optimiser step, so all ranks take the
// same step: with equal shares and a loss that is a mean of per-sample terms, the average of the ranks' mean
// gradients is the gradient of the global batch's mean.
#pragma once
#include <chrono>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <torch/torch.h>

namespace t2imu {

// torchrun's variables. With WORLD_SIZE unset (or 1) training runs in one process.
struct ProcessGroupEnv {
    int rank = 0, world_size = 1;
    int local_rank = 0;  // the rank among the processes on this machine: which GPU "cuda" means
    std::string master_addr;
    int master_port = 0;
};

// Reads the variables through `getenv` (the process environment by default). Refuses a RANK outside
// [0, WORLD_SIZE), and a WORLD_SIZE > 1 without MASTER_ADDR and MASTER_PORT.
ProcessGroupEnv read_process_group_env(const std::function<const char*(const char*)>& getenv = [](const char* name) {
    return std::getenv(name);
});

// The samples [begin, begin + size) of a global batch that `rank` computes. Refuses a batch that the ranks
// cannot share equally: unequal shares would weight the samples of the smaller shares more in the average.
struct BatchShare {
    int begin = 0, size = 0;
};
BatchShare batch_share(int global_batch, int rank, int world_size);

// The rank's process group; in one process (world size 1) every collective is a no-op.
class DataParallel {
public:
    DataParallel() = default;
    // Joins the group: blocks until all WORLD_SIZE ranks have reached MASTER_ADDR:MASTER_PORT, at most `timeout`
    // (then throws).
    // `device` is where the tensors handed to the collectives live.
    DataParallel(const ProcessGroupEnv& env, const torch::Device& device,
                 std::chrono::milliseconds timeout = std::chrono::minutes(5));
    ~DataParallel();
    DataParallel(DataParallel&&) noexcept;
    DataParallel& operator=(DataParallel&&) noexcept;

    int rank() const { return env_.rank; }
    int world_size() const { return env_.world_size; }
    bool is_main() const { return env_.rank == 0; }
    std::string backend() const;  // "gloo", "nccl", or "none" in one process

    // Overwrites `tensors` with rank 0's values (one flat buffer for all of them).
    void broadcast_from_main(const std::vector<torch::Tensor>& tensors) const;

    // After backward, before the optimiser step: replaces each parameter's gradient by its mean over the ranks,
    // in one all-reduce of a flat buffer. A gradient that is undefined on a rank (the parameter took no part in
    // its share, e.g. the text encoder when every caption of the share was dropped) counts as zero there, and
    // stays undefined only where it is undefined on every rank, as in one process with the whole batch.
    // `riders` (1-D, float32, the same length on every rank) travel in the same buffer; their means over the
    // ranks are returned (the loss terms for the log; a stop flag whose mean is > 0 when any rank asked).
    torch::Tensor average_gradients(const std::vector<torch::Tensor>& parameters, const torch::Tensor& riders) const;

    // Waits until every rank has reached it.
    void barrier() const;

private:
    struct Group;
    ProcessGroupEnv env_;
    std::unique_ptr<Group> group_;
};

}  // namespace t2imu
