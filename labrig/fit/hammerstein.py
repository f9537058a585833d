"""Identification of seed 001's Hammerstein model: Nelder-Mead, GA (single objective), NSGA-II (two objectives).

Seed 001 (Caponetto et al., sections 3-5) identifies the stages sequentially: the electric stage on the
current error, then the electromechanical stage on the displacement error with the electric stage
fixed; and, multi-objective, all parameters at once on (current error, displacement error).
Errors are normalised RMS errors, rms(sim - meas)/rms(meas) per record, averaged over records.

Search space: every parameter lives in the box HammersteinParams.BOUNDS, mapped to z in [0, 1] (log
scale for "log" bounds, so relative steps are uniform); GA / NSGA-II search z directly; Nelder-Mead
searches u = logit(z), which is unbounded. Populations are evaluated as one batch through
labrig.physics.hammerstein.simulate_batch and chunked over an executor (labrig.fit.executors).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any, Literal

import numpy as np
from scipy import optimize, signal
from scipy.special import expit, logit

from labrig.fit.executors import PopulationMap
from labrig.physics import hammerstein as hm
from labrig.physics.params import HammersteinParams

BAD = 1e3  # objective of a candidate whose simulation is not finite
Stage = Literal["electric", "mechanical", "joint"]


@dataclass(frozen=True)
class Record:
    """One measured record of seed 001's bench: drive V_in, absorbed current I_abs, tip displacement."""

    fs: float
    v: np.ndarray
    i: np.ndarray
    delta: np.ndarray


def as_record(r: Any) -> Record:
    if isinstance(r, Record):
        return r
    fs, v, i, d = r
    return Record(float(fs), np.asarray(v, float), np.asarray(i, float), np.asarray(d, float))


def decimate_record(r: Any, q: int) -> Record:
    """Anti-aliased decimation by q (zero-phase FIR), e.g. seed 001's 3 kHz to 1 kHz for fitting."""
    r = as_record(r)
    dec = lambda x: signal.decimate(x, q, ftype="fir", zero_phase=True)  # noqa: E731
    return Record(r.fs / q, dec(r.v), dec(r.i), dec(r.delta))


def synthetic_records(truth: HammersteinParams, fs: float = 250.0, duration: float = 4.0,
                      amplitudes: tuple[float, ...] = (1.0, 2.5), noise: float = 0.002, seed: int = 0,
                      f_slow: float = 0.4, band: tuple[float, float] = (8.0, 40.0)) -> list[Record]:
    """Seed-001-like records from known parameters (tests, benchmark): per amplitude a slow sine (the
    electric nonlinearity and the integrator leak show) and a multisine on ``band`` (2 Hz grid, random
    phases) around the first mode; white noise of ``noise`` times each signal's std is added."""
    rng = np.random.default_rng(seed)
    t = np.arange(int(round(duration * fs))) / fs
    f = np.arange(band[0], band[1] + 1e-9, 2.0)
    ms = np.sin(2 * np.pi * f[:, None] * t + rng.uniform(0, 2 * np.pi, (len(f), 1))).sum(axis=0)
    drives = [a * w for a in amplitudes for w in (np.sin(2 * np.pi * f_slow * t), ms / np.abs(ms).max())]
    out = []
    for v in drives:
        i, d = hm.simulate(truth, v, fs)
        out.append(Record(fs, v, i + noise * i.std() * rng.standard_normal(i.shape),
                          d + noise * d.std() * rng.standard_normal(d.shape)))
    return out


@dataclass(frozen=True)
class Group:
    """Records sharing one rate, stacked (R, N) and zero-padded at the end (the model is causal)."""

    fs: float
    v: np.ndarray
    i: np.ndarray
    delta: np.ndarray
    n: np.ndarray  # valid length of each record
    skip: int  # samples left out of the error at the start (initial state unknown in real data)


def pack(records: list, skip_s: float = 0.0) -> tuple[Group, ...]:
    recs = [as_record(r) for r in records]
    groups = []
    for fs in sorted({r.fs for r in recs}):
        rs = [r for r in recs if r.fs == fs]
        N = max(len(r.v) for r in rs)
        pad = lambda x: np.pad(x, (0, N - len(x)))  # noqa: E731
        groups.append(Group(fs, *(np.stack([pad(getattr(r, a)) for r in rs]) for a in ("v", "i", "delta")),
                            np.array([len(r.v) for r in rs]), int(round(skip_s * fs))))
    return tuple(groups)


@dataclass(frozen=True)
class Spec:
    """Everything a worker needs to score candidates (plain, picklable): see :func:`evaluate_chunk`."""

    law: str
    groups: tuple[Group, ...]
    free: tuple[str, ...]  # columns of the candidate matrix (physical values)
    base: np.ndarray  # full vector over hm.param_names(law): the fixed values
    objectives: tuple[str, ...]  # subset of ("current", "displacement")
    i_fixed: tuple[np.ndarray, ...] | None = None  # mechanical stage: the fixed electric stage's current


def _full_theta(X: np.ndarray, spec: Spec) -> np.ndarray:
    names = hm.param_names(spec.law)
    theta = np.tile(spec.base, (len(X), 1))
    for j, n in enumerate(spec.free):
        theta[:, names.index(n)] = X[:, j]
    return theta


def _simulate(X: np.ndarray, spec: Spec, g: int) -> tuple[np.ndarray | None, np.ndarray | None]:
    """(i, delta), each (P, R, N), of candidates X on group g; only what the objectives need."""
    grp, law = spec.groups[g], spec.law
    theta = _full_theta(X, spec)
    ne = len(hm.electric_names(law))
    if spec.i_fixed is not None:  # electric stage fixed: the mechanical stage only filters its current
        i = np.broadcast_to(spec.i_fixed[g], (len(X),) + grp.v.shape)
    else:
        i = hm.electric_batch(theta[:, :ne], grp.v, grp.fs, law)
    d = hm.mechanical_batch(theta[:, ne:], i, grp.fs) if "displacement" in spec.objectives else None
    return i, d


def _residual_rows(sim: np.ndarray, meas: np.ndarray, grp: Group) -> list[np.ndarray]:
    """Per record (sim - meas)/rms(meas) over the valid samples, each (P, n_r)."""
    out = []
    for r, n in enumerate(grp.n):
        m = meas[r, grp.skip:n]
        out.append((sim[:, r, grp.skip:n] - m) / max(np.sqrt(np.mean(m * m)), 1e-300))
    return out


def evaluate_chunk(X: np.ndarray, spec: Spec) -> np.ndarray:
    """Objectives (P, len(spec.objectives)) of candidates X (P, len(spec.free)): mean NRMSE over records.

    Module level with plain arguments: this is what an executor ships to its workers.
    """
    X = np.atleast_2d(X)
    F = {k: [] for k in spec.objectives}
    with np.errstate(all="ignore"):
        for g, grp in enumerate(spec.groups):
            i, d = _simulate(X, spec, g)
            for key, sim, meas in (("current", i, grp.i), ("displacement", d, grp.delta)):
                if key in F:
                    F[key] += [np.sqrt(np.mean(e * e, axis=1)) for e in _residual_rows(sim, meas, grp)]
    out = np.stack([np.mean(F[k], axis=0) for k in spec.objectives], axis=1)
    return np.where(np.isfinite(out), out, BAD)


def residuals(X: np.ndarray, spec: Spec) -> np.ndarray:
    """Concatenated normalised residuals (P, m) of the first objective (for the Jacobian)."""
    key = spec.objectives[0]
    rows = []
    for g, grp in enumerate(spec.groups):
        i, d = _simulate(np.atleast_2d(X), spec, g)
        rows += _residual_rows(i if key == "current" else d, grp.i if key == "current" else grp.delta, grp)
    return np.concatenate(rows, axis=1)


# -- the search box -------------------------------------------------------------------------------
def _box(names: tuple[str, ...]):
    """lo, hi, log flag, and log(hi/lo) (or hi - lo on linear axes): z = (f(x) - f(lo)) / span."""
    b = HammersteinParams.BOUNDS
    lo = np.array([b[n][0] for n in names])
    hi = np.array([b[n][1] for n in names])
    log = np.array([b[n][2] == "log" for n in names])
    span = np.where(log, np.log(hi / np.where(log, lo, 1.0)), hi - lo)
    return lo, hi, log, span


def to_unit(x: np.ndarray, names: tuple[str, ...]) -> np.ndarray:
    """Physical values -> z in [0, 1] (log-scaled where the bound says so)."""
    lo, hi, log, span = _box(names)
    x = np.clip(x, lo, hi)
    return np.where(log, np.log(np.where(log, x / np.where(log, lo, 1.0), 1.0)), x - lo) / span


def from_unit(z: np.ndarray, names: tuple[str, ...]) -> np.ndarray:
    lo, hi, log, span = _box(names)
    z = np.clip(z, 0.0, 1.0)
    return np.where(log, lo * np.exp(z * np.where(log, span, 0.0)), lo + z * span)


def stderr(x: np.ndarray, spec: Spec, rel_step: float = 1e-4) -> np.ndarray:
    """Gauss-Newton standard errors s^2 (J^T J)^-1 at x, J by forward differences in z (one batch)."""
    names = spec.free
    z0 = to_unit(x, names)
    dz = np.full(len(z0), rel_step)
    Z = np.vstack([z0, z0 + np.diag(dz)])
    r = residuals(from_unit(Z, names), spec)
    J = (r[1:] - r[0]).T / dz
    dof = max(r.shape[1] - len(names), 1)
    try:
        cov_z = np.linalg.inv(J.T @ J) * float(r[0] @ r[0]) / dof
    except np.linalg.LinAlgError:
        return np.full(len(names), np.nan)
    _, _, log, span = _box(names)
    dxdz = np.where(log, x * span, span)  # chain rule back to physical units
    return dxdz * np.sqrt(np.maximum(np.diag(cov_z), 0.0))


# -- results --------------------------------------------------------------------------------------
@dataclass
class HammersteinFit:
    """Identified parameters (SI), standard errors (NaN where not computed), objectives and cost."""

    method: str
    law: str
    params: dict[str, float]
    stderr: dict[str, float]
    objectives: dict[str, float]  # {"current": NRMSE of i, "displacement": NRMSE of delta}
    n_evals: int
    wall_time: float
    front_F: np.ndarray | None = None  # NSGA-II: (n_front, 2) objectives of the non-dominated set
    front_X: np.ndarray | None = None  # NSGA-II: (n_front, n_params) parameters, columns front_names
    front_names: tuple[str, ...] = ()
    knee: int | None = None  # index of the chosen point in the front
    stages: dict[str, Any] = field(default_factory=dict)
    resolution: dict[str, float] = field(default_factory=dict)  # how tightly the optimiser pinned each (_resolution)

    def to_params(self) -> HammersteinParams:
        return HammersteinParams(law=self.law).with_vector(tuple(self.params), tuple(self.params.values()))


def knee_point(F: np.ndarray) -> int:
    """Knee rule: scale each objective by its best value on the front (f / min f, so the utopia point is
    (1, 1) and a 1 % rise counts the same in either error) and take the point nearest the utopia.
    Scaling by the front's range instead lets noise-level differences in one error decide (docs)."""
    F = np.asarray(F, float)
    Fn = F / np.maximum(F.min(axis=0), 1e-300) - 1.0
    return int(np.argmin(np.hypot(Fn[:, 0], Fn[:, 1])))


def _spec(groups, law, base: HammersteinParams, stage: Stage, i_fixed=None) -> Spec:
    free = {"electric": hm.electric_names(law), "mechanical": hm.MECH_NAMES, "joint": hm.param_names(law)}[stage]
    objs = {"electric": ("current",), "mechanical": ("displacement",), "joint": ("current", "displacement")}[stage]
    return Spec(law, groups, free, base.vector(hm.param_names(law)), objs, i_fixed)


def _fixed_current(groups, law, p: HammersteinParams) -> tuple[np.ndarray, ...]:
    th = p.vector(hm.electric_names(law))[None]
    return tuple(hm.electric_batch(th, g.v, g.fs, law)[0] for g in groups)


def _finish(method, law, p: HammersteinParams, groups, n_evals, t0, with_stderr=True, **extra) -> HammersteinFit:
    names = hm.param_names(law)
    F = evaluate_chunk(p.vector(names)[None], _spec(groups, law, p, "joint"))[0]
    se = np.full(len(names), np.nan)
    if with_stderr:  # electric on the current, mechanical on the displacement (the sequential split)
        ne = len(hm.electric_names(law))
        se[:ne] = stderr(p.vector(hm.electric_names(law)), _spec(groups, law, p, "electric"))
        sm = _spec(groups, law, p, "mechanical", _fixed_current(groups, law, p))
        se[ne:] = stderr(p.vector(hm.MECH_NAMES), sm)
    return HammersteinFit(method, law, p.as_dict(names), dict(zip(names, map(float, se))),
                          {"current": float(F[0]), "displacement": float(F[1])}, n_evals, time.perf_counter() - t0,
                          **extra)


# -- single-objective, sequential -----------------------------------------------------------------
def _nelder_mead(spec: Spec, x0: np.ndarray, maxfev: int, step: float) -> tuple[np.ndarray, int]:
    z0 = np.clip(to_unit(x0, spec.free), 1e-4, 1 - 1e-4)
    u0 = logit(z0)
    f = lambda u: float(evaluate_chunk(from_unit(expit(u), spec.free)[None], spec)[0, 0])  # noqa: E731
    simplex = np.vstack([u0, u0 + step * np.eye(len(u0))])
    res = optimize.minimize(f, u0, method="Nelder-Mead",
                            options={"maxfev": maxfev, "xatol": 1e-7, "fatol": 1e-10, "initial_simplex": simplex})
    return from_unit(expit(res.x), spec.free), int(res.nfev), _resolution(from_unit(expit(res.final_simplex[0]), spec.free))


def _resolution(X: np.ndarray) -> np.ndarray:
    """How tightly an optimiser pinned its answer: the standard deviation of each parameter over the points it ended
    with (Nelder-Mead's final simplex, the best quarter of a GA's final population, the knee's neighbours on a front)."""
    return np.std(np.atleast_2d(X), axis=0, ddof=1) if len(np.atleast_2d(X)) > 1 else np.zeros(np.shape(X)[-1])


def _pymoo_problem(fmap: PopulationMap, n_var: int, n_obj: int, names: tuple[str, ...]):
    from pymoo.core.problem import Problem

    class _Batch(Problem):  # elementwise=False: pymoo hands over the whole population at once
        def __init__(self):
            super().__init__(n_var=n_var, n_obj=n_obj, xl=0.0, xu=1.0, elementwise=False)

        def _evaluate(self, Z, out, *args, **kwargs):
            out["F"] = fmap(from_unit(Z, names))

    return _Batch()


def _ga(spec: Spec, pop_size: int, n_gen: int, seed: int, executor) -> tuple[np.ndarray, int]:
    from pymoo.algorithms.soo.nonconvex.ga import GA
    from pymoo.optimize import minimize

    with PopulationMap(evaluate_chunk, (spec,), executor) as fmap:
        problem = _pymoo_problem(fmap, len(spec.free), 1, spec.free)
        res = minimize(problem, GA(pop_size=pop_size, eliminate_duplicates=True), ("n_gen", n_gen), seed=seed,
                       verbose=False)
        Z, F = res.pop.get("X"), res.pop.get("F")[:, 0]
        top = Z[np.argsort(F)[: max(2, len(Z) // 4)]]
        return from_unit(np.atleast_2d(res.X)[0], spec.free), fmap.n_evals, _resolution(from_unit(top, spec.free))


def fit_sequential(records: list, method: Literal["nelder-mead", "ga"] = "nelder-mead", law: str = "poly", *,
                   x0: HammersteinParams | None = None, skip_s: float = 0.0, maxfev: int = 3000, step: float = 0.5,
                   pop_size: int = 50, n_gen: int = 60, seed: int = 0, executor: Any = "auto",
                   with_stderr: bool = True) -> HammersteinFit:
    """Seed 001's sequential identification: electric stage on the current error, then the mechanical
    stage on the displacement error with the electric stage fixed. ``x0`` is Nelder-Mead's start (and
    holds the law); GA ignores it except for the law."""
    t0 = time.perf_counter()
    p = x0 if x0 is not None else HammersteinParams(law=law)
    if p.law != law:
        p = HammersteinParams(law=law).with_vector(hm.MECH_NAMES, p.vector(hm.MECH_NAMES))
    groups, n_evals, stages, resolution = pack(records, skip_s), 0, {}, {}
    for stage in ("electric", "mechanical"):
        i_fixed = _fixed_current(groups, law, p) if stage == "mechanical" else None
        spec = _spec(groups, law, p, stage, i_fixed)
        if method == "nelder-mead":
            x, n, res = _nelder_mead(spec, p.vector(spec.free), maxfev, step)
        elif method == "ga":
            x, n, res = _ga(spec, pop_size, n_gen, seed, executor)
        else:
            raise ValueError(f"unknown method {method!r}")
        p, n_evals = p.with_vector(spec.free, x), n_evals + n
        resolution.update(zip(spec.free, map(float, res)))
        stages[stage] = {"n_evals": n, spec.objectives[0]: float(evaluate_chunk(x[None], spec)[0, 0])}
    return _finish(method, law, p, groups, n_evals, t0, with_stderr, stages=stages, resolution=resolution)


def fit_nelder_mead(records: list, law: str = "poly", **kw) -> HammersteinFit:
    return fit_sequential(records, "nelder-mead", law, **kw)


def fit_ga(records: list, law: str = "poly", **kw) -> HammersteinFit:
    return fit_sequential(records, "ga", law, **kw)


# -- multi-objective ------------------------------------------------------------------------------
def fit_nsga2(records: list, law: str = "poly", *, pop_size: int = 100, n_gen: int = 100, seed: int = 0,
              skip_s: float = 0.0, executor: Any = "auto", with_stderr: bool = True) -> HammersteinFit:
    """NSGA-II on (current NRMSE, displacement NRMSE) over all parameters at once; the knee of the
    final non-dominated set (:func:`knee_point`) is reported as the parameters."""
    from pymoo.algorithms.moo.nsga2 import NSGA2
    from pymoo.optimize import minimize

    t0 = time.perf_counter()
    groups = pack(records, skip_s)
    spec = _spec(groups, law, HammersteinParams(law=law), "joint")
    with PopulationMap(evaluate_chunk, (spec,), executor) as fmap:
        res = minimize(_pymoo_problem(fmap, len(spec.free), 2, spec.free), NSGA2(pop_size=pop_size),
                       ("n_gen", n_gen), seed=seed, verbose=False)
        n_evals = fmap.n_evals
    F, X = np.atleast_2d(res.F), from_unit(np.atleast_2d(res.X), spec.free)
    order = np.argsort(F[:, 0])
    F, X = F[order], X[order]
    k = knee_point(F)
    p = HammersteinParams(law=law).with_vector(spec.free, X[k])
    res = _resolution(X[max(0, k - 1):k + 2])
    return _finish("nsga2", law, p, groups, n_evals, t0, with_stderr, front_F=F, front_X=X,
                   front_names=spec.free, knee=k, resolution=dict(zip(spec.free, map(float, res))))


def identify(records: list, method: str = "nelder-mead", law: str = "poly", **kw) -> HammersteinFit:
    """One entry point: method in {"nelder-mead", "ga", "nsga2"}."""
    return fit_nsga2(records, law, **kw) if method == "nsga2" else fit_sequential(records, method, law, **kw)
