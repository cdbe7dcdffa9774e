"""The Jacob's-ladder model of docs/model.md shared by the numba peers
(ladder_numba.py, sweep_numba.py): units, the A springs' rest length and
the ground state the runs start from.

Blocks of length s = 1 and mass m = 1; block n's centre (X_n, Y_n) and
angle theta_n; its arm t_n = (sin theta_n, (-1)^n cos theta_n).
"""
import math

import numpy as np
from numba import njit

# Units (docs/model.md): block length s, arm r = s/2, mass m.
S = 1.0
R = 0.5 * S
M = 1.0


@njit(cache=True)
def rest_a(b, alpha):
    """Rest length a = sqrt(b^2 + 4 s^2 cos^2 alpha) of the A springs, which
    makes angle alpha (radians) a ground state."""
    return math.sqrt(b * b + 4 * S * S * math.cos(alpha) ** 2)


@njit(cache=True)
def ground_state(n, alpha, b):
    """Centres X, Y, angles theta (all alpha, radians) and parities (-1)^n
    (index i is block n = i + 1) of the ground state at angle alpha."""
    x = np.zeros(n)
    y = np.zeros(n)
    th = np.full(n, alpha)
    par = np.empty(n)
    dy = S * math.cos(abs(alpha))
    for i in range(n):
        par[i] = -1.0 if i % 2 == 0 else 1.0
        x[i] = i * b
        if i > 0:
            y[i] = y[i - 1] + par[i - 1] * dy
    return x, y, th, par
