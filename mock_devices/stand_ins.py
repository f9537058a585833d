"""How a simulator stands in for its instrument on the simulated bench: it registers itself, from its own module.

A simulator module declares ``@stands_in("<kind>")`` on a function that builds the simulator over the world,
starts it on loopback and returns what it serves (``Served``: the simulator, its ``[instruments.<kind>]``
rig-file table, how to stop it). ``mock_devices.simbench.SimulatedInstruments`` serves every registered
stand-in; labrig reads the tables through the rig file alone, so the simulated bench never imports labrig's
instrument registry (DESIGN.md 2: the simulator knows physics, nothing else of labrig).
"""

from __future__ import annotations

import importlib
import pkgutil
from dataclasses import dataclass
from typing import Any, Callable

from mock_devices.world_api import WorldView


@dataclass(frozen=True)
class SimOptions:
    """What every stand-in is started with (each adds its own offset to ``seed``: the streams stay distinct)."""

    transport: str = "tcp"  # serial instruments on "tcp" (socket://) or "pty"
    seed: int = 0
    impedance_model: str = "IM3590"  # the analyser model served (drivers.analyser_models)


@dataclass
class Served:
    sim: Any  # the simulator (tests and fault injection reach it as ``sims.<kind>``)
    table: dict[str, Any]  # its ``[instruments.<kind>]`` table in a rig file
    stop: Callable[[], None]


StandIn = Callable[[WorldView, SimOptions], Served]
STAND_INS: dict[str, StandIn] = {}


def stands_in(kind: str) -> Callable[[StandIn], StandIn]:
    """Register the decorated function as the simulated stand-in for instruments of ``kind``."""

    def register(fn: StandIn) -> StandIn:
        STAND_INS[kind] = fn
        return fn

    return register


def stand_ins() -> dict[str, StandIn]:
    """Every registered stand-in, after importing every module of ``mock_devices`` (each registers its own)."""
    import mock_devices

    for mod in pkgutil.iter_modules(mock_devices.__path__):
        importlib.import_module(f"mock_devices.{mod.name}")
    return dict(STAND_INS)
