"""Diagnosis and seed-001 figures: held-out residuals before and after the extension, the evidence blocks,
the gain, and the Hammerstein NSGA-II Pareto front with its knee.

Pure functions returning a matplotlib ``Figure`` (object API) or None when there is nothing to draw.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from matplotlib.figure import Figure

from labrig.diagnose.residuals import BlockResiduals, HeldoutResiduals

BEFORE_COLOUR, AFTER_COLOUR = "0.45", "C3"
MAX_POINTS = 4000  # per block and curve: a figure, not a data dump


def _thin(n: int) -> slice:
    return slice(None, None, max(1, math.ceil(n / MAX_POINTS)))


def _draw_axes(ax: Any, b: BlockResiduals, small: bool = True) -> None:
    """Scale, zero line, title with the block's RMS before and after, labels."""
    size = 8 if small else 10
    if b.x_log and np.all(b.x > 0):
        ax.set_xscale("log")
    ax.axhline(0.0, color="k", linewidth=0.6)
    ax.set_title(f"{b.title}: RMS {b.rms_before:.3g} -> {b.rms_after:.3g} noise units", fontsize=size + 1)
    ax.set_xlabel(b.x_label, fontsize=size)
    ax.set_ylabel("residual (noise units)", fontsize=size)
    ax.grid(True, alpha=0.3)


def _draw_block(ax: Any, b: BlockResiduals, extension: str, small: bool = True) -> None:
    """One block's residuals: lines for time series (steps), markers for the rest, before grey, after red."""
    labels = ("before: baseline", f"after: + {extension}")
    if b.x_label.startswith("time"):
        for k, name in enumerate(dict.fromkeys(b.series)):
            m = b.series == name
            th = _thin(int(m.sum()))
            ax.plot(b.x[m][th], b.before[m][th], linewidth=1.0, color=BEFORE_COLOUR, label=labels[0] if k == 0 else None)
            ax.plot(b.x[m][th], b.after[m][th], linewidth=1.0, alpha=0.8, color=AFTER_COLOUR, label=labels[1] if k == 0 else None)
    else:
        ax.plot(b.x, b.before, "o", markersize=4, markerfacecolor="none", color=BEFORE_COLOUR, label=labels[0])
        ax.plot(b.x, b.after, "x", markersize=5, color=AFTER_COLOUR, label=labels[1])
    _draw_axes(ax, b, small)


def _held_text(res: HeldoutResiduals) -> str:
    if res.same_records:
        return "on the fitted records themselves (one pressure: nothing to hold out)"
    return "on the held-out pressures " + ", ".join(f"{p:g}" for p in res.heldout_kPa) + " kPa"


def residuals_figure(res: HeldoutResiduals) -> Figure | None:
    """Every feature block's residuals, before (baseline) and after (extension), on the held-out records."""
    if not res.blocks:
        return None
    ncol = 2
    nrow = math.ceil(len(res.blocks) / ncol)
    fig = Figure(figsize=(11.0, 2.9 * nrow + 0.6), layout="constrained")
    axes = np.atleast_1d(fig.subplots(nrow, ncol)).ravel()
    for ax, b in zip(axes, res.blocks):
        _draw_block(ax, b, res.extension)
    for ax in axes[len(res.blocks):]:
        ax.set_visible(False)
    axes[0].legend(fontsize=8)
    fig.suptitle(f"Residuals before and after {res.extension}, {_held_text(res)}")
    return fig


def evidence_figure(res: HeldoutResiduals) -> Figure | None:
    """The block(s) the extension fixes most, drawn large: the evidence for the named cause."""
    ev = res.evidence()
    if not ev:
        return None
    fig = Figure(figsize=(11.0, 3.8 * len(ev)), layout="constrained")
    axes = np.atleast_1d(fig.subplots(len(ev), 1))
    for ax, b in zip(axes, ev):
        if b.x_label.startswith("time") or len(set(b.series)) <= 1:
            _draw_block(ax, b, res.extension, small=False)
            ax.legend(fontsize=8)
            continue
        # several kinds of point (Re/Im, 2f/3f, 50/60 Hz per channel): one marker each, before and after
        markers = "osD^v<>ph*"
        for k, name in enumerate(dict.fromkeys(b.series)):
            m = b.series == name
            ax.plot(b.x[m], b.before[m], markers[k % 10], markerfacecolor="none", color=BEFORE_COLOUR, label=f"{name}, before")
            ax.plot(b.x[m], b.after[m], markers[k % 10], color=AFTER_COLOUR, label=f"{name}, after")
        _draw_axes(ax, b, small=False)
        ax.legend(fontsize=7, ncol=2)
    lead = f"Evidence for {res.extension}" if res.accepted else f"{res.extension} (best candidate, not accepted)"
    fig.suptitle(f"{lead}: the residual block(s) it fixes most, {_held_text(res)}")
    return fig


def gain_figure(res: HeldoutResiduals, diagnosis: dict) -> Figure:
    """Per-block RMS residual before and after (log scale) and the held-out NRMSE with its ratio and DeltaBIC."""
    fig = Figure(figsize=(11.0, 0.45 * len(res.blocks) + 2.6), layout="constrained")
    ax_b, ax_g = fig.subplots(1, 2, width_ratios=[2, 1])
    names = [b.title for b in res.blocks]
    y = np.arange(len(res.blocks))
    evidence = {b.name for b in res.evidence()}
    ax_b.barh(y + 0.2, [b.rms_before for b in res.blocks], height=0.4, color="0.6", label="before: baseline")
    ax_b.barh(y - 0.2, [b.rms_after for b in res.blocks], height=0.4, color=AFTER_COLOUR, label=f"after: + {res.extension}")
    ax_b.set_yticks(y, [f"{n}  *" if b.name in evidence else n for n, b in zip(names, res.blocks)], fontsize=8)
    ax_b.invert_yaxis()
    ax_b.set_xscale("log")
    ax_b.set_xlabel("held-out RMS residual (noise units; * = evidence)")
    ax_b.legend(fontsize=8)
    ax_b.grid(True, axis="x", which="both", alpha=0.3)
    gain = diagnosis.get("gain", {})
    vals = [res.nrmse_before, res.nrmse_after]
    ax_g.bar(["baseline", f"+ {res.extension}"], vals, color=["0.6", AFTER_COLOUR])
    for k, v in enumerate(vals):
        ax_g.text(k, v, f"{v:.3g}", ha="center", va="bottom", fontsize=9)
    ax_g.set_ylabel("held-out NRMSE (noise units)")
    ratio, dbic = gain.get("heldout_nrmse_ratio"), gain.get("delta_bic")
    ax_g.set_title(f"ratio {ratio:.3f}, DeltaBIC {dbic:.1f}" if ratio is not None and dbic is not None else "gain", fontsize=9)
    ax_g.grid(True, axis="y", alpha=0.3)
    fig.suptitle(f"Gain of {res.extension} on held-out records")
    return fig


def knee(seed001: dict) -> tuple[float, float] | None:
    """(current error, displacement error) at the knee of the stored front (the fitter's own rule), or None."""
    from labrig.fit.hammerstein import knee_point

    front = seed001.get("pareto_front")
    if not front:
        return None
    F = np.asarray(front, float)
    k = knee_point(F)
    return float(F[k, 0]), float(F[k, 1])


def pareto_figure(seed001: dict) -> Figure | None:
    """Seed 001's NSGA-II front: current NRMSE against displacement NRMSE, the knee marked."""
    kn = knee(seed001)
    if kn is None:
        return None
    F = np.asarray(seed001["pareto_front"], float)
    order = np.argsort(F[:, 0])
    fig = Figure(figsize=(7.0, 5.0), layout="constrained")
    ax = fig.subplots()
    ax.plot(F[order, 0], F[order, 1], "o-", color="C0", markersize=5, label="non-dominated set (NSGA-II)")
    ax.plot(*kn, "*", color="C3", markersize=16, label=f"knee: current {kn[0]:.3g}, displacement {kn[1]:.3g}")
    ax.set_xlabel("current error (NRMSE)")
    ax.set_ylabel("displacement error (NRMSE)")
    if np.all(F > 0):  # fronts are L-shaped: on log axes the knee region is not squashed into a corner
        ax.set_xscale("log")
        ax.set_yscale("log")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.suptitle(f"Seed 001 Hammerstein ({seed001.get('law', '?')} law): Pareto front of the two errors")
    return fig
