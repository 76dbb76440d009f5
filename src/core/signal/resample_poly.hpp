// Rational-rate resampling by a polyphase FIR filter, with the semantics of scipy.signal.resample_poly(x, up,
// down, window=('kaiser', 5.0), padtype='line'): a Kaiser-windowed (beta 5) sinc low-pass of 20 * max(up, down)
// + 1 taps with its cut-off at the lower Nyquist rate, normalised to unit DC gain (times up), applied so that
// output sample i lies at input time i * down / up (zero phase); beyond both ends the signal continues the line
// through its first and last samples, so a trend or an offset (gravity) does not ring at the edges.
// Output length ceil(n * up / down). Used to bring real recordings to a common rate (SisFall 200 -> 50 Hz,
// HAR at 20 Hz).
#pragma once
#include <vector>

namespace t2imu {

std::vector<double> kaiser_lowpass(int taps, double cutoff_nyquist, double beta);  // scipy firwin semantics
std::vector<double> resample_poly(const std::vector<double>& x, int up, int down);

}  // namespace t2imu
