"""``labrig check --rig RIG.toml [--json]``: before a long run, connect to every instrument of a rig, identify it,
read one harmless value, and say per instrument: ok, or the fault and what to look at. What each check does is
its kind's entry in ``labrig.instruments``. Exit 3 naming the
instruments that fault (DESIGN.md: labrig check)."""

from __future__ import annotations

from dataclasses import asdict, dataclass

import click

from labrig.rig import RigFile, kinds, load_rig


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


def check_instrument(name: str, cfg: RigFile) -> CheckLine:
    """One instrument: connect, identify, read (its kind's ``check``); any failure becomes the line's fault
    (never raises)."""
    kind = kinds()[name]
    try:
        identity, value = kind.check(getattr(cfg.instruments, name), cfg)
    except Exception as exc:  # the point is to report every instrument, whatever went wrong with one
        return CheckLine(name, False, fault=f"{type(exc).__name__}: {exc}", look_at=kind.look_at)
    return CheckLine(name, True, identity=identity, value=value)


def check_rig(cfg: RigFile) -> list[CheckLine]:
    """Every instrument of the rig, in ``kinds()`` order."""
    return [check_instrument(name, cfg) for name in kinds()]


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
