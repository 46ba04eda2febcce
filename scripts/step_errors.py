#!/usr/bin/env python3
"""How a trajectory errs over short steps, per axis of the camera frame.

Usage:
  scripts/step_errors.py GROUNDTRUTH ESTIMATE [--lag N]

Trajectories are TUM files of T_world_camera (t x y z qx qy qz qw). For every
pair of estimate poses N lines apart (1 by default; pairs more than N / 10 s
apart are skipped as gaps) whose times are in the ground truth, the relative
pose error E = (G_a^-1 G_b)^-1 (P_a^-1 P_b) is taken in the camera frame at a.
Prints the RMS of its translation (mm) and rotation (deg) per camera axis
(x right, y down, z forward), the mean translation error, and the
correlation of the sideways translation errors with the rotation about the
axis that moves the image the same way (x with y, y with x): near -1 or +1,
a translation error that is a turn in disguise (the monocular ambiguity of
far scenes). Needs python3-numpy (Debian).
"""
import argparse
import sys

import numpy as np


def rotation(q):
    x, y, z, w = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def load_poses(path):
    rows = np.loadtxt(path, comments="#")
    if rows.ndim != 2 or rows.shape[1] != 8:
        sys.exit(f"{path}: expected 8 columns (t x y z qx qy qz qw) per line")
    poses = np.repeat(np.eye(4)[None], len(rows), axis=0)
    for k, row in enumerate(rows):
        poses[k, :3, :3] = rotation(row[4:8])
        poses[k, :3, 3] = row[1:4]
    return rows[:, 0], poses


def small_angle(r):
    """The rotation vector of a small rotation matrix (rad)."""
    return 0.5 * np.array([r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1]])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("groundtruth")
    parser.add_argument("estimate")
    parser.add_argument("--lag", type=int, default=1)
    args = parser.parse_args()
    t_gt, g = load_poses(args.groundtruth)
    t_est, p = load_poses(args.estimate)
    # The simulator writes the truth at every sensor time, so poses pair exactly (to 0.1 ms).
    truth_index = {round(t, 4): k for k, t in enumerate(t_gt)}
    translation, rot = [], []
    for a in range(len(t_est) - args.lag):
        b = a + args.lag
        ga, gb = truth_index.get(round(t_est[a], 4)), truth_index.get(round(t_est[b], 4))
        if ga is None or gb is None or t_est[b] - t_est[a] > 0.1 * args.lag:
            continue
        step_true = np.linalg.inv(g[ga]) @ g[gb]
        step_est = np.linalg.inv(p[a]) @ p[b]
        e = np.linalg.inv(step_true) @ step_est
        translation.append(1000.0 * e[:3, 3])
        rot.append(np.degrees(small_angle(e[:3, :3])))
    if not translation:
        sys.exit(f"{args.estimate}: no pose pair found in {args.groundtruth}")
    translation, rot = np.array(translation), np.array(rot)
    rms = lambda v: np.sqrt((v ** 2).mean(0))
    print(f"{args.estimate}: {len(translation)} steps of {args.lag} frame(s)")
    print("  translation rms x y z (mm): " + " ".join(f"{v:.2f}" for v in rms(translation)) +
          f"   mean norm {np.linalg.norm(translation, axis=1).mean():.2f}")
    print("  rotation rms x y z (deg):   " + " ".join(f"{v:.4f}" for v in rms(rot)))
    print(f"  corr(t_x, r_y) {np.corrcoef(translation[:, 0], rot[:, 1])[0, 1]:+.2f}"
          f"   corr(t_y, r_x) {np.corrcoef(translation[:, 1], rot[:, 0])[0, 1]:+.2f}")


if __name__ == "__main__":
    main()
