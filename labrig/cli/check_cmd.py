"""``labrig check --rig RIG.toml [--json]``: before a long run, connect to every instrument of a rig, identify it,
read one harmless value, and say per instrument: ok, or the fault and what to look at. Exit 3 naming the
instruments that fault (DESIGN.md: labrig check)."""

from __future__ import annotations

from contextlib import closing
from dataclasses import asdict, dataclass
from typing import Callable

import click
import numpy as np

from labrig.rig import RigFile, load_rig

TIMEOUT_S = 3.0


@dataclass
class CheckLine:
    instrument: str
    ok: bool
    identity: str = ""
    value: str = ""
    fault: str = ""
    look_at: str = ""

    def text(self) -> str:
        if self.ok:
            return f"ok     {self.instrument:10s} {self.identity}; {self.value}"
        return f"FAULT  {self.instrument:10s} {self.fault} -> look at: {self.look_at}"


def _daq(cfg: RigFile) -> tuple[str, str]:
    from drivers.daq import DaqRig

    d = cfg.instruments.daq
    with DaqRig(device=d.device, grpc_target=None if d.address == "local" else d.address, drive_channel=d.drive_channel,
                voltage_channel=d.voltage_channel, current_channel=d.current_channel,
                displacement_channel=d.displacement_channel, current_gain_A_per_V=d.current_gain_A_per_V,
                displacement_m_per_V=d.displacement_m_per_V) as daq:
        out = daq.run_finite(np.zeros(20), 1000.0, timeout_s=10.0)  # 20 ms at 0 V: reads every AI channel
    where = "this computer" if d.address == "local" else f"gRPC {d.address}"
    return (f"NI-DAQmx {d.device} on {where}",
            f"AI at 0 V drive: {np.mean(out['v_V']):+.4f} V, {np.mean(out['i_A']) * 1e3:+.4f} mA, "
            f"{np.mean(out['disp_m']) * 1e3:+.4f} mm")


def _impedance(cfg: RigFile) -> tuple[str, str]:
    from drivers import analyser_models
    from drivers.analysers import open_analyser

    ins = cfg.instruments.impedance
    an = open_analyser(ins.address, ins.model, timeout_s=TIMEOUT_S)
    with closing(an):
        idn = an.identify()
        if ins.model != analyser_models.LEGACY_MODEL and ins.model not in idn.upper():
            raise ModelMismatch(f"the rig file names a {ins.model} but the instrument answers *IDN? {idn!r}")
        return idn, f"AC level {an.ac_V:g} V; {analyser_models.get(ins.model).range_text()}"


def _keyence(cfg: RigFile) -> tuple[str, str]:
    from drivers.keyence import open_keyence

    k = cfg.instruments.keyence
    with open_keyence(k.address, dialect=k.dialect, timeout_s=TIMEOUT_S) as laser:
        program = laser.program()
        d = laser.read_displacement(1)
    return f"Keyence {k.dialect} controller, program {program}", f"OUT1 {d * 1e3:+.4f} mm"


def _loadcell(cfg: RigFile) -> tuple[str, str]:
    from drivers.loadcell import LoadCell

    with LoadCell(cfg.instruments.loadcell.address, stale_s=TIMEOUT_S) as lc:
        frame = lc.latest()
    return f"indicator frame {frame.raw.strip().decode('ascii', 'replace')!r}", f"{frame.force_N:.3f} N ({'stable' if frame.stable else 'unstable'})"


def _clamp(cfg: RigFile) -> tuple[str, str]:
    from drivers.clamp import MotorClamp

    c = cfg.instruments.clamp
    if c.mode == "operator":
        return "operator-set clamp", "nothing to connect (the load cell confirms the force)"
    with MotorClamp(c.address, timeout_s=TIMEOUT_S, max_force_N=cfg.safety.max_force_N) as clamp:
        return "motor clamp controller", f"target {clamp.target_N():.2f} N"


class ModelMismatch(Exception):
    """The instrument is not the model the rig file names."""


# instrument -> (check, where to look when it faults)
CHECKS: dict[str, tuple[Callable[[RigFile], tuple[str, str]], str]] = {
    "daq": (_daq, "the NI device name and, for a remote DAQ, the gRPC server at the address"),
    "impedance": (_impedance, "the analyser's LAN settings (IP, port), that it is on, and [instruments.impedance] model"),
    "keyence": (_keyence, "the RS-232C cable, port and baud rate, the controller's power and its mode (R0 = general)"),
    "loadcell": (_loadcell, "the indicator's power, cable and port, and that its stream output is on"),
    "clamp": (_clamp, "the clamp controller's cable, port and power"),
}


def check_instrument(name: str, cfg: RigFile) -> CheckLine:
    """One instrument: connect, identify, read; any failure becomes the line's fault (never raises)."""
    fn, look_at = CHECKS[name]
    try:
        identity, value = fn(cfg)
    except Exception as exc:  # the point is to report every instrument, whatever went wrong with one
        return CheckLine(name, False, fault=f"{type(exc).__name__}: {exc}", look_at=look_at)
    return CheckLine(name, True, identity=identity, value=value)


def check_rig(cfg: RigFile) -> list[CheckLine]:
    return [check_instrument(name, cfg) for name in CHECKS]


@click.command("check")
@click.option("--rig", "rig_path", required=True, type=click.Path(dir_okay=False), help="the rig file to check")
@click.option("--json", "as_json", is_flag=True, help="one JSON object: {ok, instruments: [...]}")
def check_cmd(rig_path: str, as_json: bool) -> None:
    """Connect to every instrument of RIG.toml, identify it and read one value; exit 3 if any faults."""
    from labrig.cli.common import print_json

    lines = check_rig(load_rig(rig_path))
    faulty = [line.instrument for line in lines if not line.ok]
    if as_json:
        print_json({"ok": not faulty, "rig": rig_path, "instruments": [asdict(line) for line in lines]})
    else:
        for line in lines:
            click.echo(line.text())
    if faulty:
        click.echo(f"labrig check: instrument fault: {', '.join(faulty)}", err=True)
        raise click.exceptions.Exit(3)
