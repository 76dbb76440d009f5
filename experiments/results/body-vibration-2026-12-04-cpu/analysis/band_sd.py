# Per class and axis, the median over recordings of the sd in 0-2, 2-5 and 5-10 Hz (m/s^2), real and synthetic.
# Usage: python3 band_sd.py REAL_DATASET SYNTHETIC_DATASET
import sys
import numpy as np
from common import CLASSES, load_waist_20hz, welch_20hz

BANDS = [(0, 2), (2, 5), (5, 10.1)]


def band_sd(recordings, activity):
    rows = []
    for a, x in recordings:
        if a != activity or len(x) < 40:
            continue
        f, p = welch_20hz(x)
        df = f[1] - f[0]
        rows.append([np.sqrt(p[(f >= lo) & (f < hi)].sum(0) * df) for lo, hi in BANDS])
    return np.median(np.array(rows), 0)  # [band, axis]


real, synthetic = load_waist_20hz(sys.argv[1]), load_waist_20hz(sys.argv[2])
print('class, data: sd x/y/z in 0-2 Hz | 2-5 Hz | 5-10 Hz (m/s^2, median per recording)')
for c in CLASSES:
    for name, recs in [('real', real), ('synthetic', synthetic)]:
        b = band_sd(recs, c)
        print(c, name, ' | '.join(' '.join('%.2f' % v for v in band) for band in b))
