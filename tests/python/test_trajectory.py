"""slamkit.Trajectory: arrays in and out, TUM, KITTI and EuRoC files read and written."""
import numpy as np
import pytest

import slamkit


def helix(n=100, step=0.1):
    """A camera on a helix turning about z: stamps, positions, quaternions (qx qy qz qw)."""
    t = np.arange(n) * step
    positions = np.stack([np.cos(t), np.sin(t), 0.2 * t], axis=1)
    half = t / 2
    quaternions = np.stack([0 * t, 0 * t, np.sin(half), np.cos(half)], axis=1)
    return t, positions, quaternions


def test_arrays_round_trip():
    stamps, positions, quaternions = helix()
    t = slamkit.Trajectory(stamps, positions=positions, quaternions=quaternions)
    assert len(t) == 100
    np.testing.assert_array_equal(t.stamps, stamps)
    np.testing.assert_array_equal(t.positions, positions)
    np.testing.assert_allclose(t.quaternions, quaternions, atol=1e-15)
    poses = t.poses
    assert poses.shape == (100, 4, 4)
    np.testing.assert_allclose(poses[:, :3, 3], positions)
    again = slamkit.Trajectory(stamps, poses)
    np.testing.assert_allclose(again.poses, poses, atol=1e-15)


def test_unsorted_stamps_are_sorted_and_quaternions_normalised():
    stamps, positions, quaternions = helix(5)
    order = [3, 0, 4, 1, 2]
    t = slamkit.Trajectory(stamps[order], positions=positions[order],
                           quaternions=2 * quaternions[order])
    assert t.was_unsorted
    np.testing.assert_array_equal(t.stamps, stamps)
    np.testing.assert_allclose(t.quaternions, quaternions, atol=1e-15)


@pytest.mark.parametrize("make, message", [
    (lambda s, p, q: slamkit.Trajectory(s, positions=p[:, :2], quaternions=q),
     "positions must have shape (100, 3), not (100, 2)"),
    (lambda s, p, q: slamkit.Trajectory(s, np.zeros((100, 3, 4))),
     "poses must have shape (100, 4, 4), not (100, 3, 4)"),
    (lambda s, p, q: slamkit.Trajectory(s, positions=p),
     "give either poses (N, 4, 4) or both positions (N, 3) and quaternions (N, 4)"),
    (lambda s, p, q: slamkit.Trajectory(np.where(s == s[7], np.nan, s), positions=p,
                                        quaternions=q),
     "stamps[7] holds nan: values must be finite and within 1e100"),
    (lambda s, p, q: slamkit.Trajectory(s, positions=p, quaternions=q * (s != s[4])[:, None]),
     "quaternions[4] is zero: not a rotation"),
    (lambda s, p, q: slamkit.Trajectory(np.where(s == s[2], s[1], s), positions=p,
                                        quaternions=q),
     "stamps[2] repeats the stamp 0.100000: each pose needs its own time"),
    (lambda s, p, q: slamkit.Trajectory(s, np.tile(np.diag([1.0, 1, 2, 1]), (100, 1, 1))),
     "poses[0] is not a rigid transform"),
])
def test_bad_arrays_raise_value_error_naming_them(make, message):
    with pytest.raises(ValueError) as raised:
        make(*helix())
    assert str(raised.value).startswith(message)


def test_write_and_read_back_exactly(tmp_path):
    stamps, positions, quaternions = helix()
    t = slamkit.Trajectory(1305031453.359684 + stamps, positions=positions,
                           quaternions=quaternions)
    path = tmp_path / "out" / "t.txt"
    t.write(path, comment="a helix")
    text = path.read_text()
    assert text.startswith("# a helix\n# timestamp tx ty tz qx qy qz qw\n1305031453.359684 1 0 0 0 0 0 1\n")
    back = slamkit.read_trajectory(path)
    np.testing.assert_array_equal(back.stamps, t.stamps)
    np.testing.assert_array_equal(back.positions, t.positions)
    # The writer turns quaternions to qw >= 0 and the reader normalises them again: the same
    # rotations, to the last bits.
    np.testing.assert_allclose(back.poses, t.poses, rtol=0, atol=1e-15)


def test_read_options_and_warnings(tmp_path):
    path = tmp_path / "ns.txt"
    path.write_text("1000000000 0 0 0 0 0 0 1\n2000000000 1 0 0 0 0 0 1\n"
                    "2000000000 2 0 0 0 0 0 1\n3000000000 nan 0 0 0 0 0 1\n")
    last = slamkit.read_trajectory(path, time_unit="ns")
    np.testing.assert_array_equal(last.stamps, [1.0, 2.0])
    assert last.positions[1, 0] == 2.0
    first = slamkit.read_trajectory(path, time_unit="ns", duplicate_stamps="first")
    assert first.positions[1, 0] == 1.0
    assert any("ns.txt:4" in w for w in last.warnings)
    with pytest.raises(ValueError, match="unknown time unit 'h'"):
        slamkit.read_trajectory(path, time_unit="h")


def test_kitti_and_euroc_files_read_as_the_tum_file_of_the_same_poses(tmp_path):
    stamps, positions, quaternions = helix(20)
    t = slamkit.Trajectory(stamps, positions=positions, quaternions=quaternions)
    kitti = tmp_path / "poses.txt"
    np.savetxt(kitti, t.poses[:, :3, :].reshape(-1, 12), fmt="%.17g")
    times = tmp_path / "times.txt"
    np.savetxt(times, stamps, fmt="%.17g")
    euroc = tmp_path / "data.csv"
    rows = np.column_stack([np.round(stamps * 1e9).astype(np.int64), positions,
                            quaternions[:, [3, 0, 1, 2]]])  # w first
    with open(euroc, "w") as f:
        f.write("#timestamp [ns],p_x,p_y,p_z,q_w,q_x,q_y,q_z\n")
        for r in rows:
            f.write("%d," % r[0] + ",".join("%.17g" % v for v in r[1:]) + "\n")
    for read in [slamkit.read_trajectory(kitti, times=times),  # detected: 12 fields
                 slamkit.read_trajectory(kitti, format="kitti", times=times),
                 slamkit.read_trajectory(euroc)]:  # detected: the header
        np.testing.assert_allclose(read.stamps, stamps, rtol=0, atol=1e-9)
        np.testing.assert_allclose(read.poses, t.poses, rtol=0, atol=1e-12)
    by_index = slamkit.read_trajectory(kitti)
    np.testing.assert_array_equal(by_index.stamps, np.arange(20))
    with pytest.raises(ValueError, match="unknown trajectory format 'ply'"):
        slamkit.read_trajectory(kitti, format="ply")


def test_kitti_and_euroc_files_written_read_back(tmp_path):
    stamps, positions, quaternions = helix()
    t = slamkit.Trajectory(1403715273.262142976 + stamps, positions=positions,
                           quaternions=quaternions)
    t.write(tmp_path / "kitti" / "poses.txt", format="kitti", times=tmp_path / "kitti" / "times.txt")
    t.write(tmp_path / "data.csv", format="euroc")
    # The nanosecond nearest to the stored stamp (a double holds it to about 0.24 us).
    assert (tmp_path / "data.csv").read_text().startswith(
        "#timestamp [ns],p_RS_R_x [m],p_RS_R_y [m],p_RS_R_z [m],q_RS_w [],q_RS_x [],q_RS_y [],"
        "q_RS_z []\n%d,1,0,0,1,0,0,0\n" % (1403715273 * 10**9 + 262142897))
    for back in [slamkit.read_trajectory(tmp_path / "kitti" / "poses.txt",
                                         times=tmp_path / "kitti" / "times.txt"),
                 slamkit.read_trajectory(tmp_path / "data.csv")]:
        np.testing.assert_array_equal(back.stamps, t.stamps)
        np.testing.assert_array_equal(back.positions, t.positions)
        np.testing.assert_allclose(back.poses, t.poses, rtol=0, atol=1e-15)
    with pytest.raises(ValueError, match="times"):
        t.write(tmp_path / "t.csv", format="euroc", times=tmp_path / "times.txt")
    with pytest.raises(ValueError, match="comment"):
        t.write(tmp_path / "p.txt", comment="a helix", format="kitti")


def test_bad_file_raises_value_error_with_file_and_line(tmp_path):
    path = tmp_path / "bad.txt"
    path.write_text("# header\n1 0 0 0 0 0 0 1\n2 0 0 zero 0 0 0 1\n")
    with pytest.raises(ValueError) as raised:
        slamkit.read_trajectory(path)
    assert str(raised.value).startswith(f"{path}:3: ")
    assert isinstance(raised.value, slamkit.InputError)
