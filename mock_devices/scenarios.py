"""Hidden-effect scenarios for the simulated bench: ``labrig run ... --sim --scenario NAME --seed N``.

Each scenario draws physically plausible strengths from the seed. The truth stays in this process; it
never reaches the session file or anything the diagnosis reads.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from mock_devices.world import Effect

ScenarioFactory = Callable[[np.random.Generator], list[Effect]]

SCENARIOS: dict[str, ScenarioFactory] = {
    "none": lambda rng: [],
}


def names() -> list[str]:
    return sorted(SCENARIOS)


def effects_for(name: str, seed: int) -> list[Effect]:
    """The effects of scenario ``name`` (several may be joined with '+'), strengths drawn from ``seed``."""
    out: list[Effect] = []
    for k, part in enumerate(name.split("+")):
        if part not in SCENARIOS:
            raise KeyError(f"unknown scenario {part!r} (known: {', '.join(names())})")
        out += SCENARIOS[part](np.random.default_rng([seed, k, 1009]))
    return out
