"""pytest setup of the cross-check suite: the harness package (xcheck/) on the path, and one
session-wide run of every case in every system (xcheck.runner), shared by the tests."""
import os
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from xcheck import paths, runner  # noqa: E402


@pytest.fixture(scope="session")
def solidkit_bin() -> Path:
    b = paths.solidkit_bin()
    if not b.exists():
        pytest.fail(f"solidkit binary not found at {b} (cargo build --release -p solidkit, or set SOLIDKIT_BIN)")
    return b


@pytest.fixture(scope="session")
def crosscheck(solidkit_bin):
    """Every selected case built in every system, judged, and the report written."""
    return runner.run_all()


def pytest_report_header(config):
    return [f"solidkit: {paths.solidkit_bin()}", f"cross-check output: {paths.out_dir()}",
            f"cases: {os.environ.get('CROSSCHECK_CASES', 'all')}"]
