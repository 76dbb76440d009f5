# How far a linear, time-invariant filter of the synthetic signals can go: each synthetic recording's three axes
# are filtered (zero phase, by FFT) with gains sqrt(real / synthetic) of the mean Welch spectra at 20 Hz, taken
#   global: over all classes together (one filter per axis, as a device model would be),
#   class:  per class (a filter per class and axis, calibrated on the real data's labels),
#   nclass: per class, each recording's spectrum normalised to unit power first (catch22 z-normalises windows).
# Writes a copy of the synthetic data set at OUT. Usage: python3 linear_bound.py REAL SYNTHETIC OUT MODE
import csv, os, shutil, sys
import numpy as np
from common import CLASSES, load_waist_20hz, welch_20hz

real_root, synthetic_root, out, mode = sys.argv[1:5]
real, synthetic = load_waist_20hz(real_root), load_waist_20hz(synthetic_root)


def mean_spectrum(recordings, activity):
    spectra = []
    for a, x in recordings:
        if (mode != 'global' and a != activity) or len(x) < 40:
            continue
        f, p = welch_20hz(x)
        spectra.append(p / p.sum(0, keepdims=True) if mode == 'nclass' else p)
    return f, np.mean(spectra, 0)


gains = {}
for c in CLASSES:
    f, pr = mean_spectrum(real, c)
    _, ps = mean_spectrum(synthetic, c)
    g = np.sqrt(pr / ps)
    g[0] = 1.0  # gravity and posture pass unchanged
    gains[c] = (f, g)
os.makedirs(out, exist_ok=True)
shutil.copy(os.path.join(synthetic_root, 'manifest.csv'), out)
for r in csv.DictReader(open(os.path.join(synthetic_root, 'manifest.csv'))):
    a = np.loadtxt(os.path.join(synthetic_root, r['path']), delimiter=',', skiprows=1, ndmin=2)
    fs, acc = float(r['rate_hz']), a[:, 1:4]
    f, g = gains[r['activity']]
    fr = np.fft.rfftfreq(len(acc), 1 / fs)
    G = np.stack([np.interp(fr, f, g[:, i]) for i in range(3)], 1)  # beyond 10 Hz: the gain at 10 Hz
    mean = acc.mean(0)
    a[:, 1:4] = np.fft.irfft(np.fft.rfft(acc - mean, axis=0) * G, n=len(acc), axis=0) + mean
    os.makedirs(os.path.dirname(os.path.join(out, r['path'])), exist_ok=True)
    with open(os.path.join(out, r['path']), 'w') as fo:
        fo.write('t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n')
        np.savetxt(fo, a, delimiter=',', fmt='%.6g')
