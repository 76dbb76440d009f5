#include "core/signal/fft.hpp"

#include <cmath>

#include "core/error.hpp"

namespace t2imu {

std::size_t next_power_of_two(std::size_t n) {
    std::size_t p = 1;
    while (p < n) p <<= 1;
    return p;
}

void fft_in_place(std::vector<std::complex<double>>& data, bool inverse) {
    const std::size_t n = data.size();
    if (n == 0 || (n & (n - 1)) != 0) throw Error("fft", "length", "a power of two", std::to_string(n));
    // Bit-reversal permutation, then Cooley-Tukey butterflies of doubling span.
    for (std::size_t i = 1, j = 0; i < n; ++i) {
        std::size_t bit = n >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) std::swap(data[i], data[j]);
    }
    const double sign = inverse ? 1.0 : -1.0;
    for (std::size_t span = 2; span <= n; span <<= 1) {
        const std::size_t half = span / 2;
        // Twiddles from cos/sin of each index rather than by repeated multiplication, which drifts.
        for (std::size_t k = 0; k < half; ++k) {
            const double angle = sign * 2.0 * M_PI * static_cast<double>(k) / static_cast<double>(span);
            const std::complex<double> w(std::cos(angle), std::sin(angle));
            for (std::size_t start = 0; start < n; start += span) {
                const std::complex<double> even = data[start + k];
                const std::complex<double> odd = w * data[start + k + half];
                data[start + k] = even + odd;
                data[start + k + half] = even - odd;
            }
        }
    }
}

}  // namespace t2imu
