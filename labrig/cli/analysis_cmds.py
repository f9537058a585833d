"""``labrig fit`` (and the hooks ``labrig run --fit --diagnose`` use): options and printing; the work is labrig.analysis."""

from __future__ import annotations

from typing import Any

import click

from labrig.analysis import batch, compute_fit, store_fit
from labrig.cli.common import exit_code, print_outcomes, scheduler_option

# labrig.physics.hammerstein.LAWS, spelled out: importing it here would load scipy for every command (test_hammerstein)
SEED001_LAWS = ("poly", "butler_volmer", "varcap")
SEED001_METHODS = ("nelder-mead", "ga", "nsga2", "all")
SEED001_BUDGETS = ("standard", "quick")  # labrig.fit.seed001_identify.BUDGETS



def summary(out: dict[str, Any]) -> None:
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
        _seed001_summary(h)
    for n in out.get("notes", []):
        click.echo(f"note: {n}")


def _g(x: Any, fmt: str = ".3g") -> str:
    return "-" if x is None else format(x, fmt)


def _seed001_summary(h: dict[str, Any]) -> None:
    methods = h.get("methods") or [h]
    click.echo(f"seed 001 Hammerstein (law {h['law']}): fitted on {len(h.get('records') or [])} records, "
               f"held out {', '.join(h.get('heldout_records') or []) or 'none'}")
    click.echo(f"  {'method':12s} {'NRMSE i':>8} {'NRMSE d':>8} {'held i':>8} {'held d':>8} {'evals':>7} {'wall s':>7}")
    for m in methods:
        click.echo(f"  {m['method']:12s} {_g(m['nrmse_current']):>8} {_g(m['nrmse_displacement']):>8} {_g(m.get('heldout_nrmse_current')):>8} "
                   f"{_g(m.get('heldout_nrmse_displacement')):>8} {m['n_evals']:7d} {m['wall_s']:7.1f}")
    for m in methods:
        u = m.get("uncertainty") or m.get("stderr") or {}
        vals = [f"{k} = {v:.4g}" + (f" ± {u[k]:.2g}" if u.get(k) is not None else "") for k, v in m["params"].items() if v is not None]
        click.echo(f"  {m['method']}: " + ", ".join(vals))
        for k, why in (m.get("undetermined") or {}).items():
            click.echo(f"    {k}: undetermined ({why})")
    if h.get("noise_nrmse"):
        n = h["noise_nrmse"]
        click.echo(f"  noise floor as NRMSE: current {_g(n.get('current'))}, displacement {_g(n.get('displacement'))}")


@click.command("fit")
@click.argument("sessions", nargs=-1, required=True, type=click.Path(dir_okay=False))
@click.option("--json", "as_json", is_flag=True, help="print one JSON object (several sessions: {\"sessions\": [...]})")
@click.option("--seed001", type=click.Choice(["auto", "on", "off"]), default="auto", show_default=True,
              help="seed 001's Hammerstein model: auto = when the session has an amplitude series or multisines")
@click.option("--seed001-method", type=click.Choice(SEED001_METHODS), default="nelder-mead", show_default=True,
              help="all = Nelder-Mead (several starts), GA and NSGA-II (several seeds) compared on the same records")
@click.option("--seed001-law", type=click.Choice(SEED001_LAWS), default="poly", show_default=True,
              help="the electric stage's nonlinear law (docs/hammerstein.md)")
@click.option("--seed001-budget", type=click.Choice(SEED001_BUDGETS), default="standard", show_default=True,
              help="starts, seeds, populations and generations of --seed001-method all (quick: a smoke test)")
@scheduler_option
def fit_cmd(sessions: tuple[str, ...], as_json: bool, seed001: str, seed001_method: str, seed001_law: str, seed001_budget: str,
            scheduler: str | None) -> None:
    """Fit the paper's model (seed 000) to each SESSION, and seed 001's where the data allows; results go into
    /entry/analysis/ of each session."""
    outcomes = batch(compute_fit, store_fit, sessions, scheduler, populations=True, seed001=seed001, seed001_method=seed001_method,
                     seed001_law=seed001_law, seed001_budget=seed001_budget)
    print_outcomes(outcomes, as_json, summary)
    if exit_code(outcomes):
        raise click.exceptions.Exit(exit_code(outcomes))
