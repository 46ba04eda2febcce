#!/usr/bin/env python3
"""Where in frequency a trajectory's position error lives: drift or jitter.

Usage: scripts/error_bands.py GROUNDTRUTH.txt ESTIMATE.tum [ESTIMATE.tum ...]

Each estimate (TUM: t x y z qx qy qz qw) is aligned to the ground truth by
SE3 (Umeyama, positions only, as `lvslam eval --align se3`), its position
error is resampled onto a uniform grid at the estimate's median rate, and the
RMS of each world axis is printed per frequency band (mm; Parseval over the
real FFT). Bands that hold most of an estimate's error are where a second
estimate would have to be better to help it. Needs python3-numpy (Debian).
"""
import sys

import numpy as np

BANDS_HZ = [(0.0, 0.1), (0.1, 0.5), (0.5, 2.0), (2.0, 4.0), (4.0, 7.5)]


def load_tum(path):
    rows = np.loadtxt(path, comments="#")
    if rows.ndim != 2 or rows.shape[1] != 8:
        sys.exit(f"{path}: expected 8 columns (t x y z qx qy qz qw) per line")
    return rows[:, 0], rows[:, 1:4]


def interpolate(t_src, p_src, t):
    return np.stack([np.interp(t, t_src, p_src[:, k]) for k in range(3)], axis=1)


def umeyama_se3(src, dst):
    """R, t minimising |R src + t - dst|^2 (Umeyama 1991, without scale)."""
    mu_s, mu_d = src.mean(0), dst.mean(0)
    u, _, vt = np.linalg.svd((dst - mu_d).T @ (src - mu_s) / len(src))
    s = np.eye(3)
    if np.linalg.det(u) * np.linalg.det(vt) < 0:
        s[2, 2] = -1
    r = u @ s @ vt
    return r, mu_d - r @ mu_s


def band_rms(t, err, rate):
    grid = np.arange(t[0], t[-1], 1.0 / rate)
    e = interpolate(t, err, grid)
    e -= e.mean(0)
    spectrum = np.abs(np.fft.rfft(e, axis=0)) ** 2
    freq = np.fft.rfftfreq(len(e), 1.0 / rate)
    # Parseval for the one-sided spectrum: mean(e^2) = sum(2 |X_k|^2) / n^2 (DC and Nyquist once).
    weight = np.full(len(freq), 2.0)
    weight[0] = 1.0
    if len(e) % 2 == 0:
        weight[-1] = 1.0
    power = spectrum * weight[:, None] / len(e) ** 2
    return [np.sqrt(power[(freq >= lo) & (freq < hi)].sum(0)) for lo, hi in BANDS_HZ]


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__.strip().splitlines()[2])
    t_gt, p_gt = load_tum(argv[1])
    header = "".join(f" | {lo:g}-{hi:g} Hz (x y z)" for lo, hi in BANDS_HZ)
    print(f"estimate | ATE mean (mm){header}")
    for path in argv[2:]:
        t, p = load_tum(path)
        inside = (t >= t_gt[0]) & (t <= t_gt[-1])
        t, p = t[inside], p[inside]
        g = interpolate(t_gt, p_gt, t)
        r, trans = umeyama_se3(p, g)
        err = p @ r.T + trans - g
        rate = 1.0 / np.median(np.diff(t))
        bands = band_rms(t, err, rate)
        cells = "".join(" | " + " ".join(f"{v * 1000:.2f}" for v in b) for b in bands)
        print(f"{path} | {np.linalg.norm(err, axis=1).mean() * 1000:.2f}{cells}")


if __name__ == "__main__":
    main(sys.argv)
