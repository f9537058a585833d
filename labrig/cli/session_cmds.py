"""``labrig inspect`` (what a session holds, what is incomplete), ``labrig import`` (CSV manifest -> session) and
``labrig export`` (session -> CSV manifest, the inverse)."""

from __future__ import annotations

from typing import Any

import click

from labrig.cli.common import print_json
from labrig.store.summary import summary


def _identity(conf: dict[str, Any]) -> str:
    keys = ("model", "identity", "idn", "address", "port", "resource", "target")
    found = [str(conf[k]) for k in keys if k in conf and not isinstance(conf[k], (dict, list))]
    return f" ({', '.join(found[:2])})" if found else ""


def _print(s: dict[str, Any]) -> None:
    echo = click.echo
    echo(f"session      {s['file']}")
    echo(f"run          {s['run_uid']}  protocol {s['protocol']}  labrig {s['labrig_version']}")
    for res in s["resumes"]:
        echo(f"resumed      {res['start_time']} as run {res['uid']}")
    end = s["exit_status"] or "none (no RunStop)"
    reason = f" ({s['reason']})" if s["reason"] else ""
    echo(f"time         {s['start_time']} .. {s['end_time'] or '?'}  exit status {end}{reason}")
    echo("sample       " + ("  ".join(f"{k}={v}" for k, v in s["sample"].items()) or "(none)"))
    if s["user"]:
        echo("operator     " + "  ".join(f"{k}={v}" for k, v in s["user"].items()))
    inst = [f"{name}{_identity(conf)}" for name, conf in s["instruments"].items()]
    echo("instruments  " + (", ".join(inst) or "(none)"))
    echo(f"steps        {len(s['steps'])}")
    width = max((len(st["name"]) for st in s["steps"]), default=4)
    kwidth = max((len(st["kind"]) for st in s["steps"]), default=4)
    for st in s["steps"]:
        p = f"{st['pressure_kPa']:7g} kPa" if isinstance(st["pressure_kPa"], (int, float)) else " " * 11
        d = f"{st['duration_s']:9.2f} s" if st["duration_s"] is not None else " " * 11
        rows = ", ".join(f"{k} {n}" + (f"/{st['expected_rows'][k]}" if st["expected_rows"].get(k) else "") for k, n in st["rows"].items())
        echo(f"  {st['index']:3d}  {st['name']:<{width}}  {st['kind']:<{kwidth}}  {p}  {d}  {st['status']:<8}  {rows or '-'}")
    for p in s["pauses"]:
        at = f" at step {p['step'] + 1}" if isinstance(p.get("step"), int) else " between steps"
        what = {"pause": "paused", "suspend": "suspended"}.get(p["kind"], p["kind"]) if p["event"] == "hold" else "resumed"
        echo(f"{what:<12} {p.get('time', '?')}{at}: {p['reason']}")
    if s["analysis"]:
        echo("analysis     " + ", ".join(s["analysis"]))
    if s["incomplete"]:
        echo(f"incomplete   {len(s['incomplete'])} item(s):")
        for line in s["incomplete"]:
            echo(f"  - {line}")
    else:
        echo("incomplete   nothing: every step done, run stopped with success")


@click.command("inspect")
@click.argument("file", type=click.Path(dir_okay=True))
@click.option("--json", "as_json", is_flag=True, help="print one JSON object")
def inspect_cmd(file: str, as_json: bool) -> None:
    """What a session file holds and what is incomplete."""
    s = summary(file)
    for note in s["notes"]:
        click.echo(f"note: {file}: {note}", err=True)
    if as_json:
        print_json(s)
    else:
        _print(s)


@click.command("import")
@click.argument("manifest", type=click.Path(dir_okay=True))
@click.option("--out", required=True, type=click.Path(dir_okay=False), help="session file to write (.h5)")
@click.option("--force", is_flag=True, help="overwrite --out if it exists")
@click.option("--allow-outside", is_flag=True, help="read CSV files outside the manifest's folder")
def import_cmd(manifest: str, out: str, force: bool, allow_outside: bool) -> None:
    """Measured data from elsewhere (TOML manifest of CSV files, DESIGN.md 6) into a session file."""
    from labrig.importer import import_manifest

    path = import_manifest(manifest, out, overwrite=force, allow_outside=allow_outside)
    s = summary(str(path))
    rows = sum(sum(st["rows"].values()) for st in s["steps"])
    click.echo(f"wrote {len(s['steps'])} records ({rows} rows) to {path}")


@click.command("export")
@click.argument("session", type=click.Path(dir_okay=True))
@click.option("--out", "out_dir", required=True, type=click.Path(file_okay=True), help="directory for manifest.toml and the CSVs")
@click.option("--force", is_flag=True, help="write into --out even if it is not empty")
def export_cmd(session: str, out_dir: str, force: bool) -> None:
    """A session's records as an import manifest and CSV files (DESIGN.md 6): ``labrig import`` reads them back."""
    from labrig.exporter import export_session

    done = export_session(session, out_dir, overwrite=force)
    for note in done.notes:
        click.echo(f"note: {note}")
    click.echo(f"wrote {done.records} records ({done.rows} rows) to {done.manifest.parent}; read back with: labrig import {done.manifest} --out FILE.h5")
