"""``labrig run`` (a protocol on the simulated or a real bench) and ``labrig sim`` (serve the simulators)."""

from __future__ import annotations

import signal
import sys
import threading
import time
from contextlib import ExitStack
from pathlib import Path
from typing import Any

import click
import tomli_w

from labrig.errors import BadInput
from labrig.suspenders import terminal_ask
from labrig.clock import SIM_TIME_SCALE as DEFAULT_TIME_SCALE


def _effects(scenario: str, seed: int) -> list[Any]:
    from mock_devices import scenarios

    try:
        return scenarios.effects_for(scenario, seed)
    except KeyError as exc:
        raise BadInput(f"--scenario: {exc.args[0]}") from None


def _known_preset(ctx: click.Context, param: click.Parameter, value: str) -> str:
    from labrig.physics import presets

    if value not in presets.names():
        raise click.BadParameter(f"unknown preset {value!r} (known: {', '.join(presets.names())})")
    return value


SEED = click.IntRange(0, 2**32 - 1)  # numpy's seed range


class _Interrupts:
    """Ctrl-C at a terminal: hold the run at the next safe point (drive at 0 V) and ask: resume, pause or
    abort. Without a terminal: stop at the next safe point. A second Ctrl-C (or SIGTERM) stops now
    (KeyboardInterrupt). SIGUSR1 pauses a headless run, and resumes it when sent again."""

    def __init__(self, runner: Any):
        self.runner, self.count = runner, 0
        self.ask = sys.stdin.isatty() and sys.stderr.isatty()

    def __enter__(self) -> "_Interrupts":
        self._old: dict[int, Any] = {}
        if threading.current_thread() is threading.main_thread():
            for sig in (signal.SIGINT, signal.SIGTERM, getattr(signal, "SIGUSR1", None)):
                if sig is not None:
                    self._old[sig] = signal.signal(sig, self._handle)
        return self

    def _handle(self, signum: int, frame: Any) -> None:
        if signum == getattr(signal, "SIGUSR1", None):
            self.runner.pauses.toggle("SIGUSR1")
            return
        self.count += 1
        pauses = self.runner.pauses
        if signum == signal.SIGINT and self.ask and pauses.pending() is None:
            self.count = 0  # the prompt decides; a Ctrl-C at the prompt aborts
            click.echo("\nCtrl-C: holding at the next safe point (Ctrl-C again to stop now)", err=True)
            pauses.ask = terminal_ask()
            pauses.request("Ctrl-C")
        elif self.count == 1 and signum == signal.SIGINT:
            click.echo("\nstopping at the next safe point (Ctrl-C again to stop now)", err=True)
            self.runner.request_stop()
        else:
            raise KeyboardInterrupt

    def __exit__(self, *exc: object) -> None:
        for sig, old in self._old.items():
            signal.signal(sig, old)


@click.command("run")
@click.argument("protocol", required=False)
@click.option("--sim", is_flag=True, help="run on a fresh simulated bench in this process")
@click.option("--rig", "rig_path", type=click.Path(dir_okay=False), help="rig file of real (or `labrig sim`) instruments")
@click.option("--scenario", default="none", show_default=True, help="hidden effect(s) on the simulated bench, joined with '+'")
@click.option("--seed", default=0, show_default=True, type=SEED)
@click.option("--preset", default="paper", show_default=True, callback=_known_preset, help="the simulated strip")
@click.option("--time-scale", default=DEFAULT_TIME_SCALE, show_default=True, type=click.FloatRange(0.1, 1e5), help="simulated bench speed")
@click.option("--out", type=click.Path(dir_okay=False), help="session file to write (HDF5)")
@click.option("--resume", "resume_path", type=click.Path(dir_okay=False), help="continue an interrupted session file")
@click.option("--live", is_flag=True, help="show the live plot window")
@click.option("--fit", "do_fit", is_flag=True, help="fit the model straight after the run")
@click.option("--diagnose", "do_diagnose", is_flag=True, help="diagnose straight after the fit")
@click.option("--limit", "limits", multiple=True, metavar="NAME=VALUE", help="simulated bench safety limit, e.g. max_current_A=0.05 (repeatable)")
@click.option("--sample", "sample_path", type=click.Path(dir_okay=False), help="specimen file (TOML: [specimen], [operator]) for this run")
@click.option("--pause-file", type=click.Path(dir_okay=False), help="hold the run (drive at 0 V) while this file exists")
@click.option("-q", "--quiet", is_flag=True, help="no progress display")
def run_cmd(protocol, sim, rig_path, scenario, seed, preset, time_scale, out, resume_path, live, do_fit, do_diagnose, limits,
            sample_path, pause_file, quiet) -> None:
    """Run PROTOCOL (a bundled name such as paper-sweep, or a TOML file) and store every sample.

    With --resume FILE.h5, continue the protocol stored in that session from its first unfinished step."""
    from labrig.session_run import RunRequest, execute

    if sim == bool(rig_path):
        raise BadInput("give exactly one of --sim or --rig RIG.toml")
    if not protocol and not resume_path:
        raise BadInput("give a PROTOCOL (a bundled name or a TOML file), or --resume FILE.h5")
    if protocol and resume_path:
        raise BadInput("--resume continues the protocol stored in the session: do not name one")
    if resume_path and out:
        raise BadInput("--resume appends to its own file: do not give --out")
    if resume_path and sample_path:
        raise BadInput("--resume continues with the sample stored in the session: do not give --sample")
    if not resume_path and not out:
        raise BadInput("--out FILE.h5 is required")
    path = Path(resume_path or out)
    if out and path.exists():
        raise BadInput(f"{out}: already exists; labrig never overwrites a session (choose another --out)")
    if resume_path and not path.exists():
        raise BadInput(f"{resume_path}: no such session to resume")
    if not sim and scenario != "none":
        raise BadInput("--scenario needs --sim")
    safety = {}
    for item in limits:
        name, _, value = item.partition("=")
        try:
            safety[name.strip()] = float(value)
        except ValueError:
            raise BadInput(f"--limit {item}: expected NAME=NUMBER, e.g. max_current_A=0.05") from None
    if safety and not sim:
        raise BadInput("--limit applies to --sim; a real rig's limits live in its rig file's [safety] table")
    req = RunRequest(
        protocol=protocol,
        path=path,
        resume=bool(resume_path),
        sim=sim,
        rig_path=rig_path,
        effects=_effects(scenario, seed) if sim else [],
        seed=seed,
        preset=preset,
        time_scale=time_scale,
        live=live,
        quiet=quiet,
        safety=safety,
        pause_file=pause_file,
        sample_path=sample_path,
    )
    result = execute(req, interrupts=_Interrupts)
    if result.noop:
        click.echo(f"labrig: {result.reason}", err=True)
        return
    if result.exit_code == 0 and (do_fit or do_diagnose):
        _after_run(path, fit=do_fit or do_diagnose, diagnose=do_diagnose, quiet=quiet)
    if result.exit_code != 0:
        drive = f"; {result.drive}" if result.drive else ""
        click.echo(f"labrig: run {result.exit_status}: {result.reason}{drive} (data so far kept in {path})", err=True)
        raise click.exceptions.Exit(result.exit_code)


@click.command("sim")
@click.option("--rig-out", required=True, type=click.Path(dir_okay=False), help="rig file to write")
@click.option("--preset", default="paper", show_default=True, callback=_known_preset)
@click.option("--scenario", default="none", show_default=True)
@click.option("--seed", default=0, show_default=True, type=SEED)
@click.option("--time-scale", default=DEFAULT_TIME_SCALE, show_default=True, type=click.FloatRange(0.1, 1e5))
@click.option("--transport", type=click.Choice(["tcp", "pty"]), default="tcp", show_default=True, help="serial instruments on socket:// or a pty")
@click.option("--impedance", "impedance_model", type=click.Choice(["IM3590", "E4990A", "SIM-WIDE"], case_sensitive=False),
              default="IM3590", show_default=True, help="the impedance analyser served (E4990A: 20 Hz floor)")
def sim_cmd(rig_out, preset, scenario, seed, time_scale, transport, impedance_model) -> None:
    """Serve the simulated instruments on 127.0.0.1 until SIGINT/SIGTERM; write the rig file pointing at them."""
    from labrig.clock import ScaledClock
    from labrig.simulate import rig_file_data
    from mock_devices.simbench import SimulatedInstruments
    from mock_devices.world import World

    effects = _effects(scenario, seed)
    clock = ScaledClock(time_scale, time.time())
    bench = World(clock, preset=preset, seed=seed, effects=effects)
    stop = threading.Event()
    handler = lambda signum, frame: stop.set()  # noqa: E731
    signal.signal(signal.SIGINT, handler)
    signal.signal(signal.SIGTERM, handler)
    with ExitStack() as stack:
        sims = stack.enter_context(SimulatedInstruments(bench, serial_transport=transport, seed=seed, impedance_model=impedance_model.upper()))
        data = rig_file_data(sims, clock, preset)
        try:
            # written whole then renamed: a client polling for the file never reads half of it
            partial = Path(rig_out).with_name(Path(rig_out).name + ".partial")
            partial.write_text("# written by `labrig sim`: simulated instruments on loopback\n" + tomli_w.dumps(data))
            partial.replace(rig_out)
        except OSError as exc:
            raise BadInput(f"{rig_out}: cannot write ({exc.strerror})") from None
        for name, table in data["instruments"].items():
            click.echo(f"{name:10s} {table.get('address', table.get('mode'))}")
        click.echo(f"rig file: {rig_out}  (time scale {time_scale:g}x; Ctrl-C to stop)", err=True)
        while not stop.wait(0.2):
            pass
    click.echo("simulated instruments stopped", err=True)


def _after_run(path: Path, fit: bool, diagnose: bool, quiet: bool) -> None:
    """``--fit`` / ``--diagnose``: the session's seed-000 fit (once), stored and printed, then its diagnosis."""
    from labrig.analysis import load_and_fit, run_fit
    from labrig.cli import analysis_cmds, diagnose_cmd

    fitted = load_and_fit(path)
    if fit:
        out = run_fit(path, fitted=fitted)
        if not quiet:
            analysis_cmds.summary(out)
    if diagnose:
        diagnose_cmd.run_and_print(path, as_json=False, quiet=quiet, fitted=fitted)
