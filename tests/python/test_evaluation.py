"""slamkit.ate, rpe, evaluate, align, associate on trajectories built from arrays."""
import numpy as np
import pytest

import slamkit


def rotation_z(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])


def groundtruth(n=200):
    t = np.arange(n) * 0.05
    positions = np.stack([np.cos(t), np.sin(2 * t), 0.3 * t], axis=1)
    poses = np.tile(np.eye(4), (n, 1, 1))
    poses[:, :3, :3] = [rotation_z(a) for a in 0.5 * t]
    poses[:, :3, 3] = positions
    return slamkit.Trajectory(t, poses)


def moved(trajectory, rotation, translation, scale=1.0, noise=0.0, stamp_shift=0.0):
    """The trajectory in another frame: x -> scale * R x + t (with position noise, seeded)."""
    poses = trajectory.poses.copy()
    poses[:, :3, :3] = rotation @ poses[:, :3, :3]
    poses[:, :3, 3] = scale * poses[:, :3, 3] @ rotation.T + translation
    poses[:, :3, 3] += np.random.default_rng(7).normal(0, noise, poses[:, :3, 3].shape)
    return slamkit.Trajectory(trajectory.stamps + stamp_shift, poses)


R = rotation_z(0.7) @ np.array([[1, 0, 0], [0, 0, -1], [0, 1.0, 0]])
T = np.array([0.5, -2.0, 1.5])


def test_se3_alignment_recovers_a_known_transform():
    gt = groundtruth()
    result = slamkit.ate(gt, moved(gt, R, T))
    ate = result.metrics["ate"]
    assert ate["pairs"] == 200 and ate["rmse"] < 1e-12
    alignment = ate["alignment"]
    assert alignment["method"] == "se3" and alignment["scale"] == 1.0
    # The alignment maps the estimate back onto groundtruth: the inverse transform.
    np.testing.assert_allclose(alignment["rotation"], R.T, atol=1e-12)
    np.testing.assert_allclose(alignment["translation"], -R.T @ T, atol=1e-12)
    assert result.ate.trans_errors.shape == (200,) and result.ate.trans_errors.max() < 1e-12
    assert result.ate.est_positions.shape == (200, 3)
    np.testing.assert_allclose(result.ate.est_positions, gt.positions, atol=1e-12)
    assert result.rpe is None


def test_sim3_alignment_recovers_the_scale():
    gt = groundtruth()
    ate = slamkit.ate(gt, moved(gt, R, T, scale=2.5), align="sim3").metrics["ate"]
    assert ate["alignment"]["scale"] == pytest.approx(1 / 2.5, abs=1e-12)
    assert ate["rmse"] < 1e-12


def test_statistics_are_numpys_of_the_per_pose_errors():
    gt = groundtruth()
    result = slamkit.ate(gt, moved(gt, R, T, noise=0.01))
    e = result.ate.trans_errors
    ate = result.metrics["ate"]
    assert ate["rmse"] == pytest.approx(np.sqrt(np.mean(e ** 2)), rel=1e-12)
    assert ate["median"] == pytest.approx(np.median(e), rel=1e-12)
    assert ate["std"] == pytest.approx(np.std(e), rel=1e-12)
    assert ate["max"] == e.max()
    assert "path" not in result.metrics["inputs"]["estimate"]
    assert result.metrics["inputs"]["estimate"]["poses"] == 200
    assert result.metrics["settings"]["title"] == "groundtruth"


def test_rpe_of_a_rigidly_moved_trajectory_is_zero():
    gt = groundtruth()
    result = slamkit.rpe(gt, moved(gt, R, T), delta=0.5)
    rpe = result.metrics["rpe"]
    assert rpe["delta"] == 0.5 and rpe["unit"] == "s" and rpe["convention"] == "tum"
    assert rpe["trans"]["max"] < 1e-12 and rpe["pairs"] == len(result.rpe.trans_errors)
    np.testing.assert_allclose(result.rpe.stamps_j - result.rpe.stamps_i, 0.5, atol=1e-9)
    assert "ate" not in result.metrics


def test_evaluate_gives_both():
    gt = groundtruth()
    result = slamkit.evaluate(gt, moved(gt, R, T, noise=0.002), unit="f", delta=10,
                              convention="evo")
    assert set(result.metrics) == {"ate", "rpe", "settings", "inputs", "coverage"}
    assert result.metrics["settings"]["association"] == "evo"
    assert result.metrics["rpe"]["convention"] == "evo"


def test_format_options_read_kitti_files(tmp_path):
    gt = groundtruth(50)
    poses = tmp_path / "est.txt"
    np.savetxt(poses, moved(gt, R, T).poses[:, :3, :].reshape(-1, 12), fmt="%.17g")
    times = tmp_path / "times.txt"
    np.savetxt(times, gt.stamps, fmt="%.17g")
    r = slamkit.ate(gt, poses, est_format="kitti", times=times)
    assert r.metrics["ate"]["pairs"] == 50
    assert r.metrics["ate"]["rmse"] < 1e-9
    assert r.metrics["inputs"]["estimate"]["format"] == "kitti"
    with pytest.raises(ValueError, match="est_format: 'ply' is not one of tum, kitti, euroc"):
        slamkit.ate(gt, poses, est_format="ply")


def test_associate_pairs_within_the_tolerance():
    gt = groundtruth()
    est = moved(gt, R, T, stamp_shift=0.015)
    assert slamkit.associate(gt, est).shape == (200, 2)
    np.testing.assert_array_equal(slamkit.associate(gt, est)[:, 0], np.arange(200))
    assert slamkit.associate(gt, est, max_diff=0.01).shape == (0, 2)
    assert len(slamkit.associate(gt, est, max_diff=0.01, offset=-0.015)) == 200


def test_align_moves_the_whole_estimate():
    gt = groundtruth()
    aligned, alignment = slamkit.align(gt, moved(gt, R, T))
    np.testing.assert_allclose(aligned.poses, gt.poses, atol=1e-12)
    assert alignment["poses_used"] == 200


@pytest.mark.parametrize("call, message", [
    (lambda gt: slamkit.ate(gt, gt, delta=1), "ate() has no option 'delta'"),
    (lambda gt: slamkit.rpe(gt, gt, align_first=3), "rpe() has no option 'align_first'"),
    (lambda gt: slamkit.ate(gt, gt, align="affine"),
     "align: 'affine' is not one of se3, sim3, translation, none"),
    (lambda gt: slamkit.ate(gt, gt, max_diff=-1), "max_diff: -1.000000 is not a non-negative"),
    (lambda gt: slamkit.ate(gt, gt, planes="xw"), "planes: unknown plane 'xw'"),
    (lambda gt: slamkit.ate(gt, slamkit.Trajectory(gt.stamps + 100, gt.poses)),
     "estimate: only 0 estimated pose(s) matched groundtruth within 0.02 s"),
])
def test_bad_options_and_inputs_raise_value_error(call, message):
    with pytest.raises(ValueError) as raised:
        call(groundtruth())
    assert str(raised.value).startswith(message), str(raised.value)
