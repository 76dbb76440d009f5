# Shared by the analysis scripts of this folder (Debian's python3-numpy and python3-scipy; not part of t2imu).
import csv, os
import numpy as np
from scipy import signal

CLASSES = ['walking', 'jogging', 'stairs_up_down', 'sit_down_stand_up', 'lying']


def load_waist_20hz(root):
    """[(activity, acc at 20 Hz [n, 3])] of a data set's waist recordings, which are at 50 Hz."""
    out = []
    for r in csv.DictReader(open(os.path.join(root, 'manifest.csv'))):
        if r['position'] != 'waist':
            continue
        assert float(r['rate_hz']) == 50, r['path']
        a = np.loadtxt(os.path.join(root, r['path']), delimiter=',', skiprows=1, ndmin=2)
        out.append((r['activity'], signal.resample_poly(a[:, 1:4], 2, 5, axis=0)))
    return out


def welch_20hz(x):
    """Per-axis Welch periodogram (2 s segments) of a recording at 20 Hz, its mean removed."""
    return signal.welch(x - x.mean(0), fs=20, nperseg=40, axis=0)
