// The device's own sample rate (realism.hpp's rate lever). A real sensor samples at its rate, and whatever
// its signal holds above half that rate folds into the band: UMAFall's SensorTags log at 20 Hz, so a jog's
// footfalls (much of their power at 10-30 Hz at the waist) reach its recordings between 0 and 10 Hz. The virtual
// sensor is sampled at the device's rate (imu_synthesis.hpp: point samples, or box means over each interval with
// attachment dynamics), the device's errors are added there, and the recording is then brought to the rate the
// user asked for by the polyphase resampler the real recordings go through (core/signal/resample_poly.hpp).
#pragma once
#include "imu/imu_synthesis.hpp"

namespace t2imu {

// `s` (at s.rate_hz) at `rate_hz`: each axis by resample_poly with up / down from the two rates, which must be
// whole numbers of Hz; samples at k / rate_hz up to the last input instant. Equal rates return `s` unchanged.
ImuSignals resample_imu_signals(const ImuSignals& s, double rate_hz);

}  // namespace t2imu
