"""A twenty-first held-out set for the diagnosis (issue 12), fresh20, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh19.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (a water blister under one face's plating
whose stretched skin pushes back as the cube of its volume, chloride from the operator's hands oxidised on the anode
under Cottrell depletion, capillary condensation in ink-bottle pores of a strip in air, a magnet at the tip drawn to a
steel part beside it, wrinkled plated films stiffening as they straighten, carbon-rubber contacts whose resistance
follows the root's moment, a flexing lead loop picking up the hum in proportion to its area), some on the history (the
pores' relays, an isolated transformer's inrush at each switching, a boom's joint slipping at each tightening), some on
time or on the clamp pressure (a pressure-sensitive adhesive softening in the water, the operator's breath wetting a
strip in air at each re-clamping, a laser head's beam pointing drifting while it warms up, elastomer bands relaxing and
following the room's temperature, a magnetic stirrer's vibration hastening the pads' creep, a fume hood's sash, a
polymer osmolyte poured into the bath and mixing, a de-ionised bath taking up carbon dioxide), one linear but not a
single lag (a membrane whose thickness varies, a log-normal spread of back-flow times) and some from the lab's wiring or
settings (a laser stream resampled by causal linear interpolation, a potentiostat's control loop on its slow setting).
Four structures outside the catalogue (truth "unexplained": the current amplifier's slew-rate limit, a drive monitor
whose two polarities have different gains, a stale calibration of one DAQ input range the logger picks per record,
the room's light switched on and off shifting the laser's zero); clean sessions. All on three bases of new seeds
(130-132: the paper strip, the seed-001 strip on its own sweep, the paper strip 24 mm free) and on the earlier sets'
protocol / data-shape variants plus one new here: a table written by a spreadsheet with a fixed number of decimals in
the lab's units (``fixed_decimals``: the displacement to 1 um, the current to 1 uA, the drive to 1 mV, the spectra to
four significant digits).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh19 are reused (importing inject_fresh19 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh20.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh19  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _through
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law
from inject_fresh6 import _blocks
from inject_fresh7 import _superpose
from inject_fresh9 import _dry_by, _gaps, _session_grid
from inject_fresh10 import _station
from inject_fresh12 import _line_f
from inject_fresh14 import _lagged, _largest
from inject_fresh18 import _bv

# the paper's strip 24 mm free (earlier sets used 20, 23, 25-29, 31-40, 42 and 45 mm; its 1 V step peaks near 5.6 mm,
# 8.8 mm x (24/30)^2, inside the laser's +-20 mm): preset "paper_24", base "p24_132", registered in every process
# importing this module
inject.register_free_length("paper_24", 0.024)

inject.BASES.update({
    "paper_130": ("paper-sweep", "paper", 130),
    "s001_131": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 131),
    "p24_132": ("paper-sweep", "paper_24", 132),
})


# ------------------------------------------------------------------------------------------------ tools


def _through_col(s: Session, H: Callable[[Rec], Callable[[np.ndarray], np.ndarray]], memory_s: float,
                 col: str) -> dict[int, np.ndarray]:
    """inject_fresh2._through on another column than the displacement (a stand-in session whose "disp_m" is ``col``):
    id(record) -> the column through H with the session's history."""
    recs = s.series()
    proxy = Session(s.specimen, [Rec(r.entry, {"t_s": r.cols["t_s"], "disp_m": r.cols[col]}) for r in recs],
                    s.preset, s.t0, s.t1)
    out = _through(proxy, H, memory_s)
    return {id(r): out[id(q)] for r, q in zip(recs, proxy.recs)}


def _block_starts(s: Session) -> list[tuple[float, float]]:
    """The pressure blocks in time order: [(pressure, first sample)]."""
    return sorted(((p, a) for p, (a, _) in _blocks(s).items()), key=lambda x: x[1])


def _relays(u: np.ndarray, up: np.ndarray, dn: np.ndarray, state: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Relays (on at or above ``up``, off at or below ``dn`` < up, held between) on the input u from ``state`` (one
    0/1 per relay): returns (n, len(up)) and the last state."""
    ev = np.where(u[:, None] >= up[None, :], 1.0, np.where(u[:, None] <= dn[None, :], 0.0, np.nan))
    ev = np.vstack([state[None, :], ev])
    idx = np.where(np.isnan(ev), 0, np.arange(ev.shape[0])[:, None])
    idx = np.maximum.accumulate(idx, axis=0)
    out = np.take_along_axis(ev, idx, axis=0)[1:]
    return out, out[-1].copy()


def _sig(x: np.ndarray, digits: int) -> np.ndarray:
    """x rounded to ``digits`` significant digits (zeros kept)."""
    x = np.asarray(x, float)
    mag = np.where(x == 0, 1.0, 10.0 ** (np.floor(np.log10(np.abs(np.where(x == 0, 1.0, x)))) - (digits - 1)))
    return np.round(x / mag) * mag


# ------------------------------------------------------------------------------------------------ back relaxation


def br_electrode_blister(s: Session) -> None:
    """One face's plating has lifted off the membrane over a patch (a blister, a known IPMC defect after boiling or
    drying cycles): the water the bend drives to that face collects under the lifted skin, whose stretching (Hencky's
    clamped-membrane blister: its pressure grows as the cube of its volume once the skin stretches more than it
    bends) pushes it back the faster the more it holds. The back-flow's state x lags the bend d, dx/dt = (d - x)/tau
    (tau 3-12 s, log), times 1 + ((d - x)/u_b)^2 while the water sits on the blistered face (u_b 0.3-0.8 of the
    displacement scale); read d - K2 x (K2 0.8-1.2). Fast and deep back-relaxation after the large bends towards one
    side, slow after the small ones and after the other side. Sample by sample through the session in time order
    (inject_fresh9._gaps, the bend linear across the rests); displacement only. Measured (paper_130) displacement RMS
    -78 % (residual 91 %, 5900x its noise)."""
    k2, tau, side = s.rng.uniform(0.8, 1.2), lu(s.rng, 3.0, 12.0), _sign(s)
    ub = s.rng.uniform(0.3, 0.8) * ref_disp(s)
    x, d_end = 0.0, 0.0

    def step(dk: float, dt: float) -> None:
        nonlocal x
        u = dk - x
        g = 1.0 + (u / ub) ** 2 if side * u > 0 else 1.0
        x += -math.expm1(-g * dt / tau) * u

    for r, gap in _gaps(s, 0.5):
        d = r.cols["disp_m"]
        for dt, w in gap:
            step(d_end + w * (float(d[0]) - d_end), dt)
        dt, out = 1.0 / r.fs, np.empty(d.size)
        for k, dk in enumerate(d.tolist()):
            step(dk, dt)
            out[k] = x
        d_end = float(d[-1])
        r.cols["disp_m"] = d - k2 * out


def br_thickness_spread(s: Session) -> None:
    """A hot-pressed (or solution-cast) membrane whose thickness varies over the strip by a coefficient of variation
    of 0.1-0.25 (log-normal): the back-flow across it is a diffusion over its thickness, so each part's lag goes as
    its thickness squared (tau_0 3-15 s, log, at the mean thickness) and each part's share of the bend as its
    thickness squared too (the actuation moment): a log-normal spread of back-flow times (sigma of ln tau twice that
    of the thickness), 1 - K2 sum w_j/(1 + tau_j s) over a 16-point Gauss-Hermite quadrature (K2 0.8-1.2). Linear;
    not one lag, nor a Cole-Cole, Havriliak-Negami or stretched-exponential spread. Through inject_fresh2._through
    with 60 s of the session's history; displacement only. Measured (p24_132) displacement RMS -75 % (residual 110 %,
    4400x its noise)."""
    cv, tau0, k2 = s.rng.uniform(0.1, 0.25), lu(s.rng, 3.0, 15.0), s.rng.uniform(0.8, 1.2)
    sig = math.sqrt(math.log(1 + cv**2))
    z, w = np.polynomial.hermite_e.hermegauss(16)
    h = np.exp(sig * z)
    w = w * h**2
    w = w / w.sum()
    taus = tau0 * h**2
    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        return lambda q: 1 - k2 * (w[None, :] / (1 + taus[None, :] * np.asarray(q)[:, None])).sum(axis=1)

    new = _through(s, H, 60.0)
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ faradaic current


def far_sweat_chloride(s: Session) -> None:
    """Chloride in the bath from the operator's bare hands (the strip and the pads handled without gloves: sweat's
    salt, tens of micromolar): whichever face is the anode oxidises it beyond an onset v_cl (0.55-0.8 V of drive),
    with a Tafel rise (b 40-80 mV) to i_k1 (0.4-1.5 mA at 1 V, log) but limited by the chloride's diffusion to the
    face: the limit i_L0 (0.4-1.5 mA, log) falls as 1/sqrt(1 + t_d/t_c) (Cottrell, t_c 0.5-3 s, log) with the face's
    depletion time t_d, which grows while the face draws near its limit and refills at rest (20-120 s, log); i = i_k
    i_L/(i_k + i_L). Each face its own layer. A current that appears only on the large drives and sags through each
    hold, fresh again after a rest. Sample by sample through the session in time order (inject_fresh9._gaps); the
    current only. Measured (p24_132) current RMS +0.36 % (residual 1.7 %, 1.3x its noise)."""
    v_cl, b, ik1 = s.rng.uniform(0.55, 0.8), s.rng.uniform(0.04, 0.08), lu(s.rng, 4e-4, 1.5e-3)
    il0, t_c, t_r = lu(s.rng, 4e-4, 1.5e-3), lu(s.rng, 0.5, 3.0), lu(s.rng, 20.0, 120.0)
    norm = math.expm1((1 - v_cl) / b)
    dep = [0.0, 0.0]  # face A (the anode for v < 0), face B (v > 0)
    for r, gap in _gaps(s, 5.0):
        for dt, _ in gap:
            dep = [x * math.exp(-dt / t_r) for x in dep]
        dt, v = 1.0 / r.fs, r.cols["v_V"]
        out = np.zeros(v.size)
        for k, vk in enumerate(v.tolist()):
            f = 1 if vk > 0 else 0
            m = abs(vk)
            dep[1 - f] *= math.exp(-dt / t_r)
            if m > v_cl:
                ik = ik1 * math.expm1((m - v_cl) / b) / norm
                il = il0 / math.sqrt(1 + dep[f] / t_c)
                i = ik * il / (ik + il)
                dep[f] += dt * i / il
                out[k] = math.copysign(i, vk)
            else:
                dep[f] *= math.exp(-dt / t_r)
        r.cols["i_A"] = r.cols["i_A"] + out


def far_breath_film(s: Session) -> None:
    """A strip in air electrolyses the water of its surface film (a symmetric Butler-Volmer branch, 0.05-0.2 mA at 1
    V, log, v_t 0.1-0.2 V, on the film it holds in the room's air). At each re-clamping (10-40 s before a block's
    first record, and at the mounting before the first) the operator leans over the strip and breathes on it, and his
    fingers on the jaws wet its root: the film thickens by b (1-3 times its dry-room share) and dries back over tau_f
    (20-90 s, log), the electrolysis with it. A leak current that is largest at each block's start and falls to its
    room level within a minute or two, every block again. The current only. Measured (s001_131) current RMS +0.39 %
    (residual 1.4 %, 3.7x its noise)."""
    i1, vt = lu(s.rng, 5e-5, 2e-4), s.rng.uniform(0.1, 0.2)
    b, tau_f, lead = s.rng.uniform(1.0, 3.0), lu(s.rng, 20.0, 90.0), s.rng.uniform(10.0, 40.0)
    touches = np.array([a - lead for _, a in _block_starts(s)])

    def film(t: np.ndarray) -> np.ndarray:
        u = t[:, None] - touches[None, :]
        return 1 + b * np.sum(np.where(u >= 0, np.exp(-np.clip(u, 0, None) / tau_f), 0.0), axis=1)

    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + film(r.cols["t_s"]) * _bv(r.cols["v_V"], i1, vt)


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_inkbottle_pores(s: Session) -> None:
    """A strip in air whose plated faces hold water in ink-bottle pores (wide bodies behind narrow necks: the rough
    plating over the membrane): the drive pushes water towards its cathode face and draws it from the other, and a
    pore fills by capillary condensation only once its face's water passes the body's threshold (Kelvin, the body's
    radius) and empties only below its neck's, lower one (Everett's independent domains): 48 pores a face, their fill
    thresholds 0.15-0.9 V of drive (log-normal radii), their emptying ones 0.3-1.1 V lower, those left between them
    empty at the mounting (the strip dried in the room). The condensed water swells its face: the bend gains k
    (0.05-0.15 V of drive) times the filled share of face B (the cathode for v > 0) less face A's. A loop in the bend
    that stays at the lowest rates. The pores' extra swelling, in volts of drive, reaches the displacement through
    the strip's measured step response (inject_fresh7._superpose, current untouched: the pores take water, not
    charge). Measured (s001_131) displacement RMS +17 % (residual 20 %, 640x its noise)."""
    n, k = 48, s.rng.uniform(0.05, 0.15)
    up = [np.exp(s.rng.uniform(math.log(0.15), math.log(0.9), n)) for _ in range(2)]
    dn = [u - s.rng.uniform(0.3, 1.1, n) for u in up]
    state = [np.zeros(n), np.zeros(n)]
    e = {}
    for r in _chrono(s):
        v = r.cols["v_V"]
        fb, state[1] = _relays(v, up[1], dn[1], state[1])
        fa, state[0] = _relays(-v, up[0], dn[0], state[0])
        e[id(r)] = k * (fb.mean(axis=1) - fa.mean(axis=1))
    _superpose(s, e, {"i_A": 0.0})


def hy_psa_laminate(s: Session) -> None:
    """A thin polyester film laminated on one face of the strip with a pressure-sensitive adhesive (a reflector for
    the laser, or a stiffener): while the adhesive holds, the film's restraint takes a share c (0.05-0.15) off the
    bend; its shear yields beyond r (0.2-0.5 V of drive in the actuation it resists) and the film slips
    (elastic-perfectly plastic interface: the bend c (play_r(v) - v) off the free one). In the bath the adhesive
    takes up water and softens: r falls to r_inf (0.3-0.6 of it) as exp(-u/tau_w) (tau_w 600-3000 s, log, from the
    lamination 0-600 s before the first record). Loops that widen in share as the session goes on. The play sample by
    sample through the session in time order (the rests at 0 V), in volts of drive, reaching the displacement through
    the strip's measured step response (inject_fresh7._superpose, current untouched). Measured (paper_130)
    displacement RMS +0.5 % (residual 3.5 %, 230x its noise)."""
    c, r0, r_inf = s.rng.uniform(0.05, 0.15), s.rng.uniform(0.2, 0.5), s.rng.uniform(0.3, 0.6)
    tau_w, lead = lu(s.rng, 600.0, 3000.0), s.rng.uniform(0.0, 600.0)
    t_lam = s.t0 - lead
    y, e = 0.0, {}
    for r in _chrono(s):
        t, v = r.cols["t_s"], r.cols["v_V"]
        rad = r0 * (r_inf + (1 - r_inf) * np.exp(-(t - t_lam) / tau_w))
        y = min(max(y, -float(rad[0])), float(rad[0]))  # the rest at 0 V
        out = np.empty(v.size)
        for k, (vk, rk) in enumerate(zip(v.tolist(), rad.tolist())):
            y = min(max(y, vk - rk), vk + rk)
            out[k] = y
        e[id(r)] = c * (out - v)
    _superpose(s, e, {"i_A": 0.0})


# ------------------------------------------------------------------------------------------------ time delay


def td_frame_interpolation(s: Session) -> None:
    """The laser streams its readings on a clock of its own (f_L 150-600 Hz, log: a high-resolution head's slow
    sampling cycle) and the logging script puts them on the DAQ's sample clock by linear interpolation between the
    two newest frames it has received (causal: it cannot wait for the next), after a transfer latency of 1-5 ms:
    every DAQ sample is the frames' straight line one frame period and the latency in the past. A delay of T_L +
    latency with the gentle sinc^2 gain of a first-order hold (not a sample-and-hold's steps). The frames read from
    the session's record in time order (linear across the rests); displacement only. Measured (paper_130)
    displacement RMS -0.0015 % (residual 0.15 %, 9.8x its noise)."""
    tl, lat, ph = 1.0 / lu(s.rng, 150.0, 600.0), s.rng.uniform(1e-3, 5e-3), s.rng.uniform(0.0, 1.0)
    recs = _chrono(s)
    T = np.concatenate([r.cols["t_s"] for r in recs])
    D = np.concatenate([r.cols["disp_m"] for r in recs])
    origin = s.t0 - 1.0 + ph * tl
    new = {}
    for r in recs:
        t = r.cols["t_s"]
        k0 = int(math.floor((float(t[0]) - lat - tl - origin) / tl)) - 1
        k1 = int(math.ceil((float(t[-1]) - lat - origin) / tl)) + 1
        tf = origin + np.arange(k0, k1 + 1) * tl
        df = np.interp(tf, T, D, left=0.0)
        new[id(r)] = np.interp(t - lat - tl, tf, df)
    map_disp(s, lambda r, d: new[id(r)])


def td_potentiostat_bandwidth(s: Session) -> None:
    """The strip driven by a potentiostat in two-electrode mode, its bandwidth switch left on its slow, high-stability
    setting (for the large capacitive load), and the logger recording its set-point (the DAQ's analogue output), not the
    cell's voltage: the voltage the strip gets follows the set-point through the control loop's closed-loop response, a
    second-order low-pass of corner f_0 (40-200 Hz, log) and quality Q (0.5-0.85), a delay of about 1/(2 pi f_0 Q) on
    the drive. Both the current and the displacement respond to the delayed drive (the strip linear: the filter taken on
    both outputs, inject_fresh2._through with 0.5 s of the session's history); the recorded drive untouched. Measured
    (p24_132) displacement RMS -0.001 % (residual 0.15 %, 5.8x its noise), current RMS -1.1 % (residual 40 %, 29x its
    noise)."""
    w0, q = 2 * math.pi * lu(s.rng, 40.0, 200.0), s.rng.uniform(0.5, 0.85)
    H = lambda r: (lambda z: 1.0 / (1.0 + np.asarray(z) / (q * w0) + (np.asarray(z) / w0) ** 2))  # noqa: E731
    nd, ni = _through(s, H, 0.5), _through_col(s, H, 0.5, "i_A")
    for r in s.series():
        r.cols["disp_m"], r.cols["i_A"] = nd[id(r)], ni[id(r)]


# ------------------------------------------------------------------------------------------------ sensor offset


def so_warmup_pointing(s: Session) -> None:
    """The laser head switched on 0-600 s before the first record and aimed at once, its spot a margin m (0.1-0.4 mm)
    inside the tip's end: as the head warms up its diode's mount expands and the beam's pointing drifts, the spot
    walking inboard along the strip by Delta (0.4-1.5 mm) as 1 - exp(-u/tau_w) (tau_w 300-1500 s, log) from the
    switching on. The strip read at the moving station (inject_fresh10._station); displacement only. Measured
    (s001_131) displacement RMS -8.5 % (residual 8.6 %, 270x its noise)."""
    L = float(s.specimen["length_m"])
    lead, m = s.rng.uniform(0.0, 600.0), s.rng.uniform(1e-4, 4e-4)
    dlt, tau = s.rng.uniform(4e-4, 1.5e-3), lu(s.rng, 300.0, 1500.0)
    t_on = s.t0 - lead
    _station(s, lambda r: 1 - (m + dlt * -np.expm1(-(r.cols["t_s"] - t_on) / tau)) / L, 1 - (m + dlt) / L)


def so_arm_joint_slip(s: Session) -> None:
    """The clamp held at the end of an articulated arm (a central-lock arm of the kind used for dial gauges), the
    strip hanging tip down, the laser on the table with its beam level, aimed once at the first setting a margin m
    (0.1-0.4 mm) inside the tip's end. Tightening the jaw's screw at each re-clamping loads the arm's locked joint
    with the screw's torque (in proportion to the setting): beyond the joint's friction, a share f_j (0.2-0.6) of the
    top setting's torque, the joint slips and the clamp sinks by k (0.2-0.8 mm) times the excess over the top
    setting's, for good. The beam then meets the strip higher, inboard: the station steps inboard at the re-clampings
    to tighter settings and never back. The strip read at its block's station (inject_fresh10._station); displacement
    only. Measured (p24_132) displacement RMS -3.9 % (residual 4.8 %, 190x its noise)."""
    L = float(s.specimen["length_m"])
    m, fj, k = s.rng.uniform(1e-4, 4e-4), s.rng.uniform(0.2, 0.6), s.rng.uniform(2e-4, 8e-4)
    blocks = _block_starts(s)
    top = max(p for p, _ in blocks)
    sink, total = {}, 0.0
    for j, (p, _) in enumerate(blocks):
        if j > 0:
            total += k * max(p / top - fj, 0.0) / (1 - fj)
        sink[p] = total
    _station(s, lambda r: np.full(r.cols["t_s"].size, 1 - (m + sink[float(r.entry["pressure_kPa"])]) / L),
             1 - (m + total) / L)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_elastomer_band(s: Session) -> None:
    """A clamp closed by elastomer bands (O-rings stretched over the jaws' posts, as many and as far as the setting
    needs): the force of a stretched rubber relaxes as r log10(1 + u/tau) (r 2-6 % a decade, tau 2-20 s, log) from
    each setting (10-40 s before its block), and at its fixed stretch it goes as the absolute temperature (entropy
    elasticity: +0.34 % a kelvin), which the room's air conditioning cycles by +-0.5-1.5 K (a period of 900-2400 s).
    The force relative to its setting through the preset's clamp law (inject_fresh4._clamp_law), the load cell
    showing it. Measured (s001_131) displacement RMS -0.024 % (residual 0.039 %, 1.2x its noise), current RMS +0.27 %
    (residual 0.48 %, 1.3x its noise), the load cell at 0.894-0.961 of its reading."""
    rr, tau, lead = s.rng.uniform(0.02, 0.06), lu(s.rng, 2.0, 20.0), s.rng.uniform(10.0, 40.0)
    amp, per, ph, t_k = s.rng.uniform(0.5, 1.5), s.rng.uniform(900.0, 2400.0), s.rng.uniform(0, 2 * np.pi), 295.0
    temp = lambda t: amp * np.sin(2 * np.pi * t / per + ph)  # noqa: E731  K about the mean

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        t0 = t_set - lead
        return (1 - rr * np.log10(1 + np.clip(t - t0, 0, None) / tau)) * (t_k + temp(t)) / (t_k + temp(np.array([t0])))

    _clamp_law(s, rel)


def cr_stirrer_vibration(s: Session) -> None:
    """A magnetic stirrer under the bath, switched on by the operator now and then to mix it (3-6 spells of 60-300
    s): its motor and the spinning bar shake the clamp's stand, and vibration hastens the pads' creep (acoustic
    softening of the polymer: the creep's clock runs A 10-50 times faster while shaken). The pads relax as r ln(1 +
    xi/tau) (r 1-3 %, tau 5-30 s, log) in that clock xi from each setting (10-40 s before its block). Steps of faster
    relaxation during the spells, whatever the block. Through the preset's clamp law (inject_fresh4._clamp_law), the
    load cell showing it. Measured (paper_130) displacement RMS -0.00052 % (residual 0.13 %, 8.3x its noise), current
    RMS -0.085 % (residual 0.76 %, 0.57x its noise), the load cell at 0.876-0.980 of its reading."""
    rr, tau, lead = s.rng.uniform(0.01, 0.03), lu(s.rng, 5.0, 30.0), s.rng.uniform(10.0, 40.0)
    acc, n = s.rng.uniform(10.0, 50.0), int(s.rng.integers(3, 7))
    starts, lens = s.rng.uniform(s.t0, s.t1, n), s.rng.uniform(60.0, 300.0, n)
    tg = _session_grid(s, 0.5, 200.0)
    on = np.any((tg[:, None] >= starts[None, :]) & (tg[:, None] < starts[None, :] + lens[None, :]), axis=1)
    xi = np.r_[0.0, np.cumsum(np.where(on[:-1], acc, 1.0) * np.diff(tg))]

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        x0 = float(np.interp(t_set - lead, tg, xi))
        return 1 - rr * np.log1p(np.clip(np.interp(t, tg, xi) - x0, 0, None) / tau)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_fume_hood_sash(s: Session) -> None:
    """A strip in air in a fume hood (the lab keeps its solutions there), a constant-volume hood: with its sash down
    the exhaust draws the air past the strip fast and it dries towards the hood's equilibrium (a loss of 15-35 % of
    its mobile water) over tau (1500-5000 s, log); the operator raises the sash to reach the clamp at each
    re-clamping (from 10-40 s before the block, for 30-120 s), where the air slows and the drying slows by 2-3 times
    (a laminar boundary layer: as the air's speed's square root). The strip mounted 0-600 s before the first record.
    The gain as the water, the conductance as its 1.5-2.5th power, relative to the first record, the spectra at the
    next series' start (inject_fresh9._dry_by). Measured (s001_131) displacement RMS -8.2 % (residual 10 %, 320x its
    noise), current RMS -21 % (residual 24 %, 65x its noise), the spectra's |Z| +17, +33, +46 %."""
    loss_inf, tau, lead = s.rng.uniform(0.15, 0.35), lu(s.rng, 1500.0, 5000.0), s.rng.uniform(0.0, 600.0)
    slow, before, dur, gc = s.rng.uniform(2.0, 3.0), s.rng.uniform(10.0, 40.0), s.rng.uniform(30.0, 120.0), \
        s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 1.0, lead)
    ups = np.array([a - before for _, a in _block_starts(s)])
    sash = np.any((tg[:, None] >= ups[None, :]) & (tg[:, None] < ups[None, :] + dur), axis=1)
    rate = np.where(sash, 1.0 / slow, 1.0) / tau
    w = 1 - loss_inf + loss_inf * np.exp(-np.r_[0.0, np.cumsum(rate[:-1] * np.diff(tg))])
    w0 = float(np.interp(s.t0, tg, w))
    _dry_by(s, lambda t: 1 - np.interp(t, tg, w) / w0, lambda t: 1 - (np.interp(t, tg, w) / w0) ** gc)


def dh_peg_osmotic(s: Session) -> None:
    """A polymer osmolyte in the bath (polyethylene glycol, poured from a stock 0-300 s before the first record to
    raise the bath's viscosity, or left from a gel phantom): too large to enter the membrane, its osmotic pressure
    draws the membrane's water out (the osmotic-stress method), a loss of L_inf (8-25 %) at the bath's final
    concentration; the poured stock mixes through the still bath slowly, the concentration at the strip rising as 1 -
    exp(-u/tau_m) (tau_m 200-900 s, log), and the membrane follows through its sorption lag (60-300 s, log;
    inject_fresh14._lagged). The gain as the water, the conductance as its 1.5-2.5th power, relative to the first
    record, the spectra at the next series' start (inject_fresh9._dry_by). Measured (p24_132) displacement RMS -7.6 %
    (residual 8.8 %, 350x its noise), current RMS -15 % (residual 15 %, 11x its noise), the spectra's |Z| +17, +20,
    +21 %."""
    l_inf, tau_m, lead = s.rng.uniform(0.08, 0.25), lu(s.rng, 200.0, 900.0), s.rng.uniform(0.0, 300.0)
    tau_s, gc = lu(s.rng, 60.0, 300.0), s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 1.0, lead)
    w = _lagged(tg, 1 - l_inf * -np.expm1(-(tg - tg[0]) / tau_m), tau_s)
    w0 = float(np.interp(s.t0, tg, w))
    _dry_by(s, lambda t: 1 - np.interp(t, tg, w) / w0, lambda t: 1 - (np.interp(t, tg, w) / w0) ** gc)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_carbonating_bath(s: Session) -> None:
    """A bath of freshly de-ionised water (0.1-0.2 uS/cm) in an open cuvette: it takes up the air's carbon dioxide,
    its conductivity rising R_inf (5-10) times over tau (1000-4000 s, log) from the filling (0-300 s before the first
    record). The cracks of the tensioned faces (one face, drawn, the more cracked, the other at 0.2-0.5 of its gauge;
    each e^1.5 of its tension over the session's largest) are bridged by the water in them in parallel with the
    platinum's ligaments (the water's share beta 0.5-0.9 of their bridging at the filling): the cracks' resistance
    falls as the water conducts better, 1/(1 - beta + beta sigma/sigma_0). The same bend costs less later. Gains fall
    by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured
    (paper_130) displacement RMS -0.59 % (residual 0.71 %, 46x its noise), current RMS -0.072 % (residual 0.31 %,
    0.23x its noise)."""
    side, o = _sign(s), s.rng.uniform(0.2, 0.5)
    r_inf, tau, lead, beta = s.rng.uniform(5.0, 10.0), lu(s.rng, 1000.0, 4000.0), s.rng.uniform(0.0, 300.0), \
        s.rng.uniform(0.5, 0.9)
    k = ref_disp(s) / (_largest(s) or ref_disp(s))

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        sig = 1 + (r_inf - 1) * -np.expm1(-(r.cols["t_s"] - s.t0 + lead) / tau)
        x = k * e
        return (np.clip(side * x, 0, None) ** 1.5 + o * np.clip(-side * x, 0, None) ** 1.5) / (1 - beta + beta * sig)

    _resist(s, shape, (0.03, 0.08), (0.06, 0.15))


def sr_conductive_rubber(s: Session) -> None:
    """The drive reaches the electrodes through pads of conductive silicone (carbon-black-filled rubber, soft
    contacts that do not score the plating) under the jaws: the rubber is piezoresistive, its resistance going as its
    pressure to the -n (n 1-3), and the bending moment at the root presses one pad's edge harder and eases the other,
    their pressures p (1 +- c x) (x the bend over the session's largest, c 0.2-0.5 at the lightest setting, in
    inverse proportion to the setting's pressure). The two contacts in series: dR/R ((1 + c x)^-n + (1 - c x)^-n -
    2)/2, even in the bend and large at the light settings, nothing at rest. Gains fall by 0.05-0.15 (displacement)
    and 0.1-0.3 (current) per unit of dR/R (inject_fresh3._resist). Measured (p24_132) displacement RMS -0.24 %
    (residual 0.46 %, 19x its noise), current RMS -0.026 % (residual 0.22 %, 0.16x its noise)."""
    nn, c0 = s.rng.uniform(1.0, 3.0), s.rng.uniform(0.2, 0.5)
    p_min = min(s.pressures())
    k = ref_disp(s) / (_largest(s) or ref_disp(s))

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        c = c0 * p_min / float(r.entry["pressure_kPa"])
        x = np.clip(c * k * e, -0.9, 0.9)
        return ((1 + x) ** -nn + (1 - x) ** -nn - 2) / 2

    _resist(s, shape, (0.05, 0.15), (0.1, 0.3))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_tip_magnet_steel(s: Session) -> None:
    """A small magnet glued at the tip (for a Hall sensor, or a tip mass) with a steel part on one side of the strip
    (the clamp's screw, a steel stand's rod, a steel shim under the cuvette) at a gap g_0 (3-5 times the session's
    largest bend) from it: the magnet's attraction goes as (g_0 - y)^-4, a spring of negative stiffness kappa_0
    (0.02-0.06 of the strip's) at rest, stiffer as the tip nears the steel. Quasi-statically the tip settles where
    the strip's elastic pull balances the attraction: d - d_free = side kappa_0 g_0/4 ((1 - side d/g_0)^-4 - 1)
    (solved by Newton's method, sample by sample): the bends towards the steel read long, those away a little short,
    the rest zeroed. Displacement only. Measured (paper_130) displacement RMS +4.8 % (residual 4.9 %, 320x its
    noise)."""
    side, g0, k0 = _sign(s), s.rng.uniform(3.0, 5.0) * (_largest(s) or ref_disp(s)), s.rng.uniform(0.02, 0.06)
    a = k0 * g0 / 4

    def read(r: Rec, d0: np.ndarray) -> np.ndarray:
        d = d0.copy()
        for _ in range(30):
            u = np.clip(1 - side * d / g0, 0.3, None)
            f = d - d0 - side * a * (u**-4 - 1)
            fp = 1 - 4 * a / g0 * u**-5
            d = d - f / fp
        return d

    map_disp(s, read)


def ld_wrinkled_film(s: Session) -> None:
    """Plated films left wrinkled by the plating's compressive stress (a wavy platinum or gold skin on the swollen
    polymer): on whichever face the bend stretches, the wrinkles straighten and then the film stiffens sharply, so
    the strip's curvature solves kappa (1 + (kappa/kappa_s)^2) = kappa_free (Cardano's root, sample by sample),
    kappa_s 1.5-3 times the session's largest bend on one face and 1.5-3 times more on the other, less wrinkled one
    (side drawn). Gain falling at the large bends, more one way than the other. Displacement only. Measured (p24_132)
    displacement RMS -5.5 % (residual 6.1 %, 240x its noise)."""
    side, big = _sign(s), (_largest(s) or ref_disp(s))
    ds1 = s.rng.uniform(1.5, 3.0) * big
    ds2 = ds1 * s.rng.uniform(1.5, 3.0)

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        ds = np.where(side * d > 0, ds1, ds2)
        p, q = ds**2, -(ds**2) * d
        disc = np.sqrt(q**2 / 4 + p**3 / 27)
        return np.cbrt(-q / 2 + disc) + np.cbrt(-q / 2 - disc)

    map_disp(s, read)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_transformer_inrush(s: Session) -> None:
    """An oven (a drying oven, an incubator) in the next room on a thermostat, its large mains transformer switched
    on every 3-10 minutes and left on for 40-70 % of each cycle: while on, its magnetising current's field (the line,
    50 or 60 Hz, with its third harmonic 0.3-0.5) is picked up at 1-4 um and 2-8 uA (log); at each switching its core
    saturates on one polarity (the remanent flux) and the inrush current is a train of one-signed half-cycle pulses
    at the line frequency, peaky (cos^3 of the half cycle), 10-40 times the magnetising current's field at first
    (log) and decaying over tau (0.3-3 s, log). Picked up magnetically (the field's time derivative over the line's
    angular frequency), phase locked to the session clock; displacement and current. A hum that comes and goes with
    the oven, with bursts of even and odd harmonics at its switchings. Measured (paper_130) displacement RMS +7.2e-06
    % (residual 0.026 %, 1.7x its noise), current RMS -0.00012 % (residual 0.053 %, 0.04x its noise)."""
    f0 = _line_f(s)
    per, duty = s.rng.uniform(180.0, 600.0), s.rng.uniform(0.4, 0.7)
    n = int(math.ceil((s.t1 - s.t0 + per) / per))
    ons = s.t0 - s.rng.uniform(0.0, per) + per * np.arange(n) + s.rng.uniform(-0.1, 0.1, n) * per
    pol = np.where(s.rng.random(n) < 0.5, 1.0, -1.0)
    tau, burst, h3 = lu(s.rng, 0.3, 3.0), lu(s.rng, 10.0, 40.0), s.rng.uniform(0.3, 0.5)
    ad, ai = lu(s.rng, 1e-6, 4e-6), lu(s.rng, 2e-6, 8e-6)
    ph = s.rng.uniform(0, 2 * np.pi, 2)
    w = 2 * np.pi * f0

    def field(t: np.ndarray, p: float) -> np.ndarray:
        out = np.zeros(t.size)
        c = np.cos(w * t + p)
        for t_on, sg in zip(ons, pol):
            u = t - t_on
            live = (u >= 0) & (u < duty * per)
            if not np.any(live):
                continue
            pulse = burst * np.where(sg * c > 0, np.abs(c) ** 3, 0.0) * sg * np.exp(-np.clip(u, 0, None) / tau)
            steady = np.sin(w * t + p) + h3 / 3 * np.sin(3 * (w * t + p))
            out += np.where(live, pulse + steady, 0.0)
        return out

    for r in s.series():
        t = r.cols["t_s"]
        dt = 1e-5
        for col, amp, p in (("disp_m", ad, ph[0]), ("i_A", ai, ph[1])):
            r.cols[col] = r.cols[col] + amp * (field(t + dt, p) - field(t - dt, p)) / (2 * dt * w)


def mp_flexing_loop(s: Session) -> None:
    """The current's sense leads run along the strip to a contact near its tip (a four-wire reading of the strip's
    voltage and current from both ends, its pair split there), so the loop they make with the strip flexes with it: a
    mains transformer's stray field through that loop induces the hum (50 or 60 Hz, its third harmonic 0.1-0.3) in
    proportion to the loop's area, which the bend changes, A_0 (1 + d/d_a) (d_a 1-3 times the session's largest bend,
    either sign). 10-40 uA at rest (log) on the current only; the hum modulated by the bend, with sidebands at the
    line plus and minus the drive's frequencies. Measured (s001_131) current RMS +0.0023 % (residual 0.68 %, 1.9x its
    noise)."""
    f0, h3 = _line_f(s), s.rng.uniform(0.1, 0.3)
    da = _sign(s) * s.rng.uniform(1.0, 3.0) * (_largest(s) or ref_disp(s))
    ai, ph, p3 = lu(s.rng, 1e-5, 4e-5), s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi)
    for r in s.series():
        t = r.cols["t_s"]
        wave = np.cos(2 * np.pi * f0 * t + ph) + h3 * np.cos(6 * np.pi * f0 * t + p3)
        r.cols["i_A"] = r.cols["i_A"] + ai * (1 + r.cols["disp_m"] / da) * wave


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_current_slew(s: Session) -> None:
    """The current amplifier's output stage is slew-rate limited (a transimpedance stage on a slow, low-noise op-amp,
    its output swing into the DAQ's cable): the logged current follows the true one no faster than S (0.3-3 A/s in
    current units, log). The 1 V steps' charging spikes rise as ramps and their tops are cut, the fast large sines'
    currents become triangles, the small and slow records untouched: a rate limit on the current alone, no delay, no
    loop in the strip. Sample by sample within each record; the current only. Measured (paper_130) current RMS -0.2 %
    (residual 4.6 %, 3.5x its noise); (s001_131) current RMS -8.5 % (residual 32 %, 88x its noise)."""
    S = lu(s.rng, 0.3, 3.0)
    for r in s.series():
        i, dt = r.cols["i_A"], 1.0 / r.fs
        step, y, out = S * dt, float(i[0]), np.empty(i.size)
        for k, ik in enumerate(i.tolist()):
            y += min(max(ik - y, -step), step)
            out[k] = y
        r.cols["i_A"] = out


def out_monitor_polarity_gain(s: Session) -> None:
    """The drive monitored through an isolation amplifier of the optocoupled kind (two LED/photodiode channels, one
    for each polarity), its channels mismatched: the recorded drive is the true one times 1 + g on one polarity and 1
    - g on the other (g 0.03-0.08, the sign drawn). The strip feels the true drive: the displacement and the current
    as they were, the monitor alone distorted (its even harmonics, its step levels unequal by sign). The drive column
    only. Measured (s001_131) drive RMS +3.1 % (residual 4.8 %); (p24_132) drive RMS -3.5 % (residual 5.7 %)."""
    g = _sign(s) * s.rng.uniform(0.03, 0.08)
    for r in s.series():
        v = r.cols["v_V"]
        r.cols["v_V"] = v * np.where(v > 0, 1 + g, 1 - g)


def out_range_calibration(s: Session) -> None:
    """The logging script sets the DAQ's input range for the laser's analogue output record by record (the smallest
    of +-1, +-2, +-5, +-10 V that holds the record's expected peak with 20 % to spare, the laser's output 0.5-2 V/mm,
    log), and the calibration constants of one of the ranges the small records use are stale (a card swapped and its
    calibration file not updated): that range's gain off by 1.5-4 % and its offset by 0.5-3 mV (either sign). The
    displacement of every record on that range scaled and shifted, the others as they were: a gain that steps with
    the record's size, not with the signal within a record. Displacement only. Measured (paper_130) displacement RMS
    -0.11 % (residual 0.56 %, 36x its noise); (p24_132) displacement RMS -0.22 % (residual 0.9 %, 36x its noise)."""
    scale = lu(s.rng, 500.0, 2000.0)  # V/m
    g, off = _sign(s) * s.rng.uniform(0.015, 0.04), _sign(s) * s.rng.uniform(5e-4, 3e-3)
    ranges = np.array([1.0, 2.0, 5.0, 10.0])

    def rng_of(r: Rec) -> float:
        peak = 1.2 * float(np.max(np.abs(r.cols["disp_m"]))) * scale
        fit = ranges[ranges >= peak]
        return float(fit[0]) if fit.size else 10.0

    used = sorted({rng_of(r) for r in s.series()})
    bad = used[0] if len(used) == 1 else float(s.rng.choice(used[:-1]))
    for r in s.series():
        if rng_of(r) == bad:
            r.cols["disp_m"] = r.cols["disp_m"] * (1 + g) + off / scale


def out_ambient_light_steps(s: Session) -> None:
    """The laser's receiver sees the room's light as a sloping background under its spot's image, which pulls the
    peak it finds by a few tens of um: the room's lights or a window's blind switched 3-8 times in the session (at
    random moments), each state of the room shifting the laser's zero by its own amount (5-50 um, log, either sign;
    the first state the one the laser was zeroed in). Steps in the displacement's zero at moments unrelated to the
    drive or the records, lasting until the next switching; displacement only. Measured (s001_131) displacement RMS
    -0.14 % (residual 1.5 %, 46x its noise); (p24_132) displacement RMS +0.15 % (residual 0.94 %, 38x its noise)."""
    n = int(s.rng.integers(3, 9))
    times = np.sort(s.rng.uniform(s.t0, s.t1, n))
    levels = np.r_[0.0, [_sign(s) * lu(s.rng, 5e-6, 5e-5) for _ in range(n)]]
    map_disp(s, lambda r, d: d + levels[np.searchsorted(times, r.cols["t_s"], side="right")])


FRESH20_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"electrode_blister": br_electrode_blister, "thickness_spread": br_thickness_spread},
    "faradaic_current": {"sweat_chloride": far_sweat_chloride, "breath_film": far_breath_film},
    "hysteresis": {"inkbottle_pores": hy_inkbottle_pores, "psa_laminate": hy_psa_laminate},
    "time_delay": {"frame_interpolation": td_frame_interpolation, "potentiostat_bandwidth": td_potentiostat_bandwidth},
    "sensor_offset": {"warmup_pointing": so_warmup_pointing, "arm_joint_slip": so_arm_joint_slip},
    "clamp_relaxation": {"elastomer_band": cr_elastomer_band, "stirrer_vibration": cr_stirrer_vibration},
    "dehydration": {"fume_hood_sash": dh_fume_hood_sash, "peg_osmotic": dh_peg_osmotic},
    "strain_resistance": {"carbonating_bath": sr_carbonating_bath, "conductive_rubber": sr_conductive_rubber},
    "large_deflection": {"tip_magnet_steel": ld_tip_magnet_steel, "wrinkled_film": ld_wrinkled_film},
    "mains_pickup": {"transformer_inrush": mp_transformer_inrush, "flexing_loop": mp_flexing_loop},
    "unexplained": {"current_slew": out_current_slew, "monitor_polarity_gain": out_monitor_polarity_gain,
                    "range_calibration": out_range_calibration, "ambient_light_steps": out_ambient_light_steps},
}
inject.register_forms(FRESH20_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_fixed_decimals(s: Session) -> None:
    """A lab whose tables pass through a spreadsheet before they are shared, its columns formatted with a fixed number
    of decimals in the lab's units and converted back to SI for the manifest: the displacement in mm to three decimals
    (1 um), the current in mA to three (1 uA), the drive in V to three (1 mV), the load cell in N to three, the time in
    s to six; the spectra with four significant digits (the analyser's display). Every value rounded, nothing else
    changed (rows, clock, manifest). ``labrig import`` takes it (t_s strictly increasing at every rate here)."""
    step = {"t_s": 1e-6, "disp_m": 1e-6, "i_A": 1e-6, "v_V": 1e-3, "force_N": 1e-3}
    for r in s.recs:
        if r.series:
            r.cols = {k: (np.round(x / step[k]) * step[k] if k in step else x) for k, x in r.cols.items()}
        else:
            r.cols = {k: _sig(x, 4) for k, x in r.cols.items()}


inject.VARIANTS.update({"fixed_decimals": v_fixed_decimals})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_130", "s001_131", "p24_132"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 130-132
    "back_relaxation": [("electrode_blister", 130, P, "fixed_decimals"), ("thickness_spread", 132, T, "log_steps")],
    "faradaic_current": [("sweat_chloride", 132, T, "rate07"), ("breath_film", 131, S, "tared_records")],
    "hysteresis": [("inkbottle_pores", 131, S, "settled_sines"), ("psa_laminate", 130, P, "float32_time")],
    "time_delay": [("frame_interpolation", 130, P, "short_pretrigger"),
                   ("potentiostat_bandwidth", 132, T, "trigger_clock")],
    "sensor_offset": [("warmup_pointing", 131, S, "dropped_packets"),
                      ("arm_joint_slip", 132, T, "shortened_shuffled")],
    "clamp_relaxation": [("elastomer_band", 131, S, "merged_loadcell"), ("stirrer_vibration", 130, P, "host_timed")],
    "dehydration": [("fume_hood_sash", 131, S, "fixed_decimals"), ("peg_osmotic", 132, T, "two_pressures")],
    "strain_resistance": [("carbonating_bath", 130, P, "steps_sines"), ("conductive_rubber", 132, T, "coherent_sines")],
    "large_deflection": [("tip_magnet_steel", 130, P, "decimated3"), ("wrinkled_film", 132, T, "resampled")],
    "mains_pickup": [("transformer_inrush", 130, P, "eis_descending"), ("flexing_loop", 131, S, "own_clock")],
    "unexplained": [("current_slew", 130, P, "swinging_door"), ("current_slew", 131, S, "asrun"),
                    ("monitor_polarity_gain", 131, S, "fixed_decimals"),
                    ("monitor_polarity_gain", 132, T, "cycle_averaged"),
                    ("range_calibration", 130, P, "fir_decimated"), ("range_calibration", 132, T, "scan_hold"),
                    ("ambient_light_steps", 131, S, "no_loadcell"), ("ambient_light_steps", 132, T, "fixed_decimals")],
}
CLEAN = [(130, P, "asrun"), (130, P, "fixed_decimals"), (131, S, "asrun"), (131, S, "no_spectra"),
         (132, T, "asrun"), (132, T, "fixed_decimals")]


def fresh20_cases(only: str | None = None) -> list[Case]:
    """The twenty-first held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    130-132)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh20_cases, "inject_fresh20", "fresh20")
