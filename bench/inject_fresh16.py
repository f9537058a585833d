"""A seventeenth held-out set for the diagnosis (issue 12), fresh16, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh15.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (a back-flow through an anode layer the
bend has emptied, platelets of a cracked film butting together under compression, a cracked silver-epoxy joint at
the electrode's feed opening with one bending direction, a meniscus pinned at the bath's water line, a drive
amplifier whose supply ripple grows with its load), some on the history (electrolysis gas lodged in the pores, the
strip's electrolysis gases discharging as a hydrogen-oxygen cell, the drive amplifier's fan switching on after the
heavy records), some on time or on the clamp pressure (PTFE pads passing their 19 C transition in a warming bath, a
bath clouding under the laser's automatic averaging, a charger plugged into the logging laptop, felt pads feeding
water to the root less as they are squeezed, the clamp's Poisson bulge pre-stretching the films at the jaw's edge),
and some from the lab's wiring or settings (protection diodes across the strip, a tracking stage with a lead screw's
backlash, a laser polled over a serial line, a script re-aiming the laser at each record, a push-pull pair of heads
misaligned along the strip, a force servo holding a drifting load cell's reading, a triangulation head calibrated in
air reading through a window into water). Four structures outside the catalogue (truth "unexplained": the drive's
output task on a clock of its own, a DC-blocking capacitor in the drive line, a multiplexed DAQ's ghost of the laser's
channel in the current's, the strip's leads swapped at re-clampings); clean sessions. All on three bases of new seeds
(118-120: the paper strip, the seed-001 strip on its own sweep, the paper strip 29 mm free) and on the earlier sets'
protocol / data-shape variants plus one new here: a logger that decimates every record through a linear-phase
anti-alias filter to a rate of its own (``fir_decimated``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh15 are reused (importing inject_fresh15 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh16.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy import signal, special

import inject
import inject_fresh15  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp
from inject_fresh2 import _chrono, _spec, _through
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law, _preset, _ratio_both
from inject_fresh6 import _blocks
from inject_fresh8 import _hum
from inject_fresh9 import _dry_by, _gaps, _session_grid
from inject_fresh10 import _lag_varying, _lambda, _station
from inject_fresh11 import _walk
from inject_fresh12 import _line_f
from inject_fresh14 import _lagged, _largest

# the paper's strip 29 mm free (earlier sets used 20, 25, 27, 28, 30, 31, 32-40, 42 and 45 mm; its 1 V step peaks
# near 8.2 mm, 8.8 mm x (29/30)^2, 8.27 mm measured, inside the laser's +-20 mm): registered in every process importing
# this module
inject.register_free_length("paper_29", 0.029)

inject.BASES.update({
    "paper_118": ("paper-sweep", "paper", 118),
    "s001_119": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 119),
    "p29_120": ("paper-sweep", "paper_29", 120),
})

GAMMA_WATER = 0.072  # N/m, water's surface tension at 25 C
LASER_M_PER_V = 2e-3  # the laser's analogue scale (docs/effects.md: 2 mm/V)
CURRENT_A_PER_V = 1e-2  # the current amplifier's (10 mA/V)


# ------------------------------------------------------------------------------------------------ tools


def _grid_of(s: Session, col: str, weight: Callable[[np.ndarray, np.ndarray], np.ndarray] | None = None,
             lead: float = 600.0) -> tuple[np.ndarray, np.ndarray]:
    """A 1 s grid over the session (from ``lead`` s before its first sample) and, per cell, the mean of abs(col)
    (or of weight(col, v)) over the samples in it, 0 at rest: the load an instrument saw second by second."""
    tg = _session_grid(s, 1.0, lead)
    recs = _chrono(s)
    t = np.concatenate([r.cols["t_s"] for r in recs])
    x = np.concatenate([r.cols[col] for r in recs])
    v = np.concatenate([r.cols["v_V"] for r in recs])
    cell = np.clip(((t - tg[0]) // 1.0).astype(int), 0, tg.size - 1)
    n = np.bincount(cell, minlength=tg.size)
    w = np.abs(x) if weight is None else weight(x, v)
    return tg, np.bincount(cell, weights=w, minlength=tg.size) / np.maximum(n, 1)


def _held_area(t: np.ndarray, d: np.ndarray) -> Callable[[np.ndarray], np.ndarray]:
    """u -> int_{t[0]}^{u} d, d held at its first value before the record and its last after it (trapezoids)."""
    cum = np.r_[0.0, np.cumsum(0.5 * (d[1:] + d[:-1]) * np.diff(t))]

    def area(u: np.ndarray) -> np.ndarray:
        u = np.asarray(u, float)
        return np.where(u < t[0], d[0] * (u - t[0]),
                        np.where(u > t[-1], cum[-1] + d[-1] * (u - t[-1]), np.interp(u, t, cum)))

    return area


def _block_pressure(s: Session) -> Callable[[np.ndarray], np.ndarray]:
    """Session time -> the clamp pressure set at it (the block it falls in; the first block's before the session)."""
    spans = sorted((a, p) for p, (a, _) in _blocks(s).items())
    starts, ps = np.array([a for a, _ in spans]), np.array([p for _, p in spans])
    return lambda t: ps[np.clip(np.searchsorted(starts, np.asarray(t, float), side="right") - 1, 0, None)]


def _eibeam(s: Session) -> tuple[float, float, float]:
    """The strip's bending stiffness EI (the preset's modulus, the manifest's width and thickness), width, length."""
    b, h, L = (float(s.specimen[k]) for k in ("width_m", "thickness_m", "length_m"))
    return _preset(s).specimen().mechanics.E * b * h**3 / 12, b, L


# ------------------------------------------------------------------------------------------------ back relaxation


def br_anode_depletion(s: Session) -> None:
    """The back-flow returns to the anode side, whose pores the forward drag has just emptied: the more water the bend
    has moved, the drier that layer, and its permeability falls steeply with its water (Kozeny-Carman), so the
    returning flow slows as it grows: the store x of water moved follows the bend d with a lag tau0 (1 + (x/x_d)^m)
    (tau0 3-10 s, log; x_d 0.3-0.8 of the session's largest bend; m 1.5-2.5), the reading d - K2 x (K2 0.8-1.2).
    Small sines relax at tau0, the 1 V steps several times more slowly. Sample by sample through the session in time
    order (the store carried over the rests, the displacement linear across them); displacement only. Measured
    (paper_118): K2 1.09, tau0 3.5 s, x_d 0.75 of the largest bend: displacement RMS -74 % (residual 105 %, 6100x
    its noise); the 1 V steps peak at 1.68 mm 2.6 s after their edges (8.82 mm clean), 0.37 mm by the plateaus' ends
    (the store's lag grown to 9.6 s there), -1.73 mm 2 s after the falls (+6.64 mm clean); the 0.5 V sines' gain
    0.907 at 0.1 Hz with 27 deg of lead, 0.998 at 1.4 Hz."""
    k2, tau0 = s.rng.uniform(0.8, 1.2), lu(s.rng, 3.0, 10.0)
    xd, m = s.rng.uniform(0.3, 0.8) * _largest(s), s.rng.uniform(1.5, 2.5)
    x, d_end = 0.0, 0.0
    for r, gap in _gaps(s, 1.0):
        d = r.cols["disp_m"]
        for dt, u in gap:
            x += -math.expm1(-dt / (tau0 * (1 + (abs(x) / xd) ** m))) * (d_end + u * (float(d[0]) - d_end) - x)
        dt, out = 1.0 / r.fs, np.empty(d.size)
        for k, dk in enumerate(d.tolist()):
            x += -math.expm1(-dt / (tau0 * (1 + (abs(x) / xd) ** m))) * (dk - x)
            out[k] = x
        d_end = float(d[-1])
        r.cols["disp_m"] = d - k2 * out


def br_pore_bubbles(s: Session) -> None:
    """Electrolysis gas lodged in the pores the back-flow runs through: while the drive is above v_g (0.8-0.95 V: the 1
    V steps and the crests of the 1 V harmonics) the charge passed makes gas, which nucleates in the membrane's
    water channels and dissolves back over tau_g 300-1200 s (log); the bubbles block channels (the Jamin effect of
    bubbles in capillaries), so the back-flow's lag grows to tau0 (1 + J g) and its share falls to K2 (1 - c g), g
    the gas over the session's most (J 1-3, c 0.1-0.3; tau0 3-10 s, log; K2 0.8-1.2). The records after each 1 V
    step and harmonic give back less and more slowly, recovering over the slow sines. Through
    inject_fresh10._lag_varying; displacement only. Measured (p29_120): K2 0.82, tau0 5.5 s, the gas above 0.91 V,
    tau_g 560 s, J 2.05, c 0.11: displacement RMS -55 % (residual 67 %, 3600x its noise); the 1 V steps held at
    3.30, 3.49, 3.49, 3.59 mm at their plateaus' ends block by block (8.26 mm clean: the gas growing through each
    step slows its give-back), +1.2 to +1.45 mm 2 s after the falls (+6.20 mm clean); the 0.5 V sines after them at
    0.1 Hz only -0.9 % with 4.5 deg of lead (the back-flow slowed, tau about 17 s), the 1 V harmonics' -1.4 %."""
    k2, tau0, vg = s.rng.uniform(0.8, 1.2), lu(s.rng, 3.0, 10.0), s.rng.uniform(0.8, 0.95)
    tau_g, jam, c = lu(s.rng, 300.0, 1200.0), s.rng.uniform(1.0, 3.0), s.rng.uniform(0.1, 0.3)
    tg, dose = _grid_of(s, "i_A", lambda i, v: np.abs(i) * (np.abs(v) > vg), lead=0.0)
    a = math.exp(-1.0 / tau_g)
    g, _ = signal.lfilter([1.0], [1.0, -a], dose, zi=[0.0])
    g = g / max(float(np.max(g)), 1e-30)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        x = np.interp(t, tg, g)
        return k2 * (1 - c * x), tau0 * (1 + jam * x)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_gas_cell(s: Session) -> None:
    """The strip's own electrolysis gases discharging as a hydrogen-oxygen cell: the drive splits water (i_1
    sinh(v/2v_t)/sinh(1/2v_t), i_1 0.05-0.2 mA at 1 V, log; v_t 0.08-0.14 V), its hydrogen and oxygen stay on
    the faces (bubbles, and dissolved in the pores) as a charge Q of gas, and the strip is then a fuel cell of EMF E
    = E_c tanh(Q/Q_s) (E_c 0.6-0.9 V, the mixed potentials of the Pt/H2 and Pt/O2 couples; Q_s 10-40 s of i_1):
    whenever the drive is below that EMF (at rest after a 1 V step, on the way down of each sine) the cell
    discharges through the amplifier, G (E - v) with G E_c 0.2-0.6 of i_1, opposite to the current that made the
    gas, and its gas also escapes over tau_g 20-120 s (log). A current that flows back after every large drive, in
    the sense opposite to it. Sample by sample through the session in time order (the gas carried over the rests,
    discharging there); the analyser at 0 V sees an equilibrated strip (spectra untouched): the current only.
    Measured (s001_119): 0.097 mA at 1 V, v_t 0.11 V, E_c 0.85 V, Q_s 23 s of i_1, G E_c 0.29 i_1, tau_g 30 s:
    current residual 1.6 % of its RMS (4.3x its noise); +0.097 mA through each held 1 V (0.54-0.64 mA clean), then
    -0.019 mA 1 s after the falls, -0.016 mA at 5 s, -0.009 mA at 20 s; the 1 V harmonics' current +1.4 to +1.5 %
    with 0.5-0.6 deg of lag, the 0.5 V sines' +0.5 %."""
    i1, vt = lu(s.rng, 5e-5, 2e-4), s.rng.uniform(0.08, 0.14)
    ec, qs, g_d = s.rng.uniform(0.6, 0.9), i1 * s.rng.uniform(10.0, 40.0), s.rng.uniform(0.2, 0.6) * i1
    tau_g = lu(s.rng, 20.0, 120.0)
    g_d = g_d / ec
    scale = i1 / math.sinh(1 / (2 * vt))

    def discharge(q: float, v: float) -> float:
        e = ec * math.tanh(q / qs)
        return g_d * (max(e - v, 0.0) if q > 0 else min(e - v, 0.0))

    def step(q: float, v: float, dt: float) -> float:
        return q + (scale * math.sinh(v / (2 * vt)) - discharge(q, v) - q / tau_g) * dt

    def rest(q: float, sec: float) -> float:
        n = max(int(math.ceil(sec / 0.5)), 1)
        for _ in range(n):
            q = step(q, 0.0, sec / n)
        return q

    gas = _walk(s, step, "v_V", 0.0, rest)
    for r in s.series():
        v, q = r.cols["v_V"], gas[id(r)]
        e = ec * np.tanh(q / qs)
        back = g_d * np.where(q > 0, np.clip(e - v, 0, None), np.clip(e - v, None, 0))
        r.cols["i_A"] = r.cols["i_A"] + scale * np.sinh(v / (2 * vt)) - back


def far_protection_diodes(s: Session) -> None:
    """Protection across the strip's terminals: two antiparallel strings of two silicon signal diodes (1N4148-type,
    ideality n 1.7-2.0) fitted in the drive box after the current sense, to keep the strip below the voltage at
    which it electrolyses: they conduct I_s (exp(v/(2 n V_T)) - 1) on either polarity, 30-150 uA at 1 V (log) when
    the box is cold and next to nothing at 0.5 V; the box warms through the session (5-15 K, 1 - exp(-t/tau), tau
    0.3-1 session, from its switch-on 0-600 s before the first record) and each diode's drop falls 2 mV/K, so the
    diodes' current at 1 V grows by exp(0.002 dT/(n V_T)). Odd, exponential, no bending, growing with time; the
    analyser's 10 mV sees nothing (spectra untouched): the current only. Measured (s001_119): n 1.96, 40 uA at 1 V
    cold, the box warming 13 K (tau 0.66 session): current residual 0.79 % of its RMS (2.1x its noise); +0.041,
    +0.049, +0.054, +0.058 mA on the 1 V steps' plateaus block by block (0.54-0.64 mA clean), nothing at rest; the 1
    V harmonics' current +0.3 to +0.5 %, the 0.5 V sines' +0.01 %."""
    n, i1 = s.rng.uniform(1.7, 2.0), lu(s.rng, 3e-5, 1.5e-4)
    vt = 0.02569  # kT/q at 25 C
    a = 2 * n * vt
    i_s = i1 / math.expm1(1 / a)
    dtk, tau, lead = s.rng.uniform(5.0, 15.0), s.rng.uniform(0.3, 1.0) * (s.t1 - s.t0), s.rng.uniform(0.0, 600.0)
    for r in s.series():
        v = r.cols["v_V"]
        warm = dtk * -np.expm1(-(r.cols["t_s"] - s.t0 + lead) / tau)
        r.cols["i_A"] = r.cols["i_A"] + np.sign(v) * i_s * np.exp(0.002 * warm / (n * vt)) * np.expm1(np.abs(v) / a)


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_meniscus_pinning(s: Session) -> None:
    """The clamp held above the bath (to keep its contacts dry), the strip entering the water at x_w 0.3-0.5 L: the
    bath's surface meets both faces along a contact line whose contact angle swings between its receding and
    advancing values before the line moves (contact-angle hysteresis, 0.15-0.35 in cos theta on the plated surface).
    The meniscus is a spring (its deformation before the line depins 0.1-0.4 mm, log) in series with a slider at 2 b
    gamma dcos: the strip's deflection at the water line, d (x_w/L)^2 on the uniform bend, drags the meniscus until
    it slips, and the force F acts back on the strip there (the tip moving by F x_w^2 (3L - x_w)/(6 EI), the water
    line by F x_w^3/(3 EI): EI from the preset's modulus). Small sines stay pinned (a stiffer strip), larger ones
    open loops, a remanence after each large step. Quasi-static, sample by sample through the session in time order
    (the line pinned over the rests); displacement only. Measured (paper_118): the water line at 0.48 L, dcos 0.18
    (F_p 0.11 mN, 0.25 mm at the tip), the meniscus slipping after 0.32 mm (1.8 mm of tip travel): displacement RMS
    -1.0 % (residual 5.2 %, 300x its noise); the 0.5 V sines' gain 0.864 at every frequency (pinned: a stiffer
    strip), the 1 V harmonics' 0.873 with 1.1 deg of lag (slipping at their crests), the 1 V steps' peaks -0.25 mm
    (-2.8 %) and +0.25 mm left at their records' ends; the small records after them offset by where the meniscus was
    left (the 20 Hz records by 0.12 mm RMS)."""
    EI, b, L = _eibeam(s)
    xw, fp = s.rng.uniform(0.3, 0.5) * L, 2 * b * GAMMA_WATER * s.rng.uniform(0.15, 0.35)
    km = fp / lu(s.rng, 1e-4, 4e-4)
    cww, ctw, share = xw**3 / (3 * EI), xw**2 * (3 * L - xw) / (6 * EI), (xw / L) ** 2
    z = 0.0
    for r in _chrono(s):
        d = r.cols["disp_m"]
        out = np.empty(d.size)
        for k, dk in enumerate(d.tolist()):
            u = dk * share
            f = km * (u - z) / (1 + km * cww)
            if f > fp:
                f, z = fp, u - cww * fp - fp / km
            elif f < -fp:
                f, z = -fp, u + cww * fp + fp / km
            out[k] = dk - ctw * f
        r.cols["disp_m"] = out


def hy_stage_backlash(s: Session) -> None:
    """A high-resolution laser head with a short range on a motorised stage that the lab's script drives to keep the
    spot in range: whenever the head's reading leaves a band of +-B (0.12-0.25 of the session's largest bend) the
    script moves the stage by the reading, and the logged displacement is the head's reading plus the stage's
    position counted from the motor's steps. The lead screw has a backlash b (15-60 um, log): after each reversal of
    the motor the stage lags its count by b, so the logged value is off by +-b/2 by the direction of the last move,
    zeroed at the session's start. A relay-like loop of height b on every record large enough to move the stage,
    nothing on the small ones. Sample by sample through the session in time order (the stage held over the rests);
    displacement only. Measured (s001_119): a band of +-0.93 mm (0.20 of the largest bend), 26 um of backlash:
    displacement residual 1.3 % of its RMS (43x its noise); the 1 V steps' rise as it was, -26 um from the first
    re-centring of each fall on, carried through the small records that follow (the 0.5 V sines offset by 26 um,
    their swing unchanged), the 1 V harmonics' swing +1.3 to +1.6 %."""
    band, bl = s.rng.uniform(0.12, 0.25) * _largest(s), lu(s.rng, 1.5e-5, 6e-5)
    e0 = _sign(s) * bl / 2
    xm, xs = 0.0, -e0
    for r in _chrono(s):
        d = r.cols["disp_m"]
        out = np.empty(d.size)
        for k, dk in enumerate(d.tolist()):
            rd = dk - xs
            if abs(rd) > band:
                xm += rd
                xs = min(max(xs, xm - bl / 2), xm + bl / 2)
            out[k] = dk - xs + xm - e0
        r.cols["disp_m"] = out


# ------------------------------------------------------------------------------------------------ time delay


def td_serial_polling(s: Session) -> None:
    """The laser's reading polled over a serial line by the logging script (9600, 19200 or 38400 baud, drawn): it sends
    a three-character query, the head's interface latches its latest reading 0.5-2 ms later (log) and answers with
    it in millimetres, four decimals, no padding ("-1.2345" CR LF: 8 to 10 characters, a sign only when negative,
    two digits from 10 mm), and the script stamps the reading when the answer's last character has arrived, sleeps
    1-5 ms (log) and polls again; the stamped readings are interpolated linearly onto the DAQ's rows. A delay of the
    answer's transmission (8-10 characters of 10 bits: 2-10 ms), a little longer on the negative side, and a poll
    every 5-20 ms. Each record with the tip held at its first value before it; displacement only. Measured
    (p29_120): 9600 baud, a latch 1.1 ms after the query, 3.2 ms of sleep (a poll every 17 ms): displacement
    residual 0.20 % of its RMS (11x its noise); a lag of 8.3-8.9 ms on every sine, the 4.4 Hz sines' gain 0.983, the
    20 Hz ones' 0.70 at -62 deg (residuals 48 %); the steps' peaks -0.02 %."""
    baud = float(s.rng.choice([9600.0, 19200.0, 38400.0]))
    tc, lat, pause = 10.0 / baud, lu(s.rng, 5e-4, 2e-3), lu(s.rng, 1e-3, 5e-3)
    query = 3 * tc

    def chars(y: float) -> int:
        return 8 + (y < 0) + (abs(y) >= 0.01)

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        t = r.cols["t_s"]
        latch_at = lambda u: float(np.interp(u, t, d))  # noqa: E731  (held at its ends)
        tk = float(t[0]) - s.rng.uniform(0.0, 0.02)
        stamps, vals = [], []
        while True:
            y = latch_at(tk + lat)
            st = tk + lat + chars(y) * tc
            stamps.append(st)
            vals.append(y)
            if st > t[-1]:
                break
            tk = st + pause + query
        return np.interp(t, np.array(stamps), np.array(vals))

    map_disp(s, read)


def td_turbid_averaging(s: Session) -> None:
    """A laser looking into the bath, its controller's averaging on "auto": it averages the last N of its samples (cycle
    T 0.2-1 ms, log), choosing N in powers of two so that N times the received light stays above its noise target,
    N0 (1, 2 or 4) on the clear bath at the start. The bath clouds through the session (fine particles shed by the
    tubing, micro-bubbles coming out of warming water), its transmission over the beam's path falling as exp(-a), a
    growing as 1 - exp(-t/tau) (tau 0.3-1 session) to 1.2-2.5 by the end: N doubles step by step, and the reading
    (the moving mean over N T, stamped at its end) lags by N T/2, from 0.1-2 ms at the start to 4-16 times that by
    the end, in steps. Each record with the tip held at its first value before it; displacement only.
    Measured (paper_118): a 0.55 ms cycle, N0 4, the bath's loss reaching 1.84: N 8, 16, 32, 32 over the four
    blocks, a lag of 2.25, 4.5, 8.9, 8.9 ms on the sines, the 20 Hz ones at -16, -32, -64, -64 deg (gain 0.98 to
    0.80); displacement residual 0.16 % of its RMS (9.0x its noise)."""
    cyc, n0 = lu(s.rng, 2e-4, 1e-3), int(s.rng.choice([1, 2, 4]))
    a_end, tau = s.rng.uniform(1.2, 2.5), s.rng.uniform(0.3, 1.0) * (s.t1 - s.t0)
    norm = -math.expm1(-(s.t1 - s.t0) / tau)

    def window(t: np.ndarray) -> np.ndarray:
        a = a_end * -np.expm1(-(t - s.t0) / tau) / norm
        return cyc * n0 * 2.0 ** np.ceil(a / math.log(2) - 1e-9)

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        t = r.cols["t_s"]
        area, w = _held_area(t, d), window(t)
        return (area(t) - area(t - w)) / w

    map_disp(s, read)


# ------------------------------------------------------------------------------------------------ sensor offset


def so_record_autoaim(s: Session) -> None:
    """The lab's script re-aims the laser before each record: it steps the head along the strip in steps of D (0.5-1.5
    mm) until the reflection is lost at the tip's end, then backs off by a margin m (1.5-4 mm) from the last
    position with a reading: each record's spot sits at L - m - u_r, u_r the search's miss (uniform in [0, D], drawn
    record by record). The strip read at each record's own station through the beam's transfer functions
    (inject_fresh10._station); displacement only. Measured (paper_118): steps of 1.07 mm, a margin of 2.23 mm: the
    stations 0.890-0.925 L record by record; displacement RMS -20 % (residual 20 %, 1100x its noise); the 1 V steps'
    peaks -17.9 to -20.5 %, the 0.1 Hz sines' gain 0.83-0.85, the 9.4 Hz ones' 0.92 with -18 to -19 deg, the 20 Hz
    ones' 0.52-0.55."""
    L = float(s.specimen["length_m"])
    step, margin = s.rng.uniform(0.5e-3, 1.5e-3), s.rng.uniform(1.5e-3, 4e-3)
    at = {id(r): (L - margin - s.rng.uniform(0.0, step)) / L for r in _chrono(s)}
    _station(s, lambda r: np.full(r.cols["t_s"].size, at[id(r)]), min(at.values()))


def so_push_pull_heads(s: Session) -> None:
    """Two laser heads facing the strip's two faces (a push-pull pair, to cancel the stand's vibration and the bath's
    refraction drift), the lab taking half their difference as the tip's displacement; mounted by eye, the heads'
    spots are not opposite each other: one at x_1 0.95-1 L, the other delta 0.08-0.2 L further inboard. The reading
    is the mean of the strip's deflections at the two stations, through the beam's own transfer functions
    (displacement_tf with sensor_x over the tip's, with the session's history, inject_fresh2._through); displacement
    only. Measured (p29_120): the spots at 0.979 L and 0.877 L: displacement RMS -13.5 % (residual 13.5 %, 730x its
    noise); the steps' peaks -13.5 %, the 0.1 Hz sines' gain 0.868 (the mean of the two stations' static bends
    0.864), 0.920 at 4.4 Hz, 0.955 at 9.4 Hz with -13.7 deg, 0.667 at 20 Hz."""
    from labrig.physics import transfer

    x1 = s.rng.uniform(0.95, 1.0)
    x2 = x1 - s.rng.uniform(0.08, 0.2)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        s1, s2 = (sp.with_(sensor_x=x * sp.geometry.length) for x in (x1, x2))

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                both = transfer.displacement_tf(z, s1) + transfer.displacement_tf(z, s2)
                q = 0.5 * both / transfer.displacement_tf(z, sp)
            return np.where(np.isfinite(q), q, 0.5 * (x1**2 + x2**2))

        return h

    out = _through(s, H, 10.0)
    map_disp(s, lambda r, d: out[id(r)])


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_ptfe_transition(s: Session) -> None:
    """PTFE pads under a held jaw gap in a bath filled from a cold tap (10-15 C, 0-600 s before the first record)
    warming towards the room (22-26 C), so that it passes 19 C 10-45 % into the session: PTFE's crystal transition
    near 19 C (width 0.3-0.8 K) swells it by about 1 % in volume, beside its ordinary expansion, and the pads follow
    the water with a lag of 60-200 s (log). Under the fixed gap (a frame of a few N/um against a few um of swelling)
    the force rises by the same amount at every setting, b_low (p_min/p) at the lightest (b_low 10-25 %, 60-85 % of
    it in the transition), on top of the pads' cold flow (1 - c ln(1 + u/tau_p), c 0.3-1 %, tau_p 20-100 s, log, u
    from the setting 20-60 s before the block's first record). A force jump in the block the transition falls in,
    nearly flat ones before and after. Through the preset's clamp law (inject_fresh4._clamp_law). Measured
    (paper_118): the tap at 10.7 C, the room 23.5 C, 19 C passed 1950 s into the session (in the 1837 kPa block),
    b_low 0.20 (63 % of it in the transition), c 0.74 %: the load cell from 0.990 to 1.010 of its setting through
    the 1837 kPa block (+0.6 N), falling 1-2 % in the others (cold flow); the top block's sines near f1 +9 % (at 4.4
    Hz: its force -2 %); displacement residual 0.031 % of its RMS (1.8x its noise), current 0.12 % (0.09x)."""
    tf, troom = s.rng.uniform(10.0, 15.0), s.rng.uniform(22.0, 26.0)
    t_fill, ux = s.t0 - s.rng.uniform(0.0, 600.0), s.rng.uniform(0.1, 0.45)
    tau = (s.t0 + ux * (s.t1 - s.t0) - t_fill) / math.log((troom - tf) / (troom - 19.0))
    width, lag = s.rng.uniform(0.3, 0.8), lu(s.rng, 60.0, 200.0)
    b_low, share = s.rng.uniform(0.1, 0.25), s.rng.uniform(0.6, 0.85)
    c, tau_p, lead = s.rng.uniform(0.003, 0.01), lu(s.rng, 20.0, 100.0), s.rng.uniform(20.0, 60.0)
    tg = np.arange(t_fill, s.t1 + 1.0, 1.0)
    pad = _lagged(tg, troom - (troom - tf) * np.exp(-(tg - t_fill) / tau), lag)
    swell = share * special.expit((pad - 19.0) / width) + (1 - share) * (pad - tf) / (troom - tf)
    p_min = min(s.pressures())

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        u = np.clip(t - (t_set - lead), 0, None)
        rise = b_low * (p_min / p) * (np.interp(t, tg, swell) - np.interp(t_set - lead, tg, swell))
        return (1 + rise) * (1 - c * np.log1p(u / tau_p))

    _clamp_law(s, rel)


def cr_servo_zero_drift(s: Session) -> None:
    """A motorised clamp whose servo holds its load cell's reading at the setting all through each block, the cell's
    zero drifting as the cell warms beside the motor (its bridge's zero coefficient; the cell tared at its switch-on
    0-300 s before the first record, warming with tau 600-2000 s, log): the reading is the true force plus the zero
    z, so the servo holds the true force at F_set - z(t), z reaching 0.5-2 N by the session's end (a strain-gauge
    cell's zero coefficient of 0.05-0.1 % of its 98 N range per 10 K, the cell 10-20 K warmer; either sign, drawn).
    The logged force_N shows the setting unchanged; the strip follows the true force through the preset's clamp law
    (each record the specimen clamped at its mean true pressure, inject_fresh4._ratio_both): a drift that is the
    larger share of the light settings'. Displacement and current only. Measured (p29_120): the zero -0.65 N by the
    end (tau 990 s: the true force rising, 1.0 % of the top setting), the load cell as set: displacement residual
    0.015 % of its RMS (0.79x its noise), current 0.12 % (0.09x); the top block's sines near f1 -4.7 % at 4.4 Hz,
    +1.7 % at 3 Hz, the 1837 kPa block's +0.9 % at 4.4 Hz."""
    z_end, tau, lead = _sign(s) * s.rng.uniform(0.5, 2.0), lu(s.rng, 600.0, 2000.0), s.rng.uniform(0.0, 300.0)
    area = float(s.specimen["clamp_area_m2"])
    norm = -math.expm1(-(s.t1 - s.t0 + lead) / tau)
    zero = lambda t: z_end * -np.expm1(-(t - s.t0 + lead) / tau) / norm  # noqa: E731
    pre = _preset(s)
    mean = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        mean[id(r)] = p * float(np.mean(1 - zero(r.cols["t_s"]) / (p * 1e3 * area)))
    _ratio_both(s, lambda r: pre.specimen(mean[id(r)]))


# ------------------------------------------------------------------------------------------------ dehydration


def dh_amplifier_fan(s: Session) -> None:
    """A strip in air beside the drive amplifier, whose heatsink fan runs on a thermostat: the heatsink follows the
    amplifier's dissipation (its 12 V rails times the strip's current) through a lag of 60-300 s (log), the fan
    starts above 0.5-0.8 of the session's hottest and stops 0.1-0.3 below that, and while it runs it blows the
    heatsink's air, 3-8 K warmer than the room, over the strip: the strip's surface sees the room's humidity (35-55
    %) times exp(-0.06 dT), and its water follows the isotherm (inject_fresh10._lambda) through the sorption lag,
    100-400 s (log) while drying, 1.5-3x slower re-wetting. Drying in episodes after the heavy records (the fast
    sines, the steps), partly made up between them. The gain as the water, the conductance as its 1.5-2.5th power
    (inject_fresh9._dry_by). Measured (s001_119): a 215 s heatsink lag, the fan on above 0.68 and off below 0.50 of
    the hottest, its air 5.3 K warmer, the room at 43 %: the fan ran from 4-5 min into each block (after its step
    and harmonic) to the block's end, the water down 11.7 % by each block's end and back to -4.5 to -5 % by the next
    one's start; displacement RMS -3.3 % (residual 3.8 %, 128x its noise), current -15 % (44x); the 1 V steps' peaks
    0, -4.1, -4.6, -4.5 % block by block, their plateaus' current 0 to -7.8 %, the 20 Hz sines' -12 % in every
    block, the later spectra's |Z| +8.5 to +9.4 %."""
    tau_h, q_on, hys = lu(s.rng, 60.0, 300.0), s.rng.uniform(0.5, 0.8), s.rng.uniform(0.1, 0.3)
    dtk, a_room = s.rng.uniform(3.0, 8.0), s.rng.uniform(0.35, 0.55)
    tau_d, slow, gc = lu(s.rng, 100.0, 400.0), s.rng.uniform(1.5, 3.0), s.rng.uniform(1.5, 2.5)
    tg, load = _grid_of(s, "i_A")
    heat = _lagged(tg, load, tau_h)
    heat = heat / max(float(np.max(heat)), 1e-30)
    fan, on = np.zeros(tg.size), False
    for k, hk in enumerate(heat.tolist()):
        on = hk > q_on or (on and hk > q_on - hys)
        fan[k] = on
    lam0 = float(_lambda(np.array([a_room]))[0])
    rel = _lagged(tg, _lambda(a_room * np.exp(-0.06 * dtk * fan)), tau_d, tau_d * slow) / lam0
    _dry_by(s, lambda t: 1 - np.interp(t, tg, rel), lambda t: 1 - np.interp(t, tg, rel) ** gc)


def dh_pad_supply(s: Session) -> None:
    """A strip in air whose root is held between felt pads dipping into a water reservoir (to keep it from drying): the
    pads wick water to the root and the strip loses it by evaporation from its free part, so its water sits where
    supply and loss balance. Squeezed harder at each re-clamping (20-60 s before the block's first record), the
    felt's pores close and the supply falls: the strip's equilibrium water drops by l_top 10-25 % at the top
    setting, as ((p - p_first)/(p_top - p_first))^m (m 1-2), and it moves there with tau 300-900 s (log). A drying
    that steps down with each tighter setting and settles within the block. The gain as the water, the conductance
    as its 1.5-2.5th power (inject_fresh9._dry_by). Measured (s001_119): l_top 0.19, m 1.18, tau 500 s: displacement
    RMS -4.5 % (residual 6.7 %, 220x its noise), current -11 % (42x); the 1 V steps' peaks 0, -0.6, -5.5, -12.0 %
    block by block, their plateaus' current 0, -1.0, -9.4, -19.9 %, the 20 Hz sines' 0, -4.4, -10.7, -17.7 %; the
    spectra's |Z| 0, +0.5, +9.6, +24 %."""
    l_top, m, tau = s.rng.uniform(0.1, 0.25), s.rng.uniform(1.0, 2.0), lu(s.rng, 300.0, 900.0)
    lead, gc = s.rng.uniform(20.0, 60.0), s.rng.uniform(1.5, 2.5)
    spans = sorted((a, p) for p, (a, _) in _blocks(s).items())
    p_first, p_top = spans[0][1], max(p for _, p in spans)
    tg = _session_grid(s, 1.0, 0.0)
    press = _block_pressure(s)(tg + lead)
    target = 1 - l_top * np.clip((press - p_first) / max(p_top - p_first, 1e-9), 0, 1) ** m
    water = _lagged(tg, target, tau)
    _dry_by(s, lambda t: 1 - np.interp(t, tg, water), lambda t: 1 - np.interp(t, tg, water) ** gc)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_epoxy_joint(s: Session) -> None:
    """The drive lead joined to one electrode near the root with conductive (silver) epoxy, the joint cracked: bending
    the strip one way (drawn) opens the crack under the joint and shrinks its contact, whose constriction resistance
    goes as 1/(contact radius), R_j0/(1 - e+/e_o) (e+ the bend that way over the displacement scale, e_o 1.5-3,
    capped at 0.9 of the opening), R_j0 0.05-0.2 of the strip's series resistance; the other way the joint is
    pressed shut. Gains fall by 0.02-0.06 (displacement) and 0.05-0.15 (current) per unit of dR/R
    (inject_fresh3._resist): one-sided, steep near the opening (the 1 V steps), little on the small sines. Measured
    (s001_119): the joint opening for positive bends, R_j0 0.20 of the series resistance, e_o 2.7 scales (2.9 mm):
    displacement RMS -5.5 % (residual 5.9 %, 200x its noise), current residual 5.1 % (14x); the 1 V steps' peaks
    -6.7 %, their plateaus' current -24 %, the 1 V harmonics' -1.3 % (current -1.7 %), the 0.5 V sines' -0.08 %."""
    sg, rj, eo = _sign(s), s.rng.uniform(0.05, 0.2), s.rng.uniform(1.5, 3.0)
    _resist(s, lambda r, e: rj * (1 / (1 - np.clip(sg * e / eo, 0, 0.9)) - 1), (0.02, 0.06), (0.05, 0.15))


def sr_poisson_prestrain(s: Session) -> None:
    """The pads squeeze the strip's root and, by Poisson's effect, spread it lengthwise out of the jaws: the plated
    films just beyond the jaw's edge are stretched by a pre-strain that grows with the clamp pressure, pi(p) =
    pi_top c (p/p_top)^n (pi_top 0.5-0.9, n 0.7-1.2), while their cracks stay shut below a closure c (0.3-0.6 of the
    displacement scale): each face's resistance rises as (e + pi(p) - c)+ for the face in tension, so the crack
    gauge's dead zone shrinks block by block with the tightening. Gains fall by 0.01-0.03 (displacement) and
    0.03-0.08 (current) per unit (inject_fresh3._resist). Measured (p29_120): closure 0.49 of the scale, the
    pre-strain reaching 0.63 of it at 4287 kPa (n 1.08): displacement RMS -6.0 % (residual 6.3 %, 340x its noise),
    current residual 2.1 % (1.6x); the 1 V steps' peaks -8.4, -8.6, -8.8, -9.0 % block by block, their plateaus'
    current -11.7 to -12.6 %, the 1 V harmonics' -2.7 to -3.3 %, the 0.5 V sines' at 0.1 Hz -0.03, -0.14, -0.32,
    -0.51 %."""
    c, pi_top, n = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.5, 0.9), s.rng.uniform(0.7, 1.2)
    p_top = max(s.pressures())

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        pre = c * pi_top * (float(r.entry["pressure_kPa"]) / p_top) ** n
        return np.clip(e + pre - c, 0, None) + np.clip(-e + pre - c, 0, None)

    _resist(s, shape, (0.01, 0.03), (0.03, 0.08))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_closure_stiffening(s: Session) -> None:
    """One face's plated film is cracked through (a mud-crack mosaic) and carries nothing in tension, but compressed it
    closes its cracks and the platelets butt together: beyond the bend d_c (0.2-0.5 of the session's largest bend
    towards the side that compresses it, drawn) the closed share of its cracks grows linearly over w d_c (w 0.3-1,
    the spread of the cracks' gaps) and the film adds a share k 0.15-0.5 to the bending stiffness: the moment
    balance y + k F(y) = d (F the closed share integrated from d_c) maps the linear reading d to the bend y. Small
    bends and the other side linear, large bends towards that side compressed. Quasi-static; displacement only.
    Measured (p29_120): the film closing for positive bends from 2.7 mm (0.33 of the largest), k 0.23, w 0.89:
    displacement RMS -5.9 % (residual 6.8 %, 370x its noise); the 1 V steps' peaks -10.0 %, their bend 2 s after the
    falls -7.0 %, the 1 V harmonics' crests -2.1 to -2.3 % (their troughs as they were), the 0.5 V sines unchanged."""
    sg = _sign(s)
    big = max(max(float(np.max(sg * r.cols["disp_m"])) for r in s.series()), 1e-9)
    dc, k, w = s.rng.uniform(0.2, 0.5) * big, s.rng.uniform(0.15, 0.5), s.rng.uniform(0.3, 1.0)
    y = np.linspace(-1.5, 1.5, 6001) * max(big, _largest(s))
    z = sg * y
    closed = np.where(z <= dc, 0.0,
                      np.where(z <= dc * (1 + w), (z - dc) ** 2 / (2 * w * dc), w * dc / 2 + z - dc * (1 + w)))
    m = y + sg * k * closed
    map_disp(s, lambda r, d: np.interp(d, m, y))


def ld_through_window(s: Session) -> None:
    """A triangulation head outside the cuvette, reading the strip through its flat window on the side the strip bends
    towards under a positive drive (the beam square to the window, the receiving lens a baseline B 20-35 mm beside
    the beam, the window Z_g 10-25 mm from the head, the strip z_0, 1.3-2 times its largest bend, behind the window
    in water), its linearisation made for air: the receiving ray refracts at the window (Snell, n 1.333), so the
    head's air-calibrated distance B/tan(alpha) follows the water path's depth nonlinearly; the lab calibrated the
    scale at rest (a small known move). The reading (Z_air(z_0) - Z_air(z_0 - y))/Z_air'(z_0): compressed the more,
    the closer the strip comes to the window (the steps), slightly stretched the other way. Displacement only.
    Measured (paper_118): B 24.6 mm, the window 23.9 mm from the head, 16.5 mm of water at rest: displacement RMS
    -1.6 % (residual 1.7 %, 98x its noise); the 1 V steps' peaks -2.4 %, the 1 V harmonics' crests -1.05 % and
    troughs +0.05 %, the 0.5 V sines -0.03 %."""
    B, zg = s.rng.uniform(20e-3, 35e-3), s.rng.uniform(10e-3, 25e-3)
    big = _largest(s)
    z0, sg, nw = s.rng.uniform(1.3, 2.0) * big, 1.0, 1.333

    def z_air(zw: np.ndarray) -> np.ndarray:
        lo, hi = np.zeros(zw.size), np.full(zw.size, 0.5 * np.pi - 1e-6)
        for _ in range(60):  # the ray's angle in air: zg tan(a) + zw tan(a_w) = B, sin(a) = n sin(a_w)
            mid = 0.5 * (lo + hi)
            aw = np.arcsin(np.sin(mid) / nw)
            f = zg * np.tan(mid) + zw * np.tan(aw) - B
            lo, hi = np.where(f < 0, mid, lo), np.where(f < 0, hi, mid)
        return B / np.tan(0.5 * (lo + hi))

    y = np.linspace(-1.05, 1.05, 2101) * big
    za, h = z_air(z0 - sg * y), 1e-3 * big
    slope = float((z_air(np.array([z0 + h])) - z_air(np.array([z0 - h])))[0]) / (2 * h)
    read = (float(z_air(np.array([z0]))[0]) - za) / (sg * slope)
    map_disp(s, lambda r, d: np.interp(d, y, read))


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_loaded_ripple(s: Session) -> None:
    """The drive amplifier's supply is a capacitor-input rectifier whose ripple grows with the current drawn from it (dV
    = I/(2 f C)), and the amplifier's finite supply rejection passes the ripple to its output: the strip is driven
    by an extra voltage k_r (I_q + |i|) r(t), k_r 10-60 uV per mA at the output (log), I_q 1-5 mA the amplifier's
    own quiescent draw (log), |i| the strip's current over the last half line cycle, r(t) the ripple at twice the
    line (50 or 60 Hz) with its harmonics to the 5th (the rectifier's sawtooth, whose 1/k the supply rejection's
    fall with frequency offsets), phase locked to the session clock. The strip answers through its own admittance
    (labrig.physics.transfer at each record's pressure): a hum in the current that swells while the strip draws
    current (the step edges, the fast sines). The displacement's share (its transfer at 100-600 Hz, well below a
    nanometre) is left out: the current only. Measured (paper_118): 50.0 Hz, 22 uV per mA, I_q 5.0 mA: the current's
    lines at 100, 200 and 300 Hz 3.2-4.5 uA on the step records, 6.4-8.6 uA on the fast sines (their current 5-20
    mA); current residual 0.24 % of its RMS (0.18x its noise: narrow lines)."""
    from labrig.physics import transfer

    f0, kr, iq, ph = _line_f(s), lu(s.rng, 1e-5, 6e-5) / 1e-3, lu(s.rng, 1e-3, 5e-3), s.rng.uniform(0, 2 * np.pi)
    ks = np.arange(1, 6)
    for r in s.series():
        t, i = r.cols["t_s"], r.cols["i_A"]
        n = max(int(round(r.fs / (2 * f0))), 1)
        load = iq + np.convolve(np.abs(i), np.full(n, 1.0 / n), mode="full")[: i.size]
        sp = _spec(s, r)
        z = 2j * np.pi * 2 * f0 * ks
        wave = np.exp(1j * (2 * np.pi * 2 * f0 * np.outer(t, ks) + ks * ph))
        r.cols["i_A"] = i + kr * load * np.imag(wave @ transfer.admittance_tf(z, sp))


def mp_laptop_charger(s: Session) -> None:
    """The logging laptop's charger plugged in 30-70 % into the session (its battery low): a two-prong (class II)
    charger whose Y capacitors tie the laptop's ground to the mains, so from then on their leakage current (the
    line's flat-topped voltage differentiated: its 3rd, 0.03-0.08, and 5th, 0.01-0.04, weighted by their orders)
    returns through the USB DAQ's ground into the rig's earthed instruments, and the ground drop sits on both
    single-ended inputs: 1-4 um on the displacement and 3-10 uA on the current (log), 50 or 60 Hz, phase locked to
    the session clock, absent before the plug-in. Measured (p29_120): 60.0 Hz, plugged in 2460 s into the session
    (before the 3062 kPa block): from then on 1.41 um and 7.0 uA at 60 Hz, 0.21 um and 1.0 uA at 180 Hz, 0.28 um and
    1.4 uA at 300 Hz; displacement residual 0.023 % of its RMS (1.2x its noise), current 0.11 % (0.09x)."""
    f0, h3, h5 = _line_f(s), s.rng.uniform(0.03, 0.08), s.rng.uniform(0.01, 0.04)
    ad, ai, ph = lu(s.rng, 1e-6, 4e-6), lu(s.rng, 3e-6, 1e-5), s.rng.uniform(0, 2 * np.pi)
    t_on = s.t0 + s.rng.uniform(0.3, 0.7) * (s.t1 - s.t0)
    for r in s.series():
        t = r.cols["t_s"]
        hum = (t >= t_on) * _hum(t, f0, {3: 3 * h3, 5: 5 * h5}, ph)
        r.cols["disp_m"] = r.cols["disp_m"] + ad * hum
        r.cols["i_A"] = r.cols["i_A"] + ai * hum


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_ao_clock(s: Session) -> None:
    """The drive comes from an output task on a clock of its own (a USB DAQ's analogue output timed by its own
    oscillator, not the input's sample clock), started with each record: it runs 100-400 ppm (log, either sign) off
    the input's clock, so the drive the strip feels is the command played faster or slower, and the logged command
    (v_V, as programmed on the input's clock) and the strip's current and displacement drift apart through each
    record, by up to 25 ms by the end of a 61 s step. The current and the displacement at t0 + (t - t0)(1 + eps);
    v_V and the load cell untouched. Measured: (paper_118) -131 ppm: the 20 Hz sines' current and displacement -2.8
    deg against the command, the steps' falls 4 ms early, current residual 4.5 % of its RMS (3.4x its noise),
    displacement 0.043 % (2.5x); (s001_119) +234 ppm: +5.1 deg at 20 Hz, current 5.3 % (14x), displacement 0.078 %
    (2.6x)."""
    eps = _sign(s) * lu(s.rng, 1e-4, 4e-4)
    for r in s.series():
        t = r.cols["t_s"]
        tw = t[0] + (t - t[0]) * (1 + eps)
        for col in ("i_A", "disp_m"):
            r.cols[col] = np.interp(tw, t, r.cols[col])


def out_dc_block(s: Session) -> None:
    """A DC-blocking capacitor in the drive line (a supercapacitor, 0.1-0.47 F, log, fitted to keep the amplifier's
    offset from electrolysing the strip): the strip feels the drive through the divider s C_b Z/(1 + s C_b Z), Z its
    own impedance (labrig.physics.transfer at each record's pressure), so the slow part of every drive is shared
    with the capacitor, the strip's DC leak is blocked and the charge the capacitor gathers over the session swings
    the strip back at rest, while the logged command (v_V) shows none of it. The current and the displacement less
    their part 1/(1 + s C_b Z), which is slow (below 1 Hz): run over the whole session from its start (the capacitor
    uncharged) on a 20 Hz grid (each cell the signal's integral over it; over the rests between records each
    record's last value decaying with 10 s, the strip relaxing), taken back onto each record's samples. The
    analyser, wired at the strip, sees it unchanged. Measured: (paper_118) 0.227 F: the 1 V steps' peaks 7.76-7.82
    mm (8.82 clean), the current at their plateaus' ends 0.45, 0.33, 0.28, 0.25 mA block by block (0.55-0.59 clean:
    the charge gathered over the session), -0.92 to -1.05 mA 5 s after the falls (-0.86 to -0.93 clean); the 0.1 Hz
    sines -2.2 % with 1.2 deg of lead; displacement RMS -13 % (residual 16 %, 940x its noise), current residual 6.4
    % (4.8x); (p29_120) 0.194 F: the steps' peaks 7.16-7.20 mm (8.27), their plateaus' current 0.43 to 0.22 mA, the
    0.1 Hz sines -2.6 %; displacement residual 18 % (960x), current 6.9 % (5.2x)."""
    from labrig.physics import transfer

    cb = lu(s.rng, 0.1, 0.47)
    recs = _chrono(s)
    dt = 0.05
    tg = np.arange(s.t0 - 10.0, s.t1 + dt, dt)
    t = np.concatenate([r.cols["t_s"] for r in recs])
    cell = np.clip(((t - tg[0]) // dt).astype(int), 0, tg.size - 1)
    share = np.concatenate([np.full(r.cols["t_s"].size, 1.0 / (r.fs * dt)) for r in recs])
    cover = np.clip(np.bincount(cell, weights=share, minlength=tg.size), 0, 1)
    mid = tg + dt / 2
    t_end = np.array([float(r.cols["t_s"][-1]) for r in recs])
    last = np.searchsorted(t_end, mid) - 1
    since = mid - t_end[np.clip(last, 0, None)]
    for col in ("i_A", "disp_m"):
        x = np.bincount(cell, weights=share * np.concatenate([r.cols[col] for r in recs]), minlength=tg.size)
        ends = np.array([float(r.cols[col][-1]) for r in recs])
        tail = ends[np.clip(last, 0, None)] * np.exp(-np.clip(since, 0, None) / 10.0)
        x = x + (1 - cover) * np.where(last >= 0, tail, 0.0)
        removed = {}
        for p in s.pressures():
            sp = _preset(s).specimen(p)

            def g(z: np.ndarray, sp=sp) -> np.ndarray:
                with np.errstate(divide="ignore", invalid="ignore"):
                    q = 1 / (1 + z * cb / transfer.admittance_tf(z, sp))
                return np.where(np.isfinite(q), q, 1.0)

            removed[p] = inject.lti(x, 1 / dt, g)
        for r in recs:
            r.cols[col] = r.cols[col] - np.interp(r.cols["t_s"], mid, removed[float(r.entry["pressure_kPa"])])


def out_mux_ghosting(s: Session) -> None:
    """A multiplexed DAQ scanning the laser's channel just before the current's, the current amplifier's output behind a
    protection resistor and a filter capacitor the multiplexer's sampling capacitor cannot settle in the convert
    interval: the current's reading carries a share g (0.05-0.3 %, log) of the voltage left from the laser's
    channel, (1 - g) v_i + g v_d, the laser's 2 mm/V and the amplifier's 10 mA/V: the current shows a copy of the
    bend, 20-150 uA at the steps' plateaus. The current only. Measured: (s001_119) g 0.17 %: +0.038 mA on the 1 V
    steps' plateaus (0.54-0.64 mA clean), current residual 0.57 % of its RMS (1.5x its noise); (p29_120) g 0.17 %:
    +0.070 mA (0.53-0.57 mA clean), 0.88 % (0.66x)."""
    g = lu(s.rng, 5e-4, 3e-3)
    for r in s.series():
        r.cols["i_A"] = (1 - g) * r.cols["i_A"] + g * CURRENT_A_PER_V * r.cols["disp_m"] / LASER_M_PER_V


def out_swapped_leads(s: Session) -> None:
    """The strip's two drive leads end in identical plugs that the operator pulls and re-plugs at each re-clamping:
    after the first block each block's polarity is a coin toss (at least one swapped): in a swapped block the strip
    is driven with -v while the logged command is v, so its current and displacement come out with the opposite sign
    (the strip being symmetric and settled over the re-clamping's rest). The spectra (a two-terminal impedance) and
    the load cell as they were. Measured: (paper_118) the 1837, 3062 and 4287 kPa blocks swapped; (p29_120) the 1837
    and 4287 kPa blocks."""
    starts = sorted(a for a, _ in _blocks(s).values())
    flip = [False] + [bool(s.rng.random() < 0.5) for _ in starts[1:]]
    if len(starts) > 1 and not any(flip):
        flip[int(s.rng.integers(1, len(starts)))] = True
    swapped = {a for a, f in zip(starts, flip) if f}
    first = {p: a for p, (a, _) in _blocks(s).items()}
    for r in s.series():
        if first[float(r.entry["pressure_kPa"])] in swapped:
            r.cols["i_A"], r.cols["disp_m"] = -r.cols["i_A"], -r.cols["disp_m"]


FRESH16_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"anode_depletion": br_anode_depletion, "pore_bubbles": br_pore_bubbles},
    "faradaic_current": {"gas_cell": far_gas_cell, "protection_diodes": far_protection_diodes},
    "hysteresis": {"meniscus_pinning": hy_meniscus_pinning, "stage_backlash": hy_stage_backlash},
    "time_delay": {"serial_polling": td_serial_polling, "turbid_averaging": td_turbid_averaging},
    "sensor_offset": {"record_autoaim": so_record_autoaim, "push_pull_heads": so_push_pull_heads},
    "clamp_relaxation": {"ptfe_transition": cr_ptfe_transition, "servo_zero_drift": cr_servo_zero_drift},
    "dehydration": {"amplifier_fan": dh_amplifier_fan, "pad_supply": dh_pad_supply},
    "strain_resistance": {"epoxy_joint": sr_epoxy_joint, "poisson_prestrain": sr_poisson_prestrain},
    "large_deflection": {"closure_stiffening": ld_closure_stiffening, "through_window": ld_through_window},
    "mains_pickup": {"loaded_ripple": mp_loaded_ripple, "laptop_charger": mp_laptop_charger},
    "unexplained": {"ao_clock": out_ao_clock, "dc_block": out_dc_block, "mux_ghosting": out_mux_ghosting,
                    "swapped_leads": out_swapped_leads},
}
inject.register_forms(FRESH16_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def fir_rate(fs: float) -> int:
    """``fir_decimated``'s factor for a record at fs: 4 if that keeps 100 Hz or more, else 2."""
    return 4 if fs / 4 >= 100.0 else 2


def v_fir_decimated(s: Session) -> None:
    """A logger (or its export tool) that stores every time series decimated through a linear-phase anti-alias filter,
    the factor chosen per record to keep at least 100 Hz (4 where that allows, else 2: the step records at 125 Hz, the
    slow sines at 100 Hz, the 20 Hz one at 250 Hz): every column but t_s through one windowed-sinc FIR (Kaiser, beta
    8; 16-32 taps per factor, drawn for the session; its cut-off 0.40-0.45 of the new rate) whose delay is taken off
    (zero phase; each record's ends extended by their first and last values), then every q-th row from an offset drawn
    per record, stamped with its own time. The drive's edges ring a little on either side (as a delta-sigma DAQ's do),
    the spectra and the manifest as they were. ``labrig import`` takes it (t_s strictly increasing, each record at its
    own rate)."""
    half, cut = int(s.rng.integers(8, 17)), s.rng.uniform(0.4, 0.45)
    for r in s.series():
        q = fir_rate(r.fs)
        h = signal.firwin(2 * half * q + 1, 2 * cut / q, window=("kaiser", 8.0))
        pad, off = half * q, int(s.rng.integers(0, q))
        new = {}
        for k, x in r.cols.items():
            if k == "t_s":
                new[k] = x[off::q]
                continue
            y = np.convolve(np.r_[np.full(pad, x[0]), x, np.full(pad, x[-1])], h, mode="valid")
            new[k] = y[off::q]
        r.cols = new


inject.VARIANTS.update({"fir_decimated": v_fir_decimated})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_118", "s001_119", "p29_120"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 118-120
    "back_relaxation": [("anode_depletion", 118, P, "fir_decimated"), ("pore_bubbles", 120, T, "asrun")],
    "faradaic_current": [("gas_cell", 119, S, "rate07"), ("protection_diodes", 119, S, "eis_descending")],
    "hysteresis": [("meniscus_pinning", 118, P, "tared_records"), ("stage_backlash", 119, S, "settled_sines")],
    "time_delay": [("serial_polling", 120, T, "dropped_packets"), ("turbid_averaging", 118, P, "float32_time")],
    "sensor_offset": [("record_autoaim", 118, P, "shortened_shuffled"), ("push_pull_heads", 120, T, "coherent_sines")],
    "clamp_relaxation": [("ptfe_transition", 118, P, "merged_loadcell"), ("servo_zero_drift", 120, T, "asrun")],
    "dehydration": [("amplifier_fan", 119, S, "host_timed"), ("pad_supply", 119, S, "fir_decimated")],
    "strain_resistance": [("epoxy_joint", 119, S, "steps_sines"), ("poisson_prestrain", 120, T, "two_pressures")],
    "large_deflection": [("closure_stiffening", 120, T, "short_pretrigger"), ("through_window", 118, P, "resampled")],
    "mains_pickup": [("loaded_ripple", 118, P, "asrun"), ("laptop_charger", 120, T, "trigger_clock")],
    "unexplained": [("ao_clock", 118, P, "log_steps"), ("ao_clock", 119, S, "asrun"),
                    ("dc_block", 118, P, "own_clock"), ("dc_block", 120, T, "asrun"),
                    ("mux_ghosting", 119, S, "fir_decimated"), ("mux_ghosting", 120, T, "decimated3"),
                    ("swapped_leads", 118, P, "asrun"), ("swapped_leads", 120, T, "no_loadcell")],
}
CLEAN = [(118, P, "asrun"), (118, P, "fir_decimated"), (119, S, "asrun"), (119, S, "no_spectra"),
         (120, T, "asrun"), (120, T, "fir_decimated")]


def fresh16_cases(only: str | None = None) -> list[Case]:
    """The seventeenth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    118-120)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh16_cases, "inject_fresh16", "fresh16")
