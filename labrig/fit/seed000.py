"""Seed 000 fit: clamp-area electrical values (Table 1) and the free line's values (shared across
pressures), K_t bar per pressure, alpha and gamma (Tables 2 and 3), the optimum clamping pressure.

Three stages, each an lmfit least-squares fit (labrig.fit.seed000_problem): the impedance spectra alone
(R_cont held at the paper's value: the spectrum cannot tell it, docs/model.md 9), the displacement FRF
with the electrical values held, then both together with R_cont free. The FRF tells R_cont through the
voltage divider v(0)/V0 = 1 - Z1/Z(f) (eq. 5-6, 12). Residuals are in units of their noise (the analyser's
relative noise, estimated from the spectrum fit; each FRF point's standard deviation, floored), so the
covariance is used as it is, inflated by the reduced chi-square only when the fit is worse than the noise.
Every reported parameter carries a status: ``fitted``, ``fixed`` (at a documented value, not told by the
data) or ``undetermined`` (its 1-sigma interval is wider than itself, or it sits at a bound): an
undetermined contact resistance is reported as null.
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
from labrig.fit import seed000_problem as sp000
from labrig.fit.seed000_problem import LINE_NAMES, Problem, clamp_name, tag
from labrig.estimate.session_data import PressureData, SessionData, step_offset, step_onset
from labrig.physics import presets, transfer
from labrig.physics.clamp import ClampLaw
from labrig.physics.params import AIR_25C, WATER_25C, Fluid, Geometry, Specimen
from labrig.records import RecordKind

REL_UNDETERMINED = 1.0  # a parameter whose 1-sigma is larger than itself is not reported as told
# the spectra's RMS, in units of their own noise, that joining the DAQ's current may leave (fit_electrical): clean
# sessions 0.97-1.00 with it (1.0 by construction without); a current read 5-30 ms late 67-152, a drying 8-43
CURRENT_AGREES = 1.5
# the share by which the current's RMS must fall when the electrical values are freed to it, where it puts the spectra
# beyond CURRENT_AGREES: a current read late or filtered 0.21-0.24, a faradaic branch 0.42-0.88, a drying 0.74-0.88
# (set on the seen sets fresh19-22, docs/diagnosis.md); fresh29's shunt amplifier's RFI filter (a 1 ms lag on the
# current) 0.34, the seen sets fresh22-29's faradaic branches and dryings 0.64-0.94, the tuning set's 0.71-0.89: 0.38
# splits 0.34 from 0.42 (docs/model.md)
CURRENT_MOVES = 0.38
MIN_FRF_LINES = 4  # alpha, gamma and K_t bar need a resonance and its flanks
# the staged valley's largest step (log10 values: decades; exponents: their own units) per standard error of R:
# clean sessions give at most 0.02, drying strips 0.5-14 in the cached sets, beyond 100 where a CI run overflowed
VALLEY_MAX_STEP = 1.0


def base_specimen(sample: dict[str, Any]) -> Specimen:
    """The prior specimen: the session's preset, or the paper's material in the imported geometry (its line's
    per-length values scaled with the width, as the seed-001 preset scales them: R_s is held, not fitted, so an
    unscaled one would misfit every strip not 4 mm wide).

    It keeps the preset's number of modes (10), the model the simulated bench runs: with 4 modes the
    FRF's shape is 0.5 % low below 1 Hz, which the joint fit turned into +0.2 ohm of R_cont and +1.5 % of alpha."""
    name = sample.get("preset")
    if name in presets.names():
        return presets.get(name).base
    sp = presets.get("paper").base
    w = float(sample.get("width_m", sp.geometry.width))
    area = float(sample.get("clamp_area_m2", sp.geometry.clamp_area))
    geom = Geometry(float(sample.get("length_m", sp.geometry.length)), w, float(sample.get("thickness_m", sp.geometry.thickness)), area / w, w)
    fluid: Fluid = AIR_25C if str(sample.get("medium", "water")) == "air" else WATER_25C
    mech = sp.mechanics if fluid is WATER_25C else dataclasses.replace(sp.mechanics, mu_v=None, density=2000.0)
    return sp.with_(geometry=geom, fluid=fluid, mechanics=mech, line=presets.line_for_width(w))


def prior_specimens(sample: dict[str, Any], pressures: list[float]) -> dict[float, Specimen]:
    """The paper's strip at each pressure: clamp-area values and K_t bar from the clamp law (Tables 1-2).
    They are the start values, and the values of what the data cannot tell (R_sc, R_pc)."""
    base = base_specimen(sample)
    name = sample.get("preset")
    law: ClampLaw = presets.get(name if name in presets.names() else "paper").clamp_law
    return {p: base.with_(clamp=law.clamp_at(p * 1e3), Kt_bar=law.kt_bar_at(p * 1e3), pressure=p * 1e3) for p in pressures}


@dataclass
class ParamEstimate:
    value: float
    stderr: float = float("nan")
    status: str = "fitted"  # fitted | fixed | undetermined

    def as_json(self) -> dict[str, Any]:
        err = self.stderr if self.status != "fixed" and math.isfinite(self.stderr) else None
        return {"value": self.value, "stderr": err, "status": self.status}


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
    eis_noise_rel: float | None = None  # the analyser's relative noise per component, from the spectra
    frf_excess_rel: float | None = None  # relative FRF error beyond the points' noise, from the FRF
    elapsed_s: float = 0.0
    specimens: dict[float, Specimen] = field(default_factory=dict)  # the fitted strip per pressure
    # the strip from the stages alone: electrical values from the spectra, mechanics from the FRF with those
    # held. A misfit of the displacement path cannot bend the electrical values here (the joint fit's R_cont
    # can), so the diagnosis judges each channel against a baseline told by that channel.
    staged_specimens: dict[float, Specimen] = field(default_factory=dict)
    # the electrical stage's loosest direction: per parameter, its change along one standard error of the line
    # resistance R with the others following their correlation with it (a shallow valley with R_c and the CPEs),
    # within which the diagnosis lets the displacement FRF move the staged strip (labrig/diagnose/nuisance.py)
    staged_valley: dict[str, float] = field(default_factory=dict)
    # the staged strip on the spectra's electrical values alone, where the current was joined though it put the spectra
    # beyond their noise (``electrical_stage``): a faradaic branch is judged on it too (labrig/diagnose/engine.py)
    spectra_specimens: dict[float, Specimen] = field(default_factory=dict)

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
            "line": {k: v.as_json() for k, v in self.line.items()},
            "eis_redchi": self.eis_redchi,
            "frf_redchi": self.frf_redchi,
            "eis_noise_rel": self.eis_noise_rel,
            "frf_excess_rel": self.frf_excess_rel,
            "notes": self.notes,
        }


# ------------------------------------------------------------------------------------- stages


def fit_impedance(data: list[PressureData], priors: dict[float, Specimen]) -> tuple[lmfit.minimizer.MinimizerResult, float]:
    """Spectra alone: line shared, clamp per pressure, R_cont held at the prior (the spectrum cannot tell
    it from R_c and R: docs/model.md 9). Fitted with unit weights, so the residual's rms is the analyser's
    relative noise per component; returned with it, the uncertainties scaled to it."""
    pars = lmfit.Parameters()
    sp000.add_line(pars, priors[data[0].pressure_kPa])
    for d in data:
        sp000.add_clamp(pars, d.pressure_kPa, priors[d.pressure_kPa], vary_r_cont=False)
    res = Problem(priors, eis=data).minimize(pars)
    sigma = max(float(np.sqrt(res.redchi)), sp000.EIS_SIGMA_FLOOR)
    for p in res.params.values():
        if p.stderr is not None:
            p.stderr *= sigma
    return res, sigma


def fit_electrical(data: list[PressureData], priors: dict[float, Specimen]) -> tuple[lmfit.minimizer.MinimizerResult, float]:
    """The electrical stage: the spectra (``fit_impedance``, which also gives the analyser's noise), then the
    spectra and the same pressures' DAQ current admittance together. The spectrum alone leaves the line and clamp
    resistances free to trade along a shallow valley (R 7 % high against R_c 5 % low in one clean session of ten,
    which then put the displacement FRF 1-3 % off near resonance); the current, 15x less noisy per point, pins it.
    The current carries no displacement-path effect, so this stage stays a purely electrical baseline.

    The current chooses along the spectra's valley; it does not overrule them. Where joining it puts the spectra
    beyond ``CURRENT_AGREES`` x their own noise and yet brings the current itself little closer (its RMS down by less
    than ``CURRENT_MOVES``), the current holds what no electrical values make (a current read late, or through a
    filter of its own): the spectra's values are kept (the third value returned: False). A strip that changed between
    the spectra and the sines (a drying) moves both, and the current, which the values then follow, is joined."""
    res, sigma, agrees, _ = electrical_stage(data, priors)
    return res, sigma, agrees


def electrical_stage(data: list[PressureData], priors: dict[float, Specimen]) -> tuple:
    """``fit_electrical``'s result and, where the current was joined though it put the spectra beyond
    ``CURRENT_AGREES`` (a faradaic branch, a drying), the spectra's fit alone (else None): the diagnosis judges a
    branch of the current on those values too (``Seed000Fit.spectra_specimens``)."""
    alone, sigma = fit_impedance(data, priors)
    joined = current_agreement(data, priors, alone, sigma)
    if joined is None:
        return alone, sigma, True, None
    res, spectra_rms, fall = joined
    if spectra_rms > CURRENT_AGREES and fall < CURRENT_MOVES:
        return alone, sigma, False, None
    return res, sigma, True, (alone if spectra_rms > CURRENT_AGREES else None)


def current_agreement(data: list[PressureData], priors: dict[float, Specimen], alone: lmfit.minimizer.MinimizerResult,
                      sigma: float) -> tuple[lmfit.minimizer.MinimizerResult, float, float] | None:
    """The spectra and the DAQ's current admittance fitted together from the spectra's fit ``alone``: (the joined
    fit, the spectra's RMS in it in units of their noise, the share by which the current's RMS fell from the spectra's
    values to the joined ones); None without a current. ``fit_electrical`` reads the last two against
    ``CURRENT_AGREES`` and ``CURRENT_MOVES``."""
    cur = [d for d in data if d.current_lines() is not None]
    if not cur:
        return None
    problem = Problem(priors, eis=data, cur=cur, sigma_eis=sigma)
    res = problem.minimize(alone.params)
    n = problem.offsets[len(data)]
    rms = lambda r: float(np.sqrt(np.mean(r**2)))  # noqa: E731
    return res, rms(res.residual[:n]), 1.0 - rms(res.residual[n:]) / rms(problem.residual(alone.params)[n:])


def valley(res: lmfit.minimizer.MinimizerResult, name: str) -> dict[str, float]:
    """Each varied parameter's change along one standard error of ``name`` with the others at their conditional
    best (the covariance's column over its standard deviation): the fit's shallowest valley through that parameter.
    Empty where the fit has no usable covariance (none, not finite, or any step beyond ``VALLEY_MAX_STEP``)."""
    cov, names = getattr(res, "covar", None), list(getattr(res, "var_names", []) or [])
    if cov is None or name not in names:
        return {}
    k = names.index(name)
    sd = math.sqrt(cov[k, k]) if cov[k, k] > 0 else 0.0
    if not sd or not np.all(np.isfinite(cov[:, k])):
        return {}
    step = {n: float(cov[j, k] / sd) for j, n in enumerate(names)}
    # Spectra no single strip fits (a strip drying through the session) loosen the covariance to steps of decades:
    # no valley a spectrum allows, and 10**step can overflow downstream
    return step if max(map(abs, step.values())) <= VALLEY_MAX_STEP else {}


def fit_frf(data: list[PressureData], priors: dict[float, Specimen], electrical: lmfit.Parameters) -> lmfit.Parameters:
    """Start values for alpha and gamma (shared) and K_t bar (per pressure): the complex log of the
    displacement FRF with the electrical values held at ``electrical`` (or at the priors where it has none)."""
    pars = sp000.merged(electrical)
    for p in pars.values():
        p.vary = False
    any_sp = next(iter(priors.values()))
    kts = {}
    for d in data:
        f, h, _, _ = d.frf_lines()
        kts[d.pressure_kPa] = _kt_guess(f, h, priors[d.pressure_kPa])
    sp000.add_mechanics(pars, 0.1, any_sp.mechanics.alpha, kts)
    return Problem(priors, frf=data).minimize(pars).params


def joint_params(eis_data: list[PressureData], frf_data: list[PressureData], eis0: lmfit.Parameters, frf0: lmfit.Parameters) -> lmfit.Parameters:
    """Spectra and displacement FRF together: every told parameter free, R_cont where both were measured."""
    pars = sp000.merged(eis0, {n: p for n, p in frf0.items() if n not in eis0})
    both = {d.pressure_kPa for d in eis_data} & {d.pressure_kPa for d in frf_data}
    for p in both:
        pars[clamp_name("r_cont", p)].vary = True
    return pars


def fit_with_frf(problem: Problem, pars: lmfit.Parameters, n_told: int) -> lmfit.minimizer.MinimizerResult:
    """Fit, then let the FRF residuals tell their error beyond the points' noise (excess_error) and refit
    until it settles (within 20 %); ``n_told`` parameters are told by the FRF alone."""
    for _ in range(4):
        res = problem.minimize(pars)
        new = problem.frf_excess_from(res.params, n_told)
        settled = abs(math.log(new / problem.frf_excess)) < math.log(1.2)
        problem.frf_excess, pars = new, res.params
        if settled:
            break
    return res


def _kt_guess(f: np.ndarray, h: np.ndarray, sp: Specimen) -> float:
    """Start K_t bar where the model's f1 sits at the measured resonance (peak of |H| f^(1-n))."""
    peak = f[np.argmax(np.abs(h) * f ** (1 - sp.line.n))]
    best, err = 5.0, np.inf
    for kt in np.geomspace(0.5, 100, 40):
        e = abs(transfer.modal_set(sp.with_(Kt_bar=kt, n_modes=1)).f_Hz[0] - peak)
        if e < err:
            best, err = kt, e
    return best


# ------------------------------------------------------------------------------------- estimates


def estimate(params: lmfit.Parameters, name: str) -> ParamEstimate:
    """A parameter on its physical scale (log10 names back to values), with its status."""
    p = params[name]
    log = name.startswith("log_")
    val = 10**p.value if log else p.value
    if not p.vary:
        return ParamEstimate(val, float("nan"), "fixed")
    err = float("nan") if p.stderr is None else float(p.stderr)
    rel = math.log(10) * err if log else err / max(abs(p.value), 1e-300)
    span = p.max - p.min if math.isfinite(p.max - p.min) else 1.0
    at_bound = min(abs(p.value - p.min), abs(p.max - p.value)) < 1e-6 * span
    told = math.isfinite(rel) and rel <= REL_UNDETERMINED and not at_bound
    return ParamEstimate(val, val * math.log(10) * err if log else err, "fitted" if told else "undetermined")


def clamp_estimates(params: lmfit.Parameters, p: float, prior: Specimen) -> dict[str, ParamEstimate]:
    """Table 1's six values at pressure p in SI (r_cont in ohm m^2): fitted or fixed at the paper's."""
    out = {k: estimate(params, clamp_name(k, p)) for k in sp000.CLAMP_FREE}
    area = prior.geometry.clamp_area
    out["r_cont"] = dataclasses.replace(out["r_cont"], value=out["r_cont"].value * area, stderr=out["r_cont"].stderr * area)
    for k in sp000.CLAMP_FIXED:
        out[k] = ParamEstimate(getattr(prior.clamp, k), float("nan"), "fixed")
    return out


# ------------------------------------------------------------------------------------- driver


def _measured_actuation(d: PressureData) -> tuple[float | None, float | None]:
    """(peak |displacement| of the step response, harmonic amplitude) at this pressure."""
    peak = None
    steps = d.of_kind(RecordKind.STEP)
    if steps:
        r = steps[0]
        m = step_metrics(r.t, r.v, r.d, step_onset(r), step_offset(r))
        peak = m.peak_m / max(abs(float(r.meta.get("amplitude_V", 1.0))), 1e-12)
    harm = None
    hs = d.of_kind(RecordKind.HARMONIC)
    if hs:
        from labrig.estimate import harmonic_metrics

        r = hs[0]
        harm = harmonic_metrics(r.t, r.v, r.d, float(r.meta["frequency_Hz"]))[0]
    return peak, harm


def _run_stages(sd: SessionData, priors: dict[float, Specimen], fit: Seed000Fit, joint: bool = True) -> lmfit.Parameters | None:
    """The fit stages the data allow; the final parameter set (None if nothing could be fitted). ``joint`` False:
    the staged strip alone (``fit.staged_specimens``), without the joint refinement (``staged_specimens``)."""
    with_eis = [d for d in sd.pressures if d.eis is not None]
    with_frf = [d for d in sd.pressures if (lines := d.frf_lines()) is not None and lines[0].size >= MIN_FRF_LINES]
    final = None
    if with_eis:
        res, fit.eis_noise_rel, agrees, disputed = electrical_stage(with_eis, priors)
        if not agrees:
            fit.notes.append(f"the DAQ's current disagrees with the spectra (with it, the spectra beyond {CURRENT_AGREES:g} x their "
                             "noise): the electrical values are the spectra's alone")
        final = res.params
        fit.staged_valley = valley(res, "log_R")
        fit.staged_specimens = _specimens(priors, final)
    else:
        fit.notes.append("no impedance spectrum: contact resistance and Table 1 values cannot be told (null)")
    if with_frf:
        electrical = final if final is not None else _prior_electrical(priors)
        pars = fit_frf(with_frf, priors, electrical)
        fit.staged_specimens = _specimens(priors, pars)
        if joint and with_eis and disputed is not None:
            fit.spectra_specimens = _specimens(priors, fit_frf(with_frf, priors, disputed.params))
        if not joint:
            return pars
        if with_eis:
            pars = joint_params(with_eis, with_frf, final, pars)
        problem = Problem(priors, eis=with_eis, frf=with_frf, sigma_eis=fit.eis_noise_rel or 1.0)
        n_told = sum(1 for n, p in pars.items() if p.vary and n.startswith(("log_kt_", "gamma", "log_alpha", "R_cont_")))
        res = fit_with_frf(problem, pars, n_told)
        r, n_eis = res.residual, problem.offsets[len(with_eis)]
        fit.eis_redchi = float(np.mean(r[:n_eis] ** 2)) if with_eis else None
        fit.frf_redchi = float(np.mean(r[n_eis:] ** 2))
        fit.frf_excess_rel = problem.frf_excess
        final = res.params
        fit.alpha = estimate(final, "log_alpha")
        fit.gamma = estimate(final, "gamma")
    else:
        fit.notes.append(f"no stepped-sine FRF (nor multisine BLA) with >= {MIN_FRF_LINES} frequencies: f1, K_t bar, alpha and gamma cannot be told (null)")
    if with_eis:
        fit.line = {k: estimate(final, n) for k, n in LINE_NAMES.items()}
        fit.line["R_s"] = ParamEstimate(priors[with_eis[0].pressure_kPa].line.R_s, float("nan"), "fixed")
        held = "R_sc and R_pc held at the paper's clamp law (Table 1): the spectrum tells only the total leak"
        if not with_frf:
            held += "; R_cont held too (the spectrum cannot tell it from the CPE resistances without an FRF): R_cont_ohm null"
        fit.notes.append(held)
    return final


def _specimens(priors: dict[float, Specimen], pars: lmfit.Parameters) -> dict[float, Specimen]:
    problem, v = Problem(priors), pars.valuesdict()
    return {p: problem.specimen(v, p) for p in priors}


def _prior_electrical(priors: dict[float, Specimen]) -> lmfit.Parameters:
    pars = lmfit.Parameters()
    sp000.add_line(pars, next(iter(priors.values())), vary=False)
    for p, sp in priors.items():
        sp000.add_clamp(pars, p, sp, vary_r_cont=False)
    return pars


def _row(d: PressureData, fit: Seed000Fit, final: lmfit.Parameters | None, prior: Specimen, problem: Problem) -> tuple[dict[str, Any], Specimen]:
    p = d.pressure_kPa
    row: dict[str, Any] = {"pressure_kPa": p, "R_cont_ohm": None}
    sp = problem.specimen(final.valuesdict(), p) if final is not None else prior
    if final is not None and d.eis is not None:
        ests = clamp_estimates(final, p, prior)
        rc = ests["r_cont"]
        area = prior.geometry.clamp_area
        row["R_cont_status"] = rc.status
        if rc.status == "fitted":
            row["R_cont_ohm"] = rc.value / area
            row["R_cont_ohm_stderr"] = rc.stderr / area
        row["clamp"] = {k: e.as_json() for k, e in ests.items()}
    kt_name = f"log_kt_{tag(p)}"
    if final is not None and kt_name in final:
        kt = estimate(final, kt_name)
        ms = transfer.modal_set(sp)
        dk = kt.value * 1e-4
        df = (transfer.modal_set(sp.with_(Kt_bar=kt.value + dk)).f_Hz[0] - ms.f_Hz[0]) / dk
        row.update(Kt_bar=kt.value, Kt_bar_stderr=kt.stderr, f1_Hz=float(ms.f_Hz[0]), f1_Hz_stderr=float(abs(df) * kt.stderr), xi1=float(ms.xi[0]))
    else:
        row.update(Kt_bar=None, f1_Hz=None)
    peak, harm = _measured_actuation(d)
    row["peak_disp_m"] = peak
    row["harmonic_amp_m"] = harm
    forces = [r.force_N for r in d.records if r.force_N.size]
    if d.records:
        row["force_N_mean"] = float(np.mean(np.concatenate(forces))) if forces else None
        if forces:  # the pressure the bench actually applied (the load cell), next to the nominal one
            row["pressure_measured_kPa"] = row["force_N_mean"] / prior.geometry.clamp_area / 1e3
    return row, sp


def staged_specimens(sd: SessionData) -> dict[float, Specimen]:
    """The strip per pressure from the fit's stages alone (electrical values from the spectra, mechanics from the FRF
    with them held: ``Seed000Fit.staged_specimens``), the priors where no stage can run. The diagnosis' baseline
    (``diagnose.engine.baseline_specimens``) without the joint refinement, which it does not use: the wet strip's
    refits (diagnose/wet_strip.py) run this, not ``fit_seed000``."""
    fit = Seed000Fit([])
    priors = prior_specimens(sd.sample, [d.pressure_kPa for d in sd.pressures])
    if sd.pressures:
        _run_stages(sd, priors, fit, joint=False)
    return fit.staged_specimens or priors


def fit_seed000(sd: SessionData) -> Seed000Fit:
    t0 = time.perf_counter()
    fit = Seed000Fit([], notes=list(sd.notes))
    priors = prior_specimens(sd.sample, [d.pressure_kPa for d in sd.pressures])
    final = _run_stages(sd, priors, fit) if sd.pressures else None
    problem = Problem(priors)
    measured: dict[float, float] = {}
    modelled: dict[float, float] = {}
    for d in sd.pressures:
        row, sp = _row(d, fit, final, priors[d.pressure_kPa], problem)
        fit.per_pressure.append(row)
        fit.specimens[d.pressure_kPa] = sp
        if row["peak_disp_m"] is not None:
            measured[d.pressure_kPa] = row["peak_disp_m"]
        if row["Kt_bar"] is not None:
            modelled[d.pressure_kPa] = float(abs(transfer.frf(np.array([0.1]), sp)[0]))
    if len(measured) >= 2:
        fit.optimum_pressure_kPa = max(measured, key=measured.get)
    elif sd.pressures:
        fit.notes.append("fewer than two pressures with a step response: the optimum cannot be told (null)")
    if len(modelled) >= 2:
        fit.model_optimum_pressure_kPa = max(modelled, key=modelled.get)
    fit.elapsed_s = time.perf_counter() - t0
    return fit
