"""A tour of the Python package, as a script (it runs in the tests, and each
block pastes into a Jupyter cell). Writes its files into the folder given as
the first argument (default: out/python-tour).

    pip install .                    # from a clone of the repository
    python examples/python_tour.py
"""

import sys
from pathlib import Path

import numpy as np

import jacobs_ladder as jl

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out/python-tour")
out.mkdir(parents=True, exist_ok=True)

# 1. The paper's kink: N = 10, b = 1.3 s, α = 60°, block 1 turned over 1000 τ.
run = jl.simulate(alpha=60, n=10, t_end=3000)
print(run)
print("arrival times (τ):", np.round(run.arrival_times, 1))
print("integrator:", run.integrator["name"], "dt =", run.integrator["dt"],
      "arrival error ≈", run.integrator["arrival_error"], "τ")

# θ_n(t) in radians, samples × N: the kink position from the arrays alone.
flipped = (np.sin(run.theta) < 0).sum(axis=1)
print("blocks flipped at t = 1000, 2000, 3000 τ:", flipped[[100, 200, 300]])

# 2. The antikink is slower; blocks that never flip are NaN.
slow = jl.simulate(alpha=-60, t_end=3000)
print("antikink speed:", round(slow.speed, 4), "blocks/τ; never flipped:",
      int(np.isnan(slow.arrival_times).sum()))

# 3. A built-in figure, and your own scene: rendered in memory (a notebook
#    shows them inline) or saved as `ladder render` writes them.
fig = jl.Scene.builtin("2d").render()
fig.save(out)
mine = jl.Scene(alpha=70, n=12, name="k70", t_end=2500)
strip = mine.replace(output={"kind": "filmstrip", "times": [0, 800, 1200, 1600, 2400]})
print("wrote", [p.name for p in strip.save(out)])

# 4. The linear theory of `ladder theory --json`.
th = jl.theory(alpha=60)
print("winding number", th["winding_number"], "barrier", th["barrier"])

# 5. A small sweep: where the antikink is pinned.
table = jl.sweep(alpha=[-50, -60, -70], n=8, t_end=3000)
for a, o, f in zip(table["alpha"], table["outcome"], table["front"]):
    print(f"alpha = {a:6.1f}: {o:10s} front {f}")
