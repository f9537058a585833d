"""``labrig replay``: a recorded session into the live window, or re-run against its recorded traffic."""

from __future__ import annotations

from pathlib import Path

import click

from labrig.errors import BadInput


@click.command("replay")
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--live", is_flag=True, help="play the session into the live window with its original timing")
@click.option("--speed", default=1.0, show_default=True, type=float, help="time scale of the playback (0: as fast as possible)")
@click.option("--screenshot", type=click.Path(dir_okay=False), help="save the window as PNG when the replay ends (then close)")
@click.option("--check", "do_check", is_flag=True, help="re-run the protocol against the recorded instrument traffic")
def replay_cmd(file: str, live: bool, speed: float, screenshot: str | None, do_check: bool) -> None:
    """Replay FILE.h5: --live plays it into the window; --check re-runs its protocol on its recorded traffic.

    --check exits 0 on PASS, 1 at the first divergence (the step and the command or stream), 2 on bad input.
    """
    from labrig.store.reader import SessionReader

    if not Path(file).exists():
        raise BadInput(f"{file}: no such file")
    if not (live or do_check):
        raise BadInput("give --live and/or --check")
    if speed < 0:
        raise BadInput(f"--speed {speed:g}: must be >= 0")
    if screenshot and not live:
        raise BadInput("--screenshot needs --live")
    with SessionReader(file):  # BadInput (exit 2) for a file that is not a session
        pass
    code = 0
    if do_check:
        from labrig.replay import check

        res = check(file)
        click.echo(res.message)
        for note in res.notes:
            click.echo(f"  note: {note}")
        code = 0 if res.ok else 1
    if live:
        from labrig.replay import replay_live

        n = replay_live(file, speed, screenshot)
        click.echo(f"replayed {n} events" + (f"; screenshot {screenshot}" if screenshot else ""), err=True)
    if code:
        # SystemExit, not click's Exit: with standalone_mode=False click 8.5 returns Exit's code from
        # app.main() instead of raising it, and labrig.cli.main drops that return value (exit 0)
        raise SystemExit(code)
