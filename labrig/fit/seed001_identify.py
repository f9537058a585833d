"""Seed 001's identification (``fit_seed001``): one method, or the comparison of Nelder-Mead (several starts), GA and NSGA-II (several seeds) on the same records.

Per method: the best run's parameters, their standard errors and their spread over the runs (starts or seeds) that converged, the NRMSE of current and displacement on the fitted and on the held-out
records, evaluations and wall time; the NSGA-II fronts of all seeds merged into one non-dominated front and its
knee; the static I-V trend measured on the step records (seed 001's Fig. 1) against each identified law; the
session's noise level, so the errors can be read as structural misfit or noise.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from labrig.fit.executors import is_dask_client
from labrig.fit.hammerstein import HammersteinFit, fit_nsga2, fit_sequential, from_unit, knee_point
from labrig.estimate.session_data import SessionData
from labrig.fit.seed001 import MAX_RATE_HZ, MAX_S, Seed001Data, clean, prepare, summarise
from labrig.physics import hammerstein as hm
from labrig.physics.params import HammersteinParams
from labrig.records import RecordKind

CONVERGED = 0.5  # a run converged when its summed error is within 50 % of the best run's


@dataclass(frozen=True)
class Budget:
    nm_starts: int = 3
    nm_maxfev: int = 400  # per stage
    ga_seeds: int = 2
    ga_pop: int = 40
    ga_gen: int = 30  # per stage
    nsga_seeds: int = 2
    nsga_pop: int = 60
    nsga_gen: int = 50
    max_rate_Hz: float = 250.0  # records decimated to at most this rate ...
    max_s: float = 8.0  # ... and cut to this length (labrig.fit.seed001.prepare)


# quick: a smoke test of the whole path (seconds), not an identification to trust
BUDGETS = {"standard": Budget(), "quick": Budget(2, 120, 2, 16, 8, 2, 24, 12, max_rate_Hz=125.0, max_s=4.0)}


def nelder_mead_runs(records: list, law: str, b: Budget, executor: Any = "auto") -> list[HammersteinFit]:
    """Start 0 is the default parameters; the others are drawn uniformly from the middle of the search box. Given a
    dask client, each start is a task on the cluster."""
    names = hm.param_names(law)
    rng = np.random.default_rng(0)
    starts = [HammersteinParams(law=law)] + [HammersteinParams(law=law).with_vector(names, from_unit(rng.uniform(0.2, 0.8, len(names)), names))
                                             for _ in range(b.nm_starts - 1)]
    if is_dask_client(executor):  # Nelder-Mead is sequential: on a cluster its starts are the parallel tasks
        futures = [executor.submit(fit_sequential, records, "nelder-mead", law, x0=x0, maxfev=b.nm_maxfev, pure=False) for x0 in starts]
        return executor.gather(futures)
    return [fit_sequential(records, "nelder-mead", law, x0=x0, maxfev=b.nm_maxfev) for x0 in starts]


def ga_runs(records: list, law: str, b: Budget, executor: Any = "auto") -> list[HammersteinFit]:
    return [fit_sequential(records, "ga", law, pop_size=b.ga_pop, n_gen=b.ga_gen, seed=s, executor=executor) for s in range(b.ga_seeds)]


def nsga2_runs(records: list, law: str, b: Budget, executor: Any = "auto") -> list[HammersteinFit]:
    return [fit_nsga2(records, law, pop_size=b.nsga_pop, n_gen=b.nsga_gen, seed=s, executor=executor) for s in range(b.nsga_seeds)]


METHODS = {"nelder-mead": nelder_mead_runs, "ga": ga_runs, "nsga2": nsga2_runs}


def _score(f: HammersteinFit) -> float:
    return f.objectives["current"] + f.objectives["displacement"]


def pick(runs: list[HammersteinFit]) -> tuple[HammersteinFit, dict[str, float | None], int]:
    """The best run, the spread (standard deviation) of each parameter over the runs that converged (summed error
    within ``CONVERGED`` of the best: a start trapped in another minimum says where the optimiser went, not what the
    data tell), None with fewer than two such runs; and how many converged."""
    best = min(runs, key=_score)
    conv = [r for r in runs if _score(r) <= _score(best) * (1 + CONVERGED)]
    spread = {n: (float(np.std([r.params[n] for r in conv], ddof=1)) if len(conv) > 1 else None) for n in best.params}
    return best, spread, len(conv)


def merged_front(fits: list[HammersteinFit]) -> tuple[np.ndarray, np.ndarray, int]:
    """The non-dominated set of all seeds' fronts (sorted by current error) and its knee (knee_point)."""
    F = np.vstack([f.front_F for f in fits])
    X = np.vstack([f.front_X for f in fits])
    keep = [k for k in range(len(F)) if not np.any(np.all(F <= F[k], axis=1) & np.any(F < F[k], axis=1))]
    F, X = F[keep], X[keep]
    F, idx = np.unique(F, axis=0, return_index=True)
    X = X[idx]
    order = np.argsort(F[:, 0])
    return F[order], X[order], knee_point(F[order])


def static_trend(data: Seed001Data) -> dict[str, Any]:
    """Seed 001's Fig. 1: the steady current at the end of each step's on-phase (mean of its last fifth) against the
    drive there; what the electric stage's static law (hm.static_current) must follow."""
    V, I, names = [], [], []
    for r in data.raw:
        if r.kind != RecordKind.STEP or not r.meta.get("on_s"):
            continue
        pre, on = float(r.meta.get("pre_s", 0.0)), float(r.meta["on_s"])
        sel = (r.t - r.t[0] >= pre + 0.8 * on) & (r.t - r.t[0] < pre + on)
        if sel.sum() > 2:
            V.append(float(np.mean(r.v[sel])))
            I.append(float(np.mean(r.i[sel])))
            names.append(r.name)
    return {"V": V, "I": I, "records": names}


def noise_level(data: Seed001Data) -> dict[str, float | None]:
    """Noise as an NRMSE: the std of current and displacement while the drive is still 0 V before each step,
    over the rms of the record (median over steps). What an error at the noise floor would be."""
    out: dict[str, list] = {"current": [], "displacement": []}
    for r in data.raw:
        pre = float(r.meta.get("pre_s", 0.0)) if r.kind == RecordKind.STEP else 0.0
        sel = (r.t - r.t[0]) < 0.9 * pre
        if sel.sum() > 10:
            for key, x in (("current", r.i), ("displacement", r.d)):
                out[key].append(np.std(x[sel]) / max(np.sqrt(np.mean((x - x[0]) ** 2)), 1e-300))
    return {k: (float(np.median(v)) if v else None) for k, v in out.items()}


def with_gap(entries: list[dict[str, Any]], n_samples: int) -> None:
    """Widen each method's stated uncertainty by its optimality gap. A method that stopped at an error F above the
    best any method found, F_best, leaves a sum of squares (F^2 - F_best^2) n unexplained by noise; the parameters
    that move the sum of squares by that much lie within sqrt(gap * n) standard errors, gap = 1 - (F_best / F)^2
    (Gauss-Newton: stderr^2 = s^2 [(J^T J)^-1]_kk with s^2 = F^2 n / dof, and dof ~ n). Electric parameters take the
    current's gap, mechanical ones the displacement's (the sequential split)."""
    best = {k: min((e[f"nrmse_{k}"] for e in entries if e[f"nrmse_{k}"] is not None), default=None) for k in ("current", "displacement")}
    electric = set(hm.ELECTRIC_BASE) | {x for law in hm.LAWS.values() for x in law.extra}
    for e in entries:
        gap = {k: (max(0.0, 1.0 - (best[k] / e[f"nrmse_{k}"]) ** 2) if best[k] and e[f"nrmse_{k}"] else 0.0) for k in best}
        e["optimality_gap"] = gap
        for n, u in e["uncertainty"].items():
            se = e["stderr"].get(n)
            if u is not None and se is not None:
                g = gap["current" if n in electric else "displacement"]
                e["uncertainty"][n] = float(np.hypot(u, se * np.sqrt(g * n_samples)))


def compare(data: Seed001Data, law: str = "poly", budget: str | Budget = "standard", executor: Any = "auto",
            methods: tuple[str, ...] = tuple(METHODS)) -> dict[str, Any]:
    """Every method on ``data.fit``, scored on ``data.fit`` and ``data.heldout`` (DESIGN.md 6 JSON)."""
    b = BUDGETS[budget] if isinstance(budget, str) else budget
    trend = static_trend(data)
    grid = np.linspace(-max([2.0, *map(abs, trend["V"])]), max([2.0, *map(abs, trend["V"])]), 41)
    entries, fronts, laws = [], None, {}
    for name in methods:
        t0 = time.perf_counter()
        runs = METHODS[name](data.fit, law, b, executor)
        best, spread, n_conv = pick(runs)
        e = summarise(best, data, spread)
        e.update(n_evals=int(sum(r.n_evals for r in runs)), wall_s=time.perf_counter() - t0, runs=len(runs), converged=n_conv,
                 run_objectives=[[clean(r.objectives["current"]), clean(r.objectives["displacement"])] for r in runs])
        if name == "nsga2":
            F, X, k = merged_front(runs)
            p = HammersteinParams(law=law).with_vector(runs[0].front_names, X[k])
            fronts = {"pareto_front": F.tolist(), "pareto_knee": k, "knee_params": p.as_dict(hm.param_names(law))}
            e["pareto_front"] = F.tolist()
        p = best.to_params()
        laws[name] = {"V": grid.tolist(), "I": hm.static_current(p, grid).tolist(),
                      "at_measured": hm.static_current(p, np.asarray(trend["V"])).tolist()}
        entries.append(e)
    with_gap(entries, sum(len(r.v) for r in data.fit))
    return {
        "law": law,
        "budget": budget if isinstance(budget, str) else "custom",
        "records": data.fit_names,
        "heldout_records": data.heldout_names,
        "methods": entries,
        **(fronts or {"pareto_front": None, "pareto_knee": None}),
        "nonlinearity": {"measured": trend, "laws": laws},
        "noise_nrmse": noise_level(data),
    }


def fit_seed001(sd: SessionData, method: str = "nelder-mead", law: str = "poly", force: bool = False, max_rate_Hz: float = MAX_RATE_HZ,
                max_s: float = MAX_S, executor: Any = "auto", budget: str = "standard") -> dict[str, Any] | None:
    """Identify the Hammerstein model with one method, or with ``method="all"`` compare Nelder-Mead (several starts),
    GA and NSGA-II (several seeds) on the same records (``compare`` below). None when the session has
    no records that can tell it."""
    if method == "all":
        b = BUDGETS[budget]
        data = prepare(sd, force, b.max_rate_Hz, b.max_s)
        return None if data is None else compare(data, law, budget=budget, executor=executor)
    data = prepare(sd, force, max_rate_Hz, max_s)
    if data is None:
        return None
    if method == "nsga2":
        fit = fit_nsga2(data.fit, law=law, pop_size=40, n_gen=40, executor=executor)
    else:
        fit = fit_sequential(data.fit, method=method, law=law, executor=executor)
    return summarise(fit, data)
