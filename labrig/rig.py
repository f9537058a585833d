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
    [instruments.impedance] address (VISA resource name), model ("IM3590", "E4990A" or "SIM-WIDE", the analyser of
                            labrig's older simulator; required: drivers/analyser_models.py)
    [instruments.daq]       address (gRPC host:port, or "local"), device, drive/voltage/current/displacement
                            channels, current_gain_A_per_V, displacement_m_per_V, watchdog_s (rig seconds
                            without a reset from the host before the DAQ puts 0 V on the drive by itself)
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import Field, StringConstraints, ValidationError

from drivers.clamp import ClampController, MotorClamp, OperatorClamp
from drivers.daq import DaqRig
from drivers.daq_watchdog import DEFAULT_TIMEOUT_S as DEFAULT_WATCHDOG_S
from drivers.errors import InstrumentError
from drivers.instrument import Instrument
from drivers import analyser_models
from drivers.analysers import open_analyser
from drivers.impedance_analyzer import ImpedanceAnalyzer
from drivers.keyence import open_keyence
from drivers.loadcell import LoadCell
from drivers.transcript import Transcript
from labrig.clock import ScaledClock
from labrig.errors import BadInput, validation_error
from labrig.safe_read import read_text_file
from labrig.validation import StrictModel, Text, matching
from labrig.physics import presets
from labrig.specimen import OperatorCfg, SpecimenCfg, sample_record, user_record
from labrig.suspenders import SuspendCfg


# the bench's physical limits (docs/input_validation.md says where each comes from)
AO_RANGE_V = 10.0  # the DAQ's analog output range: no safety limit above what the drive can put out
LOADCELL_CAPACITY_N = 98.0  # Dacell UMMA-K10
MAX_RIG_FILE_BYTES = 1 << 20
Address = Annotated[str, StringConstraints(min_length=1, max_length=512), matching(r"[^\x00-\x20\x7f]+", "contains a space or a control character")]
# what pyvisa opens: TCPIP0::host::5025::SOCKET, TCPIP::host::inst0::INSTR, GPIB0::17::INSTR, USB0::...::INSTR, ASRL/dev/ttyUSB0::INSTR
VisaResource = Annotated[str, StringConstraints(max_length=512), matching(
    r"(?i:TCPIP|GPIB|USB|ASRL|VXI|PXI)[^\x00-\x20:]*::[^\x00-\x20\x7f]+", "not a VISA resource name (e.g. TCPIP::192.168.0.5::5025::SOCKET)")]
Channel = Annotated[str, matching(r"[A-Za-z0-9_./-]{1,64}", "not a device or channel name (letters, digits, _ . / -)")]


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


class KeyenceCfg(_Strict):
    address: Address
    dialect: Literal["LK-G", "LK-2000"] = "LK-G"


class LoadCellCfg(_Strict):
    address: Address


class ClampCfg(_Strict):
    mode: Literal["motor", "operator"] = "operator"
    address: Address | None = None


class ImpedanceCfg(_Strict):
    address: VisaResource
    # required: the model sets the range a plan is checked against before anything moves (an E4990A stops at 20 Hz)
    model: Literal[tuple(analyser_models.MODELS)]  # type: ignore[valid-type]


class DaqCfg(_Strict):
    address: Address = "local"
    device: Channel = "Dev1"
    drive_channel: Channel = "ao0"
    voltage_channel: Channel = "ai0"
    current_channel: Channel = "ai1"
    displacement_channel: Channel = "ai2"
    current_gain_A_per_V: float = Field(1e-3, gt=0, le=100.0)  # a current amplifier or shunt: 1 pA/V .. 100 A/V
    displacement_m_per_V: float = Field(1e-3, gt=0, le=1.0)  # the laser's analog output: mm per volt
    watchdog_s: float = Field(DEFAULT_WATCHDOG_S, gt=0, allow_inf_nan=False, strict=True)


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
    """A rig file, every value checked (one line naming the file and field, ``BadInput``) before any instrument opens."""
    return parse_rig(read_text_file(path, "rig file", MAX_RIG_FILE_BYTES, toml=True), str(path))


ZERO_TOL_V = 0.02  # |drive read back| at or below this is 0 V (AI noise ~0.1 mV, 16 bits over ±10 V: 0.3 mV)
STALE_RIG_S = 2.0  # a load cell with no valid frame for this many rig seconds is a fault...
STALE_WALL_S = 0.05  # ... never fewer wall seconds (the host's scheduling: 50 rig s on a 1000x bench)...
STALE_GRACE_WALL_S = 1.0  # ... and a stream that looks stale gets this long to show a frame (a stalled process:
# 0.2 s faulted a seed001 run in 1 of 4 on this 2-core machine with the suite beside it, after a 0.25 s stall)
REPLY_RIG_S = 5.0  # an ordinary instrument reply may take this many rig seconds...
REPLY_WALL_S = 0.5  # ... never fewer wall seconds (a TCP/VISA round trip on a loaded host)
SERIAL_REPLY_RIG_S = 0.5  # a serial instrument (laser, clamp motor) answers a short command within this


def rig_timeout(clock: ScaledClock, rig_s: float, floor_wall_s: float) -> float:
    """``rig_s`` seconds of the rig's clock as a wall-clock timeout, at least ``floor_wall_s``.

    At 1x (a real bench) this is ``rig_s``; on a 1000x simulated bench the floor covers the host's own
    latency, which the scaled clock does not slow down."""
    return max(rig_s / clock.time_scale, floor_wall_s)


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
    def instruments(self) -> dict[str, Instrument]:
        """Every instrument of the rig by its rig-file name, the drive first (the order ``safe()`` and ``close()`` use)."""
        return {"daq": self.daq, "impedance": self.analyzer, "keyence": self.laser, "loadcell": self.loadcell, "clamp": self.clamp}

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
            watchdog_s=d.watchdog_s,
            time_scale=clock.time_scale,
        )
        opened.append(daq)
        analyzer = open_analyser(ins.impedance.address, ins.impedance.model, transcript=tr,
                                                 timeout_s=rig_timeout(clock, REPLY_RIG_S, REPLY_WALL_S),
                                                 sweep_timeout_s=rig_timeout(clock, 600.0, REPLY_WALL_S))
        opened.append(analyzer)
        serial_s = rig_timeout(clock, SERIAL_REPLY_RIG_S, REPLY_WALL_S)
        laser = open_keyence(ins.keyence.address, dialect=ins.keyence.dialect, transcript=tr, timeout_s=serial_s)
        opened.append(laser)
        loadcell = LoadCell(ins.loadcell.address, transcript=tr, clock=clock, grace_wall_s=STALE_GRACE_WALL_S,
                            stale_s=max(STALE_RIG_S, STALE_WALL_S * clock.time_scale))
        opened.append(loadcell)
        clamp = (MotorClamp(ins.clamp.address, transcript=tr, timeout_s=serial_s, max_force_N=cfg.safety.max_force_N)
                 if ins.clamp.mode == "motor" else OperatorClamp())
        return Rig(cfg, clock, daq, laser, loadcell, analyzer, clamp, tr)
    except BaseException:
        for dev in reversed(opened):
            try:
                dev.close()
            except Exception:
                pass
        raise
