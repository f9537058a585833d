"""A twenty-second held-out set for the diagnosis (issue 12), fresh21, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh20.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (the diffuse half of the double layer on
the plating's outer faces in a de-ionised bath, its capacitance growing as a Gouy-Chapman cosh of the voltage; a
single-supply amplifier's polarity relay switched by a comparator with hysteresis; a closed-cell sponge guard crushed
by the large bends and springing back along a lower plateau; the laser's analogue output able to source but not sink
current into its cable; crack bridges heated by the current they carry; capillary bridges across the cracks of a strip
in air rupturing and re-forming at different openings; an analogue eddy-current probe's exponential gap law; a video
script fitting a parabola through the clamp to the strip's drawn-back edge), some on the history (electrolysis
quickened by the strip's own dissipation; water expelled through the cathodic face by the 1 V drives and taken back
from the bath at rest; a logger whose live plot slows with every sample it holds; clamp pads left compressed overnight
by the previous user, recovering under this session's gaps), some on time or on the clamp pressure (a blotted strip in
air losing the free water that carries its back-flow while it keeps the water that carries its bending; a clamp
screw's threads embedding by the same few micrometres, so the same newtons, at every setting; the laser on a bracket
on the drive amplifier's case, tilting as the case warms with the current; visitors filling the lab with their breath;
a contaminated amplifier board whose mains leakage follows the room's humidity), one linear but not a single lag (a
recast membrane whose channel widths span a hierarchy: a log-uniform spread of back-flow times) and some from the lab's
wiring or sensors (a MEMS accelerometer at the tip used as an inclinometer, reading the tip's acceleration too; a heater
on a fast cycle-skipping controller). Four structures outside the catalogue (truth "unexplained": the dielectric
absorption of the current amplifier's ceramic feedback capacitor, optical feedback into the laser diode from the
strip's face while it stands square to the beam, the impedance analyser measuring while the strip's own current still
drifts, a cluster of dead pixels on the triangulation head's line sensor); clean sessions. All on three bases of new
seeds (133-135: the paper strip, the seed-001 strip on its own sweep, the paper strip 22 mm free) and on the earlier
sets' protocol / data-shape variants plus one new here: a logger whose step records end on a stop trigger, a
post-trigger after the drive's return to rest (``stop_trigger``: the strip's relaxation after the fall not logged).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh20 are reused (importing inject_fresh20 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh21.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh20  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _through
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law, _lag_state
from inject_fresh7 import _superpose
from inject_fresh8 import _late, _leaky
from inject_fresh9 import _dry_by, _session_grid
from inject_fresh10 import _lag_varying, _lambda, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh15 import _edges
from inject_fresh17 import _first_steps
from inject_fresh18 import _bv, _ratio_grid
from inject_fresh20 import _block_starts, _relays, _through_col

# the paper's strip 22 mm free (earlier sets used 20, 23, 24, 25-29, 31-40, 42 and 45 mm; its 1 V step peaks near
# 4.8 mm, 8.8 mm x (22/30)^2, inside the laser's +-20 mm): preset "paper_22", base "p22_135", registered in every
# process importing this module
inject.register_free_length("paper_22", 0.022)

inject.BASES.update({
    "paper_133": ("paper-sweep", "paper", 133),
    "s001_134": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 134),
    "p22_135": ("paper-sweep", "paper_22", 135),
})

G0 = 9.80665  # m/s^2
V_T = 0.025693  # kT/e at 25 C, V


# ------------------------------------------------------------------------------------------------ tools


def _counts(s: Session) -> dict[int, np.ndarray]:
    """Each series' samples numbered through the session in time order (0 for the session's first sample)."""
    out, n = {}, 0
    for r in _chrono(s):
        out[id(r)] = n + np.arange(r.cols["t_s"].size)
        n += r.cols["t_s"].size
    return out


def _series_lookup(x: dict[int, np.ndarray], s: Session) -> Callable[[np.ndarray], np.ndarray]:
    """A per-sample quantity x (id(record) -> array) as a function of session time, linear between samples (and across
    the rests), held beyond the ends: exact at every series' sample times."""
    recs = _chrono(s)
    T = np.concatenate([r.cols["t_s"] for r in recs])
    X = np.concatenate([x[id(r)] for r in recs])
    return lambda t: np.interp(np.asarray(t, float), T, X)


def _step_charge(r: Rec) -> tuple[float, float]:
    """A step record's charging: (C, tau), the charge its current carried above the plateau's leak over the rise's
    plateau per volt, and the time its excess current took to fall to 1/e of its peak."""
    v, i = r.cols["v_V"], r.cols["i_A"]
    on, off = (int(e) for e in _edges(v)[:2])
    amp = float(np.median(v[on:off]))
    leak = float(np.median(i[max(off - int(3 * r.fs), on + 1) : off]))
    ex = (i[on:off] - leak) * math.copysign(1.0, amp)
    k = int(np.argmax(ex))
    below = np.flatnonzero(ex[k:] < ex[k] / math.e)
    tau = max(float(below[0]) if below.size else 1.0, 2.0) / r.fs
    return float(np.sum(ex)) / r.fs / max(abs(amp), 1e-3), tau


def _main_side(s: Session) -> float:
    """The side the strip bends to most: the sign of the session's largest displacement (the 1 V steps' side; a sine
    from rest bends a charge-following strip mostly one way too)."""
    peak = max((float(r.cols["disp_m"][int(np.argmax(np.abs(r.cols["disp_m"])))]) for r in s.series()), key=abs)
    return 1.0 if peak >= 0 else -1.0


def _play_contact(u: np.ndarray, g: float, k: float, P: float, U: float, s0: float) -> tuple[np.ndarray, float]:
    """The reading of a tip whose free position is u (towards a foam guard at the gap g) held back by the foam: a spring
    k (of the tip's stiffness) in series with a crush variable s that the loading plateau P pushes in and the unloading
    plateau U lets back (both in displacement units, P > U), s >= 0, quasi-static. From the state s0; returns the
    readings and the last state."""
    y = u.copy()
    s, last = 0.0, -2
    for j in np.flatnonzero(u > g).tolist():
        if j != last + 1:
            s = s0 if j == 0 else 0.0  # a new contact: the foam sprang back while the tip was off it
        last = j
        uj = float(u[j])
        F = k * (uj - g - s) / (1 + k)
        if F > P:
            yj = uj - P
            s = yj - g - P / k
        elif F < U:
            yj = uj - U
            s2 = yj - g - U / k
            if s2 <= 0.0:
                s, yj = 0.0, (uj + k * g) / (1 + k)
            else:
                s = s2
        else:
            yj = uj - F
        y[j] = yj
    return y, (s if last == u.size - 1 else 0.0)


# ------------------------------------------------------------------------------------------------ back relaxation


def br_free_water_loss(s: Session) -> None:
    """A strip in air mounted straight from its bath and blotted (0-300 s before the first record): the free water in
    its widest channels, which carries the back-flow, evaporates over tau_f (600-2400 s, log) while the water of the
    cations' hydration shells, which carries the bending, stays at the room's humidity. The back-flow's share falls from
    K0 (0.6-1.0) towards K0 k_inf (k_inf 0.15-0.4) and its lag lengthens from tau0 (2-6 s, log) to tau0 (1 + m) (m 1-3)
    as the channels empty (the free water's fraction exp(-u/tau_f)); the reading d - K2(t) x with x the lag of d, sample
    by sample through the session in time order (inject_fresh10._lag_varying); displacement only. Measured (s001_134)
    displacement RMS -37 % (residual 45 %, 1500x its noise)."""
    lead, tau_f = s.rng.uniform(0.0, 300.0), lu(s.rng, 600.0, 2400.0)
    k0, k_inf = s.rng.uniform(0.6, 1.0), s.rng.uniform(0.15, 0.4)
    tau0, m = lu(s.rng, 2.0, 6.0), s.rng.uniform(1.0, 3.0)
    t_m = s.t0 - lead

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        f = np.exp(-np.clip(np.asarray(t, float) - t_m, 0, None) / tau_f)
        return k0 * (k_inf + (1 - k_inf) * f), tau0 * (1 + m * (1 - f))

    _lag_varying(s, state)


def br_hierarchical_pores(s: Session) -> None:
    """A recast membrane (cast from solution and not annealed) whose ionic channels span a hierarchy of widths: each
    width's back-flow lag goes as its width to the -2, and the widths are spread so that the lags fill the decades
    between tau_min (0.5-2 s, log) and tau_max = tau_min r (r 30-300, log) evenly in log, each decade carrying the same
    share. 1 - K2 G(s), G(s) = 1 - ln((1 + s tau_max)/(1 + s tau_min))/ln r (K2 0.8-1.2): a back-flow that grows as the
    log of the time between the two lags, linear but neither one lag, a Cole-Cole, a Havriliak-Negami, a stretched
    exponential nor a log-normal spread. Through inject_fresh2._through with 240 s of the session's history;
    displacement only. Measured (p22_135) displacement RMS -69 % (residual 87 %, 2900x its noise)."""
    t_min, ratio, k2 = lu(s.rng, 0.5, 2.0), lu(s.rng, 30.0, 300.0), s.rng.uniform(0.8, 1.2)
    t_max, lr = t_min * ratio, math.log(ratio)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        return lambda q: 1 - k2 * (1 - np.log((1 + np.asarray(q) * t_max) / (1 + np.asarray(q) * t_min)) / lr)

    new = _through(s, H, 240.0)
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ faradaic current


def far_self_heating(s: Session) -> None:
    """A strip in air electrolysing the water it holds (a symmetric Butler-Volmer branch, 0.05-0.2 mA at 1 V, log, v_t
    0.1-0.2 V) warms by its own dissipation: its temperature rise follows the power v i it takes (the drive times the
    measured current) through its thermal resistance to the still air (1-4 K/mW, log) and its heat capacity (a lag of
    10-40 s, log), and the electrolysis' exchange current follows Arrhenius (E_a 50-70 kJ/mol from 25 C). A leak current
    that grows through each 1 V hold and after the heavy records, and shrinks over the rests. The temperature through
    the session in time order (inject_fresh8._leaky); the current only. Measured (s001_134) current RMS +0.31 %
    (residual 1.0 %, 2.8x its noise)."""
    i1, vt = lu(s.rng, 5e-5, 2e-4), s.rng.uniform(0.1, 0.2)
    r_th, tau, ea = lu(s.rng, 1.0, 4.0), lu(s.rng, 10.0, 40.0), s.rng.uniform(50e3, 70e3)
    rate = {id(r): r_th * 1e3 * np.abs(r.cols["v_V"] * r.cols["i_A"]) / tau for r in s.series()}
    dT = _leaky(s, rate, tau)
    t0 = 298.15
    for r in s.series():
        arr = np.exp(ea / 8.314 * (1 / t0 - 1 / (t0 + dT[id(r)])))
        r.cols["i_A"] = r.cols["i_A"] + arr * _bv(r.cols["v_V"], i1, vt)


def far_gouy_chapman(s: Session) -> None:
    """A strip in a de-ionised bath: the outer faces of its plating, open to the bath, charge a double layer whose
    diffuse half is wide in the dilute water, its capacitance C_GC cosh(u/2 v_T) (Gouy-Chapman) in series with the
    compact layer's C_H = r C_GC (r 5-30, log): the outer faces' capacitance grows from s_inf/(1 + r) to s_inf (0.05-0.2
    of the strip's own, log) as each face's voltage u (half the strip's interface voltage) passes a few v_T acosh(r).
    The interface voltage follows the drive through the strip's own charging lag, both read off the pressure's first
    step record (its charge per volt above the leak, its excess current's 1/e time; an exact lag through the session in
    time order, inject_fresh4._lag_state); the extra charge i = (C(u) - C(0)) dv_i/dt, dv_i/dt = (v - v_i)/tau, on the
    current only (the bath's ions do not bend the strip). A charging current that grows with the drive beyond 0.2-0.4 V,
    with odd harmonics and no DC part. Measured (paper_133) current RMS +2.3 % (residual 7.0 %, 5.3x its noise)."""
    s_inf, r = lu(s.rng, 0.05, 0.2), lu(s.rng, 5.0, 30.0)
    charge = {p: _step_charge(q) for p, q in _first_steps(s).items()}
    if not charge:
        return
    c_any = next(iter(charge.values()))

    vi, y, t_end = {}, 0.0, None
    for q in _chrono(s):  # the interface's voltage: an exact first-order lag of the drive, 0 V over the rests
        tau = charge.get(float(q.entry["pressure_kPa"]), c_any)[1]
        if t_end is not None:
            y *= math.exp(-max(float(q.cols["t_s"][0]) - t_end, 0.0) / tau)
        vi[id(q)] = _lag_state(q.cols["v_V"], q.fs, tau, y)
        y, t_end = float(vi[id(q)][-1]), float(q.cols["t_s"][-1])
    for q in s.series():
        c0, tau = charge.get(float(q.entry["pressure_kPa"]), c_any)
        u = vi[id(q)]
        g = 1 / (1 + r / np.cosh(np.clip(u / 2 / (2 * V_T), -50, 50))) - 1 / (1 + r)
        q.cols["i_A"] = q.cols["i_A"] + s_inf * c0 * g * (q.cols["v_V"] - u) / tau


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_polarity_relay(s: Session) -> None:
    """A single-supply (unipolar) drive amplifier made bipolar by a double-pole relay across its output, switched by a
    comparator with hysteresis on the command (on at +v_h, off at -v_h, v_h 0.05-0.15 V: set wide so that the relay does
    not chatter on the noise at rest; its rest contacts positive). The strip gets the command's magnitude, which the
    amplifier cannot take below its output's saturation v_sat (5-25 mV above ground), with the relay's sign: S[v]
    max(|v|, v_sat), wrong near every zero crossing until the command has passed the other threshold, and +-v_sat at
    rest after the last polarity. A memory of the sign that stays however slowly the drive goes round: loops at the
    crossings of the sines, a jump of about 2 v_h where the relay flips; the logged v_V is the command. The difference S
    max(|v|, v_sat) - v, sample by sample through the session in time order, reaches the current and the displacement
    through the strip's measured step responses (inject_fresh7._superpose). Measured (paper_133) displacement RMS +1.9 %
    (residual 4.5 %, 280x its noise), current RMS +0.36 % (residual 10 %, 7.5x its noise)."""
    vh, vsat = s.rng.uniform(0.05, 0.15), s.rng.uniform(0.005, 0.025)
    state, e = 1.0, {}
    for r in _chrono(s):
        v = r.cols["v_V"]
        sw = np.where(v >= vh, 1.0, np.where(v <= -vh, -1.0, 0.0))
        idx = np.maximum.accumulate(np.where(sw != 0, np.arange(v.size), -1))
        S = np.where(idx >= 0, sw[np.maximum(idx, 0)], state)
        state = float(S[-1])
        e[id(r)] = S * np.maximum(np.abs(v), vsat) - v
    _superpose(s, e)


def hy_foam_guard(s: Session) -> None:
    """A closed-cell sponge (neoprene foam) glued inside the cuvette as a guard against the strip's tip hitting the
    wall, on the side the large drives bend it to, at a gap of 0.4-0.7 of the 1 V harmonic's bend: the tip pressing into
    it meets its elastic stiffness (k_f 0.3-1 of the tip's own), then its cells buckle at a plateau force (0.1-0.3 of
    the scale in tip displacement) and, as the tip comes back, spring back along a lower plateau (0.3-0.6 of it), the
    foam's classic compression loop: the crush variable a play between the two plateaus, released when the tip leaves.
    The reading solves the tip's balance between the strip's pull and the foam, quasi-statically, sample by sample
    through the session in time order; displacement only. Rate-independent loops at the large bends on the foam's side
    only. Measured (p22_135) displacement RMS -5.6 % (residual 6.1 %, 200x its noise)."""
    side, ref = _main_side(s), ref_disp(s)
    g, k = s.rng.uniform(0.4, 0.7) * ref, s.rng.uniform(0.3, 1.0)
    P = s.rng.uniform(0.1, 0.3) * ref
    U = P * s.rng.uniform(0.3, 0.6)
    st = 0.0
    for r in _chrono(s):
        y, st = _play_contact(side * r.cols["disp_m"], g, k, P, U, st)
        r.cols["disp_m"] = side * y


# ------------------------------------------------------------------------------------------------ time delay


def td_live_plot_lag(s: Session) -> None:
    """The laser polled by the logging script in the same loop that redraws its live plot of every sample so far (a
    plotting library re-rendering all the lines at each block): the redraw's time grows with the data held, so each
    reading waits longer in the serial buffer before the script reads and stamps it. A delay from tau0 (1-3 ms, log) at
    the session's first sample to tau_end (8-25 ms, log) at its last, growing with the samples logged (fast in the long,
    fast-sampled records, not at all over the rests), the same for every drive frequency within a record; the session's
    history supplies the samples before each record (inject_fresh8._late); displacement only. Measured (s001_134)
    displacement RMS -0.0011 % (residual 0.5 %, 16x its noise)."""
    t0, t_end = lu(s.rng, 1e-3, 3e-3), lu(s.rng, 8e-3, 25e-3)
    n = _counts(s)
    total = max(sum(r.cols["t_s"].size for r in s.series()) - 1, 1)
    _late(s, lambda r, t: t0 + (t_end - t0) * n[id(r)] / total, 0.3)


def td_source_only_output(s: Session) -> None:
    """The laser's analogue output is a source-only stage (an emitter follower, 0-10 V over the range): it charges the
    cable and the DAQ's input filter capacitor at once but lets them discharge only through the load resistor, so its
    output follows a rising voltage at once and a falling one with tau = R_L C (3-15 ms, log: a long cable to the DAQ's
    rack and a filter capacitor on its input). Which way the voltage falls (towards or away from the head) is drawn.
    Half of each cycle late, the other on time: a lag that grows with the frequency, with even harmonics and a small
    offset on the fast sines. Sample by sample within each record from its first value (settled over the rest before);
    displacement only. Measured (p22_135) displacement RMS -0.018 % (residual 0.13 %, 4.2x its noise)."""
    sg, tau = _sign(s), lu(s.rng, 3e-3, 15e-3)
    for r in s.series():
        x = sg * r.cols["disp_m"]
        a = math.exp(-1.0 / (r.fs * tau))
        y, out = float(x[0]), np.empty(x.size)
        for k, xk in enumerate(x.tolist()):
            y = xk if xk >= y else xk + (y - xk) * a
            out[k] = y
        r.cols["disp_m"] = sg * out


# ------------------------------------------------------------------------------------------------ sensor offset


def so_mems_inclinometer(s: Session) -> None:
    """No laser: a MEMS accelerometer die (2 x 2 mm on a thin flex, about 5 mg, its mass under 4 % of the strip's modal
    mass with the water it carries and left out) glued at the tip of the hanging strip, its sensitive axis along the
    bending direction, used as an inclinometer: it reads g sin(theta) plus the tip's own acceleration, which the lab's
    static calibration (the strip tilted by hand) converts as a uniform arc, d = (L/2) a/g. So the reading is (L/2)
    w'(L) + (L/2g) w''(L, t) through the sensor's digital low-pass (a low-power part at 25-60 readings a second: second
    order at 6-15 Hz, log): right at rest, a zero where w^2 = 2 g/L (4-5 Hz, near the first resonance) and the sign
    turned above it; the poles where they were. The slope through the beam's own transfer functions
    (labrig.physics.transfer with a sensor lever), with the session's history (inject_fresh2._through); displacement
    only. Measured (paper_133) displacement RMS -4.6 % (residual 4.8 %, 300x its noise; the reading's own noise at rest
    4.0 um)."""
    from labrig.physics import presets, transfer

    fc = lu(s.rng, 6.0, 15.0)
    wc = 2 * math.pi * fc
    pre = presets.get(s.preset)
    L = float(s.specimen["length_m"])
    lev = 1e-3 * L
    grids: dict[float, Callable] = {}

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        p = float(r.entry["pressure_kPa"])
        if p not in grids:
            sp = pre.specimen(p)

            def slope(z: np.ndarray) -> np.ndarray:
                tip = transfer.displacement_tf(z, sp)
                return (transfer.displacement_tf(z, sp.with_(sensor_lever=lev)) / tip - 1) / lev

            grids[p] = _ratio_grid(slope, 600.0, complex(2.0 / L))
        sl = grids[p]

        def h(z: np.ndarray) -> np.ndarray:
            z = np.asarray(z)
            return (0.5 * L * sl(z) + 0.5 * L / G0 * z * z) / (1 + 1.4142 * z / wc + (z / wc) ** 2)

        return h

    new = _through(s, H, 2.0)
    map_disp(s, lambda r, d: new[id(r)])


def so_amplifier_bracket(s: Session) -> None:
    """The laser head on an aluminium bracket screwed to the drive amplifier's case (the one flat surface near the
    cuvette), aimed at the start a margin m (0.1-0.4 mm) inside the tip's end: the amplifier dissipates a quiescent
    share (0.3-1 of its heaviest second's load) from its switching on (300-1200 s before the first record) plus a share
    in proportion to the current it delivers, the case and bracket warm through a lag of 200-800 s (log), and the
    bracket's bending tilts the beam so the spot walks inboard by Delta (0.3-1.2 mm at the session's warmest). The strip
    read at the moving station (inject_fresh10._station) on a 1 s grid of the current's load; displacement only.
    Measured (p22_135) displacement RMS -8.7 % (residual 8.8 %, 290x its noise)."""
    L = float(s.specimen["length_m"])
    m, dlt = s.rng.uniform(1e-4, 4e-4), s.rng.uniform(3e-4, 1.2e-3)
    lead, tau, q = s.rng.uniform(300.0, 1200.0), lu(s.rng, 200.0, 800.0), s.rng.uniform(0.3, 1.0)
    tg = _session_grid(s, 1.0, lead)
    recs = _chrono(s)
    t = np.concatenate([r.cols["t_s"] for r in recs])
    x = np.abs(np.concatenate([r.cols["i_A"] for r in recs]))
    cell = np.clip(((t - tg[0]) // 1.0).astype(int), 0, tg.size - 1)
    load = np.bincount(cell, weights=x, minlength=tg.size) / np.maximum(np.bincount(cell, minlength=tg.size), 1)
    load = load / max(float(load.max()), 1e-12) + q
    a = math.exp(-1.0 / tau)
    temp = np.empty(tg.size)
    th = 0.0
    for k, h in enumerate(load.tolist()):
        th = h + (th - h) * a
        temp[k] = th
    temp = temp / float(temp.max())
    _station(s, lambda r: 1 - (m + dlt * np.interp(r.cols["t_s"], tg, temp)) / L, 1 - (m + dlt) / L)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_thread_embedding(s: Session) -> None:
    """The clamp's screw, its washer and the jaw's seat embed after each tightening (the surface roughness of every
    loaded joint flattening, VDI 2230's settling): a fixed settling displacement, so the same force lost at every
    setting, Delta F (0.3-1.2 N) as 1 - exp(-(u/tau)^beta) (tau 20-120 s, log, beta 0.3-0.5, from each setting 10-40 s
    before its block). A share of the force that falls as 1/p: 3-12 % of the lightest setting's, a percent or so of the
    tightest. Through the preset's clamp law (inject_fresh4._clamp_law), the load cell showing it. Measured (paper_133)
    displacement RMS -0.0011 % (residual 0.014 %, 0.87x its noise), current RMS -0.025 % (residual 0.15 %, 0.11x its
    noise), the load cell at 0.940-0.996 of its reading."""
    df, tau, beta, lead = s.rng.uniform(0.3, 1.2), lu(s.rng, 20.0, 120.0), s.rng.uniform(0.3, 0.5), \
        s.rng.uniform(10.0, 40.0)
    area = float(s.specimen["clamp_area_m2"])

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        u = np.clip(t - (t_set - lead), 0, None)
        return 1 - df / (p * 1e3 * area) * -np.expm1(-((u / tau) ** beta))

    _clamp_law(s, rel)


def cr_overnight_set(s: Session) -> None:
    """Elastomer pads left compressed overnight by the previous user (6-16 h at 1-1.5 times this session's top force,
    released 5-20 min before the first setting): under this session's screw-set gaps they are still recovering their
    thickness. The pads as a linear viscoelastic solid, relaxation k_inf + (1 - k_inf)(1 + t/tau)^-n (k_inf 0.8-0.92,
    tau 1-10 s, log, n 0.15-0.35), the force the Boltzmann sum of every gap change: the overnight compression and its
    release, then each setting (10-40 s before its block) made to reach its target on the load cell. The early blocks'
    force relaxes less, or rises, as the overnight set recovers; the later ones relax as fresh pads would. Through the
    preset's clamp law (inject_fresh4._clamp_law), the load cell showing it. Measured (p22_135) displacement RMS -0.0043
    % (residual 0.12 %, 3.9x its noise), current RMS -0.019 % (residual 0.63 %, 0.46x its noise), the load cell at
    0.850-0.969 of its reading."""
    f_prev, hold, rel_t = s.rng.uniform(1.0, 1.5), s.rng.uniform(6 * 3600.0, 16 * 3600.0), s.rng.uniform(300.0, 1200.0)
    k_inf, tau, n = s.rng.uniform(0.8, 0.92), lu(s.rng, 1.0, 10.0), s.rng.uniform(0.15, 0.35)
    blocks = _block_starts(s)
    leads = s.rng.uniform(10.0, 40.0, len(blocks))
    top = max(p for p, _ in blocks)

    def K(t: np.ndarray) -> np.ndarray:
        return np.where(t >= 0, k_inf + (1 - k_inf) * (1 + np.clip(t, 0, None) / tau) ** -n, 0.0)

    t_set = [a - ld for (_, a), ld in zip(blocks, leads)]
    steps = [(t_set[0] - rel_t - hold, f_prev * top), (t_set[0] - rel_t, -f_prev * top)]
    for (p, _), ts in zip(blocks, t_set):
        now = sum(dd * float(K(np.array([ts - tj]))[0]) for tj, dd in steps)
        steps.append((ts, p - now))
    tj = np.array([x for x, _ in steps])
    dj = np.array([x for _, x in steps])

    def force(t: np.ndarray) -> np.ndarray:
        return K(np.asarray(t, float)[:, None] - tj[None, :]) @ dj

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        return force(t) / p

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_eo_expulsion(s: Session) -> None:
    """A strip in water whose cathodic face's cracks let the electro-osmotic flux out: beyond v_e (0.5-0.8 V of drive)
    the water the cations drag to the cathode leaves through them into the bath, at a rate growing with the drive's
    excess (a held 1 V losing 2-6 % of the strip's water in 30 s), and the strip takes water back from the bath through
    its faces over tau_r (200-800 s, log). The loss a leaky store through the session in time order
    (inject_fresh8._leaky), rising in the 1 V records, falling in the 0.5 V ones and the rests. The gain as the water,
    the conductance as its 1.5-2.5th power, the spectra at the next series' start (inject_fresh9._dry_by). Measured
    (p22_135) displacement RMS -2.1 % (residual 2.2 %, 72x its noise), current RMS -3.0 % (residual 3.2 %, 2.3x its
    noise), the spectra's |Z| +0, +0.95, +1.4, +1.4 %."""
    ve, x30, tau, gc = s.rng.uniform(0.5, 0.8), s.rng.uniform(0.02, 0.06), lu(s.rng, 200.0, 800.0), \
        s.rng.uniform(1.5, 2.5)
    g = x30 / 30.0
    rate = {id(r): g * np.clip(np.abs(r.cols["v_V"]) - ve, 0, None) / (1 - ve) for r in s.series()}
    loss = _series_lookup(_leaky(s, rate, tau), s)
    _dry_by(s, lambda t: loss(t), lambda t: 1 - (1 - loss(t)) ** gc)


def dh_room_occupancy(s: Session) -> None:
    """A strip in air, taken from a humid storage box (0.15-0.3 above the room's relative humidity) and mounted 300-1800
    s before the first record, dries towards the room's humidity (0.35-0.55) through Nafion's isotherm
    (inject_fresh10._lambda) and its sorption lag (100-400 s, log); 20-60 % into the session a group comes into the lab
    and stays 10-30 min, their breath raising the humidity by 0.05-0.15 with the room's air-change time (10-30 min) and
    letting it fall as they leave: the strip dries, takes some water back and dries again. The gain as the water, the
    conductance as its 1.5-2.5th power, relative to the first record, the spectra at the next series' start
    (inject_fresh9._dry_by). Measured (s001_134) displacement RMS -8.4 % (residual 9.7 %, 320x its noise), current RMS
    -21 % (residual 22 %, 60x its noise), the spectra's |Z| +0, +40, +24, +22 %."""
    rh0, box, lead = s.rng.uniform(0.35, 0.55), s.rng.uniform(0.15, 0.3), s.rng.uniform(300.0, 1800.0)
    tau_s, gc = lu(s.rng, 100.0, 400.0), s.rng.uniform(1.5, 2.5)
    t_in = s.t0 + s.rng.uniform(0.2, 0.6) * (s.t1 - s.t0)
    stay, drh, t_air = s.rng.uniform(600.0, 1800.0), s.rng.uniform(0.05, 0.15), s.rng.uniform(600.0, 1800.0)
    tg = _session_grid(s, 1.0, lead)
    u_in, u_out = np.clip(tg - t_in, 0, None), np.clip(tg - t_in - stay, 0, None)
    rh = rh0 + drh * (-np.expm1(-u_in / t_air) + np.expm1(-u_out / t_air))
    target = _lambda(np.clip(rh, 0.0, 0.95))
    w, x = np.empty(tg.size), float(_lambda(np.array([min(rh0 + box, 0.95)]))[0])
    a = math.exp(-1.0 / tau_s)
    for k, y in enumerate(target.tolist()):
        x = y + (x - y) * a
        w[k] = x
    w0 = float(np.interp(s.t0, tg, w))
    _dry_by(s, lambda t: 1 - np.interp(t, tg, w) / w0, lambda t: 1 - (np.interp(t, tg, w) / w0) ** gc)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_bridge_joule(s: Session) -> None:
    """The cracks of the tensioned face (one face, drawn, the other at 0.2-0.5 of its gauge; each e^1.5 of its tension
    over the session's largest) carry the face's current through narrow metal bridges, which the current heats: their
    resistance rises with their temperature, which follows the current's square (over a high percentile of the session's
    current) through a thermal lag of 1-10 ms (log), by a factor 1 + a (a 1-4) at that current. A crack gauge that grows
    where the bend and the current are both large (the fast large sines near resonance, the 1 V harmonics), little on a
    slow bend or a spike at rest. Gains fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R
    (inject_fresh3._resist). Measured (paper_133) displacement RMS -1.0 % (residual 1.2 %, 72x its noise), current RMS
    -0.21 % (residual 1.3 %, 0.99x its noise)."""
    side, o = _sign(s), s.rng.uniform(0.2, 0.5)
    a, tau = s.rng.uniform(1.0, 4.0), lu(s.rng, 1e-3, 1e-2)
    k = ref_disp(s) / (_largest(s) or ref_disp(s))
    i_ref = float(np.percentile(np.abs(np.concatenate([r.cols["i_A"] for r in s.series()])), 99.5)) or 1e-3

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        x = k * e
        gauge = np.clip(side * x, 0, None) ** 1.5 + o * np.clip(-side * x, 0, None) ** 1.5
        q = (r.cols["i_A"] / i_ref) ** 2
        h = inject.lti(q - q[0], r.fs, lambda z: 1 / (1 + tau * z)) + q[0]  # settled at the record's start
        return gauge * (1 + a * h)

    _resist(s, shape, (0.03, 0.08), (0.06, 0.15))


def sr_capillary_bridges(s: Session) -> None:
    """A strip in air whose cracked faces hold water menisci across their cracks: a crack whose meniscus stands conducts
    through it (a share beta 0.1-0.4 of its open resistance), and each meniscus ruptures when its crack opens past its
    own width (32 cracks a face, their rupture openings 0.1-0.9 of the session's largest tension, log-uniform) and forms
    again only when the crack closes to 0.3-0.7 of that (capillary condensation needs the narrower gap): relays in the
    face's tension (inject_fresh20._relays), one face drawn, the other at 0.2-0.5. dR/R = tension (beta + (1 - beta)
    share ruptured), through the session in time order (the menisci re-form at rest). Gains fall by 0.05-0.15
    (displacement) and 0.1-0.3 (current) per unit of dR/R (inject_fresh3._resist). Measured (s001_134) displacement RMS
    -5.1 % (residual 5.4 %, 180x its noise), current RMS -1.5 % (residual 5.2 %, 14x its noise)."""
    side, o, beta = _sign(s), s.rng.uniform(0.2, 0.5), s.rng.uniform(0.1, 0.4)
    n = 32
    up = [np.exp(s.rng.uniform(math.log(0.1), math.log(0.9), n)) for _ in range(2)]
    dn = [u * s.rng.uniform(0.3, 0.7, n) for u in up]
    ref = ref_disp(s)
    k = ref / (_largest(s) or ref)
    state = [np.zeros(n), np.zeros(n)]
    dr = {}
    for r in _chrono(s):
        x = k * r.cols["disp_m"] / ref
        out = np.zeros(x.size)
        for f, (w, u) in enumerate(((1.0, np.clip(side * x, 0, None)), (o, np.clip(-side * x, 0, None)))):
            st, state[f] = _relays(u, up[f], dn[f], state[f])
            out += w * u * (beta + (1 - beta) * st.mean(axis=1))
        dr[id(r)] = out
    _resist(s, lambda r, e: dr[id(r)], (0.05, 0.15), (0.1, 0.3))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_eddy_gap_law(s: Session) -> None:
    """An eddy-current proximity probe facing the tip (on one side, drawn) reads the tip's electrode (or a foil on it)
    at a rest gap where its output falls exponentially with the gap, over lambda (2-4 times the session's largest bend):
    not the linearised industrial kind but an analogue proximity sensor calibrated by the lab with two points close
    about rest. The reading lambda (exp(y/lambda) - 1), y the bend towards the probe: long towards it, short away, exact
    at rest; displacement only. Measured (p22_135) displacement RMS +10 % (residual 11 %, 360x its noise)."""
    side = _sign(s)
    lam = s.rng.uniform(2.0, 4.0) * (_largest(s) or ref_disp(s))
    map_disp(s, lambda r, d: side * lam * np.expm1(side * d / lam))


def ld_parabola_video_fit(s: Session) -> None:
    """Video of the strip's edge from the side, its deflection taken by the lab's script as a parabola y = a x^2 through
    the clamp point with zero slope (the small-deflection shape) fitted by least squares to the edge's points in the lab
    frame (x along the strip's rest axis, from the jaw's edge; the first 0.1-0.3 of the length hidden by the jaw's
    block) and evaluated at the nominal length: d = a L^2. On the exact arc the edge's points draw back and lie on a
    circle, not a parabola: a map of the linear bend d (uniform curvature 2 d/L^2), tabulated on a grid and
    interpolated; displacement only. Measured (paper_133) displacement RMS +3.6 % (residual 4.0 %, 250x its noise)."""
    L = float(s.specimen["length_m"])
    xa = s.rng.uniform(0.1, 0.3)
    big = 1.6 * (_largest(s) or ref_disp(s))
    dg = np.linspace(-big, big, 2001)
    sg = np.linspace(xa, 1.0, 24) * L
    kap = 2 * dg[:, None] / L**2
    small = np.abs(kap) < 1e-9
    ks = np.where(small, 1.0, kap)
    X = np.where(small, sg[None, :], np.sin(kap * sg[None, :]) / ks)
    Y = np.where(small, 0.5 * kap * sg[None, :] ** 2, (1 - np.cos(kap * sg[None, :])) / ks)
    a = np.sum(X**2 * Y, axis=1) / np.sum(X**4, axis=1)
    table = a * L**2
    map_disp(s, lambda r, d: np.interp(d, dg, table))


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_damp_leakage(s: Session) -> None:
    """A current amplifier whose input pins sit next to a mains-fed pin (the transformer's secondary on the same board),
    the board's surface contaminated (flux residue): the leakage current across it, the line (50 or 60 Hz) with the
    transformer's third harmonic (0.1-0.3), is 5-25 uA (log) at the room's mean humidity and follows the surface's
    conductance, exponential in the humidity, which the air conditioning cycles (+-0.03-0.08 over 900-2400 s): the hum's
    level breathes by a factor e^(+-0.5-1.2) with the cycle. On the current only. Measured (s001_134) current RMS
    +0.0024 % (residual 0.69 %, 1.9x its noise)."""
    f0, h3 = _line_f(s), s.rng.uniform(0.1, 0.3)
    a0, per, ph = lu(s.rng, 5e-6, 2.5e-5), s.rng.uniform(900.0, 2400.0), s.rng.uniform(0, 2 * np.pi)
    swing = s.rng.uniform(0.5, 1.2)
    p1, p3 = s.rng.uniform(0, 2 * np.pi, 2)
    for r in s.series():
        t = r.cols["t_s"]
        level = a0 * np.exp(swing * np.sin(2 * np.pi * t / per + ph))
        r.cols["i_A"] = r.cols["i_A"] + level * (np.cos(2 * np.pi * f0 * t + p1) + h3 * np.cos(6 * np.pi * f0 * t + p3))


def mp_cycle_skipping(s: Session) -> None:
    """A heater (a water bath's or an oven's) on a fast cycle-skipping controller: a solid-state relay passing whole
    line cycles, Q of every P (1 of 2, 1 of 3, 2 of 3, 1 of 4 or 3 of 4), the pattern following the controller's demand,
    which moves every 60-240 s. Its cord's field, the gated line current, induced into the leads (its time derivative
    over the line's angular frequency): lines at multiples of f/P, sub- and interharmonics of the line (25, 75 Hz or
    16.7, 33.3 Hz at 50 Hz) besides the line itself; 1-4 um on the displacement, 4-15 uA on the current (log), phase
    locked to the session clock. Measured (paper_133) displacement RMS +1.6e-05 % (residual 0.055 %, 3.4x its noise),
    current RMS +7.4e-05 % (residual 0.1 %, 0.076x its noise)."""
    f0 = _line_f(s)
    pats = [(2, 1), (3, 1), (3, 2), (4, 1), (4, 3)]
    ad, ai = lu(s.rng, 1e-6, 4e-6), lu(s.rng, 4e-6, 1.5e-5)
    ph = s.rng.uniform(0, 1)
    edges = [s.t0 - 60.0]
    while edges[-1] < s.t1:
        edges.append(edges[-1] + s.rng.uniform(60.0, 240.0))
    pick = s.rng.integers(0, len(pats), len(edges))
    for r in s.series():
        t = r.cols["t_s"]
        seg = np.clip(np.searchsorted(edges, t, side="right") - 1, 0, len(edges) - 1)
        P = np.array([pats[j][0] for j in pick])[seg]
        Q = np.array([pats[j][1] for j in pick])[seg]
        cyc = np.floor(f0 * t + ph).astype(np.int64)
        on = (cyc % P) < Q
        wave = np.where(on, np.cos(2 * np.pi * (f0 * t + ph)), 0.0)
        r.cols["disp_m"] = r.cols["disp_m"] + ad * wave
        r.cols["i_A"] = r.cols["i_A"] + ai * wave


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_feedback_soakage(s: Session) -> None:
    """The current amplifier's transimpedance feedback capacitor is a high-k ceramic (X7R/Y5V), whose dielectric
    absorption stores a share of every charge it carries in slow polarisation and gives it back later: its output reads
    H(s) i, H = 1/(1 + sum a_j s tau_j/(1 + s tau_j)), two absorption branches (tau 0.2-1 s and 5-30 s, log, a 1-4 %
    each). The charging spikes read a few percent low and leave a slow tail of the same charge after them; DC gain 1;
    the strip and the other channels as they were. Through inject_fresh20._through_col with 60 s of the session's
    history; the current only. Measured (paper_133) current RMS -3.0 % (residual 3.1 %, 2.3x its noise); (s001_134)
    current RMS -5.0 % (residual 5.2 %, 14x its noise)."""
    t1, t2 = lu(s.rng, 0.2, 1.0), lu(s.rng, 5.0, 30.0)
    a1, a2 = s.rng.uniform(0.01, 0.04), s.rng.uniform(0.01, 0.04)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        return lambda z: 1 / (1 + a1 * t1 * np.asarray(z) / (1 + t1 * np.asarray(z))
                              + a2 * t2 * np.asarray(z) / (1 + t2 * np.asarray(z)))

    new = _through_col(s, H, 60.0, "i_A")
    for r in s.series():
        r.cols["i_A"] = new[id(r)]


def out_optical_feedback(s: Session) -> None:
    """The strip's plated face stands square to the laser's beam at rest and mirrors part of it straight back into the
    laser diode, whose output then hops between modes and flickers: the head's reading carries an extra noise, 5-20 um
    (log, band-limited by its averaging, a first-order 30-150 Hz), while the tip's tilt 2 d/L is within theta_c (0.2-1
    deg) of square, as a Gaussian of the tilt, and none once the strip is bent away. Noise at rest and through the small
    and fast records, clean on the large bends: not the drive's, not the strip's. Displacement only. Measured (s001_134)
    displacement RMS +0.00072 % (residual 0.38 %, 12x its noise); (p22_135) displacement RMS +0.00046 % (residual 0.3 %,
    10x its noise)."""
    sig, fc, th = lu(s.rng, 5e-6, 2e-5), lu(s.rng, 30.0, 150.0), math.radians(s.rng.uniform(0.2, 1.0))
    L = float(s.specimen["length_m"])
    for r in _chrono(s):
        d = r.cols["disp_m"]
        w = s.rng.standard_normal(d.size)
        wc = 2 * math.pi * min(fc, 0.4 * r.fs)
        w = inject.lti(w, r.fs, lambda z: 1 / (1 + z / wc))
        w = w / max(float(np.std(w)), 1e-12)
        r.cols["disp_m"] = d + sig * w * np.exp(-0.5 * (2 * d / L / th) ** 2)


def out_eis_drift(s: Session) -> None:
    """The impedance analyser measures each spectrum with its 10 mV sine while the strip is still relaxing from the
    record before it: the strip's own current drifts by a (0.3-3 uA/s, log, its sign and size drawn for each spectrum)
    across the few cycles each point integrates, and a linear drift over whole cycles projects onto the sine as j 2
    a/omega: each point's admittance gains j 2 a/(omega V_ac). The lowest frequencies' reactance bent up or down, the
    error falling as 1/f^2 relative to the strip's admittance, the high frequencies untouched: a spectrum that no strip
    (and no time series) has. Only the spectra change. Measured (paper_133) the spectra's |Z| at 0.1 Hz +3.8, -1.7,
    -2.1, -13 %, their phase +2.7, -1.1, -1.4, -8.1 deg; (p22_135) |Z| at 0.1 Hz -3.3, +3.6, -2.0, -8.4 %, phase -1.9,
    +2.1, -1.2, -4.8 deg."""
    for r in s.recs:
        if r.series:
            continue
        a = _sign(s) * lu(s.rng, 3e-7, 3e-6)
        w = 2 * np.pi * r.cols["f_Hz"]
        y = 1 / (r.cols["z_re_ohm"] + 1j * r.cols["z_im_ohm"]) + 2j * a / (w * 0.01)
        r.cols["z_re_ohm"], r.cols["z_im_ohm"] = (1 / y).real, (1 / y).imag


def out_dead_pixel(s: Session) -> None:
    """A cluster of dead pixels (1-3 adjacent) on the triangulation head's line sensor (its range of 40 mm over
    1024-4096 pixels): when the spot's image (a Gaussian of 3-8 pixels) passes over them, the centroid loses their light
    and shifts away from them, by their share of the image times their distance from its centre, -(n pitch/(sigma sqrt(2
    pi))) (d_p - d) exp(-(d - d_p)^2/2 sigma^2): a fixed S-shaped error of a few um about one reading d_p (on the side
    the strip bends to, 0.1-0.9 of the 1 V harmonic's bend), wherever and whenever the tip passes it. Displacement only.
    Measured (s001_134) displacement RMS -0.013 % (residual 0.63 %, 20x its noise); (p22_135) displacement RMS -0.0038 %
    (residual 0.086 %, 2.9x its noise)."""
    pitch = 0.04 / float(s.rng.integers(1024, 4097))
    sig, nd = pitch * s.rng.uniform(3.0, 8.0), int(s.rng.integers(1, 4))
    dp = _main_side(s) * s.rng.uniform(0.1, 0.9) * ref_disp(s)
    c = nd * pitch / (sig * math.sqrt(2 * math.pi))
    map_disp(s, lambda r, d: d - c * (dp - d) * np.exp(-0.5 * ((d - dp) / sig) ** 2))


FRESH21_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"free_water_loss": br_free_water_loss, "hierarchical_pores": br_hierarchical_pores},
    "faradaic_current": {"self_heating": far_self_heating, "gouy_chapman": far_gouy_chapman},
    "hysteresis": {"polarity_relay": hy_polarity_relay, "foam_guard": hy_foam_guard},
    "time_delay": {"live_plot_lag": td_live_plot_lag, "source_only_output": td_source_only_output},
    "sensor_offset": {"mems_inclinometer": so_mems_inclinometer, "amplifier_bracket": so_amplifier_bracket},
    "clamp_relaxation": {"thread_embedding": cr_thread_embedding, "overnight_set": cr_overnight_set},
    "dehydration": {"eo_expulsion": dh_eo_expulsion, "room_occupancy": dh_room_occupancy},
    "strain_resistance": {"bridge_joule": sr_bridge_joule, "capillary_bridges": sr_capillary_bridges},
    "large_deflection": {"eddy_gap_law": ld_eddy_gap_law, "parabola_video_fit": ld_parabola_video_fit},
    "mains_pickup": {"damp_leakage": mp_damp_leakage, "cycle_skipping": mp_cycle_skipping},
    "unexplained": {"feedback_soakage": out_feedback_soakage, "optical_feedback": out_optical_feedback,
                    "eis_drift": out_eis_drift, "dead_pixel": out_dead_pixel},
}
inject.register_forms(FRESH21_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_stop_trigger(s: Session) -> None:
    """A logger armed with a stop trigger on its step records (a digitiser's or a LabVIEW acquisition's reference
    trigger on the drive's return to rest): each step record ends a post-trigger time (0.3-2 s, log, for the session)
    after the drive's fall, the first sample past half its excursion back, so the strip's relaxation after the fall is
    not logged; the sines, the spectra and the manifest as they were, the session clock kept. ``labrig import`` takes it
    (the fitter reads the edges off the data)."""
    post = lu(s.rng, 0.3, 2.0)
    for r in s.series():
        if r.kind != "step":
            continue
        e = _edges(r.cols["v_V"])
        if e.size < 2:
            continue
        n = int(e[1]) + int(round(post * r.fs)) + 1
        if n < r.cols["t_s"].size:
            r.cols = {k: x[:n] for k, x in r.cols.items()}


inject.VARIANTS.update({"stop_trigger": v_stop_trigger})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_133", "s001_134", "p22_135"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 133-135
    "back_relaxation": [("free_water_loss", 134, S, "settled_sines"),
                        ("hierarchical_pores", 135, T, "short_pretrigger")],
    "faradaic_current": [("self_heating", 134, S, "merged_loadcell"), ("gouy_chapman", 133, P, "log_steps")],
    "hysteresis": [("polarity_relay", 133, P, "two_pressures"), ("foam_guard", 135, T, "swinging_door")],
    "time_delay": [("live_plot_lag", 134, S, "fixed_decimals"), ("source_only_output", 135, T, "float32_time")],
    "sensor_offset": [("mems_inclinometer", 133, P, "coherent_sines"),
                      ("amplifier_bracket", 135, T, "shortened_shuffled")],
    "clamp_relaxation": [("thread_embedding", 133, P, "host_timed"), ("overnight_set", 135, T, "tared_records")],
    "dehydration": [("eo_expulsion", 135, T, "cycle_averaged"), ("room_occupancy", 134, S, "stop_trigger")],
    "strain_resistance": [("bridge_joule", 133, P, "stop_trigger"), ("capillary_bridges", 134, S, "dropped_packets")],
    "large_deflection": [("eddy_gap_law", 135, T, "resampled"), ("parabola_video_fit", 133, P, "decimated3")],
    "mains_pickup": [("damp_leakage", 134, S, "trigger_clock"), ("cycle_skipping", 133, P, "eis_descending")],
    "unexplained": [("feedback_soakage", 133, P, "stop_trigger"), ("feedback_soakage", 134, S, "rate07"),
                    ("optical_feedback", 134, S, "no_loadcell"), ("optical_feedback", 135, T, "steps_sines"),
                    ("eis_drift", 133, P, "fir_decimated"), ("eis_drift", 135, T, "own_clock"),
                    ("dead_pixel", 134, S, "stop_trigger"), ("dead_pixel", 135, T, "scan_hold")],
}
CLEAN = [(133, P, "asrun"), (133, P, "stop_trigger"), (134, S, "asrun"), (134, S, "no_spectra"),
         (135, T, "asrun"), (135, T, "stop_trigger")]


def fresh21_cases(only: str | None = None) -> list[Case]:
    """The twenty-second held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    133-135)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh21_cases, "inject_fresh21", "fresh21")
