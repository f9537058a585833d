"""``labrig fit`` (and the hooks ``labrig run --fit --diagnose`` use)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import click
import numpy as np

from labrig.cli.common import jsonable, print_json
from labrig.errors import BadInput

# labrig.physics.hammerstein.LAWS, spelled out: importing it here would load scipy for every command (test_hammerstein)
SEED001_LAWS = ("poly", "butler_volmer", "varcap")


def _arr(rows: list[dict[str, Any]], key: str) -> np.ndarray:
    return np.array([np.nan if r.get(key) is None else float(r[key]) for r in rows])


def load_and_fit(path: str | Path, what: str = "fit") -> tuple[Any, Any]:
    """The session's data and its seed-000 fit: what `fit` reports and `diagnose` builds on (done once)."""
    from labrig.fit.seed000 import fit_seed000
    from labrig.fit.session_data import load_session

    sd = load_session(path)
    if not sd.pressures and not sd.unpressured:
        raise BadInput(f"{path}: no finished records to {what}")
    return sd, fit_seed000(sd)


def run_fit(path: str | Path, seed001: str = "auto", seed001_method: str = "nelder-mead", fitted: tuple | None = None,
            seed001_law: str = "poly") -> dict[str, Any]:
    """Fit the seed-000 model (and seed 001's where the data allows) to a session; store the results under
    /entry/analysis/fit_seed000 and /entry/analysis/fit_seed001."""
    from labrig.fit.seed001 import fit_seed001
    from labrig.store import SessionFile

    sd, fit = fitted or load_and_fit(path)
    out = jsonable(fit.to_json())
    out["seed001"] = None
    if seed001 != "off":
        h = fit_seed001(sd, method=seed001_method, law=seed001_law, force=seed001 == "on")
        out["seed001"] = jsonable(h)
        if h is not None:
            SessionFile(path).write_analysis("fit_seed001", {"result_json": json.dumps(out["seed001"])})
    rows = out["per_pressure"]
    SessionFile(path).write_analysis(
        "fit_seed000",
        {
            "result_json": json.dumps(out),
            "pressure_kPa": _arr(rows, "pressure_kPa"),
            "R_cont_ohm": _arr(rows, "R_cont_ohm"),
            "Kt_bar": _arr(rows, "Kt_bar"),
            "f1_Hz": _arr(rows, "f1_Hz"),
            "peak_disp_m": _arr(rows, "peak_disp_m"),
        },
    )
    return out


def _summary(out: dict[str, Any]) -> None:
    click.echo(f"{'kPa':>7} {'R_cont ohm':>16} {'K_t bar':>15} {'f1 Hz':>16} {'step peak mm':>13}")

    def pm(r: dict, k: str, fmt: str) -> str:
        v, e = r.get(k), r.get(f"{k}_stderr")
        if v is None:
            return "-"
        return (fmt % v) + ("" if e is None else " ± " + (fmt % e))

    for r in out["per_pressure"]:
        peak = "-" if r.get("peak_disp_m") is None else f"{r['peak_disp_m'] * 1e3:.4f}"
        click.echo(f"{r['pressure_kPa']:7g} {pm(r, 'R_cont_ohm', '%.3f'):>16} {pm(r, 'Kt_bar', '%.3f'):>15} {pm(r, 'f1_Hz', '%.4f'):>16} {peak:>13}")
    for name, unit in (("alpha", " J/C"), ("gamma", "")):
        v, e = out.get(name), out.get(f"{name}_stderr")
        click.echo(f"{name} = " + ("-" if v is None else f"{v:.4g} ± {e:.2g}{unit}"))
    click.echo(f"optimum clamping pressure (largest measured step response): {out.get('optimum_pressure_kPa')} kPa")
    h = out.get("seed001")
    if h:
        click.echo(f"seed 001 Hammerstein ({h['method']}, law {h['law']}): NRMSE current {h['nrmse_current']:.3g}, displacement {h['nrmse_displacement']:.3g}")
        click.echo("  " + ", ".join(f"{k} = {v:.4g}" for k, v in h["params"].items() if v is not None))
    for n in out.get("notes", []):
        click.echo(f"note: {n}")


@click.command("fit")
@click.argument("session", type=click.Path(dir_okay=False))
@click.option("--json", "as_json", is_flag=True, help="print one JSON object")
@click.option("--seed001", type=click.Choice(["auto", "on", "off"]), default="auto", show_default=True,
              help="seed 001's Hammerstein model: auto = when the session has an amplitude series or multisines")
@click.option("--seed001-method", type=click.Choice(["nelder-mead", "ga", "nsga2"]), default="nelder-mead", show_default=True)
@click.option("--seed001-law", type=click.Choice(SEED001_LAWS), default="poly", show_default=True,
              help="the electric stage's nonlinear law (docs/hammerstein.md)")
def fit_cmd(session: str, as_json: bool, seed001: str, seed001_method: str, seed001_law: str) -> None:
    """Fit the paper's model (seed 000) to SESSION, and seed 001's where the data allows; results go into
    /entry/analysis/."""
    if not Path(session).exists():
        raise BadInput(f"{session}: no such session file")
    out = run_fit(session, seed001, seed001_method, seed001_law=seed001_law)
    if as_json:
        print_json(out)
    else:
        _summary(out)


def after_run(path: Path, fit: bool, diagnose: bool, quiet: bool) -> None:
    fitted = load_and_fit(path)
    if fit:
        out = run_fit(path, fitted=fitted)
        if not quiet:
            _summary(out)
    if diagnose:
        from labrig.cli import diagnose_cmd

        diagnose_cmd.run_and_print(path, as_json=False, quiet=quiet, fitted=fitted)
