"""docs/python.md's worked example, run as it is written: its output must be the one the page
shows, and its ATE RMSEs the ones `slamkit eval all` prints."""
import os
import pathlib
import re
import subprocess
import sys

from conftest import real_data, run_cli

PAGE = pathlib.Path(os.environ.get("SLAMKIT_SOURCE_DIR", pathlib.Path(__file__).parents[2])) / "docs" / "python.md"


def example_and_output():
    """The page's first ```python block and the ```text block after it."""
    text = PAGE.read_text()
    code = re.search(r"```python\n(.*?)```", text, re.S)
    output = re.search(r"```text\n(.*?)```", text[code.end():], re.S)
    return code.group(1), output.group(1)


def test_worked_example_runs_as_written(tmp_path):
    folder = real_data("trajectories/fr1_xyz")
    code, shown = example_and_output()
    (tmp_path / "example.py").write_text(code)
    result = subprocess.run([sys.executable, "example.py"], cwd=tmp_path, capture_output=True,
                            text=True)
    assert result.returncode == 0, result.stderr
    assert result.stdout == shown
    assert (tmp_path / "ate_two_runs.png").stat().st_size > 10000
    for system, line in zip(["orbslam2_rgbd", "rgbdslam"], shown.splitlines()):
        cli = run_cli("eval", "all", folder / "groundtruth.txt", folder / f"{system}.txt")
        rmse = re.search(r"absolute_translational_error\.rmse (\S+) m", cli.stdout).group(1)
        assert f"ATE RMSE {rmse} m" in line
