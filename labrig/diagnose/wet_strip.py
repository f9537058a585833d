"""A drying judged on the wet strip: the session corrected by the loss and the seed-000 fit run again on it.

The baseline is the seed-000 fit's stages (``engine.baseline_specimens``), and that fit is per pressure where a sweep
is per time: K_t bar and the clamp's electrical values per pressure, the line's values, alpha and gamma shared. A strip
drying through the session is taken in by it: the conductance's loss by the clamp values pressure by pressure, the
gain's partly by K_t bar, and what is left bends the shared values, so that the first pressure, where the strip has
hardly dried, misses too. A drying form applied on that baseline scales records it has already half explained; on a
drying of exactly the family's linear form written into a clean seed-001 session it reached 0.51 (not named) and found
the conductance's loss at 0.012 against the 0.15 written (docs/diagnosis.md, "A drying through the session").

The data hold the conductance's loss without the model: the analyser's spectrum and the DAQ's current admittance
measure the same admittance, the spectrum first and the stepped sines after it, so |Y_daq(f)| |Z(f)| at one pressure
is 1 on a strip that holds its water (within 0.3 % on the clean seed-001 sessions) and falls with the loss through the
pressure's sines. Its slope against the form's loss x(t), within each pressure (a level per pressure: a calibration
or the spectrum's own moment), is the conductance's loss k_i (``conductance_loss``).

With k_i so and the displacement's loss k_d from the form fitted on the baseline, the session's records are corrected
to the wet strip (displacement / (1 - k_d x), current / (1 - k_i x), each sample at its own time; a spectrum x (1 - k_i
x) at its start), the seed-000 fit's stages are run on them (``seed000.staged_specimens``: the joint refinement,
which the baseline does not stand on, left out), and the form is fitted again on that wet baseline, whose spectra are
dried again at their moments (no form changes a spectrum). It is scored as every form: DeltaBIC on the fitted half
(the two corrections counted as parameters), the held-out ratio against the session's own baseline. k_i is read off
the fitted half's pressures only; the refit uses every pressure, as the baseline does.
"""

from __future__ import annotations

import copy
import dataclasses
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.optimize import minimize_scalar

from labrig.diagnose.catalogue import Context, Extension
from labrig.diagnose.features import Features
from labrig.estimate import sine_estimate
from labrig.estimate.session_data import PressureData, SessionData, add_derived, sine_cycles
from labrig.fit.seed000 import staged_specimens
from labrig.records import RecordKind

LOSS_BOUNDS = (-0.5, 0.9)  # the corrections' range (a re-wetting may gain; a strip loses at most most of its water)
MIN_SINES = 3  # per pressure, inside the spectrum's band, for the admittance's trace
REFINE_STEP, REFINE_FLOOR, REFINE_EVALS = 0.5, 0.05, 3  # the conductance loss's refinement (``refine_loss``)


@dataclass
class WetSession:
    """What the refit needs beyond a context: the session's records and the halves' pressures (``engine.split``)."""

    sd: SessionData
    fit_set: set
    held_set: set


@dataclass
class WetRefit:
    """The contexts on the wet strip's baseline (``engine._adopt`` builds on them when the form is accepted)."""

    ctx_fit: Context
    ctx_held: Context


def loss_of(ext: Extension, theta: np.ndarray, feats: Features) -> Callable[[np.ndarray], np.ndarray] | None:
    """The form's loss x(t) at its fitted shape parameters (None: the form has no separable loss)."""
    loss = getattr(ext.apply, "loss", None)
    if loss is None:
        return None
    sh = list(theta[4:])
    ctx = _FeaturesOnly(feats)
    return lambda t: np.asarray(loss(np.asarray(t, float), sh, ctx), float)


@dataclass
class _FeaturesOnly:
    feats: Features  # what a loss reads of its context: the session's clock and charge


def paired_sines(feats: Features, pressures: set) -> list[tuple[Any, list]]:
    """Each spectrum of ``pressures`` with its pressure's stepped sines inside its band (at least MIN_SINES): the
    analyser's and the DAQ's readings of the same admittance."""
    out = []
    for spec in feats.spectra:
        if spec.pressure_kPa not in pressures:
            continue
        ss = [s for s in feats.sines if s.pressure_kPa == spec.pressure_kPa and spec.f.min() <= s.f <= spec.f.max() and abs(s.Hi) > 0]
        if len(ss) >= MIN_SINES:
            out.append((spec, ss))
    return out


def conductance_loss(feats: Features, x: Callable[[np.ndarray], np.ndarray], pressures: set) -> float | None:
    """k_i from log(|Y_daq| |Z|) = a_p + log(1 - k_i x(t)) over the stepped sines of ``pressures``, a_p a level per
    pressure (profiled out); |Z| at each sine's frequency from a cubic spline of log |Z| in log f (a straight line
    between the spectrum's points bends with the CPE's curvature, which the sines' order turns into a slope in time).
    None: no spectrum with MIN_SINES sines inside its band, or the loss does not change within a pressure."""
    xs, ys = [], []
    for spec, ss in paired_sines(feats, pressures):
        o = np.argsort(spec.f)
        lz = CubicSpline(np.log(spec.f[o]), np.log(np.abs(spec.Z[o])))(np.log([s.f for s in ss]))
        ys.append(np.log(np.abs([s.Hi for s in ss])) + lz)
        xs.append(x(np.array([s.t_start for s in ss])))
    if not xs or max(float(np.ptp(xp)) for xp in xs) < 1e-9:
        return None

    def cost(k: float) -> float:
        if any(np.any(k * xp >= 1.0) for xp in xs):
            return np.inf  # a loss past the whole conductance (a shape above 1 between its ends): no reading there
        return sum(float(np.sum((r - r.mean()) ** 2)) for r in (y - np.log1p(-k * xp) for xp, y in zip(xs, ys)))

    return float(minimize_scalar(cost, bounds=LOSS_BOUNDS, method="bounded", options={"xatol": 1e-5}).x)


def recorded_anew(sd: SessionData, record: Callable[[Any], Any], eis: Callable[[PressureData], Any] | None = None) -> SessionData:
    """The session with every record changed by ``record`` (a TimeRecord in, one out) and each pressure's spectrum by
    ``eis`` (None: kept), the stepped sines' estimates made again from the changed records."""
    out = []
    for b in sd.pressures:
        recs = [record(r) for r in b.records]
        nb = PressureData(b.pressure_kPa, records=recs, eis_t_start=b.eis_t_start)
        if b.eis is not None:
            nb.eis = b.eis if eis is None else eis(b)
        nb.sines = [sine_estimate(r.t, r.v, r.i, r.d, float(r.meta["frequency_Hz"]), *sine_cycles(r)) for r in recs if r.kind == RecordKind.STEPPED_SINE]
        add_derived(nb)
        out.append(nb)
    return dataclasses.replace(sd, pressures=out)


def wet_session(sd: SessionData, x: Callable[[np.ndarray], np.ndarray], k_d: float, k_i: float) -> SessionData:
    """The session as the wet strip would have read it: every sample divided by its loss, each spectrum multiplied
    (its impedance rises as the conductance falls), the stepped sines' estimates made again."""

    def record(r):
        xr = x(r.t_start + (r.t - r.t[0]))
        return dataclasses.replace(r, d=r.d / (1 - k_d * xr), i=r.i / (1 - k_i * xr))

    return recorded_anew(sd, record, lambda b: (b.eis[0], b.eis[1] * (1 - k_i * float(x(np.array([b.eis_time]))[0]))))


def redried(ctx: Context, x: Callable[[np.ndarray], np.ndarray], k_i: float) -> Context:
    """``ctx`` (on the wet strip's baseline) with its spectra's predictions dried again at their moments."""
    out = copy.copy(ctx)
    out.spectra = [(spec, zb / (1 - k_i * float(x(np.array([spec.t_start]))[0]))) for spec, zb in ctx.spectra]
    return out


def _shape_reading(ws: WetSession, feats: Features, ext: Extension, params: dict[str, float]) -> dict[str, float] | None:
    """The form's loss shape at ``params`` (its parameters past the four levels and losses) as ``wet_*`` names, with
    the conductance's loss read off the admittance's trace on the fitted half at that shape. None: no separable loss
    or no trace to read."""
    shape = {f"wet_{p}": float(params[p]) for p in ext.params[4:]}
    x = loss_of(ext, np.r_[np.zeros(4), list(shape.values())], feats)
    k_i = None if x is None else conductance_loss(feats, x, ws.fit_set)
    return None if k_i is None else {"wet_conductance_loss": k_i, **shape}


def correction(ws: WetSession, feats: Features, ext: Extension, params: dict[str, float]) -> dict[str, float] | None:
    """The wet strip's correction for the form ``ext`` fitted on the baseline (``params``): its loss's shape, its
    displacement loss, and the conductance's loss read off the admittance's trace on the fitted half (the names
    ``wet_*`` report it with the form's own parameters). None: no separable loss or no trace to read."""
    reading = _shape_reading(ws, feats, ext, params)
    return None if reading is None else {"wet_gain_loss": float(np.clip(params["gain_loss"], *LOSS_BOUNDS)), **reading}


def reshaped(ws: WetSession, feats: Features, ext: Extension, corr: dict[str, float], wet_params: dict[str, float]) -> dict[str, float] | None:
    """The correction ``corr`` at the loss's shape the form took on the wet strip (``wet_params``: its fit there), the
    conductance's loss read again off the admittance's trace at that shape, the displacement's loss kept. None where
    the form has no shape parameters or the trace gives no reading."""
    reading = _shape_reading(ws, feats, ext, wet_params) if ext.params[4:] else None
    return None if reading is None else {**corr, **reading}


def wet_contexts(ws: WetSession, feats: Features, ext: Extension, corr: dict[str, float], build) -> tuple[Context, Context] | None:
    """The fitted and held-out contexts (``build``: ``engine.build_context``) on the seed-000 fit of the session
    corrected by ``corr`` (``correction``), their spectra dried again. None if that fit gives no strip."""
    x = loss_of(ext, np.r_[np.zeros(4), [corr[f"wet_{p}"] for p in ext.params[4:]]], feats)
    k_i = corr["wet_conductance_loss"]
    both = refitted_contexts(ws, wet_session(ws.sd, x, corr["wet_gain_loss"], k_i), feats, build)
    if both is None:
        return None
    cf = redried(both[0], x, k_i)
    return cf, cf if both[1] is both[0] else redried(both[1], x, k_i)


def refitted_contexts(ws: WetSession, corrected: SessionData, feats: Features, build) -> tuple[Context, Context] | None:
    """The fitted and held-out contexts (``build``: ``engine.build_context``) of the recorded features ``feats`` on the
    seed-000 fit's stages on the ``corrected`` session (the same context twice where the halves are the same records). None if
    that fit gives no strip."""
    specimens = staged_specimens(corrected)  # the baseline's stages: the joint refinement is not what it stands on
    if not specimens:
        return None
    cf = build(feats, specimens, ws.fit_set)
    return cf, cf if ws.fit_set == ws.held_set else build(feats, specimens, ws.held_set)


def refine_loss(k0: float, on_wet: Callable[[float], Any], first: Any = None) -> Any:
    """The candidate ``on_wet(k)`` of least fitted-half chi-square (``chi2_fit``) over a few conductance losses from
    the admittance's reading k0 on: k0, then steps of REFINE_STEP (relative, at least REFINE_FLOOR) uphill or down
    while the chi-square falls, at most REFINE_EVALS refits (each the seed-000 fit's stages). The reading is biased
    where the loss is not the form's shape within a pressure (a loss that speeds up late reads low early)."""
    lo, hi = LOSS_BOUNDS
    best = first if first is not None else on_wet(k0)  # ``first``: on_wet(k0), already fitted
    if best is None:
        return None
    step = max(REFINE_STEP * abs(k0), REFINE_FLOOR)
    k, evals, direction = k0, 1, +1
    while evals < REFINE_EVALS:
        k_next = float(np.clip(k + direction * step, lo, hi))
        cand = on_wet(k_next) if k_next != k else None
        evals += 1
        if cand is not None and cand.chi2_fit < best.chi2_fit:
            best, k = cand, k_next
        elif direction > 0 and k == k0:
            direction = -1  # not uphill: try once below the reading
        else:
            break
    return best
