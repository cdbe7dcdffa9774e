"""A simulated run (``jacobs_ladder.Run``): the engine's arrays and record,
handed over as numpy arrays; nothing is computed here."""

from __future__ import annotations

import json
from typing import Any, Dict, List, Optional

from . import _native
from ._lazy import np

class Run:
    """A simulated run: numpy arrays of its samples and its record.

    Arrays (samples × N where per block; N = blocks, block 1 driven):

    - ``t``: sample times, τ (every ``sample_every`` τ from 0 to t_end).
    - ``theta``: angles θ_n, radians, as integrated (not wrapped).
    - ``x``, ``y``: block centres X_n, Y_n, in s: x runs down the ladder
      (along gravity, block 1 at the top), y across it (the paper's Fig. 1).
    - ``vx``, ``vy``, ``omega``: their velocities, s/τ and rad/τ.
    - ``kink_position``: where the wall is at each sample, in blocks
      (fractional: the count of blocks past the wall plus the fraction by
      which the block at the wall has turned; 10.11 for N = 10 means the
      wave has run off the end), not a count of flipped blocks.
    - ``kinetic``, ``elastic``, ``gravitational``: the energies at each
      sample, in k s² (½ m (Ẋ² + Ẏ²) + ½ I θ̇² summed; Σ ½ k [(L_A − a)² +
      (L_B − b)²]; −m G Σ X_n); ``dissipated``: the energy dissipated from
      t = 0, recorded when ``simulate(..., dissipation=True)``, else
      computed when first asked for (the run made again with it recorded:
      the same trajectory bit for bit, at the cost of a second run). After
      the drive ends, kinetic + elastic + gravitational + dissipated stays
      constant to the integrator's accuracy.
    - ``arrival_times``: per block, τ: the first sign change of sin θ_n;
      NaN where the block never flipped (the CLI's ``null``).
    - ``final_theta_deg``: θ_n at t_end in degrees, wrapped to (−180, 180]
      (the CLI's ``final_theta_deg``).

    Records: ``integrator`` (the report the data files carry: scheme, dt,
    steps, force evaluations, auto's achieved arrival error), ``speed``
    (blocks/τ, NaN when too few blocks flipped), ``bulk_speed`` (the
    experiment figures' fit over the chain's lower half), ``waves`` (one
    record per domain wall, where the engine reports them, else None) and
    ``record`` (everything the engine reports about the run, as a dict).

    A run of an apparatus (``simulate(..., apparatus={...})``,
    docs/experiments.md) has its numbers in the apparatus' units beside
    the model's: ``t_s`` and ``arrival_times_s`` (s), ``speed_cm_s`` and
    ``bulk_speed_cm_s`` (cm/s), ``bulk_fit`` (the figures' fitted line)
    and ``tau_s`` (τ in s); a run of the model alone has None there.
    """

    __slots__ = ("_d", "record", "scene")

    def __init__(self, arrays: Dict[str, Any], scene: Optional["Scene"] = None):
        self._d = arrays
        self.record: Dict[str, Any] = json.loads(arrays["record"])
        self.scene = scene

    def __reduce__(self):
        # The arrays (numpy pickles them whole) and the record's JSON text.
        return (Run, (self._d, self.scene))

    t = property(lambda self: self._d["t"], doc="Sample times, τ.")
    theta = property(lambda self: self._d["theta"], doc="θ_n(t), radians, samples × N.")
    x = property(
        lambda self: self._d["x"],
        doc="X_n(t), block centres, s; samples × N. X runs down the ladder, along gravity.",
    )
    y = property(
        lambda self: self._d["y"],
        doc="Y_n(t), block centres, s; samples × N. Y runs across the ladder.",
    )
    kinetic = property(
        lambda self: self._d["kinetic"], doc="Kinetic energy at each sample, k s²."
    )
    elastic = property(
        lambda self: self._d["elastic"], doc="Elastic energy of the springs at each sample, k s²."
    )
    gravitational = property(
        lambda self: self._d["gravitational"], doc="−m G Σ X_n at each sample, k s²."
    )
    vx = property(lambda self: self._d["vx"], doc="dX_n/dt, s/τ; samples × N.")
    vy = property(lambda self: self._d["vy"], doc="dY_n/dt, s/τ; samples × N.")
    omega = property(lambda self: self._d["omega"], doc="dθ_n/dt, rad/τ; samples × N.")
    kink_position = property(
        lambda self: self._d["kink_position"],
        doc="The wall's position at each sample, in blocks (fractional; N + a fraction once it ran off the end).",
    )
    arrival_times = property(
        lambda self: self._d["arrival_times"], doc="Arrival time per block, τ; NaN where none."
    )
    final_theta_deg = property(
        lambda self: self._d["final_theta_deg"], doc="θ_n at t_end, degrees, wrapped to (−180, 180]."
    )

    @property
    def dissipated(self) -> Any:
        """Energy dissipated since t = 0 at each sample, k s². Recorded by
        ``simulate(..., dissipation=True)``; otherwise the run is made
        again with it recorded when first asked for (the same trajectory
        bit for bit; it takes a second run)."""
        d = self._d.get("dissipated")
        if d is None:
            scene = _native._Scene.from_json(json.dumps(self.record["scene"]))
            again = scene.simulate(None, self.t, None, True)
            d = self._d["dissipated"] = again["dissipated"]
        return d

    @property
    def t_s(self) -> Optional[Any]:
        """Sample times in seconds (an apparatus' run; else None)."""
        return self._d.get("t_s")

    @property
    def arrival_times_s(self) -> Optional[Any]:
        """Arrival time per block in seconds, NaN where none (an
        apparatus' run; else None)."""
        return self._d.get("arrival_times_s")

    @property
    def tau_s(self) -> Optional[float]:
        """τ = √(m/k) in seconds (an apparatus' run; else None)."""
        return self.record.get("tau_s")

    @property
    def n(self) -> int:
        """Number of blocks N."""
        return int(self.arrival_times.shape[0])

    @property
    def integrator(self) -> Dict[str, Any]:
        """The integrator report: ``requested``, ``name``, ``dt``, ``steps``,
        ``force_evals``, and for ``auto`` its ``tolerance`` and achieved
        ``arrival_error`` (τ)."""
        return self.record["integrator"]

    @property
    def speed(self) -> float:
        """Wave speed, blocks/τ (least squares over the arrivals); NaN when
        too few blocks flipped."""
        s = self.record.get("speed")
        return float("nan") if s is None else float(s)

    @property
    def speed_cm_s(self) -> Optional[float]:
        """:attr:`speed` in cm/s (an apparatus' run; NaN when no speed;
        None for a run of the model alone)."""
        if "cm_per_s" not in self.record:
            return None
        s = self.record.get("speed_cm_s")
        return float("nan") if s is None else float(s)

    @property
    def bulk_speed(self) -> float:
        """The experiment figures' speed (blocks/τ): the fit over the
        chain's lower half, blocks N/2 + 1 .. N − 1, by the rule of
        :attr:`speed` (blocks that flip in groups have none); NaN unless
        every one of them flipped, one after the other down the chain."""
        s = self.record.get("bulk_speed")
        return float("nan") if s is None else float(s)

    @property
    def bulk_speed_cm_s(self) -> Optional[float]:
        """:attr:`bulk_speed` in cm/s, as the experiment figures draw it
        (an apparatus' run; NaN when none; None for the model alone)."""
        if "cm_per_s" not in self.record:
            return None
        fit = self.bulk_fit
        return float("nan") if fit is None else float(fit["speed_cm_s"])

    @property
    def bulk_fit(self) -> Optional[Dict[str, Any]]:
        """The experiment figures' fitted line of an apparatus' run, as its
        data file has it: position (n − 1) b = ``centroid_cm`` +
        ``speed_cm_s`` (t − t_1 − ``centroid_s``) over ``blocks`` (first
        and last, one-based); None where there is no bulk speed or no
        apparatus."""
        numbers = self.record.get("apparatus")
        return numbers.get("bulk") if isinstance(numbers, dict) else None

    @property
    def waves(self) -> Optional[List[Dict[str, Any]]]:
        """One record per domain wall (kind, launched_at, arrival_times with
        NaN for none, front, fate), where the engine reports waves; None
        otherwise."""
        waves = self.record.get("waves")
        if waves is None:
            return None
        if isinstance(waves, dict):  # {"waves": [...], "block_n": {...}}
            waves = waves.get("waves", [])
        out = []
        for w in waves:
            w = dict(w)
            if isinstance(w.get("arrival_times"), list):
                w["arrival_times"] = np.array(
                    [np.nan if a is None else a for a in w["arrival_times"]], dtype=float
                )
            out.append(w)
        return out

    @property
    def block_n(self) -> Optional[Dict[str, Any]]:
        """The free bottom block's own record beside the waves (its sign
        changes, τ, and final angle), where the engine reports waves."""
        waves = self.record.get("waves")
        return waves.get("block_n") if isinstance(waves, dict) else None

    def to_dict(self) -> Dict[str, Any]:
        """Every array and record, as a dict (arrays are numpy arrays)."""
        d = {k: v for k, v in self._d.items() if k != "record"}
        d.update({k: v for k, v in self.record.items() if k not in d})
        d["waves"] = self.waves
        return d

    def __repr__(self) -> str:
        m = self.record.get("model", {})
        alpha = m.get("alpha")
        wave = self.record.get("launched", "wave")
        # Blocks 1..N-1 (block N, free, turns its own way): the engine's count.
        flipped = self.record.get("blocks_flipped")
        integ = self.integrator
        t_end = self.record.get("t_end")
        if not isinstance(t_end, (int, float)):  # "auto": the window it reached
            t_end = float(self.t[-1]) if len(self.t) else float("nan")
        return (
            f"<Run {wave} α = {alpha:g}°, N = {self.n}, b = {m.get('b'):g}, "
            f"γ = {m.get('gamma'):g}: t = 0..{t_end:g} τ, "
            f"{len(self.t)} samples, {flipped}/{self.n - 1} blocks flipped, "
            f"{integ['name']} dt = {integ['dt']:g} ({integ['requested']})>"
        )
