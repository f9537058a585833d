"""Refitting the baseline's mechanical parameters together with an extension that reshapes the linear path.

A sensor offset or a channel delay changes the shape of the displacement FRF. The seed-000 fit has already
bent alpha, gamma and K_t bar towards that shape (K_t bar by 5-10 %, with alpha and gamma following), so an
extension applied on top of the fitted baseline alone cannot remove the misfit: it would have to undo the
bend. Such extensions (``Extension.refit_mechanics``) are fitted with alpha, gamma (global) and K_t bar (per
pressure) free again, and judged against the baseline refitted the same way, so the gain they claim is
their own and not the refit's.

Held out: alpha, gamma and the extension's parameters come from the fitted half; K_t bar of a held-out
pressure is a per-pressure nuisance (the baseline fit also took it from those records) and is refitted there
on the sine records alone, with everything else fixed.

The electrical values may move too, along one line: the electrical stage's shallowest valley, the line resistance R
with the values correlated with it (the clamp's R_c, the CPEs) following (``Seed000Fit.staged_valley``), in units of
R's standard error and held to the stage's estimate by a unit Gaussian prior. The spectra and the current leave R
loosest of the electrical values (20 % standard error on the seed-001 strip, correlation -0.99 with R_c), and an R
two of those off reshapes the displacement FRF by 1-2 % at every pressure, as a sensor offset does (fresh5's clean
seed 72: R 37 % high, named sensor_offset at 0.46). With the valley free the current FRF and the spectra join the
residual: they, not the displacement, tell where along it the strip sits. Without a valley (no spectra) it stays put.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from labrig.diagnose.catalogue import Context, Extension, Prediction, baseline, frf_by_pressure
from labrig.diagnose.features import predict_step, specimen_for
from labrig.fit.seed000_problem import shifted
from labrig.physics import transfer
from labrig.physics.impedance import impedance

NUISANCE_BLOCKS = ("frf_d", "harm_d", "frf_i", "eis")  # what the mechanics (the first two) and the valley (all) change
STEP_BLOCKS = ("step_d", "step_i")  # and the step records, where a refit is asked to keep them (``refit(steps=True)``)
LOG_BOUND_GLOBAL = 1.5  # alpha and gamma within a factor e^1.5 of the fitted values
LOG_BOUND_KT = 0.7
# least_squares stops when an iteration changes the cost by less than this share of it (or the parameters by this share
# of their size): scipy's default, 1e-8, spends about half of each fit polishing a cost already within 1e-3 of its end
# (logged on the tuning set's time-delay seed 1), and what the diagnosis reads from a fit, a held-out ratio compared at
# 0.5 and a DeltaBIC at -25, does not move at 1e-4 (docs/diagnosis.md, "The fits' stopping rule")
FIT_TOL = 1e-4
VALLEY_BOUND = 3.0  # the electrical values within this many of R's standard errors along the valley


@dataclass
class Refit:
    theta: np.ndarray  # the extension's parameters (empty for the reference)
    log_alpha: float
    log_gamma: float
    log_kt: dict[float, float]  # per pressure, fitted and held-out halves together
    ctx_fit: Context
    ctx_held: Context
    valley_sd: float = 0.0  # where along the electrical stage's valley, in standard errors of R

    def params(self) -> dict[str, float]:
        return {"alpha_factor": math.exp(self.log_alpha), "gamma_factor": math.exp(self.log_gamma), "electrical_valley_sd": self.valley_sd,
                **{f"Kt_factor_{p:g}kPa": math.exp(v) for p, v in sorted(self.log_kt.items())}}


def with_mechanics(ctx: Context, log_alpha: float, log_gamma: float, log_kt: dict[float, float], steps: bool = True,
                   valley_sd: float = 0.0, valley: dict | None = None) -> Context:
    """A copy of ``ctx`` whose baseline predictions use rescaled mechanics and electrical values moved ``valley_sd``
    along ``valley`` (steps left out if not ``steps``). Effects accepted earlier (``ctx.chain``) are re-applied on
    the new baseline.
    """
    specimens = {}
    moved = bool(valley_sd and valley)
    for p, sp in ctx.specimens.items():
        m = sp.mechanics
        mech = dataclasses.replace(m, alpha=m.alpha * math.exp(log_alpha), gamma=m.gamma * math.exp(log_gamma))
        sp = shifted(sp, p, valley, valley_sd) if moved else sp
        specimens[p] = sp.with_(Kt_bar=sp.Kt_bar * math.exp(log_kt.get(p, 0.0)), mechanics=mech)
    f3 = [dataclasses.replace(s, f=3 * s.f) for s in ctx.sines]
    new = dataclasses.replace(ctx, specimens=specimens, Hd=frf_by_pressure(ctx.sines, specimens), Hd3=frf_by_pressure(f3, specimens), base=None, cache={})
    if moved:  # the electrical path too: the current and the spectra
        new.Hi = frf_by_pressure(ctx.sines, specimens, lambda f, sp: transfer.admittance_tf(2j * np.pi * f, sp))
        new.spectra = [(s, impedance(2j * np.pi * s.f, specimen_for(specimens, s.pressure_kPa))) for s, _ in ctx.spectra]
    if steps:
        both = [predict_step(specimen_for(specimens, st.pressure_kPa), st) for st in ctx.steps]
        new.step_d = [d for d, _ in both]
        if moved:
            new.step_i = [i for _, i in both]
    else:
        new.steps, new.step_d, new.step_i = [], [], []
    for ext, th in ctx.chain:
        new.base = ext.apply(th, new)
    return new


def with_fitted_mechanics(ctx: Context, params: dict[str, float], valley: dict | None = None) -> Context:
    """``ctx`` with the mechanics a refitted extension reported (``Refit.params`` names; none: unchanged)."""
    if "alpha_factor" not in params:
        return ctx
    kt = {p: math.log(params[f"Kt_factor_{p:g}kPa"]) for p in ctx.specimens if f"Kt_factor_{p:g}kPa" in params}
    return with_mechanics(ctx, math.log(params["alpha_factor"]), math.log(params["gamma_factor"]), kt,
                          valley_sd=params.get("electrical_valley_sd", 0.0), valley=valley)


def _predict(ext: Extension | None, theta: np.ndarray, ctx: Context) -> Prediction:
    return baseline(ctx) if ext is None else ext.apply(theta, ctx)


def _residual(ext, theta, ctx, la, lg, lkt, blocks_fn, vs: float = 0.0, valley: dict | None = None,
              steps: bool = False) -> np.ndarray:
    c = with_mechanics(ctx, la, lg, lkt, steps=steps, valley_sd=vs, valley=valley)
    bl = blocks_fn(_predict(ext, theta, c), c)
    return np.concatenate([bl[k][0] for k in NUISANCE_BLOCKS + (STEP_BLOCKS if steps else ()) if k in bl])


def refit(ext: Extension | None, ctx_fit: Context, ctx_held: Context, blocks_fn, starts: list[np.ndarray],
          valley: dict | None = None, steps: bool = False, near: Refit | None = None) -> Refit:
    """Fit the extension (``None``: the baseline alone) with the mechanics free on the fitted half and the
    electrical values free along ``valley`` (``Seed000Fit.staged_valley``; none: held), then the held-out half's
    K_t bar; both contexts rebuilt with the result (steps included). With ``steps`` the fitted half's step records
    join the sines in the fit: their edges tell R, and so the valley, better than the spectra do. ``near``: a refit
    of the same parameters to start from (the sine-only one: the steps move it little, and each evaluation costs
    twice as much with them)."""
    p_fit = sorted({s.pressure_kPa for s in ctx_fit.sines if s.pressure_kPa is not None})
    p_held = sorted({s.pressure_kPa for s in ctx_held.sines if s.pressure_kPa is not None} - set(p_fit))
    k = 0 if ext is None else len(ext.params)
    nv = 1 if valley else 0  # the coordinate along the valley, where there is one
    lo = np.r_[(ext.lo if ext else ()), -LOG_BOUND_GLOBAL, -LOG_BOUND_GLOBAL, [-VALLEY_BOUND] * nv, [-LOG_BOUND_KT] * len(p_fit)]
    hi = np.r_[(ext.hi if ext else ()), LOG_BOUND_GLOBAL, LOG_BOUND_GLOBAL, [VALLEY_BOUND] * nv, [LOG_BOUND_KT] * len(p_fit)]

    def res(x: np.ndarray) -> np.ndarray:
        vs = x[k + 2 : k + 2 + nv]  # the electrical stage's own estimate, one standard error a unit: a prior residual
        fit = _residual(ext, x[:k], ctx_fit, x[k], x[k + 1], dict(zip(p_fit, x[k + 2 + nv :])), blocks_fn,
                        float(vs[0]) if nv else 0.0, valley, steps)
        return np.r_[fit, vs]

    best, cost = None, np.inf
    for th0 in starts or [np.zeros(0)]:
        x0 = np.r_[th0, 0.0, 0.0, [0.0] * nv, [0.0] * len(p_fit)] if near is None else \
            np.r_[th0, near.log_alpha, near.log_gamma, [near.valley_sd] * nv, [near.log_kt.get(p, 0.0) for p in p_fit]]
        x0 = np.clip(x0, lo, hi)
        try:
            r = least_squares(res, x0, bounds=(lo, hi), x_scale="jac", max_nfev=50, ftol=FIT_TOL, xtol=FIT_TOL)
        except (ValueError, FloatingPointError, OverflowError):
            continue
        if np.isfinite(r.cost) and r.cost < cost:
            best, cost = r.x, r.cost
    if best is None:
        best = np.r_[starts[0] if starts else np.zeros(0), 0.0, 0.0, [0.0] * nv, [0.0] * len(p_fit)]
    theta, la, lg, vs = best[:k], float(best[k]), float(best[k + 1]), float(best[k + 2]) if nv else 0.0
    lkt = dict(zip(p_fit, map(float, best[k + 2 + nv :])))
    if p_held:
        def res_h(x: np.ndarray) -> np.ndarray:
            return _residual(ext, theta, ctx_held, la, lg, {**lkt, **dict(zip(p_held, x))}, blocks_fn, vs, valley)

        rh = least_squares(res_h, np.zeros(len(p_held)), bounds=(-LOG_BOUND_KT, LOG_BOUND_KT), x_scale="jac", max_nfev=40, ftol=FIT_TOL, xtol=FIT_TOL)
        lkt.update(zip(p_held, map(float, rh.x)))
    same = ctx_held is ctx_fit
    cf = with_mechanics(ctx_fit, la, lg, lkt, valley_sd=vs, valley=valley)
    ch = cf if same else with_mechanics(ctx_held, la, lg, lkt, valley_sd=vs, valley=valley)
    return Refit(theta, la, lg, lkt, cf, ch, vs)
