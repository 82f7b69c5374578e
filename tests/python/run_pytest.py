"""Runs one file of the Python module's tests under pytest, for ctest.

Without pytest (Debian's python3-pytest) the test fails under CI=true and is skipped elsewhere
(exit 77, ctest's SKIP_RETURN_CODE), saying what to install.
"""
import os
import sys

try:
    import pytest
except ImportError:
    print("python3-pytest is missing for " + sys.executable +
          ": install it (scripts/setup.sh does)", file=sys.stderr)
    sys.exit(1 if os.environ.get("CI") == "true" else 77)

# -p no:cacheprovider: nothing written into the source tree.
sys.exit(pytest.main(["-q", "-p", "no:cacheprovider", *sys.argv[1:]]))
