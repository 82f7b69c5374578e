"""slamkit.Sequence on the real TUM pieces: frames, stamps, camera and groundtruth."""
import numpy as np
import pytest

import slamkit
from conftest import real_data

FR1_DESK = "rgbd_dataset_freiburg1_desk_9frames"


def listed_stamps(list_file):
    return [float(line.split()[0]) for line in list_file.read_text().splitlines()
            if line.strip() and not line.startswith("#")]


def test_frames_of_a_real_sequence():
    folder = real_data(FR1_DESK)
    sequence = slamkit.Sequence(folder)
    assert len(sequence) == 9
    np.testing.assert_array_equal(sequence.stamps, listed_stamps(folder / "rgb.txt"))
    assert sequence.camera["fx"] == 517.3 and sequence.camera["width"] == 640
    assert sequence.camera["distortion"][0] != 0  # Freiburg 1 is distorted
    frames = list(sequence)
    assert [f.index for f in frames] == list(range(9))
    frame = frames[4]
    assert frame.stamp == sequence.stamps[4]
    assert frame.colour.shape == (480, 640, 3) and frame.colour.dtype == np.uint8
    assert frame.depth.shape == (480, 640) and frame.depth.dtype == np.float32
    valid = frame.depth[frame.depth > 0]
    assert valid.size > 0.5 * frame.depth.size
    assert valid.min() >= sequence.camera["min_depth"]
    assert valid.max() <= sequence.camera["max_depth"]
    np.testing.assert_array_equal(sequence[-1].colour, frames[8].colour)
    with pytest.raises(IndexError):
        sequence[9]


def test_groundtruth_and_colour_order():
    folder = real_data(FR1_DESK)
    sequence = slamkit.Sequence(folder)
    gt = sequence.groundtruth
    assert len(gt) == 2335
    np.testing.assert_array_equal(gt.stamps, slamkit.read_trajectory(folder / "groundtruth.txt").stamps)
    # RGB order: matplotlib reads the PNG as it is stored.
    image = pytest.importorskip("matplotlib.image")
    first = folder / "rgb" / f"{listed_stamps(folder / 'rgb.txt')[0]:.6f}.png"
    np.testing.assert_array_equal(sequence[0].colour,
                                  np.round(image.imread(first) * 255).astype(np.uint8))


def test_options_and_errors(tmp_path):
    folder = real_data(FR1_DESK)
    assert len(slamkit.Sequence(folder, association=folder / "associate.txt")) == 9
    with pytest.raises(ValueError) as raised:
        slamkit.Sequence(tmp_path / "missing")
    assert "missing" in str(raised.value)
