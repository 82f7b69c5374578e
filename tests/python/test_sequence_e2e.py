"""slamkit.synth against `slamkit synth`: the same files, byte for byte, and the same errors."""
import pathlib

import numpy as np
import pytest

import slamkit
from conftest import cli_error, run_cli


def folder_bytes(folder):
    return {str(p.relative_to(folder)): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file()}


@pytest.mark.parametrize("sensor, cli_sensor", [
    ({}, []),
    ({"sensor": "kinect", "sensor_off": "rolling_shutter"},
     ["--sensor", "kinect", "--sensor-off", "rolling_shutter"]),
])
def test_synth_writes_what_the_cli_writes(tmp_path, sensor, cli_sensor):
    done = []
    sequence = slamkit.synth("loop", 4, 5, out=tmp_path / "python", progress=done.append,
                             **sensor)
    result = run_cli("synth", "--preset", "loop", "--frames", 4, "--seed", 5, "--out",
                     tmp_path / "cli", *cli_sensor)
    assert result.returncode == 0, result.stderr
    python_files = folder_bytes(tmp_path / "python")
    assert python_files == folder_bytes(tmp_path / "cli")
    assert "groundtruth.txt" in python_files and done[-1] == 4
    assert len(sequence) == 4 and sequence.groundtruth is not None
    frame = sequence[3]
    assert frame.colour.shape == (480, 640, 3) and np.count_nonzero(frame.depth) > 0


@pytest.mark.parametrize("kwargs, cli_args", [
    ({"preset": "spiral"}, ["--preset", "spiral"]),
    ({"frames": 0}, ["--frames", "0"]),
    ({"sensor": "lidar"}, ["--sensor", "lidar"]),
    ({"sensor_off": "blur"}, ["--sensor-off", "blur"]),
])
def test_synth_errors_are_the_clis(tmp_path, kwargs, cli_args):
    with pytest.raises(ValueError) as raised:
        slamkit.synth(out=tmp_path / "python", **kwargs)
    assert str(raised.value) == cli_error("synth", "--out", tmp_path / "cli", *cli_args)


def test_a_progress_callback_that_raises_stops_with_its_error(tmp_path):
    def progress(done):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        slamkit.synth("desk", 2, out=tmp_path / "seq", progress=progress)
