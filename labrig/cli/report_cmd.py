"""``labrig report``: one self-contained HTML page of a session (docs/report.md)."""

from __future__ import annotations

from pathlib import Path

import click

from labrig.errors import BadInput


@click.command("report")
@click.argument("session", type=click.Path(dir_okay=False))
@click.option("--out", required=True, type=click.Path(dir_okay=False), help="HTML file to write (overwritten)")
@click.option("--recompute", is_flag=True, help="ignore the diagnosis and seed-001 front stored in the session and compute them again")
def report_cmd(session: str, out: str, recompute: bool) -> None:
    """A self-contained HTML report of SESSION: header, seed-000 fit, seed-001 Pareto front, diagnosis."""
    from labrig.report import build_report

    if not Path(session).exists():
        raise BadInput(f"{session}: no such session file")
    if not Path(out).resolve().parent.is_dir():
        raise BadInput(f"{out}: no such directory to write the report into")
    data = build_report(session, out, recompute=recompute)
    lacks = ", ".join(sorted(data.missing))
    click.echo(f"wrote {out}" + (f"; sections without data: {lacks}" if lacks else ""))
    for w in data.warnings:
        click.echo(f"warning: {w}", err=True)
