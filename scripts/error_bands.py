#!/usr/bin/env python3
"""Where in frequency a trajectory's position error lives: drift or jitter.

Usage:
  scripts/error_bands.py GROUNDTRUTH ESTIMATE [ESTIMATE ...]
  scripts/error_bands.py --fusion-bound GROUNDTRUTH FIRST SECOND

Trajectories are TUM files (t x y z qx qy qz qw). Each estimate is aligned to
the ground truth by SE3 (Umeyama, positions only, as `lvslam eval --align
se3`), and the RMS of its position error along each world axis is printed per
frequency band (mm; Parseval over the real FFT of the error resampled at the
estimate's median rate).

--fusion-bound takes the frames both estimates have (SECOND is first aligned
onto FIRST, as a different map frame may hold it) and combines them band by
band and axis by axis with inverse-variance weights computed from their own
errors against the ground truth. No combination of the two positions by a
linear filter can do much better; it knows the truth, so it is a bound, not a
method. Prints the ATE mean of FIRST, SECOND and the combination on those
frames. Needs python3-numpy (Debian).
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


def aligned_error(p, g):
    """Error of positions p against the truth g at the same times, after SE3 alignment."""
    r, trans = umeyama_se3(p, g)
    return p @ r.T + trans - g


def band_masks(n, rate):
    freq = np.fft.rfftfreq(n, 1.0 / rate)
    return [(freq >= lo) & (freq < hi) for lo, hi in BANDS_HZ]


def band_rms(t, err, rate):
    grid = np.arange(t[0], t[-1], 1.0 / rate)
    e = interpolate(t, err, grid)
    e -= e.mean(0)
    n = len(e)
    # Parseval for the one-sided spectrum: mean(e^2) = sum(w_k |X_k|^2) / n^2,
    # w = 2 but for the DC and (n even) Nyquist bins.
    weight = np.full(n // 2 + 1, 2.0)
    weight[0] = 1.0
    if n % 2 == 0:
        weight[-1] = 1.0
    power = np.abs(np.fft.rfft(e, axis=0)) ** 2 * weight[:, None] / n**2
    return [np.sqrt(power[m].sum(0)) for m in band_masks(n, rate)]


def bands_table(gt_path, paths):
    t_gt, p_gt = load_tum(gt_path)
    header = "".join(f" | {lo:g}-{hi:g} Hz (x y z)" for lo, hi in BANDS_HZ)
    print(f"estimate | ATE mean (mm){header}")
    for path in paths:
        t, p = load_tum(path)
        inside = (t >= t_gt[0]) & (t <= t_gt[-1])
        t, p = t[inside], p[inside]
        err = aligned_error(p, interpolate(t_gt, p_gt, t))
        bands = band_rms(t, err, 1.0 / np.median(np.diff(t)))
        cells = "".join(" | " + " ".join(f"{v * 1000:.2f}" for v in b) for b in bands)
        print(f"{path} | {np.linalg.norm(err, axis=1).mean() * 1000:.2f}{cells}")


def fusion_bound(gt_path, first_path, second_path):
    t_gt, p_gt = load_tum(gt_path)
    t1, p1 = load_tum(first_path)
    t2, p2 = load_tum(second_path)
    common = np.intersect1d(np.round(t1, 6), np.round(t2, 6))
    common = common[(common >= t_gt[0]) & (common <= t_gt[-1])]
    a = p1[np.isin(np.round(t1, 6), common)]
    b = p2[np.isin(np.round(t2, 6), common)]
    r, trans = umeyama_se3(b, a)
    b = b @ r.T + trans
    g = interpolate(t_gt, p_gt, common)
    r, trans = umeyama_se3(a, g)  # one alignment for both: their errors share a frame
    ea, eb = a @ r.T + trans - g, b @ r.T + trans - g
    mean = ea.mean(0)
    fa, fb = np.fft.rfft(ea - mean, axis=0), np.fft.rfft(eb - mean, axis=0)
    rate = 1.0 / np.median(np.diff(common))
    combined = np.zeros_like(fa)
    for m in band_masks(len(common), rate):
        va, vb = (np.abs(fa[m]) ** 2).sum(0), (np.abs(fb[m]) ** 2).sum(0)
        w = vb / np.maximum(va + vb, 1e-30)
        combined[m] = w * fa[m] + (1 - w) * fb[m]
    fused = np.fft.irfft(combined, n=len(common), axis=0) + mean + g

    def ate(p):
        return np.linalg.norm(aligned_error(p, g), axis=1).mean() * 1000

    ate_a, ate_b, ate_f = ate(a), ate(b), ate(fused)
    print(f"{len(common)} frames in both; ATE mean: {first_path} {ate_a:.2f} mm, {second_path} "
          f"{ate_b:.2f} mm, band-wise inverse-variance bound {ate_f:.2f} mm ({(ate_f / ate_a - 1) * 100:+.1f} %)")


def main(argv):
    if len(argv) == 5 and argv[1] == "--fusion-bound":
        fusion_bound(*argv[2:])
    elif len(argv) >= 3 and not argv[1].startswith("--"):
        bands_table(argv[1], argv[2:])
    else:
        sys.exit("\n".join(__doc__.strip().splitlines()[2:5]))


if __name__ == "__main__":
    main(sys.argv)
