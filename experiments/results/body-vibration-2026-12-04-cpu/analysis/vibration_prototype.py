# The prototype of body vibration used to scan its gain before src/imu/body_vibration.cpp existed: a copy of a
# synthetic data set with, on each accelerometer axis, Gaussian noise through a second-order Butterworth band-pass
# run forwards and backwards (scipy's filtfilt), scaled to sd 1, times gain x the motion's local rms level (the
# acceleration apart from its 1 s moving mean, rms over 1 s). Applied to 50 Hz recordings that already carry the
# device model's noise (the C++ lever adds it before the device's errors).
# Usage: python3 vibration_prototype.py SYNTHETIC OUT GAIN [LOW_HZ=5 HIGH_HZ=12]
import csv, os, shutil, sys
import numpy as np
from scipy import signal

src, dst, gain = sys.argv[1], sys.argv[2], float(sys.argv[3])
low, high = (float(sys.argv[4]), float(sys.argv[5])) if len(sys.argv) > 5 else (5.0, 12.0)
rng = np.random.default_rng(0)


def moving_mean(x, n):  # centred, edge samples repeated
    kernel = np.ones(n) / n
    return np.stack([np.convolve(np.pad(x[:, i], (n // 2, n - 1 - n // 2), mode='edge'), kernel, 'valid')
                     for i in range(x.shape[1])], 1)


os.makedirs(dst, exist_ok=True)
shutil.copy(os.path.join(src, 'manifest.csv'), dst)
for r in csv.DictReader(open(os.path.join(src, 'manifest.csv'))):
    a = np.loadtxt(os.path.join(src, r['path']), delimiter=',', skiprows=1, ndmin=2)
    fs, acc = float(r['rate_hz']), a[:, 1:4]
    n = int(fs)
    level = np.sqrt(moving_mean(((acc - moving_mean(acc, n)) ** 2).sum(1, keepdims=True), n))[:, 0]
    b, aa = signal.butter(2, [low / (fs / 2), min(high / (fs / 2), 0.99)], 'band')
    noise = signal.filtfilt(b, aa, rng.standard_normal(acc.shape), axis=0, padlen=min(3 * len(aa), len(acc) - 1))
    noise /= noise.std(0, keepdims=True) + 1e-12
    a[:, 1:4] = acc + gain * level[:, None] * noise
    os.makedirs(os.path.dirname(os.path.join(dst, r['path'])), exist_ok=True)
    with open(os.path.join(dst, r['path']), 'w') as fo:
        fo.write('t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n')
        np.savetxt(fo, a, delimiter=',', fmt='%.6g')
