"""``labrig diagnose``: what the fitted model gets wrong, the cause, the extension and its held-out gain."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import click

from labrig.cli.common import jsonable, print_json
from labrig.errors import BadInput


def run_diagnosis(path: str | Path, fitted: tuple | None = None) -> dict[str, Any]:
    """Diagnose a session on top of its seed-000 fit (``fitted`` from ``load_and_fit``, or made here)."""
    from labrig.cli.analysis_cmds import load_and_fit
    from labrig.diagnose.catalogue import CATALOGUE
    from labrig.diagnose.engine import baseline_specimens, diagnose
    from labrig.store import SessionFile

    sd, fit = fitted or load_and_fit(path, "diagnose")
    out = jsonable(diagnose(sd, baseline_specimens(fit)))
    if out["cause"]:  # the form the cause was found in (its family's: labrig.diagnose.families)
        out["extension"] = out["extended"].get("form_describe") or CATALOGUE[out["cause"]].describe
    SessionFile(path).write_analysis("diagnosis", {"result_json": json.dumps(out), "verdict": out["verdict"], "cause": out["cause"] or ""})
    return out


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
        click.echo(f"  misfit in {w['block']}: level {w['level']:.3g} ({w['over_accuracy']:.2f} x its attainable accuracy), {w['detail']}")
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
@click.argument("session", type=click.Path(dir_okay=False))
@click.option("--json", "as_json", is_flag=True, help="print one JSON object")
def diagnose_cmd(session: str, as_json: bool) -> None:
    """Residuals of the fitted model on SESSION, the likely cause, the extension and its held-out gain."""
    if not Path(session).exists():
        raise BadInput(f"{session}: no such session file")
    run_and_print(session, as_json)
