"""A twelfth held-out set for the diagnosis (issue 12), fresh11, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh10.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude (a swelling network pushing water back harder, a
cooperative ordering of the cations, cracks opening one by one, a root lifting off its pad, a slack lead drawn taut),
some on the history (platinum roughened by its own oxidation, silver migrating under bias, friction with a Stribeck
excess, cracks that open at once and close slowly, an adhesive peeling with the bends, a coating cracking with them),
some on time or on the clamp pressure (a jitter buffer, a PTP servo hunting, a stand breathing with the air
conditioning, a hand clamp overshot and backed off, a hydraulic clamp seeping, a strip drying from its cut edges),
some from the building's wiring (a three-phase load switching, a computer's rectifier). Four structures outside the
catalogue (truth "unexplained": water bridging the jaws' contacts, a peristaltic pump's pulses, electrostatic
discharges, the laser head's fan thermostat); clean sessions. All on three bases of new seeds (103-105: the paper
strip, the seed-001 strip on its own sweep, the paper strip 33 mm free) and on the earlier sets' protocol / data-shape
variants plus one new here: a lab whose logger keeps only the sines' steady state and whose manifest is the contract's
minimal one (``settled_sines``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh10 are reused (importing inject_fresh10 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import. Strengths are drawn from
the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case, measured in
memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the column's
sample-to-sample noise at rest, std(diff)/sqrt(2) over the 200 samples before each step record's edge, the median over
the steps; the values for the three bases are in docs/effects.md).

Run: python bench/inject_fresh11.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh10  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lti, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _drive_side, _map_through, _spec
from inject_fresh3 import _cat, _resist, _sign, _through_x
from inject_fresh4 import _clamp_law
from inject_fresh6 import _beam, _blocks, _bursts
from inject_fresh7 import _superpose  # noqa: F401  (kept beside the other tools for later sets)
from inject_fresh8 import _late
from inject_fresh9 import _dry_by, _gaps, _ou, _session_grid
from inject_fresh10 import _station

# the paper's strip 33 mm free (earlier sets used 20, 25, 28, 30, 32, 35, 36, 38, 40, 42 and 45 mm; its 1 V step peaks
# near 10.6 mm, 8.8 mm x (33/30)^2, inside the laser's +-20 mm): registered in every process that imports this module
inject.register_free_length("paper_33", 0.033)

inject.BASES.update({
    "paper_103": ("paper-sweep", "paper", 103),
    "s001_104": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 104),
    "p33_105": ("paper-sweep", "paper_33", 105),
})


# ------------------------------------------------------------------------------------------------ tools


def _walk(s: Session, step: Callable[[float, float, float], float], col: str = "disp_m", x0: float = 0.0,
          rest: Callable[[float, float], float] | None = None) -> dict[int, np.ndarray]:
    """A scalar state through the session in time order, sample by sample: x = step(x, value, dt) on each sample of
    ``col``; over the rests between records rest(x, seconds) (held if None). Returns the state per record."""
    x, t_end, out = x0, None, {}
    for r in _chrono(s):
        t = r.cols["t_s"]
        if t_end is not None and rest is not None:
            x = rest(x, max(float(t[0]) - t_end, 0.0))
        dt = 1.0 / r.fs
        vals = r.cols[col].tolist()
        y = np.empty(len(vals))
        for k, u in enumerate(vals):
            x = step(x, u, dt)
            y[k] = x
        out[id(r)] = y
        t_end = float(t[-1])
    return out


def _reading_at(s: Session, pts: Callable[[Rec, object], list[tuple[float, float, int]]]) -> dict[int, np.ndarray]:
    """inject_fresh6._reading with the stations given per record, pts(record, specimen) = [(c, x, der)]: each record's
    reading sum_j c_j w^(der_j)(x_j) in place of the tip's w(L), through the strip's quasi-static deflections and
    modal parts, with the session's history."""
    kept: dict[tuple[int, int], tuple[np.ndarray, np.ndarray]] = {}

    def get(r: Rec, z: np.ndarray, which: int) -> np.ndarray:
        key = (id(r), z.size)
        if key in kept:
            return kept.pop(key)[which]
        sp = _spec(s, r)
        with np.errstate(divide="ignore", invalid="ignore"):
            st, dy, tst, tdy = _beam(sp, z, pts(r, sp))
            rho = st / tst
            kept[key] = rho, dy - rho * tdy
        return kept[key][which]

    a = _through_x(s, {id(r): r.cols["disp_m"] for r in s.series()}, lambda r: lambda z: get(r, z, 0), 2.0)
    b = _through_x(s, {id(r): r.cols["v_V"] for r in s.series()}, lambda r: lambda z: get(r, z, 1), 2.0)
    return {k: a[k] + b[k] for k in a}


def _path(s: Session, weight: Callable[[np.ndarray], np.ndarray]) -> tuple[list[Rec], np.ndarray, np.ndarray]:
    """The session's displacement path in time order: the records, the concatenated times and the running sum of
    abs(dd) weight(d) (0 at the session's first sample)."""
    recs, d, _ = _cat(s, "disp_m")
    t = np.concatenate([r.cols["t_s"] for r in recs])
    dd = np.abs(np.diff(d, prepend=d[0]))
    return recs, t, np.cumsum(dd * weight(d))


# ------------------------------------------------------------------------------------------------ back relaxation


def br_network_stiffening(s: Session) -> None:
    """The membrane's network resists the swelling the bend has pushed to the cathode side more than in proportion
    (the elastic pressure of a swollen polymer network, Flory-Rehner, grows steeply with the local uptake): the water
    that flows back is driven harder after a large bend. A lag x of the bend (tau 3-10 s, log) through the session in
    time order (the state carried over the rests, the displacement linear across them), read d - K2(x) x with K2(x)
    = K0 + (K1 - K0) tanh^2(x/x_h): K0 0.3-0.6 for small bends, K1 1.0-1.3 for large ones, x_h 0.4-0.9 of the
    displacement scale: the 0.5 V sines relax back far less than the 1 V records.
    Displacement only. Measured (paper_103): displacement RMS -64 % (residual 115 %), the 1 V steps' peaks
    -64 %, reversing to -0.86 mm by the plateau's end; the 0.5 V sines at 0.1 Hz residual 15 % against the 1 V
    harmonic's 90-101 %, the 20 Hz records' 8-12 %."""
    tau, k0, k1 = lu(s.rng, 3.0, 10.0), s.rng.uniform(0.3, 0.6), s.rng.uniform(1.0, 1.3)
    xh = s.rng.uniform(0.4, 0.9) * ref_disp(s)
    x, d_end = 0.0, 0.0
    for r, gap in _gaps(s, 1.0):
        d = r.cols["disp_m"]
        for dt, u in gap:
            x += -math.expm1(-dt / tau) * (d_end + u * (float(d[0]) - d_end) - x)
        a = math.exp(-1.0 / (r.fs * tau))
        out = np.empty(d.size)
        for k, dk in enumerate(d.tolist()):
            x = dk + (x - dk) * a
            out[k] = x
        d_end = float(d[-1])
        r.cols["disp_m"] = d - (k0 + (k1 - k0) * np.tanh(out / xh) ** 2) * out


def br_mixed_cations(s: Session) -> None:
    """The bath carries a bulky organic cation (a quaternary ammonium from a cationic detergent left in the cuvette,
    or a TBA+ salt from an earlier test) that has taken part of the sites: the small hydrated cations give the fast
    bend and flow back (K2 0.9-1.3, tau2 2-8 s, log), and the bulky ones, slow and carrying little water, creep the
    other way afterwards, a forward creep K3 0.3-0.6 K2 with tau3 4-10 tau2 (log): 1 - K2/(tau2 s + 1) + K3/(tau3 s
    + 1), a step that rises, relaxes back, and is held up by the slow forward creep. Through the lag pair with the
    session's history
    (300 s). Displacement only. Measured (p33_105): displacement RMS -72 % (residual 84 %), the 1 V steps' peaks -73 %,
    +1.85 mm by the plateau's end (10.6 mm clean); the 0.5 V sines at 0.1 Hz residual 26-27 %, the 20 Hz records'
    11-18 %."""
    k2, t2 = s.rng.uniform(0.9, 1.3), lu(s.rng, 2.0, 8.0)
    k3, t3 = k2 * s.rng.uniform(0.3, 0.6), t2 * lu(s.rng, 4.0, 10.0)
    _map_through(s, lambda r: lambda z: 1 - k2 / (t2 * z + 1) + k3 / (t3 * z + 1), 300.0)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_pt_roughening(s: Session) -> None:
    """Electrolysis (symmetric Butler-Volmer, 2 i0 sinh(v/2v_t), v_t 0.1-0.2 V, 0.08-0.25 mA at 1 V on the fresh
    electrode, log) on platinum that its own oxidation-reduction cycles roughen (place exchange on every excursion
    past the oxide's onset, 0.5-0.7 V, leaves the surface rougher: the true area grows with the charge passed there):
    the exchange current grows with the anodic charge passed above the onset so far, x (1 + (a - 1) Q(t)/Q_end), a
    1.5-3 by the session's end: a faradaic current that grows through the session, in steps at the 1 V records, and
    never recedes. Current only. Measured (s001_104): current residual 2.6 % of its RMS (5.0x its noise); the 1 V steps'
    plateaus +0.13, +0.16, +0.18, +0.21 mA block by block."""
    i1, vt = lu(s.rng, 8e-5, 2.5e-4), s.rng.uniform(0.1, 0.2)
    von, a = s.rng.uniform(0.5, 0.7), s.rng.uniform(1.5, 3.0)
    branch = lambda v: np.sinh(v / (2 * vt)) / math.sinh(1 / (2 * vt))  # noqa: E731
    recs = _chrono(s)
    q = [np.clip(np.abs(branch(r.cols["v_V"])) * (np.abs(r.cols["v_V"]) > von), 0, None) / r.fs for r in recs]
    cum = np.cumsum(np.concatenate(q))
    cum = cum / max(float(cum[-1]), 1e-30)
    for r, c in zip(recs, np.split(cum, np.cumsum([x.size for x in q])[:-1])):
        r.cols["i_A"] = r.cols["i_A"] + i1 * (1 + (a - 1) * c) * branch(r.cols["v_V"])


def far_silver_migration(s: Session) -> None:
    """The leads are fixed to the electrodes near the root with silver paint (or silver epoxy), and silver migrates
    through the wet membrane under bias (electrochemical migration: Ag+ dissolved at the anode, deposited as
    dendrites growing from the cathode): a conducting bridge whose state w (0-1) grows while the drive exceeds a
    threshold, dw/dt = k (abs(v) - v_th)+ (1 - w) (v_th 0.3-0.6 V; k so that a held 1 V grows w to 0.3-0.7 in 20 s),
    and whose thin necks dissolve again at lower drive, w/tau_d (tau_d 30-200 s, log); the bridge conducts ohmically,
    i = g w v (g 0.3-0.8 mS at w = 1, log). A current that builds along each held 1 V step and fades over the
    rests; the 0.5 V sines hardly grow it. Sample by sample through the session in time order. Current only.
    Measured (p33_105): current residual 4.0 % of its RMS (2.1x its noise); on every 1 V
    step the added current rises from 0 at the edge to 0.39 mA by the plateau's end."""
    vth, tau_d, g = s.rng.uniform(0.3, 0.6), lu(s.rng, 30.0, 200.0), lu(s.rng, 3e-4, 8e-4)
    k = -math.log(1 - s.rng.uniform(0.3, 0.7)) / ((1 - vth) * 20.0)

    def step(w: float, v: float, dt: float) -> float:
        grow = k * max(abs(v) - vth, 0.0)
        rate = grow + 1 / tau_d
        eq = grow / rate
        return eq + (w - eq) * math.exp(-rate * dt)

    w = _walk(s, step, "v_V", rest=lambda w, T: w * math.exp(-T / tau_d))
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + g * w[id(r)] * r.cols["v_V"]


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_cooperative(s: Session) -> None:
    """The cations' ordering in the clusters as a cooperative (mean-field, Weiss / Frumkin) transition on the drive:
    the ordered share M follows M = tanh((u + J M)/T), u the drive over the session's peak, with a coupling J above
    the width T (J/T 1.05-1.3, T 0.15-0.3): two stable branches that M keeps until its own disappears (at u =
    +-u_c, a few thousandths to 0.03 of the peak), where the whole population flips together: a loop of smooth
    branches with jumps, and a
    gain that saturates at large drive. Gamma = (1 - h) v + h V_peak M/M(1), h 0.04-0.08; the branch through the
    session in time order, through the strip's measured step response (inject_fresh2._drive_side); current
    untouched. Measured (paper_103): displacement RMS +8.6 % (residual 13 %, 780x its noise); the 1 V
    steps' peaks +5.1 %, the 1 V harmonic's residual 12-14 %, the 0.5 V sines' at 0.1 Hz 57 %, the 20 Hz records'
    2000-2400 % (the remanence's change through the strip's step response, on 5 um of signal)."""
    T = s.rng.uniform(0.15, 0.3)
    J, h = T * s.rng.uniform(1.05, 1.3), s.rng.uniform(0.04, 0.08)
    ms = math.sqrt(1 - T / J)
    uc = J * ms - T * math.atanh(ms)
    M = np.linspace(ms, 1 - 1e-9, 4000)
    U = T * np.arctanh(M) - J * M  # the upper branch, u rising from -u_c
    up = lambda u: np.interp(u, U, M, left=ms)  # noqa: E731
    recs = _chrono(s)
    v = np.concatenate([r.cols["v_V"] for r in recs])
    vp = max(float(np.max(np.abs(v))), 1e-9)
    u = v / vp
    ev = np.where(u > uc, 1.0, np.where(u < -uc, -1.0, 0.0))
    ev[0] = ev[0] or -1.0
    idx = np.where(ev != 0, np.arange(ev.size), 0)
    branch = ev[np.maximum.accumulate(idx)]
    m = np.where(branch > 0, up(u), -up(-u))
    gam = (1 - h) * v + h * vp * m / float(up(1.0))
    _drive_side(s, lambda _v: gam)


def hy_lugre_drive(s: Session) -> None:
    """Friction of the cations pinned in the cluster channels as a LuGre (bristle) law on the drive: the strain lags
    the drive by the bristles' deflection z, dz = dv - abs(dv) z/g(dv/dt), g = F_c + (F_s - F_c) exp(-(rate/v_s)^2)
    (a Stribeck excess: the static level F_s 1.5-2.5 F_c above the sliding one, F_c 0.04-0.1 V, v_s 0.5-3 V/s, log):
    slow drives meet the static friction and lag more, fast ones the sliding friction; Gamma = v - h z, h 0.15-0.3: a
    loop that stays as f -> 0 and narrows as the sines get faster. Sample by sample through the session in time
    order (z held over the rests), through the strip's measured step response (inject_fresh2._drive_side); current
    untouched. Measured (s001_104): displacement residual 3.2 % of its RMS (99x its noise); the 1 V steps'
    peaks 0.0 % in the first block, +1.2 % after it; the 1 V harmonic's residual 1.5 %, the 0.5 V sines' at 0.1 Hz
    24 %, the 20 Hz records' 59-80 %."""
    fc = s.rng.uniform(0.04, 0.1)
    fs_, vs, h = fc * s.rng.uniform(1.5, 2.5), lu(s.rng, 0.5, 3.0), s.rng.uniform(0.15, 0.3)
    prev = [0.0]

    def step(z: float, v: float, dt: float) -> float:
        dv = v - prev[0]
        prev[0] = v
        if dv == 0.0:
            return z
        g = fc + (fs_ - fc) * math.exp(-((dv / dt) / vs) ** 2)
        zs = math.copysign(g, dv)
        return zs + (z - zs) * math.exp(-abs(dv) / g)

    z = _walk(s, step, "v_V")
    recs = _chrono(s)
    gam = np.concatenate([r.cols["v_V"] - h * z[id(r)] for r in recs])
    _drive_side(s, lambda _v: gam)


# ------------------------------------------------------------------------------------------------ time delay


def td_jitter_buffer(s: Session) -> None:
    """The laser's readings reach the host over a wireless link (Bluetooth LE or Wi-Fi: a battery laser head, or a
    sensor hub) whose receiver plays them out through an adaptive jitter buffer: its playout delay sits at a floor of
    3-10 ms (log), jumps up to cover a packet that came late (Poisson, 0.005-0.03 per s: a rival transmitter, a
    retry burst) by 3-15 ms (log), and is brought back down slowly, 0.3-1.5 ms per s (the receiver shortens its
    buffer by dropping samples), never below the floor. A delay that jumps and sags, on the session clock (the link
    and its buffer run through the rests). Through inject_fresh8._late; displacement only. Measured (p33_105):
    delay 3.4-18 ms (median 3.4 ms), displacement residual 0.10 % of its RMS (6.6x its noise), the 20 Hz records'
    residuals 33-84 %."""
    d0, rate, fall = lu(s.rng, 3e-3, 10e-3), s.rng.uniform(0.005, 0.03), s.rng.uniform(3e-4, 1.5e-3)
    tg = _session_grid(s, 0.05, 120.0)
    n = int(s.rng.poisson(rate * (tg[-1] - tg[0])))
    events = sorted(zip(s.rng.uniform(tg[0], tg[-1], n), [lu(s.rng, 3e-3, 15e-3) for _ in range(n)]))
    ex, j, out = 0.0, 0, np.empty(tg.size)
    for k, t in enumerate(tg):
        if k:
            ex = max(ex - fall * (t - tg[k - 1]), 0.0)
        while j < len(events) and events[j][0] <= t:
            ex = max(ex, events[j][1])
            j += 1
        out[k] = d0 + ex
    _late(s, lambda r, t: np.interp(t, tg, out))


def td_ptp_hunting(s: Session) -> None:
    """The laser controller stamps its readings on a clock disciplined by IEEE 1588 (PTP) over the lab's network,
    and the controller's PI servo is tuned too tight for the path's asymmetry wander: the clock hunts, its offset
    from the DAQ's oscillating about the stream's fixed latency (3-8 ms, log) by +-1-4 ms (at most 0.8 of the
    latency) with a period of 20-120 s (log) and a second harmonic (0.1-0.3, the servo's clipping). A delay that
    swings smoothly through every record, on the session clock. Through inject_fresh8._late; displacement only.
    Measured (paper_103): delay 5.7-7.6 ms, displacement residual 0.16 % of its RMS (9.6x its
    noise), the 20 Hz records' residuals 37-58 %."""
    d0 = lu(s.rng, 3e-3, 8e-3)
    a, per = min(s.rng.uniform(1e-3, 4e-3), 0.8 * d0), lu(s.rng, 20.0, 120.0)
    h2, ph, ph2 = s.rng.uniform(0.1, 0.3), s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi)

    def delay(r: Rec, t: np.ndarray) -> np.ndarray:
        w = 2 * np.pi * t / per
        return d0 + a * (np.sin(w + ph) + h2 * np.sin(2 * w + ph2)) / (1 + h2)

    _late(s, delay)


# ------------------------------------------------------------------------------------------------ sensor offset


def so_hvac_stand(s: Session) -> None:
    """The laser on a tall stand (a post and boom, 0.3-0.5 m of aluminium) beside the strip, the room's air
    conditioning cycling its temperature: the boom's expansion and the post's bending with the warm side move the
    spot along the strip, a few millimetres' lever on a fraction of a kelvin: the station breathes with the cycle,
    from the tip to 4-10 % of L inboard and back (period 600-1800 s, the boom's thermal lag rounding the triangle
    into a sine). Read through the strip's own transfer functions at the station (inject_fresh10._station);
    displacement only. Measured (s001_104): displacement RMS -7.2 % (residual 7.3 %), the 1 V steps'
    peaks -5.6, -8.2, -8.3, -7.0 % as the cycle goes, the 20 Hz records' residuals 0.5-6.2 %."""
    dlt, per, ph = s.rng.uniform(0.04, 0.1), s.rng.uniform(600.0, 1800.0), s.rng.uniform(0, 2 * np.pi)
    _station(s, lambda r: 1 - dlt * (0.5 + 0.5 * np.sin(2 * np.pi * r.cols["t_s"] / per + ph)), 1 - dlt)


def so_flag_peel(s: Session) -> None:
    """A thin reflective foil (or a paper target, for a strip too dark to read) glued over the last 15-35 % of the
    strip, ending at the tip: at first it follows the strip and the laser reads the tip. Each bend works its adhesive,
    and the foil peels from its outer end inward, its free part a rigid tangent from the peel front x_p: the laser
    reads w(x_p) + (L - x_p) w'(x_p), a tangent extrapolation from a station that moves inboard with the bending path
    so far (the running sum of the bend's changes over the session's, to the peel's full 15-35 % of L by the end; per
    record at its mean). Through the strip's quasi-static deflections and modal parts (inject_fresh6._beam);
    displacement only. Measured (paper_103): displacement RMS -2.2 % (residual 3.1 %), the 1 V steps' peaks 0.0, -0.7,
    -2.5, -5.5 % block by block, the 20 Hz records' residuals 0.5-18 %."""
    pmax = s.rng.uniform(0.15, 0.35)
    recs, t, cum = _path(s, lambda d: np.ones_like(d))
    frac = cum / max(float(cum[-1]), 1e-30)
    cuts = np.cumsum([r.cols["t_s"].size for r in recs])[:-1]
    at = {id(r): pmax * float(np.mean(f)) for r, f in zip(recs, np.split(frac, cuts))}

    def pts(r: Rec, sp) -> list[tuple[float, float, int]]:
        L = sp.geometry.length
        x = L * (1 - at[id(r)])
        return [(1.0, x, 0), (L - x, x, 1)]

    new = _reading_at(s, pts)
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_overshoot_backoff(s: Session) -> None:
    """A hand-set clamp: at each re-clamping the operator tightens past the target (by 10-25 %), watches the load
    cell for 40-90 s while the pads relax, then backs off to the target and starts the block 10-40 s later. The pads
    as a linear viscoelastic solid with a fast and a slow arm (G(t) = 1 - g1 (1 - exp(-t/tau1)) - g2 (1 -
    exp(-t/tau2)), g1 0.04-0.1, tau1 8-25 s, g2 0.05-0.12, tau2 400-1500 s, log) under that gap history (Boltzmann
    superposition of the overshoot's step and the back-off's): after the back-off the pads first recover (the force
    rises by a few tenths of a percent over a minute), then relax slowly, the same law in every block. Through the
    preset's clamp law (inject_fresh4._clamp_law). Measured (p33_105): the load cell up to 1.004 of its setting
    after the back-off, down to 0.94 by the blocks' ends; displacement residual 0.07 % (5x its noise), current
    0.37 % (0.19x), the 4287 kPa block's 20 Hz record 11 %."""
    g1, t1 = s.rng.uniform(0.04, 0.1), lu(s.rng, 8.0, 25.0)
    g2, t2 = s.rng.uniform(0.05, 0.12), lu(s.rng, 400.0, 1500.0)
    G = lambda t: 1 - g1 * -np.expm1(-np.clip(t, 0, None) / t1) - g2 * -np.expm1(-np.clip(t, 0, None) / t2)  # noqa
    hist = {p: (s.rng.uniform(0.1, 0.25), s.rng.uniform(40.0, 90.0), s.rng.uniform(10.0, 40.0))
            for p in sorted(_blocks(s))}

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        o, hold, lead = hist[p]
        tb = t_set - lead
        F = lambda x: (1 + o) * G(x - tb + hold) - o * G(x - tb)  # noqa: E731
        return F(t) / F(np.array([tb]))[0]

    _clamp_law(s, rel)


def cr_orifice_leak(s: Session) -> None:
    """A small hydraulic clamp (a syringe-type cylinder set with a hand pump through a check valve) whose valve seat
    seeps: oil leaves through a turbulent orifice, flow ~ sqrt(pressure), so the force falls as dF/dt = -k sqrt(F),
    F/F_set = (1 - t k/(2 sqrt F_set))^2 from each setting: a finite-time law (a parabola), and, the leak growing only
    as the square root of the pressure, the low blocks lose the larger share (the highest sqrt(p_min/p) of the
    lowest's). k set so the lowest block loses 6-14 % over the session's median block length. Through the preset's
    clamp law (inject_fresh4._clamp_law). Measured (paper_103): the load cell down to 0.87, 0.90, 0.95, 0.95 of
    its setting by the blocks' ends; displacement residual 0.05 % (3.2x its noise), current 0.45 % (0.23x), the
    4287 kPa block's 20 Hz record 13 %."""
    ps = s.pressures()
    T = float(np.median([b - a for a, b in _blocks(s).values()])) or 1.0
    loss = s.rng.uniform(0.06, 0.14)
    k = 2 * math.sqrt(ps[0]) * (1 - math.sqrt(1 - loss)) / T  # in sqrt(kPa) per second

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        return np.clip(1 - np.clip(t - t_set, 0, None) * k / (2 * math.sqrt(p)), 0.0, None) ** 2

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_coating_crack(s: Session) -> None:
    """A strip in air encapsulated against drying (a parylene or PDMS coat, or a wrap of cling film) whose coating
    cracks with use: water leaves through a pinhole at first (a share a0 0.05-0.2 of the final leak) and through
    cracks that grow with every large bend (Paris-like: the damage is the bend's path weighted by (abs(d)/d_max)^m,
    m 2-4, through the session in time order), so the strip dries slowly, then faster after the large records, and
    keeps drying through the rests at the leak reached. Loss = total int(a0 + (1 - a0) D/D_end) dt normalised,
    total 0.1-0.25 by the session's end; gain x (1 - loss), conductance x (1 - c loss), c 0.3-0.8, the spectra
    following (inject_fresh9._dry_by). Measured (s001_104): displacement RMS -6.6 % (residual 9.0 %), the 1 V steps'
    peaks 0.0, -2.9, -8.3, -16 % block by block; current -3.7 % (8.8x its noise)."""
    tot, a0, m, c = s.rng.uniform(0.1, 0.25), s.rng.uniform(0.05, 0.2), s.rng.uniform(2.0, 4.0), s.rng.uniform(0.3, 0.8)
    dmax = max(float(np.max(np.abs(r.cols["disp_m"]))) for r in s.series()) or 1.0
    _, t, D = _path(s, lambda d: (np.abs(d) / dmax) ** m)
    D = D / max(float(D[-1]), 1e-30)
    tg = _session_grid(s, 1.0)
    leak = a0 + (1 - a0) * np.interp(tg, t, D, left=0.0)
    cum = np.r_[0.0, np.cumsum(0.5 * (leak[1:] + leak[:-1]) * np.diff(tg))]
    loss = tot * cum / max(float(cum[-1]), 1e-30)
    _dry_by(s, lambda x: np.interp(x, tg, loss), lambda x: c * np.interp(x, tg, loss))


def dh_edge_drying(s: Session) -> None:
    """A strip in air dries from its cut long edges first (the plated faces hold their water better than the bare
    cut membrane): a dry band grows in from each edge as the square root of time (Fickian, from the mounting 0-600 s
    before the first record) to 1.5-4 % of the width each by the session's end. The dry bands carry no charge and no
    actuation, and they are stiffer (dry Nafion 1.5-3x the wet modulus): the tip's gain follows a/(a + k(1 - a)) of
    the active share a of the width, the conductance a: the gain falls faster than the current. Through
    inject_fresh9._dry_by, the spectra following. Measured (s001_104): displacement RMS -5.8 % (residual 6.2 %), the
    1 V steps' peaks -2.4, -5.3, -7.1, -8.4 % block by block; current -4.1 % (8.0x its noise)."""
    de, k, tm = s.rng.uniform(0.015, 0.04), s.rng.uniform(1.5, 3.0), s.rng.uniform(0.0, 600.0)
    span = s.t1 - s.t0 + tm

    def a(t: np.ndarray) -> np.ndarray:
        return 1 - 2 * de * np.sqrt(np.clip(t - s.t0 + tm, 0, None) / span)

    _dry_by(s, lambda t: 1 - a(t) / (a(t) + k * (1 - a(t))), lambda t: 1 - a(t))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_discrete_cracks(s: Session) -> None:
    """A strip with a few large cracks across its tensioned electrode (a hand-cut strip, or one bent hard once): each
    crack opens at its own strain and, once open, adds its own resistance, so the face's resistance climbs in steps
    with the tension: dR/R = sum_j R_j clip((e - e_j)/w, 0, 1), 4-10 cracks opening at e_j spread over 0.2-1 of the
    session's largest tension (side drawn), each over w 0.02-0.05 of it, their shares log-normal (sigma 0.5),
    summing to 1; the compressed face unchanged. Gains fall by 0.02-0.06 (displacement), 0.05-0.15 (current) per
    unit (inject_fresh3._resist). Measured (paper_103): displacement RMS -2.6 % (residual 3.1 %, 190x its noise), the 1
    V steps' peaks -5.1 %, current residual 0.8 % (0.4x its noise)."""
    side, n = _sign(s), int(s.rng.integers(4, 11))
    ref = ref_disp(s)
    emax = max(float(np.max(side * r.cols["disp_m"])) for r in s.series()) / ref
    ej = np.sort(s.rng.uniform(0.2, 1.0, n)) * emax
    w = s.rng.uniform(0.02, 0.05) * emax
    rj = np.exp(s.rng.normal(0, 0.5, n))
    rj = rj / rj.sum()

    def shape(r: Rec, x: np.ndarray) -> np.ndarray:
        e = side * x
        return np.sum(rj[:, None] * np.clip((e[None, :] - ej[:, None]) / w, 0, 1), axis=0)

    _resist(s, shape, (0.02, 0.06), (0.05, 0.15))


def sr_peak_hold(s: Session) -> None:
    """Cracks that open at once as the electrode is stretched but close only as the polymer beneath recovers
    viscoelastically: each face's crack opening follows its tension up instantly and back down with tau_c 1-8 s
    (log), c = max(e+, e+ + (c - e+) exp(-dt/tau_c)), through the session in time order (closing over the rests):
    a sine faster than 1/tau_c keeps the cracks near their peak opening all cycle (a gain loss with the amplitude and
    few harmonics), a slow one opens and closes them (even harmonics). The tensioned face (side drawn) with the other
    at 0.1-0.4 of its gauge; gains fall by 0.02-0.06 (displacement), 0.05-0.15 (current) per unit of the
    session's largest bend (inject_fresh3._resist). Measured (s001_104): displacement RMS -2.1 % (residual 2.2 %, 67x
    its noise), the 1 V steps' peaks -2.7 %, current residual 1.6 % (3.0x its noise)."""
    side, tc, o = _sign(s), lu(s.rng, 1.0, 8.0), s.rng.uniform(0.1, 0.4)
    ref = max(float(np.max(np.abs(r.cols["disp_m"]))) for r in s.series()) or 1.0  # per unit of the largest bend

    def held(sgn: float) -> dict[int, np.ndarray]:
        def step(c: float, d: float, dt: float) -> float:
            e = max(sgn * d / ref, 0.0)
            return max(e, e + (c - e) * math.exp(-dt / tc))

        return _walk(s, step, "disp_m", rest=lambda c, T: c * math.exp(-T / tc))

    a, b = held(side), held(-side)
    _resist(s, lambda r, x: a[id(r)] + o * b[id(r)], (0.02, 0.06), (0.05, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_root_uplift(s: Session) -> None:
    """The strip's root on compliant pads behaves as a rigid footing on a tensionless elastic bed: the pads' contact
    carries the root's moment linearly (the root's share c 0.03-0.08 of the tip's motion, in the clamp law's linear
    compliance) until the strip lifts off the pad's edge on its tension side (the contact width shrinking from the
    full jaw), beyond which the root turns faster: phi/phi_u = 4/(3 - M/M_u)^2 (the Winkler footing's uplift law,
    smooth at M_u). The clamp's force presses the contact, so the uplift bend grows with the pressure, d_u = d_u0
    p/p_min (d_u0 0.5-0.8 of the lowest block's largest bend): the lowest block's large steps read more than linear,
    the higher blocks hardly. Displacement only. Measured (p33_105): the 1 V steps' peaks +3.1, 0.0, 0.0, 0.0 %
    block by block, displacement RMS +0.2 % (residual 0.7 %, 45x its noise)."""
    c, du0 = s.rng.uniform(0.03, 0.08), s.rng.uniform(0.5, 0.8)
    pmin = min(s.pressures())
    dlow = max(float(np.max(np.abs(r.cols["disp_m"]))) for r in s.series() if float(r.entry["pressure_kPa"]) == pmin)

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        du = du0 * dlow * float(r.entry["pressure_kPa"]) / pmin
        x = np.abs(d) / du
        F = np.where(x <= 1, x, 4 / (3 - np.minimum(x, 2.5)) ** 2)
        return d + c * du * np.sign(d) * (F - x)

    map_disp(s, read)


def ld_taut_lead(s: Session) -> None:
    """A fine lead wire (a sense lead, or a thermocouple's) attached at the tip and running on along the strip's axis
    to a post beyond it, left with a little slack: past a bend d_s (0.4-0.7 of the session's largest) the lead is
    drawn taut, and a taut string pulls the tip back by its tension times its angle, T y/sqrt(l^2 + y^2), T growing
    with its stretch sqrt(l^2 + y^2) - l_0 (a geometric stiffening: cubic-like, symmetric, from the slack on). The
    lead's loop is soft (its stiffness 0.3-1.5 of the tip's, in tip units), its span l 1.5-3 of the largest bend.
    The tip's quasi-static balance y - d = -kappa (stretch)+ y/sqrt(l^2 + y^2) solved sample by sample (bisection).
    Displacement only. Measured (s001_104): the 1 V steps' peaks -3.5 %, displacement RMS -1.5 % (residual 2.0 %,
    61x its noise)."""
    dmax = max(float(np.max(np.abs(r.cols["disp_m"]))) for r in s.series()) or 1.0
    ds, kap, lam = s.rng.uniform(0.4, 0.7) * dmax, s.rng.uniform(0.3, 1.5), s.rng.uniform(1.5, 3.0) * dmax
    l0 = math.hypot(lam, ds)

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        a = np.abs(d)
        lo, hi = np.minimum(a, ds), a.copy()
        for _ in range(50):
            y = 0.5 * (lo + hi)
            g = y - a + kap * np.clip(np.hypot(lam, y) - l0, 0, None) * y / np.hypot(lam, y)
            lo, hi = np.where(g < 0, y, lo), np.where(g < 0, hi, y)
        return np.sign(d) * np.where(a > ds, 0.5 * (lo + hi), a)

    map_disp(s, read)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_phase_balance(s: Session) -> None:
    """Pickup from the building's three-phase wiring: the cables behind the bench carry the three phases (the
    lab's heaters and pumps on different phases), and the field at the rig is their imbalance, sum_k a_k
    exp(j(w t + 2 pi k/3)): each phase's load switches between a low (0.2-0.5) and a full share at random
    (0.005-0.02 switchings per s per phase), so the hum's amplitude and phase jump at every switching, with a third
    harmonic 0.05-0.2 (the triplens add up on the neutral). 50 or 60 Hz (+-0.05), phase locked to the session clock,
    on both lines with their own coupling phases: 1.5-5 um and 3-10 uA (log) at the imbalance's session mean.
    Measured (paper_103): displacement 2.5 um RMS (4.5x its noise), current 4.5 uA RMS (0.07x),
    the 20 Hz records' displacement residuals up to 56 %."""
    f = (50.0 if s.rng.random() < 0.5 else 60.0) + s.rng.uniform(-0.05, 0.05)
    ad, ai, h3 = lu(s.rng, 1.5e-6, 5e-6), lu(s.rng, 3e-6, 1e-5), s.rng.uniform(0.05, 0.2)
    pd, pi_ = s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi)
    tg = _session_grid(s, 0.5, 10.0)
    z = np.zeros(tg.size, complex)
    for k in range(3):
        lo, rate = s.rng.uniform(0.2, 0.5), s.rng.uniform(0.005, 0.02)
        n = int(s.rng.poisson(rate * (tg[-1] - tg[0])))
        flips = np.sort(s.rng.uniform(tg[0], tg[-1], n))
        state = (np.searchsorted(flips, tg) + int(s.rng.integers(0, 2))) % 2
        z = z + np.where(state == 1, 1.0, lo) * np.exp(2j * np.pi * k / 3)
    z = z / max(float(np.mean(np.abs(z))), 1e-9)
    for r in s.series():
        t = r.cols["t_s"]
        zt = z[np.clip(np.searchsorted(tg, t, side="right") - 1, 0, tg.size - 1)]  # held per 0.5 s cell: the switchings
        w = 2 * np.pi * f * t
        for col, amp, p in (("disp_m", ad, pd), ("i_A", ai, pi_)):
            third = zt**3 / np.maximum(np.abs(zt), 1e-9) ** 2  # the triplens' resultant, at the fundamental's size
            wave = np.real(zt * np.exp(1j * (w + p))) + h3 * np.real(third * np.exp(3j * (w + p)))
            r.cols[col] = r.cols[col] + amp * wave


def mp_pc_leakage(s: Session) -> None:
    """The logging computer's switch-mode supply (no power-factor correction) draws its current from the line in
    narrow pulses at each voltage peak (its capacitor-input rectifier conducts over +-15-35 deg of each peak), and
    part of that current returns through the USB cable's shield into the DAQ's ground (its EMI filter's Y capacitors
    and a shared earth): both single-ended inputs see the pulse train, odd harmonics falling slowly; its size follows
    the computer's load (an Ornstein-Uhlenbeck wander of +-20-40 %, 5-30 s: the acquisition software and the screen).
    50 or 60 Hz (+-0.05), phase locked to the session clock: 1-4 um and 3-10 uA (log) at the pulses' peaks.
    Measured (p33_105): displacement 0.67 um RMS (1.1x its noise), current 3.0 uA RMS (0.05x),
    in pulses over 19 % of the samples (1.5 um and 6.8 uA RMS there)."""
    f = (50.0 if s.rng.random() < 0.5 else 60.0) + s.rng.uniform(-0.05, 0.05)
    beta = np.deg2rad(s.rng.uniform(15.0, 35.0))
    ad, ai = lu(s.rng, 1e-6, 4e-6), lu(s.rng, 3e-6, 1e-5)
    ph, swing, tau = s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0.2, 0.4), s.rng.uniform(5.0, 30.0)
    sd, si = _sign(s), _sign(s)
    tg = _session_grid(s, 0.5, 10.0)
    load = 1 + swing * np.clip(_ou(s, tg, tau), -2.5, 2.5) / 2.5
    cb = math.cos(beta)
    for r in s.series():
        t = r.cols["t_s"]
        c = np.cos(2 * np.pi * f * t + ph)
        pulse = (np.clip(c - cb, 0, None) - np.clip(-c - cb, 0, None)) / (1 - cb)
        g = np.interp(t, tg, load) * pulse
        r.cols["disp_m"] = r.cols["disp_m"] + sd * ad * g
        r.cols["i_A"] = r.cols["i_A"] + si * ai * g


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_droplet_short(s: Session) -> None:
    """Water bridging the two jaws' contacts outside the strip (a droplet left by a re-wetting or a splash at a
    re-clamping, running down between the contact plates): an ohmic path in parallel with the strip, G 0.2-0.8 mS
    (log: 0.2-0.8 mA at 1 V) while it lasts, in 3-7 spells of 20-200 s (log) starting inside recorded series, each
    forming within half a second and thinning as it evaporates or wicks away (G (1 - u)^0.5 over the spell). The
    current amplifier measures the bridge's current beside the strip's; the strip's drive, its bend and the voltage
    know nothing of it. Current only. Measured (s001_104): 8.7 % of the current's samples touched, residual
    there 114 uA RMS (7.6x its noise); (paper_103): 2.7 %, 82 uA (1.3x)."""
    g0 = lu(s.rng, 2e-4, 8e-4)
    spells = _bursts(s, int(s.rng.integers(3, 8)), (20.0, 200.0))
    for r in s.series():
        t = r.cols["t_s"]
        G = np.zeros(t.size)
        for a, b in spells:
            u = (t - a) / (b - a)
            inside = (u >= 0) & (u < 1)
            G = G + np.where(inside, g0 * np.sqrt(np.clip(1 - u, 0, 1)) * np.clip((t - a) / 0.5, 0, 1), 0.0)
        r.cols["i_A"] = r.cols["i_A"] + G * r.cols["v_V"]


def out_peristaltic(s: Session) -> None:
    """The bath is perfused (fresh water or electrolyte, to hold its temperature and composition) by a peristaltic
    pump: each roller's release drops the flow and the outlet's jet into the cuvette pulses with it, so the drag on
    the strip carries a periodic train at the roller frequency (3 rollers at 20-100 rpm: 1-5 Hz, the motor's speed
    wandering +-0.5 %), sharp dips, |sin|^q with q 2-6, and the strip answers it through its first mode (f1 and its
    damping from labrig.physics.transfer.modal_set at the record's pressure, static gain 1): 3-10 um peak to peak
    (log) of forcing. Not mains, not the drive, in the band of the strip's sines. Displacement only. Measured
    (paper_103): 6.2 um RMS (11x its noise), the 20 Hz records' residuals 99-109 %; (p33_105): 2.7 um RMS (4.6x),
    20 Hz 32-36 %."""
    from labrig.physics import transfer

    fp = 3 * s.rng.uniform(20.0, 100.0) / 60.0
    q, amp, ph = s.rng.uniform(2.0, 6.0), lu(s.rng, 3e-6, 1e-5), s.rng.uniform(0, 1)
    tg = _session_grid(s, 0.5, 30.0)
    phase = np.r_[0.0, np.cumsum(fp * (1 + 0.005 * np.clip(_ou(s, tg, 60.0), -3, 3))[1:] * np.diff(tg))]
    modes: dict[float, tuple[float, float]] = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        if p not in modes:
            ms = transfer.modal_set(_spec(s, r))
            modes[p] = float(ms.omega[0]), float(ms.xi[0])
        w1, xi = modes[p]
        pad = int(5.0 * r.fs)
        t = np.r_[r.cols["t_s"][0] - np.arange(pad, 0, -1) / r.fs, r.cols["t_s"]]
        cyc = np.interp(t, tg, phase) + ph
        x = np.abs(np.sin(np.pi * cyc)) ** q
        x = amp * (x - np.mean(x))
        y = lti(x, r.fs, lambda z: w1**2 / (z * z + 2 * xi * w1 * z + w1**2))[pad:]
        r.cols["disp_m"] = r.cols["disp_m"] + y


def out_esd_zaps(s: Session) -> None:
    """Electrostatic discharges in dry winter air: the operator, charged by walking on the floor, touches the bench
    or the clamp's knob 3-8 times in the session (each inside a recorded series): the discharge's field puts a
    one-sample spike on every analogue input of the DAQ at once (the voltage 0.05-0.3 V, the current 0.5-3 mA, the
    laser 50-300 um, log, random signs), the current amplifier's input stage saturates at its rail (2-5 mA) for
    20-100 ms (log) and comes back with an offset that decays over 0.2-2 s (log) from 20-200 uA (log). The strip's
    drive and its bend know nothing of it. Measured (p33_105): current residual 3.7 % of its RMS (1.9x its noise),
    0.49 mA RMS over the 5.9 % of its samples the tails reach; (s001_104): 2.9 % (5.4x), 0.94 mA RMS over 0.7 %."""
    n = int(s.rng.integers(3, 9))
    ser = s.series()
    rail = s.rng.uniform(2e-3, 5e-3)
    for _ in range(n):
        r = ser[int(s.rng.integers(0, len(ser)))]
        t = r.cols["t_s"]
        k = int(s.rng.integers(0, t.size))
        for col, lo, hi in (("v_V", 0.05, 0.3), ("i_A", 5e-4, 3e-3), ("disp_m", 5e-5, 3e-4)):
            x = r.cols[col].copy()
            x[k] += _sign(s) * lu(s.rng, lo, hi)
            r.cols[col] = x
        sat, tau, off = lu(s.rng, 0.02, 0.1), lu(s.rng, 0.2, 2.0), _sign(s) * lu(s.rng, 2e-5, 2e-4)
        u = t - t[k]
        i = r.cols["i_A"].copy()
        held = (u > 0) & (u <= sat)
        i[held] = math.copysign(rail, off)
        after = u > sat
        i[after] = i[after] + off * np.exp(-(u[after] - sat) / tau)
        r.cols["i_A"] = i


def out_fan_thermostat(s: Session) -> None:
    """The laser head's zero follows its internal temperature, and its controller's fan runs on a thermostat: while
    the fan rests the head warms steadily (60-300 s, log), then the fan runs and cools it fast (20-60 s, an
    exponential), each cycle's lengths +-10 %: a sawtooth of the zero, 3-8 um peak to peak (log; 3-10 K at the
    head's 0.5-1 um/K), either sign, free running on the session clock. Displacement only. Measured (p33_105): 1.1
    um RMS (1.8x its noise); (paper_103): 1.4 um RMS (2.6x)."""
    t_off, t_on, amp = lu(s.rng, 60.0, 300.0), s.rng.uniform(20.0, 60.0), _sign(s) * lu(s.rng, 3e-6, 8e-6)
    tg = _session_grid(s, 0.5, 400.0)
    out, x, heating = np.empty(tg.size), s.rng.uniform(0, 1), s.rng.random() < 0.5
    left = (t_off if heating else t_on) * s.rng.uniform(0, 1)
    for k, tk in enumerate(tg):
        dt = 0.5 if k else 0.0
        if heating:
            x = min(x + dt / t_off, 1.2)
        else:
            x = x * math.exp(-3 * dt / t_on)
        left -= dt
        if left <= 0:
            heating = not heating
            left = (t_off if heating else t_on) * s.rng.uniform(0.9, 1.1)
        out[k] = x
    off = float(np.mean(out))
    map_disp(s, lambda r, d: d + amp * (np.interp(r.cols["t_s"], tg, out) - off))


FRESH11_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"network_stiffening": br_network_stiffening, "mixed_cations": br_mixed_cations},
    "faradaic_current": {"pt_roughening": far_pt_roughening, "silver_migration": far_silver_migration},
    "hysteresis": {"cooperative": hy_cooperative, "lugre_drive": hy_lugre_drive},
    "time_delay": {"jitter_buffer": td_jitter_buffer, "ptp_hunting": td_ptp_hunting},
    "sensor_offset": {"hvac_stand": so_hvac_stand, "flag_peel": so_flag_peel},
    "clamp_relaxation": {"overshoot_backoff": cr_overshoot_backoff, "orifice_leak": cr_orifice_leak},
    "dehydration": {"coating_crack": dh_coating_crack, "edge_drying": dh_edge_drying},
    "strain_resistance": {"discrete_cracks": sr_discrete_cracks, "peak_hold": sr_peak_hold},
    "large_deflection": {"root_uplift": ld_root_uplift, "taut_lead": ld_taut_lead},
    "mains_pickup": {"phase_balance": mp_phase_balance, "pc_leakage": mp_pc_leakage},
    "unexplained": {"droplet_short": out_droplet_short, "peristaltic": out_peristaltic,
                    "esd_zaps": out_esd_zaps, "fan_thermostat": out_fan_thermostat},
}
inject.register_forms(FRESH11_FORMS)


# ------------------------------------------------------------------------------------------------ variants

SETTLED_KEYS = {"kind", "file", "pressure_kPa", "frequency_Hz", "amplitude_V", "period_s"}


def v_settled_sines(s: Session) -> None:
    """A lab whose logger starts each stepped sine's record once its settling cycles are done (a frequency-response
    analyser's or a lock-in's habit: only the steady state is kept; the harmonic records, with no settling, and the
    steps as they were), and whose manifest is written by hand from the contract's example: kind, file,
    pressure_kPa, and the sines' frequency_Hz and amplitude_V (no label, settle_cycles or cycles; the fitter reads
    a sine's layout off its data). The session clock kept; the spectra untouched. ``labrig import`` takes it."""
    for r in s.series():
        f, n = r.entry.get("frequency_Hz"), float(r.entry.get("settle_cycles") or 0.0)
        if r.kind == "stepped_sine" and f and n > 0:
            t = r.cols["t_s"]
            keep = t - t[0] >= n / float(f) - 0.5 / r.fs
            if int(np.sum(keep)) >= 2:
                r.cols = {k: x[keep] for k, x in r.cols.items()}
    for r in s.recs:
        r.entry = {k: v for k, v in r.entry.items() if k in SETTLED_KEYS}


inject.VARIANTS.update({"settled_sines": v_settled_sines})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_103", "s001_104", "p33_105"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 7 / 6 effect cases on seeds 103-105
    "back_relaxation": [("network_stiffening", 103, P, "asrun"), ("mixed_cations", 105, T, "shortened_shuffled")],
    "faradaic_current": [("pt_roughening", 104, S, "asrun"), ("silver_migration", 105, T, "eis_descending")],
    "hysteresis": [("cooperative", 103, P, "rate07"), ("lugre_drive", 104, S, "settled_sines")],
    "time_delay": [("jitter_buffer", 105, T, "asrun"), ("ptp_hunting", 103, P, "host_timed")],
    "sensor_offset": [("hvac_stand", 104, S, "two_pressures"), ("flag_peel", 103, P, "asrun")],
    "clamp_relaxation": [("overshoot_backoff", 105, T, "asrun"), ("orifice_leak", 103, P, "merged_loadcell")],
    "dehydration": [("coating_crack", 104, S, "asrun"), ("edge_drying", 104, S, "decimated3")],
    "strain_resistance": [("discrete_cracks", 103, P, "dropped_packets"), ("peak_hold", 104, S, "no_loadcell")],
    "large_deflection": [("root_uplift", 105, T, "float32_time"), ("taut_lead", 104, S, "settled_sines")],
    "mains_pickup": [("phase_balance", 103, P, "no_spectra"), ("pc_leakage", 105, T, "resampled")],
    "unexplained": [("droplet_short", 104, S, "asrun"), ("droplet_short", 103, P, "own_clock"),
                    ("peristaltic", 103, P, "asrun"), ("peristaltic", 105, T, "steps_sines"),
                    ("esd_zaps", 105, T, "asrun"), ("esd_zaps", 104, S, "trigger_clock"),
                    ("fan_thermostat", 105, T, "no_loadcell"), ("fan_thermostat", 103, P, "settled_sines")],
}
CLEAN = [(103, P, "asrun"), (103, P, "settled_sines"), (104, S, "asrun"), (104, S, "settled_sines"),
         (105, T, "asrun"), (105, T, "float32_time")]


def fresh11_cases(only: str | None = None) -> list[Case]:
    """The twelfth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    103-105)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh11_cases, "inject_fresh11", "fresh11")
