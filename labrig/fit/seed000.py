"""Seed 000 fit: clamp-area electrical values (Table 1) from the impedance spectra, with the free line's
values shared across pressures in one global fit; K_t bar per pressure, alpha and gamma from the
displacement FRF (Tables 2 and 3); the optimum clamping pressure. lmfit, with uncertainties from the
covariance of the least-squares fit (scaled by the reduced chi-square).
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass, field
from typing import Any

import lmfit
import numpy as np

from labrig.estimate import step_metrics
from labrig.fit.session_data import PressureData, SessionData
from labrig.physics import impedance as imp
from labrig.physics import presets, transfer
from labrig.physics.params import ClampElectrical, Fluid, Geometry, LineElectrical, Specimen, WATER_25C, AIR_25C

LINE_KEYS = ("R", "R_p", "Q0", "n")
CLAMP_KEYS = ("r_cont", "R_c", "R_pc", "Q0c", "n_c")
FIT_MODES = 4  # the FRF runs to 20 Hz; mode 2 is near 24 Hz, mode 4 above 100 Hz


def base_specimen(sample: dict[str, Any]) -> Specimen:
    """The prior specimen: the session's preset, or the paper's material in the imported geometry."""
    name = sample.get("preset")
    if name in presets.names():
        return presets.get(name).base.with_(n_modes=FIT_MODES)
    sp = presets.get("paper").base
    w = float(sample.get("width_m", sp.geometry.width))
    area = float(sample.get("clamp_area_m2", sp.geometry.clamp_area))
    geom = Geometry(float(sample.get("length_m", sp.geometry.length)), w, float(sample.get("thickness_m", sp.geometry.thickness)), area / w, w)
    fluid: Fluid = AIR_25C if str(sample.get("medium", "water")) == "air" else WATER_25C
    mech = sp.mechanics if fluid is WATER_25C else dataclasses.replace(sp.mechanics, mu_v=None, density=2000.0)
    return sp.with_(geometry=geom, fluid=fluid, mechanics=mech, n_modes=FIT_MODES)


def _tag(p: float) -> str:
    return f"p{p:g}".replace(".", "_")


@dataclass
class ParamEstimate:
    value: float
    stderr: float = float("nan")


@dataclass
class Seed000Fit:
    per_pressure: list[dict[str, Any]]
    line: dict[str, ParamEstimate] = field(default_factory=dict)
    alpha: ParamEstimate | None = None
    gamma: ParamEstimate | None = None
    optimum_pressure_kPa: float | None = None
    model_optimum_pressure_kPa: float | None = None
    notes: list[str] = field(default_factory=list)
    eis_redchi: float | None = None
    frf_redchi: float | None = None
    elapsed_s: float = 0.0
    specimens: dict[float, Specimen] = field(default_factory=dict)  # the fitted strip per pressure

    def to_json(self) -> dict[str, Any]:
        def pe(x: ParamEstimate | None) -> float | None:
            return None if x is None or not math.isfinite(x.value) else x.value

        return {
            "per_pressure": self.per_pressure,
            "optimum_pressure_kPa": self.optimum_pressure_kPa,
            "model_optimum_pressure_kPa": self.model_optimum_pressure_kPa,
            "alpha": pe(self.alpha),
            "alpha_stderr": None if self.alpha is None else self.alpha.stderr,
            "gamma": pe(self.gamma),
            "gamma_stderr": None if self.gamma is None else self.gamma.stderr,
            "line": {k: {"value": v.value, "stderr": v.stderr} for k, v in self.line.items()},
            "eis_redchi": self.eis_redchi,
            "frf_redchi": self.frf_redchi,
            "notes": self.notes,
        }


# ------------------------------------------------------------------------------------- impedance


def _specimen_from(params: lmfit.Parameters, base: Specimen, p: float) -> Specimen:
    v = params.valuesdict()
    line = dataclasses.replace(base.line, **{k: 10 ** v[f"log_{k}"] if k != "n" else v["n"] for k in LINE_KEYS})
    t = _tag(p)
    clamp = dataclasses.replace(base.clamp, **{k: (10 ** v[f"log_{k}_{t}"] if k != "n_c" else v[f"n_c_{t}"]) for k in CLAMP_KEYS})
    return base.with_(line=line, clamp=clamp, pressure=p * 1e3)


def _impedance_params(data: list[PressureData], base: Specimen) -> lmfit.Parameters:
    pars = lmfit.Parameters()
    for k in LINE_KEYS:
        val = getattr(base.line, k)
        if k == "n":
            pars.add("n", val, min=0.3, max=1.0)
        else:
            pars.add(f"log_{k}", np.log10(val), min=np.log10(val) - 3, max=np.log10(val) + 3)
    for d in data:
        t = _tag(d.pressure_kPa)
        for k in CLAMP_KEYS:
            val = getattr(base.clamp, k)
            if k == "n_c":
                pars.add(f"n_c_{t}", val, min=0.3, max=1.0)
            else:
                pars.add(f"log_{k}_{t}", np.log10(val), min=np.log10(val) - 3, max=np.log10(val) + 3)
    return pars


def _impedance_residual(ps: lmfit.Parameters, data: list[PressureData], base: Specimen) -> np.ndarray:
    out = []
    for d in data:
        f, z = d.eis
        zm = imp.impedance(2j * np.pi * f, _specimen_from(ps, base, d.pressure_kPa))
        r = (zm - z) / np.abs(z)
        out += [r.real, r.imag]
    return np.concatenate(out)


def fit_impedance(data: list[PressureData], base: Specimen) -> tuple[lmfit.minimizer.MinimizerResult, dict[float, Specimen]]:
    """Global fit: free-line values shared, clamp-area values per pressure. R_s (the four-probe value) fixed."""
    res = lmfit.minimize(_impedance_residual, _impedance_params(data, base), args=(data, base), method="least_squares", x_scale="jac")
    return res, {d.pressure_kPa: _specimen_from(res.params, base, d.pressure_kPa) for d in data}


def _log_param(res: lmfit.minimizer.MinimizerResult, name: str) -> ParamEstimate:
    p = res.params[name]
    if name.startswith("log_"):
        val = 10**p.value
        err = val * np.log(10) * p.stderr if p.stderr is not None else float("nan")
        return ParamEstimate(val, err)
    return ParamEstimate(p.value, p.stderr if p.stderr is not None else float("nan"))


# ------------------------------------------------------------------------------------- FRF


def _frf_params(data: list[PressureData], specimens: dict[float, Specimen]) -> lmfit.Parameters:
    pars = lmfit.Parameters()
    any_sp = next(iter(specimens.values()))
    pars.add("gamma", 0.1, min=0.0, max=1.0)
    pars.add("log_alpha", np.log10(any_sp.mechanics.alpha), min=-4, max=2)
    for d in data:
        f, h, _, _ = d.frf()
        pars.add(f"log_kt_{_tag(d.pressure_kPa)}", np.log10(_kt_guess(f, h, specimens[d.pressure_kPa])), min=-1, max=2.5)
    return pars


def _frf_residual(ps: lmfit.Parameters, data: list[PressureData], specimen_of) -> np.ndarray:
    v = ps.valuesdict()
    out = []
    for d in data:
        f, h, _, sig = d.frf()
        sp = _mech(specimen_of(ps, d.pressure_kPa), v["gamma"], 10 ** v["log_alpha"], 10 ** v[f"log_kt_{_tag(d.pressure_kPa)}"])
        r = np.log(transfer.frf(f, sp) / h)
        # a 0.3 % floor: the FRF's tiny cycle-to-cycle scatter must not let it drag the electrical values
        w = 1.0 / np.maximum(np.nan_to_num(sig / np.abs(h), nan=0.01), 3e-3)
        out += [r.real * w, r.imag * w]
    return np.concatenate(out)


def fit_frf(data: list[PressureData], specimens: dict[float, Specimen]) -> lmfit.minimizer.MinimizerResult:
    """alpha and gamma shared, K_t bar per pressure, on the complex log of the displacement FRF (electrical fixed)."""
    return lmfit.minimize(_frf_residual, _frf_params(data, specimens), args=(data, lambda ps, p: specimens[p]), method="least_squares", x_scale="jac")


def fit_joint(eis_data: list[PressureData], frf_data: list[PressureData], base: Specimen, eis0: lmfit.Parameters, frf0: lmfit.Parameters, sigma_eis: float) -> lmfit.minimizer.MinimizerResult:
    """Impedance and displacement FRF together, every parameter free, each residual in units of its noise:
    the FRF constrains the electrical values the impedance alone leaves loose, and the covariance is global."""
    pars = lmfit.Parameters()
    for src in (eis0, frf0):
        for name, p in src.items():
            pars.add(name, p.value, min=p.min, max=p.max)
    eis_p = {d.pressure_kPa for d in eis_data}

    def spec(ps: lmfit.Parameters, p: float) -> Specimen:
        return _specimen_from(ps, base, p) if p in eis_p else base.with_(pressure=p * 1e3)

    def residual(ps: lmfit.Parameters) -> np.ndarray:
        return np.concatenate([_impedance_residual(ps, eis_data, base) / sigma_eis, _frf_residual(ps, frf_data, spec)])

    return lmfit.minimize(residual, pars, method="least_squares", x_scale="jac")


def _mech(sp: Specimen, gamma: float, alpha: float, kt: float) -> Specimen:
    return sp.with_(mechanics=dataclasses.replace(sp.mechanics, gamma=gamma, alpha=alpha), Kt_bar=kt)


def _kt_guess(f: np.ndarray, h: np.ndarray, sp: Specimen) -> float:
    """Start K_t bar where the model's f1 sits at the measured resonance (peak of |H| f^(1-n))."""
    peak = f[np.argmax(np.abs(h) * f ** (1 - sp.line.n))]
    best, err = 5.0, np.inf
    for kt in np.geomspace(0.5, 100, 40):
        e = abs(transfer.modal_set(sp.with_(Kt_bar=kt)).f_Hz[0] - peak)
        if e < err:
            best, err = kt, e
    return best


# ------------------------------------------------------------------------------------- driver


def _measured_actuation(d: PressureData) -> tuple[float | None, float | None]:
    """(peak |displacement| of the step response, harmonic amplitude) at this pressure."""
    peak = None
    steps = d.of_kind("step")
    if steps:
        r = steps[0]
        md = r.meta
        t_on = float(md.get("pre_s", 0.0))
        m = step_metrics(r.t, r.v, r.d, t_on, t_on + float(md.get("on_s", r.t[-1])))
        peak = m.peak_m / max(abs(float(md.get("amplitude_V", 1.0))), 1e-12)
    harm = None
    hs = d.of_kind("harmonic")
    if hs:
        from labrig.estimate import harmonic_metrics

        r = hs[0]
        harm = harmonic_metrics(r.t, r.v, r.d, float(r.meta["frequency_Hz"]))[0]
    return peak, harm


def fit_seed000(sd: SessionData) -> Seed000Fit:
    t0 = time.perf_counter()
    base = base_specimen(sd.sample)
    notes = list(sd.notes)
    rows = []
    fit = Seed000Fit(rows, notes=notes)
    with_eis = [d for d in sd.pressures if d.eis is not None]
    specimens = {d.pressure_kPa: base.with_(pressure=d.pressure_kPa * 1e3) for d in sd.pressures}
    eis_res = None
    if with_eis:
        eis_res, fitted = fit_impedance(with_eis, base)
        specimens.update(fitted)
        fit.eis_redchi = float(eis_res.redchi)
        fit.line = {k: _log_param(eis_res, "n" if k == "n" else f"log_{k}") for k in LINE_KEYS}
    else:
        notes.append("no impedance spectrum: contact resistance and Table 1 values cannot be told (null)")
    with_frf = [d for d in sd.pressures if d.frf() is not None and len(d.sines) >= 4]
    frf_res = None
    if with_frf:
        frf_res = fit_frf(with_frf, specimens)
        fit.frf_redchi = float(frf_res.redchi)
        if eis_res is not None:  # refine everything together: global covariance, no error propagation gap
            joint = fit_joint(with_eis, with_frf, base, eis_res.params, frf_res.params, float(np.sqrt(eis_res.redchi)))
            eis_res = frf_res = joint
            fit.eis_redchi = fit.frf_redchi = float(joint.redchi)
            fit.line = {k: _log_param(joint, "n" if k == "n" else f"log_{k}") for k in LINE_KEYS}
            specimens.update({d.pressure_kPa: _specimen_from(joint.params, base, d.pressure_kPa) for d in with_eis})
        fit.alpha = _log_param(frf_res, "log_alpha")
        fit.gamma = _log_param(frf_res, "gamma")
    else:
        notes.append("no stepped-sine FRF with >= 4 frequencies: f1, K_t bar, alpha and gamma cannot be told (null)")
    measured: dict[float, float] = {}
    modelled: dict[float, float] = {}
    for d in sd.pressures:
        p, tag = d.pressure_kPa, _tag(d.pressure_kPa)
        row: dict[str, Any] = {"pressure_kPa": p}
        sp = specimens[p]
        if eis_res is not None and d.eis is not None:
            ests = {k: _log_param(eis_res, f"n_c_{tag}" if k == "n_c" else f"log_{k}_{tag}") for k in CLAMP_KEYS}
            area = sp.geometry.clamp_area
            row["R_cont_ohm"] = ests["r_cont"].value / area
            row["R_cont_ohm_stderr"] = ests["r_cont"].stderr / area
            row["clamp"] = {k: {"value": e.value, "stderr": e.stderr} for k, e in ests.items()}
        else:
            row["R_cont_ohm"] = None
        if frf_res is not None and d in with_frf:
            kt = _log_param(frf_res, f"log_kt_{tag}")
            sp = _mech(sp, fit.gamma.value, fit.alpha.value, kt.value)
            ms = transfer.modal_set(sp)
            dk = kt.value * 1e-4
            df = (transfer.modal_set(sp.with_(Kt_bar=kt.value + dk)).f_Hz[0] - ms.f_Hz[0]) / dk
            row.update(Kt_bar=kt.value, Kt_bar_stderr=kt.stderr, f1_Hz=float(ms.f_Hz[0]), f1_Hz_stderr=float(abs(df) * kt.stderr), xi1=float(ms.xi[0]))
            specimens[p] = sp
        else:
            row.update(Kt_bar=None, f1_Hz=None)
        peak, harm = _measured_actuation(d)
        row["peak_disp_m"] = peak
        row["harmonic_amp_m"] = harm
        if d.records:
            forces = np.concatenate([r.force_N for r in d.records if r.force_N.size]) if any(r.force_N.size for r in d.records) else np.zeros(0)
            row["force_N_mean"] = float(np.mean(forces)) if forces.size else None
        if peak is not None:
            measured[p] = peak
        if frf_res is not None and d in with_frf:
            modelled[p] = float(abs(transfer.frf(np.array([0.1]), sp)[0]))
        rows.append(row)
    if len(measured) >= 2:
        fit.optimum_pressure_kPa = max(measured, key=measured.get)
    elif sd.pressures:
        notes.append("fewer than two pressures with a step response: the optimum cannot be told (null)")
    if len(modelled) >= 2:
        fit.model_optimum_pressure_kPa = max(modelled, key=modelled.get)
    fit.specimens = specimens
    fit.elapsed_s = time.perf_counter() - t0
    return fit
