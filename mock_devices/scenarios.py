"""Hidden-effect scenarios for the simulated bench: ``labrig run ... --sim --scenario NAME --seed N``.

Each scenario draws physically plausible strengths from the seed (ranges and reasons: docs/effects.md).
The truth stays in this process; it never reaches the session file or anything the diagnosis reads.
"""

from __future__ import annotations

import zlib
from typing import Callable

import numpy as np

from mock_devices import effects as fx
from mock_devices.world import Effect

ScenarioFactory = Callable[[np.random.Generator], list[Effect]]


def _log_uniform(rng: np.random.Generator, lo: float, hi: float) -> float:
    """Time constants and scale factors are only known to within a factor: uniform in log."""
    return float(np.exp(rng.uniform(np.log(lo), np.log(hi))))


def _faradaic(rng: np.random.Generator) -> list[Effect]:
    i1 = _log_uniform(rng, 1e-4, 6e-4)  # A at 1 V
    if rng.random() < 0.5:
        v_t = float(rng.uniform(0.12, 0.25))
        return [fx.FaradaicCurrent("butler_volmer", {"i0": float(i1 / (2 * np.sinh(1 / (2 * v_t)))), "v_t": v_t})]
    return [fx.FaradaicCurrent("poly", {"g3": i1})]


def _strain(rng: np.random.Generator) -> list[Effect]:
    g = _log_uniform(rng, 50.0, 250.0)
    other = g * float(rng.uniform(0.0, 0.3))
    return [fx.StrainResistance(g, other) if rng.random() < 0.5 else fx.StrainResistance(other, g)]


def _mains(rng: np.random.Generator) -> list[Effect]:
    f = float(rng.choice([50.0, 60.0]) + rng.uniform(-0.05, 0.05))
    phases = tuple(float(p) for p in rng.uniform(0, 2 * np.pi, 4))
    return [fx.MainsPickup(f, _log_uniform(rng, 1e-6, 5e-6), _log_uniform(rng, 2e-6, 1e-5), float(rng.uniform(0.1, 0.4)), phases)]


SCENARIOS: dict[str, ScenarioFactory] = {
    "none": lambda rng: [],
    "back_relaxation": lambda rng: [fx.BackRelaxation(float(rng.uniform(0.9, 1.4)), _log_uniform(rng, 3.0, 12.0))],
    "faradaic_current": _faradaic,
    "hysteresis": lambda rng: [fx.Hysteresis(float(rng.uniform(0.3, 0.6)), float(rng.uniform(0.3, 0.6)))],
    "time_delay": lambda rng: [fx.TimeDelay(_log_uniform(rng, 5e-3, 40e-3))],
    "sensor_offset": lambda rng: [fx.SensorOffset(float(rng.uniform(0.6, 0.9)))],
    "clamp_relaxation": lambda rng: [fx.ClampRelaxation(float(rng.uniform(0.05, 0.2)), _log_uniform(rng, 200.0, 1000.0))],
    "dehydration": lambda rng: [fx.Dehydration(_log_uniform(rng, 1500.0, 5000.0), float(rng.uniform(0.3, 1.0)))],
    "strain_resistance": _strain,
    "large_deflection": lambda rng: [fx.LargeDeflection(float(rng.uniform(0.6, 1.0)))],
    "mains_pickup": _mains,
}


def names() -> list[str]:
    return sorted(SCENARIOS)


def effects_for(name: str, seed: int) -> list[Effect]:
    """The effects of scenario ``name`` (several may be joined with '+'), strengths drawn from ``seed``.

    Combined effects are put in physical order (strip, measurement geometry, sensor channel, pickup)
    whatever order the names were given in; each part draws from a stream keyed by its name, so
    ``a+b`` holds exactly the ``a`` of scenario ``a`` and the ``b`` of scenario ``b``.
    """
    out: list[Effect] = []
    parts = name.split("+")
    for k, part in enumerate(parts):
        if part not in SCENARIOS:
            raise KeyError(f"unknown scenario {part!r} (known: {', '.join(names())})")
        repeat = parts[:k].count(part)  # the same name twice gives two different draws
        out += SCENARIOS[part](np.random.default_rng([seed, zlib.crc32(part.encode()), repeat, 1009]))
    return sorted(out, key=lambda e: getattr(e, "order", 0))
