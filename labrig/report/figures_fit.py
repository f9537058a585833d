"""Seed-000 figures: measured against fitted impedance and displacement FRF (Bode), fitted clamp values against
clamping pressure, step and harmonic responses against the model, and the optimum / trade-off.

Pure functions of the fit and the session data, each returning a matplotlib ``Figure`` (object API, no pyplot
state) or None when the session lacks the data. Units at the edge: kPa, Hz, mm, mA, degrees.
"""

from __future__ import annotations

from typing import Any, Callable

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from labrig.physics import impedance as imp
from labrig.physics import timeresp, transfer
from labrig.records import RecordKind

MEASURED = dict(marker="o", linestyle="none", markersize=5, markerfacecolor="none")
MODEL = dict(linestyle="-", linewidth=1.6)


def colour(p: float | None, pressures: list[float]) -> str:
    """One colour per clamping pressure, the same in every figure."""
    k = pressures.index(p) if p in pressures else len(pressures)
    return f"C{k % 10}"


def _style_legend(ax: Any, model_label: str = "model (fitted)") -> None:
    """Pressure colours plus 'markers measured, lines model' in one legend."""
    handles, labels = ax.get_legend_handles_labels()
    proxies = [Line2D([], [], color="0.3", **MEASURED), Line2D([], [], color="0.3", **MODEL)]
    ax.legend(handles + proxies, labels + ["measured", model_label], fontsize=8, ncol=2)


def _bode(axes: Any, f: np.ndarray, meas: np.ndarray, f_dense: np.ndarray, model: Callable[[np.ndarray], np.ndarray],
          c: str, label: str, scale: float, err: np.ndarray | None = None) -> None:
    """Magnitude (log-log) and phase (semilog-x) of measured points and a model curve on two axes."""
    mag, ph = axes
    dense = model(f_dense)
    unwrapped = np.degrees(np.unwrap(np.angle(dense)))
    # each measured phase within +-180 deg of the model's unwrapped phase there: a wrap never looks like a misfit
    near = np.interp(np.log(f), np.log(f_dense), unwrapped) + np.degrees(np.angle(meas / model(f)))
    if err is None:
        mag.loglog(f, np.abs(meas) * scale, color=c, label=label, **MEASURED)
    else:
        mag.errorbar(f, np.abs(meas) * scale, yerr=err * scale, color=c, label=label, capsize=2, **MEASURED)
    mag.loglog(f_dense, np.abs(dense) * scale, color=c, **MODEL)
    ph.semilogx(f, near, color=c, **MEASURED)
    ph.semilogx(f_dense, unwrapped, color=c, **MODEL)


def _bode_figure(title: str, mag_label: str) -> tuple[Figure, Any]:
    fig = Figure(figsize=(8.5, 6.5), layout="constrained")
    axes = fig.subplots(2, 1, sharex=True)
    axes[0].set_ylabel(mag_label)
    axes[1].set_ylabel("phase (deg)")
    axes[1].set_xlabel("frequency (Hz)")
    for ax in axes:
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle(title)
    return fig, axes


def _bode_per_pressure(sd: Any, specimens: dict, title: str, mag_label: str, scale: float,
                       measured: Callable[[Any], tuple | None], model: Callable[[np.ndarray, Any], np.ndarray],
                       model_label: str = "model (fitted)") -> Figure | None:
    """One Bode figure, a colour per pressure: ``measured(d)`` gives (f, complex values, error or None) or
    None for a pressure without the data; ``model(f, specimen)`` the fitted curve."""
    data = [(d.pressure_kPa, m) for d in sd.pressures if (m := measured(d)) is not None]
    if not data:
        return None
    ps = [d.pressure_kPa for d in sd.pressures]
    fig, axes = _bode_figure(title, mag_label)
    for p, (f, meas, err) in data:
        sp = specimens[p]
        _bode(axes, f, meas, np.geomspace(f.min(), f.max(), 300), lambda x, sp=sp: model(x, sp), colour(p, ps), f"{p:g} kPa", scale, err)
    _style_legend(axes[0], model_label)
    return fig


def impedance_figure(sd: Any, specimens: dict) -> Figure | None:
    """|Z| and phase per clamping pressure: measured spectrum against the fitted eq. 12."""
    return _bode_per_pressure(sd, specimens, "Impedance: measured against fitted model (eq. 12)", "|Z| (ohm)", 1.0,
                              lambda d: None if d.eis is None else (*d.eis, None),
                              lambda f, sp: imp.impedance(2j * np.pi * f, sp))


def _frf_points(d: Any) -> tuple | None:
    """What the fitter fits: the stepped sines and, where recorded, the multisine BLA's excited lines."""
    frf = d.frf_lines("all")
    return None if frf is None else (frf[0], frf[1], np.nan_to_num(frf[3], nan=0.0))


def frf_figure(sd: Any, specimens: dict, fitted: bool = True) -> Figure | None:
    """Displacement per volt, gain and phase per pressure: measured points (with their noise) against the model,
    fitted or (``fitted`` False: the fit could not tell the mechanics) the preset's."""
    title = "Displacement FRF: measured against " + ("fitted model (eq. 38)" if fitted else "the preset's model (eq. 38)")
    return _bode_per_pressure(sd, specimens, title, "gain (mm/V)", 1e3, _frf_points, transfer.frf,
                              "model (fitted)" if fitted else "model (preset mechanics)")


PARAM_PANELS = (("R_cont_ohm", "contact resistance R_cont (ohm)"), ("Kt_bar", "clamp stiffness K_t bar (-)"), ("f1_Hz", "first natural frequency f1 (Hz)"))


def _values(rows: list[dict], key: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(pressure, value, stderr) of the rows where ``key`` was fitted; a missing stderr draws no bar."""
    good = [r for r in rows if r.get(key) is not None]
    p = np.array([r["pressure_kPa"] for r in good], float)
    v = np.array([r[key] for r in good], float)
    e = np.array([np.nan if r.get(f"{key}_stderr") is None else r[f"{key}_stderr"] for r in good], float)
    return p, v, np.nan_to_num(e, nan=0.0)


def parameters_figure(fit_json: dict) -> Figure | None:
    """R_cont, K_t bar and f1 against clamping pressure, error bars = 1 standard error of the fit."""
    rows = fit_json["per_pressure"]
    panels = [(k, lab) for k, lab in PARAM_PANELS if any(r.get(k) is not None for r in rows)]
    if not panels:
        return None
    fig = Figure(figsize=(4.0 * len(panels) + 0.5, 3.8), layout="constrained")
    axes = np.atleast_1d(fig.subplots(1, len(panels)))
    for ax, (key, label) in zip(axes, panels):
        p, v, e = _values(rows, key)
        ax.errorbar(p, v, yerr=e, marker="o", capsize=4, color="C0")
        ax.set_xlabel("clamping pressure (kPa)")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    fig.suptitle("Fitted clamp values against clamping pressure (error bars: 1 standard error)")
    return fig


def _time_panels(title: str) -> tuple[Figure, Any]:
    fig = Figure(figsize=(9.0, 7.5), layout="constrained")
    axes = fig.subplots(3, 1, sharex=True, height_ratios=[3, 3, 2])
    axes[0].set_ylabel("tip displacement (mm)")
    axes[1].set_ylabel("current (mA)")
    axes[2].set_ylabel("displacement,\nmeasured - model (um)")
    axes[2].set_xlabel("time from record start (s)")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    fig.suptitle(title)
    return fig, axes


def _plot_pair(axes: Any, t: np.ndarray, meas: tuple[np.ndarray, np.ndarray], model: tuple[np.ndarray, np.ndarray], c: str, label: str) -> None:
    """Measured (solid) and model (dashed) displacement and current, and the displacement misfit."""
    for ax, m, y in ((axes[0], meas[0], model[0]), (axes[1], meas[1], model[1])):
        ax.plot(t, m * 1e3, color=c, linewidth=1.0, alpha=0.8, label=label if ax is axes[0] else None)
        ax.plot(t, y * 1e3, color=c, linestyle="--", linewidth=1.4)
    axes[2].plot(t, (meas[0] - model[0]) * 1e6, color=c, linewidth=1.0)


def _time_legend(ax: Any) -> None:
    handles, labels = ax.get_legend_handles_labels()
    proxies = [Line2D([], [], color="0.3", linewidth=1.0), Line2D([], [], color="0.3", linestyle="--", linewidth=1.4)]
    ax.legend(handles + proxies, labels + ["measured", "model prediction"], fontsize=8, ncol=2)


def step_figure(feats: Any, specimens: dict, pressures: list[float]) -> Figure | None:
    """The first step of each pressure (from rest) against the fitted model's prediction."""
    from labrig.diagnose.features import predict_step

    steps = [st for st in (feats.steps if feats is not None else []) if st.pressure_kPa in specimens]
    if not steps:
        return None
    fig, axes = _time_panels("Step response: measured against model prediction")
    for st in steps:
        d, i = predict_step(specimens[st.pressure_kPa], st)
        label = "no pressure" if st.pressure_kPa is None else f"{st.pressure_kPa:g} kPa"
        _plot_pair(axes, st.t - st.t[0], (st.d - st.d[0], st.i), (d - d[0], i), colour(st.pressure_kPa, pressures), label)
    _time_legend(axes[0])
    return fig


def harmonic_figure(sd: Any, specimens: dict) -> Figure | None:
    """The harmonic record of each pressure against the model driven by the recorded voltage (from rest)."""
    recs = [(d.pressure_kPa, d.of_kind(RecordKind.HARMONIC)[0]) for d in sd.pressures if d.of_kind(RecordKind.HARMONIC)]
    if not recs:
        return None
    ps = [d.pressure_kPa for d in sd.pressures]
    fig, axes = _time_panels("Harmonic response: measured against model prediction")
    for p, r in recs:
        sp = specimens[p]
        d, i = timeresp.simulate_many([lambda s: transfer.displacement_tf(s, sp), lambda s: transfer.admittance_tf(s, sp)], r.v, r.fs)
        _plot_pair(axes, r.t - r.t[0], (r.d - r.d[0], r.i), (d, i), colour(p, ps), f"{p:g} kPa, {r.meta.get('frequency_Hz', '?')} Hz")
    _time_legend(axes[0])
    return fig


def _actuation(fit_json: dict, sd: Any, specimens: dict, feats: Any) -> dict[str, tuple[list[float], list[float]]]:
    """Actuation per volt (mm/V) against pressure: measured step peak and harmonic amplitude, and the model's."""
    from labrig.diagnose.features import predict_step

    out: dict[str, tuple[list[float], list[float]]] = {}

    def add(name: str, p: float, v: float) -> None:
        out.setdefault(name, ([], []))
        out[name][0].append(p)
        out[name][1].append(v * 1e3)

    harm_amp = {d.pressure_kPa: abs(float(d.of_kind(RecordKind.HARMONIC)[0].meta.get("amplitude_V", 1.0))) for d in sd.pressures if d.of_kind(RecordKind.HARMONIC)}
    for r in fit_json["per_pressure"]:
        p = r["pressure_kPa"]
        if r.get("peak_disp_m") is not None:
            add("step peak, measured", p, r["peak_disp_m"])
        if r.get("harmonic_amp_m") is not None and harm_amp.get(p):
            add("harmonic amplitude, measured", p, r["harmonic_amp_m"] / harm_amp[p])
        if r.get("Kt_bar") is not None:  # the mechanics of this pressure were fitted
            add("|H(0.1 Hz)|, model", p, float(abs(transfer.frf(np.array([0.1]), specimens[p])[0])))
    for st in feats.steps if feats is not None else []:
        sp = specimens.get(st.pressure_kPa)
        row = next((r for r in fit_json["per_pressure"] if r["pressure_kPa"] == st.pressure_kPa), None)
        if sp is not None and row is not None and row.get("Kt_bar") is not None:
            d, _ = predict_step(sp, st)
            add("step peak, model", st.pressure_kPa, float(np.max(np.abs(d - d[0]))) / max(abs(st.amplitude_V), 1e-12))
    return out


def optimum_figure(fit_json: dict, sd: Any, specimens: dict, feats: Any) -> Figure | None:
    """(a) R_cont against K_t bar, the trade-off clamping pressure moves along; (b) actuation per volt against
    pressure, measured and modelled, with both optima marked."""
    act = _actuation(fit_json, sd, specimens, feats)
    rows = [r for r in fit_json["per_pressure"] if r.get("R_cont_ohm") is not None and r.get("Kt_bar") is not None]
    if not act or sum(len(v[0]) for v in act.values()) < 2:
        return None
    fig = Figure(figsize=(11.0, 4.3), layout="constrained")
    ax_t, ax_a = fig.subplots(1, 2)
    if rows:
        x = np.array([r["R_cont_ohm"] for r in rows])
        y = np.array([r["Kt_bar"] for r in rows])
        ax_t.errorbar(x, y, xerr=[r.get("R_cont_ohm_stderr") or 0 for r in rows], yerr=[r.get("Kt_bar_stderr") or 0 for r in rows],
                      marker="o", capsize=3, color="C3")
        for r in rows:
            ax_t.annotate(f"{r['pressure_kPa']:g} kPa", (r["R_cont_ohm"], r["Kt_bar"]), textcoords="offset points", xytext=(6, 4), fontsize=8)
        ax_t.set_title("each point one clamping pressure (error bars: 1 standard error)", fontsize=9)
    else:
        ax_t.text(0.5, 0.5, "R_cont and K_t bar are not both fitted", ha="center", va="center", transform=ax_t.transAxes)
    ax_t.set_xlabel("contact resistance R_cont (ohm)")
    ax_t.set_ylabel("clamp stiffness K_t bar (-)")
    for k, (name, (p, v)) in enumerate(sorted(act.items())):
        # relative to each series' largest value: the optimum is a few per cent, lost on a common mm/V axis
        rel = 100.0 * np.asarray(v) / max(np.max(np.abs(v)), 1e-300)
        ax_a.plot(p, rel, marker="o" if "measured" in name else "s", linestyle="--" if "model" in name else "-",
                  label=f"{name} (max {np.max(v):.3g} mm/V)", color=f"C{k}")
    for key, ls, lab in (("optimum_pressure_kPa", "-", "optimum, measured"), ("model_optimum_pressure_kPa", ":", "optimum, model")):
        if fit_json.get(key) is not None:
            ax_a.axvline(fit_json[key], color="k", linestyle=ls, linewidth=1.0, label=f"{lab}: {fit_json[key]:g} kPa")
    ax_a.set_xlabel("clamping pressure (kPa)")
    ax_a.set_ylabel("actuation per volt, % of its largest")
    ax_a.legend(fontsize=8)
    for ax in (ax_t, ax_a):
        ax.grid(True, alpha=0.3)
    fig.suptitle("Optimum clamping pressure and the contact-resistance / clamp-stiffness trade-off")
    return fig
