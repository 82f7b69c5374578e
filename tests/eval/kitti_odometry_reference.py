"""An independent numpy re-implementation of the KITTI devkit's odometry metric
(evaluate_odometry.cpp: calcSequenceErrors with step 10, lengths 100..800 m), for
tests/eval/kitti_metric_e2e_test.cpp. Usage: kitti_odometry_reference.py GT EST; prints JSON."""
import json
import sys

import numpy as np


def load(path):
    rows = np.loadtxt(path, ndmin=2).reshape(-1, 3, 4)
    poses = np.tile(np.eye(4), (len(rows), 1, 1))
    poses[:, :3, :] = rows
    return poses


def main():
    gt, est = load(sys.argv[1]), load(sys.argv[2])
    steps = np.linalg.norm(np.diff(gt[:, :3, 3], axis=0), axis=1)
    dist = np.concatenate([[0.0], np.cumsum(steps)])
    per_length = {}
    for first in range(0, len(gt), 10):
        for length in range(100, 900, 100):
            beyond = np.nonzero(dist > dist[first] + length)[0]
            if len(beyond) == 0:
                continue
            last = beyond[0]
            gt_delta = np.linalg.inv(gt[first]) @ gt[last]
            est_delta = np.linalg.inv(est[first]) @ est[last]
            error = np.linalg.inv(est_delta) @ gt_delta
            angle = np.arccos(np.clip((np.trace(error[:3, :3]) - 1) / 2, -1, 1))
            per_length.setdefault(length, []).append(
                (np.linalg.norm(error[:3, 3]) / length, angle / length))
    everything = [e for errors in per_length.values() for e in errors]
    print(json.dumps({
        "segments": len(everything),
        "trans_pct": 100 * float(np.mean([e[0] for e in everything])),
        "rot_deg_per_m": float(np.degrees(np.mean([e[1] for e in everything]))),
        "lengths": [{"length_m": length, "segments": len(errors),
                     "trans_pct": 100 * float(np.mean([e[0] for e in errors])),
                     "rot_deg_per_m": float(np.degrees(np.mean([e[1] for e in errors])))}
                    for length, errors in sorted(per_length.items())],
    }))


if __name__ == "__main__":
    main()
