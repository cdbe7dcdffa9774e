"""Rendering a movie prints nothing on stderr but the usual lines:
OpenH264 printed a warning when its encoder was initialised
("[OpenH264] this = 0x…, Warning: bEnableFrameSkip = 0, …"), on the
command line's stderr and into notebook cells. Its log is silenced before
the encoder starts, which leaves the MP4's bytes as they were: the
Python package's movie is the command line's, byte for byte."""

import subprocess
import sys
import textwrap

import pytest

ARGS = ["--format", "mp4", "--frames", "12", "--size", "128x96"]


@pytest.mark.parametrize("movie", ["4", "10"])
def test_the_cli_prints_only_its_line_while_encoding_an_mp4(ladder, tmp_path, movie):
    p = ladder("movie", movie, *ARGS, "--out", tmp_path)
    lines = p.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("ladder: wrote "), p.stderr
    assert "OpenH264" not in p.stderr
    assert (tmp_path / f"movie-{movie}.mp4").stat().st_size > 1000


def test_python_prints_nothing_while_encoding_an_mp4_and_gives_the_clis_bytes(ladder, tmp_path):
    # In a child process: the encoder writes to file descriptor 2, which
    # pytest's capture of sys.stderr would not see.
    code = textwrap.dedent(
        """
        import sys
        import jacobs_ladder as jl
        files = jl.Scene.builtin("4", kind="movie").render(
            format="mp4", frames=12, size=(128, 96))
        sys.stdout.buffer.write(files["movie-4.mp4"])
        """
    )
    p = subprocess.run([sys.executable, "-c", code], capture_output=True)
    assert p.returncode == 0, p.stderr.decode()
    assert p.stderr == b"", p.stderr.decode()
    ladder("movie", "4", *ARGS, "--out", tmp_path)
    assert p.stdout == (tmp_path / "movie-4.mp4").read_bytes()
