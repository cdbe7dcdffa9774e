"""The docs' tour: a built-in movie replaced with a longer chain keeps no
window fitted to the old one, and a run's summary counts blocks as the
engine does (1..N-1; block N, free, turns its own way)."""

import jacobs_ladder as jl


def test_a_longer_chain_gets_a_window_that_follows_it():
    movie = jl.Scene.builtin("4", kind="movie")
    longer = movie.replace(n=20, name="m4n20")
    assert "auto" in longer.to_toml(), longer.to_toml()
    # A window of its own asked with the new chain is kept.
    kept = movie.replace(n=20, t_end=3500)
    assert "t_end = 3500" in kept.to_toml()


def test_the_summary_counts_blocks_one_to_n_minus_one():
    run = jl.simulate(alpha=60, t_end=3000)
    assert run.record["blocks_flipped"] == 9
    assert "9/9 blocks flipped" in repr(run)


def test_the_summary_names_the_wave_by_the_engines_rule():
    # The launched wave comes from the engine (`WaveKind::launched`), as
    # the figures' titles do: α < 0 launches an antikink, α > 0 a kink.
    for alpha, wave in [(-60, "antikink"), (60, "kink"), (-1, "antikink")]:
        run = jl.simulate(alpha=alpha, n=6, t_end=50)
        assert run.record["launched"] == wave
        assert repr(run).startswith(f"<Run {wave} α"), repr(run)
