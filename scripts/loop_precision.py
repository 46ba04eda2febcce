#!/usr/bin/env python3
"""Precision and recall of loop closure in `lvslam run` output folders.

Usage:
  scripts/loop_precision.py RUN_DIR [RUN_DIR ...] [--revisit M] [--false M] [--exclude M]

Each RUN_DIR holds stats.json (its `loop` section: keyframe times and the
candidate log) and groundtruth.tum (the ground truth in the frame of
trajectory.tum, which `lvslam run` writes for a recording with ground truth).
An accepted loop is false when the true positions of its two keyframes are
more than --false metres apart (1.5). A keyframe is a revisit when an earlier
keyframe at least --exclude metres of true path behind it (15, the default
loop.exclude_recent_path) lies within --revisit metres (1.0); recall is the
share of revisits that closed a loop. Plain python3, no numpy.
"""
import argparse
import bisect
import json
import math
import os
import sys


def read_tum(path):
    times, positions = [], []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if not fields or fields[0].startswith('#'):
                continue
            times.append(float(fields[0]))
            positions.append(tuple(float(v) for v in fields[1:4]))
    return times, positions


def position_at(times, positions, t):
    i = bisect.bisect_left(times, t)
    if i <= 0:
        return positions[0]
    if i >= len(times):
        return positions[-1]
    s = (t - times[i - 1]) / (times[i] - times[i - 1])
    return tuple(a + s * (b - a) for a, b in zip(positions[i - 1], positions[i]))


def path_lengths(points):
    lengths = [0.0]
    for a, b in zip(points, points[1:]):
        lengths.append(lengths[-1] + math.dist(a, b))
    return lengths


def evaluate(run_dir, args):
    with open(os.path.join(run_dir, 'stats.json')) as f:
        loop = json.load(f).get('loop')
    if loop is None:
        sys.exit(f'{run_dir}/stats.json: no loop section (loop closure off, or a run without LiDAR)')
    if 'keyframe_t' not in loop:
        sys.exit(f'{run_dir}/stats.json: the loop section has no keyframe_t (written by an older lvslam)')
    times, positions = read_tum(os.path.join(run_dir, 'groundtruth.tum'))
    keyframes = [position_at(times, positions, t) for t in loop['keyframe_t']]
    path = path_lengths(keyframes)
    revisits = {q for q in range(len(keyframes))
                if any(path[q] - path[k] >= args.exclude and math.dist(keyframes[q], keyframes[k]) <= args.revisit
                       for k in range(q))}
    accepted = [c for c in loop['candidate_log'] if c['accepted']]
    false = [c for c in accepted if math.dist(keyframes[c['query']], keyframes[c['candidate']]) > args.false]
    closed = {c['query'] for c in accepted} - {c['query'] for c in false}
    return len(keyframes), len(revisits), len(accepted), len(false), len(closed & revisits)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('runs', nargs='+')
    parser.add_argument('--revisit', type=float, default=1.0)
    parser.add_argument('--false', type=float, default=1.5)
    parser.add_argument('--exclude', type=float, default=15.0)
    args = parser.parse_args()
    total = [0, 0, 0, 0, 0]
    print('| run | keyframes | revisits | accepted | false | recall |')
    print('|---|---:|---:|---:|---:|---:|')
    for run in args.runs:
        row = evaluate(run, args)
        total = [a + b for a, b in zip(total, row)]
        recall = f'{100.0 * row[4] / row[1]:.0f} %' if row[1] else '-'
        print(f'| {os.path.basename(os.path.normpath(run))} | {row[0]} | {row[1]} | {row[2]} | {row[3]} | {recall} |')
    recall = f'{100.0 * total[4] / total[1]:.0f} %' if total[1] else '-'
    print(f'| all | {total[0]} | {total[1]} | {total[2]} | {total[3]} | {recall} |')


if __name__ == '__main__':
    main()
