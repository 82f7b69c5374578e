"""slamkit.evaluate/ate/rpe/align against `slamkit eval` on the same files: the same metrics.json
(as the returned dict and as the file), the same CSVs and aligned.txt byte for byte, and the
same message for bad input."""
import json
import time

import numpy as np
import pytest

import slamkit
from conftest import cli_error, real_data, run_cli

REAL_PAIRS = [
    ("trajectories/fr1_xyz/groundtruth.txt", "trajectories/fr1_xyz/orbslam2_rgbd.txt"),
    ("trajectories/fr1_xyz/groundtruth.txt", "trajectories/fr1_xyz/rgbdslam.txt"),
    ("trajectories/fr2_desk/groundtruth.txt", "trajectories/fr2_desk/orbslam.txt"),
]
# (CLI options, the same as keyword options)
OPTION_SETS = [
    ([], {}),
    (["--convention", "evo", "--align", "sim3", "--unit", "f", "--delta", "10"],
     {"convention": "evo", "align": "sim3", "unit": "f", "delta": 10}),
    (["--align-first", "20", "--max-diff", "0.01", "--unit", "m", "--delta", "0.1"],
     {"align_first": 20, "max_diff": 0.01, "unit": "m", "delta": 0.1}),
]
FILES = ["metrics.json", "errors.csv", "rpe.csv", "aligned.txt"]


def synthetic_files(folder):
    """A groundtruth and a noisy, moved estimate at other stamps, as TUM files."""
    rng = np.random.default_rng(3)
    t = 1305031453.25 + np.arange(300) / 30
    positions = np.stack([np.cos(t), np.sin(t), 0.1 * (t - t[0])], axis=1)
    quaternions = rng.normal(size=(300, 4))
    gt = slamkit.Trajectory(t, positions=positions, quaternions=quaternions)
    est = slamkit.Trajectory(t[::2] + 0.004, positions=positions[::2] + rng.normal(0, 0.01, (150, 3)) + 2,
                             quaternions=quaternions[::2] + rng.normal(0, 0.01, (150, 4)))
    gt.write(folder / "gt.txt")
    est.write(folder / "est.txt", comment="a noisy estimate")
    return folder / "gt.txt", folder / "est.txt"


def check_same_as_cli(tmp_path, gt, est, cli_options, options):
    cli_out, py_out = tmp_path / "cli", tmp_path / "python"
    result = run_cli("eval", "all", gt, est, "--out", cli_out, "--no-plot", "--quiet", *cli_options)
    assert result.returncode == 0, result.stderr
    evaluation = slamkit.evaluate(str(gt), str(est), out=py_out, no_plot=True, **options)
    cli_metrics = json.loads((cli_out / "metrics.json").read_text())
    assert evaluation.metrics == cli_metrics
    for name in FILES:
        assert (py_out / name).read_bytes() == (cli_out / name).read_bytes(), name
    # The per-pose arrays are errors.csv's and rpe.csv's columns.
    errors = np.loadtxt(cli_out / "errors.csv", delimiter=",", skiprows=1, ndmin=2)
    np.testing.assert_allclose(evaluation.ate.trans_errors, errors[:, 1], rtol=1e-9, atol=1e-12)
    assert len(evaluation.rpe.trans_errors) == cli_metrics["rpe"]["pairs"]
    return evaluation


@pytest.mark.parametrize("cli_options, options", OPTION_SETS)
def test_synthetic_files_as_the_cli(tmp_path, cli_options, options):
    gt, est = synthetic_files(tmp_path)
    check_same_as_cli(tmp_path, gt, est, cli_options, options)


@pytest.mark.parametrize("pair", REAL_PAIRS)
@pytest.mark.parametrize("cli_options, options", OPTION_SETS)
def test_real_trajectories_as_the_cli(tmp_path, pair, cli_options, options):
    gt, est = (real_data(p) for p in pair)
    check_same_as_cli(tmp_path, gt, est, cli_options, options)


def test_trajectories_in_memory_give_the_same_metrics(tmp_path):
    gt_path, est_path = synthetic_files(tmp_path)
    from_files = slamkit.evaluate(str(gt_path), str(est_path))
    gt, est = slamkit.read_trajectory(gt_path), slamkit.read_trajectory(est_path)
    in_memory = slamkit.evaluate(gt, est, title=from_files.metrics["settings"]["title"],
                                 system_name="est")
    for section in ["ate", "rpe", "coverage"]:
        assert in_memory.metrics[section] == from_files.metrics[section]
    aligned, _ = slamkit.align(gt, est)
    run_cli("eval", "ate", gt_path, est_path, "--aligned", tmp_path / "cli_aligned.txt", "--quiet")
    aligned.write(tmp_path / "aligned.txt",
                  comment=f"estimate {est_path} aligned to {gt_path} (se3)")
    assert (tmp_path / "aligned.txt").read_bytes() == (tmp_path / "cli_aligned.txt").read_bytes()


def test_ate_and_rpe_alone_as_the_cli(tmp_path):
    gt, est = synthetic_files(tmp_path)
    for command, function in [("ate", slamkit.ate), ("rpe", slamkit.rpe)]:
        json_file = tmp_path / f"{command}.json"
        assert run_cli("eval", command, gt, est, "--json", json_file, "--quiet").returncode == 0
        assert function(str(gt), str(est)).metrics == json.loads(json_file.read_text())


BAD_LINES = {
    "not_a_number.txt": "1 0 0 0 0 0 0 1\n2 0 0 x 0 0 0 1\n",
    "seven_fields.txt": "1 0 0 0 0 0 0 1\n2 0 0 0 0 0 1\n",
    "nanoseconds.txt": "1305031453000000000 0 0 0 0 0 0 1\n1305031454000000000 1 0 0 0 0 0 1\n",
    "empty.txt": "# nothing\n",
}


@pytest.mark.parametrize("name", sorted(BAD_LINES))
def test_bad_files_raise_the_clis_message(tmp_path, name):
    gt, _ = synthetic_files(tmp_path)
    bad = tmp_path / name
    bad.write_text(BAD_LINES[name])
    message = cli_error("eval", "ate", gt, bad)
    with pytest.raises(ValueError) as raised:
        slamkit.ate(str(gt), str(bad))
    assert str(raised.value) == message


def test_missing_file_and_bad_out_folder_raise_the_clis_message(tmp_path):
    gt, est = synthetic_files(tmp_path)
    with pytest.raises(ValueError) as raised:
        slamkit.ate(str(gt), str(tmp_path / "missing.txt"))
    assert str(raised.value) == cli_error("eval", "ate", gt, tmp_path / "missing.txt")
    with pytest.raises(ValueError) as raised:
        slamkit.ate(str(gt), str(est), out=gt)
    assert str(raised.value) == cli_error("eval", "ate", gt, est, "--out", gt)


def test_plots_on_request(tmp_path):
    gt, est = synthetic_files(tmp_path)
    slamkit.evaluate(str(gt), str(est), plot=tmp_path / "plots")
    for figure in ["ate_over_time", "trajectory_xy", "rpe_over_time"]:
        assert (tmp_path / "plots" / f"{figure}.png").stat().st_size > 0, figure


def test_figure_formats_and_resolution_as_the_clis(tmp_path):
    gt, est = synthetic_files(tmp_path)
    slamkit.ate(str(gt), str(est), plot=tmp_path / "python", plot_format="pdf,png", dpi=50)
    result = run_cli("eval", "ate", gt, est, "--plot", tmp_path / "cli", "--plot-format", "pdf",
                     "--plot-format", "png", "--dpi", 50, "--quiet")
    assert result.returncode == 0, result.stderr
    names = sorted(p.name for p in (tmp_path / "python").iterdir())
    assert names == sorted(p.name for p in (tmp_path / "cli").iterdir())
    assert "ate_over_time.pdf" in names and not any(n.endswith(".svg") for n in names)
    png = "ate_over_time.png"
    assert (tmp_path / "python" / png).read_bytes() == (tmp_path / "cli" / png).read_bytes()
    with pytest.raises(ValueError, match="plot_format"):
        slamkit.ate(str(gt), str(est), plot=tmp_path / "bad", plot_format=["png", "eps"])


def test_a_million_poses_from_arrays(tmp_path, capsys):
    """ate() on arrays of 1,000,000 poses: the CLI's numbers, and both durations printed (not
    asserted: the machine is shared; the module was about 2x faster than the CLI here, which
    also parses the files)."""
    n = 1_000_000
    rng = np.random.default_rng(11)
    t = 1000 + np.arange(n) * 0.01
    positions = np.stack([np.cos(t / 10), np.sin(t / 7), 0.001 * t], axis=1)
    quaternions = rng.normal(size=(n, 4))
    noisy_positions = positions + rng.normal(0, 0.01, positions.shape)
    noisy_quaternions = quaternions + rng.normal(0, 0.01, quaternions.shape)
    slamkit.Trajectory(t, positions=positions, quaternions=quaternions).write(tmp_path / "gt.txt")
    slamkit.Trajectory(t + 0.001, positions=noisy_positions,
                       quaternions=noisy_quaternions).write(tmp_path / "est.txt")

    started = time.perf_counter()
    cli = run_cli("eval", "ate", tmp_path / "gt.txt", tmp_path / "est.txt", "--no-plot",
                  "--json", tmp_path / "metrics.json", "--quiet")
    cli_seconds = time.perf_counter() - started
    assert cli.returncode == 0, cli.stderr

    started = time.perf_counter()
    gt = slamkit.Trajectory(t, positions=positions, quaternions=quaternions)
    est = slamkit.Trajectory(t + 0.001, positions=noisy_positions, quaternions=noisy_quaternions)
    result = slamkit.ate(gt, est)
    python_seconds = time.perf_counter() - started

    # The files hold the arrays' stamps and positions exactly, so the translational statistics
    # are equal; the quaternions were normalised again on reading, so the rotational ones agree
    # to the digits the CLI prints.
    expected = json.loads((tmp_path / "metrics.json").read_text())["ate"]
    ate = result.metrics["ate"]
    assert ate["pairs"] == expected["pairs"] == n
    for key in ["rmse", "mean", "median", "std", "min", "max"]:
        assert ate[key] == expected[key], key
        assert f"{ate['rot_deg'][key]:.6f}" == f"{expected['rot_deg'][key]:.6f}", key
    with capsys.disabled():
        print(f"\n1,000,000 poses: slamkit eval ate {cli_seconds:.2f} s, slamkit.ate from arrays "
              f"{python_seconds:.2f} s ({python_seconds / cli_seconds:.2f}x)")
