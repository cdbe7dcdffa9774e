"""Python's memory against the command line's: the arrays cross
to numpy without a second copy of the run resident, so a run's peak is
within 1.2 times the CLI's for the same run; and a run the process has no
memory for (an address-space limit, RLIMIT_AS) raises an exception with a
hint instead of aborting the interpreter.

Each measurement runs in a fresh process (a peak is a process's whole
life), the CLI's through `os.wait4` (its own rusage), Python's printing
its own `ru_maxrss`."""

import os
import subprocess
import sys
import textwrap
import time

import pytest

from conftest import ladder_bin

# N = 20000 kept at 401 samples (t_end 200, every 0.5 τ): 385 MB of
# positions and velocities, the size of a reported run (N = 20000 to
# t_end 4000 every 10 τ) at a twentieth of its time.
N = 20000
T_END = 200
EVERY = 0.5
# Verlet's step: the memory does not depend on it (N × samples), the time
# does (its default 0.01 τ took 12 s of CPU a run); `auto` finds its own.
DT = {"verlet": 0.05, "auto": None}


def cli_peak_kb(tmp_path, integrator):
    out = tmp_path / "run.npz"
    p = subprocess.Popen(
        [
            str(ladder_bin()),
            "simulate",
            "--n",
            str(N),
            "--t-end",
            str(T_END),
            "--sample-every",
            str(EVERY),
            "--integrator",
            integrator,
            *(["--dt", str(DT[integrator])] if DT[integrator] else []),
            "--npz",
            str(out),
        ],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
    )
    _, status, usage = os.wait4(p.pid, 0)
    err = p.stderr.read().decode()
    p.stderr.close()
    assert os.waitstatus_to_exitcode(status) == 0, err
    out.unlink()
    return usage.ru_maxrss


def python_peak_kb(integrator):
    code = textwrap.dedent(
        f"""
        import resource
        import jacobs_ladder as jl
        run = jl.simulate(n={N}, t_end={T_END}, integrator={integrator!r}, sample_every={EVERY},
                          dt={DT[integrator]!r})
        assert run.x.shape == (401, {N}), run.x.shape
        print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
        """
    )
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return int(p.stdout.split()[-1])


@pytest.mark.parametrize("integrator", ["auto", "verlet"])
def test_python_peak_memory_is_within_1_2_times_the_clis(tmp_path, integrator):
    cli = cli_peak_kb(tmp_path, integrator)
    py = python_peak_kb(integrator)
    # The run itself: 48 bytes per block and sample; both hold it once.
    run_kb = 48 * N * 401 / 1024
    assert cli > 0.9 * run_kb, f"the CLI's peak {cli} kB is below the run's {run_kb:.0f} kB"
    assert py <= 1.2 * cli, (
        f"{integrator}: Python's peak {py / 1024:.0f} MB is {py / cli:.2f} times the CLI's "
        f"{cli / 1024:.0f} MB (at most 1.2)"
    )


LIMITED = textwrap.dedent(
    """
    import json, resource, sys, time
    import numpy
    import jacobs_ladder as jl
    extra_mb, keywords = int(sys.argv[1]), json.loads(sys.argv[2])
    # Warm the engine (its threads and their stacks) before the limit.
    jl.simulate(n=6, t_end=100, sample_every=50)
    with open("/proc/self/statm") as f:
        size = int(f.read().split()[0]) * resource.getpagesize()
    limit = size + extra_mb * 2**20
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    start = time.perf_counter()
    try:
        jl.simulate(**keywords)
    except (MemoryError, jl.RunError) as e:
        print(type(e).__name__, round(time.perf_counter() - start, 3), e, sep="|")
        sys.exit(0)
    print("no exception")
    sys.exit(3)
    """
)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_AS and /proc are Linux's")
@pytest.mark.parametrize(
    "extra_mb, keywords, within",
    [
        # 600 MB more address space than the process has; the run keeps
        # 401 samples of N = 100000 (1.9 GB): refused before it starts.
        (600, {"n": 100000}, 15.0),
        # 2.5 GB: room for the run's samples (1.9 GB), not for numpy's
        # columns beside them (the rows' address space stays with the
        # allocator): the run is made, the columns are refused (a run of
        # about 10 s).
        (2560, {"n": 100000, "t_end": 40, "sample_every": 0.1}, 120.0),
    ],
)
def test_a_run_past_the_address_space_limit_raises_and_does_not_abort(extra_mb, keywords, within):
    import json

    p = subprocess.run(
        [sys.executable, "-c", LIMITED, str(extra_mb), json.dumps(keywords)],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert p.returncode == 0, f"exit {p.returncode} (negative: a signal): {p.stdout} {p.stderr}"
    kind, seconds, message = p.stdout.strip().split("|", 2)
    assert kind in ("RunError", "MemoryError")
    assert "not enough memory" in message and "hint" in message, message
    assert float(seconds) < within, f"refused after {seconds} s"


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="ulimit -v is a shell's")
def test_the_cli_past_the_address_space_limit_exits_1_with_a_hint(tmp_path):
    # 1 GB of address space; the run keeps 401 samples of N = 100000 (1.9 GB).
    # (t_end 400 τ every 1 τ: within the cap on steps × N.)
    run = f"simulate --n 100000 --t-end 400 --sample-every 1 --npz {tmp_path}/x.npz"
    cmd = f"ulimit -v 1000000; exec {ladder_bin()} {run}"
    start = time.perf_counter()
    p = subprocess.run(["bash", "-c", cmd], capture_output=True, text=True, timeout=120)
    assert p.returncode == 1, f"exit {p.returncode}: {p.stderr}"
    assert "not enough memory" in p.stderr and "hint" in p.stderr, p.stderr
    assert p.stderr.count("\n") <= 2, p.stderr
    assert time.perf_counter() - start < 10
    assert not (tmp_path / "x.npz").exists()
