"""A twenty-eighth held-out set for the diagnosis (issue 12), fresh27, written without sight of the diagnosis (its
code, its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh26.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (a laminated membrane whose bond plane the
back-flow must cross, an aged surge varistor across the strip's terminals, a wet splash guard's capillary bridge
snapping onto the tip, a tracking stage whose encoder is read late, a two-range laser head switching range with the
bend, a screw loosened by the resonant records' shaking, a water film flung off the tip by its acceleration, a carbon
nanotube overlayer's signed piezoresistance, a notched optical fibre read as the bend, a push-pull pair of heads
without linearisation tables), some on the history, the clamp pressure or the session's events (porous gold over nickel
on a jaw's contact cracked by each tighter setting, a thixotropic clay gel rebuilding at rest, the floor sagging under
the operator at each re-clamping, cork pads swelling against the held gap, a microwave oven's spells next door, the
step records' older single-ended task) and some on time (salt leaching from a strip stored in brine, a laser cable's
jacket relaxing, a reference electrode's frit leaking potassium chloride into the bath, the plating's residual
compression relaxing); lab wiring or sensors among them (the varistor, the contact, the stage's encoder, the
two-range head, the tripod, the cable, the fibre, the head pair, the oven's and the old task's hum). Four structures
outside the catalogue (truth "unexplained": a strip in air bending as a bimorph with its own Joule heat, the
building's sway on a windy day, a DAQ front end's sample-and-hold released at each record's start, the drive's
output ranges each with its own uncalibrated gain and offset); clean sessions. All on three bases of new seeds
(151-153: the paper strip, the seed-001 strip on its own sweep, the paper strip 18 mm free) and on the earlier sets'
protocol / data-shape variants plus one new here: a logger that stamps its rows with the PC's time of day, a session
run late in the evening across midnight (``midnight_clock``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh26 are reused (importing inject_fresh26 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh27.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy.signal import butter, sosfiltfilt

import inject
import inject_fresh26  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lti, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _map_through, _step_response
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law
from inject_fresh6 import _bursts
from inject_fresh7 import _ramp_env
from inject_fresh8 import _hum
from inject_fresh9 import _dry_by, _ou, _session_grid
from inject_fresh10 import _lag_varying, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh20 import _relays
from inject_fresh22 import _table_map
from inject_fresh24 import _by_pressure_start
from inject_fresh25 import _setting_of
from inject_fresh26 import _split_noise

# the paper's strip 18 mm free (earlier sets used 19-29 and 31-45 mm, 30 mm is the paper preset itself and the seed-001
# strip is 20 mm; its 1 V step peaks near 3.2 mm, well inside the laser's +-20 mm): preset "paper_18", base "p18_153",
# registered in every process importing this module
inject.register_free_length("paper_18", 0.018)

inject.BASES.update({
    "paper_151": ("paper-sweep", "paper", 151),
    "s001_152": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 152),
    "p18_153": ("paper-sweep", "paper_18", 153),
})

DAY_S = 86400.0


# ------------------------------------------------------------------------------------------------ tools


def _smooth(x: np.ndarray, fs: float, corner: float = 30.0) -> np.ndarray:
    """x through a zero-phase second-order low-pass at ``corner`` Hz (above every drive frequency of the records: flat
    on them), or at 0.3 of the record's Nyquist frequency where that is lower."""
    if x.size < 16:
        return x.copy()
    return sosfiltfilt(butter(2, min(corner / (0.5 * fs), 0.3), output="sos"), x)


def _acceleration(r: Rec) -> np.ndarray:
    """The tip's acceleration (m/s^2) from the record's displacement, its noise taken off (``_smooth``)."""
    d = _smooth(r.cols["disp_m"], r.fs)
    return np.gradient(np.gradient(d) * r.fs) * r.fs


def _unit_step(r: Rec, col: str) -> tuple[np.ndarray, np.ndarray]:
    """A step record's measured unit-step response of any column (inject_fresh2._step_response, which reads the
    displacement's): from the drive's rise to its fall, per volt, from the value just before the rise."""
    return _step_response(Rec(r.entry, {**r.cols, "disp_m": r.cols[col]}))


def _slab_left(u: np.ndarray, tau: float, terms: int = 400) -> np.ndarray:
    """The share of a slab's content still in it u seconds after its faces were opened to a sink (Fickian, both faces:
    sum_n 8/((2n + 1) pi)^2 exp(-(2n + 1)^2 pi^2 u/(4 tau)), tau = l^2/D of its half-thickness l), 1 at u <= 0."""
    u = np.clip(np.asarray(u, float), 0.0, None)
    k = 2.0 * np.arange(terms) + 1.0
    left = np.sum(8.0 / (k * np.pi) ** 2 * np.exp(-np.outer(u, k**2) * np.pi**2 / (4.0 * tau)), axis=1)
    return np.where(u > 0, left / np.sum(8.0 / (k * np.pi) ** 2), 1.0)


def _laminate_kernel(q: np.ndarray, beta: float) -> np.ndarray:
    """The opposing swelling's share 1 - R(q) of a membrane of two films bonded along its mid-plane, the bond a barrier
    of Biot number beta: R = [tanh q - (1 - sech q)/q + (beta/q)(1 - tanh q/q)] / [tanh q + beta/q], q = sqrt(tau s)
    (tau = l^2/D of one film); R -> 1 - tanh(q)/q as beta -> infinity (the single slab), 1 - tanh(q/2)/q as beta -> 0
    (each half alone)."""
    q = np.asarray(q, complex)
    out = np.empty(q.shape, complex)
    small, big = np.abs(q) < 1e-4, np.abs(q) > 30.0
    mid = ~small & ~big
    qm = q[mid]
    th, sech = np.tanh(qm), 1.0 / np.cosh(qm)
    out[mid] = 1.0 - (th - (1.0 - sech) / qm + beta / qm * (1.0 - th / qm)) / (th + beta / qm)
    qb = q[big]
    out[big] = 1.0 - (1.0 - 1.0 / qb + beta / qb * (1.0 - 1.0 / qb)) / (1.0 + beta / qb)
    out[small] = 1.0 - q[small] ** 2 * (0.5 + beta / 3.0) / beta
    return out


def _visits(s: Session, first: tuple[float, float], extra: tuple[int, int],
            length: tuple[float, float]) -> list[tuple[float, float, float]]:
    """Someone at the bench: from each re-clamping's setting (inject_fresh25._setting_of) for ``first`` seconds (log),
    and ``extra`` more times (an integer range) at moments inside the session for ``length`` seconds (log); each visit
    (start, end, its size 0.7-1.3)."""
    setting = _setting_of(s)
    out = []
    for p, a in sorted(_by_pressure_start(s).items(), key=lambda kv: kv[1]):
        t = setting(p, a)
        out.append((t, t + lu(s.rng, *first), s.rng.uniform(0.7, 1.3)))
    for _ in range(int(s.rng.integers(*extra))):
        t = s.rng.uniform(s.t0, s.t1)
        out.append((t, t + lu(s.rng, *length), s.rng.uniform(0.7, 1.3)))
    return out


def _present(t: np.ndarray, visits: list[tuple[float, float, float]]) -> np.ndarray:
    """The size of the visit under way at each t (the largest where two overlap), 0 between visits."""
    out = np.zeros(np.shape(t))
    for a, b, size in visits:
        out = np.where((t >= a) & (t < b), np.maximum(out, size), out)
    return out


# ------------------------------------------------------------------------------------------------ back relaxation


def br_laminated_midplane(s: Session) -> None:
    """A thick strip cut from a laminate: two Nafion films hot-pressed into one membrane before plating (the way labs
    make stronger strips), the bond plane in the middle denser than the films: the water the bend pushed to the cathode
    half spreads through that half quickly (tau = l^2/D of one film, 1-4 s, log) but crosses the bond plane slowly (its
    permeability h, Biot number beta = 2 h l/D 0.05-0.3, log; tau/beta at most 40 s). The opposing swelling is the first
    moment of the water across the membrane: the reading d - K2 (1 - R(q)) d (K2 0.7-1.1; R the laminate's moment over
    the water's at the cathode face, _laminate_kernel, q = sqrt(tau s)): half of the give-back within the cathode half
    over tau, the rest across the bond over tau/beta, a two-stage relaxation with a plateau between (beta -> infinity is
    inject's single slab, tanh q/q). Through inject_fresh2._through with 180 s of the session's history; displacement
    only. Measured (p18_153) displacement RMS -65 % (residual 69 %, 1500x its noise), the 1 V steps (1.48 mm clean 5 s
    after their edge, 3.25 mm by their plateaus' end) at 0.81 and 1.10 mm."""
    k2, tau = s.rng.uniform(0.7, 1.1), lu(s.rng, 1.0, 4.0)
    beta = max(lu(s.rng, 0.05, 0.3), tau / 40.0)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        return lambda z: 1.0 - k2 * _laminate_kernel(np.sqrt(tau * np.asarray(z) + 0j), beta)

    _map_through(s, H, 180.0)


def br_salt_leaching(s: Session) -> None:
    """A strip stored in concentrated brine (1-2 M NaCl, to keep it in its sodium form), rinsed briefly and mounted in
    the deionised bath 0-300 s before the first record: the salt its clusters took up (Donnan exclusion is weak at such
    a concentration) leaves through both faces by diffusion across the membrane, its share left following a slab's
    desorption (inject_fresh27._slab_left, tau_s = l^2/D 300-1500 s, log). As the membrane's salt falls its osmotic
    (Donnan) swelling rises and its clusters hold more free water: the back-flow's share K2 = K_f (1 - g F) (K_f 0.8-1.1
    leached, g 0.3-0.6) grows and its lag tau = tau_f (1 + c F) (tau_f 3-8 s, log, c 0.3-0.8: the salt-laden clusters'
    narrower channels) shortens as the salt F leaves. Through inject_fresh10._lag_varying (the reading d - K2 x, x the
    lag of d, sample by sample through the session, carried over the rests); displacement only. Measured (paper_151)
    displacement RMS -68 % (residual 81 %, 5000x its noise), the 1 V steps (8.82 mm clean) at 3.32 mm by their plateaus'
    end in the first block, 1.73, 1.57, 1.55 mm in the later ones."""
    t_m, tau_s = s.t0 - s.rng.uniform(0.0, 300.0), lu(s.rng, 300.0, 1500.0)
    k_f, g = s.rng.uniform(0.8, 1.1), s.rng.uniform(0.3, 0.6)
    tau_f, c = lu(s.rng, 3.0, 8.0), s.rng.uniform(0.3, 0.8)
    tg = _session_grid(s, 5.0, 10.0)
    left = _slab_left(tg - t_m, tau_s)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        f = np.interp(np.asarray(t, float), tg, left)
        return k_f * (1 - g * f), tau_f * (1 + c * f)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_aged_varistor(s: Session) -> None:
    """A surge-protection varistor (a low-voltage zinc-oxide disc, 3.3-5.6 V working voltage) fitted across the drive
    box's output terminals after the current sense, aged by the surges it has taken (its grain-boundary barriers
    degraded, its leakage up): below its working voltage it conducts with the ZnO's pre-breakdown power law, i = I_1
    abs(v)^alpha sign(v) (I_1 0.1-0.4 mA at 1 V, log; alpha 3-6), its nanofarads of capacitance negligible beside the
    strip's. The amplifier holds the strip's voltage, so the strip is as it was and the current sense reads the
    varistor's current on top of the strip's. Odd, memoryless; the current only. Measured (s001_152) current RMS +0.42 %
    (residual 1.8 %, 4.8x its noise), 0.11 mA on the 1 V plateaus."""
    i1, alpha = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(3.0, 6.0)
    for r in s.series():
        v = r.cols["v_V"]
        r.cols["i_A"] = r.cols["i_A"] + i1 * np.sign(v) * np.abs(v) ** alpha


def far_porous_gold_contact(s: Session) -> None:
    """The jaws' contacts gold-flash plated over nickel (a thin, porous gold), and the jaw on one face (drawn: the face
    that is the anode for one sign of the drive) biting into the wet plating: each tighter setting cracks more of the
    gold at the contact's edges and exposes nickel in the wet crevice, the exposed share growing with the highest
    setting so far, A = ((p_hi - p_c)/(p_top - p_c))^m (p_c 0.15-0.45 of the session's top setting, m 1-2; none below
    p_c), for good. Where that face is the anode the exposed nickel dissolves (Tafel, b 0.04-0.08 V, from the drive's
    own voltage) up to the crevice's ohmic limit (i_T/(1 + i_T/i_lim), i_lim 2-5 times the current at 1 V), 0.2-0.6 mA
    (log) at 1 V with all of it exposed; on the other sign nothing (the dissolved nickel is carried off). One-sided,
    memoryless within a setting, growing with the settings; the current only. Measured (p18_153) current RMS +0.33 %
    (residual 3.8 %, 2.6x its noise), nothing on the first two blocks' 1 V plateaus, 0.13 mA on the third's, 0.51 mA on
    the last's."""
    side, top = _sign(s), max(s.pressures())
    p_c, m = s.rng.uniform(0.15, 0.45) * top, s.rng.uniform(1.0, 2.0)
    b, i1, lim = s.rng.uniform(0.04, 0.08), lu(s.rng, 2e-4, 6e-4), s.rng.uniform(2.0, 5.0)
    i_lim = lim * i1
    kin1 = i1 / (1.0 - i1 / i_lim)  # the kinetic current at 1 V that the ohmic limit brings to i1
    p_hi = 0.0
    for r in _chrono(s):
        p_hi = max(p_hi, float(r.entry["pressure_kPa"]))
        area = min(max((p_hi - p_c) / max(top - p_c, 1e-9), 0.0), 1.0) ** m
        if area <= 0:
            continue
        u = side * r.cols["v_V"]
        kin = kin1 * np.exp(np.clip((u - 1.0) / b, -700.0, 50.0))
        r.cols["i_A"] = r.cols["i_A"] + side * area * np.where(u > 0, kin / (1.0 + kin / i_lim), 0.0)


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_bridge_snap(s: Session) -> None:
    """A strip in air beside a glass slide the lab stood by it as a draught shield, on one side (drawn) and beyond the
    tip's reach (1.05-1.3 of the session's largest bend towards it), a drop of condensed water hanging from its edge
    towards the strip: when the tip comes out to the drop (at c 0.6-0.9 of that largest bend) a capillary bridge forms
    and pulls the tip towards the slide, by a (0.03-0.1 of it, the bridge's pull over the strip's tip stiffness) at
    once; drawn back, the bridge stretches and its pull falls in proportion, a (1 - e/e_r), e the stretch beyond where
    it formed, until it breaks at e_r (0.15-0.35 of that bend, the stretch a bridge of that volume survives): attached,
    the tip at y = u + a (1 - e/e_r), e = c - y (u where the strip alone would be; the full pull while e < 0). A snap on
    the way out, a smooth release further back, the tip never on the glass: rate-independent memory at the large bends
    on that side only. Sample by sample through the session in time order, the laser's noise kept on the held reading
    (inject_fresh26._split_noise); displacement only. Measured (s001_152) displacement RMS +3.3 % (residual 5.6 %, 180x
    its noise), the 1 V steps at 5.12-5.15 mm for 4.69-4.71 mm."""
    side = _sign(s)
    ext = max(float(np.max(side * r.cols["disp_m"])) for r in s.series())
    ext = ext if ext > 0 else (_largest(s) or ref_disp(s))
    c, a, e_r = s.rng.uniform(0.6, 0.9) * ext, s.rng.uniform(0.03, 0.1) * ext, s.rng.uniform(0.15, 0.35) * ext
    on = False
    for r in _chrono(s):
        sig, noise = _split_noise(r)
        out = np.empty(sig.size)
        for k, u in enumerate((side * sig).tolist()):
            if not on and u >= c:
                on = True
            if on:
                y = (u + a - a * c / e_r) / (1.0 - a / e_r)
                if c - y < 0:
                    y = u + a
                elif c - y > e_r:
                    on, y = False, u
            else:
                y = u
            out[k] = y
        r.cols["disp_m"] = side * out + noise


def hy_thixotropic_clay(s: Session) -> None:
    """The strip's tip (its last millimetres) in a bath thickened with a synthetic clay (a Laponite suspension, a clear
    thixotropic gel labs use as a tissue phantom or to stop a bath sloshing): the clay's structure lambda (0-1) builds
    at rest towards 1 over tau_b (20-120 s, log) and is broken by the tip's shearing, in proportion to the distance the
    tip travels (lambda x exp(-abs(dy)/(c D)), c 0.5-2, D the session's largest bend); its yield holds the tip while the
    strip's pull stays within r_max lambda of where it sticks (r_max 0.05-0.15 D). After a rest the tip starts stuck in
    a set gel (a wide dead band), and moving fluidises it (the band narrows): the memory depends on the rests and on the
    path. Sample by sample through the session in time order (the gel set at the first record, rebuilding over each
    rest), the laser's noise kept on the held reading (inject_fresh26._split_noise); displacement only. Measured
    (paper_151) displacement RMS -2.0 % (residual 9.8 %, 600x its noise), the 1 V steps at 3.29 mm 5 s after their edge
    (3.87 clean) and 8.37 mm by their plateaus' end (8.82)."""
    D = _largest(s) or ref_disp(s)
    r_max, tau_b, c = s.rng.uniform(0.05, 0.15) * D, lu(s.rng, 20.0, 120.0), s.rng.uniform(0.5, 2.0)
    lam, y, t_end = 1.0, None, None
    for r in _chrono(s):
        t = r.cols["t_s"]
        if t_end is not None:
            lam = 1.0 - (1.0 - lam) * math.exp(-max(float(t[0]) - t_end, 0.0) / tau_b)
        sig, noise = _split_noise(r)
        y = float(sig[0]) if y is None else y
        build, out = -math.expm1(-1.0 / (r.fs * tau_b)), np.empty(sig.size)
        for k, u in enumerate(sig.tolist()):
            lam += (1.0 - lam) * build
            rad = r_max * lam
            new = min(max(y, u - rad), u + rad)
            lam *= math.exp(-abs(new - y) / (c * D))
            y = new
            out[k] = y
        r.cols["disp_m"] = out + noise
        t_end = float(t[-1])


# ------------------------------------------------------------------------------------------------ time delay


def td_tracking_stage_latency(s: Session) -> None:
    """A high-resolution laser head with a short range on a motorised linear stage that its controller servoes to keep
    the reading centred (a first-order tracking loop, bandwidth f_s 0.3-2 Hz, log), the lab's logger adding the stage's
    position, read from the motion controller over USB late by L (20-80 ms, log), to the head's analogue reading (read
    at once): the reading d + s(t - L) - s(t), s the stage's share of d, d/(1 + z/w_s). The slow motion, which the stage
    takes, is late by L; the fast, which the head takes, is not: H = 1 + (exp(-z L) - 1)/(1 + z/w_s), gain 1 at both
    ends. Through inject_fresh2._through with 5 s of the session's history; displacement only. Measured (p18_153)
    displacement residual 1.1 % of its RMS (24x its noise): the 0.1 Hz sines' 2.5-4.4 %, the stepped sines' rising to
    18.6 % at 2 Hz and falling to 4.1 % at 13.7 Hz, the 1 V steps' 0.49 %."""
    ws, L = 2 * math.pi * lu(s.rng, 0.3, 2.0), lu(s.rng, 0.02, 0.08)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        return lambda z: 1.0 + (np.exp(-np.asarray(z) * L) - 1.0) / (1.0 + np.asarray(z) / ws)

    _map_through(s, H, 5.0)


def td_dual_range_head(s: Session) -> None:
    """A two-range triangulation head (a near range of short exposure and a far one its controller switches to when the
    target leaves the near window, as some long-range heads do): beyond abs(d) R_s (0.35-0.6 of the session's largest
    bend) it switches to the far range and back below R_s (1 - h) (h 0.1-0.25, the switch's hysteresis). Each range
    reports late by its own processing: the near tau_n (0.5-2 ms), the far tau_n + dtau (dtau 8-20 ms: its longer
    exposure and averaging). The reading the strip at t - tau(t) (linear interpolation within the record, its first
    value held before it), tau following the range sample by sample through the session in time order (a switch steps
    the latency at once). A delay that grows with the bend and remembers the way it came; displacement only. Measured
    (p18_153) displacement residual 0.16 % of its RMS (3.4x its noise), the 1 V harmonics' 0.25 %, the 20 Hz records'
    29-33 % (the near range's own latency)."""
    D = _largest(s) or ref_disp(s)
    r_s, h = s.rng.uniform(0.35, 0.6) * D, s.rng.uniform(0.1, 0.25)
    tn, dtau = s.rng.uniform(5e-4, 2e-3), s.rng.uniform(8e-3, 2e-2)
    state = np.zeros(1)
    for r in _chrono(s):
        t, d = r.cols["t_s"], r.cols["disp_m"]
        far, state = _relays(np.abs(d), np.array([r_s]), np.array([r_s * (1 - h)]), state)
        r.cols["disp_m"] = np.interp(t - (tn + dtau * far[:, 0]), t, d)


# ------------------------------------------------------------------------------------------------ sensor offset


def so_tripod_floor_sag(s: Session) -> None:
    """The laser head on a tripod standing on a suspended timber floor, the clamp's bench on its own legs a metre away,
    the spot aimed a margin m0 (0.1-0.3 mm) inside the tip's end: while the operator stands at the bench (from each
    re-clamping's setting for 60-240 s, log, checking the load cell and the reading, and 1-3 times more for 30-120 s,
    log) the joists sag under their weight at the tripod's feet and tilt it, its head 0.4-0.8 m up turning so that the
    spot steps inboard along the strip by delta (0.3-1.2 mm, each visit 0.7-1.3 of it) at once, and back when they step
    away (the floor springs back). The strip read at the moving station (inject_fresh10._station); displacement only.
    Measured (s001_152) displacement RMS -10 % (residual 10 %, 330x its noise), the 1 V steps (each block's first
    record) at 4.19-4.22 mm for 4.69-4.71 mm."""
    L = float(s.specimen["length_m"])
    m0, dlt = s.rng.uniform(1e-4, 3e-4), s.rng.uniform(3e-4, 1.2e-3)
    visits = _visits(s, (60.0, 240.0), (1, 4), (30.0, 120.0))
    most = max(v[2] for v in visits)
    _station(s, lambda r: 1 - (m0 + dlt * _present(r.cols["t_s"], visits)) / L, 1 - (m0 + dlt * most) / L)


def so_cable_relaxation(s: Session) -> None:
    """The laser head on an articulated arm (a magnetic base's jointed arm, its joints compliant), its stiff PVC cable
    looped down to the controller on the floor: the cable's bend pushes on the head, and the PVC jacket's stress relaxes
    logarithmically from the head's mounting (60-900 s before the first record, tau 5-60 s, log), so the arm springs
    back by a little more each decade and the spot, aimed a margin m0 (0.1-0.3 mm) inside the tip's end, walks inboard
    along the strip by 0.3-1.0 mm by the session's end, as log10(1 + u/tau): fast at first, slower and slower, never
    settling. The strip read at the moving station (inject_fresh10._station); displacement only. Measured (paper_151)
    displacement RMS -4.6 % (residual 4.8 %, 290x its noise), the 1 V steps at 8.55, 8.41, 8.36, 8.33 mm block by block
    (8.82 mm clean)."""
    L = float(s.specimen["length_m"])
    m0, total = s.rng.uniform(1e-4, 3e-4), s.rng.uniform(3e-4, 1e-3)
    t_m, tau = s.t0 - s.rng.uniform(60.0, 900.0), lu(s.rng, 5.0, 60.0)
    norm = math.log10(1 + (s.t1 - t_m) / tau)

    def frac(r: Rec) -> np.ndarray:
        return 1 - (m0 + total * np.log10(1 + np.clip(r.cols["t_s"] - t_m, 0, None) / tau) / norm) / L

    _station(s, frac, 1 - (m0 + total) / L)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_cork_pads(s: Session) -> None:
    """Pads of agglomerated cork (cut from a 3-5 mm cork sheet to spread the force) under a screw clamp's fixed gap, dry
    until the bath was filled 0-120 s before the first setting: cork takes up water and swells against the held gap, its
    uptake a slab's (1 - _slab_left, tau_w 600-1800 s, log), the force rising by a_0 (p_min/p) (a_0 0.25-0.5 at the
    lowest setting: the swelling's force is the same at every setting, a larger share of a light one) times the uptake
    since the setting, while the cork's cell walls creep (r 2-5 % a decade, tau 5-30 s, log): F/F_set = 1 + a_0
    (p_min/p)(S(t) - S(t_set)) - r log10(1 + u/tau). The first, light setting rises, the later, heavy ones sag. From
    each setting (inject_fresh25._setting_of) through the preset's clamp law (inject_fresh4._clamp_law), the load cell
    showing it. Measured (paper_151) displacement residual 0.069 % of its RMS (4.2x its noise), current residual 0.38 %
    (0.29x its noise), the load cell at 1.00-1.12 of its reading in the first block, 0.95-0.99 in the later ones."""
    tau_w = lu(s.rng, 600.0, 1800.0)
    a0, r_c, tau = s.rng.uniform(0.25, 0.5), s.rng.uniform(0.02, 0.05), lu(s.rng, 5.0, 30.0)
    p_min = min(s.pressures())
    setting = _setting_of(s)
    starts = {p: setting(p, a) for p, a in _by_pressure_start(s).items()}
    t_f = min(starts.values()) - s.rng.uniform(0.0, 120.0)

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        t = np.asarray(t, float)
        t_set = starts.get(p, t_first - 20.0)
        up = _slab_left(np.array([t_set - t_f]), tau_w)[0] - _slab_left(t - t_f, tau_w)
        return 1 + a0 * p_min / p * up - r_c * np.log10(1 + np.clip(t - t_set, 0, None) / tau)

    _clamp_law(s, rel)


def cr_junker_loosening(s: Session) -> None:
    """A screw clamp on a plain washer, self-loosening as bolted joints do under transverse vibration (Junker's test):
    the strip's resonant records shake the jaw (the root's dynamic reaction, the strip's and its water's inertia, in
    proportion to the tip's acceleration), and while that exceeds the thread's slip threshold (c 0.2-0.5 of the
    session's largest tip acceleration, _acceleration) the screw turns back a little at every cycle: its loosening runs
    at the excess, dl/dt = k (abs(a)/a_max - c)+ (k set so that the whole session's shaking would take l_0 2-6 times
    over), counted from each setting (the operator re-tightens), the force falling by r_l (1 - exp(-l/l_0)) (r_l
    0.05-0.15) beside the pads' own slow creep (0.5-1.5 % a decade, tau 5-30 s, log). The force drops in the fast, large
    records and holds through the slow ones and the rests. Through the preset's clamp law (inject_fresh4._clamp_law),
    the load cell showing it. Measured (paper_151) displacement residual 0.065 % of its RMS (4.0x its noise), current
    residual 0.49 % (0.37x its noise), the load cell falling to 0.91-0.92 of its reading in every block."""
    c, r_l, mult = s.rng.uniform(0.2, 0.5), s.rng.uniform(0.05, 0.15), s.rng.uniform(2.0, 6.0)
    r_c, tau = s.rng.uniform(0.005, 0.015), lu(s.rng, 5.0, 30.0)
    acc = {id(r): np.abs(_acceleration(r)) for r in s.series()}
    a_max = max(float(np.max(a)) for a in acc.values()) or 1.0
    excess = {k: np.clip(a / a_max - c, 0, None) for k, a in acc.items()}
    total = sum(float(np.sum(x)) / r.fs for r in s.series() for x in [excess[id(r)]]) or 1.0
    k = mult / total
    setting = _setting_of(s)
    starts = {p: setting(p, a) for p, a in _by_pressure_start(s).items()}
    ts, ls, p_last, run = [], [], None, 0.0
    for r in _chrono(s):
        p = float(r.entry["pressure_kPa"])
        if p != p_last:
            run, p_last = 0.0, p
        inc = k * np.cumsum(excess[id(r)]) / r.fs
        ts.append(r.cols["t_s"])
        ls.append(run + inc)
        run += float(inc[-1])
    tt, ll = np.concatenate(ts), np.concatenate(ls)
    order = np.argsort(tt, kind="stable")
    tt, ll = tt[order], ll[order]

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        t = np.asarray(t, float)
        u = np.clip(t - starts.get(p, t_first - 20.0), 0, None)
        return 1 - r_l * -np.expm1(-np.interp(t, tt, ll)) - r_c * np.log10(1 + u / tau)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_fling_off(s: Session) -> None:
    """A strip in air sprayed with a plant mister 0-300 s before the first record to keep it wet: while a film of
    surface water lasts the membrane stays at its wet uptake. The film evaporates at its steady rate (gone in T_f
    1500-4000 s, log, by that alone) and is flung off as droplets whenever the tip's acceleration passes the film's
    capillary hold, a_c (0.3-0.6 of the session's largest, _acceleration): shed at the excess (abs(a)/a_c - 1)+, so that
    the session's shaking would take 1-2 films. Once it is gone the strip dries towards the room's equilibrium (a share
    w_inf 0.7-0.85 of its water) over tau_d (600-2000 s, log). The gain as the water, the conductance as its 1.5-2.5th
    power, relative to the first record; the spectra at the next series' start (inject_fresh9._dry_by). Measured
    (s001_152) displacement RMS -7.8 % (residual 11 %, 340x its noise), current RMS -19 % (residual 24 %, 67x its
    noise); the 1 V steps at 4.69, 4.57, 4.13, 3.92 mm block by block (4.69-4.71 mm clean), the impedance at 0.1 Hz
    1.06, 1.33, 1.51x in the later blocks' spectra."""
    t_s, t_f = s.t0 - s.rng.uniform(0.0, 300.0), lu(s.rng, 1500.0, 4000.0)
    c, shed = s.rng.uniform(0.3, 0.6), s.rng.uniform(1.0, 2.0)
    w_inf, tau_d, gc = s.rng.uniform(0.7, 0.85), lu(s.rng, 600.0, 2000.0), s.rng.uniform(1.5, 2.5)
    acc = {id(r): np.abs(_acceleration(r)) for r in s.series()}
    a_c = c * (max(float(np.max(a)) for a in acc.values()) or 1.0)
    excess = {k: np.clip(a / a_c - 1.0, 0, None) for k, a in acc.items()}
    k = shed / (sum(float(np.sum(excess[id(r)])) / r.fs for r in s.series()) or 1.0)
    film, t_prev, gone = 1.0, t_s, None
    for r in _chrono(s):
        t = r.cols["t_s"]
        film -= max(float(t[0]) - t_prev, 0.0) / t_f
        if film <= 0:
            gone = t_prev + (film + max(float(t[0]) - t_prev, 0.0) / t_f) * t_f
            break
        left = film - (t - t[0]) / t_f - k * np.cumsum(excess[id(r)]) / r.fs
        if np.any(left <= 0):
            gone = float(t[int(np.argmax(left <= 0))])
            break
        film, t_prev = float(left[-1]), float(t[-1])
    if gone is None:
        gone = t_prev + film * t_f

    def water(t: np.ndarray) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - gone, 0, None)
        return w_inf + (1 - w_inf) * np.exp(-u / tau_d)

    w0 = float(water(np.array([s.t0]))[0])
    _dry_by(s, lambda t: 1 - water(t) / w0, lambda t: 1 - (water(t) / w0) ** gc)


def dh_kcl_frit_leak(s: Session) -> None:
    """A reference electrode (Ag/AgCl in 3 M KCl, left in the cuvette from the impedance set-up) whose ceramic frit
    leaks its filling into the deionised bath at a steady rate from its dipping in (0-600 s before the first record):
    the bath's potassium rises in proportion to the time, to 1-5 mM (log) by the session's end, and the membrane, which
    prefers potassium to its own cations (selectivity K 5-20 over a bath of 0.05-0.2 mM of them, log), takes it up to
    the share x_eq = K c/(c_0 + K c) through its exchange lag (tau_x 200-800 s, log). The potassium form holds less
    water: the gain falls by s_g x (s_g 0.1-0.25), the conductance by s_c x (s_c 0.2-0.4). A loss that starts at once
    and slows as the sites fill. The spectra at the next series' start (inject_fresh9._dry_by). Measured (paper_151)
    displacement RMS -8.8 % (residual 10 %, 620x its noise), current RMS -33 % (residual 34 %, 25x its noise); the 1 V
    steps at 8.77, 7.83, 7.80, 7.79 mm block by block (8.82 mm clean), the impedance at 0.1 Hz 1.52-1.56x in the later
    blocks' spectra."""
    t_in, c_end = s.t0 - s.rng.uniform(0.0, 600.0), lu(s.rng, 1e-3, 5e-3)
    sel, c0, tau_x = lu(s.rng, 5.0, 20.0), lu(s.rng, 5e-5, 2e-4), lu(s.rng, 200.0, 800.0)
    s_g, s_c = s.rng.uniform(0.1, 0.25), s.rng.uniform(0.2, 0.4)
    dt = 2.0
    tg = np.arange(t_in, s.t1 + dt, dt)
    conc = c_end * (tg - t_in) / (s.t1 - t_in)
    eq = sel * conc / (c0 + sel * conc)
    a, x = math.exp(-dt / tau_x), np.empty(tg.size)
    prev = 0.0
    for k, e in enumerate(eq.tolist()):
        prev = e + (prev - e) * a
        x[k] = prev
    x0 = float(np.interp(s.t0, tg, x))
    up = lambda t: np.interp(np.asarray(t, float), tg, x) - x0  # noqa: E731  (relative to the first record)
    _dry_by(s, lambda t: s_g * up(t) / (1 - s_g * x0), lambda t: s_c * up(t) / (1 - s_c * x0))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_cnt_overlayer(s: Session) -> None:
    """One face (drawn) sprayed with a carbon-nanotube ink over its platinum to lower its surface resistance, the
    nanotube network carrying a share of that face's conduction: a nanotube network is piezoresistive both ways, its
    resistance up in tension and down in compression, linear over these strains, while the platinum's own cracks stay
    shut (a fresh, well-bonded plating): that face's dR/R = k side e (k 0.1-0.3 per unit of e, the bend over the
    session's displacement scale), signed. Gains fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of
    dR/R (inject_fresh3._resist), so they rise when the coated face is compressed: an even part of the bend and of the
    current, no dead zone. Measured (s001_152) displacement RMS -3.7 % (residual 3.9 %, 120x its noise), current RMS
    -0.87 % (residual 2.7 %, 7.3x its noise); the 1 V steps at 4.44-4.47 mm for 4.69-4.71 mm."""
    side, k = _sign(s), s.rng.uniform(0.1, 0.3)
    _resist(s, lambda r, e: k * side * np.asarray(e), (0.03, 0.08), (0.06, 0.15))


def sr_relaxing_prestress(s: Session) -> None:
    """Electrodes plated by electroless reduction, left in residual compression that holds their cracks shut: a face's
    cracks open only once its tension passes its pre-strain e0 (0.4-0.8 of the session's largest tension at the first
    record), and the compression relaxes as the swollen polymer beneath the film creeps in shear under it, e0(t) = e0 (1
    - c log10(1 + u/tau)) from the strip's soaking (0-600 s before the first record, tau 30-300 s, log; c set so that e0
    falls to 0.2-0.5 of its start by the session's end): the same bend opens more cracks later in the session. Both
    faces (k 0.8-1.5 per unit of opening, the other face 0.5-1 of it). Gains fall by 0.03-0.08 (displacement) and
    0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (p18_153) displacement RMS -3.6 % (residual
    4.1 %, 91x its noise), current RMS -0.23 % (residual 1.5 %, 1.0x its noise); the 1 V steps at 3.09, 3.05, 3.03, 3.02
    mm block by block (3.25 mm clean)."""
    e0, end = s.rng.uniform(0.4, 0.8), s.rng.uniform(0.2, 0.5)
    t_m, tau = s.t0 - s.rng.uniform(0.0, 600.0), lu(s.rng, 30.0, 300.0)
    k, o = s.rng.uniform(0.8, 1.5), s.rng.uniform(0.5, 1.0)
    c = (1 - end) / math.log10(1 + (s.t1 - t_m) / tau)
    q = ref_disp(s) / (_largest(s) or ref_disp(s))

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        x = q * np.asarray(e)
        th = e0 * (1 - c * np.log10(1 + np.clip(r.cols["t_s"] - t_m, 0, None) / tau))
        return k * (np.clip(x - th, 0.0, None) + o * np.clip(-x - th, 0.0, None))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_notched_pof(s: Session) -> None:
    """No laser: a plastic optical fibre (a 1 mm PMMA fibre) glued along the strip over its free length, its cladding
    notched across the face on one side (drawn), read by an LED and a photodiode, the lab's linear calibration made at
    small bends: bending that opens the notches loses light as exp(-g x) (x the bend over the session's largest, g
    0.3-0.8), bending that closes them gains it back only up to the unnotched fibre's, 1 + h tanh(g abs(x)/h) (h
    0.1-0.3). Read as (1 - T/T0)/g (slope 1 at rest): the opening side compresses as the exponential does, the closing
    side saturates sooner. The fibre reads the mean curvature, the tip's 2 d/L^2 for the quasi-static bend (the first
    mode's ratio, a few per cent apart near resonance, left out). Tabulated and interpolated
    (inject_fresh22._table_map); displacement only. Measured (p18_153) displacement RMS -10 % (residual 11 %, 240x its
    noise), the 1 V steps at 2.78 mm for 3.25 mm."""
    side, g, h = _sign(s), s.rng.uniform(0.3, 0.8), s.rng.uniform(0.1, 0.3)
    D = _largest(s) or ref_disp(s)

    def reading(d: np.ndarray) -> np.ndarray:
        x = side * d / D
        trans = np.where(x >= 0, np.exp(-g * x), 1 + h * np.tanh(g * np.abs(x) / h))
        return side * D * (1 - trans) / g

    _table_map(s, reading)


def ld_push_pull_triangulation(s: Session) -> None:
    """Two triangulation heads facing the strip's two faces at the tip (a push-pull pair, to cancel the stand's sway),
    both without linearisation tables and calibrated near their reference distance Z0 (40-100 mm; the second head's Z0
    0.8-1.25 of the first's), each spot's image moving as d/(Z0 + d) (inject_fresh2's single head): the lab takes half
    their difference, d Z1/(Z1 + d)/2 + d Z2/(Z2 - d)/2. The pair cancels most of the single head's even part and leaves
    an odd one that reads the large bends long on both sides. Tabulated and interpolated (slope 1 at rest,
    inject_fresh22._table_map); displacement only. Measured (s001_152) displacement RMS -0.23 % (residual 0.24 %, 7.6x
    its noise), the 1 V steps at 4.67-4.70 mm for 4.69-4.71 mm (the pair's Z0 apart: the even part reads the steps' side
    short)."""
    z1 = s.rng.uniform(0.04, 0.1)
    z2 = z1 * s.rng.uniform(0.8, 1.25)
    _table_map(s, lambda d: 0.5 * d * z1 / (z1 + d) + 0.5 * d * z2 / (z2 - d))


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_microwave_oven(s: Session) -> None:
    """The microwave oven in the lab's kitchen corner, on the bench's circuit, used 2-5 times in the session (1-4 min
    each, log, each starting inside a recorded series) at a reduced power level: its timer switches the magnetron on for
    a share D (0.3-0.7) of every power cycle (20-30 s), and while on, its high-voltage transformer (a half-wave doubler,
    drawing on one half-cycle) loads the line with a strongly one-sided current, whose field puts the line (50 or 60 Hz)
    with its even harmonics (2nd 0.3-0.6, 3rd 0.1-0.3, 4th 0.05-0.15) on the laser's cable and the current amplifier's
    input: 4-12 um (log) on the displacement, 30-100 uA (log) on the current; the oven's fan and lamp a weaker line
    (0.1-0.2 of it) throughout each use. Phase locked to the session clock; the relay's edges sharp. Measured
    (paper_151) displacement residual 0.058 % of its RMS (3.6x its noise), current residual 0.36 % (0.27x its noise); 14
    of the 68 time series touched."""
    f0 = _line_f(s)
    uses = _bursts(s, int(s.rng.integers(2, 6)), (60.0, 240.0))
    duty, period, ph = s.rng.uniform(0.3, 0.7), s.rng.uniform(20.0, 30.0), s.rng.uniform(0.0, 1.0)
    harm = {2: s.rng.uniform(0.3, 0.6), 3: s.rng.uniform(0.1, 0.3), 4: s.rng.uniform(0.05, 0.15)}
    fan = s.rng.uniform(0.1, 0.2)
    amp = {"disp_m": lu(s.rng, 4e-6, 1.2e-5), "i_A": lu(s.rng, 3e-5, 1e-4)}
    phase = {col: s.rng.uniform(0, 2 * np.pi) for col in amp}
    for r in s.series():
        t = r.cols["t_s"]
        using = _ramp_env(t, uses, 1e-3)
        if not using.any():
            continue
        level = using * np.where(((t / period + ph) % 1.0) < duty, 1.0, fan)
        for col, a in amp.items():
            r.cols[col] = r.cols[col] + a * level * _hum(t, f0, harm, phase[col])


def mp_rse_step_task(s: Session) -> None:
    """The step records taken by the lab's older acquisition task (the step script), which configures the laser's and
    the current amplifier's channels single-ended (RSE, against the DAQ's own ground) where the sine records' task reads
    them differentially: the DAQ's ground and the instruments' grounds differ by the line's drop along the shared earth,
    so the step records, and only they, carry hum (50 or 60 Hz with its 3rd, 0.1-0.4): 4-12 um (log) on the
    displacement, 30-80 uA (log) on the current. Phase locked to the session clock. Measured (p18_153) displacement
    residual 0.20 % of its RMS (4.3x its noise), current residual 0.67 % (0.47x its noise)."""
    f0 = _line_f(s)
    harm = {3: s.rng.uniform(0.1, 0.4)}
    amp = {"disp_m": lu(s.rng, 4e-6, 1.2e-5), "i_A": lu(s.rng, 3e-5, 8e-5)}
    phase = {col: s.rng.uniform(0, 2 * np.pi) for col in amp}
    for r in s.series():
        if r.kind != "step":
            continue
        for col, a in amp.items():
            r.cols[col] = r.cols[col] + a * _hum(r.cols["t_s"], f0, harm, phase[col])


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_joule_bimorph(s: Session) -> None:
    """A strip in air warmed by its own dissipation: the Joule heat of its current in the electrodes' surface resistance
    and the membrane (R_s i^2, R_s 15-50 ohm, log) and of its leak (v^2/R_p, R_p 1-4 kOhm, log) raises its temperature
    through its thermal lag (tau_th 5-20 s, log, against the air's convection; cooling over the rests), and the strip,
    its two faces plated unevenly, bends as a bimorph with it: a one-signed bend (the side drawn) that follows the
    power, not the drive's sign, 3-10 um (log) at the session's hottest. An even, slow companion of every large drive,
    in the displacement only. Measured (s001_152) displacement residual 0.097 % of its RMS (3.1x its noise), 3.9 um at
    its largest."""
    side, r_s, r_p = _sign(s), lu(s.rng, 15.0, 50.0), lu(s.rng, 1e3, 4e3)
    tau, amp = lu(s.rng, 5.0, 20.0), lu(s.rng, 3e-6, 1e-5)
    temp, x, t_end = {}, 0.0, None
    for r in _chrono(s):
        t, v, i = r.cols["t_s"], r.cols["v_V"], r.cols["i_A"]
        if t_end is not None:
            x *= math.exp(-max(float(t[0]) - t_end, 0.0) / tau)
        p = r_s * i**2 + v**2 / r_p
        a = math.exp(-1.0 / (r.fs * tau))
        out = np.empty(t.size)
        for k, pk in enumerate(p.tolist()):
            x = pk + (x - pk) * a
            out[k] = x
        temp[id(r)] = out
        t_end = float(t[-1])
    top = max(float(np.max(x)) for x in temp.values()) or 1.0
    map_disp(s, lambda r, d: d + side * amp * temp[id(r)] / top)


def out_building_sway(s: Session) -> None:
    """The lab on an upper floor of a tall building on a windy day: the building sways at its first mode (f_b 0.3-1 Hz,
    damping 0.01-0.03), excited by the gusts (a forcing whose strength wanders, log-normal with 0.3-0.6 of spread,
    correlation 30-120 s, log), and the floor's tilt rocks the laser's tall stand against the clamp's short one: a
    narrow-band random motion at f_b, 1-4 um RMS (log), of the reading and not of the strip, independent of the drive
    and of the records. A 2nd-order resonator on a 20 Hz session grid, taken onto each record's samples; displacement
    only. Measured (paper_151) 1.7 um RMS, displacement residual 0.050 % of its RMS (3.1x its noise); (p18_153) 2.3 um
    RMS, 0.18 % (4.1x)."""
    fb, zeta = s.rng.uniform(0.3, 1.0), s.rng.uniform(0.01, 0.03)
    spread, corr, rms = s.rng.uniform(0.3, 0.6), lu(s.rng, 30.0, 120.0), lu(s.rng, 1e-6, 4e-6)
    dt = 0.05
    tg = _session_grid(s, dt, 600.0)
    gust = np.exp(spread * _ou(s, tg, corr))
    w = s.rng.normal(size=tg.size) * gust
    wn = 2 * math.pi * fb
    x = lti(w, 1.0 / dt, lambda z: wn * wn / (z * z + 2 * zeta * wn * z + wn * wn))
    keep = tg >= s.t0
    x = x / (float(np.std(x[keep])) or 1.0) * rms
    map_disp(s, lambda r, d: d + np.interp(r.cols["t_s"], tg, x))


def out_held_input_filters(s: Session) -> None:
    """An isolated DAQ front end, one sample-and-hold isolation amplifier per channel, that the logger puts on hold when
    it stops the acquisition and releases at each record's arming: each amplifier's output has held the last value of
    the record before (the first record: 0, as powered up) through the rest, and settles from it to the live input
    through its output filter (tau 3-15 ms, log) once released. Every DAQ channel alike (the drive's monitor, the
    current, the laser; the load cell is read over its own serial line): each record starts with a transient from the
    last record's end value, x + (x_prev_end - x_0) exp(-(t - t_0)/tau), none in the strip itself. Measured (paper_151)
    displacement residual 0.21 % of its RMS (13x its noise), 1.3 mm at a record's start at most, current residual 1.6 %
    (1.2x its noise), 3.2 mA at most, the drive monitor's 0.03x its noise; (p18_153) displacement 0.18 % (4.0x), 0.45 mm
    at most, current 1.4 % (0.98x)."""
    tau = lu(s.rng, 3e-3, 1.5e-2)
    held = {"v_V": 0.0, "i_A": 0.0, "disp_m": 0.0}
    for r in _chrono(s):
        t = r.cols["t_s"]
        fade = np.exp(-(t - t[0]) / tau)
        for col in held:
            x = r.cols[col]
            end = float(x[-1])
            r.cols[col] = x + (held[col] - float(x[0])) * fade
            held[col] = end


def out_ao_range_errors(s: Session) -> None:
    """The drive's output task picks its range record by record (the smallest of +-1, +-2, +-5, +-10 V holding the
    record's peak command with 10 % to spare: the 0.5 V sines on +-1 V, the 1 V steps and harmonics on +-2 V), and the
    board's self-calibration holds for its +-10 V range only: each range drives the strip with its own gain error (-1 to
    +1 %) and offset (-4 to +4 mV) from the record's arming to its end, while v_V logs the command. The strip answers (1
    + g_r) v + o_r: each record's current and displacement scaled by its range's gain, plus its response to the offset's
    step from the record's first sample: the strip's own measured unit-step responses at that pressure (_unit_step, the
    pressure's step record from its rise to its fall, held at their last value beyond), the offset's slow bend and its
    charging and leak currents. Measured (s001_152) displacement RMS -0.65 % (residual 0.80 %, 26x its noise), current
    residual 0.37 % (1.0x its noise), the 1 V steps at 4.65-4.68 mm for 4.69-4.71 mm; (p18_153) displacement -1.1 %
    (residual 1.2 %, 25x), current 0.33 % (0.23x), the steps at 3.21-3.22 mm for 3.25 mm."""
    ranges = {1.0: (s.rng.uniform(-0.01, 0.01), s.rng.uniform(-4e-3, 4e-3)),
              2.0: (s.rng.uniform(-0.01, 0.01), s.rng.uniform(-4e-3, 4e-3))}
    units = {float(r.entry["pressure_kPa"]): {col: _unit_step(r, col) for col in ("disp_m", "i_A")}
             for r in reversed(_chrono(s)) if r.kind == "step"}  # the first step record of each pressure, as measured
    for r in s.series():
        peak = 1.1 * float(np.max(np.abs(r.cols["v_V"])))
        g, o = ranges[min((x for x in ranges if x >= peak), default=2.0)]
        unit = units.get(float(r.entry["pressure_kPa"])) or next(iter(units.values()))
        u = r.cols["t_s"] - r.cols["t_s"][0]
        for col, (ts, resp) in unit.items():
            r.cols[col] = (1 + g) * r.cols[col] + o * np.interp(u, ts, resp)


FRESH27_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"laminated_midplane": br_laminated_midplane, "salt_leaching": br_salt_leaching},
    "faradaic_current": {"aged_varistor": far_aged_varistor, "porous_gold_contact": far_porous_gold_contact},
    "hysteresis": {"bridge_snap": hy_bridge_snap, "thixotropic_clay": hy_thixotropic_clay},
    "time_delay": {"tracking_stage_latency": td_tracking_stage_latency, "dual_range_head": td_dual_range_head},
    "sensor_offset": {"tripod_floor_sag": so_tripod_floor_sag, "cable_relaxation": so_cable_relaxation},
    "clamp_relaxation": {"cork_pads": cr_cork_pads, "junker_loosening": cr_junker_loosening},
    "dehydration": {"fling_off": dh_fling_off, "kcl_frit_leak": dh_kcl_frit_leak},
    "strain_resistance": {"cnt_overlayer": sr_cnt_overlayer, "relaxing_prestress": sr_relaxing_prestress},
    "large_deflection": {"notched_pof": ld_notched_pof, "push_pull_triangulation": ld_push_pull_triangulation},
    "mains_pickup": {"microwave_oven": mp_microwave_oven, "rse_step_task": mp_rse_step_task},
    "unexplained": {"joule_bimorph": out_joule_bimorph, "building_sway": out_building_sway,
                    "held_input_filters": out_held_input_filters, "ao_range_errors": out_ao_range_errors},
}
inject.register_forms(FRESH27_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_midnight_clock(s: Session) -> None:
    """A logger that stamps its rows with the PC's time of day (seconds since midnight, to 10 us: its export's five
    decimals), and a session run late in the evening: midnight falls in a rest between two records drawn from the
    session's middle (their rest's midpoint 30-70 % into it, midnight at a moment drawn within that rest), so every time
    series before it carries stamps near 86400 s and every one after it starts again from a few seconds. Each record's
    stamps strictly increasing and every value as it was; the spectra, the rows and the manifest's order unchanged. The
    import contract asks t_s strictly increasing within a file and nothing across files; ``labrig import`` takes it (the
    clock then not shared by every record: laid back to back, docs/storage.md)."""
    recs = _chrono(s)
    span = s.t1 - s.t0
    rests = [(float(a.cols["t_s"][-1]), float(b.cols["t_s"][0])) for a, b in zip(recs, recs[1:])]
    mid = [(a, b) for a, b in rests if b > a and 0.3 <= (0.5 * (a + b) - s.t0) / span <= 0.7]
    mid = mid or [max(rests, key=lambda x: x[1] - x[0])]
    a, b = mid[int(s.rng.integers(0, len(mid)))]
    m = a + (b - a) * s.rng.uniform(0.1, 0.9)
    for r in s.series():
        t = r.cols["t_s"] + (DAY_S - m)
        r.cols["t_s"] = np.round(np.where(t >= DAY_S, t - DAY_S, t), 5)


inject.VARIANTS.update({"midnight_clock": v_midnight_clock})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_151", "s001_152", "p18_153"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 151-153
    "back_relaxation": [("laminated_midplane", 153, T, "log_steps"), ("salt_leaching", 151, P, "coherent_sines")],
    "faradaic_current": [("aged_varistor", 152, S, "midnight_clock"), ("porous_gold_contact", 153, T, "no_spectra")],
    "hysteresis": [("bridge_snap", 152, S, "loadcell_dropout"), ("thixotropic_clay", 151, P, "reversed_laser")],
    "time_delay": [("tracking_stage_latency", 153, T, "fir_decimated"), ("dual_range_head", 153, T, "no_loadcell")],
    "sensor_offset": [("tripod_floor_sag", 152, S, "tared_records"), ("cable_relaxation", 151, P, "swinging_door")],
    "clamp_relaxation": [("cork_pads", 151, P, "merged_loadcell"), ("junker_loosening", 151, P, "measured_pressures")],
    "dehydration": [("fling_off", 152, S, "steps_sines"), ("kcl_frit_leak", 151, P, "split_spectra")],
    "strain_resistance": [("cnt_overlayer", 152, S, "own_clock"), ("relaxing_prestress", 153, T, "cycle_averaged")],
    "large_deflection": [("notched_pof", 153, T, "trigger_clock"),
                         ("push_pull_triangulation", 152, S, "fixed_decimals")],
    "mains_pickup": [("microwave_oven", 151, P, "eis_descending"), ("rse_step_task", 153, T, "short_pretrigger")],
    "unexplained": [("joule_bimorph", 152, S, "float32_time"), ("joule_bimorph", 152, S, "stop_trigger"),
                    ("building_sway", 151, P, "scan_hold"), ("building_sway", 153, T, "decimated3"),
                    ("held_input_filters", 151, P, "midnight_clock"), ("held_input_filters", 153, T, "host_timed"),
                    ("ao_range_errors", 152, S, "shortened_shuffled"), ("ao_range_errors", 153, T, "spectra_last")],
}
CLEAN = [(151, P, "midnight_clock"), (151, P, "two_pressures"), (152, S, "midnight_clock"), (152, S, "settled_sines"),
         (153, T, "asrun"), (153, T, "dropped_packets")]


def fresh27_cases(only: str | None = None) -> list[Case]:
    """The twenty-eighth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    151-153)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh27_cases, "inject_fresh27", "fresh27")
