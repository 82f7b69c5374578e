"""slamkit.run and slamkit.track against `slamkit run` and `slamkit track`: the same run folder,
byte for byte (but for the files that hold times), arrays equal to the files, progress,
Ctrl-C and the GIL."""
import json
import os
import pathlib
import shutil
import signal
import tempfile
import threading
import time

import numpy as np
import pytest

import slamkit
from conftest import cli_error, run_cli

# Written with the time they took or the day they were made.
TIMED_FILES = {"run.json", "timing.json", "tracking.csv", "mapping.csv", "report.html"}


@pytest.fixture(scope="module")
def sequence(tmp_path_factory):
    return slamkit.synth("loop", 30, 3, out=tmp_path_factory.mktemp("synth") / "loop30")


def folder_bytes(folder):
    return {str(p.relative_to(folder)): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file() and p.name not in TIMED_FILES}


def pose_lines(text):
    return [line for line in text.splitlines() if not line.startswith(b"#")]


def run_json(folder):
    return json.loads((folder / "run.json").read_text())


@pytest.mark.parametrize("command", ["run", "track"])
def test_a_run_from_python_writes_the_folder_the_cli_writes(tmp_path, sequence, command):
    # The same folder name for both: metrics.json and aligned.txt name the files they read.
    cli = run_cli(command, sequence.folder, "--out", tmp_path / "run", "--threads", 1)
    assert cli.returncode == 0, cli.stderr
    cli_files = folder_bytes(tmp_path / "run")
    shutil.rmtree(tmp_path / "run")
    result = getattr(slamkit, command)(sequence, {"pipeline": {"threads": 1}}, tmp_path / "run")
    python_files = folder_bytes(tmp_path / "run")
    assert python_files == cli_files
    assert {"trajectory.txt", "keyframes.txt", "metrics.json"} <= set(python_files)
    assert run_json(tmp_path / "run")["status"] == "complete"
    # The arrays are the files' contents (their pose lines; the headers differ).
    for name, trajectory in [("trajectory.txt", result.trajectory),
                             ("keyframes.txt", result.keyframes)]:
        trajectory.write(tmp_path / name)
        assert pose_lines((tmp_path / name).read_bytes()) == pose_lines(python_files[name])
    assert result.metrics == json.loads(python_files["metrics.json"])
    assert result.out == tmp_path / "run"
    assert len(result.lost) == len(sequence) and result.frames_lost == int(result.lost.sum())
    assert result.seconds["total"] > 0 and result.frames_per_second > 0
    if command == "run":
        assert "map.ply" in python_files and result.map_points.shape[1] == 3
        assert result.map_colours.dtype == np.uint8
        assert result.map_colours.shape == result.map_points.shape
        assert result.map_normals.shape == result.map_points.shape
    else:
        assert result.map_points is None and "map.ply" not in python_files


def test_figure_options_as_the_clis(tmp_path, sequence):
    options = ("--plot-format", "png", "--dpi", 50)
    cli = run_cli("track", sequence.folder, "--out", tmp_path / "run", "--threads", 1, *options)
    assert cli.returncode == 0, cli.stderr
    cli_files = folder_bytes(tmp_path / "run")
    shutil.rmtree(tmp_path / "run")
    slamkit.track(sequence, {"pipeline": {"threads": 1}}, tmp_path / "run", plot_format="png",
                  dpi=50)
    assert folder_bytes(tmp_path / "run") == cli_files
    assert "ate_over_time.png" in cli_files and "ate_over_time.svg" not in cli_files
    with pytest.raises(ValueError, match="dpi: 5 not in"):
        slamkit.track(sequence, plot_format="png", dpi=5)
    with pytest.raises(ValueError, match="plot_format: 'eps'"):
        slamkit.run(sequence, plot_format="eps")


def test_without_out_the_same_run_is_returned_and_nothing_is_kept(tmp_path, sequence):
    kept = slamkit.run(sequence, {"pipeline": {"threads": 1}}, tmp_path / "kept", plot=False)
    result = slamkit.run(sequence.folder, {"pipeline": {"threads": 1}})
    assert not list(pathlib.Path(tempfile.gettempdir()).glob("slamkit_run.*"))
    assert result.out is None and result.metrics is None
    np.testing.assert_array_equal(result.trajectory.poses, kept.trajectory.poses)
    np.testing.assert_array_equal(result.map_points, kept.map_points)
    np.testing.assert_array_equal(result.map_colours, kept.map_colours)


def test_progress_reports_every_tracked_frame_and_the_fusion(sequence):
    calls = []
    slamkit.run(sequence, progress=lambda stage, done, total: calls.append((stage, done, total)))
    track = [c for c in calls if c[0] == "track"]
    assert [done for _, done, _ in track] == list(range(1, len(sequence) + 1))
    fused = [c for c in calls if c[0] == "map"]
    assert fused and fused[-1][1] == fused[-1][2]


def test_ctrl_c_stops_the_run_and_marks_its_folder_interrupted(tmp_path, sequence):
    def progress(stage, done, total):
        if stage == "track" and done == 5:
            os.kill(os.getpid(), signal.SIGINT)  # what Ctrl-C sends

    with pytest.raises(KeyboardInterrupt):
        slamkit.run(sequence, out=tmp_path / "run", progress=progress)
    status = run_json(tmp_path / "run")
    assert status["status"] == "interrupted" and status["signal"] == signal.SIGINT
    assert not list((tmp_path / "run").glob("*.tmp"))
    assert not (tmp_path / "run" / "trajectory.txt").exists()


def test_an_exception_from_progress_stops_the_run_and_is_raised(tmp_path, sequence):
    def progress(stage, done, total):
        if done == 3:
            raise ValueError("enough")

    with pytest.raises(ValueError, match="enough"):
        slamkit.track(sequence, out=tmp_path / "run", progress=progress)
    status = run_json(tmp_path / "run")
    assert status["status"] == "failed" and "enough" in status["error"]


def test_the_gil_is_released_while_the_pipeline_works(sequence):
    stamps, stop = [], threading.Event()

    def tick():
        while not stop.is_set():
            stamps.append(time.monotonic())
            time.sleep(0.001)

    ticker = threading.Thread(target=tick)
    ticker.start()
    try:
        start = time.monotonic()
        slamkit.track(sequence)
        end = time.monotonic()
    finally:
        stop.set()
        ticker.join()
    during = [s for s in stamps if start < s < end]
    assert len(during) > 10, "the Python thread did not run while the pipeline worked"


def test_bad_settings_raise_before_anything_is_written(tmp_path, sequence):
    with pytest.raises(ValueError, match="num_featurez"):
        slamkit.run(sequence, {"orb": {"num_featurez": 10}}, tmp_path / "run")
    assert not (tmp_path / "run").exists()
    with pytest.raises(ValueError, match="threads"):
        slamkit.run(sequence, threads=-1)


def test_a_missing_sequence_raises_the_clis_message(tmp_path):
    with pytest.raises(ValueError) as raised:
        slamkit.run(tmp_path / "missing", out=tmp_path / "py")
    assert str(raised.value) == cli_error("run", tmp_path / "missing", "--out", tmp_path / "cli")
