"""slamkit.settings and write_settings against the CLI: the same file, the same errors."""
import pytest

import slamkit
from conftest import cli_error, run_cli


def test_written_defaults_are_slamkit_settings(tmp_path):
    slamkit.write_settings(None, tmp_path / "defaults.yaml")
    cli = run_cli("settings")
    assert cli.returncode == 0
    assert (tmp_path / "defaults.yaml").read_text() == cli.stdout


@pytest.mark.parametrize("text", [
    "orb:\n  num_featurs: 3\n",
    "orb:\n  num_features: -3\n",
    "tracking:\n  ransac:\n    confidence: 2\n",
    "orb: 3\n",
])
def test_bad_files_raise_the_message_of_run(tmp_path, text):
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    message = cli_error("run", tmp_path / "no-sequence", "--out", tmp_path / "run",
                        "--settings", path)
    with pytest.raises(ValueError) as raised:
        slamkit.settings(path)
    assert str(raised.value) == message
