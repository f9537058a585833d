"""The rig: the instruments of one bench (from a rig file), its clock and its safety limits.

Rig file (TOML), as ``labrig sim --rig-out`` writes it::

    [clock]            time_scale = 1000.0, epoch_wall = <unix time>   (simulated benches only)
    [sample]           preset = "paper"                                (the strip's geometry and medium)
    [sample.specimen]  name, length_m, width_m, thickness_m, clamp_area_m2, medium, temperature_C, batch, notes
    [sample.operator]  name, notes                                     (labrig.specimen; instead of the preset)
    [safety]           max_drive_V, max_current_A, max_force_N
    [instruments.<name>]    one table per instrument kind (labrig.instruments: the tables, what each holds)
"""

from __future__ import annotations

import threading
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

from pydantic import Field, ValidationError, create_model

from drivers.errors import InstrumentError
from drivers.instrument import Instrument
from drivers.transcript import Transcript
from labrig.clock import ScaledClock
from labrig.errors import BadInput, validation_error
from labrig.instrument_kind import InstrumentKind, Opening
from labrig.instruments import KINDS
from labrig.safe_read import read_text_file
from labrig.validation import StrictModel, Text
from labrig.physics import presets
from labrig.specimen import OperatorCfg, SpecimenCfg, sample_record, user_record
from labrig.suspenders import SuspendCfg


# the bench's physical limits (docs/input_validation.md says where each comes from)
AO_RANGE_V = 10.0  # the DAQ's analog output range: no safety limit above what the drive can put out
LOADCELL_CAPACITY_N = 98.0  # Dacell UMMA-K10
MAX_RIG_FILE_BYTES = 1 << 20


def kinds() -> dict[str, InstrumentKind]:
    """The instrument kinds a rig file may hold (``labrig.instruments.KINDS``), in opening order: the drive first."""
    return dict(KINDS)


class _Strict(StrictModel):
    """Every rig model: strict (labrig.validation): unknown keys, booleans as numbers, inf and nan refused."""


class ClockCfg(_Strict):
    # a simulated bench runs 1..1e5 x; below 0.1 x a second of protocol is minutes of waiting (a typo, not a bench)
    time_scale: float = Field(1.0, ge=0.1, le=1e5)
    epoch_wall: float | None = Field(None, ge=0, le=4e9)  # unix time (4e9: year 2096)


class SafetyCfg(_Strict):
    """Defaults safe for an IPMC in water: below electrolysis-heavy drive, well under the load cell's 98 N."""

    max_drive_V: float = Field(2.0, gt=0, le=AO_RANGE_V)
    max_current_A: float = Field(0.2, gt=0, le=10.0)
    max_force_N: float = Field(90.0, gt=0, le=LOADCELL_CAPACITY_N)
    suspend: SuspendCfg = SuspendCfg()  # [safety.suspend]: conditions that hold the run (labrig.suspenders)


class SampleCfg(_Strict):
    """``[sample]``: a preset strip, or a described one (``[sample.specimen]``, ``[sample.operator]``; labrig.specimen)."""

    preset: Text = "paper"
    specimen: SpecimenCfg | None = None
    operator: OperatorCfg | None = None


class RigFile(_Strict):
    """A rig file. ``instruments`` holds one table per kind of ``kinds()`` (``rig_file_model`` types it)."""

    clock: ClockCfg = ClockCfg()
    sample: SampleCfg = SampleCfg()
    safety: SafetyCfg = SafetyCfg()
    instruments: Any


@lru_cache(maxsize=8)
def _rig_file_model(kinds: tuple[InstrumentKind, ...]) -> type[RigFile]:
    tables: dict[str, Any] = {k.name: (k.config, ... if k.default is None else k.default) for k in kinds}
    instruments = create_model("Instruments", __base__=_Strict, **tables)
    return create_model("RigFile", __base__=RigFile, instruments=(instruments, ...))


def rig_file_model() -> type[RigFile]:
    """The rig file's model: ``RigFile`` with an ``[instruments.<name>]`` table for every registered kind."""
    return _rig_file_model(tuple(kinds().values()))


def parse_rig(data: dict[str, Any], source: str) -> RigFile:
    try:
        cfg = rig_file_model().model_validate(data)
    except ValidationError as exc:
        raise validation_error(exc, source) from None
    if cfg.sample.preset not in presets.names():
        raise BadInput(f"{source}: sample.preset: unknown preset {cfg.sample.preset!r} (known: {', '.join(presets.names())})")
    return cfg


def load_rig(path: str | Path) -> RigFile:
    """A rig file, every value checked (one line naming the file and field, ``BadInput``) before any instrument opens."""
    return parse_rig(read_text_file(path, "rig file", MAX_RIG_FILE_BYTES, toml=True), str(path))


ZERO_TOL_V = 0.02  # |drive read back| at or below this is 0 V (AI noise ~0.1 mV, 16 bits over ±10 V: 0.3 mV)


@dataclass(frozen=True)
class SafeState:
    """What ``Rig.safe()`` achieved: the drive as read back (None: could not be read) and what failed."""

    drive_V: float | None
    problems: tuple[str, ...] = ()

    @property
    def verified(self) -> bool:
        """The drive was read back at 0 V."""
        return self.drive_V is not None and abs(self.drive_V) <= ZERO_TOL_V

    def line(self) -> str:
        """One phrase for the operator: the drive state, and what to do when it is not known to be 0 V."""
        if self.verified:
            return f"drive read back at {self.drive_V:+.3f} V"
        if self.drive_V is None:
            return ("drive state UNKNOWN (it could not be read back): check that the DAQ's watchdog put its output "
                    "at 0 V, or switch off the amplifier")
        return f"drive read back at {self.drive_V:+.3f} V, NOT 0 V: switch off the amplifier now"


@dataclass
class Rig:
    """Open drivers + clock + limits. ``safe()`` puts the drive at 0 V before anything else.

    ``instruments``: every instrument by its rig-file name, in ``kinds()`` order (the drive first: the order
    ``safe()`` and ``close()`` use). The protocols' roles read them by name: ``daq``, ``analyzer``, ``laser``,
    ``loadcell``, ``clamp``."""

    config: RigFile
    clock: ScaledClock
    instruments: dict[str, Instrument] = field(default_factory=dict)
    transcript: Transcript = field(default_factory=Transcript)
    # one safe() at a time: the force logger's thread and the run's thread may both make the rig safe at once
    _safe_lock: threading.RLock = field(default_factory=threading.RLock, repr=False, compare=False)

    @property
    def daq(self) -> Any:  # drivers.daq.Daq
        return self.instruments["daq"]

    @property
    def analyzer(self) -> Any:  # drivers.analysers: the model's driver
        return self.instruments["impedance"]

    @property
    def laser(self) -> Any:  # drivers.keyence
        return self.instruments["keyence"]

    @property
    def loadcell(self) -> Any:  # drivers.loadcell.LoadCell
        return self.instruments["loadcell"]

    @property
    def clamp(self) -> Any:  # drivers.clamp: MotorClamp or OperatorClamp
        return self.instruments["clamp"]

    @property
    def limits(self) -> SafetyCfg:
        return self.config.safety

    @property
    def clamp_area_m2(self) -> float:
        spec = self.config.sample.specimen
        return spec.clamp_area_m2 if spec is not None else presets.get(self.config.sample.preset).base.geometry.clamp_area

    def user_info(self) -> dict[str, Any]:
        """Who ran it (``/entry/user``): the [operator] table, {} when not given."""
        return user_record(self.config.sample.operator)

    def sample_info(self) -> dict[str, Any]:
        if self.config.sample.specimen is not None:
            return sample_record(self.config.sample.specimen)
        g = presets.get(self.config.sample.preset).base
        return {
            "preset": self.config.sample.preset,
            "length_m": g.geometry.length,
            "width_m": g.geometry.width,
            "thickness_m": g.geometry.thickness,
            "clamp_length_m": g.geometry.clamp_length,
            "clamp_area_m2": g.geometry.clamp_area,
            "medium": g.fluid.name,
        }

    def describe(self) -> dict[str, Any]:
        d = self.config.model_dump(mode="json")
        try:
            d["identity"] = {"impedance": self.analyzer.identify(), "daq": self.daq.describe()}
        except InstrumentError as exc:
            d["identity"] = {"error": str(exc)}
        return d

    def safe(self) -> SafeState:
        """Drive to 0 V first, then everything else safe, then read the drive back. Never raises.

        Every instrument with an output (``Instrument.has_output``: the drive, the analyser's source) is made
        safe, the drive first. The drive counts as safe only when read back at 0 V (``SafeState.verified``):
        ``safe()``'s own word is not enough, since a write to a dead link cannot be confirmed."""
        with self._safe_lock, self.daq.held():  # 0 V written and read back with no record started between
            return self._safe()

    def _safe(self) -> SafeState:
        problems = []
        for name, dev in self.instruments.items():
            if not dev.has_output:
                continue
            try:
                if not dev.safe():
                    problems.append(f"{name}: could not write 0 V to the {'drive' if dev is self.daq else 'output'}")
            except Exception as exc:  # a dead instrument must not stop the others being made safe
                problems.append(f"{name}: {exc}")
        if self.daq.replaying:
            return SafeState(0.0, tuple(problems))  # a replay drives nothing
        try:
            drive = self.daq.drive_readback_V()
        except Exception as exc:
            problems.append(f"daq: drive read-back failed: {exc}")
            return SafeState(None, tuple(problems))
        if abs(drive) > ZERO_TOL_V and not problems:  # written but not there: try once more, then say so
            self.daq.safe()
            try:
                drive = self.daq.drive_readback_V()
            except Exception as exc:
                problems.append(f"daq: drive read-back failed: {exc}")
                return SafeState(None, tuple(problems))
        return SafeState(drive, tuple(problems))

    def close(self) -> None:
        self.safe()
        for dev in self.instruments.values():
            try:
                dev.close()
            except Exception:
                pass


def open_rig(cfg: RigFile, clock: ScaledClock | None = None, transcript: Transcript | None = None) -> Rig:
    """Connect to every instrument of ``cfg`` (drivers record their traffic into ``transcript``), in ``kinds()``
    order; if one fails, those already open are closed again."""
    tr = transcript or Transcript()
    clock = clock or ScaledClock(cfg.clock.time_scale, cfg.clock.epoch_wall)
    opening = Opening(cfg, clock, tr)
    opened: dict[str, Instrument] = {}
    try:
        for name, kind in kinds().items():
            opened[name] = kind.open(getattr(cfg.instruments, name), opening)
        return Rig(cfg, clock, opened, tr)
    except BaseException:
        for dev in reversed(opened.values()):
            try:
                dev.close()
            except Exception:
                pass
        raise
