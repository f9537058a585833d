"""A twenty-sixth held-out set for the diagnosis (issue 12), fresh25, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh24.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (the back-flow driven by the water's
activity along Nafion's isotherm, nitrate reduction on platinum with its current maximum, a guide plate holding the
strip's edge by electroadhesion, the laser controller's latency predictor, a scanning spot sampled by the DAQ,
Morison drag on the strip in water, a capacitance-reading probe, a Hall current sensor beside the amplifier's
transformer), some on the history, the clamp pressure or the session's events (salt poured into the bath at a
re-clamping, a burred lid slot wearing in, rubber pads softening past their largest squeeze so far, the operator's
tightening speed at each setting, the jaws' squeeze pre-stretching the plating, a welder next door at work), some on
time (a laser stream's phase-locked loop relocking at each record, an MDF shelf swelling in a rain front, an
oscillating desk fan switched on mid-session, a glycerol-water solvent drying to its glycerol, a detergent residue
wetting the cracks), one linear but neither a lag nor a spread of lags (the swelling stress that drives the back-flow
relaxing by the network's own creep: a give-back that partly comes back) and some from the lab's wiring or sensors
(the predictor, the scanning spot, the probe, the Hall sensor). Four structures outside the catalogue (truth
"unexplained": the operator breathing on a strip in air at each re-clamping, electrolysis bubbles kicking the strip as
they leave it, a water drop on the tip of a strip in air evaporating, a galvanic couple at the jaws' contact
re-made at each re-clamping); clean sessions. All on three bases of new seeds (145-147: the paper strip, the seed-001
strip on its own sweep, the paper strip 21 mm free) and on the earlier sets' protocol / data-shape variants plus one
new here: the manifest's pressure of every record written from the load cell's reading at the record's start, not the
setting (``measured_pressures``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh24 are reused (importing inject_fresh24 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh25.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh24  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _through
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law
from inject_fresh9 import _dry_by, _gaps, _session_grid
from inject_fresh10 import _lambda, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh22 import _f1, _grid_lag, _table_map
from inject_fresh23 import _settings
from inject_fresh24 import _by_pressure_start, _lag

# the paper's strip 21 mm free (earlier sets used 20, 22-29, 31-45 mm, 30 mm is the paper preset itself and the
# seed-001 strip is 20 mm; its 1 V step peaks near 4.4 mm, well inside the laser's +-20 mm): preset "paper_21", base
# "p21_147", registered in every process importing this module
inject.register_free_length("paper_21", 0.021)

inject.BASES.update({
    "paper_145": ("paper-sweep", "paper", 145),
    "s001_146": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 146),
    "p21_147": ("paper-sweep", "paper_21", 147),
})


# ------------------------------------------------------------------------------------------------ tools


def _play_by(u: np.ndarray, rad: np.ndarray, y: float) -> tuple[np.ndarray, float]:
    """A dry-friction element with a radius given per sample: y_k = clip(y_(k-1), u_k - r_k, u_k + r_k)."""
    out = np.empty(u.size)
    for k, (uk, rk) in enumerate(zip(u.tolist(), rad.tolist())):
        y = min(max(y, uk - rk), uk + rk)
        out[k] = y
    return out, y


def _mode_ratio(w0: float, z0: float, w1: float, z1: float) -> Callable[[np.ndarray], np.ndarray]:
    """A first mode moved from (w0, z0) to (w1, z1), its static gain kept."""
    def h(z: np.ndarray) -> np.ndarray:
        z = np.asarray(z, complex)
        return (z * z + 2 * z0 * w0 * z + w0 * w0) / (z * z + 2 * z1 * w1 * z + w1 * w1) * (w1 * w1) / (w0 * w0)

    return h


def _setting_of(s: Session) -> Callable[[float, float], float]:
    """Each pressure's setting time (inject_fresh23._settings; 20 s before its first sample for a pressure without a
    block of its own)."""
    t_set = _settings(s)
    return lambda p, t_first: t_set.get(p, t_first - 20.0)


# ------------------------------------------------------------------------------------------------ back relaxation


def br_creeping_network(s: Session) -> None:
    """The back-flow is driven by the swelling stress of the polymer network on the cathode side, and that stress
    relaxes by the network's own creep (a standard linear solid: a share c 0.4-0.8 of it over tau_v, 4-12 times the
    back-flow's time tau_d 1-4 s, log): the water flows back over tau_d as the swollen side pushes it, and once the push
    has crept away it is drawn to the cathode side again, so the give-back partly comes back. The opposing swelling
    K2/(1 + s tau_d) (1 - c/(1 + s tau_v)) (K2 0.6-1.0): a step's bend rises, sags to 1 - K2 and recovers to 1 - K2 (1 -
    c); its impulse response changes sign, so it is neither a lag nor a spread of lags (no completely monotone kernel).
    Through inject_fresh2._through with 150 s of the session's history; displacement only. Measured (paper_145)
    displacement RMS -51 % (residual 54 %, 3300x its noise), the 1 V steps (8.8 mm clean) sagging to 2.0 mm 5 s after
    their edge and back to 3.9 mm by the plateaus' end."""
    k2, td = s.rng.uniform(0.6, 1.0), lu(s.rng, 1.0, 4.0)
    tv, c = td * lu(s.rng, 4.0, 12.0), s.rng.uniform(0.4, 0.8)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        return lambda z: 1 - k2 / (1 + td * np.asarray(z)) * (1 - c / (1 + tv * np.asarray(z)))

    new = _through(s, H, 150.0)
    map_disp(s, lambda r, d: new[id(r)])


def _activity_drive(rh: float, q: float, n: int = 801) -> tuple[np.ndarray, np.ndarray]:
    """The back-flow's driving force against the bend g (in units of the largest), for a membrane at the water
    content of the room's humidity rh whose swollen side gains and whose other side loses q lambda0 at g = 1: the
    difference of the two sides' water activities (the inverse of Nafion's isotherm, inject_fresh10._lambda) over its
    small-signal slope, so that it is g for small g."""
    ag = np.linspace(0.0, 1.0, 4001)
    lg = _lambda(ag)
    lam0 = float(_lambda(np.array([rh]))[0])
    act = lambda lam: np.interp(lam, lg, ag)  # noqa: E731
    g = np.linspace(-2.0, 2.0, n)
    d = q * lam0
    slope = float((act(np.array([lam0 + 1e-3 * d])) - act(np.array([lam0 - 1e-3 * d])))[0]) / (2e-3 * d)
    return g, (act(lam0 + d * g) - act(lam0 - d * g)) / (2 * d * slope)


def br_isotherm_activity(s: Session) -> None:
    """A strip in air in a humid room (0.6-0.8 RH): the back-flow is driven not by the difference of water content
    across the membrane but by the difference of the water's activity, and along Nafion's isotherm (inject_fresh10's
    Zawodzinski fit) the activity follows the water content far from linearly at this humidity: the swollen side
    (gaining q 0.25-0.5 of its water at the largest bend) sits on the isotherm's steep part, the drained side on its
    flat part. The returned water x follows dx/dt = A((d - x)/D) D/tau (D the session's largest bend, tau 2-8 s, log,
    A(g) the two sides' activity difference over its small-signal slope, odd, A(g) ~ g for small g), the opposing
    swelling K2 x (K2 0.6-1.0): small bends give back at 1/tau, large ones at a rate set by the isotherm's curvature.
    Sample by sample through the session in time order (the rests sub-stepped at 0.05 s, inject_fresh9._gaps);
    displacement only. Measured (s001_146) displacement RMS -59 % (residual 63 %, 2000x its noise), the 1 V steps (4.7
    mm clean) at 1.3 mm 5 s after their edge, 1.8 mm by the plateaus' end."""
    rh, q = s.rng.uniform(0.6, 0.8), s.rng.uniform(0.25, 0.5)
    k2, tau = s.rng.uniform(0.6, 1.0), lu(s.rng, 2.0, 8.0)
    D = _largest(s) or ref_disp(s)
    g_tab, a_tab = _activity_drive(rh, q)
    g_lo, dg = float(g_tab[0]), float(g_tab[1] - g_tab[0])
    a_list, top = a_tab.tolist(), len(a_tab) - 2

    def run(d: np.ndarray, dt: float, x: float) -> tuple[np.ndarray, float]:
        out = np.empty(d.size)
        c = dt * D / tau
        for k, dk in enumerate(d.tolist()):
            f = ((dk - x) / D - g_lo) / dg
            j = min(max(int(f), 0), top)
            w = min(max(f - j, 0.0), 1.0)
            x += c * (a_list[j] + w * (a_list[j + 1] - a_list[j]))
            out[k] = x
        return out, x

    x = 0.0
    for r, rest in _gaps(s, 0.05):
        if rest:
            _, x = run(np.zeros(len(rest)), rest[0][0], x)
        y, x = run(r.cols["disp_m"], 1.0 / r.fs, x)
        r.cols["disp_m"] = r.cols["disp_m"] - k2 * y


# ------------------------------------------------------------------------------------------------ faradaic current


def far_nitrate_peak(s: Session) -> None:
    """A bath made with nitrate (tap water high in it, or a KNO3 supporting electrolyte): on whichever face is the
    cathode, nitrate is reduced on the platinum from E_n (0.15-0.3 V of drive, b 0.03-0.06 V), but the hydrogen that
    platinum adsorbs at more negative potentials blocks the sites nitrate needs, so beyond E_h (0.45-0.6 V, width
    0.04-0.08 V) the current falls again: the current maximum of nitrate reduction on Pt (0.15-0.4 mA at the peak, log),
    a region of negative slope, and only beyond it water's own exponential (0.02-0.08 mA at 1 V, log, b_w 0.08-0.12 V).
    Odd in the drive (either face the cathode, the anode's oxygen in series taken into the positions), memoryless: the
    0.5 V sines' crests draw more nitrate current than the 1 V plateaus. The current only. Measured (paper_145) current
    RMS +3.9 % (residual 5.6 %, 4.2x its noise), 0.29 mA at the 0.5 V sines' crests, 0.06 mA on the 1 V plateaus."""
    e_n, b, e_h = s.rng.uniform(0.15, 0.3), s.rng.uniform(0.03, 0.06), s.rng.uniform(0.45, 0.6)
    w_h, i_p = s.rng.uniform(0.04, 0.08), lu(s.rng, 1.5e-4, 4e-4)
    i_w, b_w = lu(s.rng, 2e-5, 8e-5), s.rng.uniform(0.08, 0.12)

    def law(a: np.ndarray) -> np.ndarray:
        k = np.exp((a - e_n) / b)
        return i_p * k / (1 + k) / (1 + np.exp((a - e_h) / w_h)) + i_w * np.expm1(a / b_w) / math.expm1(1 / b_w)

    zero = float(law(np.zeros(1))[0])
    for r in s.series():
        v = r.cols["v_V"]
        r.cols["i_A"] = r.cols["i_A"] + np.sign(v) * (law(np.abs(v)) - zero)


def far_saline_added(s: Session) -> None:
    """At one re-clamping after the first (drawn) the operator pours salt into the deionised bath (to bring it to a
    protocol's saline, or a conductivity standard by mistake), and it mixes through the cuvette over tau_m (30-120 s,
    log, from the setting). From then on chloride is oxidised at whichever face is the anode, at a lower overpotential
    than water on platinum (E_cl 0.25-0.4 V of drive, Tafel b 0.03-0.05 V) up to its diffusion limit (0.15-0.4 mA, log),
    the cathode's hydrogen in series: a sigmoid wave, odd in the drive, that is absent from the blocks before the salt
    and present in every record after it. The current only. Measured (p21_147) current RMS +1.6 % (residual 3.9 %, 2.8x
    its noise): nothing in the first two blocks, 0.17-0.25 mA on the 1 V plateaus and at the 0.5 V sines' crests after
    the salt."""
    setting = _setting_of(s)
    blocks = sorted(_by_pressure_start(s).items(), key=lambda kv: kv[1])
    k = int(s.rng.integers(1, len(blocks))) if len(blocks) > 1 else 0
    t_add = setting(*blocks[k])
    tau_m, e_cl, b = lu(s.rng, 30.0, 120.0), s.rng.uniform(0.25, 0.4), s.rng.uniform(0.03, 0.05)
    i_l = lu(s.rng, 1.5e-4, 4e-4)
    k0 = 1 / (1 + math.exp(e_cl / b))
    for r in s.series():
        t, v = r.cols["t_s"], r.cols["v_V"]
        mix = np.where(t >= t_add, -np.expm1(-np.clip(t - t_add, 0.0, None) / tau_m), 0.0)
        wave = 1 / (1 + np.exp(-(np.abs(v) - e_cl) / b)) - k0
        r.cols["i_A"] = r.cols["i_A"] + np.sign(v) * i_l * mix * wave


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_electroadhesive_guide(s: Session) -> None:
    """A strip in air kept from twisting out of the laser's spot by a guide plate along its edge (anodised aluminium,
    earthed with the rig's frame), the edge in light contact with it: the plating next to the plate is at the drive's
    potential, and across the plate's thin oxide the two are an electroadhesive pair (an electrostatic chuck's physics):
    the edge is pressed onto the plate with a force as the drive squared, and Coulomb friction on it holds the tip while
    the strip's pull stays within r = r0 + r1 v^2 of where it is (r0 0.002-0.005 of the session's largest bend, the
    contact's own; r1 0.02-0.05 of it at 1 V). A play whose radius follows the drive, not the bend: at rest the tip runs
    almost free, the 1 V records stick and slip in wide loops. Quasi-static, sample by sample through the session in
    time order (the tip held over the rests); displacement only. Measured (s001_146) displacement RMS -1.8 % (residual
    3.1 %, 98x its noise)."""
    D = _largest(s) or ref_disp(s)
    r0, r1 = s.rng.uniform(0.002, 0.005) * D, s.rng.uniform(0.02, 0.05) * D
    y = 0.0
    for r in _chrono(s):
        v = r.cols["v_V"]
        r.cols["disp_m"], y = _play_by(r.cols["disp_m"], r0 + r1 * v * v, y)


def hy_burred_lid_slot(s: Session) -> None:
    """A cuvette closed by a lid cut that morning from PTFE sheet (to keep the bath from evaporating), the strip's tip
    end passing through a slot in it: the slot's machining burrs rub the tip's faces, a dry friction that holds it while
    its pull stays within r of where it is; the burrs wear down as the tip slides over them, the radius falling with the
    path slid P (the sum of the tip's moves) as r_inf + (r0 - r_inf) exp(-P/P0) (r0 0.03-0.06 of the session's largest
    bend, r_inf 0.2-0.5 of r0, P0 0.03-0.12 of the session's whole path): wide loops in the first records, narrow ones
    late, a running-in the session's history sets. Quasi-static, sample by sample through the session in time order;
    displacement only. Measured (p21_147) displacement RMS -0.59 % (residual 4.5 %, 130x its noise)."""
    D = _largest(s) or ref_disp(s)
    r0 = s.rng.uniform(0.03, 0.06) * D
    r_inf = r0 * s.rng.uniform(0.2, 0.5)
    path = sum(float(np.sum(np.abs(np.diff(r.cols["disp_m"])))) for r in s.series())
    P0 = s.rng.uniform(0.03, 0.12) * path
    y, P = 0.0, 0.0
    for r in _chrono(s):
        u = r.cols["disp_m"]
        out = np.empty(u.size)
        for k, uk in enumerate(u.tolist()):
            rad = r_inf + (r0 - r_inf) * math.exp(-P / P0)
            yn = min(max(y, uk - rad), uk + rad)
            P += abs(yn - y)
            y = yn
            out[k] = y
        r.cols["disp_m"] = out


# ------------------------------------------------------------------------------------------------ time delay


def td_pll_relock(s: Session) -> None:
    """The laser streams its readings on its own clock (f_L 200-500 Hz, log) and the logging software puts them on the
    DAQ's samples through a software phase-locked loop that it restarts at each record's start: the stream's alignment
    starts off by a random part of the laser's sample period (uniform +-1/(2 f_L)) and settles, as a type-II loop does,
    with a damped oscillation (natural frequency 0.2-0.6 Hz, damping 0.3-0.7) onto the stream's fixed latency (2-4 ms):
    a delay that changes within each record, wrong and swinging over its first seconds (a step's edge at 1 s among them)
    and steady later. Each reading the strip at t - tau(t) (linear interpolation within the record, its first and last
    values held beyond it); displacement only. Measured (paper_145) displacement residual 0.051 % of its RMS (3.1x its
    noise), the 20 Hz records' residuals 18-21 % (4 um at most)."""
    f_l, wn, zeta = lu(s.rng, 200.0, 500.0), 2 * math.pi * s.rng.uniform(0.2, 0.6), s.rng.uniform(0.3, 0.7)
    lat = s.rng.uniform(2e-3, 4e-3)
    wd = wn * math.sqrt(1 - zeta * zeta)
    for r in _chrono(s):
        t, x = r.cols["t_s"], r.cols["disp_m"]
        u = t - t[0]
        e0 = s.rng.uniform(-0.5, 0.5) / f_l
        tau = lat + e0 * np.exp(-zeta * wn * u) * (np.cos(wd * u) + zeta * wn / wd * np.sin(wd * u))
        r.cols["disp_m"] = np.interp(t - tau, t, x)


def td_delay_compensation(s: Session) -> None:
    """The laser controller's 'delay compensation' (a tracking controller's predictor, to offset its own processing
    time) left on: its output, late by its processing latency tau_p (3-8 ms, log), is pushed forward by tau_c (0.5-1.5
    tau_p) with the slope over the last h (2-5 ms) of readings, y = x(t - tau_p) + tau_c (x(t - tau_p) - x(t - tau_p -
    h))/h: H = e^(-s tau_p) (1 + (tau_c/h)(1 - e^(-s h))), a net delay tau_p - tau_c at low frequencies (late or early,
    drawn by the ranges) with a gain that rises over the faster records, the predictor's overshoot at the steps' edges.
    Linear, neither a lag nor a pure delay. Through inject_fresh2._through (0.5 s of the session's history);
    displacement only. Measured (p21_147) displacement residual 0.10 % of its RMS (3.0x its noise), the 20 Hz records'
    residuals 45-48 %."""
    tp = lu(s.rng, 3e-3, 8e-3)
    tc, h = tp * s.rng.uniform(0.5, 1.5), s.rng.uniform(2e-3, 5e-3)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        def f(z: np.ndarray) -> np.ndarray:
            z = np.asarray(z, complex)
            return np.exp(-z * tp) * (1 + tc / h * (1 - np.exp(-z * h)))

        return f

    new = _through(s, H, 0.5)
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ sensor offset


def so_scanned_spot(s: Session) -> None:
    """A scanning head (a galvo-scanned triangulation spot, or a scanning vibrometer's mirrors left in continuous line
    scan, as labs do to average over the surface's speckle) sweeping its spot along the strip between m0 (0.1-0.3 mm)
    and m0 + l (l 0.5-1.5 mm) inside the tip's end at f_scan (300-1200 Hz, free running, a cosine sweep), its output
    read by the DAQ at each sample: each sample reads the strip at the station the spot had at that instant, and the
    DAQ, sampling without regard to the scan, aliases the sweep to |f_scan - k fs|: the station wobbles at a beat that
    depends on each record's rate (a slow wobble on some records, a fast one on others). The strip read at the moving
    station (inject_fresh10._station); displacement only. Measured (paper_145) displacement RMS -4.9 % (residual 5.7 %,
    340x its noise)."""
    L = float(s.specimen["length_m"])
    m0, l, f_scan = s.rng.uniform(1e-4, 3e-4), s.rng.uniform(5e-4, 1.5e-3), s.rng.uniform(300.0, 1200.0)
    ph = s.rng.uniform(0, 2 * np.pi)
    frac = lambda r: 1 - (m0 + l * (1 - np.cos(2 * np.pi * f_scan * r.cols["t_s"] + ph)) / 2) / L  # noqa: E731
    _station(s, frac, 1 - (m0 + l) / L)


def so_mdf_shelf(s: Session) -> None:
    """The laser head on an MDF shelf bracket across the bench (the lab's own shelving), aimed at the start a margin m0
    (0.1-0.3 mm) inside the tip's end: a rain front passes through the session and the room's humidity rises by 0.15-0.3
    RH around a moment 20-60 % into it (a sigmoid of width 300-900 s), the board's moisture follows it through its
    sorption lag (600-2000 s, log), and the swelling board carries the head along the strip, the spot walking inboard by
    0.3-0.8 mm at the full rise: a slow walk late in the session, the room's weather and not the bench's. The strip read
    at the moving station (inject_fresh10._station); displacement only. Measured (p21_147) displacement RMS -4.3 %
    (residual 4.6 %, 140x its noise)."""
    L = float(s.specimen["length_m"])
    m0, walk = s.rng.uniform(1e-4, 3e-4), s.rng.uniform(3e-4, 8e-4)
    t_f = s.t0 + s.rng.uniform(0.2, 0.6) * (s.t1 - s.t0)
    w, tau = s.rng.uniform(300.0, 900.0), lu(s.rng, 600.0, 2000.0)
    tg = _session_grid(s, 2.0, 600.0)
    rise = 1 / (1 + np.exp(-(tg - t_f) / w))
    board = _grid_lag(tg, rise, tau, float(rise[0]))
    board = (board - board[0]) / max(1.0 - float(board[0]), 1e-9)
    _station(s, lambda r: 1 - (m0 + walk * np.interp(r.cols["t_s"], tg, board)) / L, 1 - (m0 + walk) / L)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_mullins_pads(s: Session) -> None:
    """Filled-rubber pads under a screw clamp's fixed gap: rubber softens the first time it is squeezed past the largest
    squeeze it has known (the Mullins effect), quickly (over tau_m 10-60 s, log) and for good, so each setting loses a
    share m (0.08-0.2) of its force in proportion to its excess over the largest setting before it, (1 - p_max/p): the
    first setting all of m, the later ones less and less on the paper's rising sweep, a setting below an earlier one
    nothing; beside it the pads' logarithmic creep from each setting (0.5-1.5 % a decade, tau 2-20 s, log). Through the
    preset's clamp law (inject_fresh4._clamp_law), the load cell showing it. Measured (p21_147) displacement RMS -0.0025
    % (residual 0.11 %, 3.2x its noise), current RMS -0.049 % (residual 0.55 %, 0.40x its noise), the load cell at
    0.880-0.976 of its reading."""
    m, tau_m = s.rng.uniform(0.08, 0.2), lu(s.rng, 10.0, 60.0)
    r_c, tau_c = s.rng.uniform(0.005, 0.015), lu(s.rng, 2.0, 20.0)
    t_set = _settings(s)
    before, top = {}, 0.0
    for p, _ in sorted(t_set.items(), key=lambda kv: kv[1]):
        before[p], top = top, max(top, p)

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - t_set.get(p, t_first - 20.0), 0, None)
        soft = m * max(1 - before.get(p, 0.0) / p, 0.0) * -np.expm1(-u / tau_m)
        return 1 - soft - r_c * np.log10(1 + u / tau_c)

    _clamp_law(s, rel)


def cr_tightening_speed(s: Session) -> None:
    """The operator turns the clamp's screw to each setting by hand, some settings quickly and some slowly (the ramp T_r
    1-30 s, log, drawn per setting), stopping when the load cell reads the target; the pads are a linear viscoelastic
    solid with two relaxing arms (g1 0.05-0.12 over tau1 3-10 s, g2 0.05-0.12 over tau2 60-300 s, log), and after a
    ramp-and-hold the force left to relax is what the ramp did not: each arm's g tau (1 - e^(-T_r/tau))/T_r of the set
    force, the relaxation F(u)/F(0) = (G_inf T_r + sum g_i tau_i e^(-u/tau_i)(1 - e^(-T_r/tau_i)))/(G_inf T_r + sum g_i
    tau_i (1 - e^(-T_r/tau_i))). A quick setting relaxes by nearly g1 + g2, a slow one by much less of its fast arm: the
    relaxation's size changes from block to block with the hand, not the pressure. Through the preset's clamp law
    (inject_fresh4._clamp_law), the load cell showing it. Measured (paper_145) displacement RMS -0.0030 % (residual 0.14
    %, 8.4x its noise), current RMS -0.015 % (residual 0.93 %, 0.70x its noise), the load cell at 0.850-0.943 of its
    reading."""
    g1, g2 = s.rng.uniform(0.05, 0.12), s.rng.uniform(0.05, 0.12)
    t1, t2 = lu(s.rng, 3.0, 10.0), lu(s.rng, 60.0, 300.0)
    t_set = _settings(s)
    ramp = {p: lu(s.rng, 1.0, 30.0) for p, _ in sorted(t_set.items(), key=lambda kv: kv[1])}
    g_inf = 1 - g1 - g2

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - t_set.get(p, t_first - 20.0), 0, None)
        tr = ramp.get(p, 5.0)
        arms = [(g1, t1), (g2, t2)]
        num = g_inf * tr + sum(g * ta * np.exp(-u / ta) * -math.expm1(-tr / ta) for g, ta in arms)
        den = g_inf * tr + sum(g * ta * -math.expm1(-tr / ta) for g, ta in arms)
        return num / den

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_oscillating_fan(s: Session) -> None:
    """A strip in air on a bench where, 10-40 % into the session, someone switches on an oscillating desk fan: its head
    sweeps the room every T (8-30 s) and its air reaches the strip for a share 0.15-0.35 of each sweep. The strip's
    water relaxes towards the room's (0.55-0.75 of its water at the start) at a still-air rate (tau 3000-10000 s, log)
    and, in the fan's gusts, at a forced one (tau 100-400 s, log): a slow drying that turns quicker at the switch-on and
    goes down in a staircase of gusts. The gain as the water, the conductance as its 1.5-2.5th power, relative to the
    first record, the spectra at the next series' start (inject_fresh9._dry_by). Measured (s001_146) displacement RMS
    -18 % (residual 23 %, 740x its noise), current RMS -38 % (residual 48 %, 130x its noise)."""
    t_on = s.t0 + s.rng.uniform(0.1, 0.4) * (s.t1 - s.t0)
    T, duty, ph = s.rng.uniform(8.0, 30.0), s.rng.uniform(0.15, 0.35), s.rng.uniform(0.0, 1.0)
    w_eq, tau0, tau_f = s.rng.uniform(0.55, 0.75), lu(s.rng, 3000.0, 10000.0), lu(s.rng, 100.0, 400.0)
    gc = s.rng.uniform(1.5, 2.5)
    dt = 0.25
    tg = _session_grid(s, dt, 10.0)
    gust = (tg >= t_on) & (((tg - t_on) / T + ph) % 1.0 < duty)
    decay = np.exp(-dt * (1 / tau0 + gust / tau_f))
    w = w_eq + (1 - w_eq) * np.cumprod(decay)
    w0 = float(np.interp(s.t0, tg, w))
    _dry_by(s, lambda t: 1 - np.interp(t, tg, w) / w0, lambda t: 1 - (np.interp(t, tg, w) / w0) ** gc)


def dh_glycerol_solvent(s: Session) -> None:
    """A strip in air soaked in a glycerol-water mixture (a lab's way to slow its drying: water 0.7-0.9 of the solvent
    by mass) and mounted 0-300 s before the first record: the water evaporates (tau 800-3000 s, log) towards what
    glycerol holds at the room's humidity (0.15-0.3 of the solvent), the glycerol stays. The strain follows the
    solvent's amount (a share 0.3-0.6 of the lost solvent's bend), the ionic conductance its amount and its viscosity,
    which climbs steeply as the mixture thickens (Arrhenius mixing of water's 0.89 mPa s and glycerol's 1.41 Pa s by
    mass fraction; the conductance as its -0.3 to -0.6th power, a fractional Walden rule): the current falls far faster
    than the bend. Relative to the first record, the spectra at the next series' start (inject_fresh9._dry_by). Measured
    (s001_146) displacement RMS -19 % (residual 23 %, 730x its noise), current RMS -74 % (residual 85 %, 230x its
    noise)."""
    x0, x_eq = s.rng.uniform(0.7, 0.9), s.rng.uniform(0.15, 0.3)
    tau, lead = lu(s.rng, 800.0, 3000.0), s.rng.uniform(0.0, 300.0)
    share, beta = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.3, 0.6)
    tg = _session_grid(s, 2.0, lead)
    x = x_eq + (x0 - x_eq) * np.exp(-(tg - tg[0]) / tau)
    mass = (1 - x0) / (1 - x)  # the solvent left, glycerol kept
    eta = np.exp(x * math.log(0.89e-3) + (1 - x) * math.log(1.41))
    m0, e0 = float(np.interp(s.t0, tg, mass)), float(np.interp(s.t0, tg, eta))
    _dry_by(s, lambda t: share * (1 - np.interp(t, tg, mass) / m0),
            lambda t: 1 - np.interp(t, tg, mass) / m0 * (np.interp(t, tg, eta) / e0) ** -beta)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_surfactant_wetted_cracks(s: Session) -> None:
    """A cuvette rinsed with detergent and not rinsed clean (a lab-glass detergent's residue): the surfactant comes off
    the glass into the bath and adsorbs on the cracked plating (Langmuir uptake, tau_s 600-2400 s, log, from the filling
    0-300 s before the first record), and the wetter crack walls let the bath bridge a crack up to a wider opening: a
    crack adds resistance only beyond e0(t), which grows from 0.05-0.15 of the session's largest tension to 0.4-0.7 of
    it as the walls are covered. The tensioned face (side drawn) and the other at 0.2-0.5 of its gauge (k 0.8-1.5 per
    unit): the gauge's dead zone widens through the session, the same bend costing less late than early. Gains fall by
    0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (paper_145)
    displacement RMS -3.6 % (residual 4.1 %, 250x its noise), current RMS -0.36 % (residual 1.8 %, 1.4x its noise)."""
    side, o, k = _sign(s), s.rng.uniform(0.2, 0.5), s.rng.uniform(0.8, 1.5)
    e_a, e_b = s.rng.uniform(0.05, 0.15), s.rng.uniform(0.4, 0.7)
    tau_s, t_fill = lu(s.rng, 600.0, 2400.0), s.t0 - s.rng.uniform(0.0, 300.0)
    q = ref_disp(s) / (_largest(s) or ref_disp(s))

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        x = side * q * np.asarray(e)
        e0 = e_a + (e_b - e_a) * -np.expm1(-(r.cols["t_s"] - t_fill) / tau_s)
        return k * (np.clip(x - e0, 0.0, None) + o * np.clip(-x - e0, 0.0, None))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_extrusion_prestrain(s: Session) -> None:
    """The jaws' squeeze extrudes the wet polymer under them along the strip (Poisson's flow of a soft, nearly
    incompressible layer), and the extruded polymer drags the plating just outside the jaws with it: both faces' films
    there are pre-stretched in proportion to the clamp pressure, by c (0.3-0.8) of the cracks' closure e0 (0.3-0.6 of
    the session's largest tension) at the session's highest setting, so their cracks open at a bend of e0 (1 - c
    p/p_max): the gauge's dead zone shrinks with the setting, the harder clamp costing more resistance for the same bend
    (each face k 0.8-1.5 per unit, the other face 0.5-1 of it). Gains fall by 0.03-0.08 (displacement) and 0.06-0.15
    (current) per unit of dR/R (inject_fresh3._resist). Measured (p21_147) displacement RMS -2.3 % (residual 2.7 %, 81x
    its noise), current RMS -0.14 % (residual 0.87 %, 0.62x its noise)."""
    e0, c, k, o = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.3, 0.8), s.rng.uniform(0.8, 1.5), s.rng.uniform(0.5, 1.0)
    p_max = max(s.pressures())
    q = ref_disp(s) / (_largest(s) or ref_disp(s))

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        x = q * np.asarray(e)
        dz = e0 * (1 - c * float(r.entry["pressure_kPa"]) / p_max)
        return k * (np.clip(x - dz, 0.0, None) + o * np.clip(-x - dz, 0.0, None))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_morison_drag(s: Session) -> None:
    """The strip in water swinging at large amplitude: the water's drag on it is not only the linear (viscous, Sader)
    part the model has but also the form drag of the separated flow around a flat plate at a Keulegan-Carpenter number
    of a few (the swing over the width), the Morison term C_d |u| u, on the first mode: y'' + 2 zeta w y' + w^2 y = w^2
    u - c2 |y'| y' (w the strip's first resonance at its pressure from the preset's FRF, inject_fresh22._f1; zeta
    0.1-0.2), c2 set so that at the session's fastest tip speed (its 99.9th percentile) it adds an equivalent damping
    ratio of 0.05-0.2 (log). The fast large swings (the resonant sines, the steps' edges) are held back, the slow ones
    untouched, with odd harmonics. Integrated sample by sample in each record (the difference from the measured
    displacement, from rest at its start); displacement only. Measured (p21_147) displacement RMS -0.0003 % (residual
    0.19 %, 5.7x its noise)."""
    zeta, zq = s.rng.uniform(0.1, 0.2), lu(s.rng, 0.05, 0.2)
    speeds = np.concatenate([np.abs(np.gradient(r.cols["disp_m"]) * r.fs) for r in s.series()])
    vmax = float(np.percentile(speeds, 99.9)) or 1e-3
    cache: dict[float, float] = {}
    for r in s.series():
        w = 2 * math.pi * _f1(s, float(r.entry["pressure_kPa"]), cache)
        c2 = 2 * zq * w * 3 * math.pi / (8 * vmax)
        dt, d = 1.0 / r.fs, r.cols["disp_m"]
        dd = (np.gradient(d) * r.fs).tolist()
        e, ve = 0.0, 0.0
        out = np.empty(d.size)
        a1, a2 = 2 * zeta * w, w * w
        for k, dk in enumerate(dd):
            u = dk + ve
            ve += dt * (-a1 * ve - a2 * e - c2 * abs(u) * u)
            e += dt * ve
            out[k] = e
        r.cols["disp_m"] = d + out


def ld_single_plate_capacitance(s: Session) -> None:
    """No laser: a strip in air read by a single capacitive plate facing one face near its tip (the side drawn), at a
    gap g 2-4 times the session's largest bend, through a capacitance meter (a charge amplifier's bridge) whose output
    is the capacitance itself, C ~ 1/(g - y), not the gap (the usual probe's electronics linearise 1/C; this one does
    not), calibrated by its slope at rest: the reading g y/(g - y) expands the bends towards the plate and compresses
    those away from it, even and odd parts together. Tabulated and interpolated (inject_fresh22._table_map);
    displacement only. Measured (s001_146) displacement RMS -25 % (residual 26 %, 840x its noise; the plate on the side
    the positive bends leave, the 1 V steps read 3.1 mm for 4.7 mm)."""
    side = _sign(s)
    g = s.rng.uniform(2.0, 4.0) * (_largest(s) or ref_disp(s))
    _table_map(s, lambda x: side * g * (side * x) / (g - side * x))


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_arc_welder(s: Session) -> None:
    """The workshop next door welds a job during the session (a transformer stick welder on the building's supply): for
    20-40 min (log) from a moment inside the session the welder strikes arcs of 2-15 s (log) with pauses of 1-10 s (log)
    between them, and each arc's current (the line's frequency, 50 or 60 Hz; the arc's voltage clamps it into a
    flat-topped wave, 3rd 0.15-0.35, 5th 0.05-0.15) runs in cables along the corridor wall: its field reaches the
    laser's cable (5-15 um, log) and the current amplifier's input (50-150 uA, log), each arc at 0.6-1 of full current
    and flickering with the arc's length (10-30 % at 2-8 Hz). Bursts of hum in one stretch of the session, none outside
    it. Phase locked to the session clock. Measured (paper_145) displacement residual 0.067 % of its RMS (4.1x its
    noise, the 20 Hz records inside the job 74-116 %, 9-12 um), current residual 1.0 % (0.78x its noise)."""
    f0 = _line_f(s)
    h3, h5 = s.rng.uniform(0.15, 0.35), s.rng.uniform(0.05, 0.15)
    amp = {"disp_m": lu(s.rng, 5e-6, 1.5e-5), "i_A": lu(s.rng, 5e-5, 1.5e-4)}
    ph = {col: s.rng.uniform(0, 2 * np.pi, 3) for col in amp}
    job = lu(s.rng, 1200.0, 2400.0)
    start = s.t0 + s.rng.uniform(0.0, max(s.t1 - s.t0 - job, 1.0))
    arcs, t = [], start + s.rng.uniform(0.0, 5.0)
    while t < start + job:
        dur = lu(s.rng, 2.0, 15.0)
        arcs.append((t, t + dur, s.rng.uniform(0.6, 1.0), s.rng.uniform(0.1, 0.3), s.rng.uniform(2.0, 8.0),
                     s.rng.uniform(0, 2 * np.pi)))
        t += dur + lu(s.rng, 1.0, 10.0)
    for r in s.series():
        tt = r.cols["t_s"]
        env = np.zeros(tt.size)
        for a, b, size, fl, f_fl, p_fl in arcs:
            on = (tt >= a) & (tt < b)
            if on.any():
                env[on] = size * (1 + fl * np.sin(2 * np.pi * f_fl * tt[on] + p_fl))
        if not env.any():
            continue
        w = 2 * np.pi * f0 * tt
        for col, a in amp.items():
            p = ph[col]
            wave = np.cos(w + p[0]) + h3 * np.cos(3 * w + p[1]) + h5 * np.cos(5 * w + p[2])
            r.cols[col] = r.cols[col] + a * env * wave


def mp_hall_current_sensor(s: Session) -> None:
    """The current read by an open-loop Hall-effect sensor on the drive lead (a maker-style board, inside the drive
    amplifier's box) a few centimetres from the amplifier's mains transformer: the Hall element reads the transformer's
    stray field as current. That field is the magnetising current's (the core driven into saturation: peaky, 3rd
    0.2-0.4, 5th 0.05-0.15, 10-40 uA, log) and the load current's (in phase with the line, in proportion to the power
    the amplifier delivers, |i| over the last 20 ms, 20-80 uA, log, at the session's largest current): a hum on the
    current alone that swells on the large records. Phase locked to the session clock. Measured (s001_146) current
    residual 1.0 % of its RMS (2.7x its noise), 28 uA RMS on the 1 V steps' plateaus."""
    f0 = _line_f(s)
    h3, h5 = s.rng.uniform(0.2, 0.4), s.rng.uniform(0.05, 0.15)
    a_m, a_l = lu(s.rng, 1e-5, 4e-5), lu(s.rng, 2e-5, 8e-5)
    ph, p3, p5 = s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi)
    i_ref = _largest(s, "i_A") or 1e-3
    for r in s.series():
        t, i = r.cols["t_s"], r.cols["i_A"]
        w = 2 * np.pi * f0 * t + ph
        mag = np.sin(w) + h3 * np.sin(3 * w + p3) + h5 * np.sin(5 * w + p5)
        load = _lag(np.abs(i), r.fs, 0.02) / i_ref
        r.cols["i_A"] = i + a_m * mag + a_l * load * np.cos(w)


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_operator_breath(s: Session) -> None:
    """A strip in air, the operator standing over it after each re-clamping (from 0-20 s after the setting, for 60-240
    s, checking the load cell and the laser) and 1-3 times more at random: each exhalation's air pushes the light strip
    (a gust of a few tenths of a metre per second on its face) away from the operator (the side drawn), quasi-statically
    (far below its resonance): a pulse of 5-25 um (log, each breath 0.7-1.3 of it) over 0.35-0.45 of each breath, the
    breaths 3-5 s apart (each 10 % either way). Spells of a slow, one-sided pulse train, none between them. Displacement
    only. Measured (s001_146) displacement residual 0.23 % of its RMS (7.2x its noise, up to 21 um in the spells)."""
    side, A = _sign(s), lu(s.rng, 5e-6, 2.5e-5)
    period, share = s.rng.uniform(3.0, 5.0), s.rng.uniform(0.35, 0.45)
    setting = _setting_of(s)
    spells = [(setting(p, a) + s.rng.uniform(0.0, 20.0), lu(s.rng, 60.0, 240.0))
              for p, a in sorted(_by_pressure_start(s).items(), key=lambda kv: kv[1])]
    spells += [(s.rng.uniform(s.t0, s.t1), lu(s.rng, 60.0, 240.0)) for _ in range(int(s.rng.integers(1, 4)))]
    breaths = []
    for a, dur in spells:
        t = a
        while t < a + dur:
            T = period * s.rng.uniform(0.9, 1.1)
            breaths.append((t, share * T, s.rng.uniform(0.7, 1.3)))
            t += T
    for r in s.series():
        t = r.cols["t_s"]
        y = np.zeros(t.size)
        for b, w, size in breaths:
            if b > t[-1] or b + w < t[0]:
                continue
            on = (t >= b) & (t < b + w)
            y[on] += size * np.sin(np.pi * (t[on] - b) / w) ** 2
        r.cols["disp_m"] = r.cols["disp_m"] + side * A * y


def out_bubble_kicks(s: Session) -> None:
    """Electrolysis on the strip's faces at the large drives (abs(v) beyond v_g 0.6-0.85 V) grows gas bubbles that leave
    the faces at random (a Poisson rate of 1-5 a second at 1 V, in proportion to abs(v) - v_g), and each departure kicks
    the strip (the bubble's detachment and the liquid's rush into its place): the tip rings at its own first mode (its
    resonance at the pressure from the preset's FRF, inject_fresh22._f1; damping 0.1-0.25 in water) from a kick of 5-20
    um (log, each 0.5-1.5 of it), towards the face the bubble left: the cathode's mostly (twice the anode's gas).
    Transient ringing at random moments of the large records, nothing in the small ones. Displacement only. Measured
    (p21_147) displacement residual 0.15 % of its RMS (4.5x its noise, up to 35 um on the 1 V records); (paper_145)
    0.043 % (2.6x, up to 19 um)."""
    v_g, rate, A = s.rng.uniform(0.6, 0.85), s.rng.uniform(1.0, 5.0), lu(s.rng, 5e-6, 2e-5)
    zeta, side = s.rng.uniform(0.1, 0.25), _sign(s)
    cache: dict[float, float] = {}
    for r in _chrono(s):
        t, v = r.cols["t_s"], r.cols["v_V"]
        lam = rate * np.clip(np.abs(v) - v_g, 0.0, None) / (1 - v_g)
        if not lam.any():
            continue
        n = s.rng.poisson(lam / r.fs)
        w = 2 * math.pi * _f1(s, float(r.entry["pressure_kPa"]), cache)
        wd = w * math.sqrt(1 - zeta * zeta)
        span = int(5.0 / (zeta * w) * r.fs) + 1
        y = np.zeros(t.size)
        for k in np.flatnonzero(n):
            for _ in range(int(n[k])):
                face = np.sign(v[k]) * (1.0 if s.rng.random() < 2 / 3 else -1.0)
                u = t[k : k + span] - t[k]
                y[k : k + span] += side * face * A * s.rng.uniform(0.5, 1.5) * np.exp(-zeta * w * u) * np.sin(wd * u)
        r.cols["disp_m"] = r.cols["disp_m"] + y


def out_evaporating_tip_drop(s: Session) -> None:
    """A strip in air wetted by the operator at mounting (0-300 s before the first record), a drop of water left hanging
    on its tip: its mass (0.15-0.4 of the first mode's mass at the tip) lowers the first resonance by sqrt(1 + mu) and
    its damping ratio with it, and the drop evaporates with its contact line pinned, its mass falling linearly to
    nothing over 0.4-1.0 of the session: the resonance climbs back through the session while the static gain stays (a
    mass changes no statics). The first mode moved from the preset's (inject_fresh22._f1; the strip's damping taken as
    0.03-0.1) to the loaded one record by record (mu at the record's middle), through inject_fresh2._through (2 s of the
    session's history); displacement only. Measured (s001_146) displacement residual 0.20 % of its RMS (6.3x its noise;
    the 20 Hz records' residuals 37-131 %)."""
    mu0, zeta = s.rng.uniform(0.15, 0.4), s.rng.uniform(0.03, 0.1)
    t_w = s.t0 - s.rng.uniform(0.0, 300.0)
    life = s.rng.uniform(0.4, 1.0) * (s.t1 - s.t0)
    cache: dict[float, float] = {}

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        w0 = 2 * math.pi * _f1(s, float(r.entry["pressure_kPa"]), cache)
        mu = mu0 * max(1 - (float(np.mean(r.cols["t_s"])) - t_w) / life, 0.0)
        k = math.sqrt(1 + mu)
        return _mode_ratio(w0, zeta, w0 / k, zeta / k)

    new = _through(s, H, 2.0)
    map_disp(s, lambda r, d: new[id(r)])


def out_galvanic_contact(s: Session) -> None:
    """The jaws' contacts are fixed to the clamp by steel screws whose heads touch the strip's plating beside them, in
    the bath's water wicked into the contact: steel and platinum in one electrolyte are a galvanic couple, and at each
    re-clamping the screw's head bites into fresh plating and remakes it. Its current (100-300 uA on the freshly made
    contact, log, each setting 0.5-1 of it, the steel the anode: one sign) runs through the strip's circuit and the
    current amplifier whatever the drive, and falls as the couple polarises, (1 + u/tau)^(-1/2) (tau 120-600 s, log, u
    from the setting). An offset on the current that jumps at each re-clamping and decays, independent of the drive. The
    current only. Measured (paper_145) current residual 3.5 % of its RMS (2.7x its noise); (p21_147) 2.9 % (2.1x)."""
    side, i_g, tau = _sign(s), lu(s.rng, 1e-4, 3e-4), lu(s.rng, 120.0, 600.0)
    setting = _setting_of(s)
    blocks = sorted(_by_pressure_start(s).items(), key=lambda kv: kv[1])
    size = {p: s.rng.uniform(0.5, 1.0) for p, _ in blocks}
    start = dict(blocks)
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        u = np.clip(r.cols["t_s"] - setting(p, start[p]), 0.0, None)
        r.cols["i_A"] = r.cols["i_A"] + side * i_g * size[p] / np.sqrt(1 + u / tau)


FRESH25_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"creeping_network": br_creeping_network, "isotherm_activity": br_isotherm_activity},
    "faradaic_current": {"nitrate_peak": far_nitrate_peak, "saline_added": far_saline_added},
    "hysteresis": {"electroadhesive_guide": hy_electroadhesive_guide, "burred_lid_slot": hy_burred_lid_slot},
    "time_delay": {"pll_relock": td_pll_relock, "delay_compensation": td_delay_compensation},
    "sensor_offset": {"scanned_spot": so_scanned_spot, "mdf_shelf": so_mdf_shelf},
    "clamp_relaxation": {"mullins_pads": cr_mullins_pads, "tightening_speed": cr_tightening_speed},
    "dehydration": {"oscillating_fan": dh_oscillating_fan, "glycerol_solvent": dh_glycerol_solvent},
    "strain_resistance": {"surfactant_wetted_cracks": sr_surfactant_wetted_cracks,
                          "extrusion_prestrain": sr_extrusion_prestrain},
    "large_deflection": {"morison_drag": ld_morison_drag, "single_plate_capacitance": ld_single_plate_capacitance},
    "mains_pickup": {"arc_welder": mp_arc_welder, "hall_current_sensor": mp_hall_current_sensor},
    "unexplained": {"operator_breath": out_operator_breath, "bubble_kicks": out_bubble_kicks,
                    "evaporating_tip_drop": out_evaporating_tip_drop, "galvanic_contact": out_galvanic_contact},
}
inject.register_forms(FRESH25_FORMS)


# ------------------------------------------------------------------------------------------------ variants


LOADCELL_STEP_N = 0.0980665  # the indicator's 0.01 kgf
READ_S = 0.5  # the script's reading: the load cell's mean over the record's first half second


def v_measured_pressures(s: Session) -> None:
    """A lab whose acquisition script writes each record's pressure into the manifest from the load cell, not from the
    setting: the force it read at the record's start (its mean over the first 0.5 s) over the clamp's area, in kPa to
    0.1 (the indicator's resolution gives steps of 6 kPa at the paper's 16 mm^2), so the records of one block carry
    pressures that differ by the clamp's relaxation and the indicator's last digit; a spectrum (no load cell with the
    analyser) the reading of the time series after it in the manifest (the one before it at the end). A record without
    a force column keeps the pressure it had. The values, the rows and the rest of the manifest as they were. The
    import contract asks a positive pressure_kPa of each record; ``labrig import`` takes it."""
    area = float(s.specimen["clamp_area_m2"])
    read: dict[int, float] = {}
    for r in s.series():
        if "force_N" in r.cols:
            t = r.cols["t_s"]
            f = float(np.mean(r.cols["force_N"][t <= t[0] + READ_S]))
            if f > 0:
                read[id(r)] = round(f / area / 1e3, 1)
    for k, r in enumerate(s.recs):
        if r.series:
            if id(r) in read:
                r.entry["pressure_kPa"] = read[id(r)]
            continue
        nxt = [q for q in s.recs[k + 1 :] if q.series and id(q) in read]
        prv = [q for q in s.recs[:k] if q.series and id(q) in read]
        if nxt or prv:
            r.entry["pressure_kPa"] = read[id((nxt or prv[::-1])[0])]


inject.VARIANTS.update({"measured_pressures": v_measured_pressures})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_145", "s001_146", "p21_147"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 145-147
    "back_relaxation": [("creeping_network", 145, P, "log_steps"), ("isotherm_activity", 146, S, "fixed_decimals")],
    "faradaic_current": [("nitrate_peak", 145, P, "eis_descending"), ("saline_added", 147, T, "short_pretrigger")],
    "hysteresis": [("electroadhesive_guide", 146, S, "scan_hold"), ("burred_lid_slot", 147, T, "cycle_averaged")],
    "time_delay": [("pll_relock", 145, P, "stop_trigger"), ("delay_compensation", 147, T, "swinging_door")],
    "sensor_offset": [("scanned_spot", 145, P, "rate07"), ("mdf_shelf", 147, T, "tared_records")],
    "clamp_relaxation": [("mullins_pads", 147, T, "measured_pressures"),
                         ("tightening_speed", 145, P, "merged_loadcell")],
    "dehydration": [("oscillating_fan", 146, S, "split_spectra"), ("glycerol_solvent", 146, S, "steps_sines")],
    "strain_resistance": [("surfactant_wetted_cracks", 145, P, "dropped_packets"),
                          ("extrusion_prestrain", 147, T, "resampled")],
    "large_deflection": [("morison_drag", 147, T, "fir_decimated"),
                         ("single_plate_capacitance", 146, S, "coherent_sines")],
    "mains_pickup": [("arc_welder", 145, P, "float32_time"), ("hall_current_sensor", 146, S, "own_clock")],
    "unexplained": [("operator_breath", 146, S, "loadcell_dropout"), ("operator_breath", 146, S, "trigger_clock"),
                    ("bubble_kicks", 145, P, "decimated3"), ("bubble_kicks", 147, T, "no_loadcell"),
                    ("evaporating_tip_drop", 146, S, "no_spectra"), ("evaporating_tip_drop", 146, S, "host_timed"),
                    ("galvanic_contact", 145, P, "measured_pressures"),
                    ("galvanic_contact", 147, T, "shortened_shuffled")],
}
CLEAN = [(145, P, "measured_pressures"), (145, P, "two_pressures"), (146, S, "measured_pressures"),
         (146, S, "settled_sines"), (147, T, "asrun"), (147, T, "spectra_last")]


def fresh25_cases(only: str | None = None) -> list[Case]:
    """The twenty-sixth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    145-147)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh25_cases, "inject_fresh25", "fresh25")
