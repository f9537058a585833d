"""A twenty-fifth held-out set for the diagnosis (issue 12), fresh24, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh23.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (the back-flow's re-entry through a
saturable step, hydrogen evolution in a phosphate buffer with the buffer's pre-wave before water's, a fork guide whose
friction grows with the strip's twist, a tip dragging on the cuvette's floor until the bend lifts it, a programmable
amplifier whose filter narrows on the ranges the small records use, a spot tracker that pulls in as the tip tilts,
electrowetting drawing the surface water into the tensioned face's cracks, a differential capacitive probe, the strip
mounted upright under its own weight), some on the history, the clamp pressure or the session's events (stainless jaws
scratched at every re-clamping and repassivating, electrolysis gas trapped in the clamp's crevice, palladium hydride
closing the cathode's cracks, a laser on a leaking suction cup re-pressed at every re-clamping), some on time (the
glue under the pads still curing, a salt crust's brine drying out as the room dries, a dehumidifier cycling on its
hygrostat, a solar inverter's output under passing clouds), two linear but neither a lag nor a spread of lags (the
back-flow's flux relaxing to Fick's law as a telegraph equation; a logging script's two-tap hum canceller) and some
from the lab's wiring or sensors (the mains monitor's ghost in the next multiplexed channel, the amplifier ranges, the
tracker, the probes). Four structures outside the catalogue (truth "unexplained": the impedance analyser's idle test
signal leaking through the switch box and aliased by each record's rate, the cuvette's plastic charged at each
re-clamping pulling a strip in air, a pneumatic table's levelling valve hunting, popcorn noise in the current
amplifier); clean sessions. All on three bases of new seeds (142-144: the paper strip, the seed-001 strip on its own
sweep, the paper strip 44 mm free) and on the earlier sets' protocol / data-shape variants plus one new here: each
impedance spectrum measured by two instruments, a potentiostat's analyser below a split frequency and an impedance
analyser above it, each exported as its own file and listed as its own record (``split_spectra``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh23 are reused (importing inject_fresh23 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh24.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy.signal import lfilter, lfilter_zi

import inject
import inject_fresh23  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _through
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law
from inject_fresh9 import _dry_by, _session_grid
from inject_fresh10 import _lambda, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh16 import LASER_M_PER_V
from inject_fresh22 import _grid_lag, _table_map
from inject_fresh23 import _settings

# the paper's strip 44 mm free (earlier sets used 20, 22-29, 31-43 and 45 mm, and 30 mm is the paper preset itself;
# its 1 V step peaks near 18.3 mm, 17.5 mm at 43 mm x (44/43)^2, inside the laser's +-20 mm): preset "paper_44", base
# "p44_144", registered in every process importing this module
inject.register_free_length("paper_44", 0.044)

inject.BASES.update({
    "paper_142": ("paper-sweep", "paper", 142),
    "s001_143": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 143),
    "p44_144": ("paper-sweep", "paper_44", 144),
})

N_CHANNELS = 5  # the DAQ's scan list: drive monitor, current, mains monitor, laser, load cell


# ------------------------------------------------------------------------------------------------ tools


def _lag(x: np.ndarray, fs: float, tau: float) -> np.ndarray:
    """A first-order lag of x (time constant tau) at the record's rate, started settled on its first value."""
    a = math.exp(-1.0 / (fs * tau))
    b, den = [1 - a], [1.0, -a]
    return lfilter(b, den, x, zi=lfilter_zi(b, den) * x[0])[0]


def _friction_play(u: np.ndarray, y: float, radius: Callable[[float], float]) -> tuple[np.ndarray, float]:
    """A dry-friction element whose radius depends on where it sticks: y_k = clip(y_(k-1), u_k - r(y_(k-1)),
    u_k + r(y_(k-1))), sample by sample. Returns the positions and the last one."""
    out = np.empty(u.size)
    for k, uk in enumerate(u.tolist()):
        r = radius(y)
        y = min(max(y, uk - r), uk + r)
        out[k] = y
    return out, y


def _by_pressure_start(s: Session) -> dict[float, float]:
    """Each pressure's first sample (its block's start)."""
    out: dict[float, float] = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        out[p] = min(out.get(p, np.inf), float(r.cols["t_s"][0]))
    return out


# ------------------------------------------------------------------------------------------------ back relaxation


def br_telegraph_flux(s: Session) -> None:
    """The back-flow through a membrane whose polymer relaxes on the diffusion's own time scale (a strip stored dry
    and re-soaked, or a recast film annealed below its glass transition): the water flux does not follow Fick's law
    at once but relaxes to it with the chains' relaxation time tau_r (Cattaneo's flux law, the viscoelastic
    diffusion of Cohen and of Kalospiros and Astarita: tau_r dJ/dt + J = -D dc/dx), so the water obeys the damped
    wave (telegraph) equation tau_r c'' + c' = D c_xx. The opposing swelling is the slab's uptake through it, K2
    tanh(q)/q with q = sqrt(s tau_d (1 + s tau_r)) (K2 0.8-1.2, tau_d = l^2/D 3-15 s, log, tau_r 0.05-0.3 of it,
    log): the give-back starts late and steeply (the front travels at sqrt(D/tau_r)), and past tau_r/tau_d = 1/pi^2
    its slowest mode rings, an uptake overshoot (the sorption overshoot of glassy polymers). Fickian diffusion
    (inject's diffusion form) is its tau_r -> 0 limit. Through inject_fresh2._through with 120 s of the session's
    history; displacement only. Measured (p44_144) displacement RMS -74 % (residual 87 %, 11000x its noise), the 1 V
    steps (18.3 mm clean) peaking at 4.6 mm after 5.7 s and falling to 3.0 mm by the plateaus' end, the 0.5 V sines'
    gain at 0.1 Hz 0.93 of their clean one."""
    k2, td = s.rng.uniform(0.8, 1.2), lu(s.rng, 3.0, 15.0)
    tr = td * lu(s.rng, 0.05, 0.3)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        def h(z: np.ndarray) -> np.ndarray:
            q = np.sqrt(td * np.asarray(z, complex) * (1 + tr * np.asarray(z, complex)))
            small = np.abs(q) < 1e-8
            qs = np.where(small, 1.0, q)
            e = np.exp(-2 * qs)
            return 1 - k2 * np.where(small, 1 - q * q / 3, (1 - e) / (1 + e) / qs)

        return h

    new = _through(s, H, 120.0)
    map_disp(s, lambda r, d: new[id(r)])


def _saturable(d: np.ndarray, fs: float, x: float, V: float, K: float) -> tuple[np.ndarray, float]:
    """The store x following d through dx/dt = V (d - x)/(K + |d - x|), sample by sample (exact for the linear part
    when |d - x| << K, the rate capped at V when it is >> K)."""
    dt = 1.0 / fs
    out = np.empty(d.size)
    for k, dk in enumerate(d.tolist()):
        g = dk - x
        x += g * (1 - math.exp(-dt * V / (K + abs(g))))
        out[k] = x
    return out, x


def br_saturable_uptake(s: Session) -> None:
    """The water the bend pushed to the cathode side returns only as the anode side's ion clusters take it up, and
    that uptake passes a saturable step (the hydrated cations re-dissociating from their sulfonates to take their
    water back, a site-limited exchange like a carrier's): the store x of returned water follows the bend with the
    Michaelis-Menten rate dx/dt = V (d - x)/(K + |d - x|) (K 0.02-0.08 of the session's largest bend, the
    small-signal time K/V 2-10 s, log), so small bends relax exponentially at K/V and large ones at the capped rate
    V, a straight line in time that lasts in proportion to the bend: the larger the bend, the slower its relative
    give-back. The opposing swelling K2 x (K2 0.8-1.2). Sample by sample through the session in time order (over the
    rests the store follows a bend at rest, sub-stepped at 0.05 s); displacement only. Measured (paper_142)
    displacement RMS -48 % (residual 63 %, 3800x its noise), the 1 V steps (8.8 mm clean) held near 4.3 mm from 20 s
    on, the 0.5 V sines' gain at 0.1 Hz 0.97 of their clean one."""
    big = _largest(s) or ref_disp(s)
    k2, K = s.rng.uniform(0.8, 1.2), s.rng.uniform(0.02, 0.08) * big
    V = K / lu(s.rng, 2.0, 10.0)
    x, t_end = 0.0, None
    for r in _chrono(s):
        t = r.cols["t_s"]
        if t_end is not None:
            gap = max(float(t[0]) - t_end, 0.0)
            n = int(math.ceil(gap / 0.05))
            if n:
                _, x = _saturable(np.zeros(n), n / gap, x, V, K)
        y, x = _saturable(r.cols["disp_m"], r.fs, x, V, K)
        r.cols["disp_m"] = r.cols["disp_m"] - k2 * y
        t_end = float(t[-1])


# ------------------------------------------------------------------------------------------------ faradaic current


def far_scratch_repassivation(s: Session) -> None:
    """The clamp's contacts are the bare stainless-steel jaws, wetted by the bath: at every re-clamping the jaw on
    one face (drawn) is dragged over the strip's plating and its passive film is scratched where the water reaches
    it, and that bare steel, at its face's potential, passes an anodic dissolution current to the other face through
    the bath whenever its face is the anode (Tafel-like, (exp(x/b) - 1)/(exp(1/b) - 1) of the drive's share x, b
    0.08-0.15 V; 0.2-1 mA at 1 V on the fresh scratch, log), while the scratch repassivates: its active area falls
    as (1 + u/tau_p)^-n (tau_p 20-120 s, log, n 0.6-1, u the time since the setting; the classic
    scratch-repassivation transient). Nothing when the face is the cathode. A current that appears at each
    re-clamping on one polarity and dies away over the block's first records. Each block's setting 10-40 s before
    its first record (inject_fresh23._settings); the current only. Measured (p44_144) current RMS +0.083 % (residual
    0.50 %, 0.40x its noise): the jaw on the face the negative drive makes the anode, 0.17-0.23 mA at the crests of
    each block's 1 V harmonic (its first record on that polarity), 3 uA or less by the slow sines."""
    side, i1, b = _sign(s), lu(s.rng, 2e-4, 1e-3), s.rng.uniform(0.08, 0.15)
    tau_p, n = lu(s.rng, 20.0, 120.0), s.rng.uniform(0.6, 1.0)
    t_set, first = _settings(s), _by_pressure_start(s)
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        u = np.clip(r.cols["t_s"] - t_set.get(p, first[p] - 20.0), 0.0, None)
        x = side * r.cols["v_V"]
        law = np.where(x > 0, np.expm1(np.clip(x, 0.0, None) / b) / math.expm1(1 / b), 0.0)
        r.cols["i_A"] = r.cols["i_A"] + side * i1 * (1 + u / tau_p) ** -n * law


def far_phosphate_prewave(s: Session) -> None:
    """A strip tested in phosphate-buffered saline (PBS, the medium of bio-IPMC work): at whichever face is the
    cathode the buffer's weak acid (H2PO4-) gives up its proton at a lower overpotential than water, a wave that
    rises at E_b (0.45-0.7 V of drive, width w 0.03-0.06 V) to a plateau set by the acid's diffusion (i_b 0.04-0.15
    mA, log), and only beyond it does water's own reduction grow exponentially (0.02-0.1 mA at 1 V, log, b_w
    0.08-0.15 V): the two-wave polarisation curve of hydrogen evolution in buffered neutral media, the anode's
    oxygen in series taken into the waves' positions. Odd in the drive (either face the cathode), memoryless. The
    current only. Measured (paper_142) current RMS +0.39 % (residual 1.7 %, 1.3x its noise), +0.12 mA on the 1 V
    steps' plateaus."""
    e_b, w, i_b = s.rng.uniform(0.45, 0.7), s.rng.uniform(0.03, 0.06), lu(s.rng, 4e-5, 1.5e-4)
    i_w, b_w = lu(s.rng, 2e-5, 1e-4), s.rng.uniform(0.08, 0.15)
    for r in s.series():
        v = r.cols["v_V"]
        a = np.abs(v)
        wave = i_b / (1 + np.exp(-(a - e_b) / w)) - i_b / (1 + math.exp(e_b / w))
        r.cols["i_A"] = r.cols["i_A"] + np.sign(v) * (wave + i_w * np.expm1(a / b_w) / math.expm1(1 / b_w))


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_twist_guide(s: Session) -> None:
    """The tip runs in the slot of a PTFE fork (a guide the lab fits to keep a long strip from swinging sideways out
    of the laser's spot), its faces clear of the tines; but the strip twists as it bends (its plating uneven across
    the width), so its edges press on the slot's walls with a force that grows with the bend, and Coulomb friction
    on them grows with it: the tip sticks while the strip's pull stays within c |y| of where it is (c 0.03-0.08, the
    friction over the strip's stiffness per unit of twist), a play whose radius is proportional to the bend. Loading
    reads y = u/(1 + c), unloading sticks and then follows u/(1 - c): lens-shaped loops pinched at rest,
    self-similar, their area as the swing squared, the same at any rate and any amplitude in proportion (a constant
    loss factor, Kimball and Lovell's solid friction). Quasi-static, sample by sample through the session in time
    order; displacement only. Measured (s001_143) displacement RMS -1.7 % (residual 7.2 %, 240x its noise), the 1 V
    steps' plateaus at 4.37 mm (4.69 mm clean)."""
    c = s.rng.uniform(0.03, 0.08)
    y = 0.0
    for r in _chrono(s):
        r.cols["disp_m"], y = _friction_play(r.cols["disp_m"], y, lambda q: c * abs(q))


def hy_floor_drag(s: Session) -> None:
    """The strip hangs a little too low in its cuvette, its tip resting on the floor and pressed on it by the
    strip's own slight bow (a preload): the tip drags on the glass with Coulomb friction, sticking while the strip's
    pull stays within r of where it is, r0 at rest 0.02-0.06 of the session's largest bend; but the bent strip's tip
    rises (the arc's draw-up 2 d^2/3L), unloading the floor as 1 - (y/d_off)^2, and lifts off beyond d_off (0.3-0.6
    of the largest bend): a play whose radius shrinks with the bend and vanishes beyond the lift-off. Small sines
    stick and slip in wide loops, the large bends run free, and after each record the tip stays where the floor held
    it, off its rest. Quasi-static, sample by sample through the session in time order (the tip held over the
    rests); displacement only. Measured (p44_144) displacement RMS -0.35 % (residual 6.7 %, 840x its noise), the 1 V
    steps' plateaus untouched (lifted off)."""
    big = _largest(s) or ref_disp(s)
    r0, d_off = s.rng.uniform(0.02, 0.06) * big, s.rng.uniform(0.3, 0.6) * big
    y = 0.0
    for r in _chrono(s):
        r.cols["disp_m"], y = _friction_play(r.cols["disp_m"], y, lambda q: r0 * max(1 - (q / d_off) ** 2, 0.0))


# ------------------------------------------------------------------------------------------------ time delay


PGA_GAINS = (1, 2, 5, 10)


def _pga_gain(peak: float, volts_per_m: float) -> int:
    """The largest gain that keeps a record's peak (with 20 % to spare) within the ADC's +-10 V."""
    ok = [g for g in PGA_GAINS if g * volts_per_m * peak * 1.2 <= 10.0]
    return max(ok) if ok else 1


def td_pga_bandwidth(s: Session) -> None:
    """The laser's analogue output through a programmable-gain conditioning amplifier whose script picks the gain
    record by record (1, 2, 5 or 10: the largest that keeps the record's peak, with 20 % to spare, within the ADC's
    +-10 V; the laser's scale set so that the session's largest bend just fits at gain 1, 0.6-1 of it), each range
    with its own output filter, narrowed in proportion to the gain to keep the amplified noise down (a first-order
    corner at f_1/G, f_1 100-300 Hz, log): the 1 V steps on gain 1 late by a millisecond, the small fast sines on
    gain 10 by 5-16 ms. A lag that steps with each record's size, not with its frequency. Through
    inject_fresh2._through (1 s of the session's history through the record's own filter); displacement only.
    Measured (paper_142) displacement residual 0.15 % of its RMS (8.7x its noise), the 20 Hz records' residuals
    32-44 %, the 0.1 Hz sines' 0.44 %."""
    big = _largest(s) or ref_disp(s)
    vpm = 10.0 / (1.2 * big) * s.rng.uniform(0.6, 1.0)
    f1 = lu(s.rng, 100.0, 300.0)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        tau = _pga_gain(float(np.max(np.abs(r.cols["disp_m"]))), vpm) / (2 * math.pi * f1)
        return lambda z: 1 / (1 + tau * np.asarray(z))

    new = _through(s, H, 1.0)
    map_disp(s, lambda r, d: new[id(r)])


def td_hum_canceller(s: Session) -> None:
    """The lab's logging script cancels mains hum on the laser's channel by averaging each reading with the one taken
    half a line period earlier (a two-tap comb: the line's fundamental and odd harmonics cancel, sin(wt) + sin(w(t -
    T/2)) = 0), the half period D = 1/2f taken from the bench's line-frequency meter (the grid 50 or 60 Hz, off
    nominal by up to 0.02 Hz) and the reading D earlier interpolated linearly between the record's samples (D fs 1.7
    to 10 samples here): y = (x(t) + x(t - D))/2, a linear filter that is no lag: a pure group delay of D/2 (4-5 ms)
    with the comb's gain cos(pi f D), 0.81 at 20 Hz on a 50 Hz grid (the interpolation leaving 0.19 of a 60 Hz line
    on a 200 Hz record). Through inject_fresh2._through (1 s of the session's history); displacement only. Measured (s001_143)
    displacement residual 0.19 % of its RMS (6.2x its noise), the 20 Hz records' residuals 59 %."""
    delay = 1 / (2 * _line_f(s))

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        m, mu = divmod(delay * r.fs, 1.0)

        def h(z: np.ndarray) -> np.ndarray:
            e = np.exp(-np.asarray(z) / r.fs)
            return (1 + e**m * ((1 - mu) + mu * e)) / 2

        return h

    new = _through(s, H, 1.0)
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ sensor offset


def so_edge_tracker(s: Session) -> None:
    """A tracking laser (a galvo-steered triangulation spot) whose controller locks the spot onto the strip's end:
    it finds the end where the return falls to half its level and holds the spot a margin m0 (0.1-0.3 mm) inside it;
    but the tilted end returns less light (the plated face's lobe turning away, as cos^k of the tip's angle), so at
    a bend the half-level point moves inboard and the tracker pulls the spot in with it, by m1 (0.2-0.8 mm) at the
    session's largest bend, as the tip's angle squared, through the tracker's servo lag (20-100 ms, log). The
    station follows the bend's square: none at rest, most on the steps' plateaus. The strip read at the moving
    station (inject_fresh10._station); displacement only. Measured (paper_142) displacement RMS -3.6 % (residual
    3.7 %, 220x its noise)."""
    L, big = float(s.specimen["length_m"]), _largest(s) or ref_disp(s)
    m0, m1, tau = s.rng.uniform(1e-4, 3e-4), s.rng.uniform(2e-4, 8e-4), lu(s.rng, 0.02, 0.1)
    frac = {id(r): 1 - (m0 + m1 * (_lag(r.cols["disp_m"], r.fs, tau) / big) ** 2) / L for r in s.series()}
    _station(s, lambda r: frac[id(r)], 1 - (m0 + m1) / L)


def so_suction_mount(s: Session) -> None:
    """The laser head on a suction-cup mount stuck to the cuvette's stand's glass shelf, re-pressed by the operator
    and re-aimed at the re-clamping (2-8 s after each setting), a margin m0 (0.1-0.3 mm) inside the tip's end: the
    cup's vacuum leaks past its rim (tau 600-3000 s, log), and its rubber rim creeps under the head's weight at a
    rate inverse to the suction left, v0 exp(u/tau), so the head droops and the spot walks inboard faster and
    faster, by 0.2-0.6 mm at the longest block's end, until the next re-aim: an accelerating walk within each block.
    The strip read at the moving station (inject_fresh10._station); displacement only. Measured (p44_144)
    displacement RMS -1.2 % (residual 1.2 %, 150x its noise)."""
    L = float(s.specimen["length_m"])
    m0, tau, walk = s.rng.uniform(1e-4, 3e-4), lu(s.rng, 600.0, 3000.0), s.rng.uniform(2e-4, 6e-4)
    t_set, first = _settings(s), _by_pressure_start(s)
    aims = sorted((t_set.get(p, a - 20.0) + s.rng.uniform(2.0, 8.0), p) for p, a in first.items())
    ends = [a for a, _ in aims[1:]] + [s.t1]
    longest = max(e - a for (a, _), e in zip(aims, ends))
    v0 = walk / (tau * math.expm1(longest / tau))
    aim_of = {p: a for a, p in aims}

    def margin(r: Rec) -> np.ndarray:
        u = np.clip(r.cols["t_s"] - aim_of[float(r.entry["pressure_kPa"])], 0.0, None)
        return m0 + v0 * tau * np.expm1(u / tau)

    _station(s, lambda r: 1 - margin(r) / L, 1 - (m0 + walk) / L)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_curing_glue(s: Session) -> None:
    """Pads re-glued to the jaws with a two-part epoxy that morning, 600-2400 s before the first setting, and still
    curing under the clamp's fixed gap: epoxy shrinks as it cures (1-3 % of its layer), its conversion
    autocatalytic, a sigmoid in time (its half-cure 1800-5400 s after mixing, log, width 0.2-0.4 of that), so the
    gap the pads fill opens by the same micrometres whatever the setting: the same newtons lost at every setting
    (1.5-5 N at full cure, log) since each re-clamping restored the force, on top of the pads' logarithmic creep
    from each setting (0.5-1.5 % a decade, tau 2-20 s, log). A loss that quickens and then slows again through the
    session, biggest in share at the light settings. Through the preset's clamp law (inject_fresh4._clamp_law), the
    load cell showing it. Measured (s001_143) displacement RMS -0.0048 % (residual 0.0085 %, 0.28x its noise),
    current RMS +0.053 % (residual 0.13 %, 0.34x its noise), the load cell at 0.953-0.996 of its reading."""
    area = float(s.specimen["clamp_area_m2"])
    r_c, tau_c, dF = s.rng.uniform(0.005, 0.015), lu(s.rng, 2.0, 20.0), lu(s.rng, 1.5, 5.0)
    t_set = _settings(s)
    t_mix = min(t_set.values(), default=s.t0) - s.rng.uniform(600.0, 2400.0)
    half = lu(s.rng, 1800.0, 5400.0)
    width = half * s.rng.uniform(0.2, 0.4)

    def cure(t: np.ndarray) -> np.ndarray:
        return 1 / (1 + np.exp(-(np.asarray(t, float) - t_mix - half) / width))

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        ts = t_set.get(p, t_first - 20.0)
        u = np.clip(np.asarray(t, float) - ts, 0, None)
        return 1 - r_c * np.log10(1 + u / tau_c) - dF * (cure(t) - cure(np.array([ts]))[0]) / (p * 1e3 * area)

    _clamp_law(s, rel)


def cr_crevice_gas(s: Session) -> None:
    """Screw jaws on rubber pads under a fixed gap, the strip's plating wet in the crevice between the pad and the
    jaw's contact: whenever the drive is beyond water splitting's onset (v_on 0.6-0.85 V: the 1 V steps' plateaus,
    the crests of the 1 V harmonics) the contact's electrolysis makes gas, in proportion to abs(v) - v_on, that the
    pads trap in the crevice, and the trapped gas pushes the jaws apart against the gap (a pocket's pressure over
    the contact's area), escaping along the pads over tau_e (100-600 s, log); each re-clamping opens the jaws and
    lets it all out. The force rises during each large drive by the same newtons at any setting (0.2-0.8 N after a
    30 s step at 1 V) and sinks over the rests, on top of the pads' logarithmic creep from each setting (1-2.5 % a
    decade, tau 2-20 s, log). Through the preset's clamp law (inject_fresh4._clamp_law), the load cell showing it.
    Measured (paper_142) displacement RMS +0.00039 % (residual 0.033 %, 1.9x its noise), current RMS -0.033 %
    (residual 0.15 %, 0.11x its noise), the load cell at 0.977-1.020 of its reading."""
    area = float(s.specimen["clamp_area_m2"])
    v_on, tau_e, dF = s.rng.uniform(0.6, 0.85), lu(s.rng, 100.0, 600.0), s.rng.uniform(0.2, 0.8)
    r_c, tau_c = s.rng.uniform(0.01, 0.025), lu(s.rng, 2.0, 20.0)
    t_set = _settings(s)
    g_ref = tau_e * -math.expm1(-30.0 / tau_e)  # the gas after 30 s at 1 V
    T, G, g, t_end, p_last = [], [], 0.0, None, None
    for r in _chrono(s):
        t, p = r.cols["t_s"], float(r.entry["pressure_kPa"])
        if p != p_last:
            g = 0.0  # the jaws opened at the re-clamping: the gas let out
        elif t_end is not None:
            g *= math.exp(-max(float(t[0]) - t_end, 0.0) / tau_e)
        a = math.exp(-1.0 / (r.fs * tau_e))
        src = np.clip(np.abs(r.cols["v_V"]) - v_on, 0.0, None) / (1 - v_on) / r.fs
        y, _ = lfilter([1.0], [1.0, -a], src, zi=[a * g])
        g, t_end, p_last = float(y[-1]), float(t[-1]), p
        T.append(t)
        G.append(y)
    T, G = np.concatenate(T), np.concatenate(G)

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        ts = t_set.get(p, t_first - 20.0)
        u = np.clip(np.asarray(t, float) - ts, 0, None)
        return 1 - r_c * np.log10(1 + u / tau_c) + dF * np.interp(t, T, G) / g_ref / (p * 1e3 * area)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_salt_efflorescence(s: Session) -> None:
    """A strip in air last stored in saline and blotted, a salt crust on its faces: while the room's humidity stays
    above the salt's efflorescence point (NaCl's 0.43-0.47 RH) the crust is a supersaturated brine film, an ionic
    path over the faces in parallel with the strip (0.1-0.3 of its conductance); the building's heating dries the
    room linearly from 0.55-0.65 RH through the session, crossing the efflorescence point 30-70 % into it, and the
    brine then crystallises and its film's conduction dies within 30-120 s (log), never to come back while the room
    stays below the deliquescence point (0.75). The membrane's water follows Nafion's isotherm
    (inject_fresh10._lambda) through its sorption lag (100-400 s, log). The gain as the water, the membrane's
    conductance as its 1.5-2.5th power, the film's share as it dies, relative to the first record; the spectra at
    the next series' start (inject_fresh9._dry_by). Measured (s001_143) displacement RMS -20 % (residual 25 %, 840x
    its noise), current RMS -45 % (residual 56 %, 150x its noise), the spectra's |Z| at 0.1 Hz +0, +50, +150, +240
    %."""
    erh, rh0, at = s.rng.uniform(0.43, 0.47), s.rng.uniform(0.55, 0.65), s.rng.uniform(0.3, 0.7)
    share, tau_f = s.rng.uniform(0.1, 0.3), lu(s.rng, 30.0, 120.0)
    tau_s, gc = lu(s.rng, 100.0, 400.0), s.rng.uniform(1.5, 2.5)
    t_e = s.t0 + at * (s.t1 - s.t0)
    tg = _session_grid(s, 1.0, 300.0)
    rh = np.clip(rh0 + (erh - rh0) * (tg - s.t0) / (t_e - s.t0), 0.05, 0.95)
    w = _grid_lag(tg, _lambda(rh), tau_s, float(_lambda(np.array([rh0]))[0]))
    film = np.where(tg < t_e, 1.0, np.exp(-np.clip(tg - t_e, 0, None) / tau_f))
    w0 = float(np.interp(s.t0, tg, w))
    cond = (1 - share) * (w / w0) ** gc + share * film
    c0 = float(np.interp(s.t0, tg, cond))
    _dry_by(s, lambda t: 1 - np.interp(t, tg, w) / w0, lambda t: 1 - np.interp(t, tg, cond) / c0)


def dh_hygrostat_dehumidifier(s: Session) -> None:
    """A strip in air in a closed enclosure whose humidity the operator brings down with a small desiccant
    dehumidifier switched on 0-30 % into the session, on its own hygrostat: running, it dries the box towards
    0.20-0.30 RH (tau 200-600 s, log) until the box reaches its cut-out (0.40-0.50, its cut-in at least 0.05 below
    the room), then rests while the room's moisture (0.55-0.70 RH) leaks back in (tau 600-2000 s, log) until the
    cut-in 0.05-0.10 higher: a relaxation oscillation between the two thresholds, quick down and slow up. The
    strip's water follows Nafion's isotherm (inject_fresh10._lambda) through its sorption lag (100-400 s, log): a
    fall to a sawtooth plateau. The gain as the water, the conductance as its 1.5-2.5th power, relative to the first
    record, the spectra at the next series' start (inject_fresh9._dry_by). Measured (s001_143) displacement RMS -25
    % (residual 31 %, 1000x its noise), current RMS -60 % (residual 64 %, 170x its noise), the spectra's |Z| at 0.1
    Hz +0, +200, +190, +200 %."""
    rh_r, rh_d, band = s.rng.uniform(0.55, 0.70), s.rng.uniform(0.20, 0.30), s.rng.uniform(0.05, 0.10)
    lo = s.rng.uniform(0.40, min(0.50, rh_r - band - 0.05))  # its cut-in below the room's humidity
    tau_on, tau_off = lu(s.rng, 200.0, 600.0), lu(s.rng, 600.0, 2000.0)
    t_on = s.t0 + s.rng.uniform(0.0, 0.3) * (s.t1 - s.t0)
    tau_s, gc = lu(s.rng, 100.0, 400.0), s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 1.0, 300.0)
    rh, x, running = np.empty(tg.size), rh_r, False
    a_on, a_off = math.exp(-1.0 / tau_on), math.exp(-1.0 / tau_off)
    for k, tk in enumerate(tg.tolist()):
        if tk >= t_on and not running and x >= lo + band:
            running = True
        elif running and x <= lo:
            running = False
        x = rh_d + (x - rh_d) * a_on if running else rh_r + (x - rh_r) * a_off
        rh[k] = x
    w = _grid_lag(tg, _lambda(rh), tau_s, float(_lambda(np.array([rh_r]))[0]))
    w0 = float(np.interp(s.t0, tg, w))
    _dry_by(s, lambda t: 1 - np.interp(t, tg, w) / w0, lambda t: 1 - (np.interp(t, tg, w) / w0) ** gc)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_electrowetted_cracks(s: Session) -> None:
    """A strip in air whose faces' plating is cracked (the face a positive bend stretches, drawn, and the other at
    0.2-0.5 of its gauge), its cracks opening beyond e0 (0.1-0.3 of the session's largest tension) and adding
    resistance with their opening; the surface water film stands at their mouths, and the drive's own potential
    across each face's double layer electrowets the crack walls (Lippmann: the interfacial tension falls as the
    square of the interface's potential off its zero-charge point, -0.15-0.15 V), drawing water into the open
    cracks, which then conduct ionically: a crack's added resistance falls by b (0.5-0.9) times u^2/(u^2 + v_ew^2)
    (u the face's half of the drive less its zero-charge potential, v_ew 0.3-0.6 V), the water creeping in and out
    through 0.1-1 s (log). The resistance follows the bend while the drive is low and is partly shorted while it is
    high: the 1 V steps' cracks bridged, the same bend at rest not. Gains fall by 0.03-0.08 (displacement) and
    0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (s001_143) displacement RMS -3.1 %
    (residual 3.2 %, 110x its noise), current RMS -0.39 % (residual 1.4 %, 3.6x its noise)."""
    side, o, e0 = _sign(s), s.rng.uniform(0.2, 0.5), s.rng.uniform(0.1, 0.3)
    k, b, v_ew = s.rng.uniform(0.5, 1.5), s.rng.uniform(0.5, 0.9), s.rng.uniform(0.3, 0.6)
    tau_w, e_pzc = lu(s.rng, 0.1, 1.0), s.rng.uniform(-0.15, 0.15)
    q = ref_disp(s) / (_largest(s) or ref_disp(s))

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        x, v = side * q * np.asarray(e), r.cols["v_V"]
        out = np.zeros(x.size)
        for g, sg, pot in ((1.0, 1.0, -1.0), (o, -1.0, 1.0)):  # the stretched-by-positive face is the cathode then
            u = pot * side * v / 2 - e_pzc
            wet = _lag(u * u / (u * u + v_ew * v_ew), r.fs, tau_w)
            out += g * k * np.clip(sg * x - e0, 0.0, None) * (1 - b * wet)
        return out

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_hydride_closed_cracks(s: Session) -> None:
    """A strip plated with palladium instead of platinum, its plating cracked: a bend opens the cracks of the face
    it stretches, and under a positive drive that face is the cathode (it swells, convex), where hydrogen goes into
    the palladium as its hydride beyond v_a (0.2-0.4 V), filling at a rate (|v| - v_a)/(1 - v_a) (1 - h)/tau_a
    (tau_a 2-10 s at 1 V, log) and leaving it when the face is the anode (h |v|/tau_d, tau_d 1-5 s, log) or slowly
    at rest (tau_r 60-300 s, log); the hydride expands the film (palladium's lattice swells by a few per cent),
    pressing its cracks shut against the bend's tension by eta (0.3-0.8 of the session's largest tension) at full
    loading. Each face's cracks open by its tension less eta h (k 1-2 per unit, the other face 0.2-0.5 of that): a
    held drive's cracks open at once and close as the hydride builds, a bend without drive (the back-flow's) opens
    them fully. Sample by sample through the session in time order. Gains fall by 0.03-0.08 (displacement) and
    0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (p44_144) displacement RMS -0.16 %
    (residual 0.24 %, 30x its noise), current RMS -0.024 % (residual 0.12 %, 0.10x its noise), the 1 V steps'
    plateaus at 18.19 mm (18.28 mm clean)."""
    side, o, k = _sign(s), s.rng.uniform(0.2, 0.5), s.rng.uniform(1.0, 2.0)
    eta, v_a = s.rng.uniform(0.3, 0.8), s.rng.uniform(0.2, 0.4)
    tau_a, tau_d, tau_r = lu(s.rng, 2.0, 10.0), lu(s.rng, 1.0, 5.0), lu(s.rng, 60.0, 300.0)
    ref = ref_disp(s)
    q = ref / (_largest(s) or ref)
    h, t_end, dr = [0.0, 0.0], None, {}
    for r in _chrono(s):
        x, v, t, dt = side * q * r.cols["disp_m"] / ref, side * r.cols["v_V"], r.cols["t_s"], 1.0 / r.fs
        if t_end is not None:
            h = [hf * math.exp(-max(float(t[0]) - t_end, 0.0) / tau_r) for hf in h]
        out = np.zeros(x.size)
        for f, (g, sg) in enumerate(((1.0, 1.0), (o, -1.0))):  # face f is the cathode when sg v > 0
            hf, hist = h[f], np.empty(x.size)
            for j, vj in enumerate((sg * v).tolist()):
                if vj > v_a:
                    hf += dt * (vj - v_a) / (1 - v_a) * (1 - hf) / tau_a
                elif vj < 0:
                    hf -= dt * hf * min(-vj / tau_d, 1.0 / dt)
                hf -= dt * hf / tau_r
                hist[j] = hf
            h[f] = hf
            out += g * k * np.clip(sg * x - eta * hist, 0.0, None)
        dr[id(r)], t_end = out, float(t[-1])
    _resist(s, lambda r, e: dr[id(r)], (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_differential_capacitor(s: Session) -> None:
    """No laser: a strip in air read by a differential capacitive probe, two guarded plates facing the two sides of
    an insulated foil tab at the tip (a copper foil on Kapton, so that the drive on the plating stays off the probe)
    at a gap g 2.5-5 times the session's largest bend, the tab 0-5 % of g off the middle (either side); the probe's
    charge amplifier, its plates excited in antiphase, puts out the difference of the two capacitances, C1 - C2 ~
    1/(g - y) - 1/(g + y) = 2y/(g^2 - y^2), not their ratio, and the lab calibrated it by its slope at rest. Odd
    (with a small even part from the off-centring), expanding: the large bends read long as 1/(1 - (y/g)^2).
    Tabulated and interpolated (inject_fresh22._table_map); displacement only. Measured (s001_143) displacement RMS
    +6.5 % (residual 7.1 %, 240x its noise), the 1 V steps' plateaus at 5.20 mm (4.69 mm clean)."""
    big = _largest(s) or ref_disp(s)
    g = s.rng.uniform(2.5, 5.0) * big
    off = s.rng.uniform(-0.05, 0.05) * g

    def reading(x: np.ndarray) -> np.ndarray:
        y = np.asarray(x, float) + off
        return 2 * y / (g * g - y * y)

    _table_map(s, reading)


def _upright_arc(u: np.ndarray, beta: float, n: int = 200) -> np.ndarray:
    """The tip's lateral position (over L) of a strip standing up from its clamp, bent by a uniform moment (u = its
    tip angle without a load) and by its own weight beta (q L^3/EI) above each section: theta'(s) = u + beta int_s^1
    (y(s') - y(s)) ds', y' = sin theta, by fixed-point iteration from the unloaded arc on n steps (trapezoids)."""
    u = np.asarray(u, float)[:, None]
    sg = np.linspace(0.0, 1.0, n + 1)[None, :]
    h = 1.0 / n
    y = np.where(np.abs(u) < 1e-12, u * sg * sg / 2, (1 - np.cos(u * sg)) / np.where(np.abs(u) < 1e-12, 1.0, u))
    for _ in range(200):
        area = np.concatenate([np.zeros((u.shape[0], 1)), np.cumsum((y[:, 1:] + y[:, :-1]) * h / 2, axis=1)], axis=1)
        above = area[:, -1:] - area - y * (1 - sg)
        kap = u + beta * above
        th = np.concatenate([np.zeros((u.shape[0], 1)), np.cumsum((kap[:, 1:] + kap[:, :-1]) * h / 2, axis=1)], axis=1)
        sn = np.sin(th)
        new = np.concatenate([np.zeros((u.shape[0], 1)), np.cumsum((sn[:, 1:] + sn[:, :-1]) * h / 2, axis=1)], axis=1)
        done = float(np.max(np.abs(new - y))) < 1e-14
        y = new
        if done:
            break
    return y[:, -1]


def ld_upright_self_weight(s: Session) -> None:
    """The strip mounted upright, its clamp below and its tip up (a lab whose fixture stands on the bath's floor):
    its weight less the water's buoyancy (beta = q L^3/EI 0.2-0.7, a tenth of the heavy column's buckling load 7.84
    or less) presses down along it, and on the bent strip the weight above each section acts at its lateral offset,
    a moment that adds to the bend: theta'(s) = u + beta int_s^1 (y(s') - y(s)) ds', y' = sin theta, u the tip's
    angle the drive alone would give (2 d/L). Its linear part amplifies every bend alike (taken as the fitted
    stiffness: slope 1 at rest); as the bent strip's lateral positions fall behind the linear ones, the weight's
    lever does too, and the large bends read short on both sides: a stiffening odd law, the inverted pendulum's
    against the hanging bead's (inject_fresh23). Tabulated and interpolated (inject_fresh22._table_map);
    displacement only. Measured (p44_144) displacement RMS -0.36 % (residual 0.40 %, 50x its noise), the 1 V steps'
    plateaus at 18.16 mm (18.28 mm clean)."""
    L, beta = float(s.specimen["length_m"]), s.rng.uniform(0.2, 0.7)

    def reading(x: np.ndarray) -> np.ndarray:
        u = np.abs(2 * np.asarray(x, float) / L)
        ug = np.linspace(0.0, max(float(np.max(u)), 1e-6), 161)[1:]
        ratio = _upright_arc(ug, beta) / ((1 - np.cos(ug)) / ug)
        return np.asarray(x, float) * np.interp(u, np.r_[0.0, ug], np.r_[ratio[0], ratio])

    _table_map(s, reading)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_pv_inverter(s: Session) -> None:
    """The building's grid-tied solar inverter feeding the lab's distribution board: its output current (at the line
    frequency, nearly sinusoidal: third 0.02-0.06, fifth 0.02-0.05) runs in the cables behind the bench, and its
    field reaches the laser's cable (1-4 um at full sun, log) and the current amplifier's input (2-8 uA, log), each
    with its own coupling phase. Its size follows the sun on the panels: passing clouds shade them (the sun's spells
    120-600 s, the shade's 60-300 s, mean, log; the shade at 0.15-0.4 of full power, each edge smoothed over 10-40
    s), and the inverter's maximum-power tracker steps its power up and down by 1-3 % every 0.5-1.5 s (perturb and
    observe). Phase locked to the session clock. Measured (paper_142) displacement RMS +1.5e-05 % (residual 0.055 %,
    3.3x its noise), current RMS +1.4e-05 % (residual 0.049 %, 0.037x its noise)."""
    f0 = _line_f(s)
    h3, h5 = s.rng.uniform(0.02, 0.06), s.rng.uniform(0.02, 0.05)
    amp = {"disp_m": lu(s.rng, 1e-6, 4e-6), "i_A": lu(s.rng, 2e-6, 8e-6)}
    ph = {col: s.rng.uniform(0, 2 * np.pi, 3) for col in amp}
    t_sun, t_shade, shade = lu(s.rng, 120.0, 600.0), lu(s.rng, 60.0, 300.0), s.rng.uniform(0.15, 0.4)
    edge, dither, step = lu(s.rng, 10.0, 40.0), s.rng.uniform(0.01, 0.03), s.rng.uniform(0.5, 1.5)
    tg = _session_grid(s, 0.5, 120.0)
    level, t, sunny = np.empty(tg.size), float(tg[0]), s.rng.random() < 0.5
    while t <= tg[-1]:
        nxt = t + float(s.rng.exponential(t_sun if sunny else t_shade))
        level[(tg >= t) & (tg < nxt)] = 1.0 if sunny else shade
        t, sunny = nxt, not sunny
    power = _grid_lag(tg, level, edge, float(level[0]))
    p0 = s.rng.uniform(0, 2 * np.pi)
    for r in s.series():
        t = r.cols["t_s"]
        a = np.interp(t, tg, power) * (1 + dither * np.sign(np.sin(np.pi * (t - s.t0) / step + p0)))
        for col, size in amp.items():
            p = ph[col]
            wave = np.cos(2 * np.pi * f0 * t + p[0]) + h3 * np.cos(6 * np.pi * f0 * t + p[1]) + \
                h5 * np.cos(10 * np.pi * f0 * t + p[2])
            r.cols[col] = r.cols[col] + size * a * wave


def mp_line_monitor_ghost(s: Session) -> None:
    """The lab logs the mains voltage on the DAQ (a small transformer and divider to +-5 V, to stamp the grid's
    frequency with the data) on the channel scanned just before the laser's: a multiplexed DAQ's input does not
    settle completely from one channel to the next, and the laser's reading keeps a ghost of the mains monitor's,
    e^(-T/tau) of it, T the time between channels (the scan spread over the sample period: 1/(5 fs)) and tau the
    input's settling with the source's impedance (0.15-0.3 ms, log): 2e-4-1e-3 of it at 1 kHz (log), a fiftieth of
    that or less at 200 Hz. What it copies is the building's voltage, flat-topped (its third -0.02 to -0.05, its
    fifth 0.01-0.04), at the laser's 2 mm/V: a hum on the displacement that grows with the record's rate. Phase
    locked to the session clock; displacement only. Measured (p44_144) displacement RMS +3.2e-07 % (residual 0.0085
    %, 1.1x its noise), 2.5 um of hum on the 20 Hz records (their residuals 21 %), none to speak of at 200 Hz."""
    f0, ph = _line_f(s), s.rng.uniform(0, 2 * np.pi)
    h3, h5 = -s.rng.uniform(0.02, 0.05), s.rng.uniform(0.01, 0.04)
    tau, g_fast = lu(s.rng, 1.5e-4, 3e-4), lu(s.rng, 2e-4, 1e-3)
    for r in s.series():
        g = g_fast * math.exp(-(1 / (N_CHANNELS * r.fs) - 1 / (N_CHANNELS * 1000.0)) / tau)
        w = 2 * np.pi * f0 * r.cols["t_s"] + ph
        volts = 5.0 * (np.cos(w) + h3 * np.cos(3 * w) + h5 * np.cos(5 * w))
        r.cols["disp_m"] = r.cols["disp_m"] + LASER_M_PER_V * g * volts


# ------------------------------------------------------------------------------------------------ outside the catalogue


def _spectrum_top(s: Session) -> tuple[float, complex]:
    """The highest frequency of the session's first spectrum and the strip's impedance there (10 kHz, 30 Ohm if the
    session has none)."""
    for r in s.recs:
        if not r.series and r.cols["f_Hz"].size:
            k = int(np.argmax(r.cols["f_Hz"]))
            return float(r.cols["f_Hz"][k]), complex(r.cols["z_re_ohm"][k], r.cols["z_im_ohm"][k])
    return 1e4, 30.0 + 0j


def out_analyser_idle_leak(s: Session) -> None:
    """The impedance analyser keeps putting out its test signal between its sweeps, at the last frequency of the
    last sweep (the spectra's highest, 10 kHz, its synthesiser 5-50 ppm off the DAQ's clock, either way), and the
    switch box that gives the strip to the analyser or to the DAQ isolates it only so far: 0.5-2 mV of it (log)
    reach the drive line during every time series. The drive monitor reads it and the strip passes its current
    through its impedance at that frequency (the spectra's top point: mostly its series resistance), and the DAQ,
    without an anti-alias filter, samples it at each record's own rate: on the 200 Hz and 1 kHz records 10 kHz folds
    onto 0 Hz and the clocks' offset leaves a slow beat (0.05-0.5 Hz), on the others a line at 10 kHz modulo the
    rate (97 Hz at 220 Hz, 149 Hz at 469 Hz). Phase continuous on the session clock. Drive monitor and current.
    Measured (paper_142) drive residual 0.16 % of its RMS (3.5x its noise), current 0.92 % (0.69x); (p44_144) drive
    0.13 % (2.9x), current 0.72 % (0.58x)."""
    f_top, Z = _spectrum_top(s)
    fa = f_top * (1 + _sign(s) * lu(s.rng, 5e-6, 5e-5))
    a, ph = lu(s.rng, 5e-4, 2e-3), s.rng.uniform(0, 2 * np.pi)
    for r in s.series():
        w = 2 * np.pi * fa * (r.cols["t_s"] - s.t0) + ph
        r.cols["v_V"] = r.cols["v_V"] + a * np.cos(w)
        r.cols["i_A"] = r.cols["i_A"] + a / abs(Z) * np.cos(w - np.angle(Z))


def out_tribo_cuvette(s: Session) -> None:
    """A strip in air in a polystyrene cuvette whose wall the operator brushes with a gloved hand at every
    re-clamping (at the setting): the rubbed plastic charges (triboelectrically, a random amount each time, 0.3-1 of
    the largest) and pulls the strip's tip towards it (the side drawn) with the image force of a charged wall on a
    conductor, as the charge squared: an offset of up to 5-30 um (log) and a softening of the strip by the force's
    gradient (0.5-2 % more gain, at full charge), both fading as the charge leaks off the plastic in the room's
    humidity (tau 120-900 s, log). An offset and a gain that jump at the re-clampings and decay through each block.
    Displacement only. Measured (s001_143) displacement RMS +0.55 % (residual 0.60 %, 20x its noise, offsets of up
    to 6.6 um)."""
    side, d_e, kap = _sign(s), lu(s.rng, 5e-6, 3e-5), s.rng.uniform(0.005, 0.02)
    tau = lu(s.rng, 120.0, 900.0)
    t_set, first = _settings(s), _by_pressure_start(s)
    events = sorted(t_set.get(p, a - 20.0) for p, a in first.items())
    amounts = s.rng.uniform(0.3, 1.0, len(events))
    charge_at = []  # the charge just after each rubbing
    q, t_prev = 0.0, None
    for te, dq in zip(events, amounts):
        q = (q * math.exp(-(te - t_prev) / tau) if t_prev is not None else 0.0) + dq
        charge_at.append(q)
        t_prev = te
    top = max(charge_at)
    ev = np.array(events)
    for r in s.series():
        t = r.cols["t_s"]
        k = np.clip(np.searchsorted(ev, t, side="right") - 1, 0, len(ev) - 1)
        q = np.where(t >= ev[0], np.array(charge_at)[k] * np.exp(-np.clip(t - ev[k], 0, None) / tau), 0.0) / top
        r.cols["disp_m"] = r.cols["disp_m"] * (1 + kap * q * q) + side * d_e * q * q


def out_table_hunting(s: Session) -> None:
    """The clamp's stand on a pneumatic isolation table, the laser on a post on the floor beside it, and the table's
    levelling valves set with too much gain: the table hunts in a limit cycle (a relay loop: a valve fills the leg
    at a constant rate until the height sensor passes its dead band, then vents it), rocking the clamp's stand by a
    few microradians, so that the strip's root moves sideways by +-2-8 um (log) in a triangle wave, rising over
    0.3-0.7 of each period and falling over the rest, its period 1-4 s wandering by 3-10 % from cycle to cycle.
    Present through the whole session, at rest as in the records. Displacement only. Measured (paper_142)
    displacement residual 0.055 % of its RMS (3.3x its noise, the 20 Hz records' residuals 28-34 %); (p44_144) 0.029
    % (3.6x, 23-25 %)."""
    A, P, duty = lu(s.rng, 2e-6, 8e-6), s.rng.uniform(1.0, 4.0), s.rng.uniform(0.3, 0.7)
    jit = s.rng.uniform(0.03, 0.1)
    n = int((s.t1 - s.t0 + 20.0) / (P * (1 - 3 * jit))) + 2
    periods = P * np.clip(1 + jit * s.rng.standard_normal(n), 0.5, 1.5)
    starts = s.t0 - 10.0 - s.rng.uniform(0.0, P) + np.r_[0.0, np.cumsum(periods)[:-1]]
    for r in s.series():
        t = r.cols["t_s"]
        k = np.clip(np.searchsorted(starts, t, side="right") - 1, 0, n - 1)
        u = np.clip((t - starts[k]) / periods[k], 0.0, 1.0)
        y = np.where(u < duty, -A + 2 * A * u / duty, A - 2 * A * (u - duty) / (1 - duty))
        r.cols["disp_m"] = r.cols["disp_m"] + y


def out_popcorn_noise(s: Session) -> None:
    """Burst (popcorn) noise in the current amplifier: a bipolar input stage with a contaminated junction whose trap
    captures and releases a carrier, switching its offset between two levels at random, a random telegraph signal (1
    or 2 independent traps, drawn; each 15-60 uA at the current's scale, log, either sign, its mean dwell in each
    state 0.05-2 s, log, exponentially distributed). Running through the whole session, at rest as in the records.
    The current only. Measured (s001_143) current residual 0.15 % of its RMS (0.40x its noise); (p44_144) 1.4 %
    (1.1x)."""
    for _ in range(1 + int(s.rng.random() < 0.5)):
        a = _sign(s) * lu(s.rng, 1.5e-5, 6e-5)
        t_hi, t_lo = lu(s.rng, 0.05, 2.0), lu(s.rng, 0.05, 2.0)
        state = bool(s.rng.random() < t_hi / (t_hi + t_lo))
        t, edges = s.t0 - 5.0, []
        while t <= s.t1:
            n = 4096
            means = np.where((np.arange(n) % 2 == 0) == state, t_hi, t_lo)
            steps = s.rng.exponential(means)
            edges.append(t + np.cumsum(steps))
            t = float(edges[-1][-1])
        edges = np.concatenate(edges)
        for r in s.series():
            k = np.searchsorted(edges, r.cols["t_s"], side="right")
            high = (k % 2 == 0) == state
            r.cols["i_A"] = r.cols["i_A"] + a * high


FRESH24_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"telegraph_flux": br_telegraph_flux, "saturable_uptake": br_saturable_uptake},
    "faradaic_current": {"scratch_repassivation": far_scratch_repassivation,
                         "phosphate_prewave": far_phosphate_prewave},
    "hysteresis": {"twist_guide": hy_twist_guide, "floor_drag": hy_floor_drag},
    "time_delay": {"pga_bandwidth": td_pga_bandwidth, "hum_canceller": td_hum_canceller},
    "sensor_offset": {"edge_tracker": so_edge_tracker, "suction_mount": so_suction_mount},
    "clamp_relaxation": {"curing_glue": cr_curing_glue, "crevice_gas": cr_crevice_gas},
    "dehydration": {"salt_efflorescence": dh_salt_efflorescence, "hygrostat_dehumidifier": dh_hygrostat_dehumidifier},
    "strain_resistance": {"electrowetted_cracks": sr_electrowetted_cracks,
                          "hydride_closed_cracks": sr_hydride_closed_cracks},
    "large_deflection": {"differential_capacitor": ld_differential_capacitor,
                         "upright_self_weight": ld_upright_self_weight},
    "mains_pickup": {"pv_inverter": mp_pv_inverter, "line_monitor_ghost": mp_line_monitor_ghost},
    "unexplained": {"analyser_idle_leak": out_analyser_idle_leak, "tribo_cuvette": out_tribo_cuvette,
                    "table_hunting": out_table_hunting, "popcorn_noise": out_popcorn_noise},
}
inject.register_forms(FRESH24_FORMS)


# ------------------------------------------------------------------------------------------------ variants


SPLIT_FLOOR_HZ = (20.0, 40.0, 100.0)  # the impedance analyser's lowest frequency (an E4990A's 20 Hz, or the lab's)


def _part(r: Rec, keep: np.ndarray, tag: str) -> Rec:
    entry = dict(r.entry)
    stem = str(entry["file"])
    entry["file"] = (stem[:-4] if stem.lower().endswith(".csv") else stem) + f"_{tag}.csv"
    if "label" in entry:
        entry["label"] = f"{entry['label']}_{tag}"
    return Rec(entry, {k: x[keep].copy() for k, x in r.cols.items()})


def v_split_spectra(s: Session) -> None:
    """Two instruments for the impedance: the strip's low frequencies measured by a potentiostat's frequency-response
    analyser and its high ones by an impedance analyser that starts at f_s (20, 40 or 100 Hz, drawn for the session:
    the analyser's lowest frequency, an E4990A's 20 Hz or the lab's choice), the frequency at the split measured by
    both; each instrument's software exports its own file, and the lab's manifest lists each as its own spectrum record
    at that pressure, where the spectrum was, in the order the two ran (the potentiostat first or the analyser first,
    drawn for the session), labelled by instrument. The values, the time series and the rest of the manifest as they
    were. The import contract takes any number of spectra per pressure (each f_Hz positive); ``labrig import`` takes
    it."""
    floor = float(s.rng.choice(SPLIT_FLOOR_HZ))
    low_first = bool(s.rng.random() < 0.5)
    out = []
    for r in s.recs:
        f = r.cols.get("f_Hz") if not r.series else None
        if f is None or f.size == 0 or not np.any(f >= floor):
            out.append(r)
            continue
        f_s = float(np.min(f[f >= floor]))
        lo, hi = f <= f_s, f >= f_s
        if lo.sum() < 3 or hi.sum() < 3:
            out.append(r)
            continue
        parts = [_part(r, lo, "fra"), _part(r, hi, "analyser")]
        out += parts if low_first else parts[::-1]
    s.recs = out


inject.VARIANTS.update({"split_spectra": v_split_spectra})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_142", "s001_143", "p44_144"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 6 / 7 / 7 effect cases on seeds 142-144
    "back_relaxation": [("telegraph_flux", 144, T, "log_steps"), ("saturable_uptake", 142, P, "stop_trigger")],
    "faradaic_current": [("scratch_repassivation", 144, T, "short_pretrigger"),
                         ("phosphate_prewave", 142, P, "coherent_sines")],
    "hysteresis": [("twist_guide", 143, S, "cycle_averaged"), ("floor_drag", 144, T, "fixed_decimals")],
    "time_delay": [("pga_bandwidth", 142, P, "fir_decimated"), ("hum_canceller", 143, S, "split_spectra")],
    "sensor_offset": [("edge_tracker", 142, P, "tared_records"), ("suction_mount", 144, T, "rate07")],
    "clamp_relaxation": [("curing_glue", 143, S, "merged_loadcell"), ("crevice_gas", 142, P, "split_spectra")],
    "dehydration": [("salt_efflorescence", 143, S, "eis_descending"),
                    ("hygrostat_dehumidifier", 143, S, "settled_sines")],
    "strain_resistance": [("electrowetted_cracks", 143, S, "resampled"),
                          ("hydride_closed_cracks", 144, T, "swinging_door")],
    "large_deflection": [("differential_capacitor", 143, S, "host_timed"),
                         ("upright_self_weight", 144, T, "scan_hold")],
    "mains_pickup": [("pv_inverter", 142, P, "own_clock"), ("line_monitor_ghost", 144, T, "trigger_clock")],
    "unexplained": [("analyser_idle_leak", 142, P, "spectra_last"), ("analyser_idle_leak", 144, T, "split_spectra"),
                    ("tribo_cuvette", 143, S, "dropped_packets"), ("tribo_cuvette", 143, S, "two_pressures"),
                    ("table_hunting", 142, P, "decimated3"), ("table_hunting", 144, T, "shortened_shuffled"),
                    ("popcorn_noise", 143, S, "float32_time"), ("popcorn_noise", 144, T, "no_loadcell")],
}
CLEAN = [(142, P, "steps_sines"), (142, P, "split_spectra"), (143, S, "no_spectra"), (143, S, "split_spectra"),
         (144, T, "loadcell_dropout"), (144, T, "asrun")]


def fresh24_cases(only: str | None = None) -> list[Case]:
    """The twenty-fifth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    142-144)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh24_cases, "inject_fresh24", "fresh24")
