// Samplers over an x0-predicting denoiser: MDM's ancestral DDPM loop and two few-step schemes, as free
// functions of (denoiser, x_T, schedule).
//
//   DDPM         every step T-1 .. 0: x_{t-1} ~ q(x_{t-1} | x_t, x0_hat) (FIXED_SMALL variance), as MDM samples.
//   DDIM         Song et al. 2021, K evenly spaced steps; eta = 0 is the deterministic probability-flow update,
//                eta = 1 adds DDPM-like noise.
//   DPM-Solver++ Lu et al. 2022, the 2M multistep data-prediction solver in log-SNR time: second order from
//                the second step on, using the previous step's x0 estimate.
// The few-step schedules visit t_k = round((T-1) (1 - k/(K-1))^2), k = 0..K-1 (quadratic spacing, as DDIM's
// paper uses: the cosine schedule's last steps span a wide range of noise levels, and evenly spaced steps waste
// evaluations there; measured on Gaussian data with its exact denoiser, the sample standard deviation ratio at
// K = 10/20/50 is DDIM 0.855/0.929/0.971 and DPM-Solver++ 2M 1.087/1.017/1.002 with quadratic spacing, against
// 0.777/0.888/0.955 and 1.365/1.185/1.039 with linear spacing). The K-th and last denoiser call, at t = 0, gives
// the sample (its x0 estimate), so K is the number of denoiser evaluations.
#pragma once
#include <torch/torch.h>
#include <functional>
#include <string>
#include <vector>

#include "diffusion/gaussian_diffusion.hpp"
#include "diffusion/sample_options.hpp"

namespace t2imu {

// x0 estimate for x_t at integer steps t ([B] int64); guidance, masks and text live inside the closure.
using X0Predictor = std::function<torch::Tensor(const torch::Tensor& x_t, const torch::Tensor& t)>;

// `noise` supplies the per-step Gaussian draws (e.g. seeded); it is asked for tensors shaped like x.
using NoiseSource = std::function<torch::Tensor(const torch::Tensor& like)>;

// `t_start`: the step x is at (-1 = T-1, pure noise). A smaller one continues a partly noised motion (SDEdit,
// Meng et al. 2022: the hybrid source noises a retrieved clip to t_start and lets the model finish it); DDPM
// then takes t_start + 1 steps, the few-step samplers their K evaluations spread over t_start .. 0.
torch::Tensor sample_ddpm(const GaussianDiffusion& diffusion, const X0Predictor& denoiser, torch::Tensor x_T,
                          const NoiseSource& noise, int t_start = -1);
torch::Tensor sample_ddim(const NoiseSchedule& schedule, const X0Predictor& denoiser, torch::Tensor x_T, int steps,
                          double eta, const NoiseSource& noise, int t_start = -1);
torch::Tensor sample_dpmpp_2m(const NoiseSchedule& schedule, const X0Predictor& denoiser, torch::Tensor x_T, int steps,
                              int t_start = -1);

// Descending, first t_start (-1 = T-1), last 0, quadratic spacing as above; at most t_start + 1 steps.
std::vector<int> sampling_timesteps(int schedule_steps, int steps, int t_start = -1);

}  // namespace t2imu
