"""Where the harness finds the repository, the solidkit binary and writes its output."""
import os
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
FIXTURES = ROOT / "fixtures" / "crosscheck"
CASES_FILE = FIXTURES / "cases.json"


def solidkit_bin() -> Path:
    """The solidkit binary: $SOLIDKIT_BIN, else target/release/solidkit."""
    env = os.environ.get("SOLIDKIT_BIN")
    return Path(env) if env else ROOT / "target" / "release" / "solidkit"


def out_dir() -> Path:
    """Output folder: $CROSSCHECK_OUT, else target/crosscheck."""
    env = os.environ.get("CROSSCHECK_OUT")
    return Path(env) if env else ROOT / "target" / "crosscheck"


def keep_meshes() -> bool:
    """Whether meshes of cases that passed stay on disk ($CROSSCHECK_KEEP_MESHES=1). By default
    they are deleted once measured, so a full run needs about 0.5 GB instead of 2.5 GB; every
    failure keeps its files and prints the command that remakes them."""
    return os.environ.get("CROSSCHECK_KEEP_MESHES", "") not in ("", "0")
