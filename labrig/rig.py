"""The rig: the instruments of one bench (from a rig file), its clock and its safety limits.

Rig file (TOML), as ``labrig sim --rig-out`` writes it::

    [clock]            time_scale = 1000.0, epoch_wall = <unix time>   (simulated benches only)
    [sample]           preset = "paper"                                (the strip's geometry and medium)
    [sample.specimen]  name, length_m, width_m, thickness_m, clamp_area_m2, medium, temperature_C, batch, notes
    [sample.operator]  name, notes                                     (labrig.specimen; instead of the preset)
    [safety]           max_drive_V, max_current_A, max_force_N
    [instruments.keyence]   address (pyserial URL or device path), dialect
    [instruments.loadcell]  address
    [instruments.clamp]     mode = "motor" (address) or "operator"
    [instruments.impedance] address (VISA resource name)
    [instruments.daq]       address (gRPC host:port, or "local"), device, drive/voltage/current/displacement
                            channels, current_gain_A_per_V, displacement_m_per_V
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from drivers.clamp import ClampController, MotorClamp, OperatorClamp
from drivers.daq import DaqRig
from drivers.errors import InstrumentError
from drivers.impedance_analyzer import ImpedanceAnalyzer
from drivers.keyence import open_keyence
from drivers.loadcell import LoadCell
from drivers.transcript import Transcript
from labrig.clock import ScaledClock
from labrig.errors import BadInput, validation_error
from labrig.physics import presets
from labrig.specimen import OperatorCfg, SpecimenCfg, sample_record, user_record
from labrig.suspenders import SuspendCfg


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid")


class ClockCfg(_Strict):
    time_scale: float = Field(1.0, gt=0)
    epoch_wall: float | None = None


class SafetyCfg(_Strict):
    """Defaults safe for an IPMC in water: below electrolysis-heavy drive, well under the load cell's 98 N."""

    max_drive_V: float = Field(2.0, gt=0)
    max_current_A: float = Field(0.2, gt=0)
    max_force_N: float = Field(90.0, gt=0)
    suspend: SuspendCfg = SuspendCfg()  # [safety.suspend]: conditions that hold the run (labrig.suspenders)


class SampleCfg(_Strict):
    """``[sample]``: a preset strip, or a described one (``[sample.specimen]``, ``[sample.operator]``; labrig.specimen)."""

    preset: str = "paper"
    specimen: SpecimenCfg | None = None
    operator: OperatorCfg | None = None


class KeyenceCfg(_Strict):
    address: str
    dialect: Literal["LK-G", "LK-2000"] = "LK-G"


class LoadCellCfg(_Strict):
    address: str


class ClampCfg(_Strict):
    mode: Literal["motor", "operator"] = "operator"
    address: str | None = None


class ImpedanceCfg(_Strict):
    address: str


class DaqCfg(_Strict):
    address: str = "local"
    device: str = "Dev1"
    drive_channel: str = "ao0"
    voltage_channel: str = "ai0"
    current_channel: str = "ai1"
    displacement_channel: str = "ai2"
    current_gain_A_per_V: float = Field(1e-3, gt=0)
    displacement_m_per_V: float = Field(1e-3, gt=0)


class Instruments(_Strict):
    keyence: KeyenceCfg
    loadcell: LoadCellCfg
    clamp: ClampCfg = ClampCfg()
    impedance: ImpedanceCfg
    daq: DaqCfg


class RigFile(_Strict):
    clock: ClockCfg = ClockCfg()
    sample: SampleCfg = SampleCfg()
    safety: SafetyCfg = SafetyCfg()
    instruments: Instruments


def parse_rig(data: dict[str, Any], source: str) -> RigFile:
    try:
        cfg = RigFile.model_validate(data)
    except ValidationError as exc:
        raise validation_error(exc, source) from None
    if cfg.sample.preset not in presets.names():
        raise BadInput(f"{source}: sample.preset: unknown preset {cfg.sample.preset!r} (known: {', '.join(presets.names())})")
    if cfg.instruments.clamp.mode == "motor" and not cfg.instruments.clamp.address:
        raise BadInput(f"{source}: instruments.clamp.address: required when mode = 'motor'")
    return cfg


def load_rig(path: str | Path) -> RigFile:
    p = Path(path)
    try:
        data = tomllib.loads(p.read_text())
    except FileNotFoundError:
        raise BadInput(f"{path}: no such rig file") from None
    except tomllib.TOMLDecodeError as exc:
        raise BadInput(f"{path}: not valid TOML ({exc})") from None
    return parse_rig(data, str(path))


@dataclass
class Rig:
    """Open drivers + clock + limits. ``safe()`` puts the drive at 0 V before anything else."""

    config: RigFile
    clock: ScaledClock
    daq: DaqRig
    laser: Any
    loadcell: LoadCell
    analyzer: ImpedanceAnalyzer
    clamp: ClampController
    transcript: Transcript = field(default_factory=Transcript)

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

    def safe(self) -> list[str]:
        """Drive to 0 V first, then everything else safe. Never raises; returns what failed."""
        problems = []
        for what, fn in (("daq", self.daq.abort), ("impedance", self.analyzer.safe)):
            try:
                fn()
            except Exception as exc:  # a dead instrument must not stop the others being made safe
                problems.append(f"{what}: {exc}")
        return problems

    def close(self) -> None:
        self.safe()
        for dev in (self.daq, self.analyzer, self.laser, self.loadcell, self.clamp):
            try:
                dev.close()
            except Exception:
                pass


def open_rig(cfg: RigFile, clock: ScaledClock | None = None, transcript: Transcript | None = None) -> Rig:
    """Connect to every instrument of ``cfg`` (drivers record their traffic into ``transcript``)."""
    tr = transcript or Transcript()
    clock = clock or ScaledClock(cfg.clock.time_scale, cfg.clock.epoch_wall)
    ins = cfg.instruments
    opened: list[Any] = []
    try:
        d = ins.daq
        daq = DaqRig(
            device=d.device,
            grpc_target=None if d.address == "local" else d.address,
            drive_channel=d.drive_channel,
            voltage_channel=d.voltage_channel,
            current_channel=d.current_channel,
            displacement_channel=d.displacement_channel,
            current_gain_A_per_V=d.current_gain_A_per_V,
            displacement_m_per_V=d.displacement_m_per_V,
            transcript=tr,
        )
        opened.append(daq)
        analyzer = ImpedanceAnalyzer(ins.impedance.address, transcript=tr, sweep_timeout_s=600.0)
        opened.append(analyzer)
        laser = open_keyence(ins.keyence.address, dialect=ins.keyence.dialect, transcript=tr)
        opened.append(laser)
        loadcell = LoadCell(ins.loadcell.address, transcript=tr, stale_s=2.0)
        opened.append(loadcell)
        clamp = MotorClamp(ins.clamp.address, transcript=tr, max_force_N=cfg.safety.max_force_N) if ins.clamp.mode == "motor" else OperatorClamp()
        return Rig(cfg, clock, daq, laser, loadcell, analyzer, clamp, tr)
    except BaseException:
        for dev in reversed(opened):
            try:
                dev.close()
            except Exception:
                pass
        raise
