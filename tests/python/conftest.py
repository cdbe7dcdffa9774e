"""Shared fixtures: the `ladder` binary of this checkout (the Python package
must give what it gives), run in a temporary folder.

And the project's rule for a missing precondition (docs/testing.md), here
for every skip, whatever raised it (`pytest.skip`, `importorskip`, a
`skipif` mark): under CI (`CI` set to anything but `false`/`0`, or
`LADDER_REQUIRE_ALL=1`) the skip is turned into a failure; elsewhere it is
written to the file `LADDER_SKIP_LOG` names, which `scripts/test` lists at
the end of its output, and pytest's `-rs` summary shows it too."""

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


def strict() -> bool:
    """Whether this run is CI's: every precondition must hold (the same
    rule as tests/integration/common/require.rs)."""

    def on(key, off):
        return key in os.environ and os.environ[key] not in off

    return on("CI", ("", "false", "0")) or on("LADDER_REQUIRE_ALL", ("", "0"))


def needed(module, extra="test"):
    """The module `module` of the package's `extra` extras, imported; if it
    is missing the test is skipped (and so failed under CI, and listed)."""
    return pytest.importorskip(module, reason=f"{module} is not installed (pip install '.[{extra}]')")


def _skip_reason(report) -> str:
    if isinstance(report.longrepr, tuple):
        return report.longrepr[2].removeprefix("Skipped: ")
    return str(report.longrepr)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    report = outcome.get_result()
    if not report.skipped or hasattr(report, "wasxfail"):
        return
    reason = _skip_reason(report)
    if strict():
        report.outcome = "failed"
        report.longrepr = (
            f"{item.nodeid}: {reason}; under CI every precondition must hold. "
            "Outside CI (CI unset) the test would be reported as skipped."
        )
        return
    log = os.environ.get("LADDER_SKIP_LOG")
    if log:
        with open(log, "a") as f:
            f.write(f"SKIPPED python {item.nodeid}: {reason}\n")
