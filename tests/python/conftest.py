"""Shared fixtures of the Python tests: the lrchain CLI (for cross-checks) and the source tree.

ctest passes LRCHAIN_CLI and LRCHAIN_SOURCE_DIR; run by hand from a build tree, both are found from
the location of the imported package (<build>/python/lrchain).
"""

import json
import os
import subprocess
from pathlib import Path

import pytest

import lrchain

SOURCE_DIR = Path(os.environ.get("LRCHAIN_SOURCE_DIR", Path(__file__).resolve().parents[2]))


def _cli_path():
    if "LRCHAIN_CLI" in os.environ:
        return Path(os.environ["LRCHAIN_CLI"])
    return Path(lrchain.__file__).resolve().parents[2] / "cli" / "lrchain"


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def cli():
    """Runs the lrchain CLI with an argv list and returns its parsed JSON stdout."""
    path = _cli_path()
    assert path.is_file(), f"lrchain CLI not found at {path} (set LRCHAIN_CLI)"

    def run(*args, cwd=None):
        done = subprocess.run([str(path), *map(str, args)], capture_output=True, text=True, cwd=cwd, check=False)
        assert done.returncode == 0, f"lrchain {' '.join(map(str, args))}: exit {done.returncode}: {done.stderr}"
        return json.loads(done.stdout)

    return run
