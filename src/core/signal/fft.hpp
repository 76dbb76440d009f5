// A small iterative radix-2 FFT: enough for catch22's autocorrelation and periodogram, without an FFTW
// dependency. Lengths must be powers of two (callers zero-pad).
#pragma once
#include <complex>
#include <cstddef>
#include <vector>

namespace t2imu {

// The smallest power of two >= n (1 for n = 0).
std::size_t next_power_of_two(std::size_t n);

// In-place discrete Fourier transform, X_k = sum_t x_t exp(-2 pi i k t / N), or its inverse without the 1/N
// factor when `inverse` is true. data.size() must be a power of two.
void fft_in_place(std::vector<std::complex<double>>& data, bool inverse = false);

}  // namespace t2imu
