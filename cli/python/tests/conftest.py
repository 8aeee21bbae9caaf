"""Shared fixtures of the Python package's tests: the repository's fixtures folder and the
command-line binary (``SOLIDKIT_BIN``, or target/release/solidkit when built)."""

import os
import pathlib

import pytest

REPO = pathlib.Path(__file__).resolve().parents[3]


@pytest.fixture
def fixtures() -> pathlib.Path:
    return REPO / "fixtures"


@pytest.fixture
def solidkit_bin() -> str:
    path = os.environ.get("SOLIDKIT_BIN") or str(REPO / "target" / "release" / "solidkit")
    if not os.path.exists(path):
        pytest.skip("the solidkit binary is not built (set SOLIDKIT_BIN)")
    return path
