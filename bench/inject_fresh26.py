"""A twenty-seventh held-out set for the diagnosis (issue 12), fresh26, written without sight of the diagnosis (its
code, its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh25.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (a back-flow through pores holding a
shear-thinning gel's polymer, a thick porous platinum black whose pores double the electrolysis' Tafel slope, a catheter
sleeve's lips gripping the tip beyond its clearance, a collagen plug strain-stiffening at the tip, a laser head read
beyond the range of its linearisation table, the clamp's pads creeping faster under the bend's moment), some on the
history, the clamp pressure or the session's events (residual platinum salt reduced into the pores by the cathodic
charge, a flake of plating lodged between the tip and the cuvette until the next re-clamping, a laptop's USB link
waking from selective suspend after each long rest, foam pads whose cells collapse above their plateau stress, a heat
gun used on a splash at one re-clamping, misaligned jaws pre-bending the root harder at each setting, a tweezer scratch
across one face at one re-clamping, a motorised clamp's driver holding more current at the tighter settings, a cracked
cable shield making and breaking contact), some on time (a tap-water bath's chlorine escaping, an anti-alias filter's
Y5V capacitor warming in the DAQ box, an orbital shaker making the laser's rod clamp slip in steps, an ink dot bleeding
along the wet strip, the building's heating coming on) and from the lab's wiring or sensors (the USB link, the filter,
the rod clamp, the ink dot, the range-limited table, the clamp's driver, the cable's shield). Four structures outside
the catalogue (truth "unexplained": a ceiling radiant panel cycling on its thermostat and bending an unevenly plated
strip in air as a bimorph, a radio on the bench shaking a strip in air at its resonance, an electroplating
rectifier next door shifting the rig's earth under the DAQ's single-ended inputs, the bath's swirl after each touch
spinning down); clean sessions. All on three bases of new seeds (148-150: the paper strip, the seed-001 strip on its own
sweep, the paper strip 19 mm free) and on the earlier sets' protocol / data-shape variants plus one new here: the laser
head facing the strip's other face, so that every displacement is written with the opposite sign
(``reversed_laser``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh25 are reused (importing inject_fresh25 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh26.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy.signal import butter, sosfiltfilt

import inject
import inject_fresh25  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lti, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _through
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law
from inject_fresh9 import _dry_by, _session_grid
from inject_fresh10 import _lag_varying, _lambda, _station
from inject_fresh11 import _walk
from inject_fresh12 import _line_f
from inject_fresh14 import _largest, _thermostat
from inject_fresh16 import CURRENT_A_PER_V, LASER_M_PER_V
from inject_fresh19 import _magnus
from inject_fresh22 import _f1, _table_map
from inject_fresh24 import _by_pressure_start, _friction_play
from inject_fresh25 import _setting_of

# the paper's strip 19 mm free (earlier sets used 20-29 and 31-45 mm, 30 mm is the paper preset itself and the seed-001
# strip is 20 mm; its 1 V step peaks near 3.6 mm, well inside the laser's +-20 mm): preset "paper_19", base "p19_150",
# registered in every process importing this module
inject.register_free_length("paper_19", 0.019)

inject.BASES.update({
    "paper_148": ("paper-sweep", "paper", 148),
    "s001_149": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 149),
    "p19_150": ("paper-sweep", "paper_19", 150),
})

R_GAS = 8.314  # J/(mol K)


# ------------------------------------------------------------------------------------------------ tools


def _split_noise(r: Rec, col: str = "disp_m") -> tuple[np.ndarray, np.ndarray]:
    """A column as (its signal, its sensor noise): the signal through a zero-phase second-order low-pass at 0.15 of the
    record's rate (far above every drive frequency of the records: flat on them), the noise what is left (its part above
    that corner). A form that holds the strip keeps the sensor's noise on the held reading."""
    x = r.cols[col]
    if x.size < 16:
        return x.copy(), np.zeros(x.size)
    smooth = sosfiltfilt(butter(2, 0.3, output="sos"), x)  # corner 0.3 of Nyquist = 0.15 fs
    return smooth, x - smooth


def _held_by(s: Session, radius: Callable[[Rec, np.ndarray], np.ndarray] | None = None,
             sticky: Callable[[float], float] | None = None, free: Callable[[Rec], np.ndarray] | None = None) -> None:
    """Dry friction on the strip's tip through the session in time order, the sensor's noise kept: each record's signal
    (``_split_noise``) through a play, its radius per sample ``radius(r, signal)`` or, where ``sticky`` is given, set by
    where it sticks (inject_fresh24._friction_play); samples where ``free(r)`` is True run free (the element follows
    the tip). The noise added back on top."""
    y = 0.0
    for r in _chrono(s):
        sig, noise = _split_noise(r)
        loose = free(r) if free is not None else np.zeros(sig.size, bool)
        if sticky is not None:
            out, y = _friction_play(sig, y, sticky)
        else:
            out = np.empty(sig.size)
            for k, (uk, rk, fk) in enumerate(zip(sig.tolist(), radius(r, sig).tolist(), loose.tolist())):
                y = uk if fk else min(max(y, uk - rk), uk + rk)
                out[k] = y
        r.cols["disp_m"] = out + noise


def _charge_clock(s: Session) -> tuple[np.ndarray, np.ndarray]:
    """The charge passed through the strip so far (the integral of abs(i) over the series in time order, constant over
    the rests): (session times, charge), for interpolation."""
    ts, qs, q = [], [], 0.0
    for r in _chrono(s):
        t, i = r.cols["t_s"], np.abs(r.cols["i_A"])
        c = q + np.r_[0.0, np.cumsum(0.5 * (i[1:] + i[:-1]) * np.diff(t))]
        ts.append(t)
        qs.append(c)
        q = float(c[-1])
    return np.concatenate(ts), np.concatenate(qs)


def _on_grid(s: Session, col: str, tg: np.ndarray, rest: float = 0.0) -> np.ndarray:
    """A column read on the session grid tg: its value inside a record, ``rest`` between records."""
    out = np.full(tg.size, rest)
    for r in s.series():
        t = r.cols["t_s"]
        inside = (tg >= t[0]) & (tg <= t[-1])
        out[inside] = np.interp(tg[inside], t, r.cols[col])
    return out


def _later_setting(s: Session) -> tuple[float, float]:
    """One pressure block after the first, drawn: (its pressure, its setting time); the first block's if only one."""
    setting = _setting_of(s)
    blocks = sorted(_by_pressure_start(s).items(), key=lambda kv: kv[1])
    p, a = blocks[int(s.rng.integers(1, len(blocks))) if len(blocks) > 1 else 0]
    return p, setting(p, a)


# ------------------------------------------------------------------------------------------------ back relaxation


def br_shear_thinning_pores(s: Session) -> None:
    """A strip stored between tests in a thickened storage gel (a carbomer or xanthan hydrogel a lab keeps its strips
    wet in), its polymer drawn into the electrodes' outer pores: the water the bend pushed to the cathode side flows
    back through pores holding a shear-thinning solution (Carreau: the viscosity falls with the shear rate as (1 +
    (rate/rate_c)^2)^((n - 1)/2), n 0.3-0.6), so the back-flow's conductance grows with its own speed: the returned
    water x follows dx/dt = (d - x)/tau (1 + ((d - x)/(g_c D))^2)^((1 - n)/(2 n)) (tau 2-8 s, log; g_c 0.1-0.3; D the
    session's largest bend), exact for a rate held over each sample, the opposing swelling K2 x (K2 0.6-1.0): a small
    bend gives back over tau, a large one much faster, and its give-back saturates the speed-up as it completes. Sample
    by sample through the session in time order (inject_fresh11._walk; the rests at rest, sub-stepped at 0.05 s);
    displacement only. Measured (paper_148) displacement RMS -59 % (residual 62 %, 3700x its noise), the 1 V steps (8.8
    mm clean) at 2.3 mm 5 s after their edge, 3.5 mm by the plateaus' end."""
    k2, tau = s.rng.uniform(0.6, 1.0), lu(s.rng, 2.0, 8.0)
    g_c, n = s.rng.uniform(0.1, 0.3), s.rng.uniform(0.3, 0.6)
    m = (1 - n) / (2 * n)
    D = _largest(s) or ref_disp(s)
    scale = 1.0 / (g_c * D) ** 2

    def step(x: float, d: float, dt: float) -> float:
        g = d - x
        return x + g * -math.expm1(-dt / tau * (1 + g * g * scale) ** m)

    def rest(x: float, seconds: float) -> float:  # the strip at rest, sub-stepped at 0.05 s
        n = max(int(math.ceil(seconds / 0.05)), 1)
        for _ in range(n if seconds > 0 else 0):
            x = step(x, 0.0, seconds / n)
        return x

    y = _walk(s, step, rest=rest)
    map_disp(s, lambda r, d: d - k2 * y[id(r)])


def br_residual_pt_salt(s: Session) -> None:
    """A strip plated by impregnation-reduction and not washed out long enough: platinum ammine cations left in the
    membrane are reduced at the membrane's interface with whichever electrode is the cathode as the session's charge
    passes, growing platinum into the pores the back-flow runs through and narrowing them: the back-flow's time constant
    grows with the charge passed so far, tau = tau_0 (1 + c Q/Q_end) (tau_0 1-4 s, log; c 1.5-4; Q the integral of
    abs(i), Q_end the session's), its share K2 (0.6-1.0) kept (the pores narrow, the water still comes back). A lag with
    a time constant that the session's own charge sets (inject_fresh10._lag_varying, reading d - K2 x); displacement
    only. Measured (p19_150) displacement RMS -64 % (residual 73 %, 1800x its noise), the 1 V steps (3.6 mm clean) at
    0.84 mm 5 s after their edge in the first block, 1.2 mm in the last (giving back more slowly)."""
    k2, tau0, c = s.rng.uniform(0.6, 1.0), lu(s.rng, 1.0, 4.0), s.rng.uniform(1.5, 4.0)
    tq, q = _charge_clock(s)
    q_end = max(float(q[-1]), 1e-30)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        share = np.interp(t, tq, q) / q_end
        return np.full(np.shape(t), k2), tau0 * (1 + c * share)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_chlorinated_tap(s: Session) -> None:
    """A bath of fresh tap water, its residual disinfectant (free chlorine, hypochlorous acid: 0.2-1 mg/l) reduced on
    whichever face is the cathode at a low overpotential (a wave from E_c 0.1-0.25 V of drive, width b 0.03-0.06 V) up
    to its diffusion limit, 0.15-0.4 mA (log) with the bath as filled, the anode's oxygen in series (odd in the drive);
    the chlorine escapes from the open cuvette (and light decomposes it), first order from the filling 0-300 s before
    the first record, tau 900-3600 s (log): the wave's limit falls through the session. Memoryless in the drive, the
    current only. Measured (p19_150) current RMS +1.9 % (residual 4.3 %, 3.0x its noise), 0.31 mA on the first block's 1
    V plateaus, 0.04 mA on the last's."""
    e_c, b = s.rng.uniform(0.1, 0.25), s.rng.uniform(0.03, 0.06)
    i_l, tau = lu(s.rng, 1.5e-4, 4e-4), lu(s.rng, 900.0, 3600.0)
    t_fill = s.t0 - s.rng.uniform(0.0, 300.0)
    k0 = 1 / (1 + math.exp(e_c / b))
    for r in s.series():
        t, v = r.cols["t_s"], r.cols["v_V"]
        wave = 1 / (1 + np.exp(-(np.abs(v) - e_c) / b)) - k0
        r.cols["i_A"] = r.cols["i_A"] + np.sign(v) * i_l * np.exp(-(t - t_fill) / tau) * wave


def far_porous_tafel_doubling(s: Session) -> None:
    """Electrodes of thick platinum black (a lab's recipe for a large double layer), porous through their depth: water
    is electrolysed on the pores' walls (a symmetric Butler-Volmer kinetics, 2 i0 sinh(u/2 v_t), v_t 0.08-0.14 V), but
    the pore water's resistance drops the potential along each pore, so only a depth lambda ~ 1/sqrt(r g_F) reacts, and
    it shrinks as the kinetic conductance g_F grows with the drive (de Levie's porous electrode): i = i_k tanh(m)/m, m =
    m_1 sqrt(i_k/i_k(1 V)) (m_1 2-5): the whole depth at small drives, a thinning skin at large ones, the current
    growing with twice the kinetic Tafel slope there (0.25-0.6 mA at 1 V, log). Odd, memoryless; the current only.
    Measured (paper_148) current RMS +1.9 % (residual 4.1 %, 3.1x its noise), 0.27 mA on the 1 V plateaus."""
    vt, m1, i1 = s.rng.uniform(0.08, 0.14), s.rng.uniform(2.0, 5.0), lu(s.rng, 2.5e-4, 6e-4)
    ik1 = i1 * m1 / math.tanh(m1)
    s1 = math.sinh(1 / (2 * vt))
    for r in s.series():
        v = r.cols["v_V"]
        ik = ik1 * np.sinh(np.abs(v) / (2 * vt)) / s1
        m = m1 * np.sqrt(ik / ik1)
        share = np.where(m > 1e-6, np.tanh(m) / np.where(m > 1e-6, m, 1.0), 1.0)
        r.cols["i_A"] = r.cols["i_A"] + np.sign(v) * ik * share


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_lodged_flake(s: Session) -> None:
    """A flake of plating that came off the strip's edge (or a fibre of lint) drifting in the bath lodges between the
    tip and the cuvette's wall at a moment inside a record drawn from the middle of the session (the 15-60 % of its
    records in time order), and rubs there: dry friction that holds the tip while its pull stays within r (0.02-0.06 of
    the session's largest bend) of where it sticks, until the operator sees it at the next re-clamping and fishes it out
    (the tip free again from that setting; held to the end if none follows). An episode of rate-independent memory the
    session's events bound; before and after it the strip runs free. Quasi-static, sample by sample through the session
    in time order; the laser's own noise kept on the held reading (_held_by); displacement only. Measured (s001_149)
    displacement RMS -0.0002 % (residual 0.20 %, 6.0x its noise)."""
    D = _largest(s) or ref_disp(s)
    rad = s.rng.uniform(0.02, 0.06) * D
    recs = _chrono(s)
    lo = int(0.15 * len(recs))
    r_in = recs[int(s.rng.integers(lo, max(int(0.6 * len(recs)), lo + 1)))]
    t_in = s.rng.uniform(float(r_in.cols["t_s"][0]), float(r_in.cols["t_s"][-1]))
    setting = _setting_of(s)
    later = [setting(p, a) for p, a in _by_pressure_start(s).items() if setting(p, a) > t_in]
    t_out = min(later) if later else math.inf

    def free(r: Rec) -> np.ndarray:
        t = r.cols["t_s"]
        return (t < t_in) | (t >= t_out)

    _held_by(s, radius=lambda r, u: np.full(u.size, rad), free=free)


def hy_sheath_capstan(s: Session) -> None:
    """The strip tested as a catheter's steering tip: its free end runs through a short PTFE sleeve (a cut catheter's
    lumen, 2-4 mm long) that leaves the tip a clearance: within it the tip runs free, beyond it (a bend past c 0.25-0.5
    of the session's largest) it bears on the sleeve's lips with a normal force growing with the excess, and the
    contact's friction, wrapped over the lip's curve, grows with the tip's angle as a capstan does (exp(mu theta),
    PTFE's mu 0.1-0.3, theta 2 d/L): a play whose radius is r_1 (|y|/D - c)_+ exp(mu 2|y|/L) (r_1 0.15-0.4 of the
    largest bend D) where it sticks (inject_fresh24._friction_play). No memory at the small records, sticking loops at
    the large ones. Quasi-static, sample by sample through the session in time order, the laser's noise kept (_held_by);
    displacement only. Measured (p19_150) displacement RMS -3.7 % (residual 11 %, 280x its noise), the 1 V steps held at
    3.1 mm of their 3.6 mm at the plateaus' end."""
    D = _largest(s) or ref_disp(s)
    L = float(s.specimen["length_m"])
    c, mu, r1 = s.rng.uniform(0.25, 0.5), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.15, 0.4) * D
    _held_by(s, sticky=lambda y: r1 * max(abs(y) / D - c, 0.0) * math.exp(mu * 2 * abs(y) / L))


# ------------------------------------------------------------------------------------------------ time delay


def td_usb_suspend(s: Session) -> None:
    """The laser streams over USB to the logging laptop, stamped on arrival, and the laptop's selective suspend puts the
    idle link to sleep: after a rest longer than its idle timeout (T_s 30-60 s) the record's first readings wait in the
    head's buffer while the link wakes (L_0 40-150 ms, log), and the host then drains the backlog a little faster than
    the head fills it (the delay falling by kappa 0.02-0.08 s per second) down to the link's steady latency (1-3 ms): a
    delay that starts long after the long rests (each block's step and harmonic, the slow sines), shrinks over the
    record's first seconds and never appears on records that follow closely. Each reading the strip at t - delay(t)
    (linear interpolation within the record, its first value held before it); displacement only. Measured (paper_148)
    displacement residual 0.34 % of its RMS (20x its noise), the 20 Hz records' residuals 95-110 %."""
    t_s, l0 = s.rng.uniform(30.0, 60.0), lu(s.rng, 0.04, 0.15)
    kappa, lat = s.rng.uniform(0.02, 0.08), s.rng.uniform(1e-3, 3e-3)
    t_end = -math.inf
    for r in _chrono(s):
        t, x = r.cols["t_s"], r.cols["disp_m"]
        u = t - t[0]
        backlog = l0 * s.rng.uniform(0.8, 1.2) if t[0] - t_end > t_s else 0.0
        delay = lat + np.clip(backlog - kappa * u, 0.0, None)
        r.cols["disp_m"] = np.interp(t - delay, t, x)
        t_end = float(t[-1])


def td_y5v_warming_filter(s: Session) -> None:
    """The laser's analogue line through the lab's home-made anti-alias RC (corner 8-20 Hz, log, with the box cold)
    whose capacitor is a Y5V ceramic, and the DAQ's box (its fan stopped, the lid closed) warming from the session's
    start by 8-15 K over tau_b 900-3000 s (log): Y5V loses capacitance steeply as it warms (-1.5 to -2.5 % per K above
    20 C), so the filter's time constant, its group delay at low frequencies, shrinks by a fifth to a third through the
    session: a lag of the displacement whose delay falls with the box's warming. Record by record (its time constant at
    the record's middle) through inject_fresh2._through (0.5 s of the session's history); displacement only. Measured
    (s001_149) displacement residual 0.26 % of its RMS (8.1x its noise), the 20 Hz records' residuals 71-76 %."""
    fc, dT = lu(s.rng, 8.0, 20.0), s.rng.uniform(8.0, 15.0)
    tau_b, coef = lu(s.rng, 900.0, 3000.0), s.rng.uniform(0.015, 0.025)
    rc0 = 1 / (2 * math.pi * fc)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        warm = dT * -math.expm1(-(float(np.mean(r.cols["t_s"])) - s.t0) / tau_b)
        rc = rc0 * max(1 - coef * warm, 0.2)
        return lambda z: 1 / (1 + rc * np.asarray(z))

    new = _through(s, H, 0.5)
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ sensor offset


def so_shaker_ratchet(s: Session) -> None:
    """The laser head on a rod in a rod clamp, aimed at the start a margin m0 (0.1-0.3 mm) inside the tip's end, and an
    orbital shaker on the same bench running one job (20-60 min, log, from 10-60 % into the session): its vibration
    makes the rod clamp slip now and then (Poisson, 0.005-0.02 a second), each slip turning the head so that its spot
    steps inboard along the strip by 10-40 um (log), and between the slips it holds. A staircase walk of the spot over
    one stretch of the session, none before it, held after it. The strip read at the moving station
    (inject_fresh10._station); displacement only. Measured (p19_150) displacement RMS -2.7 % (residual 2.8 %, 71x its
    noise)."""
    L = float(s.specimen["length_m"])
    m0 = s.rng.uniform(1e-4, 3e-4)
    dur = lu(s.rng, 1200.0, 3600.0)
    a = s.t0 + s.rng.uniform(0.1, 0.6) * (s.t1 - s.t0)
    rate = s.rng.uniform(0.005, 0.02)
    slips, t = [], a
    while True:
        t += s.rng.exponential(1 / rate)
        if t >= a + dur:
            break
        slips.append((t, lu(s.rng, 1e-5, 4e-5)))
    ts = np.array([x for x, _ in slips]) if slips else np.zeros(0)
    walk = np.cumsum([y for _, y in slips]) if slips else np.zeros(0)
    total = float(walk[-1]) if slips else 0.0

    def frac(r: Rec) -> np.ndarray:
        k = np.searchsorted(ts, r.cols["t_s"], side="right")
        return 1 - (m0 + np.r_[0.0, walk][k]) / L

    _station(s, frac, 1 - (m0 + total) / L)


def so_bleeding_ink_dot(s: Session) -> None:
    """No laser: video tracking of a dot of water-based ink drawn at the tip's end of a strip in air (a quick target for
    a dark strip), 0-600 s before the first record. The strip's wet surface wicks the ink inboard along it (the end
    bounds it on the other side), so the dot spreads one way and its centroid, which the tracker follows, walks inboard
    as the square root of the time since it was drawn: m0 (0.1-0.3 mm) + c sqrt(t - t_i), c set so that it has moved
    0.3-0.8 mm more by the session's end. The strip read at the moving station (inject_fresh10._station); displacement
    only. Measured (s001_149) displacement RMS -5.5 % (residual 5.6 %, 170x its noise)."""
    L = float(s.specimen["length_m"])
    m0, more = s.rng.uniform(1e-4, 3e-4), s.rng.uniform(3e-4, 8e-4)
    t_i = s.t0 - s.rng.uniform(0.0, 600.0)
    c = more / math.sqrt(s.t1 - t_i)
    _station(s, lambda r: 1 - (m0 + c * np.sqrt(np.clip(r.cols["t_s"] - t_i, 0.0, None))) / L, 1 - (m0 + more) / L)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_foam_cell_collapse(s: Session) -> None:
    """Closed-cell foam pads under a screw clamp's fixed gap (an EVA or neoprene foam cut to spread the force): below
    their plateau stress the foam's cells only bend, and the force relaxes a little (viscoelastically, r_v 0.5-1.5 % a
    decade, tau 2-20 s, log); at and above it their walls buckle and the cells collapse one after another under the held
    gap, a creep that takes r_c (0.06-0.15) off the force over tau_c 20-200 s (log). The plateau is crossed at p_c
    (0.3-0.7 of the session's highest setting, a band of 0.05-0.1 of it): the light settings hold, the heavy ones sag.
    From each setting (inject_fresh25._setting_of) through the preset's clamp law (inject_fresh4._clamp_law), the load
    cell showing it. Measured (paper_148) displacement residual 0.14 % of its RMS (8.2x its noise), current residual
    0.70 % (0.53x its noise), the load cell at 0.87-0.99 of its reading."""
    r_v, tau_v = s.rng.uniform(0.005, 0.015), lu(s.rng, 2.0, 20.0)
    r_c, tau_c = s.rng.uniform(0.06, 0.15), lu(s.rng, 20.0, 200.0)
    top = max(s.pressures())
    p_c, w = s.rng.uniform(0.3, 0.7) * top, s.rng.uniform(0.05, 0.1) * top
    setting = _setting_of(s)

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - setting(p, t_first), 0, None)
        collapse = r_c / (1 + math.exp(-(p - p_c) / w))
        return 1 - r_v * np.log10(1 + u / tau_v) + collapse * np.expm1(-u / tau_c)

    _clamp_law(s, rel)


def cr_moment_assisted_creep(s: Session) -> None:
    """Rubber pads under a screw clamp's fixed gap creeping logarithmically (r 3-6 % of the force per decade of creep
    time, tau 2-20 s, log), but the strip's bend loads the pads too: its root moment presses the pad under the jaw's
    edge on the side it bends away from, and the creep's clock runs faster under that extra stress, dxi/dt = 1 + a
    (d/D)^2 (a 20-80; D the session's largest bend): the held 1 V steps and the large sines age the pads many times
    faster than the rests and the small sines. The force follows r log10(1 + xi/tau), xi counted from each setting
    (inject_fresh25._setting_of) on a 0.2 s session grid; through the preset's clamp law (inject_fresh4._clamp_law), the
    load cell showing it. Measured (p19_150) displacement residual 0.14 % of its RMS (3.4x its noise), current residual
    0.63 % (0.44x its noise), the load cell at 0.92-0.99 of its reading."""
    r, tau, a = s.rng.uniform(0.03, 0.06), lu(s.rng, 2.0, 20.0), s.rng.uniform(20.0, 80.0)
    D = _largest(s) or ref_disp(s)
    setting = _setting_of(s)
    starts = {p: setting(p, t0) for p, t0 in _by_pressure_start(s).items()}
    dt = 0.2
    tg = _session_grid(s, dt, max(s.t0 - min(starts.values()), 0.0) + 1.0)
    rate = 1 + a * (_on_grid(s, "disp_m", tg) / D) ** 2
    clock = np.r_[0.0, np.cumsum(0.5 * (rate[1:] + rate[:-1]) * dt)]

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        t = np.asarray(t, float)
        xi = np.clip(np.interp(t, tg, clock) - np.interp(starts.get(p, t_first - 20.0), tg, clock), 0.0, None)
        return 1 - r * np.log10(1 + xi / tau)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_heat_gun_splash(s: Session) -> None:
    """A strip in air, drying slowly in the still room (towards 0.65-0.8 of its water, tau 4000-15000 s, log); at one
    re-clamping after the first (drawn) the operator dries a splash on the clamp with a heat gun (or a hair dryer) for
    20-90 s from the setting, the strip in its hot, dry stream: its water falls towards 0.35-0.6 of what it held (tau
    15-60 s), then, the gun off, the strip takes part of it back from the room over 200-800 s (log), to 0.4-0.8 of the
    way back, and dries slowly on from there. A sudden loss at one event, a partial recovery, the slow drying beneath.
    The gain as the water, the conductance as its 1.5-2.5th power, relative to the first record; the spectra at the next
    series' start (inject_fresh9._dry_by). Measured (s001_149) displacement RMS -12 % (residual 19 %, 600x its noise),
    current RMS -15 % (residual 18 %, 49x its noise); the third block's 1 V step at 3.0 mm for 4.7 mm."""
    w_room, tau0 = s.rng.uniform(0.65, 0.8), lu(s.rng, 4000.0, 15000.0)
    _, t_g = _later_setting(s)
    blow, w_hot, tau_h = s.rng.uniform(20.0, 90.0), s.rng.uniform(0.35, 0.6), s.rng.uniform(15.0, 60.0)
    tau_r, back = lu(s.rng, 200.0, 800.0), s.rng.uniform(0.4, 0.8)
    gc = s.rng.uniform(1.5, 2.5)
    dt = 1.0
    tg = _session_grid(s, dt, 10.0)
    w = np.empty(tg.size)
    x, low = 1.0, None
    for k, t in enumerate(tg.tolist()):
        if t_g <= t < t_g + blow:
            x += (w_hot - x) * -math.expm1(-dt / tau_h)
        else:
            if t >= t_g + blow and low is None:
                low = x
            target = w_room  # the room's slow drying, and after the gun the water it gives back drying with it
            if low is not None:
                target += (low + back * (1 - low) - w_room) * math.exp(-(t - t_g - blow) / tau0)
            x += (target - x) * -math.expm1(-dt / (tau_r if low is not None and x < target else tau0))
        w[k] = x
    w0 = float(np.interp(s.t0, tg, w))
    _dry_by(s, lambda t: 1 - np.interp(t, tg, w) / w0, lambda t: 1 - (np.interp(t, tg, w) / w0) ** gc)


def dh_morning_heating(s: Session) -> None:
    """A strip in air in a room whose heating comes on at a moment 10-50 % into the session (the building's morning
    schedule): the air warms by 2-5 K over tau_T 600-1800 s (log) from T0 19-22 C at its absolute humidity, so the
    relative humidity falls from 0.40-0.55 as the saturation pressure climbs (Magnus, inject_fresh19._magnus), and the
    strip's water follows Nafion's isotherm (inject_fresh10._lambda) through its sorption lag (tau_s 200-800 s, log,
    quickening with the warmth by Arrhenius, 20-40 kJ/mol). The gain as a share (0.5-0.9) of the water lost; the
    conductance with the water to the 1.5-2.5th power and with the warmth (Arrhenius, 10-15 kJ/mol: proton conduction in
    Nafion), so the current first rises with the warming and then falls behind the drying. The spectra at the next
    series' start (inject_fresh9._dry_by). Measured (s001_149) displacement RMS -1.8 % (residual 2.6 %, 81x its noise),
    current RMS -2.4 % (residual 3.2 %, 8.6x its noise)."""
    t_on = s.t0 + s.rng.uniform(0.1, 0.5) * (s.t1 - s.t0)
    dT, tau_T, T0 = s.rng.uniform(2.0, 5.0), lu(s.rng, 600.0, 1800.0), s.rng.uniform(19.0, 22.0)
    rh0, tau_s, e_s = s.rng.uniform(0.40, 0.55), lu(s.rng, 200.0, 800.0), s.rng.uniform(20e3, 40e3)
    share, gc, e_c = s.rng.uniform(0.5, 0.9), s.rng.uniform(1.5, 2.5), s.rng.uniform(10e3, 15e3)
    dt = 2.0
    tg = _session_grid(s, dt, 10.0)
    T = T0 + dT * np.where(tg > t_on, -np.expm1(-np.clip(tg - t_on, 0.0, None) / tau_T), 0.0)
    rh = rh0 * _magnus(T0) / _magnus(T)
    target = _lambda(rh)
    lam = np.empty(tg.size)
    x = float(target[0])
    inv = 1 / (T0 + 273.15)
    for k, (y, tk) in enumerate(zip(target.tolist(), T.tolist())):
        tau = tau_s * math.exp(-e_s / R_GAS * (inv - 1 / (tk + 273.15)))
        x = y + (x - y) * math.exp(-dt / tau)
        lam[k] = x
    rel = lam / lam[0]
    arr = np.exp(-e_c / R_GAS * (1 / (T + 273.15) - inv))
    _dry_by(s, lambda t: share * (1 - np.interp(t, tg, rel)), lambda t: 1 - np.interp(t, tg, rel ** gc * arr))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_offset_jaws_prebend(s: Session) -> None:
    """Jaws whose faces are offset along the strip's thickness (a worn clamp whose moving jaw has play in its guide):
    the squeeze bends the root over the offset, so the films just beyond the jaws start pre-bent, one face (drawn) in
    tension by e_p = e_top p/p_max (e_top 0.15-0.4 of the session's largest tension), the other in compression. The
    cracks of each face open beyond a closure e0 (0.25-0.5): the pre-tensioned face's for a smaller bend its way, the
    other's for a larger one, and the asymmetry grows with each tighter setting (each face k 0.8-1.5 per unit, the other
    0.5-1 of it). Gains fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R
    (inject_fresh3._resist). Measured (paper_148) displacement RMS -3.6 % (residual 4.0 %, 240x its noise), current RMS
    -0.23 % (residual 1.2 %, 0.87x its noise); the 1 V steps' plateaus at 8.36 mm in the first block, 8.25 mm in the
    last (8.83 mm clean)."""
    side, e_top, e0 = _sign(s), s.rng.uniform(0.15, 0.4), s.rng.uniform(0.25, 0.5)
    k, o = s.rng.uniform(0.8, 1.5), s.rng.uniform(0.5, 1.0)
    p_max = max(s.pressures())
    q = ref_disp(s) / (_largest(s) or ref_disp(s))

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        x = side * q * np.asarray(e)
        ep = e_top * float(r.entry["pressure_kPa"]) / p_max
        return k * (np.clip(x + ep - e0, 0.0, None) + o * np.clip(-x - ep - e0, 0.0, None))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_tweezer_scratch(s: Session) -> None:
    """A plating cracked all over but mildly (both faces' cracks opening beyond e0 0.3-0.5 of the session's largest
    tension, k0 0.3-0.6 per unit), and at one re-clamping after the first (drawn) the operator's tweezers score a line
    across one face (drawn) near the root while re-seating the strip: from that setting on, that face carries a notch
    whose thin ligament opens at a small tension e_s (0.02-0.1) and adds k_s (1.5-3) per unit of opening, saturating as
    the ligament tears through (tanh, at 0.3-0.6): a gauge that jumps at an event, on one face. Gains fall by 0.03-0.08
    (displacement) and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (p19_150) displacement RMS
    -0.72 % (residual 0.83 %, 21x its noise), current RMS -0.069 % (residual 0.44 %, 0.31x its noise)."""
    e0, k0 = s.rng.uniform(0.3, 0.5), s.rng.uniform(0.3, 0.6)
    _, t_sc = _later_setting(s)
    side, e_s, k_s, sat = _sign(s), s.rng.uniform(0.02, 0.1), s.rng.uniform(1.5, 3.0), s.rng.uniform(0.3, 0.6)
    q = ref_disp(s) / (_largest(s) or ref_disp(s))

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        x = q * np.asarray(e)
        base = k0 * (np.clip(x - e0, 0.0, None) + np.clip(-x - e0, 0.0, None))
        notch = k_s * sat * np.tanh(np.clip(side * x - e_s, 0.0, None) / sat)
        return base + np.where(r.cols["t_s"] >= t_sc, notch, 0.0)

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_collagen_plug(s: Session) -> None:
    """The strip tested as a medical actuator with its tip pushed a few millimetres into a plug of collagen (or fibrin)
    gel in the bath, a tissue phantom: a biopolymer network strain-stiffens (its fibres straighten), its restoring force
    on the tip following Fung's exponential law, k (exp(B |u|/D) - 1)/B; its linear part is one more spring the strip's
    static gain already holds, and its excess over it, (exp(B U) - 1 - B U)/B (U the tip's bend over the session's
    largest, B 2-5), holds the large bends back: the strip's free bend X reaches only U with X = U + g (exp(B U) - 1 - B
    U)/B, odd, g set so that the largest bend reads 0.8-0.95 of its free value. Quasi-static (the gel's viscosity left
    out), tabulated and interpolated (inject_fresh22._table_map); displacement only. Measured (p19_150) displacement RMS
    -8.5 % (residual 9.7 %, 240x its noise), the 1 V steps at 3.05 mm for 3.62 mm."""
    B, keep = s.rng.uniform(2.0, 5.0), s.rng.uniform(0.8, 0.95)
    D = _largest(s) or ref_disp(s)
    g = B * (1 - keep) / (math.exp(B * keep) - 1 - B * keep)
    U = np.linspace(0.0, 2.0, 4001)
    X = U + g * (np.exp(B * U) - 1 - B * U) / B

    def reading(d: np.ndarray) -> np.ndarray:
        return np.sign(d) * D * np.interp(np.abs(d) / D, X, U)

    _table_map(s, reading)


def ld_table_knee(s: Session) -> None:
    """A triangulation head whose controller's linearisation table the lab made itself over +-R_c only (its calibration
    stage's travel: 0.4-0.7 of the session's largest bend) and which the controller extrapolates beyond it with its last
    segments' slopes: the raw optics compress the far travel (the receiver's image moving less per millimetre away from
    the reference distance), so beyond +-R_c the reading climbs at s_+ and s_- (0.78-0.93 each, drawn for either side)
    of the true slope: a knee on either side, larger bends read short by different amounts. Tabulated and interpolated
    (inject_fresh22._table_map); displacement only. Measured (s001_149) displacement RMS -3.9 % (residual 4.8 %, 150x
    its noise), the 1 V steps at 4.35 mm for 4.70 mm."""
    D = _largest(s) or ref_disp(s)
    rc = s.rng.uniform(0.4, 0.7) * D
    sp, sm = s.rng.uniform(0.78, 0.93), s.rng.uniform(0.78, 0.93)

    def reading(d: np.ndarray) -> np.ndarray:
        return np.where(d > rc, rc + sp * (d - rc), np.where(d < -rc, -rc + sm * (d + rc), d))

    _table_map(s, reading)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_stepper_hold_current(s: Session) -> None:
    """A motorised clamp whose closed-loop stepper driver holds the lead screw with a current in proportion to the
    torque the held force needs (a 'load-adaptive' hold: 0.2 of its rating at no load, all of it at the session's
    highest setting), fed from a linear bench supply whose mains transformer sits beside the laser's cable and the
    current amplifier's input: the transformer's stray field follows its load, so the line's hum (50 or 60 Hz, 3rd
    0.1-0.3, 5th 0.03-0.1) on the displacement (3-10 um, log) and on the current (30-100 uA, log) at the highest setting
    steps up with each tighter setting, from each block's setting on (inject_fresh25._setting_of). Phase locked to the
    session clock. Measured (paper_148) displacement residual 0.082 % of its RMS (4.8x its noise), current residual 1.1
    % (0.80x its noise)."""
    f0 = _line_f(s)
    h3, h5 = s.rng.uniform(0.1, 0.3), s.rng.uniform(0.03, 0.1)
    amp = {"disp_m": lu(s.rng, 3e-6, 1e-5), "i_A": lu(s.rng, 3e-5, 1e-4)}
    ph = {col: s.rng.uniform(0, 2 * np.pi, 3) for col in amp}
    top = max(s.pressures())
    setting = _setting_of(s)
    blocks = sorted(((setting(p, a), p) for p, a in _by_pressure_start(s).items()))
    t_set = np.array([t for t, _ in blocks])
    load = np.array([0.2 + 0.8 * p / top for _, p in blocks])
    for r in s.series():
        t = r.cols["t_s"]
        k = np.clip(np.searchsorted(t_set, t, side="right") - 1, 0, None)
        level = np.where(t >= t_set[0], load[k], 0.2)
        w = 2 * np.pi * f0 * t
        for col, a in amp.items():
            p = ph[col]
            wave = np.sin(w + p[0]) + h3 * np.sin(3 * w + p[1]) + h5 * np.sin(5 * w + p[2])
            r.cols[col] = r.cols[col] + a * level * wave


def mp_cracked_shield(s: Session) -> None:
    """The laser's analogue cable with its shield's drain cracked at the DAQ's connector (a fatigued solder joint): the
    joint makes and breaks contact as the bench warms and vibrates, at random (a telegraph, each state lasting 30-300 s,
    log, drawn afresh each time), and while it is open the cable's unshielded length picks up the line's electric field
    (50 or 60 Hz, 3rd 0.2-0.4, 5-15 um, log), while it is closed only 0.05-0.15 of that leaks through. Hum on the
    displacement that switches between two levels at moments of its own. Phase locked to the session clock. Measured
    (s001_149) displacement residual 0.29 % of its RMS (9.0x its noise)."""
    f0 = _line_f(s)
    h3, a, leak = s.rng.uniform(0.2, 0.4), lu(s.rng, 5e-6, 1.5e-5), s.rng.uniform(0.05, 0.15)
    p1, p3 = s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi)
    edges, state, t = [], bool(s.rng.random() < 0.5), s.t0 - s.rng.uniform(0.0, 300.0)
    states = [state]
    while t < s.t1:
        t += lu(s.rng, 30.0, 300.0)
        edges.append(t)
        state = not state
        states.append(state)
    te, st = np.array(edges), np.array(states)
    for r in s.series():
        tt = r.cols["t_s"]
        open_ = st[np.searchsorted(te, tt, side="right")]
        w = 2 * np.pi * f0 * tt
        wave = np.sin(w + p1) + h3 * np.sin(3 * w + p3)
        r.cols["disp_m"] = r.cols["disp_m"] + a * np.where(open_, 1.0, leak) * wave


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_radiant_panel_bimorph(s: Session) -> None:
    """A strip in air under a ceiling radiant heating panel on its thermostat (a cycle of 300-900 s, heating over 30-60
    % of it): the strip, its two faces plated unevenly (as most are), bends as a bimorph with its temperature, which
    follows the panel's on and off through its own lag (the strip and the air about it, tau 20-60 s) by 1-3 K: a
    one-signed offset of the displacement (10-40 um, log, at the full swing; the side drawn) that rises and falls with
    the thermostat's cycle, independent of the drive and of the records. Displacement only. Measured (s001_149)
    displacement residual 0.54 % of its RMS (17x its noise)."""
    side, amp = _sign(s), lu(s.rng, 1e-5, 4e-5)
    period, duty, phase = s.rng.uniform(300.0, 900.0), s.rng.uniform(0.3, 0.6), s.rng.uniform(0.0, 1.0)
    tau = s.rng.uniform(20.0, 60.0)
    dt = 0.5
    tg = _session_grid(s, dt, 600.0)
    heat = (((tg / period + phase) % 1.0) < duty).astype(float)
    a = math.exp(-dt / tau)
    temp = np.empty(tg.size)
    x = duty
    for k, h in enumerate(heat.tolist()):
        x = h + (x - h) * a
        temp[k] = x
    lo, hi = float(np.min(temp)), float(np.max(temp))
    swing = (temp - lo) / max(hi - lo, 1e-12)
    for r in s.series():
        r.cols["disp_m"] = r.cols["disp_m"] + side * amp * np.interp(r.cols["t_s"], tg, swing)


def out_radio_music(s: Session) -> None:
    """A radio on the bench (the lab's music) beside a strip in air: the sound's pressure on the light strip drives it
    through its first mode (its resonance at the pressure from the preset's FRF, inject_fresh22._f1; the mode's damping
    0.02-0.08 in air), broadband forcing that the strip filters to a narrow ringing at its own frequency, its loudness
    following the music's phrases (a syllabic swell of 30-70 % at 1-4 Hz) and the songs (150-300 s each, a gap of 2-8 s
    between them); the radio on for 20-60 min (log) from a moment inside the session, off otherwise. 3-10 um RMS (log)
    at full loudness. Each record's noise filtered through the mode with 2 s of lead-in; displacement only. Measured
    (s001_149) displacement residual 0.16 % of its RMS (4.9x its noise)."""
    zeta, amp = s.rng.uniform(0.02, 0.08), lu(s.rng, 3e-6, 1e-5)
    depth, f_syl, ph = s.rng.uniform(0.3, 0.7), s.rng.uniform(1.0, 4.0), s.rng.uniform(0, 2 * np.pi)
    on = lu(s.rng, 1200.0, 3600.0)
    start = s.t0 + s.rng.uniform(0.0, max(s.t1 - s.t0 - on, 1.0))
    songs, t = [], start
    while t < start + on:
        d = s.rng.uniform(150.0, 300.0)
        songs.append((t, min(t + d, start + on)))
        t += d + s.rng.uniform(2.0, 8.0)
    cache: dict[float, float] = {}
    for r in _chrono(s):
        tt = r.cols["t_s"]
        env = np.zeros(tt.size)
        for a, b in songs:
            inside = (tt >= a) & (tt < b)
            env[inside] = np.minimum(1.0, np.minimum(tt[inside] - a, b - tt[inside]) / 2.0)
        if not env.any():
            continue
        env *= 1 + depth * np.sin(2 * np.pi * f_syl * tt + ph)
        w = 2 * math.pi * _f1(s, float(r.entry["pressure_kPa"]), cache)
        lead = int(2.0 * r.fs)
        noise = s.rng.normal(size=tt.size + lead)
        ring = lti(noise, r.fs, lambda z: w * w / (z * z + 2 * zeta * w * z + w * w))[lead:]
        ring /= float(np.std(ring)) or 1.0
        r.cols["disp_m"] = r.cols["disp_m"] + amp * env * ring


def out_plating_rectifier_ground(s: Session) -> None:
    """An electroplating line next door whose rectifier's DC return finds its way through the building's earth: while
    its tank runs (4-10 runs of 60-600 s, log, each starting at a moment inside the session, ramping up over 1-3 s) the
    rig's earth sits V_g (1.5-5 mV, log; each run 0.6-1.2 of it) away from the DAQ's, and the DAQ's single-ended inputs
    read it on every channel: the drive monitor V_g, the laser's analogue output V_g at its 2 mm/V, the current
    amplifier's V_g at its 10 mA/V (inject_fresh16's scales), while the drive amplifier, floating, keeps the strip's own
    drive as it was. Offsets on the three channels at once, switching on and off with the neighbour's work. Measured
    (paper_148) displacement residual 0.094 % of its RMS (5.6x its noise), current 0.50 % (0.38x), drive monitor 6.7x
    its noise; (p19_150) displacement 0.14 % (3.6x), current 0.23x, drive monitor 4.2x."""
    vg = lu(s.rng, 1.5e-3, 5e-3)
    runs = []
    for _ in range(int(s.rng.integers(4, 11))):
        a = s.rng.uniform(s.t0, s.t1)
        runs.append((a, a + lu(s.rng, 60.0, 600.0), s.rng.uniform(0.6, 1.2), s.rng.uniform(1.0, 3.0)))
    for r in s.series():
        t = r.cols["t_s"]
        off = np.zeros(t.size)
        for a, b, size, ramp in runs:
            off = np.maximum(off, size * np.clip((t - a) / ramp, 0.0, 1.0) * (t < b))
        if not off.any():
            continue
        off *= vg
        r.cols["v_V"] = r.cols["v_V"] + off
        r.cols["disp_m"] = r.cols["disp_m"] + LASER_M_PER_V * off
        r.cols["i_A"] = r.cols["i_A"] + CURRENT_A_PER_V * off


def out_swirl_spindown(s: Session) -> None:
    """The bath set swirling by every touch: at each re-clamping (the operator's hand and tools in the water, at the
    setting, inject_fresh25._setting_of) and 1-3 more times (re-aiming the laser, dipping a thermometer) the water is
    set rotating one way or the other (drawn each time) at U_0 (each 0.6-1.2 of the session's), and the swirl spins down
    (1/(1 + u/tau), tau 30-120 s, log, a turbulent spin-down). The swirl's drag on the strip goes as its speed squared:
    a one-way offset of the tip (A 10-40 um, log, at U_0) fading after each touch, with the swirl's turbulence on it (an
    Ornstein-Uhlenbeck wander of 20-40 % of the offset, correlation 0.5-2 s). Quasi-static; displacement only. Measured
    (paper_148) displacement residual 0.063 % of its RMS (3.7x its noise); (p19_150) 0.58 % (14x)."""
    A, tau, turb, corr = lu(s.rng, 1e-5, 4e-5), lu(s.rng, 30.0, 120.0), s.rng.uniform(0.2, 0.4), s.rng.uniform(0.5, 2.0)
    setting = _setting_of(s)
    touches = [setting(p, a) for p, a in _by_pressure_start(s).items()]
    touches += [s.rng.uniform(s.t0, s.t1) for _ in range(int(s.rng.integers(1, 4)))]
    events = [(t, _sign(s) * s.rng.uniform(0.6, 1.2)) for t in sorted(touches)]
    for r in s.series():
        t = r.cols["t_s"]
        u = np.zeros(t.size)
        for a, size in events:
            u = np.where(t >= a, size / (1 + np.clip(t - a, 0.0, None) / tau), u)  # the latest touch's swirl
        if not u.any():
            continue
        dt = 1.0 / r.fs
        alpha = math.exp(-dt / corr)
        w = np.empty(t.size)
        x = s.rng.normal()
        kicks = s.rng.normal(size=t.size) * math.sqrt(1 - alpha * alpha)
        for k in range(t.size):
            x = alpha * x + kicks[k]
            w[k] = x
        r.cols["disp_m"] = r.cols["disp_m"] + A * u * np.abs(u) * (1 + turb * w)


FRESH26_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"shear_thinning_pores": br_shear_thinning_pores, "residual_pt_salt": br_residual_pt_salt},
    "faradaic_current": {"chlorinated_tap": far_chlorinated_tap, "porous_tafel_doubling": far_porous_tafel_doubling},
    "hysteresis": {"lodged_flake": hy_lodged_flake, "sheath_capstan": hy_sheath_capstan},
    "time_delay": {"usb_suspend": td_usb_suspend, "y5v_warming_filter": td_y5v_warming_filter},
    "sensor_offset": {"shaker_ratchet": so_shaker_ratchet, "bleeding_ink_dot": so_bleeding_ink_dot},
    "clamp_relaxation": {"foam_cell_collapse": cr_foam_cell_collapse,
                         "moment_assisted_creep": cr_moment_assisted_creep},
    "dehydration": {"heat_gun_splash": dh_heat_gun_splash, "morning_heating": dh_morning_heating},
    "strain_resistance": {"offset_jaws_prebend": sr_offset_jaws_prebend, "tweezer_scratch": sr_tweezer_scratch},
    "large_deflection": {"collagen_plug": ld_collagen_plug, "table_knee": ld_table_knee},
    "mains_pickup": {"stepper_hold_current": mp_stepper_hold_current, "cracked_shield": mp_cracked_shield},
    "unexplained": {"radiant_panel_bimorph": out_radiant_panel_bimorph, "radio_music": out_radio_music,
                    "plating_rectifier_ground": out_plating_rectifier_ground, "swirl_spindown": out_swirl_spindown},
}
inject.register_forms(FRESH26_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_reversed_laser(s: Session) -> None:
    """A lab whose laser head faces the strip's other face (the only side its stand could reach), its controller
    reporting the distance change towards the head as positive: every time series' displacement written with the
    opposite sign (a positive drive bends the strip away from the head: the steps read negative). The drive, the
    current, the load cell, the spectra, the rows and the manifest as they were. The import contract says nothing of
    the displacement's sign; ``labrig import`` takes it."""
    for r in s.series():
        r.cols["disp_m"] = -r.cols["disp_m"]


inject.VARIANTS.update({"reversed_laser": v_reversed_laser})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_148", "s001_149", "p19_150"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 6 / 7 / 7 effect cases on seeds 148-150
    "back_relaxation": [("shear_thinning_pores", 148, P, "log_steps"), ("residual_pt_salt", 150, T, "stop_trigger")],
    "faradaic_current": [("chlorinated_tap", 150, T, "eis_descending"),
                         ("porous_tafel_doubling", 148, P, "short_pretrigger")],
    "hysteresis": [("lodged_flake", 149, S, "scan_hold"), ("sheath_capstan", 150, T, "swinging_door")],
    "time_delay": [("usb_suspend", 148, P, "float32_time"), ("y5v_warming_filter", 149, S, "settled_sines")],
    "sensor_offset": [("shaker_ratchet", 150, T, "tared_records"), ("bleeding_ink_dot", 149, S, "rate07")],
    "clamp_relaxation": [("foam_cell_collapse", 148, P, "merged_loadcell"),
                         ("moment_assisted_creep", 150, T, "measured_pressures")],
    "dehydration": [("heat_gun_splash", 149, S, "split_spectra"), ("morning_heating", 149, S, "steps_sines")],
    "strain_resistance": [("offset_jaws_prebend", 148, P, "fixed_decimals"),
                          ("tweezer_scratch", 150, T, "dropped_packets")],
    "large_deflection": [("collagen_plug", 150, T, "fir_decimated"), ("table_knee", 149, S, "coherent_sines")],
    "mains_pickup": [("stepper_hold_current", 148, P, "reversed_laser"), ("cracked_shield", 149, S, "own_clock")],
    "unexplained": [("radiant_panel_bimorph", 149, S, "loadcell_dropout"),
                    ("radiant_panel_bimorph", 149, S, "host_timed"),
                    ("radio_music", 149, S, "cycle_averaged"), ("radio_music", 149, S, "trigger_clock"),
                    ("plating_rectifier_ground", 148, P, "no_loadcell"),
                    ("plating_rectifier_ground", 150, T, "reversed_laser"),
                    ("swirl_spindown", 148, P, "shortened_shuffled"), ("swirl_spindown", 150, T, "decimated3")],
}
CLEAN = [(148, P, "reversed_laser"), (148, P, "two_pressures"), (149, S, "reversed_laser"), (149, S, "no_spectra"),
         (150, T, "asrun"), (150, T, "spectra_last")]


def fresh26_cases(only: str | None = None) -> list[Case]:
    """The twenty-seventh held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    148-150)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh26_cases, "inject_fresh26", "fresh26")
