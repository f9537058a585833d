"""Seed 001's Hammerstein grey box: nonlinear electric stage V_in -> I_abs, linear stage I_abs -> delta.

Pure numpy/scipy, no I/O, no state. Seed 001 (Caponetto et al.) Fig. 2/3; its text stops at 3.1, the
laws below are the ones DESIGN.md 4 asks for (docs/hammerstein.md has the derivations).

Electric stage, state v = v_c (double-layer voltage), input V = V_in, output i = I_abs:

    i = (V - v) / R_s,        C_dl m(v) dv/dt = i - i_nl(v)

with a law from :data:`LAWS` (``m`` = C(v)/C_dl, 1 unless the law says otherwise). Mechanical stage:

    delta(s) = K/(s + eps) * wn^2/(s^2 + 2 zeta wn s + wn^2) * I(s)     (DC gain K/eps, m/A)

Time stepping (vectorised over the population, rows = candidates x records): split
dv/dt = -lam v + b V + G(v, V) with lam = (1/R_s + g1)/C_dl, b = 1/(R_s C_dl) and the law's remainder G.
The linear part is integrated exactly (exponential integrator, input linear between samples); G by
the second-order Adams-Bashforth form of ETD2 (Cox & Matthews 2002), one G evaluation per step. The
stiff linear part therefore never limits the step; the explicit G does only for extreme candidates.
|v_c| <= max|V| holds for the true solution (the branch is passive), so v is clipped there: this only
removes error and keeps blown-up candidates finite (they simply score badly).
The mechanical stage is the bilinear transform prewarped at wn (exact DC gain and resonance), lfilter.
CPE instead of C_dl is not offered: a fractional derivative needs the whole history per step
(Grunwald-Letnikov, O(N^2)) or an RC-ladder with extra states; the fractional mechanical variant neither.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy import integrate, signal

from labrig.physics.params import HammersteinParams

ELECTRIC_BASE = ("R_s", "C_dl", "g1")
MECH_NAMES = ("K", "eps", "wn", "zeta")

Cols = dict[str, np.ndarray]  # parameter name -> per-row values
MAX_ROWS = 1024  # rows (candidates x records) stepped together; measured sweet spot on 2 cores


@dataclass(frozen=True)
class Law:
    """One nonlinear electric law: its extra parameters, the equations, and the stepper's remainder G."""

    name: str
    extra: tuple[str, ...]
    equation: str
    i_nl: Callable[[np.ndarray, Cols], np.ndarray]  # branch current at v (A), includes g1 v
    cap: Callable[[np.ndarray, Cols], np.ndarray]  # C(v)/C_dl
    # G(v, bV, lam, c): dv/dt - (-lam v + b V); bV = b*V at this sample (only varcap needs it)
    remainder: Callable[[np.ndarray, np.ndarray, np.ndarray, Cols], np.ndarray]
    needs_bV: bool = False


def _one(v: np.ndarray, c: Cols) -> np.ndarray:
    return np.ones_like(v)


def _poly_i(v, c):
    return c["g1"] * v + c["g3"] * v**3


def _poly_G(v, bV, lam, c):
    return c["k3"] * (v * v * v)  # k3 = -g3/C_dl, precomputed


def _bv_i(v, c):
    return c["g1"] * v + 2.0 * c["i0"] * np.sinh(v / (2.0 * c["v_t"]))


def _bv_G(v, bV, lam, c):
    return c["kb"] * np.sinh(c["ab"] * v)  # kb = -2 i0/C_dl, ab = 1/(2 v_t)


def _varcap_i(v, c):
    return c["g1"] * v


def _varcap_cap(v, c):
    return 1.0 + c["c2"] * v * v


def _varcap_G(v, bV, lam, c):
    # (bV - lam v)/m(v) - (bV - lam v) = -(bV - lam v) c2 v^2 / (1 + c2 v^2)
    w = c["c2"] * (v * v)
    return (lam * v - bV) * (w / (1.0 + w))


LAWS: dict[str, Law] = {
    "poly": Law("poly", ("g3",), "i_nl = g1 v + g3 v^3 (odd polynomial)", _poly_i, _one, _poly_G),
    "butler_volmer": Law(
        "butler_volmer",
        ("i0", "v_t"),
        "i_nl = g1 v + 2 i0 sinh(v / (2 v_t))  (symmetric Butler-Volmer, alpha = 1/2, v_t = n R T / F effective)",
        _bv_i,
        _one,
        _bv_G,
    ),
    "varcap": Law("varcap", ("c2",), "i_nl = g1 v,  C(v) = C_dl (1 + c2 v^2)", _varcap_i, _varcap_cap, _varcap_G, True),
}


def electric_names(law: str) -> tuple[str, ...]:
    return ELECTRIC_BASE + LAWS[law].extra


def param_names(law: str) -> tuple[str, ...]:
    """Column order of theta in :func:`simulate_batch`: electric parameters, then mechanical."""
    return electric_names(law) + MECH_NAMES


def _phis(z: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """exp(z), phi1 = (e^z - 1)/z, phi2 = (e^z - 1 - z)/z^2, with series where they cancel (z -> 0)."""
    small = np.abs(z) < 1e-3
    zs = np.where(small, 1.0, z)
    phi1 = np.where(small, 1.0 + z / 2 + z * z / 6 + z**3 / 24, np.expm1(zs) / zs)
    phi2 = np.where(small, 0.5 + z / 6 + z * z / 24 + z**3 / 120, (np.expm1(zs) - zs) / (zs * zs))
    return np.exp(z), phi1, phi2


def _law_consts(law: str, c: Cols) -> Cols:
    c = dict(c)
    if law == "poly":
        c["k3"] = -c["g3"] / c["C_dl"]
    elif law == "butler_volmer":
        c["kb"] = -2.0 * c["i0"] / c["C_dl"]
        c["ab"] = 1.0 / (2.0 * c["v_t"])
    return c


def electric_batch(theta_e: np.ndarray, v: np.ndarray, fs: float, law: str) -> np.ndarray:
    """Absorbed current for P electric parameter sets (columns :func:`electric_names`) and R records.

    ``v`` is (N,) or (R, N) (records of equal length and rate, e.g. padded at the end); returns
    (P, N) or (P, R, N). All P*R rows advance together: one numpy op per row block per time step.
    """
    theta_e = np.atleast_2d(np.asarray(theta_e, float))
    V = np.atleast_2d(np.asarray(v, float))
    P, (R, N) = theta_e.shape[0], V.shape
    block = max(1, MAX_ROWS // R)
    if P > block:  # bounded blocks: past ~1000 rows the (N, rows) arrays fall out of cache (docs)
        return np.concatenate([electric_batch(theta_e[s:s + block], v, fs, law) for s in range(0, P, block)])
    names = electric_names(law)
    c = {n: np.repeat(theta_e[:, j], R) for j, n in enumerate(names)}  # rows: candidate-major
    lam = (1.0 / c["R_s"] + c["g1"]) / c["C_dl"]
    b = 1.0 / (c["R_s"] * c["C_dl"])
    h = 1.0 / fs
    E, phi1, phi2 = _phis(-lam * h)
    A1, A2 = h * (phi1 + phi2), h * phi2  # ETD2: h[(phi1+phi2) G_k - phi2 G_{k-1}]
    Vt = np.tile(V, (P, 1)).T  # (N, M), time-major so each step reads a contiguous row
    U = np.diff(Vt, axis=0, append=Vt[-1:])  # U = h b (phi1 V_k + phi2 dV_k): exact for V linear in a step
    U *= phi2
    U += phi1 * Vt
    U *= h * b
    bVt = b * Vt if LAWS[law].needs_bV else Vt
    G_fn = LAWS[law].remainder
    c = _law_consts(law, c)
    vmax = float(np.max(np.abs(V))) if V.size else 0.0
    out = np.zeros_like(Vt)  # out[0] = 0: from rest, and G(0, .) = 0 for every law
    G_prev, tmp = np.zeros(Vt.shape[1]), np.empty(Vt.shape[1])
    mul, lo, hi = np.multiply, np.maximum, np.minimum
    with np.errstate(over="ignore", invalid="ignore"):
        for k in range(N - 1):  # in-place ops: the per-op call overhead is the cost here, not the flops
            x, y = out[k], out[k + 1]
            G = G_fn(x, bVt[k], lam, c)
            mul(E, x, out=y)
            y += U[k]
            y += mul(A1, G, out=tmp)
            y -= mul(A2, G_prev, out=tmp)
            hi(y, vmax, out=y)
            lo(y, -vmax, out=y)
            G_prev = G
    i = (Vt - out) / c["R_s"]
    i = i.T.reshape(P, R, N)
    return i[:, 0, :] if np.ndim(v) == 1 else i


def mech_tf(K: float, eps: float, wn: float, zeta: float) -> tuple[np.ndarray, np.ndarray]:
    """Continuous delta/I_abs = K wn^2 / ((s + eps)(s^2 + 2 zeta wn s + wn^2)) as (num, den)."""
    return np.array([K * wn**2]), np.polymul([1.0, eps], [1.0, 2 * zeta * wn, wn**2])


PREWARP_MAX = 0.9  # of Nyquist (pi fs rad/s): the highest frequency the mode's bilinear map is prewarped at


def mech_discrete(theta_m: np.ndarray, fs: float) -> np.ndarray:
    """Bilinear (Tustin) sections prewarped at wn for P candidates: sos (P, 2, 6) for scipy's sosfilt.

    Two sections (integrator, mode), each in closed form: a single third-order polynomial with a pole
    at 1 - eps/fs loses ~1e-9 of accuracy to round-off in its coefficients.

    The prewarp frequency is wn held below ``PREWARP_MAX`` of Nyquist: prewarped at a mode above Nyquist, tan(wn /
    2 fs) folds negative, c < 0 maps the left half-plane outside the unit circle and the filter diverges (an NSGA-II
    quick fit at 125 Hz returned wn = 1114 rad/s, stable there by the fold; at 250 Hz its step grew to 1e65 mm).
    Any c > 0 keeps the map stable; below the cap the prewarp is exact at wn.
    """
    K, eps, wn, zeta = np.atleast_2d(np.asarray(theta_m, float)).T
    wp = np.minimum(wn, PREWARP_MAX * np.pi * fs)
    c = wp / np.tan(wp / (2.0 * fs))  # s = c (1 - q)/(1 + q), q = z^-1
    sos = np.zeros((len(K), 2, 6))
    # K/(s + eps) -> K (1 + q) / ((c + eps) + (eps - c) q)
    sos[:, 0, 0] = sos[:, 0, 1] = K / (c + eps)
    sos[:, 0, 3], sos[:, 0, 4] = 1.0, (eps - c) / (c + eps)
    # wn^2/(s^2 + 2 zeta wn s + wn^2) -> wn^2 (1 + q)^2 / (a0 + a1 q + a2 q^2)
    a0, a1, a2 = c * c + 2 * zeta * wn * c + wn**2, 2 * (wn**2 - c * c), c * c - 2 * zeta * wn * c + wn**2
    g = wn**2 / a0
    sos[:, 1, 0], sos[:, 1, 1], sos[:, 1, 2] = g, 2 * g, g
    sos[:, 1, 3], sos[:, 1, 4], sos[:, 1, 5] = 1.0, a1 / a0, a2 / a0
    return sos


def mechanical_batch(theta_m: np.ndarray, i: np.ndarray, fs: float) -> np.ndarray:
    """Tip displacement for P mechanical parameter sets (columns :data:`MECH_NAMES`); i is (P, ..., N)."""
    sos = mech_discrete(theta_m, fs)
    i = np.asarray(i, float)
    # one C-level filter per candidate (coefficients differ); the loop is over P, not over samples
    return np.stack([signal.sosfilt(sos[p], i[p], axis=-1) for p in range(len(sos))])


def simulate_batch(theta: np.ndarray, v: np.ndarray, fs: float, law: str) -> tuple[np.ndarray, np.ndarray]:
    """(i, delta) for a population theta (P, len(param_names(law))); v (N,) -> (P, N), v (R, N) -> (P, R, N)."""
    theta = np.atleast_2d(np.asarray(theta, float))
    ne = len(electric_names(law))
    i = electric_batch(theta[:, :ne], v, fs, law)
    return i, mechanical_batch(theta[:, ne:], i, fs)


def simulate(params: HammersteinParams, v: np.ndarray, fs: float) -> tuple[np.ndarray, np.ndarray]:
    """(i, delta) of one parameter set for the drive v (N,) sampled at fs, starting from rest."""
    i, d = simulate_batch(params.vector(param_names(params.law))[None], v, fs, params.law)
    return i[0], d[0]


def electric_rhs(params: HammersteinParams, V: Callable[[float], float]) -> Callable:
    """dv/dt of the electric stage written straight from the law's i_nl and C(v) (for solve_ivp)."""
    law = LAWS[params.law]
    c = {n: np.asarray(getattr(params, n)) for n in electric_names(params.law)}

    def rhs(t, y):
        x = y[0]
        return [((V(t) - x) / params.R_s - law.i_nl(x, c)) / (params.C_dl * law.cap(x, c))]

    return rhs


def simulate_reference(params: HammersteinParams, v: np.ndarray, fs: float, rtol: float = 1e-10,
                       method: str = "DOP853") -> tuple[np.ndarray, np.ndarray]:
    """Slow reference: solve_ivp on the electric ODE (V linear between samples), lsim for delta.

    DOP853 suits plausible parameters (tau = R_s C_dl >> 1/fs); pass method="Radau" for stiff ones.
    """
    t = np.arange(len(v)) / fs
    sol = integrate.solve_ivp(
        electric_rhs(params, lambda s: np.interp(s, t, v)), (0, t[-1]), [0.0], method=method,
        t_eval=t, rtol=rtol, atol=1e-12, max_step=1.0 / fs,  # max_step: do not stride over input samples
    )
    i = (v - sol.y[0]) / params.R_s
    num, den = mech_tf(params.K, params.eps, params.wn, params.zeta)
    _, d, _ = signal.lsim((num, den), i, t)
    return i, d


def static_current(params: HammersteinParams, V: np.ndarray, iters: int = 80) -> np.ndarray:
    """The electric stage's static (DC) I-V law: the steady current once the double layer has charged.

    At DC dv/dt = 0, so i = (V - v)/R_s = i_nl(v): solve V = v + R_s i_nl(v) for v (bisection on
    [-|V|, |V|]; the left side is increasing in v for every law with g1, g3, i0 >= 0) and return i_nl(v).
    This is the curve seed 001's Fig. 1 measures ("experimental nonlinearity trend"); C(v) plays no part.
    """
    V = np.asarray(V, float)
    law = LAWS[params.law]
    c = {n: np.asarray(getattr(params, n)) for n in electric_names(params.law)}
    lo, hi = -np.abs(V), np.abs(V)
    for _ in range(iters):
        mid = 0.5 * (lo + hi)
        above = mid + params.R_s * law.i_nl(mid, c) > V
        hi, lo = np.where(above, mid, hi), np.where(above, lo, mid)
    return law.i_nl(0.5 * (lo + hi), c)
