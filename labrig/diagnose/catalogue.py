"""The effect catalogue (DESIGN.md 5; the names are a contract): for each effect a model extension on top of
the fitted seed-000 baseline, expressed on the diagnosis features so it can be fitted in milliseconds.

Each extension maps parameters theta to predictions of every feature block (FRF of displacement and current,
harmonic ratios, first step response, clamp force against its target, line-frequency components). The baseline is theta = 0.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from labrig.physics import timeresp, transfer
from labrig.diagnose.features import Features, SineFeature, StepFeature, predict_step, specimen_for
from labrig.physics.params import Specimen



@dataclass
class Context:
    """Baseline predictions for one group of records (a set of pressures), computed once."""

    feats: Features
    specimens: dict[float, Specimen]
    sines: list[SineFeature]
    steps: list[StepFeature]
    lines: list
    Hd: np.ndarray  # baseline FRF at each sine's frequency and pressure
    Hi: np.ndarray
    Hd3: np.ndarray  # baseline FRF at 3 f (for harmonics made before the linear stage)
    step_d: list[np.ndarray]
    step_i: list[np.ndarray]
    force_nominal: np.ndarray  # N, per sine: the clamp target (from the pressure)
    area: float
    length: float
    base: "Prediction | None" = None  # accepted effects so far: extensions build on it (forward selection)
    chain: list = field(default_factory=list)  # (extension, theta) of those effects, to rebuild base on new mechanics
    cache: dict = field(default_factory=dict)  # what an extension precomputes once per context (it depends on the specimens only)
    step_timing: list = field(default_factory=list)  # per step: (displacement, current) sampling uncertainty at the edges
    spectra: list = field(default_factory=list)  # (SpectrumFeature, the baseline's Z there): no extension changes Z


_BY_RECORDS: dict[tuple, tuple[tuple, Any]] = {}  # (kind, the lists' ids) -> (the lists, what was made of them)
_BY_RECORDS_KEPT = 96


def by_records(kind: str, records: tuple, make: Callable[[], Any]) -> Any:
    """``make()`` once per ``kind`` and tuple of record lists (a context's ``sines``, ``steps``, ``lines``, ...), by
    identity: what derives from the measured records alone is made once for every context around them (the blocks
    are evaluated thousands of times in a fit, on contexts that a copy or a refit of the mechanics makes anew around
    the same lists)."""
    key = (kind, *map(id, records))
    hit = _BY_RECORDS.get(key)
    if hit is not None and all(a is b for a, b in zip(hit[0], records)):
        return hit[1]
    out = make()
    if len(_BY_RECORDS) >= _BY_RECORDS_KEPT:
        del _BY_RECORDS[next(iter(_BY_RECORDS))]
    _BY_RECORDS[key] = (records, out)  # the lists kept alive with it: their ids cannot be reused while cached
    return out


@dataclass
class Prediction:
    Hd: np.ndarray
    Hi: np.ndarray
    hd: np.ndarray  # (n, 2): predicted displacement harmonic ratios k = 2, 3
    hi: np.ndarray
    step_d: list[np.ndarray]
    step_i: list[np.ndarray]
    force_rel: np.ndarray  # predicted mean clamp force of each sine record relative to its target, minus 1
    line: dict[tuple[str, float], float]  # predicted line amplitude per (channel, Hz); absent = none (noise only)
    # the lines scaled in each record by a level of its own, fitted on that record (line_levels.py): a source
    # switched on and off or varying between records, its spectrum and couplings fixed
    line_level: bool = False

    def copy(self) -> "Prediction":
        """A copy whose arrays an extension may change in place."""
        return Prediction(self.Hd.copy(), self.Hi.copy(), self.hd.copy(), self.hi.copy(), [d.copy() for d in self.step_d],
                          [i.copy() for i in self.step_i], self.force_rel.copy(), dict(self.line), self.line_level)


def baseline(ctx: Context) -> Prediction:
    """The baseline's predictions, or those of the effects already accepted (a fresh copy)."""
    if ctx.base is not None:
        return ctx.base.copy()
    n = len(ctx.sines)
    return Prediction(ctx.Hd.copy(), ctx.Hi.copy(), np.zeros((n, 2), complex), np.zeros((n, 2), complex),
                      [d.copy() for d in ctx.step_d], [i.copy() for i in ctx.step_i], np.zeros(n), {})


@dataclass
class Extension:
    name: str
    params: tuple[str, ...]
    x0: tuple[float, ...]
    lo: tuple[float, ...]
    hi: tuple[float, ...]
    apply: Callable[[np.ndarray, Context], Prediction]
    describe: str = ""
    refit_mechanics: bool = False  # change the linear path's shape: fitted with alpha, gamma, K_t bar free
    form: str = ""  # which form of the effect's family (labrig.diagnose.families)
    # a start read off the data it is fitted on (one least-squares start besides x0), for forms of many parameters
    # whose values the data show directly (a line's amplitude)
    start: Callable[[Context], np.ndarray] | None = None
    # parameters fitted inside the prediction on every record (a pickup's level per record), counted in DeltaBIC
    inner_dof: Callable[[Context], int] | None = None
    # blocks of which the base must miss one for the form to be fitted (empty: any): a form whose signature sits there
    needs: frozenset[str] = frozenset()
    # the least-squares' parameter scale: the Jacobian's columns, or the parameters' own units (1.0) where a parameter
    # no datum reads at the start (its column ~0) would be sent far by the Jacobian's scale (families' ``varying``)
    x_scale: Any = "jac"


def _drive(s: SineFeature) -> complex:
    return complex(s.est.drive[0])


def cosine_harmonics(fun, amp: np.ndarray, n: int) -> np.ndarray:
    """The cosine coefficients of harmonics 1-3 of a static map driven by a cosine, fun(a cos wt) over one cycle
    sampled at n points, a row per amplitude of ``amp`` (a describing function; an odd or even map has no sine
    terms)."""
    wt = 2 * np.pi * np.arange(n) / n
    return 2 * np.fft.rfft(fun(np.asarray(amp)[:, None] * np.cos(wt)[None, :]), axis=1)[:, 1:4].real / n


# ------------------------------------------------------------------------------------------------ effects


def step_through(st: StepFeature, y: np.ndarray, tf) -> np.ndarray:
    """A step record's predicted displacement ``y`` (on the record's averaged grid) read through the transfer function
    ``tf(s)`` of a path after the strip (a sensor's filter, a relaxation of the bend, a coupled mode)."""
    return timeresp.simulate(tf, y, 1.0 / float(np.median(np.diff(st.t))))


def _back_relaxation(th, ctx):
    k2, tau = th
    p = baseline(ctx)
    if k2 == 0:
        return p
    # DESIGN.md 5 prints 1 - K2 tau s/(tau s + 1), which removes gain *above* 1/tau and never makes a step
    # peak and relax; the slow opposing flux is a low-pass: the step rises, peaks, then decays or reverses
    B = lambda s: 1.0 - k2 / (tau * s + 1.0)  # noqa: E731
    f = np.array([s.f for s in ctx.sines])
    p.Hd = p.Hd * B(2j * np.pi * f)
    for k, st in enumerate(ctx.steps):
        p.step_d[k] = step_through(st, p.step_d[k], B)
    return p


def _faradaic(th, ctx):
    g1, g3 = th
    p = baseline(ctx)
    for k, s in enumerate(ctx.sines):
        a = _drive(s)
        i1 = p.Hi[k] * a + g1 * a + 0.75 * g3 * abs(a) ** 2 * a
        p.hi[k, 1] = 0.25 * g3 * a**3 / i1
        p.Hi[k] = i1 / a
    for k, st in enumerate(ctx.steps):
        p.step_i[k] = p.step_i[k] + g1 * st.v + g3 * st.v**3
    return p


def _play(x: np.ndarray, r: float) -> np.ndarray:
    """Play (backlash) operator of half-width r on a 1-D drive, starting at 0.

    y_k = clip(y_{k-1}, x_k - r, x_k + r). y holds until x leaves the band around it; from there it is the
    running maximum of x - r (or minimum of x + r) until x turns back through the whole band. Each such phase
    is one vectorised pass, and a step drive with small noise has a phase per edge, not per sample.
    """
    x = np.asarray(x, float).ravel()
    y = np.empty_like(x)
    k, state = 0, 0.0
    while k < x.size:
        rest = x[k:]
        out = np.flatnonzero(np.abs(rest - state) > r)  # first sample that pushes the band
        if out.size == 0:
            y[k:] = state
            break
        j = k + out[0]
        y[k:j] = state
        up = x[j] - r > state
        push = np.maximum.accumulate(x[j:] - r) if up else np.minimum.accumulate(x[j:] + r)
        back = np.flatnonzero(x[j:] + r < push) if up else np.flatnonzero(x[j:] - r > push)  # turned through the band
        end = j + (back[0] if back.size else x.size - j)
        y[j:end] = push[: end - j]
        state, k = float(y[end - 1]), end
    return y


_TH = np.linspace(0, 2 * np.pi, 257)[:-1]


def _play_df(a: np.ndarray, r: float) -> tuple[np.ndarray, np.ndarray]:
    """Describing function of the play operator at amplitudes a: fundamental and 3rd harmonic gains."""
    a = np.atleast_1d(np.asarray(a, float))
    x = a[:, None] * np.cos(_TH)[None, :]
    rr = np.minimum(r, 0.99 * a)[:, None]
    # the periodic state in closed form (the recursion from the cosine's top, where the band sits at a - r): held at
    # a - r until x + r comes down to it, then x + r to the bottom; held at r - a until x - r comes up to it
    down = _TH[None, :] <= np.pi
    y = np.where(down, np.minimum(a[:, None] - rr, x + rr), np.maximum(rr - a[:, None], x - rr))
    c = np.fft.rfft(y, axis=1) / _TH.size * 2
    return c[:, 1] / a, c[:, 3] / a


def block_drive(st: StepFeature) -> np.ndarray:
    """A step record's drive as the means of its blocks of ``st.q`` samples (the grid the step is compared on; a
    last partial block left out)."""
    n = (st.v_full.size // st.q) * st.q
    return st.v_full[:n].reshape(-1, st.q).mean(axis=1)


def at_full_rate(yb: np.ndarray, st: StepFeature) -> np.ndarray:
    """Block values ``yb`` (``block_drive``'s grid) held over their samples, the last held to the record's end."""
    return np.r_[np.repeat(yb, st.q), np.full(st.v_full.size - yb.size * st.q, yb[-1] if yb.size else 0.0)]


def _hysteresis(th, ctx):
    w, r, gain = th
    return played_drive(w, [r], gain, ctx)


def played_drive(w: float, radii, gain: float, ctx: Context) -> "Prediction":
    """The strip driven by (1 - w) v + w P[v], P the mean of play operators of the given half-widths (one: a
    play; several: a Prandtl-Ishlinskii operator with their density), the gain refitted (the baseline's alpha
    already took in the average loss of gain the memory causes). Sines by describing function, the step through
    the strip's dynamics from rest."""
    p = baseline(ctx)
    if ctx.sines:
        drv = np.array([_drive(s) for s in ctx.sines])
        a = np.abs(drv)
        n1, n3 = (np.mean(x, axis=0) for x in zip(*(_play_df(a, r) for r in radii)))
        g1 = (1 - w) + w * n1
        p.Hd = p.Hd * g1 * gain
        p.hd[:, 1] = w * n3 * ctx.Hd3 / (g1 * ctx.Hd) * (drv / a) ** 2
    for k, st in enumerate(ctx.steps):
        sp = specimen_for(ctx.specimens, st.pressure_kPa)
        # the play runs on the 50 Hz block means the step is compared at: at full rate it would walk 30,000
        # samples per call, and the band only moves at the step's edges
        played = at_full_rate(np.mean([_play(block_drive(st), r) for r in radii], axis=0), st)
        veff = (1 - w) * st.v_full + w * played
        p.step_d[k] = gain * predict_step(sp, st, veff)[0]
    return p


def delayed(ctx: Context, tau_d: float, tau_i: float = 0.0) -> Prediction:
    """The baseline with the displacement read tau_d and the current tau_i after the recorded drive: exp(-s tau) on
    the FRF, each step's response shifted (a channel at 0 left as it is)."""
    p = baseline(ctx)
    w = 2j * np.pi * np.array([s.f for s in ctx.sines])
    for attr, steps, tau in (("Hd", p.step_d, tau_d), ("Hi", p.step_i, tau_i)):
        if tau:
            setattr(p, attr, getattr(p, attr) * np.exp(-w * tau))
            for k, st in enumerate(ctx.steps):
                steps[k] = np.interp(st.t - tau, st.t, steps[k], left=0.0)
    return p


def _time_delay(th, ctx):
    (tau,) = th
    return delayed(ctx, tau)


def sensor_read(ctx: Context, **changes) -> Prediction:
    """The baseline with the displacement read elsewhere: every specimen ``with_(**changes)`` (the spot's position,
    a flag's lever), the sine FRF and the steps predicted again."""
    p = baseline(ctx)
    at = {q: sp.with_(**changes) for q, sp in ctx.specimens.items()}
    p.Hd = frf_by_pressure(ctx.sines, at)
    for k, st in enumerate(ctx.steps):
        p.step_d[k] = predict_step(specimen_for(at, st.pressure_kPa), st)[0]
    return p


def _sensor_offset(th, ctx):
    # gain, damping and K_t bar are refitted with it (MECH_REFIT): the baseline fit bent them towards the
    # moved zeros, so x_m is judged on the linear path's shape, with the poles free to sit where they are
    (xi,) = th
    return sensor_read(ctx, sensor_x=min(xi, 1.0) * ctx.length)


def frf_by_pressure(sines: list[SineFeature], specimens: dict[float, Specimen], tf=transfer.frf) -> np.ndarray:
    """``tf(f, specimen)`` (the displacement FRF unless given) at each sine's frequency with its pressure's specimen
    (one modal set per pressure)."""
    out = np.zeros(len(sines), complex)
    for q in {s.pressure_kPa for s in sines}:
        idx = [k for k, s in enumerate(sines) if s.pressure_kPa == q]
        out[idx] = tf(np.array([sines[k].f for k in idx]), specimen_for(specimens, q))
    return out


def force_following_frf(ctx: Context, b_kt: float) -> tuple[np.ndarray, np.ndarray]:
    """Per sine: the force the load cell read over the clamp target, rel = F/F0 (nan where unknown), and the
    baseline FRF with K_t bar following it, K_t bar rel^b_kt. Cached per exponent in ``ctx.cache``: a
    finite-difference Jacobian moves one parameter at a time, so most of a fit's evaluations share b_kt."""
    seen = ctx.cache.setdefault("force_following_frf", {})  # exponent -> (rel, Hd), oldest first
    hit = seen.get(float(b_kt))
    if hit is None:
        rel = np.full(len(ctx.sines), np.nan)
        Hd = np.full(len(ctx.sines), np.nan, dtype=complex)
        for k, s in enumerate(ctx.sines):
            if not np.isfinite(s.force_mean) or ctx.force_nominal[k] <= 0:
                continue
            rel[k] = s.force_mean / ctx.force_nominal[k]
            sp = specimen_for(ctx.specimens, s.pressure_kPa)
            Hd[k] = transfer.frf(np.array([s.f]), sp.with_(Kt_bar=sp.Kt_bar * rel[k] ** b_kt))[0]
        if len(seen) >= 64:  # a fit's old exponents: drop the oldest
            del seen[next(iter(seen))]
        hit = seen[float(b_kt)] = (rel, Hd)
    return hit


def creep_since_first_record(ctx: Context) -> np.ndarray:
    """Per sine: rig seconds since the first sine record at its pressure (the clamp settled there)."""
    first: dict = {}
    for s in ctx.sines:
        first[s.pressure_kPa] = min(first.get(s.pressure_kPa, np.inf), s.t_start)
    return np.array([max(s.t_start - first[s.pressure_kPa], 0.0) for s in ctx.sines])


def follow_force(p: "Prediction", ctx: Context, b_kt: float, b_gain: float) -> None:
    """K_t bar and the gain follow the force the load cell reads: Hd = H(K_t bar rel^b_kt) rel^b_gain."""
    rel, Hd = force_following_frf(ctx, b_kt)
    ok = np.isfinite(rel)
    p.Hd[ok] = Hd[ok] * rel[ok] ** b_gain


def _clamp_relaxation(th, ctx):
    loss, tau, b_kt, b_gain = th
    p = baseline(ctx)
    p.force_rel[:] = -loss * (1.0 - np.exp(-creep_since_first_record(ctx) / tau))
    follow_force(p, ctx, b_kt, b_gain)
    return p


def _dehydration(th, ctx):
    rate_d, rate_i = th
    p = baseline(ctx)
    t0 = ctx.feats.t0
    for k, s in enumerate(ctx.sines):
        dt = max(s.t_start - t0, 0.0)
        p.Hd[k] *= np.exp(-rate_d * dt)
        p.Hi[k] *= np.exp(-rate_i * dt)
    for k, st in enumerate(ctx.steps):
        dt = max(st.t_start - t0, 0.0)
        p.step_d[k] = p.step_d[k] * np.exp(-rate_d * dt)
        p.step_i[k] = p.step_i[k] * np.exp(-rate_i * dt)
    return p


def _sensitivity(tf, sp: Specimen, k: float = 0.01):
    """d tf / d ln R_s by central difference: how the response moves when the electrodes' resistance does."""
    lo, hi = (sp.with_(line=dataclasses.replace(sp.line, R_s=sp.line.R_s * (1 + d))) for d in (-k, k))
    return lambda s: (tf(s, hi) - tf(s, lo)) / (2 * k)


def _gauge_strain(disp: np.ndarray, sp: Specimen) -> tuple[np.ndarray, np.ndarray]:
    """Tensile strain of electrode A (delta > 0) and of electrode B from the laser's reading: e = w h / x_m^2."""
    e = disp * sp.geometry.thickness / sp.x_sensor**2
    return np.clip(e, 0, None), np.clip(-e, 0, None)


def _strain_basis(ctx: Context) -> dict:
    """What the strain-resistance extension adds per unit gauge factor, computed once per context.

    Each electrode's resistance grows with its own tensile strain, e = w h / x_m^2 (uniform-curvature reading
    of the laser), dR_A/R = G_A max(e, 0), dR_B/R = G_B max(-e, 0); to first order the response becomes
    y = H v + eps(t) (dH/d ln R_s) v with eps = (dR_A + dR_B)/(2R). Linear in (G_A, G_B): the rectified strain
    gives the fundamental an amplitude-dependent change, odd harmonics (G_A + G_B) and even ones (G_A - G_B).
    Sines: harmonics 1-3 over one period of the baseline's steady state about the record's mean bend (a sine on a
    strip still bent by an earlier record may never cross zero, and then rectifies little: on the tuning bench
    0.1 Hz sines rode on 0.07-1.5 mm as the records' spacing allowed); steps: the product at the record's rate,
    then block-averaged as the step is compared."""
    if "strain" in ctx.cache:
        return ctx.cache["strain"]
    n = 64
    th = 2 * np.pi * np.arange(n) / n
    ph = np.exp(1j * th)
    sines = np.zeros((len(ctx.sines), 2, 2, 3), complex)  # (sine, channel d/i, electrode A/B, harmonic 1-3)
    for q in {s.pressure_kPa for s in ctx.sines}:
        idx = [k for k, s in enumerate(ctx.sines) if s.pressure_kPa == q]
        sp = specimen_for(ctx.specimens, q)
        w = 2j * np.pi * np.array([ctx.sines[k].f for k in idx])
        sens = (_sensitivity(transfer.displacement_tf, sp)(w), _sensitivity(transfer.admittance_tf, sp)(w))
        for j, k in enumerate(idx):
            a = _drive(ctx.sines[k])
            parts = _gauge_strain(ctx.sines[k].bend_m + (ctx.Hd[k] * a * ph).real, sp)  # on the bend it rides on
            for c in range(2):
                sv = (sens[c][j] * a * ph).real
                for el, part in enumerate(parts):
                    sines[k, c, el] = 0.5 * np.fft.fft(part * sv)[1:4] * 2 / n
    steps = []
    for st in ctx.steps:
        sp = specimen_for(ctx.specimens, st.pressure_kPa)
        d, sd, si = timeresp.simulate_many([lambda s: transfer.displacement_tf(s, sp), _sensitivity(transfer.displacement_tf, sp),
                                            _sensitivity(transfer.admittance_tf, sp)], st.v_full, st.fs_full)
        parts = _gauge_strain(d, sp)
        steps.append(np.array([[st.decimate(0.5 * part * sv) for part in parts] for sv in (sd, si)]))  # (channel, electrode, t)
    ctx.cache["strain"] = {"sines": sines, "steps": steps}
    return ctx.cache["strain"]


def _strain_resistance(th, ctx):
    g = np.asarray(th, float)
    p = baseline(ctx)
    if not g.any():
        return p
    basis = _strain_basis(ctx)
    for k, s in enumerate(ctx.sines):
        a = _drive(s)
        for c, (H, h) in enumerate(((p.Hd, p.hd), (p.Hi, p.hi))):
            x1 = H[k] * a
            x = np.array([x1, h[k, 0] * x1, h[k, 1] * x1]) + g @ basis["sines"][k, c]
            H[k], h[k] = x[0] / a, x[1:] / x[0]
    for k, b in enumerate(basis["steps"]):
        p.step_d[k] = p.step_d[k] + g @ b[0]
        p.step_i[k] = p.step_i[k] + g @ b[1]
    return p


def _large_deflection(th, ctx):
    (c3,) = th
    p = baseline(ctx)
    L2 = ctx.length**2
    for k, s in enumerate(ctx.sines):
        a1 = p.Hd[k] * _drive(s)
        g = 1 - 0.75 * c3 * abs(a1) ** 2 / L2
        p.hd[k, 1] = -(c3 / (4 * L2)) * a1**2 / g
        p.Hd[k] *= g
    for k, st in enumerate(ctx.steps):
        p.step_d[k] = p.step_d[k] - c3 * p.step_d[k] ** 3 / L2
    return p


def _mains(th, ctx):
    d50, i50, d60, i60 = th
    p = baseline(ctx)
    p.line = {("d", 50.0): d50 * 1e-6, ("i", 50.0): i50 * 1e-6, ("d", 60.0): d60 * 1e-6, ("i", 60.0): i60 * 1e-6}
    return p


CATALOGUE: dict[str, Extension] = {
    e.name: e
    for e in (
        Extension("back_relaxation", ("K2", "tau2_s"), (0.5, 10.0), (-0.5, 0.2), (2.5, 300.0), _back_relaxation, "H(s)(1 - K2/(tau2 s + 1)): a slow opposing flux"),
        Extension("faradaic_current", ("g1_S", "g3_S_per_V2"), (0.0, 0.0), (-0.05, -0.05), (0.05, 0.05), _faradaic, "parallel odd-polynomial conductance i = g1 v + g3 v^3"),
        Extension("hysteresis", ("weight", "play_V", "gain"), (0.2, 0.05, 1.0), (0.0, 1e-3, 0.2), (1.0, 1.0, 5.0), _hysteresis, "Prandtl-Ishlinskii play operator on the drive (gain refitted)"),
        Extension("time_delay", ("tau_s",), (0.005,), (-0.2, ), (0.2,), _time_delay, "exp(-s tau) on the displacement channel (alpha, gamma, K_t bar refitted)", refit_mechanics=True),
        Extension("sensor_offset", ("x_over_L",), (0.85,), (0.3,), (1.0,), _sensor_offset, "laser spot at x_m < L: read w(x_m) (alpha, gamma, K_t bar refitted)", refit_mechanics=True),
        Extension("clamp_relaxation", ("force_loss", "creep_tau_s", "kt_exponent", "gain_exponent"), (0.05, 500.0, 1.0, 0.0), (-0.2, 20.0, -10.0, -10.0), (0.6, 1e4, 10.0, 10.0), _clamp_relaxation, "clamp force creeps, F = F0 (1 - r (1 - exp(-t/tau))); K_t bar and gain follow it"),
        Extension("dehydration", ("gain_decay_per_s", "conductance_decay_per_s"), (0.0, 0.0), (-1e-3, -1e-3), (1e-2, 1e-2), _dehydration, "gain and conductance decay with time"),
        Extension("strain_resistance", ("gauge_A", "gauge_B"), (10.0, 10.0), (0.0, 0.0), (2000.0, 2000.0), _strain_resistance,
                  "electrode resistance growing with its tensile strain: y = H v + eps(t) dH/dln R_s v (amplitude-dependent gain, even and odd harmonics)"),
        Extension("large_deflection", ("c3",), (0.0,), (-50.0,), (500.0,), _large_deflection, "projection of the arc: delta - c3 delta^3 / L^2"),
        Extension("mains_pickup", ("disp50_um", "cur50_uA", "disp60_um", "cur60_uA"), (1.0, 1.0, 1.0, 1.0), (0.0,) * 4, (1e4,) * 4, _mains, "additive 50/60 Hz line of constant amplitude"),
    )
}

# the first form of each family: the one the simulated bench (the tuning set) was built with
FIRST_FORMS = {"back_relaxation": "single", "faradaic_current": "odd_polynomial", "hysteresis": "play_drive", "time_delay": "delay",
               "sensor_offset": "beam", "clamp_relaxation": "exponential_creep", "dehydration": "exponential", "strain_resistance": "gauge",
               "large_deflection": "cubic", "mains_pickup": "lines"}
CATALOGUE = {k: dataclasses.replace(e, form=FIRST_FORMS[k]) for k, e in CATALOGUE.items()}
