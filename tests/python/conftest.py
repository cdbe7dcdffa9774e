"""Shared fixtures: the `ladder` binary of this checkout (the Python package
must give what it gives), run in a temporary folder."""

import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def ladder_bin() -> Path:
    env = os.environ.get("LADDER_BIN")
    path = Path(env) if env else ROOT / "target" / "release" / "ladder"
    if not path.exists():
        pytest.fail(
            f"the ladder binary {path} is missing: build it first (cargo build --release), "
            "or point LADDER_BIN at it"
        )
    return path


@pytest.fixture(scope="session")
def ladder():
    """Runs `ladder ARGS...`; returns the CompletedProcess (text)."""
    binary = ladder_bin()

    def run(*args, check=True, cwd=None):
        p = subprocess.run(
            [str(binary), *map(str, args)], capture_output=True, text=True, cwd=cwd
        )
        if check and p.returncode != 0:
            raise AssertionError(f"ladder {' '.join(map(str, args))} failed: {p.stderr}")
        return p

    return run


@pytest.fixture(scope="session")
def ladder_json(ladder):
    def run(*args):
        return json.loads(ladder(*args).stdout)

    return run
