"""Seed 000's fit as a least-squares problem: which parameters, on what scale, which are fixed, and the
residuals in units of their noise (docs/model.md section 9).

Parametrisation (named lmfit parameters; ``_<tag>`` marks a per-pressure one):

* free line, shared across pressures: ``log_R``, ``log_R_p``, ``log_Q0``, ``n`` (eq. 2-4, 9-10);
  R_s stays at the preset's four-probe value.
* clamp area, per pressure (Table 1, eq. 5): ``R_cont`` in ohm on a linear scale (what the data see is
  Z1 = 2(R_cont + R_sc L_c), linear in it), ``log_R_c``, ``log_Q0c``, ``n_c``. R_sc and R_pc are fixed at
  the paper's clamp law (physics/clamp.py) at that pressure: the spectrum only tells the total leak
  L/R_p + L_c/R_pc, of which the clamp carries about 12 %, so R_pc on its own would wander to a bound.
* mechanics: ``gamma`` and ``log_alpha`` shared, ``log_kt`` per pressure (eq. 23-33, Table 2-3).

Residuals: impedance as (Z_model - Z)/|Z| over the analyser's relative noise (real and imaginary parts);
displacement FRF as the complex log of H_model/H over each point's relative standard deviation with the
FRF's error beyond it (excess_error, at least FRF_EXCESS_MIN) added in quadrature; the DAQ's current
admittance (electrical stage only) as (Y_model - Y)/|Y| over its relative noise with CUR_FLOOR in quadrature.
The Jacobian is a forward difference that re-evaluates only the blocks a parameter touches.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import lmfit
import numpy as np
from scipy.optimize import brentq

from labrig.estimate.session_data import PressureData
from labrig.physics import impedance as imp
from labrig.physics import transfer
from labrig.physics.params import Specimen

MAX_NFEV_PER_PARAM = 40  # bounds a fit that does not converge; converging ones use far fewer (minimize)

LINE_NAMES = {"R": "log_R", "R_p": "log_R_p", "Q0": "log_Q0", "n": "n"}
CLAMP_FREE = ("r_cont", "R_c", "Q0c", "n_c")
CLAMP_FIXED = ("R_sc", "R_pc")  # at the paper's clamp law: not told by the data (docs/model.md 9)
# The stepped-sine FRF differs from the bench's exact H(j omega) by 2e-4 in magnitude and 3e-4 rad in phase
# below 1 Hz, the same sign at every point (the CPE's slow start-up transient): a correlated error that no
# per-point weight can average away. The FRF's error beyond its scatter is therefore never taken below
# 5e-4 (docs/model.md 9: with 1e-4 gamma and the CPE index come out 2-3 sigma off in every seed).
FRF_EXCESS_MIN = 5e-4
# The DAQ current's stepped-sine estimates scatter by ~8e-5 of |Y|; their bias against the exact admittance is
# of the FRF's order (CPE start-up), so each point's relative error is never taken below this
CUR_FLOOR = 5e-4
EIS_SIGMA_FLOOR = 1e-4  # a noise-free (modelled) spectrum must not give infinite weights


def tag(p: float) -> str:
    return f"p{p:g}".replace(".", "_")


def clamp_name(key: str, p: float) -> str:
    return f"R_cont_{tag(p)}" if key == "r_cont" else (f"n_c_{tag(p)}" if key == "n_c" else f"log_{key}_{tag(p)}")


def shifted(sp: Specimen, p: float, step: dict[str, float], s: float) -> Specimen:
    """The strip at pressure p with its electrical values moved by ``s`` x ``step`` (per parameter name, on the fit's
    own scales: log10 values multiply, the exponents n and n_c and R_cont add); names of other pressures ignored."""
    if not s or not step:
        return sp
    line = {}
    for k, n in LINE_NAMES.items():
        if n in step:
            line[k] = getattr(sp.line, k) + s * step[n] if k == "n" else getattr(sp.line, k) * 10 ** (s * step[n])
    clamp = {}
    for k in CLAMP_FREE:
        n = clamp_name(k, p)
        if n in step:
            v = getattr(sp.clamp, k)
            clamp[k] = v + s * step[n] * sp.geometry.clamp_area if k == "r_cont" else (v + s * step[n] if k == "n_c" else v * 10 ** (s * step[n]))
    return sp.with_(line=dataclasses.replace(sp.line, **line), clamp=dataclasses.replace(sp.clamp, **clamp))


def frf_noise(h: np.ndarray, sig: np.ndarray) -> np.ndarray:
    """Relative standard deviation per component (real, imaginary) of each FRF point: the estimators give
    that of the complex value (PressureData.frf_lines), hence the sqrt(2) (NaN sigma: 1 %)."""
    return np.nan_to_num(sig / np.abs(h), nan=0.01 * np.sqrt(2)) / np.sqrt(2)


def excess_error(r: np.ndarray, noise: np.ndarray, dof: int) -> float:
    """The relative error s added in quadrature to each point's noise so that sum r^2/(noise^2 + s^2) = dof:
    what the FRF misses beyond its cycle-to-cycle scatter (estimator bias, model error), told by the data."""
    def excess_chi2(s: float) -> float:
        return float(np.sum(r**2 / (noise**2 + s**2))) - dof
    if dof <= 0 or excess_chi2(FRF_EXCESS_MIN) <= 0:
        return FRF_EXCESS_MIN
    if excess_chi2(1.0) > 0:  # misfit beyond 100 %: an effect the model lacks (the diagnosis will say which)
        return 1.0
    return float(brentq(excess_chi2, FRF_EXCESS_MIN, 1.0))


@dataclass
class Problem:
    """The data of one fit stage and the priors (the paper's values at each pressure) it starts from."""

    priors: dict[float, Specimen]  # preset / clamp law per pressure: start values and fixed values
    eis: list[PressureData] = field(default_factory=list)
    frf: list[PressureData] = field(default_factory=list)
    cur: list[PressureData] = field(default_factory=list)  # the DAQ's current admittance (PressureData.current_lines)
    sigma_eis: float = 1.0  # analyser's relative noise per component (real, imaginary)
    frf_excess: float = FRF_EXCESS_MIN  # relative FRF error beyond the points' own noise (excess_error)

    def __post_init__(self) -> None:
        self._eis_data = {d.pressure_kPa: d.eis for d in self.eis}
        self._frf_data = {d.pressure_kPa: d.frf_lines() for d in self.frf}  # stepped sines and multisine BLA
        self._noise = {p: np.tile(frf_noise(h, sig), 2) for p, (f, h, _, sig) in self._frf_data.items()}
        self._cur_data = {d.pressure_kPa: d.current_lines() for d in self.cur}
        # current blocks last: callers index the spectra and FRF blocks from the start
        self.blocks = [("eis", d.pressure_kPa) for d in self.eis] + [("frf", d.pressure_kPa) for d in self.frf] + [("cur", d.pressure_kPa) for d in self.cur]
        size = {"eis": lambda p: self._eis_data[p][0].size, "frf": lambda p: self._frf_data[p][0].size, "cur": lambda p: self._cur_data[p][0].size}
        sizes = [2 * size[k](p) for k, p in self.blocks]
        self.offsets = np.concatenate([[0], np.cumsum(sizes)]).astype(int)

    # ---------------------------------------------------------------------------------- model
    def specimen(self, v: dict[str, float], p: float) -> Specimen:
        """The strip at pressure p for parameter values v (names absent from v keep the prior's value)."""
        sp = self.priors[p]
        t = tag(p)
        line = {k: (v[n] if k == "n" else 10 ** v[n]) for k, n in LINE_NAMES.items() if n in v}
        clamp = {}
        for k in CLAMP_FREE:
            n = clamp_name(k, p)
            if n in v:
                clamp[k] = v[n] * sp.geometry.clamp_area if k == "r_cont" else (v[n] if k == "n_c" else 10 ** v[n])
        mech = {k: val for k, val in (("gamma", v.get("gamma")), ("alpha", 10 ** v["log_alpha"] if "log_alpha" in v else None)) if val is not None}
        kt = 10 ** v[f"log_kt_{t}"] if f"log_kt_{t}" in v else sp.Kt_bar
        return sp.with_(
            line=dataclasses.replace(sp.line, **line),
            clamp=dataclasses.replace(sp.clamp, **clamp),
            mechanics=dataclasses.replace(sp.mechanics, **mech),
            Kt_bar=kt,
        )

    def _frf_log_error(self, p: float, v: dict[str, float]) -> np.ndarray:
        """log(H_model / H) at pressure p, real parts then imaginary (relative gain error, phase error)."""
        f, h, _, _ = self._frf_data[p]
        r = np.log(transfer.frf(f, self.specimen(v, p)) / h)
        return np.concatenate([r.real, r.imag])

    def block(self, kind: str, p: float, v: dict[str, float]) -> np.ndarray:
        """One pressure's impedance or FRF residuals, in units of their noise."""
        if kind == "frf":
            return self._frf_log_error(p, v) / np.sqrt(self._noise[p] ** 2 + self.frf_excess**2)
        if kind == "cur":
            f, h, sig = self._cur_data[p]
            r = (transfer.admittance_tf(2j * np.pi * f, self.specimen(v, p)) - h) / np.abs(h)
            r /= np.hypot(np.nan_to_num(sig / np.abs(h), nan=0.01) / np.sqrt(2), CUR_FLOOR)
            return np.concatenate([r.real, r.imag])
        f, z = self._eis_data[p]
        r = (imp.impedance(2j * np.pi * f, self.specimen(v, p)) - z) / np.abs(z) / self.sigma_eis
        return np.concatenate([r.real, r.imag])

    def frf_excess_from(self, params: lmfit.Parameters, n_told: int) -> float:
        """excess_error of the FRF blocks at ``params``; ``n_told`` parameters were told by them."""
        v = params.valuesdict()
        r = np.concatenate([self._frf_log_error(p, v) for p in self._frf_data])
        return excess_error(r, np.concatenate(list(self._noise.values())), r.size - n_told)

    def residual(self, params: lmfit.Parameters) -> np.ndarray:
        v = params.valuesdict()
        return np.concatenate([self.block(k, p, v) for k, p in self.blocks])

    # ---------------------------------------------------------------------------------- Jacobian
    def _touches(self, name: str, kind: str, p: float) -> bool:
        """Does parameter ``name`` enter block (kind, p)? Per-pressure names only their own pressure's
        blocks; the mechanics only the FRF."""
        mech = name in ("gamma", "log_alpha") or name.startswith("log_kt_")
        if mech and kind in ("eis", "cur"):
            return False
        per_p = name.startswith(("log_kt_", "R_cont_", "log_R_c_", "log_Q0c_", "n_c_"))
        return not per_p or name.endswith("_" + tag(p))

    def jacobian(self, params: lmfit.Parameters) -> np.ndarray:
        """Forward differences, re-evaluating only the blocks each varied parameter touches."""
        v = params.valuesdict()
        names = [n for n, p in params.items() if p.vary]
        base = [self.block(k, p, v) for k, p in self.blocks]
        jac = np.zeros((self.offsets[-1], len(names)))
        for j, name in enumerate(names):
            h = 1e-7 * max(1.0, abs(v[name]))
            hi = params[name].max
            if np.isfinite(hi) and v[name] + h > hi:
                h = -h  # step inward at an upper bound
            vj = {**v, name: v[name] + h}
            for b, (k, p) in enumerate(self.blocks):
                if self._touches(name, k, p):
                    jac[self.offsets[b] : self.offsets[b + 1], j] = (self.block(k, p, vj) - base[b]) / h
        return jac

    def minimize(self, params: lmfit.Parameters) -> lmfit.minimizer.MinimizerResult:
        """Trust-region least squares. Residuals are already in units of noise: the covariance is
        inflated by the reduced chi-square when the fit is worse than the noise, never shrunk.

        At most ``MAX_NFEV_PER_PARAM`` evaluations per varied parameter: clean sessions converge in <= 36 in all,
        sessions with a catalogue effect in <= 750; on an imported sweep the model cannot take (a drying front,
        steps and sines only) the trust region crept on for 6109 evaluations with their Jacobians (116 s). The
        misfit is the diagnosis' to describe, not the fit's to chase."""
        nvary = sum(p.vary for p in params.values())
        res = lmfit.minimize(
            lambda ps: self.residual(ps), params, method="least_squares", scale_covar=False,
            jac=lambda ps: self.jacobian(ps), x_scale="jac", max_nfev=MAX_NFEV_PER_PARAM * (nvary + 1),
        )
        inflate = float(np.sqrt(max(res.redchi, 1.0)))
        for p in res.params.values():
            if p.vary and p.stderr is not None:
                p.stderr *= inflate
        return res


# ------------------------------------------------------------------------------------- parameters


def add_line(pars: lmfit.Parameters, sp: Specimen, vary: bool = True) -> None:
    for k, n in LINE_NAMES.items():
        val = getattr(sp.line, k)
        if k == "n":
            pars.add(n, val, min=0.3, max=1.0, vary=vary)
        else:
            pars.add(n, np.log10(val), min=np.log10(val) - 3, max=np.log10(val) + 3, vary=vary)


def add_clamp(pars: lmfit.Parameters, p: float, start: Specimen, vary_r_cont: bool) -> None:
    """Per-pressure clamp parameters starting at ``start``'s clamp; R_cont free only when told."""
    c, area = start.clamp, start.geometry.clamp_area
    pars.add(clamp_name("r_cont", p), c.r_cont / area, min=0.0, max=50.0, vary=vary_r_cont)
    for k in ("R_c", "Q0c"):
        val = np.log10(getattr(c, k))
        pars.add(clamp_name(k, p), val, min=val - 3, max=val + 3)
    pars.add(clamp_name("n_c", p), c.n_c, min=0.3, max=1.0)


def add_mechanics(pars: lmfit.Parameters, gamma: float, alpha: float, kts: dict[float, float]) -> None:
    pars.add("gamma", gamma, min=0.0, max=1.0)
    pars.add("log_alpha", np.log10(alpha), min=-4, max=2)
    for p, kt in kts.items():
        pars.add(f"log_kt_{tag(p)}", np.log10(kt), min=-1, max=2.5)


def merged(*sources: lmfit.Parameters) -> lmfit.Parameters:
    """One parameter set from several stages' results: values, bounds and vary flags kept."""
    pars = lmfit.Parameters()
    for src in sources:
        for name, p in src.items():
            pars.add(name, p.value, min=p.min, max=p.max, vary=p.vary)
    return pars
