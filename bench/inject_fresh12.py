"""A thirteenth held-out set for the diagnosis (issue 12), fresh12, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh11.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (a resistive electrode's potential
profile, thermally activated bistable clusters, friction at the jaw's edge loaded by the bend, a focus-tracking
sensor's slew limit, a raised target plate), some on the history (back-flow whose direction sets its speed, cracks
that drain the water faster, cracks plated shut by the cathodic charge), some on time or on the clamp pressure (a
copper contact passivating, a pneumatic clamp on the lab's air line, pads wicking the bath, a dry skin, the room's
humidity, a strip curling as it dries, the laser's bracket on the clamp's jaw), some from the lab's wiring or
settings (a building on its generator, a frequency converter's interharmonics, a laser averaging set per record, a
flexible target flag, cracks bypassed by the double layer). Four structures outside the catalogue (truth
"unexplained": the laser's linearisation ripple, a class-B drive amplifier's crossover, the utility's ripple-control
telegrams, an AC-coupled current amplifier); clean sessions. All on three bases of new seeds (106-108: the paper strip,
the seed-001 strip on its own sweep, the paper strip 34 mm free) and on the earlier sets' protocol / data-shape
variants plus one new here: a logger armed on the drive's edge with a short pretrigger buffer, so every step record
starts a few tens of samples before its edge (``short_pretrigger``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh11 are reused (importing inject_fresh11 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import. Strengths are drawn from
the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case, measured in
memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the column's
sample-to-sample noise at rest, std(diff)/sqrt(2) over the 200 samples before each step record's edge, the median over
the steps; the values for the three bases are in docs/effects.md).

Run: python bench/inject_fresh12.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh11  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _drive_side, _map_through
from inject_fresh3 import _cat, _resist, _sign, _through_x
from inject_fresh4 import _clamp_law
from inject_fresh6 import _bursts, _reading
from inject_fresh7 import _superpose
from inject_fresh8 import _arc, _hum
from inject_fresh9 import _dry_by, _gaps, _ou, _session_grid
from inject_fresh10 import _lag_varying, _lambda, _station
from inject_fresh11 import _path, _walk

# the paper's strip 34 mm free (earlier sets used 20, 25, 28, 30, 32, 33, 35, 36, 38, 40, 42 and 45 mm; its 1 V step
# peaks near 11.3 mm, 8.8 mm x (34/30)^2, inside the laser's +-20 mm): registered in every process importing this module
inject.register_free_length("paper_34", 0.034)

inject.BASES.update({
    "paper_106": ("paper-sweep", "paper", 106),
    "s001_107": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 107),
    "p34_108": ("paper-sweep", "paper_34", 108),
})


# ------------------------------------------------------------------------------------------------ tools


def _per_record(s: Session, col: str, step: Callable[[float, float, float], float]) -> dict[int, np.ndarray]:
    """A scalar state through each record sample by sample, x = step(x, value, dt) on ``col``, starting each record
    at its first value (a loop that caught up over the rest before it). Returns the state per record."""
    out = {}
    for r in s.series():
        vals, dt = r.cols[col].tolist(), 1.0 / r.fs
        x, y = vals[0], np.empty(len(vals))
        for k, u in enumerate(vals):
            x = step(x, u, dt)
            y[k] = x
        out[id(r)] = y
    return out


def _phase(tg: np.ndarray, f: np.ndarray) -> np.ndarray:
    """The phase (rad) of a line whose frequency f (Hz) is given on the grid tg, integrated from the grid's start."""
    return 2 * np.pi * np.r_[0.0, np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(tg))]


def _line_f(s: Session) -> float:
    """The building's line frequency: 50 or 60 Hz, off nominal by up to 0.02 Hz."""
    return (50.0 if s.rng.random() < 0.5 else 60.0) + s.rng.uniform(-0.02, 0.02)


# ------------------------------------------------------------------------------------------------ back relaxation


def br_imbibition_drainage(s: Session) -> None:
    """The back-flow fills and empties through the electrode's pores at different speeds (capillary hysteresis of
    wetting: water drawn into the hydrophilic membrane's pores by their suction moves fast, water leaving them against
    it slowly): the back-flow's store x follows the bend with tau_in 2-6 s (log) while the bend is beyond it (abs(d) >
    abs(x): it fills) and with tau_out 2.5-5x slower (log) while it empties, read d - K2 x, K2 0.9-1.3. Sample by sample
    through the session in time order (the store carried over the rests, the displacement linear across them): a step
    rises, gives back fast, and after its fall the give-back drains slowly, a long tail of the other sign. Displacement
    only. Measured (paper_106): displacement RMS -67 % (residual 120 %), the 1 V steps' peaks -66 %, reversing to -0.69
    mm by the plateau's end; after the fall the give-back drains slowly: -2.6 mm 2 s on, -2.3 mm 14 s on (+4.2 mm
    clean); the 20 Hz records' residuals 52-62 %."""
    k2, t_in = s.rng.uniform(0.9, 1.3), lu(s.rng, 2.0, 6.0)
    t_out = t_in * lu(s.rng, 2.5, 5.0)
    x, d_end = 0.0, 0.0
    for r, gap in _gaps(s, 1.0):
        d = r.cols["disp_m"]
        for dt, u in gap:
            target = d_end + u * (float(d[0]) - d_end)
            x += -math.expm1(-dt / (t_in if abs(target) > abs(x) else t_out)) * (target - x)
        a_in, a_out = math.exp(-1.0 / (r.fs * t_in)), math.exp(-1.0 / (r.fs * t_out))
        out = np.empty(d.size)
        for k, dk in enumerate(d.tolist()):
            x = dk + (x - dk) * (a_in if abs(dk) > abs(x) else a_out)
            out[k] = x
        d_end = float(d[-1])
        r.cols["disp_m"] = d - k2 * out


def br_crack_drainage(s: Session) -> None:
    """The electrode's cracks, opened a little more by every bend, give the water a short way out of the membrane: the
    back-flow speeds up and grows with the path the strip has bent through so far (the running sum of abs(dd) over the
    session's), tau from tau0 6-15 s (log) down by 2-4x and K2 from 0.6-0.9 up to 1.1-1.4 by the session's end: the
    first block barely gives back, the last reverses. Through inject_fresh10._lag_varying with the path's share as the
    state's clock; displacement only. Measured (p34_108): displacement RMS -64 % (residual 87 %), the 1 V steps' peaks
    -58, -66, -71, -75 % block by block, their plateaus' ends +4.4, +2.9, +1.7, +0.5 mm (11.2 mm clean)."""
    t0, a = lu(s.rng, 6.0, 15.0), s.rng.uniform(2.0, 4.0)
    k0, k1 = s.rng.uniform(0.6, 0.9), s.rng.uniform(1.1, 1.4)
    _, t, cum = _path(s, lambda d: np.ones_like(d))
    share = cum / max(float(cum[-1]), 1e-30)

    def state(tt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        p = np.interp(tt, t, share, left=0.0, right=1.0)
        return k0 + (k1 - k0) * p, t0 / (1 + (a - 1) * p)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_resistive_electrode(s: Session) -> None:
    """Electrolysis (symmetric Butler-Volmer, v_t 0.1-0.2 V) along a resistive electrode fed at the root: the
    interface's potential falls along the strip (leak-limited, cosh((L - x)/lambda)/cosh(L/lambda), lambda 0.5-1.5 L)
    and reaches the far parts late (the line's diffusion, a lag tau_e (x/L)^2, tau_e 0.05-0.5 s, log), so the faradaic
    current is the sum of eight segments' exponentials at their own potentials: softer than one exponential at 1 V, and
    on a fast sine the far segments never reach their share. 0.1-0.4 mA at 1 V held (log). Each segment's lag with the
    session's history (inject_fresh3._through_x); current only. Measured (s001_107): current residual 3.4 % of its RMS
    (6.4x its noise); +0.20 mA on the 1 V steps' plateaus, 90 % of it within 0.11 s of the edge; the 20 Hz records'
    current residuals 0.3 %."""
    i1, vt = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.1, 0.2)
    lam, tau_e = s.rng.uniform(0.5, 1.5), lu(s.rng, 0.05, 0.5)
    xs = (np.arange(8) + 0.5) / 8
    prof = np.cosh((1 - xs) / lam) / math.cosh(1 / lam)
    scale = i1 / float(np.mean(2 * np.sinh(prof / (2 * vt))))
    v = {id(r): r.cols["v_V"] for r in s.series()}
    add = {id(r): np.zeros(r.cols["v_V"].size) for r in s.series()}
    for x, g in zip(xs, prof):
        lag = _through_x(s, v, lambda r, tx=tau_e * x * x: lambda z: 1 / (tx * z + 1), 2.0)
        for k in add:
            add[k] = add[k] + 2 * np.sinh(g * lag[k] / (2 * vt)) / xs.size
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + scale * add[id(r)]


def far_copper_contact(s: Session) -> None:
    """The jaw's contact is copper (or a brass screw) touching the wet electrode: a galvanic couple. Copper dissolves
    and oxygen is reduced at a mixed (corrosion) potential E 0.05-0.2 V off the platinum's (either sign), the net charge
    transfer a Wagner-Traud law i_c (exp((v - E)/b_a) - exp(-(v - E)/b_c)), b_a and b_c 0.15-0.3 V (widened by the
    film's resistance), so a small standing current flows at 0 V and the faradaic current grows unevenly with the two
    polarities; the contact's oxide film thickens parabolically (Wagner's law), i_c ~ 1/sqrt(1 + t/t_p), t_p 300-1500 s
    (log) from the mounting: 0.15-0.4 mA at 1 V at the session's start (log), fading. Current only. Measured (p34_108):
    current residual 2.7 % of its RMS (1.4x its noise); +0.22, +0.11, +0.08, +0.07 mA on the 1 V steps' plateaus block
    by block; a standing -20 uA at rest before the first step, -7 uA before the last."""
    e0, ba, bc = _sign(s) * s.rng.uniform(0.05, 0.2), s.rng.uniform(0.15, 0.3), s.rng.uniform(0.15, 0.3)
    i1, tp = lu(s.rng, 1.5e-4, 4e-4), lu(s.rng, 300.0, 1500.0)
    law = lambda v: np.exp((v - e0) / ba) - np.exp(-(v - e0) / bc)  # noqa: E731
    scale = i1 / float(law(np.array([1.0]))[0])
    for r in s.series():
        fade = 1 / np.sqrt(1 + (r.cols["t_s"] - s.t0) / tp)
        r.cols["i_A"] = r.cols["i_A"] + scale * fade * law(r.cols["v_V"])


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_kramers_relays(s: Session) -> None:
    """The clusters' cations as bistable units switching by thermal activation over a barrier the drive tilts (Kramers /
    Neel-Arrhenius: up at k_j exp(a u), down at k_j exp(-a u), u the drive over the session's peak, a 1.5-3): eight
    populations whose rates at zero drive span 0.05-20 /s (log spaced, the spread of the barriers), each following dp/dt
    = k_up (1 - p) - k_down p exactly for the drive held over each sample. Slow drives leave every population in
    equilibrium (a saturating, loop-free gain), fast ones leave the slow populations behind (loops whose width peaks
    where the drive's period meets their times: a rate-dependent hysteresis, not a rate-independent one). Gamma = (1 -
    h) v + h V_peak M/M_eq(1), h 0.15-0.3 (M = mean(2 p - 1)); through the strip's measured step response
    (inject_fresh2._drive_side); current untouched. Measured (paper_106): displacement RMS +1.5 % (residual 6.0 %, 350x
    its noise); the 1 V steps' peaks -0.2, +0.8, +0.8, +0.8 %, the 1 V harmonic's residual 5.2 %, the 0.5 V sines' at
    0.1 Hz 58 %, the 20 Hz records' 530-620 % (the slow populations relaxing after the large records, through the
    strip's step response, on a few um of signal)."""
    a, h = s.rng.uniform(1.5, 3.0), s.rng.uniform(0.15, 0.3)
    k = np.logspace(math.log10(0.05), math.log10(20.0), 8) * math.exp(s.rng.uniform(-0.3, 0.3))
    recs = _chrono(s)
    v = np.concatenate([r.cols["v_V"] for r in recs])
    dts = np.concatenate([np.full(r.cols["v_V"].size, 1.0 / r.fs) for r in recs])
    vp = max(float(np.max(np.abs(v))), 1e-9)
    p, m = np.full(k.size, 0.5), np.empty(v.size)
    for j, (u, dt) in enumerate(zip((v / vp).tolist(), dts.tolist())):
        rate = k * (math.exp(a * u) + math.exp(-a * u))
        eq = 1 / (1 + math.exp(-2 * a * u))
        p = eq + (p - eq) * np.exp(-rate * dt)
        m[j] = 2 * float(p.mean()) - 1
    gam = (1 - h) * v + h * vp * m / math.tanh(a)
    _drive_side(s, lambda _v: gam)


def hy_fulcrum_friction(s: Session) -> None:
    """Coulomb friction where the strip bears on the jaw's front edge: the edge is a fulcrum the bending moment presses
    the strip onto, so the friction's normal force, and with it the slip threshold, grows with the bend: an elasto-slide
    element whose slider x follows the reading d through a play of radius r0 + c abs(d) (r0 0.5-2 % of the displacement
    scale, c 0.05-0.15), held by its friction over the rests, its spring taking a share w 0.3-0.6 of the motion: d - w
    (d - x). Narrow loops about the rest, wide ones at the large bends, a remanence after each large step. Sample by
    sample through the session in time order (inject_fresh11._walk); displacement only. Measured (s001_107):
    displacement residual 3.0 % of its RMS (94x its noise); the 1 V steps' peaks -3.0 %, +53 um left at the records'
    ends, the 1 V harmonic's residual 3.2 %, the 20 Hz records' 21-26 %."""
    ref = ref_disp(s)
    r0, c, w = s.rng.uniform(0.005, 0.02) * ref, s.rng.uniform(0.05, 0.15), s.rng.uniform(0.3, 0.6)

    def step(x: float, d: float, dt: float) -> float:
        rr = r0 + c * abs(d)
        return min(max(x, d - rr), d + rr)

    xs = _walk(s, step, "disp_m")
    map_disp(s, lambda r, d: d - w * (d - xs[id(r)]))


# ------------------------------------------------------------------------------------------------ time delay


def td_sweep_averaging(s: Session) -> None:
    """The lab's script sets the laser controller's moving average before each record to keep the noise down: for a sine
    a window of 1/q of its period (q 20-60), at least 1 ms and at most 30-80 ms, as the controller offers it (2^n of its
    100-400 us sampling period); for a step a fixed setting of 8-32 ms. A causal boxcar (1 - exp(-sT))/(sT) on the
    displacement, a delay T/2 that changes from record to record: the same phase lag, 180/q deg, on every sine up to the
    window's floor, not a delay growing with the frequency. With the session's history (inject_fresh2._map_through);
    displacement only. Measured (p34_108): q 27, windows of 83 ms (0.1-0.45 Hz, at the cap), 41, 21, 10, 5.2 and 2.6 ms
    up to 20 Hz, 10 ms on the steps; displacement residual 0.53 % of its RMS (42x its noise), the 0.1 Hz sines'
    residuals 2.5 %, the 20 Hz records' 13 %."""
    q, t_s = s.rng.uniform(20.0, 60.0), lu(s.rng, 1e-4, 4e-4)
    t_max, t_step = s.rng.uniform(0.03, 0.08), lu(s.rng, 0.008, 0.032)

    def window(r: Rec) -> float:
        f = r.entry.get("frequency_Hz")
        want = min(max(1.0 / (q * float(f)), 1e-3), t_max) if f else t_step
        return t_s * 2.0 ** round(math.log2(want / t_s))

    def boxcar(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        T = window(r)

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):  # z = 0: inject.lti sets the DC gain itself
                return -np.expm1(-z * T) / (z * T)

        return h

    _map_through(s, boxcar, 1.0)


def td_focus_tracking(s: Session) -> None:
    """No triangulation: a focus-tracking (autofocus) displacement sensor whose objective is servoed onto the surface by
    a voice coil and read by its position: a first-order loop (tau 1-4 ms, log) whose coil can move only so fast, the
    lens's speed clipped at v_max 0.25-0.5 of the session's fastest tip speed (its 99.9th percentile): small and slow
    motions lag by tau, the step edges and the fast large sines are slewed, a delay that grows with the motion's speed.
    The loop caught up over each rest; sample by sample in each record; displacement only. Measured (paper_106):
    displacement residual 0.70 % of its RMS (41x its noise), the 1 V steps' edges 38 ms late at half height, the 20 Hz
    records' residuals 10-12 %."""
    tau = lu(s.rng, 1e-3, 4e-3)
    speed = max(float(np.percentile(np.abs(np.diff(r.cols["disp_m"])) * r.fs, 99.9)) for r in s.series())
    vmax = s.rng.uniform(0.25, 0.5) * speed

    def step(y: float, d: float, dt: float) -> float:
        move = (d - y) * -math.expm1(-dt / tau)
        return y + min(max(move, -vmax * dt), vmax * dt)

    ys = _per_record(s, "disp_m", step)
    map_disp(s, lambda r, d: ys[id(r)])


# ------------------------------------------------------------------------------------------------ sensor offset


def so_jaw_bracket(s: Session) -> None:
    """The laser's bracket is screwed to the clamp's moving jaw (a compact fixture), aimed at the tip once at the first
    (lowest) setting: each tighter setting flexes the jaw's frame, and the bracket's lever turns the beam inboard in
    proportion to the clamp force, the station x_m/L = 1 - c (p - p_min)/(p_max - p_min), c 0.05-0.12 at the top
    pressure: the station steps inboard block by block with the pressure, constant within each. Through
    inject_fresh10._station (the beam's own transfer functions at the station); displacement only. Measured (s001_107):
    the 1 V steps' peaks 0.0, -4.5, -8.9, -13 % block by block, displacement RMS -6.5 % (residual 8.3 %), the 20 Hz
    records' residuals 0-9.4 %."""
    c = s.rng.uniform(0.05, 0.12)
    lo, hi = min(s.pressures()), max(s.pressures())
    span = max(hi - lo, 1e-9)
    _station(s, lambda r: np.full(r.cols["t_s"].size, 1 - c * (float(r.entry["pressure_kPa"]) - lo) / span), 1 - c)


def so_flexible_flag(s: Session) -> None:
    """A foil flag glued at the tip and sticking out beyond it by e 0.05-0.2 L (a target for a strip too dark or too
    narrow to read), the laser on the flag: the flag is no rigid extension but a cantilever of its own, its first mode
    at 25-60 Hz (log) with damping 0.05-0.25 (the medium's drag), so its end follows the rigid extension w(L) + e w'(L)
    through 1/(1 + 2 zeta s/w_f + (s/w_f)^2): a station beyond the tip at low frequency (a larger gain and a changed
    modal shape) with a resonance of its own near the fast records. The rigid reading through the strip's quasi-static
    deflections and modal parts (inject_fresh6._reading), the flag's mode with the session's history
    (inject_fresh3._through_x); displacement only. Measured (paper_106): displacement RMS +24 % (residual 24 %), the 1 V
    steps' peaks +24 %, the 20 Hz records' residuals 44-57 %."""
    e, ff, zeta = s.rng.uniform(0.05, 0.2), lu(s.rng, 25.0, 60.0), s.rng.uniform(0.05, 0.25)
    wf = 2 * np.pi * ff
    rigid = _reading(s, lambda sp: [(1.0, sp.geometry.length, 0), (e * sp.geometry.length, sp.geometry.length, 1)])
    new = _through_x(s, rigid, lambda r: lambda z: 1 / (1 + 2 * zeta * z / wf + (z / wf) ** 2), 0.5)
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_air_supply(s: Session) -> None:
    """A pneumatic clamp (an air cylinder) on the lab's compressed-air line through a cheap regulator: the line's
    pressure falls as the lab draws air and jumps back when the compressor cuts in (a sawtooth of period 3-12 min, the
    refill 5-15 % of it), and the regulator passes a share of the swing, so the clamp force follows the supply, F/F_set
    = S(t)/S(t_set), S = 1 + a saw(t), a 0.03-0.07 (+-3-7 %): a force that sags and recovers over and over, the same in
    every block. Through the preset's clamp law (inject_fresh4._clamp_law). Measured (paper_106): the load cell between
    0.94 and 1.08 of its setting (1.02, 0.97, 1.07, 1.00 at the blocks' ends); displacement residual 0.04 % (2.4x its
    noise), current 0.19 % (0.1x), the 20 Hz records' up to 1.4 %."""
    per, fill = s.rng.uniform(180.0, 720.0), s.rng.uniform(0.05, 0.15)
    a, ph = s.rng.uniform(0.03, 0.07), s.rng.uniform(0, 1)

    def supply(t: np.ndarray) -> np.ndarray:
        u = np.mod(t / per + ph, 1.0)
        return 1 + a * np.where(u < 1 - fill, 1 - 2 * u / (1 - fill), -1 + 2 * (u - 1 + fill) / fill)

    _clamp_law(s, lambda t, p, t_set: supply(t) / supply(np.array([t_set]))[0])


def cr_wicking_pads(s: Session) -> None:
    """Felt (or blotting-paper) pads under the jaws, dipping into the bath: they wick the water up (Washburn, a front
    rising as sqrt(t) from the mounting 0-300 s before the first record, fully wet after 0.5-1.5 of the session) and
    soften as they wet, so at each setting's fixed gap the force falls by c 0.15-0.3 times the share wetted since the
    setting: F/F_set = (1 - c w(t))/(1 - c w(t_set)). The early blocks lose the most, the last ones (pads already wet)
    little: a fall that is fast then stops, fixed by the session's clock, not by each setting's. Through the preset's
    clamp law (inject_fresh4._clamp_law). Measured (p34_108): the load cell at 0.91, 0.96, 0.97, 0.98 of its setting by
    the blocks' ends; displacement residual 0.03 % (2.2x its noise), current 0.26 % (0.1x), the 20 Hz records' up to 3.1
    %."""
    tm, tw, c = s.rng.uniform(0.0, 300.0), s.rng.uniform(0.5, 1.5) * (s.t1 - s.t0), s.rng.uniform(0.15, 0.3)
    wet = lambda t: np.minimum(np.sqrt(np.clip(t - s.t0 + tm, 0, None) / tw), 1.0)  # noqa: E731
    _clamp_law(s, lambda t, p, t_set: (1 - c * wet(t)) / (1 - c * wet(np.array([t_set]))[0]))


# ------------------------------------------------------------------------------------------------ dehydration


def dh_dry_skin(s: Session) -> None:
    """A strip in air dries through a dense skin that its own drying builds under the electrodes: the skin's
    permeability falls exponentially with its thickness (Elovich-like), so the water lost grows as log(1 + t/t_0) (t_0
    0.02-0.1 of the session, log, from the mounting 0-300 s before), total 0.08-0.2 of the gain by the end; the skin
    sits between the electrode and the wet bulk, so it costs the conductance more than the coupling (1.3-2x the gain's
    loss, at most 0.6): the current falls faster than the bend, the spectra rising with it (inject_fresh9._dry_by).
    Measured (s001_107): displacement RMS -10 % (residual 12 %), the 1 V steps' peaks -1.9, -10, -14, -16 % block by
    block; current -17 % (32x its noise)."""
    tot, u0, c, tm = s.rng.uniform(0.08, 0.2), lu(s.rng, 0.02, 0.1), s.rng.uniform(1.3, 2.0), s.rng.uniform(0.0, 300.0)
    span = s.t1 - s.t0 + tm

    def loss(t: np.ndarray) -> np.ndarray:
        u = np.clip(t - s.t0 + tm, 0, None) / span
        return tot * np.log1p(u / u0) / math.log1p(1 / u0)

    _dry_by(s, loss, lambda t: np.minimum(c * loss(t), 0.6))


def dh_humidity_wander(s: Session) -> None:
    """A strip in air in a room whose humidity falls through the session (the afternoon warming, a dehumidifier) and
    wanders about the trend (doors, people, the weather: an Ornstein-Uhlenbeck wander of +-3-6 % RH over 300-1200 s):
    from 0.45-0.6 down by 0.1-0.2. The strip's water follows Nafion's isotherm (inject_fresh10._lambda) through its
    sorption lag (100-400 s, log), equilibrated at the start: the gain as lambda/lambda_0, the conductance as
    (lambda/lambda_0)^1.5-2.5 (percolation of the water channels): a drying that pauses and partly recovers. Through
    inject_fresh9._dry_by. Measured (s001_107): displacement RMS -7.2 % (residual 9.8 %), the 1 V steps' peaks +0.2,
    -3.2, -11, -16 % block by block; current -10 % (31x its noise)."""
    a0, drop, sig = s.rng.uniform(0.45, 0.6), s.rng.uniform(0.1, 0.2), s.rng.uniform(0.03, 0.06)
    tau_ou, tau_s, gc = s.rng.uniform(300.0, 1200.0), lu(s.rng, 100.0, 400.0), s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 1.0, 600.0)
    u = np.clip((tg - s.t0) / (s.t1 - s.t0), 0, 1)
    rh = np.clip(a0 - drop * u + sig * np.clip(_ou(s, tg, tau_ou), -3, 3) * (tg > s.t0), 0.05, 0.95)
    lam, x = _lambda(rh), float(_lambda(np.array([a0]))[0])
    lag = np.empty(tg.size)
    for k, target in enumerate(lam.tolist()):  # the strip's uptake lagging the room's
        x += -math.expm1(-(1.0 if k else 0.0) / tau_s) * (target - x)
        lag[k] = x
    rel = lag / float(_lambda(np.array([a0]))[0])
    _dry_by(s, lambda t: 1 - np.interp(t, tg, rel), lambda t: 1 - np.interp(t, tg, rel) ** gc)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_double_layer_bypass(s: Session) -> None:
    """The electrode's cracks, in water, are bridged by the double layers on their walls: a crack is a resistance
    (growing with the tension) in parallel with the walls' capacitance, so its extra drop is low-passed by the crack's
    own time constant tau_c 5-40 ms (log): the slow records feel the whole crack resistance, the fast sines and the step
    edges little. The change -k LP(e x) on the displacement and the current, e the tensioned face's strain over the
    session's scale (side drawn) with the other face at 0.1-0.4 of its gauge, k 0.03-0.08 (displacement) and 0.08-0.2
    (current) per unit; the low-pass with the session's history (inject_fresh3._through_x). Measured (paper_106):
    displacement RMS -1.9 % (residual 2.0 %, 115x its noise), the 1 V steps' peaks -2.6 %, current residual 1.3 % (0.7x
    its noise); the 20 Hz records untouched (< 0.01 %)."""
    side, o, tc = _sign(s), s.rng.uniform(0.1, 0.4), lu(s.rng, 5e-3, 4e-2)
    kd, ki = s.rng.uniform(0.03, 0.08), s.rng.uniform(0.08, 0.2)
    ref = ref_disp(s)
    e = {id(r): np.clip(side * r.cols["disp_m"] / ref, 0, None) + o * np.clip(-side * r.cols["disp_m"] / ref, 0, None)
         for r in s.series()}
    for col, k in (("disp_m", kd), ("i_A", ki)):
        x = {id(r): e[id(r)] * r.cols[col] for r in s.series()}
        drop = _through_x(s, x, lambda r: lambda z: 1 / (tc * z + 1), 0.5)
        for r in s.series():
            r.cols[col] = r.cols[col] - k * drop[id(r)]


def sr_crack_plating(s: Session) -> None:
    """The bath carries the metal's ions (platinum or gold salt left from the plating, or copper from a contact), and
    the cathodic current re-deposits metal in the cracks of the face it passes through: the cracks are bridged (healed)
    in proportion to the cathodic charge that face has passed so far (Q/Q_end through the session in time order), their
    strain sensitivity falling to 1 - h of its start, h 0.4-0.8. The tensioned face (side drawn) with the other at
    0.1-0.3 of its gauge; gains fall by 0.02-0.06 (displacement) and 0.05-0.15 (current) per unit of the session's
    largest bend (inject_fresh3._resist). Measured (p34_108): displacement RMS -2.9 % (residual 3.0 %, 240x its noise),
    the 1 V steps' peaks -5.0, -4.3, -3.7, -3.0 % block by block, current residual 1.7 % (0.9x its noise)."""
    side, h, o = _sign(s), s.rng.uniform(0.4, 0.8), s.rng.uniform(0.1, 0.3)
    recs, i, cuts = _cat(s, "i_A")
    dt = np.concatenate([np.full(r.cols["i_A"].size, 1.0 / r.fs) for r in recs])
    q = np.cumsum(np.clip(-side * i, 0, None) * dt)
    heal = {id(r): x for r, x in zip(recs, np.split(1 - h * q / max(float(q[-1]), 1e-30), cuts))}
    emax = max(float(np.max(np.abs(r.cols["disp_m"]))) for r in s.series()) / ref_disp(s)  # per unit of the largest

    def shape(r: Rec, x: np.ndarray) -> np.ndarray:
        return (heal[id(r)] * np.clip(side * x, 0, None) + o * np.clip(-side * x, 0, None)) / emax

    _resist(s, shape, (0.02, 0.06), (0.05, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_raised_target(s: Session) -> None:
    """The laser reads a small flat target plate (a cover-slip or a mirror chip) carried on a post H 0.5-2 mm above the
    strip's tip and parallel to it, the beam fixed in the lab where the plate's centre sits at rest: as the tip turns by
    theta on the exact arc (inject_fresh8._arc), the beam meets the tilted plate away from its centre, reading Y + (L -
    X) tan(theta) + H (1/cos(theta) - 1): the tip's draw-back times the plate's slope (odd, reads more) and the post's
    lift (even, always up). Displacement only. Measured (s001_107): the 1 V steps' peaks +9.1 %, displacement RMS +5.4 %
    (residual 5.9 %, 180x its noise)."""
    hp = s.rng.uniform(0.5e-3, 2e-3)

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        L = float(s.specimen["length_m"])
        k, Y, X = _arc(d, L)
        th = k * L
        return Y + (L - X) * np.tan(th) + hp * (1 / np.cos(th) - 1)

    map_disp(s, read)


def ld_drying_curl(s: Session) -> None:
    """A strip in air curls along its length as it dries (its two faces' electrodes shrink differently): its rest shape
    becomes an arc whose tip angle grows from 0-5 deg to 12-25 deg through the session (exponentially, time constant
    0.3-1 of the session; either side), the laser zeroed before each record. The strip bends about that curled rest, so
    the exact arc's tip height Y(k0 + k) - Y(k0) (k = 2 d/L^2) carries an even part that grows with the curl: the bends
    into the curl read less than those out of it, more so late in the session. Displacement only. Measured (s001_107):
    the 1 V steps' peaks -2.2, -4.5, -6.4, -8.2 % block by block, displacement RMS -3.9 % (residual 4.4 %, 140x its
    noise)."""
    side, th_a, th_b = _sign(s), math.radians(s.rng.uniform(0.0, 5.0)), math.radians(s.rng.uniform(12.0, 25.0))
    tau = s.rng.uniform(0.3, 1.0)

    def curl(t: np.ndarray) -> np.ndarray:
        u = np.clip((t - s.t0) / (s.t1 - s.t0), 0, 1)
        return side * (th_a + (th_b - th_a) * -np.expm1(-u / tau) / -math.expm1(-1 / tau))

    def height(k: np.ndarray, L: float) -> np.ndarray:
        ks = np.where(np.abs(k) < 1e-9, 1e-9, k)
        return (1 - np.cos(ks * L)) / ks

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        L = float(s.specimen["length_m"])
        k0 = curl(r.cols["t_s"]) / L
        return height(k0 + 2 * d / L**2, L) - height(k0, L)

    map_disp(s, read)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_generator_test(s: Session) -> None:
    """The building's monthly test of its standby generator falls inside the session: for 10-30 min (log) the lab runs
    on the diesel set, whose governor holds the frequency 0.2-0.5 Hz off nominal and hunts about it (+-0.05-0.2 Hz, 3-10
    s), and whose alternator's slot harmonics (5th 0.1-0.3, 7th 0.05-0.2) and heavier loading of the bench's cables
    raise the pickup 1.5-3x; before and after, the grid's steady hum with its 3rd (0.1-0.2). Both lines with their own
    coupling phases: 1-3 um and 3-10 uA (log) on the generator. Measured (paper_106): displacement 1.9 um RMS during the
    test (3.3x its noise), over 25 % of the session, 0.74 um before and after; current 3.9 uA during it (0.06x); the 20
    Hz records' residuals up to 33 %."""
    f0, off = _line_f(s), _sign(s) * s.rng.uniform(0.2, 0.5)
    hunt, per = s.rng.uniform(0.05, 0.2), s.rng.uniform(3.0, 10.0)
    g, ad, ai = s.rng.uniform(1.5, 3.0), lu(s.rng, 1e-6, 3e-6), lu(s.rng, 3e-6, 1e-5)
    dur = lu(s.rng, 600.0, 1800.0)
    start = s.t0 + s.rng.uniform(0.1, 0.7) * (s.t1 - s.t0)
    h3, h5, h7 = s.rng.uniform(0.1, 0.2), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.05, 0.2)
    pd, pi_ = s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi)
    tg = _session_grid(s, 0.005, 1.0)
    on = (tg >= start) & (tg < start + dur)
    ph = _phase(tg, np.where(on, f0 + off + hunt * np.sin(2 * np.pi * tg / per), f0))
    for r in s.series():
        t = r.cols["t_s"]
        w, gen = np.interp(t, tg, ph), (t >= start) & (t < start + dur)
        for col, amp, p in (("disp_m", ad, pd), ("i_A", ai, pi_)):
            grid = (np.cos(w + p) + h3 * np.cos(3 * (w + p))) / g
            set_ = np.cos(w + p) + h5 * np.cos(5 * (w + p)) + h7 * np.cos(7 * (w + p))
            r.cols[col] = r.cols[col] + amp * np.where(gen, set_, grid)


def mp_vfd_interharmonics(s: Session) -> None:
    """A pump in the building on a frequency converter (a six-pulse drive) on the lab's supply: besides the line's own
    hum, its DC link's ripple puts interharmonics on the mains at abs(f_line +- 6 f_out) (0.3-0.6 of the hum each) and
    its 5th and 7th characteristic harmonics (0.15-0.4, 0.1-0.3), f_out the motor's speed, which its process loop
    changes every 2-10 min (log) among 25-48 Hz: lines that move with the pump, none of them a multiple of the line
    frequency. Conducted through the bench's supplies onto both lines: 1-4 um and 3-10 uA (log) of hum. Measured
    (p34_108): displacement 1.2 um RMS (2.2x its noise), current 6.3 uA (0.1x); f_out 26-48 Hz over 28 settings; the 20
    Hz records' residuals 15-16 %."""
    f0, ad, ai = _line_f(s), lu(s.rng, 1e-6, 4e-6), lu(s.rng, 3e-6, 1e-5)
    ih, h5, h7 = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.15, 0.4), s.rng.uniform(0.1, 0.3)
    tg = _session_grid(s, 0.002, 1.0)
    edges = [tg[0]]
    while edges[-1] < tg[-1]:
        edges.append(edges[-1] + lu(s.rng, 120.0, 600.0))
    speeds = s.rng.uniform(25.0, 48.0, len(edges))
    fo = speeds[np.searchsorted(edges, tg, side="right") - 1]
    po = _phase(tg, 6 * fo)
    pd, pi_ = s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi)
    for r in s.series():
        t = r.cols["t_s"]
        w6 = np.interp(t, tg, po)
        for col, amp, p in (("disp_m", ad, pd), ("i_A", ai, pi_)):
            w = 2 * np.pi * f0 * t + p
            x = _hum(t, f0, {5: h5, 7: h7}, p) + ih * (np.cos(w + w6) + np.cos(w - w6))
            r.cols[col] = r.cols[col] + amp * x


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_linearity_ripple(s: Session) -> None:
    """The laser's linearisation table: a triangulation head converts its receiver's spot position to distance through a
    table of knots, and between them its residual is a ripple periodic in the distance (period 0.4-1.5 mm, log;
    amplitude 2-6 um, log, with a second harmonic 0.2-0.4): the reading d + eps(d + d_rest) - eps(d_rest), zeroed at
    rest. Nothing in time, nothing in frequency: a fixed error pattern in the displacement's value, which the large
    records sweep through (a ripple on the steps' rise and fall, harmonics on the large sines) and the small fast ones
    see as a local gain error. Displacement only. Measured (paper_106): 1.8 um RMS (3.1x its noise), the 1 V steps' rise
    rippled between -1.6 and +3.7 um; (s001_107): 3.8 um (6.6x), -7.3 to +2.7 um."""
    eps, lam = lu(s.rng, 2e-6, 6e-6), lu(s.rng, 4e-4, 1.5e-3)
    h2, p1, p2 = s.rng.uniform(0.2, 0.4), s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi)
    err = lambda x: eps * (np.sin(2 * np.pi * x / lam + p1) + h2 * np.sin(4 * np.pi * x / lam + p2))  # noqa: E731
    map_disp(s, lambda r, d: d + err(d) - err(np.zeros(1))[0])


def out_crossover_deadzone(s: Session) -> None:
    """The drive amplifier is a class-B push-pull stage with too little bias: its output crosses zero through a dead
    zone, out = sign(v) max(abs(v) - v_d, 0), v_d 5-25 mV (log), while the DAQ records the command. Each zero crossing
    of a sine holds the strip's voltage still for 2 v_d/(dv/dt): the charging current, largest right there, drops out in
    a notch (the slow 1 V sines' notches tens of ms wide); the held steps lose v_d. Through the strip's measured step
    responses (inject_fresh7._superpose): current and displacement, the recorded v_V untouched. Measured (s001_107):
    current residual 2.4 % of its RMS (4.4x its noise), notches of 0.24 mA on the 1 V harmonic's 4.8 mA, displacement
    residual 0.8 % (26x); (p34_108): current 3.1 % (1.6x), notches of 0.36 mA, displacement 1.1 % (88x)."""
    vd = lu(s.rng, 5e-3, 2.5e-2)
    _superpose(s, {id(r): -np.clip(r.cols["v_V"], -vd, vd) for r in s.series()})


def out_ripple_control(s: Session) -> None:
    """The utility's ripple-control (audio-frequency load control) telegrams ride on the mains: a tone at one of the
    network's frequencies (168-1050 Hz, none a multiple of the line frequency) keyed on for 0.6 s pulses, a start pulse
    and 40 bit slots of 2.5 s (35-50 % set), 3-8 telegrams in the session, picked up by the bench's wiring on both lines
    and aliased by each record's sampling: 3-8 um and 5-20 uA (log). Bursts of a line that sits nowhere the drive, the
    strip or the line frequency put anything. Measured (p34_108): 5.2 um RMS inside the pulses (9.5x its noise), 1 % of
    the samples; (paper_106): 4.2 um (7.4x)."""
    f = float(s.rng.choice([168.0, 175.0, 183.33, 216.67, 283.33, 316.67, 383.33, 485.0, 750.0, 1050.0]))
    ad, ai = lu(s.rng, 3e-6, 8e-6), lu(s.rng, 5e-6, 2e-5)
    pd, pi_ = s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi)
    starts = []
    for t0, _ in _bursts(s, int(s.rng.integers(3, 9)), (1.0, 1.0001)):
        bits = s.rng.random(40) < s.rng.uniform(0.35, 0.5)
        starts += [t0] + [t0 + 2.5 * (k + 1) for k in np.flatnonzero(bits)]
    starts = np.sort(np.array(starts))
    for r in s.series():
        t = r.cols["t_s"]
        k = np.searchsorted(starts, t, side="right") - 1
        on = (k >= 0) & (t - starts[np.clip(k, 0, None)] < 0.6)
        for col, amp, p in (("disp_m", ad, pd), ("i_A", ai, pi_)):
            r.cols[col] = r.cols[col] + amp * on * np.cos(2 * np.pi * f * t + p)


def out_ac_coupled(s: Session) -> None:
    """The current amplifier's input coupling left on AC (its switch, or a coupling capacitor in a home-made
    transimpedance stage): a first-order high-pass at 0.03-0.3 Hz (log) on the current channel only, so the steps' held
    current decays to zero and undershoots after the fall, the slow sines' current leads, the leak's DC is gone. With
    the session's history (inject_fresh3._through_x, the capacitor's charge carried over the rests); the strip and the
    other channels untouched. Measured (paper_106): current residual 20 % of its RMS (10x its noise), the 1 V steps'
    current -0.68 mA by the plateau's end; (p34_108): 34 % (18x), -0.70 mA."""
    tau = 1 / (2 * np.pi * lu(s.rng, 0.03, 0.3))
    new = _through_x(s, {id(r): r.cols["i_A"] for r in s.series()}, lambda r: lambda z: tau * z / (tau * z + 1),
                     min(5 * tau, 60.0))
    for r in s.series():
        r.cols["i_A"] = new[id(r)]


FRESH12_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"imbibition_drainage": br_imbibition_drainage, "crack_drainage": br_crack_drainage},
    "faradaic_current": {"resistive_electrode": far_resistive_electrode, "copper_contact": far_copper_contact},
    "hysteresis": {"kramers_relays": hy_kramers_relays, "fulcrum_friction": hy_fulcrum_friction},
    "time_delay": {"sweep_averaging": td_sweep_averaging, "focus_tracking": td_focus_tracking},
    "sensor_offset": {"jaw_bracket": so_jaw_bracket, "flexible_flag": so_flexible_flag},
    "clamp_relaxation": {"air_supply": cr_air_supply, "wicking_pads": cr_wicking_pads},
    "dehydration": {"dry_skin": dh_dry_skin, "humidity_wander": dh_humidity_wander},
    "strain_resistance": {"double_layer_bypass": sr_double_layer_bypass, "crack_plating": sr_crack_plating},
    "large_deflection": {"raised_target": ld_raised_target, "drying_curl": ld_drying_curl},
    "mains_pickup": {"generator_test": mp_generator_test, "vfd_interharmonics": mp_vfd_interharmonics},
    "unexplained": {"linearity_ripple": out_linearity_ripple, "crossover_deadzone": out_crossover_deadzone,
                    "ripple_control": out_ripple_control, "ac_coupled": out_ac_coupled},
}
inject.register_forms(FRESH12_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_short_pretrigger(s: Session) -> None:
    """A logger armed on the drive's edge with a short pretrigger buffer (a digitiser's or a LabVIEW trigger's
    pretrigger samples, 20-100 for the session): every step record starts that many samples before its edge (the
    first sample past half the drive's excursion), the rest of its baseline never logged; the sines, the spectra and
    the manifest as they were, the session clock kept. ``labrig import`` takes it (the fitter reads the edge off the
    data)."""
    n = int(s.rng.integers(20, 101))
    for r in s.series():
        if r.kind != "step":
            continue
        v = np.abs(r.cols["v_V"] - r.cols["v_V"][0])
        edge = int(np.argmax(v > 0.5 * float(v.max()))) if float(v.max()) > 0 else 0
        if edge > n:
            r.cols = {k: x[edge - n:] for k, x in r.cols.items()}


inject.VARIANTS.update({"short_pretrigger": v_short_pretrigger})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_106", "s001_107", "p34_108"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 7 / 6 effect cases on seeds 106-108
    "back_relaxation": [("imbibition_drainage", 106, P, "asrun"), ("crack_drainage", 108, T, "shortened_shuffled")],
    "faradaic_current": [("resistive_electrode", 107, S, "rate07"), ("copper_contact", 108, T, "short_pretrigger")],
    "hysteresis": [("kramers_relays", 106, P, "short_pretrigger"), ("fulcrum_friction", 107, S, "asrun")],
    "time_delay": [("sweep_averaging", 108, T, "trigger_clock"), ("focus_tracking", 106, P, "asrun")],
    "sensor_offset": [("jaw_bracket", 107, S, "two_pressures"), ("flexible_flag", 106, P, "eis_descending")],
    "clamp_relaxation": [("air_supply", 106, P, "asrun"), ("wicking_pads", 108, T, "merged_loadcell")],
    "dehydration": [("dry_skin", 107, S, "asrun"), ("humidity_wander", 107, S, "host_timed")],
    "strain_resistance": [("double_layer_bypass", 106, P, "dropped_packets"), ("crack_plating", 108, T, "asrun")],
    "large_deflection": [("raised_target", 107, S, "float32_time"), ("drying_curl", 107, S, "short_pretrigger")],
    "mains_pickup": [("generator_test", 106, P, "no_spectra"), ("vfd_interharmonics", 108, T, "resampled")],
    "unexplained": [("linearity_ripple", 106, P, "asrun"), ("linearity_ripple", 107, S, "decimated3"),
                    ("crossover_deadzone", 107, S, "asrun"), ("crossover_deadzone", 108, T, "own_clock"),
                    ("ripple_control", 108, T, "asrun"), ("ripple_control", 106, P, "steps_sines"),
                    ("ac_coupled", 106, P, "settled_sines"), ("ac_coupled", 108, T, "no_loadcell")],
}
CLEAN = [(106, P, "asrun"), (106, P, "short_pretrigger"), (107, S, "asrun"), (107, S, "no_loadcell"),
         (108, T, "asrun"), (108, T, "short_pretrigger")]


def fresh12_cases(only: str | None = None) -> list[Case]:
    """The thirteenth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    106-108)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh12_cases, "inject_fresh12", "fresh12")
