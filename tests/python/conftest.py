"""Shared helpers of the Python module's tests: the slamkit executable and the real data."""
import os
import pathlib
import subprocess

import pytest


def running_under_ci():
    return os.environ.get("CI") == "true"


def real_data(relative):
    """$SLAMKIT_DATA/relative; missing, the test fails under CI=true and is skipped elsewhere."""
    root = os.environ.get("SLAMKIT_DATA")
    path = pathlib.Path(root) / relative if root else None
    if path is None or not path.exists():
        why = f"real data '{relative}' not found: set SLAMKIT_DATA to the datasets folder"
        if running_under_ci():
            pytest.fail(why)
        pytest.skip(why)
    return path


def run_cli(*args):
    """Runs the slamkit executable (SLAMKIT_BINARY, set by ctest); returns the CompletedProcess."""
    binary = os.environ.get("SLAMKIT_BINARY")
    if not binary:
        pytest.fail("SLAMKIT_BINARY is not set: run these tests through ctest")
    return subprocess.run([binary, *map(str, args)], capture_output=True, text=True)


def cli_error(*args):
    """The message of `slamkit ARGS` failing with exit code 2, without 'slamkit: error: '."""
    result = run_cli(*args)
    assert result.returncode == 2, result.stderr
    prefix = "slamkit: error: "
    line = result.stderr.strip().splitlines()[-1]
    assert line.startswith(prefix), line
    return line[len(prefix):]
