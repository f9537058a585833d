"""Report section of seed 001's method comparison (``labrig fit --seed001-method all``): the method table, the
Pareto front and its knee, the measured static I-V trend against each identified law (seed 001's Fig. 1), and the
held-out records' current and displacement against each method's model."""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.figure import Figure

from labrig.report import figures_diag as fd
from labrig.report import html as h
from labrig.report.data import ReportData

TITLE = "Seed 001: Hammerstein model, Nelder-Mead, GA and NSGA-II compared"
COLUMNS = ("nrmse_current", "nrmse_displacement", "heldout_nrmse_current", "heldout_nrmse_displacement", "n_evals", "wall_s")


def nonlinearity_figure(s: dict[str, Any]) -> Figure | None:
    nl = s.get("nonlinearity") or {}
    meas, laws = nl.get("measured") or {}, nl.get("laws") or {}
    if not meas.get("V") and not laws:
        return None
    fig = Figure(figsize=(7.0, 4.5), layout="constrained")
    ax = fig.subplots()
    for k, (name, c) in enumerate(laws.items()):
        ax.plot(c["V"], np.asarray(c["I"]) * 1e3, "-", color=f"C{k}", label=f"{name}: identified static law")
    if meas.get("V"):
        ax.plot(meas["V"], np.asarray(meas["I"]) * 1e3, "ks", label="measured: steady current at the end of each step")
    ax.set_xlabel("V_in (V)")
    ax.set_ylabel("I_abs (mA)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.suptitle(f"Static I-V trend (seed 001 Fig. 1) against each identified {s.get('law')} law")
    return fig


def heldout_figure(s: dict[str, Any], sd: Any, most: int = 3) -> Figure | None:
    """The held-out records (up to ``most``), one column each: measured current and displacement against each
    method's model (its estimates, simulated from rest on the record's drive, at the fitting rate), with each
    method's NRMSE on that record."""
    from labrig.fit.seed001 import to_record
    from labrig.fit.seed001_identify import BUDGETS
    from labrig.physics import hammerstein as hm
    from labrig.physics.params import HammersteinParams

    recs = {r.name: r for r in sd.all_records()} if sd is not None else {}
    names = [n for n in (s.get("heldout_records") or []) if n in recs][:most]
    if not names:
        return None
    b = s.get("budget")
    budget = BUDGETS.get(b, BUDGETS["standard"]) if isinstance(b, str) else BUDGETS["standard"]
    fig = Figure(figsize=(4.0 * len(names) + 1.0, 5.5), layout="constrained")
    axes = np.atleast_2d(fig.subplots(2, len(names), squeeze=False))
    nrmse = lambda sim, meas: np.sqrt(np.mean((sim - meas) ** 2) / max(np.mean(meas**2), 1e-300))  # noqa: E731
    for c, name in enumerate(names):
        r = to_record(recs[name], budget.max_rate_Hz, budget.max_s)  # as the fit scored it (its NRMSE in the table)
        t = np.arange(r.v.size) / r.fs
        ax_i, ax_d = axes[0, c], axes[1, c]
        ax_i.plot(t, r.i * 1e3, "k-", lw=1.5, label="measured")
        ax_d.plot(t, r.delta * 1e3, "k-", lw=1.5, label="measured")
        for k, m in enumerate(s.get("methods") or []):
            est = {n: v for n, v in (m.get("estimates") or {}).items() if v is not None}
            p = HammersteinParams(law=s.get("law", "poly")).with_vector(tuple(est), tuple(est.values()))
            i, d = hm.simulate(p, r.v, r.fs)
            ax_i.plot(t, i * 1e3, "--", color=f"C{k}", lw=1, label=f"{m['method']} ({nrmse(i, r.i):.3f})")
            ax_d.plot(t, d * 1e3, "--", color=f"C{k}", lw=1, label=f"{m['method']} ({nrmse(d, r.delta):.3f})")
        ax_i.set_title(name, fontsize=9)
        ax_d.set_xlabel("time (s)")
        for ax in (ax_i, ax_d):
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=7, title="NRMSE on this record", title_fontsize=7)
    axes[0, 0].set_ylabel("current (mA)")
    axes[1, 0].set_ylabel("displacement (mm)")
    fig.suptitle("Held-out records (never fitted) against each method's model")
    return fig


def _table(s: dict[str, Any]) -> str:
    methods = s.get("methods") or []
    rows = [[h.cell(m["method"])] + [h.cell(m.get(c), f"seed001.methods.{m['method']}.{c}") for c in COLUMNS] for m in methods]
    body = h.table(["method", *COLUMNS], rows, cls="seed001-methods")
    names = list((methods[0].get("params") or {}) if methods else [])
    prow = []
    for n in names:
        row = [h.cell(n)]
        for m in methods:
            v, sp, why = m["params"].get(n), (m.get("spread") or {}).get(n), (m.get("undetermined") or {}).get(n)
            text = f"undetermined ({why})" if why else h.pm(v, m.get("stderr", {}).get(n)) + ("" if sp is None else f" (spread {sp:.2g})")
            row.append(h.cell(v, f"seed001.methods.{m['method']}.params.{n}", text=text))
        prow.append(row)
    return body + h.table(["parameter (SI)", *(m["method"] for m in methods)], prow, cls="seed001-params")


def section(data: ReportData) -> str:
    s = data.seed001
    noise = s.get("noise_nrmse") or {}
    text = (f"Law {s.get('law')}; fitted on {', '.join(s.get('records') or [])}; held out {', '.join(s.get('heldout_records') or []) or 'none'}; "
            f"{data.seed001_source}. The session's noise as an NRMSE: current {h.fmt(noise.get('current'), 2)}, displacement "
            f"{h.fmt(noise.get('displacement'), 2)}; errors far above it are the model's structural misfit, not noise. "
            f"Spread: standard deviation over the starts (Nelder-Mead) or seeds (GA, NSGA-II) that converged.")
    body = h.para(text) + _table(s)
    for name, fig, caption in (
        ("seed001-front", fd.pareto_figure(s), "NSGA-II non-dominated set over (current error, displacement error), all seeds merged; the star is the knee."),
        ("seed001-nonlinearity", nonlinearity_figure(s), "Measured steady current at the end of each step against each method's static I-V law."),
        ("seed001-heldout", heldout_figure(s, data.sd), "The held-out records (never fitted): measured current and displacement against each method's model."),
    ):
        body += h.figure(fig, name, caption) if fig is not None else h.missing(f"{name}: nothing to draw in this identification.")
    return h.section(TITLE, body, "seed001")
