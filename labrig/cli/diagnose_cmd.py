"""``labrig diagnose``: what the fitted model gets wrong, the cause, the extension and its held-out gain."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import click

from labrig.analysis import batch, compute_diagnosis, run_diagnosis, store_diagnosis
from labrig.cli.common import exit_code, print_json, print_outcomes, scheduler_option
from labrig.diagnose.verdict import where_text


def summary(out: dict[str, Any]) -> None:
    v = out["verdict"]
    if v == "effect":
        click.echo(f"verdict: effect -- {out['cause']} (confidence {out['confidence']:.2f}); extension: {out.get('extension', '')}")
        g = out["gain"]
        click.echo(f"held-out NRMSE {out['baseline']['heldout_nrmse']:.4g} -> {out['extended']['heldout_nrmse']:.4g} (ratio {g['heldout_nrmse_ratio']:.3f}), DeltaBIC {g['delta_bic']:.1f}")
        click.echo("  fitted: " + ", ".join(f"{k} = {p:.4g}" for k, p in out["extended"]["params"].items()))
    elif v == "none":
        click.echo(f"verdict: none -- the baseline explains the data within noise (held-out NRMSE {out['baseline']['heldout_nrmse']:.4g})")
    else:
        click.echo("verdict: unexplained -- structured residual that no catalogued extension removes")
    for w in out.get("residual", {}).get("where", []):
        click.echo(f"  misfit in {where_text(w)}")
    click.echo(f"{'candidate':20s} {'DeltaBIC':>10s} {'held-out NRMSE':>15s} {'ratio':>7s}")
    for c in out["candidates"]:
        click.echo(f"{c['name']:20s} {c['delta_bic']:10.1f} {c['heldout_nrmse']:15.4g} {c['heldout_ratio']:7.3f}")
    split = out["split"]
    click.echo(f"fitted on {split['fit'] or 'all'} kPa, held out {split['heldout'] or 'the same records'} kPa")


def run_and_print(path: str | Path, as_json: bool, quiet: bool = False, fitted: tuple | None = None) -> dict[str, Any]:
    out = run_diagnosis(path, fitted)
    if as_json:
        print_json(out)
    elif not quiet:
        summary(out)
    return out


@click.command("diagnose")
@click.argument("sessions", nargs=-1, required=True, type=click.Path(dir_okay=False))
@click.option("--json", "as_json", is_flag=True, help="print one JSON object (several sessions: {\"sessions\": [...]})")
@scheduler_option
def diagnose_cmd(sessions: tuple[str, ...], as_json: bool, scheduler: str | None) -> None:
    """Residuals of the fitted model on each SESSION, the likely cause, the extension and its held-out gain.
    Several sessions run as one batch (on the dask cluster given by --scheduler, one task per session)."""
    outcomes = batch(compute_diagnosis, store_diagnosis, sessions, scheduler)
    print_outcomes(outcomes, as_json, summary)
    if exit_code(outcomes):
        raise click.exceptions.Exit(exit_code(outcomes))
