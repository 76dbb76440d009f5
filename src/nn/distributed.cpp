#include "nn/distributed.hpp"

// The Torch package defines USE_C10D_GLOO on its users when libtorch was built with Gloo (Debian's is).
#ifndef USE_C10D_GLOO
#error "this libtorch has no c10d Gloo backend (USE_C10D_GLOO), which data-parallel training on the CPU needs"
#endif
#include <torch/version.h>
#include <torch/csrc/distributed/c10d/ProcessGroupGloo.hpp>
#include <torch/csrc/distributed/c10d/TCPStore.hpp>
#ifdef USE_C10D_NCCL
#include <torch/csrc/distributed/c10d/ProcessGroupNCCL.hpp>
#endif

#include "core/error.hpp"
#include "core/parse.hpp"

namespace t2imu {

namespace {

int env_int(const std::function<const char*(const char*)>& getenv, const char* name, int fallback, int low, int high) {
    const char* text = getenv(name);
    if (!text || !*text) return fallback;
    return static_cast<int>(integer_in(text, low, high, "environment", name));
}

bool is_loopback(const std::string& address) {
    return address == "localhost" || address.rfind("127.", 0) == 0 || address == "::1";
}

}  // namespace

ProcessGroupEnv read_process_group_env(const std::function<const char*(const char*)>& getenv) {
    ProcessGroupEnv e;
    e.world_size = env_int(getenv, "WORLD_SIZE", 1, 1, 1 << 20);
    e.rank = env_int(getenv, "RANK", 0, 0, e.world_size - 1);
    e.local_rank = env_int(getenv, "LOCAL_RANK", 0, 0, 1 << 20);
    if (e.world_size > 1 && !getenv("RANK"))
        throw Error("environment", "RANK", "this process's rank, as WORLD_SIZE is " + std::to_string(e.world_size));
    if (const char* addr = getenv("MASTER_ADDR")) e.master_addr = addr;
    e.master_port = env_int(getenv, "MASTER_PORT", 0, 1, 65535);
    if (e.world_size > 1 && (e.master_addr.empty() || e.master_port == 0))
        throw Error("environment", "MASTER_ADDR, MASTER_PORT",
                    "the address and port of rank 0's rendezvous, as WORLD_SIZE is " + std::to_string(e.world_size));
    return e;
}

BatchShare batch_share(int global_batch, int rank, int world_size) {
    if (world_size < 1 || rank < 0 || rank >= world_size)
        throw Error("environment", "RANK", "a rank in [0, WORLD_SIZE)", std::to_string(rank));
    if (global_batch % world_size != 0)
        throw Error(
            "training configuration", "train.batch",
            "a multiple of WORLD_SIZE = " + std::to_string(world_size) + " (every process takes an equal share)",
            std::to_string(global_batch));
    const int size = global_batch / world_size;
    return {rank * size, size};
}

struct DataParallel::Group {
    c10::intrusive_ptr<c10d::Store> store;
    // libtorch 2.x split the backends (Gloo, NCCL) off ProcessGroup into c10d::Backend; 1.13 (Debian's) derives
    // them from ProcessGroup. The collectives used here (allreduce, broadcast, barrier) exist on both.
#if TORCH_VERSION_MAJOR >= 2
    c10::intrusive_ptr<c10d::Backend> pg;
#else
    c10::intrusive_ptr<c10d::ProcessGroup> pg;
#endif
    bool tensors_on_host = true;  // Gloo is handed host tensors: a device buffer is staged through the CPU
    std::string backend;

    // Runs the all-reduce (sum) or broadcast on one flat buffer, in place.
    void sum(torch::Tensor& buffer) {
        torch::Tensor staged = tensors_on_host ? buffer.to(torch::kCPU) : buffer;
        std::vector<torch::Tensor> v{staged};
        pg->allreduce(v)->wait();
        if (!staged.is_same(buffer)) buffer.copy_(staged);
    }
    void broadcast(torch::Tensor& buffer) {
        torch::Tensor staged = tensors_on_host ? buffer.to(torch::kCPU) : buffer;
        std::vector<torch::Tensor> v{staged};
        pg->broadcast(v)->wait();  // BroadcastOptions' root is rank 0
        if (!staged.is_same(buffer)) buffer.copy_(staged);
    }
};

DataParallel::DataParallel(const ProcessGroupEnv& env, const torch::Device& device, std::chrono::milliseconds timeout)
    : env_(env) {
    if (env.world_size <= 1) return;
    const std::string where = env.master_addr + ":" + std::to_string(env.master_port);
    group_ = std::make_unique<Group>();
    try {
        c10d::TCPStoreOptions so;
        so.port = static_cast<std::uint16_t>(env.master_port);
        so.isServer = env.rank == 0;
        so.numWorkers = static_cast<std::size_t>(env.world_size);
        so.waitWorkers = true;
        so.timeout = timeout;
        group_->store = c10::make_intrusive<c10d::TCPStore>(env.master_addr, so);
#ifdef USE_C10D_NCCL
        if (device.is_cuda()) {
            auto options = c10d::ProcessGroupNCCL::Options::create();
            group_->pg = c10::make_intrusive<c10d::ProcessGroupNCCL>(group_->store, env.rank, env.world_size, options);
            group_->tensors_on_host = false;
            group_->backend = "nccl";
            return;
        }
#endif
        (void)device;
        // `timeout` bounds the rendezvous; a collective may wait torch's default (30 min) for a slower rank.
        auto options = c10d::ProcessGroupGloo::Options::create();
        // All ranks on one machine (MASTER_ADDR is a loopback address) talk over loopback; otherwise the
        // interface GLOO_SOCKET_IFNAME names, or the one this host's name resolves to (torch's own rule).
        if (const char* ifname = std::getenv("GLOO_SOCKET_IFNAME"))
            options->devices.push_back(c10d::ProcessGroupGloo::createDeviceForInterface(ifname));
        else if (is_loopback(env.master_addr))
            options->devices.push_back(c10d::ProcessGroupGloo::createDeviceForHostname(env.master_addr));
        else
            options->devices.push_back(c10d::ProcessGroupGloo::createDefaultDevice());
        group_->pg = c10::make_intrusive<c10d::ProcessGroupGloo>(group_->store, env.rank, env.world_size, options);
        group_->backend = "gloo";
    } catch (const std::exception& e) {
        throw Error(where, "rank " + std::to_string(env.rank) + " of " + std::to_string(env.world_size),
                    "a c10d process group with every rank", e.what());
    }
}

DataParallel::~DataParallel() = default;
DataParallel::DataParallel(DataParallel&&) noexcept = default;
DataParallel& DataParallel::operator=(DataParallel&&) noexcept = default;

std::string DataParallel::backend() const { return group_ ? group_->backend : "none"; }

void DataParallel::broadcast_from_main(const std::vector<torch::Tensor>& tensors) const {
    if (!group_ || tensors.empty()) return;
    torch::NoGradGuard no_grad;
    std::vector<torch::Tensor> flat;
    for (const torch::Tensor& t : tensors) flat.push_back(t.detach().reshape({-1}));
    torch::Tensor buffer = torch::cat(flat);
    group_->broadcast(buffer);
    int64_t at = 0;
    for (const torch::Tensor& t : tensors) {
        t.detach().copy_(buffer.slice(0, at, at + t.numel()).view(t.sizes()));
        at += t.numel();
    }
}

torch::Tensor DataParallel::average_gradients(const std::vector<torch::Tensor>& parameters,
                                              const torch::Tensor& riders) const {
    if (!group_) return riders;
    torch::NoGradGuard no_grad;
    // Layout: every gradient flattened (zeros where undefined), one "defined" flag per parameter, the riders.
    std::vector<torch::Tensor> parts;
    std::vector<float> defined;
    for (const torch::Tensor& p : parameters) {
        const torch::Tensor& g = p.grad();
        parts.push_back(g.defined() ? g.reshape({-1}).to(torch::kFloat32)
                                    : torch::zeros({p.numel()}, p.options().dtype(torch::kFloat32)));
        defined.push_back(g.defined() ? 1.0f : 0.0f);
    }
    const torch::Device device = parts.empty() ? riders.device() : parts.front().device();
    parts.push_back(torch::tensor(defined).to(device));
    parts.push_back(riders.reshape({-1}).to(device, torch::kFloat32));
    torch::Tensor buffer = torch::cat(parts);
    group_->sum(buffer);
    buffer.div_(static_cast<double>(env_.world_size));
    const int64_t n = static_cast<int64_t>(parameters.size()), flags = buffer.numel() - riders.numel() - n;
    const torch::Tensor used = buffer.slice(0, flags, flags + n).to(torch::kCPU);
    int64_t at = 0;
    for (int64_t i = 0; i < n; ++i) {
        torch::Tensor p = parameters[static_cast<size_t>(i)];
        const torch::Tensor mean = buffer.slice(0, at, at + p.numel()).view(p.sizes());
        at += p.numel();
        if (used[i].item<float>() == 0.0f) continue;  // unused on every rank
        if (p.grad().defined())
            p.mutable_grad().copy_(mean);
        else
            p.mutable_grad() = mean.to(p.dtype()).clone();
    }
    return buffer.slice(0, flags + n).to(riders.device());
}

void DataParallel::barrier() const {
    if (group_) group_->pg->barrier()->wait();
}

}  // namespace t2imu
