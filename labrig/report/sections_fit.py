"""Report sections: the header (what the session holds and what is incomplete) and the seed-000 fit.

Each function takes the gathered :class:`labrig.report.data.ReportData` and returns an HTML fragment; where
the session lacks the data it says so in a sentence instead of a figure.
"""

from __future__ import annotations

from typing import Any

from labrig.report import figures_fit as ff
from labrig.report import html as h
from labrig.report.data import ReportData
from labrig.records import HOLD_KINDS

PER_PRESSURE = (  # (JSON key, header, scale to the shown unit)
    ("R_cont_ohm", "R_cont (ohm)", 1.0),
    ("Kt_bar", "K_t bar", 1.0),
    ("f1_Hz", "f1 (Hz)", 1.0),
    ("xi1", "xi1", 1.0),
    ("peak_disp_m", "step peak (mm/V)", 1e3),
    ("harmonic_amp_m", "harmonic amplitude (mm)", 1e3),
    ("force_N_mean", "clamp force (N)", 1.0),
)
UNITS = {"r_cont": "ohm m^2", "R_sc": "ohm/m", "R_c": "ohm m", "R_pc": "ohm m", "Q0c": "S s^n/m", "n_c": "-",
         "R": "ohm m", "R_p": "ohm m", "Q0": "S s^n/m", "n": "-"}  # labrig.physics.params (SI, per length)
SCALARS = (
    ("alpha", "alpha, coupling (J/C)"),
    ("gamma", "gamma, viscoelastic"),
    ("optimum_pressure_kPa", "optimum pressure, measured (kPa)"),
    ("model_optimum_pressure_kPa", "optimum pressure, model (kPa)"),
    ("eis_redchi", "reduced chi-square, impedance"),
    ("frf_redchi", "reduced chi-square, FRF"),
)


# ------------------------------------------------------------------------------------------- header


def _protocols(s: dict[str, Any]) -> str:
    kinds = list(dict.fromkeys(st["kind"] for st in s["steps"] if st["kind"] not in HOLD_KINDS))
    return f"{s['protocol']} ({', '.join(kinds) or 'no measuring steps'})"


def _pressures(s: dict[str, Any]) -> str:
    ps = sorted({st["pressure_kPa"] for st in s["steps"] if isinstance(st["pressure_kPa"], (int, float))})
    return ", ".join(f"{p:g}" for p in ps) + " kPa" if ps else "none recorded"


def header(data: ReportData) -> str:
    s = data.summary
    done = sum(st["status"] == "done" for st in s["steps"])
    rows = [
        ("session file", str(data.path)),
        ("run", f"{s['run_uid']} (labrig {s['labrig_version']})"),
        ("protocol", _protocols(s)),
        ("clamping pressures", _pressures(s)),
        ("started / ended", f"{s['start_time'] or '?'} / {s['end_time'] or 'never (no RunStop)'}"),
        ("exit status", (s["exit_status"] or "none") + (f" ({s['reason']})" if s["reason"] else "")),
        ("steps", f"{done} of {len(s['steps'])} done"),
        ("specimen", ", ".join(f"{k} = {v}" for k, v in s["sample"].items()) or "not recorded"),
        ("instruments", ", ".join(s["instruments"]) or "none"),
        ("stored analyses", ", ".join(s["analysis"]) or "none"),
    ] + [("resumed", f"{r['start_time']} as run {r['uid']}") for r in s["resumes"]]
    body = h.table(["", ""], [[h.cell(k), h.cell(v)] for k, v in rows], cls="header")
    if s["incomplete"]:
        body += "<h3>Incomplete</h3><ul class=\"incomplete\">" + "".join(f"<li>{h.esc(line)}</li>" for line in s["incomplete"]) + "</ul>"
    else:
        body += h.para("Complete: every step done, run stopped with success.")
    notes = list(data.sd.notes) if data.sd is not None else []
    if notes:
        body += "<h3>Data left out</h3><ul>" + "".join(f"<li>{h.esc(n)}</li>" for n in notes) + "</ul>"
    return h.section("Session", body, "session")


# ------------------------------------------------------------------------------------------- seed 000


def _fig_or_missing(fig: Any, name: str, caption: str, missing: str) -> str:
    return h.figure(fig, name, caption) if fig is not None else h.missing(missing)


def _figures(data: ReportData) -> str:
    sd, sp, fj = data.sd, data.fit.specimens, data.fit_json
    pressures = [d.pressure_kPa for d in sd.pressures]
    fitted = any(r.get("Kt_bar") is not None for r in fj["per_pressure"])
    mech = "" if fitted else " The mechanics were not fitted: the model curves use the preset's values."
    out = "<h3>Impedance spectra</h3>" + _fig_or_missing(
        ff.impedance_figure(sd, sp), "impedance",
        "Bode plot of the impedance per clamping pressure: markers measured, lines the fitted eq. 12 (global fit).",
        "No impedance spectrum in this session: the contact resistance and Table 1 values cannot be told.")
    out += "<h3>Displacement FRF</h3>" + _fig_or_missing(
        ff.frf_figure(sd, sp, fitted), "frf",
        "Tip displacement per volt from the stepped sines and any multisine (best linear approximation), error bars "
        "1 standard deviation of each estimate, against the model." + mech,
        "No stepped-sine or multisine records: there is no displacement FRF to compare the model with.")
    out += "<h3>Clamp values against clamping pressure</h3>" + _fig_or_missing(
        ff.parameters_figure(fj), "parameters",
        "Contact resistance R_cont, clamp stiffness K_t bar and first natural frequency f1 per pressure, with 1 standard error.",
        "The fit could tell none of R_cont, K_t bar and f1 from this session (the notes under Fitted values say why).")
    out += "<h3>Step response</h3>" + _fig_or_missing(
        ff.step_figure(data.feats, sp, pressures), "step",
        "First step of each pressure (from rest), measured (solid) against the model (dashed); bottom: the displacement misfit." + mech,
        "No step records at a clamping pressure in this session.")
    out += "<h3>Harmonic response</h3>" + _fig_or_missing(
        ff.harmonic_figure(sd, sp), "harmonic",
        "Harmonic record of each pressure against the model driven by the recorded voltage from rest; a slow drift in "
        "the misfit is the strip still relaxing from the record before." + mech,
        "No harmonic records in this session.")
    return out


def _optimum(data: ReportData) -> str:
    fj = data.fit_json
    meas, model = fj.get("optimum_pressure_kPa"), fj.get("model_optimum_pressure_kPa")
    text = ("Optimum clamping pressure: measured (largest step response) "
            + (f"{meas:g} kPa" if meas is not None else "cannot be told")
            + "; model (largest |H(0.1 Hz)| of the fitted strip) "
            + (f"{model:g} kPa" if model is not None else "cannot be told") + ".")
    fig = ff.optimum_figure(fj, data.sd, data.fit.specimens, data.feats)
    return "<h3>Optimum clamping pressure</h3>" + h.para(text) + _fig_or_missing(
        fig, "optimum",
        "Left: contact resistance against clamp stiffness, the trade-off the clamping pressure moves along. Right: actuation "
        "per volt against pressure relative to each series' largest value, measured and model, optima marked.",
        "Fewer than two pressures with an actuation measurement: the optimum and the trade-off cannot be shown.")


def _per_pressure_table(fj: dict) -> str:
    rows = []
    for i, r in enumerate(fj["per_pressure"]):
        cells = [h.cell(r["pressure_kPa"], f"per_pressure.{i}.pressure_kPa", f"{r['pressure_kPa']:g}")]
        for key, _, scale in PER_PRESSURE:
            v, e = r.get(key), r.get(f"{key}_stderr")
            shown = None if v is None else h.pm(v * scale, None if e is None else e * scale)
            cells.append(h.cell(v, f"per_pressure.{i}.{key}", shown, e))
        rows.append(cells)
    return h.table(["pressure (kPa)"] + [lab for _, lab, _ in PER_PRESSURE], rows, cls="fit")


def _clamp_table(fj: dict) -> str:
    names = list(dict.fromkeys(k for r in fj["per_pressure"] for k in (r.get("clamp") or {})))
    if not names:
        return ""
    rows = []
    for i, r in enumerate(fj["per_pressure"]):
        clamp = r.get("clamp") or {}
        rows.append([h.cell(r["pressure_kPa"], text=f"{r['pressure_kPa']:g}")] + [
            h.cell((clamp.get(k) or {}).get("value"), f"per_pressure.{i}.clamp.{k}.value", stderr=(clamp.get(k) or {}).get("stderr"))
            for k in names])
    header = ["pressure (kPa)"] + [f"{k} ({UNITS.get(k, 'SI')})" for k in names]
    return "<h4>Clamp-area electrical values (Table 1)</h4>" + h.table(header, rows, cls="fit")


def _scalar_table(fj: dict) -> str:
    rows = [[h.cell(label), h.cell(fj.get(key), key, stderr=fj.get(f"{key}_stderr"))] for key, label in SCALARS]
    rows += [[h.cell(f"free line {k} ({UNITS.get(k, 'SI')})"), h.cell(v.get("value"), f"line.{k}.value", stderr=v.get("stderr"))] for k, v in (fj.get("line") or {}).items()]
    return h.table(["quantity", "value"], rows, cls="fit")


def fit_tables(fj: dict) -> str:
    out = "<h3>Fitted values</h3>" + _per_pressure_table(fj) + _clamp_table(fj) + _scalar_table(fj)
    if fj.get("notes"):
        out += "<h4>Notes of the fit</h4><ul>" + "".join(f"<li>{h.esc(n)}</li>" for n in fj["notes"]) + "</ul>"
    return out


def seed000(data: ReportData) -> str:
    if data.fit is None:
        return h.section("Seed 000: clamping-pressure model", h.missing(data.missing.get("fit", "No fit.")), "seed000")
    body = _figures(data) + _optimum(data) + fit_tables(data.fit_json)
    return h.section("Seed 000: clamping-pressure model", body, "seed000")
