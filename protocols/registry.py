"""Bundled protocols by name, and loading a protocol from a TOML file a user copied and edited.

A protocol file names its protocol and holds that protocol's settings tables, e.g.::

    protocol = "paper-sweep"
    [clamp]
    pressures_kPa = [612, 3062]

Anything wrong is refused with one line naming the file, the field and the problem.
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any, Callable, Iterator

from pydantic import ValidationError

from labrig.errors import BadInput, validation_error
from protocols.config import Strict
from protocols.paper_sweep import PaperSweep, paper_sweep
from protocols.seed001 import Seed001Protocol, seed001_plan
from protocols.single import (
    AmplitudeSeriesProtocol,
    EisProtocol,
    HarmonicProtocol,
    MultisineProtocol,
    SteppedSineProtocol,
    StepProtocol,
    single_plan,
)
from protocols.steps import Step

PlanFn = Callable[[Any, float], Iterator[Step]]

PROTOCOLS: dict[str, tuple[type[Strict], PlanFn]] = {
    "paper-sweep": (PaperSweep, paper_sweep),
    "eis": (EisProtocol, single_plan),
    "stepped-sine": (SteppedSineProtocol, single_plan),
    "multisine": (MultisineProtocol, single_plan),
    "step": (StepProtocol, single_plan),
    "harmonic": (HarmonicProtocol, single_plan),
    "amplitude-series": (AmplitudeSeriesProtocol, single_plan),
    "seed001": (Seed001Protocol, seed001_plan),
}


@dataclass(frozen=True)
class LoadedProtocol:
    name: str
    config: Strict
    source: str  # where it came from (bundled preset or a path)

    def plan(self, clamp_area_m2: float) -> list[Step]:
        """Materialise the plan (the runner validates and announces it before anything moves)."""
        _, fn = PROTOCOLS[self.name]
        steps = list(fn(self.config, clamp_area_m2))
        names = [s.name for s in steps]
        dup = {n for n in names if names.count(n) > 1}
        if dup:
            raise BadInput(f"{self.source}: the plan repeats step names {sorted(dup)[:3]}")
        return steps

    def as_dict(self) -> dict[str, Any]:
        return {"protocol": self.name, **self.config.model_dump(mode="json")}


def preset_text(name: str) -> str:
    return resources.files("protocols").joinpath("presets", f"{name}.toml").read_text()


def _validate(name: str, data: dict[str, Any], source: str) -> LoadedProtocol:
    model, _ = PROTOCOLS[name]
    try:
        return LoadedProtocol(name, model.model_validate(data), source)
    except ValidationError as exc:
        raise validation_error(exc, source) from None


def from_dict(data: dict[str, Any], source: str) -> LoadedProtocol:
    data = dict(data)
    name = data.pop("protocol", None)
    if name not in PROTOCOLS:
        raise BadInput(f"{source}: protocol: {'missing' if name is None else repr(name) + ' is not one of ' + ', '.join(PROTOCOLS)}")
    return _validate(name, data, source)


def bundled() -> list[str]:
    """Names ``labrig run`` accepts without a file: each protocol's preset, plus variants such as
    ``paper-sweep-amplitudes`` (a preset TOML of an existing protocol)."""
    return sorted(p.name[:-5] for p in resources.files("protocols").joinpath("presets").iterdir() if p.name.endswith(".toml"))


def load(spec: str) -> LoadedProtocol:
    """A bundled protocol name (its preset) or the path of a TOML protocol file."""
    if spec in bundled():
        return from_dict(tomllib.loads(preset_text(spec)), f"preset {spec}")
    path = Path(spec)
    if not path.exists():
        raise BadInput(f"{spec}: no such protocol file (bundled protocols: {', '.join(bundled())})")
    try:
        data = tomllib.loads(path.read_text())
    except tomllib.TOMLDecodeError as exc:
        raise BadInput(f"{spec}: not valid TOML ({exc})") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise BadInput(f"{spec}: cannot read ({exc})") from None
    return from_dict(data, str(spec))
