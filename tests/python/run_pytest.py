"""Runs one file of the Python module's tests under pytest, for ctest.

Without pytest (Debian's python3-pytest) the test fails under CI=true and is skipped elsewhere
(exit 77, ctest's SKIP_RETURN_CODE), saying what to install. A file whose tests were all
skipped (no SLAMKIT_DATA, say) is reported to ctest as skipped too, with pytest's reasons.
"""
import collections
import os
import sys

try:
    import pytest
except ImportError:
    print("python3-pytest is missing for " + sys.executable +
          ": install it (scripts/setup.sh does)", file=sys.stderr)
    sys.exit(1 if os.environ.get("CI") == "true" else 77)


class Outcomes:
    """Counts the tests' outcomes (a skip is reported at setup, a pass or failure at call)."""

    def __init__(self):
        self.counts = collections.Counter()

    def pytest_runtest_logreport(self, report):
        if report.when == "call" or report.skipped:
            self.counts[report.outcome] += 1


outcomes = Outcomes()
# -rs: the reasons of skips; -p no:cacheprovider: nothing written into the source tree.
code = pytest.main(["-q", "-rs", "-p", "no:cacheprovider", *sys.argv[1:]], plugins=[outcomes])
if code == 0 and outcomes.counts["skipped"] and not outcomes.counts["passed"]:
    sys.exit(77)
sys.exit(code)
