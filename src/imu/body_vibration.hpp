// Body vibration (realism.hpp's vibration lever): the broadband shaking a
// worn device picks up and motion capture does not: the device rattling in its belt clip or strap, skin and fat
// wobbling under it, footfalls travelling up the body. Captured markers are rigid clusters smoothed to 20-60 fps,
// so a virtual sensor on them is smoother than any real one above a few Hz.
//
// Why this form: on the shared SisFall subjects (waist, 20 Hz, median per recording of each axis's sd in 5-10
// Hz) the real board carries more there than the same retrieved motions through our sensor with the `sisfall`
// preset in every class, and the missing amount grows with how hard the body moves
// (docs/realism.md on body vibration). A stationary noise
// would swamp the quiet classes; a fixed filter of the captured signal cannot add content that is not there. So
// the vibration is Gaussian noise, band-limited to [low_hz, high_hz], whose sd follows the local level of the
// motion.
//
// Per recording, for each accelerometer axis (the gyroscope is left as it is):
//   level(t) = sqrt(mean over a 1 s window centred at t of |a_dyn|^2), a_dyn = a - its 1 s moving mean (m/s^2;
//              the window replicates the edge samples), the rms of the motion's acceleration apart from gravity
//              and posture;
//   n(t)     = white Gaussian noise shaped by the magnitude response of a zero-phase (forward-backward) second-
//              order Butterworth high-pass at low_hz and low-pass at high_hz, |G(f)| = (f/lo)^4 / (1 + (f/lo)^4)
//              x 1 / (1 + (f/hi)^4), then scaled to sd 1 over the recording;
//   a(t)    += gain x level(t) x n(t).
// A motionless sensor (level 0, up to the moving means' rounding) is left unchanged; gain 0 is off.
#pragma once
#include <cstdint>
#include <string>

#include "imu/imu_synthesis.hpp"

namespace t2imu {

struct BodyVibration {
    double gain = 0;    // vibration sd per m/s^2 of the motion's local rms level; 0 = off
    double low_hz = 5;  // band edges (Hz): the band where the real board exceeds ours most
    double high_hz = 12;
    bool enabled() const { return gain > 0; }  // ranges: realism.cpp's table
};

// Adds the vibration to s->acc (sampled at s->rate_hz). Deterministic in `seed`.
void add_body_vibration(const BodyVibration& vibration, uint64_t seed, ImuSignals* s);

}  // namespace t2imu
