#include "diffusion/recover_from_ric_torch.hpp"

#include "core/error.hpp"

namespace t2imu {

using torch::indexing::None;
using torch::indexing::Slice;

torch::Tensor qrot_torch(const torch::Tensor& q, const torch::Tensor& v) {
    const torch::Tensor w = q.index({"...", Slice(0, 1)});
    const torch::Tensor u = q.index({"...", Slice(1, 4)}).expand_as(v);
    const torch::Tensor uv = torch::cross(u, v, -1);
    const torch::Tensor uuv = torch::cross(u, uv, -1);
    return v + 2 * (w * uv + uuv);
}

torch::Tensor recover_from_ric_torch(const torch::Tensor& x) {
    if (x.dim() != 3 || x.size(2) != 263)
        throw Error("recover_from_ric_torch", "features", "[batch, frames, 263]",
                    std::to_string(x.dim()) + " dimensions");
    const int64_t batch = x.size(0), frames = x.size(1);
    // Root yaw: channel 0 holds the half-angle per frame; frame 0 starts at 0.
    const torch::Tensor zeros = torch::zeros({batch, 1}, x.options());
    const torch::Tensor angle = torch::cat({zeros, x.index({Slice(), Slice(0, -1), 0}).cumsum(1)}, 1);  // [B, F]
    const torch::Tensor inv_root =
        torch::stack({angle.cos(), torch::zeros_like(angle), -angle.sin(), torch::zeros_like(angle)}, -1);
    // Root XZ: the previous frame's velocity, turned into the world by the inverse root rotation, summed.
    const torch::Tensor zero_v = torch::zeros({batch, 1}, x.options());
    const torch::Tensor vx = torch::cat({zero_v, x.index({Slice(), Slice(0, -1), 1})}, 1);
    const torch::Tensor vz = torch::cat({zero_v, x.index({Slice(), Slice(0, -1), 2})}, 1);
    const torch::Tensor v = torch::stack({vx, torch::zeros_like(vx), vz}, -1);
    const torch::Tensor root_xz = qrot_torch(inv_root, v).cumsum(1);  // [B, F, 3]; y is replaced below
    const torch::Tensor root =
        torch::stack({root_xz.index({"...", 0}), x.index({"...", 3}), root_xz.index({"...", 2})}, -1);
    // Joints 1..21: rotation-invariant positions turned back and moved to the root's XZ.
    const torch::Tensor ric = x.index({"...", Slice(4, 67)}).reshape({batch, frames, 21, 3});
    const torch::Tensor local = qrot_torch(inv_root.unsqueeze(2).expand({batch, frames, 21, 4}), ric);
    const torch::Tensor offset =
        torch::stack({root.index({"...", 0}), torch::zeros_like(angle), root.index({"...", 2})}, -1);
    return torch::cat({root.unsqueeze(2), local + offset.unsqueeze(2)}, 2);
}

}  // namespace t2imu
