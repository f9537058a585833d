"""A twenty-ninth held-out set for the diagnosis (issue 12), fresh28, written without sight of the diagnosis (its
code, its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh27.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (a hydrogel coat taking the water up at the
faces, electrolysis behind the electrodes' series resistance, a spring-loaded tip contact that lets go of the face at
the large bends, an auxiliary logger's multiplexed delta-sigma converter, cracks whose bridges oxidise while their face
is the anode, a plating thinning towards the tip, a magnetometer beside the tip magnet's path, a receiving lens's
vignetting), some on the history, the clamp pressure or the session's events (ascorbate in the bath used up by its own
oxidation, a silicone grommet's grip relaxing, a lab jack settling at every tightening, a 3D-printed flexure clamp
creeping the more the harder it is set, a powerline network adapter's traffic, a vortex mixer used next to the bench)
and some on time (a strip thawed from the freezer, a webcam's exposure lengthening at dusk, a condensation drop growing
on the cuvette's wall in the beam, glassy shims ageing under the jaws, serum albumin fouling the plating, air from
supersaturated tap water filling the plating's pores); lab wiring or sensors among them (the contact pin, the
converter, the webcam, the jack, the drop, the magnetometer, the receiver, the adapter). Four structures outside the
catalogue (truth "unexplained": the bath's sloshing mode taking energy from the strip as a tuned absorber, a
motorised clamp's stepper hunting about its microstep, a logger storing saturating eight-bit differences, the spectra's
frequency column written in rad/s); clean sessions. All on three bases of new seeds (154-156: the paper strip, the
seed-001 strip on its own sweep, the paper strip 16 mm free) and on the earlier sets' protocol / data-shape variants
plus one new here: a logging program restarted at each re-clamping, its clock counting from its start
(``block_clock``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh27 are reused (importing inject_fresh27 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh28.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh27  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _map_through
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law
from inject_fresh6 import _bursts
from inject_fresh7 import _superpose
from inject_fresh8 import _hum
from inject_fresh9 import _dry_by, _session_grid
from inject_fresh10 import _lag_varying, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh20 import _block_starts, _relays
from inject_fresh22 import _f1, _table_map
from inject_fresh23 import _transmissibility
from inject_fresh24 import _by_pressure_start, _spectrum_top
from inject_fresh25 import _setting_of
from inject_fresh26 import _split_noise

# the paper's strip 16 mm free (earlier sets used 18-29 and 31-45 mm, 30 mm is the paper preset itself and the seed-001
# strip is 20 mm; its 1 V step peaks near 2.6 mm, well inside the laser's +-20 mm): preset "paper_16", base "p16_156",
# registered in every process importing this module
inject.register_free_length("paper_16", 0.016)

inject.BASES.update({
    "paper_154": ("paper-sweep", "paper", 154),
    "s001_155": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 155),
    "p16_156": ("paper-sweep", "paper_16", 156),
})


# ------------------------------------------------------------------------------------------------ tools


def _slab_uptake(q: np.ndarray) -> np.ndarray:
    """A slab's uptake through one face, the other closed: tanh(q)/q (1 at q = 0, 1/q for large q without overflow)."""
    q = np.asarray(q, complex)
    out = np.ones(q.shape, complex)
    big, mid = np.abs(q) > 30.0, (np.abs(q) >= 1e-6) & (np.abs(q) <= 30.0)
    out[mid] = np.tanh(q[mid]) / q[mid]
    out[big] = 1.0 / q[big]
    return out


def _window_means(t: np.ndarray, x: np.ndarray, ends: np.ndarray, width: float) -> np.ndarray:
    """The mean of x (sampled at t, linear between samples, its first value held before t[0]) over [e - width, e] for
    each e of ``ends`` (at most t[-1])."""
    c = np.concatenate([[0.0], np.cumsum(0.5 * (x[1:] + x[:-1]) * np.diff(t))])
    slope = np.diff(x) / np.diff(t)

    def cum(y: np.ndarray) -> np.ndarray:  # the integral of x from t[0] to y, exact for x linear between samples
        i = np.clip(np.searchsorted(t, y, side="right") - 1, 0, t.size - 2)
        dy = y - t[i]
        return np.where(y < t[0], (y - t[0]) * x[0], c[i] + x[i] * dy + 0.5 * slope[i] * dy * dy)

    return (cum(ends) - cum(ends - width)) / width


def _frames(t: np.ndarray, x: np.ndarray, period: float, phase: float, width: float, late: float) -> np.ndarray:
    """A reading taken in frames: each frame the mean of x over its window of ``width`` ending at the frame's time (a
    free-running clock of ``period``, its phase 0-1), ready ``late`` seconds after it; the ready values interpolated
    linearly onto the samples t (the first one held before it)."""
    k0 = math.floor((t[0] - late - width) / period - phase) - 1
    k1 = math.ceil((t[-1] - late) / period - phase) + 1
    ends = (np.arange(k0, k1 + 1) + phase) * period
    ends = ends[ends <= t[-1]]
    return np.interp(t, ends + late, _window_means(t, x, ends, width))


def _chrono_blocks(s: Session) -> list[list[Rec]]:
    """The time series in time order, cut into runs of one clamp pressure (the blocks a re-clamping separates)."""
    out: list[list[Rec]] = []
    for r in _chrono(s):
        if out and float(r.entry["pressure_kPa"]) == float(out[-1][0].entry["pressure_kPa"]):
            out[-1].append(r)
        else:
            out.append([r])
    return out


# ------------------------------------------------------------------------------------------------ back relaxation


def br_hydrogel_coat(s: Session) -> None:
    """A strip in air kept from drying by a hydrogel coat: both faces dip-coated with agarose (1-2 %, 0.2-0.6 mm, a way
    labs run a water-based strip in air). The water the cations drag to the cathode face flows back through the membrane
    as usual (its give-back K_m 0.3-0.6 over tau_m 1-4 s, log, a first-order lag), but it also passes into the coat at
    that face while the anode face draws water out of its own coat: the coat a slab closed by the air at its outer face,
    its exchange with the face the slab's uptake tanh(q)/q, q = sqrt(tau_c s), tau_c = l_c^2/D_c 15-80 s (log), its
    share K_c 0.2-0.4. H = 1 - K_m/(1 + tau_m s) - K_c tanh(q)/q: a quick give-back and a slow diffusive one with a long
    tail. Through inject_fresh2._through with 300 s of the session's history; displacement only. Measured (s001_155)
    displacement RMS -78 % (residual 86 %, 2700x its noise), the 1 V steps at 0.77-0.78 mm 5 s after their edge
    (2.02-2.05 mm clean) and 0.84-0.85 mm by their plateaus' end (4.69-4.72 mm), the stepped sines' gain 0.61 at 0.1 Hz
    and 0.98 at 1.4 Hz."""
    km, tau_m = s.rng.uniform(0.3, 0.6), lu(s.rng, 1.0, 4.0)
    kc, tau_c = s.rng.uniform(0.2, 0.4), lu(s.rng, 15.0, 80.0)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        def h(z: np.ndarray) -> np.ndarray:
            z = np.asarray(z)
            return 1.0 - km / (1.0 + tau_m * z) - kc * _slab_uptake(np.sqrt(tau_c * z + 0j))

        return h

    _map_through(s, H, 300.0)


def br_freeze_thaw(s: Session) -> None:
    """A strip kept in the lab's freezer between sessions (sealed in a bag of water against drying and mould) and thawed
    in the bath 0-300 s before the first record: the ice grown in its ionic clusters left them swollen and the channels
    between them wide, and the polymer network pulls them back as it relaxes (F = exp(-(t - t_thaw)/tau_r), tau_r
    600-2500 s, log). The back-flow, large and quick through the wide channels, weakens and slows as they close: K2 =
    K_inf (1 + g F) (K_inf 0.6-0.9, g 0.2-0.5), tau = tau_inf/(1 + c F) (tau_inf 3-10 s, log, c 1-3). Through
    inject_fresh10._lag_varying (the reading d - K2 x, x the lag of d, sample by sample through the session, carried
    over the rests); displacement only. Measured (paper_154) displacement RMS -59 % (residual 63 %, 3800x its noise),
    the 1 V steps (8.82-8.83 mm clean) at 2.64, 3.61, 3.77, 3.79 mm by their plateaus' end block by block."""
    t_th, tau_r = s.t0 - s.rng.uniform(0.0, 300.0), lu(s.rng, 600.0, 2500.0)
    k_inf, g = s.rng.uniform(0.6, 0.9), s.rng.uniform(0.2, 0.5)
    tau_inf, c = lu(s.rng, 3.0, 10.0), s.rng.uniform(1.0, 3.0)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        f = np.exp(-np.clip(np.asarray(t, float) - t_th, 0.0, None) / tau_r)
        return k_inf * (1.0 + g * f), tau_inf / (1.0 + c * f)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_ascorbate_depletion(s: Session) -> None:
    """A bio-IPMC test in a buffer with ascorbic acid added as an antioxidant (or a cell-culture medium holding it),
    0.1-1 mM in a cuvette of 2-4 ml: ascorbate is oxidised irreversibly at whichever face is the anode, a wave with its
    half-wave at E_h 0.2-0.45 V of drive and a width b 0.04-0.1 V, limited by its diffusion to the face: i = sign(v)
    i_lim c/c_0 / (1 + exp(-(abs(v) - E_h)/b)), i_lim 0.15-0.5 mA (log) at the start. The small bath holds little of it:
    each coulomb the wave passes uses up 1/(2F) mol, so c falls with the charge passed (the bath's whole content is
    1.25-3.3 times the charge the wave would pass over the session at full strength) and by its autoxidation in the open
    bath (half-life 1-4 h, log), through the rests too. Odd and memoryless within a record, weakening with the session's
    history; the current only. Measured (p16_156) current RMS +1.8 % (residual 3.5 %, 2.4x its noise), 0.20, 0.16, 0.12,
    0.09 mA on the 1 V plateaus block by block."""
    e_h, b = s.rng.uniform(0.2, 0.45), s.rng.uniform(0.04, 0.1)
    i_lim, use = lu(s.rng, 1.5e-4, 5e-4), s.rng.uniform(0.3, 0.8)
    k_ox = math.log(2.0) / lu(s.rng, 3600.0, 14400.0)

    def wave(v: np.ndarray) -> np.ndarray:
        return np.sign(v) / (1.0 + np.exp(-np.clip((np.abs(v) - e_h) / b, -60.0, 60.0)))

    recs = _chrono(s)
    waves = {id(r): wave(r.cols["v_V"]) for r in recs}
    q0 = i_lim * sum(float(np.sum(np.abs(waves[id(r)]))) / r.fs for r in recs) / use  # the bath's content as charge
    c, t_end = 1.0, None
    for r in recs:
        t, w = r.cols["t_s"], waves[id(r)]
        if t_end is not None:
            c *= math.exp(-k_ox * max(float(t[0]) - t_end, 0.0))
        rate = k_ox + i_lim * np.abs(w) / max(q0, 1e-30)
        used = np.cumsum(rate) / r.fs
        level = c * np.exp(-(used - rate / r.fs))  # at each sample, before its own share
        r.cols["i_A"] = r.cols["i_A"] + i_lim * level * w
        c, t_end = c * math.exp(-float(used[-1])), float(t[-1])


def far_ir_shielded_electrolysis(s: Session) -> None:
    """The strip's own electrolysis (a symmetric Butler-Volmer branch, i_1 sinh(v_dl/2v_t)/sinh(1/2v_t), i_1 0.1-0.4 mA
    at 1 V, log, v_t 0.1-0.2 V) at the platinum-membrane interface, which sits behind the electrodes' and the membrane's
    series resistance R_u (0.4-0.8 of the strip's high-frequency resistance, the spectra's top point): the interface
    feels v_dl = v - R_u i, so while the double layer charges (a step's edge: tens of milliamperes through R_u, most of
    the volt) the branch stays shut, and it opens as the charging current dies away; on the sines the branch follows the
    drive less the drop of their charging current. The branch's own share of i (a few per cent) left out of the drop.
    Rate-dependent: odd harmonics and a DC part where the drive holds, a delayed onset where it moves fast; the current
    only. Measured (s001_155) current RMS +0.43 % (residual 1.7 %, 4.4x its noise), 0.11 mA at the 1 V plateaus' end,
    0.05 mA 0.1 s after their edges, the 1 V harmonics' current gain 1.009-1.010."""
    i1, vt = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.1, 0.2)
    r_u = s.rng.uniform(0.4, 0.8) * max(_spectrum_top(s)[1].real, 1.0)
    norm = math.sinh(0.5 / vt)
    for r in s.series():
        v_dl = r.cols["v_V"] - r_u * r.cols["i_A"]
        r.cols["i_A"] = r.cols["i_A"] + i1 * np.sinh(np.clip(v_dl / (2.0 * vt), -60.0, 60.0)) / norm


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_grommet_seal(s: Session) -> None:
    """A strip mounted through the side wall of its cuvette (the clamp outside, its contacts kept dry), the wall's hole
    sealed by a silicone grommet whose lips grip both faces just beyond the clamp: each of three lip zones sticks to the
    strip and deflects elastically until its friction gives, then slides (an elastic-perfectly-plastic element, a stop
    operator of radius r_j, 0.02-0.15 of the session's largest bend, log-spread, times 0.7-1.3), the stuck lips adding K
    (0.1-0.25) of stiffness over the strip's own at the tip: the reading u - K mean_j z_j, u the strip's bend as it
    would be, z_j the lips' stops. Small motions see a stiffer strip, large ones slide the lips with loops and a
    remanence. The silicone's grip relaxes under the lips' squeeze from the mounting (300-1800 s before the first
    record, tau 30-300 s, log, 0.3-0.6 of it lost by the session's end, logarithmically): the loops narrow as the
    session goes on. Sample by sample through the session in time order, the laser's noise kept on the held reading
    (inject_fresh26._split_noise); displacement only. Measured (p16_156) displacement RMS -0.42 % (residual 2.1 %, 36x
    its noise), the 20 Hz sines' gain 0.78 (the lips stuck), the 1 V harmonics' 0.96-0.97, the 1 V steps at 2.545,
    2.551, 2.554, 2.555 mm block by block (2.58 mm clean)."""
    big = _largest(s) or ref_disp(s)
    k = s.rng.uniform(0.1, 0.25)
    radii = np.geomspace(0.02, 0.15, 3) * big * s.rng.uniform(0.7, 1.3)
    t_m, tau = s.t0 - s.rng.uniform(300.0, 1800.0), lu(s.rng, 30.0, 300.0)
    c = s.rng.uniform(0.3, 0.6) / math.log10(1.0 + (s.t1 - t_m) / tau)
    _stuck_zones(s, k, radii, lambda t: 1.0 - c * np.log10(1.0 + np.clip(t - t_m, 0.0, None) / tau))


def _stuck_zones(s: Session, k: float, radii: np.ndarray, scale: Callable[[np.ndarray], np.ndarray]) -> None:
    """Zones that stick and slide (stop operators of ``radii`` times ``scale(t)``, the radii changing through the
    session) taking k of the motion: the reading u - k mean_j z_j, sample by sample through the session in time order,
    the laser's noise kept on the held reading (inject_fresh26._split_noise)."""
    z, prev = [0.0] * len(radii), 0.0
    for r in _chrono(s):
        sig, noise = _split_noise(r)
        out = np.empty(sig.size)
        for i, (u, g) in enumerate(zip(sig.tolist(), scale(r.cols["t_s"]).tolist())):
            du, acc = u - prev, 0.0
            for j, rad in enumerate(radii):
                lim = rad * g
                z[j] = min(max(z[j] + du, -lim), lim)
                acc += z[j]
            out[i] = u - k * acc / len(radii)
            prev = u
        r.cols["disp_m"] = out + noise


def hy_pogo_tip_contact(s: Session) -> None:
    """The strip fed at both ends (a lab's remedy for its electrodes' voltage drop): the clamp's contacts at the root
    and a spring-loaded pin (a pogo pin) pressed on one face (drawn) near the tip. Bent away from the pin, the strip
    takes the pin's plunger along until it tops out, and beyond its reach R_p (0.35-0.7 of the session's largest bend
    away from it) the pin leaves the face; it makes contact again only once the strip has come back within R_p (1 - h)
    (h 0.1-0.3: the wet film the returning face must squeeze out, the plunger's stiction in its barrel). While it is
    off, the tip end of the electrode is fed through the electrode alone, and the strip gets a share g (0.04-0.1) less
    of the drive there: a relay on the bend, with memory of the way it came, gating a part of the drive. The drive lost,
    -g v while the pin is off, reaches the current and the displacement through the strip's measured unit-step responses
    (inject_fresh7._superpose; v_V logs the amplifier's output, unchanged); the relay through the session in time order
    on the bend as it would be. Measured (s001_155) displacement RMS -3.9 % (residual 4.4 %, 140x its noise), current
    RMS -0.33 % (residual 2.1 %, 5.5x its noise): the pin off on every 1 V step's plateau (the steps at 4.41-4.44 mm for
    4.69-4.72 mm), the other 64 time series untouched."""
    side, big = _sign(s), _largest(s) or ref_disp(s)
    reach, h, g = s.rng.uniform(0.35, 0.7) * big, s.rng.uniform(0.1, 0.3), s.rng.uniform(0.04, 0.1)
    state, lost = np.zeros(1), {}
    for r in _chrono(s):
        off, state = _relays(-side * r.cols["disp_m"], np.array([reach]), np.array([reach * (1.0 - h)]), state)
        lost[id(r)] = -g * r.cols["v_V"] * off[:, 0]
    _superpose(s, lost)


# ------------------------------------------------------------------------------------------------ time delay


def td_dusk_webcam(s: Session) -> None:
    """No laser: a USB machine-vision camera tracking the tip (a lab's cheaper readout), free running at up to f_max
    (200-400 frames/s), its exposure on automatic in a room lit by the window late in the afternoon: as the daylight
    falls (by a factor of 2-5 over the session, exponentially) the exposure E grows from E_0 (0.5-2 ms, log) in
    proportion, and once E passes the frame period the camera slows its frames to E + 0.3 ms. Each frame's position is
    the tip's mean over its exposure, ready 1-2 frame periods after it ends (the tracker's processing), interpolated
    linearly onto the DAQ's rows: a delay of E/2 + the processing, 3-11 ms at the start and growing with the session's
    time (to 3-26 ms at its end), with the exposure's small averaging. Per record at the exposure of its start (the
    light changes slowly); displacement only. Measured (paper_154) displacement residual 0.12 % of its RMS (7.5x its
    noise): the 20 Hz sines' phase -35 deg in the first block and -46 deg in the last (a delay of 4.9 to 6.4 ms), their
    gain 0.98-0.99, the 1 V steps' residuals 0.04 %."""
    f_max, e0 = float((200.0, 300.0, 400.0)[int(s.rng.integers(0, 3))]), lu(s.rng, 5e-4, 2e-3)
    fall, late, phase = s.rng.uniform(2.0, 5.0), s.rng.uniform(1.0, 2.0), s.rng.uniform(0.0, 1.0)
    span = max(s.t1 - s.t0, 1.0)

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        t = r.cols["t_s"]
        e = e0 * fall ** ((float(t[0]) - s.t0) / span)
        period = max(1.0 / f_max, e + 3e-4)
        return _frames(t, d, period, phase, e, late * period)

    map_disp(s, f)


def td_i2c_adc_scan(s: Session) -> None:
    """The laser's analogue output logged by an auxiliary single-board computer through a four-channel delta-sigma
    converter on its I2C bus (an ADS1115-type: 475 or 860 conversions a second, drawn), scanning its four inputs in turn
    with 0.3-0.6 ms of bus traffic around each conversion, the laser on the k-th (1-3, drawn), and stamping each scan at
    its end; the lab merges the stamped readings onto the DAQ's rows by linear interpolation. Each reading is the
    laser's mean over its conversion (the converter's sinc filter, a boxcar of one conversion period), stamped late by
    the conversions and the traffic that follow it in the scan: a delay of 2.3-9.8 ms and a boxcar of 1.2-2.1 ms, fixed
    for the session. Displacement only. Measured (p16_156) displacement residual 0.18 % of its RMS (3.2x its noise): the
    20 Hz sines' phase -20 deg (2.8 ms) and gain 0.94 (the scans' interpolation), the 4.4 Hz sines' -4.4 deg, the 1 V
    steps' residuals 0.04 %."""
    rate = 475.0 if s.rng.random() < 0.5 else 860.0
    k, bus, phase = int(s.rng.integers(1, 4)), s.rng.uniform(3e-4, 6e-4), s.rng.uniform(0.0, 1.0)
    conv = 1.0 / rate
    scan = 4.0 * (conv + bus)
    late = scan - k * (conv + bus) + bus  # from the laser's conversion's end to the scan's end

    map_disp(s, lambda r, d: _frames(r.cols["t_s"], d, scan, phase, conv, late))


# ------------------------------------------------------------------------------------------------ sensor offset


def so_lab_jack_ratchet(s: Session) -> None:
    """The laser head on a lab jack (a scissor jack, its screw worn) beside a hanging strip, its beam level and aimed a
    margin m0 (0.1-0.3 mm) above the tip's end before the first setting: every re-clamping's tightening jolts the bench,
    and the jack's screw backs off under the head's weight by a little, the more the harder the operator turns the
    clamp's screw (delta_k = delta_1 (p_k/p_min)^a x 0.7-1.3, delta_1 0.05-0.2 mm, a 0.5-1): the head sinks in steps and
    its beam meets the strip further and further inboard, one station per clamp setting. The strip read at the moving
    station (inject_fresh10._station); displacement only. Measured (s001_155) displacement RMS -6.8 % (residual 7.4 %,
    230x its noise), the 1 V steps at 4.53, 4.46, 4.35, 4.21 mm block by block (4.69-4.72 mm clean)."""
    length = float(s.specimen["length_m"])
    m0, d1, a = s.rng.uniform(1e-4, 3e-4), s.rng.uniform(5e-5, 2e-4), s.rng.uniform(0.5, 1.0)
    blocks = _block_starts(s)
    p_min = min(p for p, _ in blocks)
    cum = np.cumsum([d1 * (p / p_min) ** a * s.rng.uniform(0.7, 1.3) for p, _ in blocks])
    starts = np.array([t for _, t in blocks])

    def frac(r: Rec) -> np.ndarray:
        k = np.clip(np.searchsorted(starts, r.cols["t_s"], side="right") - 1, 0, cum.size - 1)
        return 1.0 - (m0 + cum[k]) / length

    _station(s, frac, 1.0 - (m0 + float(cum[-1])) / length)


def so_drop_lens(s: Session) -> None:
    """A bath held at 12-16 C by a Peltier cuvette holder (the protocol's temperature) in a room whose dew point lies
    above it: water condenses on the cuvette's outer wall, and the laser looks through that wall at the strip's tip. A
    drop grows where the beam crosses the wall (its radius as t^(1/3), breath-figure growth) and, a weak lens, deflects
    the beam so that its spot walks along the strip, inboard of its aim (a margin m0 0.1-0.3 mm inside the tip's end) by
    up to Delta (0.3-1 mm) when the drop is at its shedding size; then the drop runs down the wall and a new one starts
    on the clean glass: cycles of 300-1200 s (log, each drawn), the first begun 0-600 s before the first record. A
    sawtooth of the station through the session's time. The strip read at the moving station (inject_fresh10._station);
    displacement only. Measured (paper_154) displacement RMS -5.0 % (residual 5.1 %, 310x its noise), the 1 V steps at
    8.32, 8.34, 8.58, 8.37 mm block by block (8.82-8.83 mm clean)."""
    length = float(s.specimen["length_m"])
    m0, dmax = s.rng.uniform(1e-4, 3e-4), s.rng.uniform(3e-4, 1e-3)
    t, starts, spans = s.t0 - s.rng.uniform(0.0, 600.0), [], []
    while t < s.t1:
        starts.append(t)
        spans.append(lu(s.rng, 300.0, 1200.0))
        t += spans[-1]
    a, w = np.array(starts), np.array(spans)

    def frac(r: Rec) -> np.ndarray:
        tt = r.cols["t_s"]
        k = np.clip(np.searchsorted(a, tt, side="right") - 1, 0, a.size - 1)
        return 1.0 - (m0 + dmax * np.clip((tt - a[k]) / w[k], 0.0, 1.0) ** (1.0 / 3.0)) / length

    _station(s, frac, 1.0 - (m0 + dmax) / length)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_aging_glassy_shims(s: Session) -> None:
    """Hard shims of PMMA (cut from a sheet to keep the clamp's gap stiff, instead of soft pads) under a screw clamp's
    fixed gap: a glassy polymer well below its glass transition relaxes its stress by a stretched exponential (r 4-10 %
    of the force, tau 20-200 s, log, beta 0.3-0.5) in an effective time that physical ageing slows as the glass
    densifies under the load (Struik: t_e = t_a ln(1 + u/t_a), t_a 30-300 s, log, u the time since the setting, the
    squeeze rejuvenating the glass at every re-clamping): a relaxation that is quick just after each setting and then
    all but stops. From each setting (inject_fresh25._setting_of) through the preset's clamp law
    (inject_fresh4._clamp_law), the load cell showing it. Measured (paper_154) displacement residual 0.064 % of its RMS
    (3.9x its noise), current residual 0.31 % (0.24x its noise), the load cell at 0.95-0.96 of its setting from each
    block's first record on."""
    r_, tau = s.rng.uniform(0.04, 0.1), lu(s.rng, 20.0, 200.0)
    beta, t_a = s.rng.uniform(0.3, 0.5), lu(s.rng, 30.0, 300.0)
    setting = _setting_of(s)
    starts = {p: setting(p, a) for p, a in _by_pressure_start(s).items()}

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - starts.get(p, t_first - 20.0), 0.0, None)
        return 1.0 - r_ * -np.expm1(-((t_a * np.log1p(u / t_a)) / tau) ** beta)

    _clamp_law(s, rel)


def cr_printed_flexure(s: Session) -> None:
    """A clamp 3D-printed in PETG (a lab's own design): the moving jaw on a printed flexure that a micrometer screw
    deflects to set the force, so that the flexure is the spring in series with the strip. The printed polymer creeps
    under its bending stress by Findley's law, nonlinear in the stress (eps_c = m0 sinh(sigma/sigma_0)/(sigma/sigma_0)
    (u/100 s)^n of its elastic strain, m0 0.01-0.03, n 0.2-0.35), and under the held screw its stress relaxes by as
    much: F/F_set = 1 - eps_c, u from each setting, the top setting's stress 1-2.5 sigma_0 and the others' in proportion
    to their force: the light settings lose a few per cent, the heavy ones up to 2.4 times more. From each setting
    (inject_fresh25._setting_of) through the preset's clamp law (inject_fresh4._clamp_law), the load cell showing it.
    Measured (paper_154) displacement residual 0.057 % of its RMS (3.5x its noise), current residual 0.25 % (0.19x its
    noise), the load cell down to 0.98, 0.98, 0.97, 0.96 of its setting block by block."""
    m0, n, x_top = s.rng.uniform(0.01, 0.03), s.rng.uniform(0.2, 0.35), s.rng.uniform(1.0, 2.5)
    top = max(s.pressures())
    setting = _setting_of(s)
    starts = {p: setting(p, a) for p, a in _by_pressure_start(s).items()}

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - starts.get(p, t_first - 20.0), 0.0, None)
        x = x_top * p / top
        return 1.0 - m0 * math.sinh(x) / x * (u / 100.0) ** n

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_albumin_fouling(s: Session) -> None:
    """A bio-IPMC test in a medium with serum (albumin 0.5-5 g/l), the strip dipped 0-300 s before the first record: the
    protein adsorbs on the rough plating, a monolayer by Langmuir kinetics (tau_a 60-300 s, log; a share th_f 0.3-0.6 of
    the final coverage) and then, slowly, spreading and multilayers (tau_s 1500-5000 s, log): the adsorbed film blocks
    the plating's pores to the bath, so the double layer the drive can charge shrinks with the coverage (the conductance
    down by s_c 0.15-0.35 at full coverage) and with it the charge that bends the strip (the gain down by 0.3-0.6 of the
    conductance's loss). A loss that starts fast and keeps creeping, relative to the first record; the spectra at the
    next series' start (inject_fresh9._dry_by). Measured (p16_156) displacement RMS -3.2 % (residual 3.7 %, 65x its
    noise), current RMS -13 % (residual 14 %, 9.1x its noise); the 1 V steps at 2.57, 2.50, 2.47, 2.44 mm block by block
    (2.58 mm clean), the impedance at 0.1 Hz 1.11, 1.16, 1.20x in the later blocks' spectra."""
    t_im, th_f = s.t0 - s.rng.uniform(0.0, 300.0), s.rng.uniform(0.3, 0.6)
    tau_a, tau_s = lu(s.rng, 60.0, 300.0), lu(s.rng, 1500.0, 5000.0)
    s_c, share = s.rng.uniform(0.15, 0.35), s.rng.uniform(0.3, 0.6)

    def cover(t: np.ndarray) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - t_im, 0.0, None)
        return th_f * -np.expm1(-u / tau_a) + (1.0 - th_f) * -np.expm1(-u / tau_s)

    c0 = float(cover(np.array([s.t0]))[0])
    _dry_by(s, lambda t: share * s_c * (cover(t) - c0) / (1.0 - share * s_c * c0),
            lambda t: s_c * (cover(t) - c0) / (1.0 - s_c * c0))


def dh_degassing_pores(s: Session) -> None:
    """A bath filled 0-600 s before the first record with water straight from a pressurised tap (the 'milky' water of a
    line under pressure), supersaturated with air by S_0 10-40 %: the open bath degasses to the room (S = S_0 exp(-u/
    tau_d), tau_d 1000-3000 s, log), and meanwhile the air nucleates in the plating's rough, partly hydrophobic pores
    and grows there at a rate proportional to S, filling a share up to th_max (0.1-0.3) of them as 1 - exp(-k int S dt)
    (k such that the session's supersaturation fills 1-3 e-folds). Gas-filled pores take no part in the double layer:
    the conductance falls with the filled share and the gain with it (0.6-1 of it), relative to the first record. A loss
    that runs fast while the water is most supersaturated and stops once it has degassed; the spectra at the next
    series' start (inject_fresh9._dry_by). Measured (paper_154) displacement RMS -5.3 % (residual 6.1 %, 370x its
    noise), current RMS -7.3 % (residual 7.6 %, 5.7x its noise); the 1 V steps at 8.79, 8.29, 8.19, 8.16 mm block by
    block (8.82-8.83 mm clean), the impedance at 0.1 Hz 1.07, 1.09, 1.10x in the later blocks' spectra."""
    t_f, s0, tau_d = s.t0 - s.rng.uniform(0.0, 600.0), s.rng.uniform(0.1, 0.4), lu(s.rng, 1000.0, 3000.0)
    th_max, folds, share = s.rng.uniform(0.1, 0.3), s.rng.uniform(1.0, 3.0), s.rng.uniform(0.6, 1.0)
    tg = _session_grid(s, 5.0, max(s.t0 - t_f, 0.0) + 5.0)
    sup = s0 * np.exp(-np.clip(tg - t_f, 0.0, None) / tau_d) * (tg >= t_f)
    integral = np.concatenate([[0.0], np.cumsum(0.5 * (sup[1:] + sup[:-1]) * np.diff(tg))])
    filled = th_max * -np.expm1(-folds * integral / max(float(integral[-1]), 1e-30))
    f0 = float(np.interp(s.t0, tg, filled))

    def loss(t: np.ndarray) -> np.ndarray:
        return (np.interp(np.asarray(t, float), tg, filled) - f0) / (1.0 - f0)

    _dry_by(s, lambda t: share * loss(t), loss)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_anodic_bridge_oxide(s: Session) -> None:
    """Both faces' plating mud-cracked, each crack bridged by platinum contacts that open with the face's tension beyond
    e0 (0.05-0.2 of the session's displacement scale; k 0.1-0.3 per unit of opening, the second face 0.5-1 of it), and
    the bridges grow an oxide while their face is the anode: the oxidised share th of a face follows its anodic drive u
    (the face's anode sign, half-wave at E_ox 0.3-0.6 V, width 0.05-0.1 V) through a growth lag of 0.5-3 s (log), is
    reduced only once the face is cathodic beyond E_red (0.1-0.3 V) over 0.3-2 s (log), and otherwise holds (60-300 s,
    log, at rest). An oxidised bridge conducts 3-7 times worse, dR/R = k (e - e0)+ (1 + K th). The strip bends towards
    its anode, so the face in tension is the cathode, its oxide being reduced: at slow drives it is gone before the bend
    opens the cracks, at fast ones it is still there after each reversal. Gains fall by 0.03-0.08 (displacement) and
    0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist); the oxide's state sample by sample through the session
    in time order. Measured (s001_155) displacement RMS -2.9 % (residual 3.0 %, 96x its noise), current RMS -0.61 %
    (residual 1.8 %, 4.9x its noise); the 1 V steps at 4.50-4.52 mm for 4.69-4.72 mm; 36 of the 68 time series
    touched."""
    k, e0, big_k = s.rng.uniform(0.1, 0.3), s.rng.uniform(0.05, 0.2), s.rng.uniform(2.0, 6.0)
    o, e_ox, w = s.rng.uniform(0.5, 1.0), s.rng.uniform(0.3, 0.6), s.rng.uniform(0.05, 0.1)
    e_red, tau_g = s.rng.uniform(0.1, 0.3), lu(s.rng, 0.5, 3.0)
    tau_r, tau_h = lu(s.rng, 0.3, 2.0), lu(s.rng, 60.0, 300.0)
    oxide, th, t_end = {}, [0.0, 0.0], None
    for r in _chrono(s):
        t, v = r.cols["t_s"], r.cols["v_V"]
        if t_end is not None:
            hold = math.exp(-max(float(t[0]) - t_end, 0.0) / tau_h)
            th = [x * hold for x in th]
        dt = 1.0 / r.fs
        a_g, a_r, a_h = -math.expm1(-dt / tau_g), -math.expm1(-dt / tau_r), -math.expm1(-dt / tau_h)
        out = np.empty((2, v.size))
        for i, vk in enumerate(v.tolist()):
            for j, u in enumerate((-vk, vk)):  # face A (in tension on a positive bend) is the anode on a negative drive
                eq = 1.0 / (1.0 + math.exp(-max(min((u - e_ox) / w, 60.0), -60.0)))
                a = a_g if eq > th[j] else (a_r if u < -e_red else a_h)
                th[j] += (eq - th[j]) * a
                out[j, i] = th[j]
        oxide[id(r)], t_end = out, float(t[-1])

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        e, ox = np.asarray(e), oxide[id(r)]
        face_a = np.clip(e - e0, 0.0, None) * (1.0 + big_k * ox[0])
        return k * (face_a + o * np.clip(-e - e0, 0.0, None) * (1.0 + big_k * ox[1]))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_graded_plating(s: Session) -> None:
    """A strip plated by impregnation-reduction while hanging tip down in the reducing bath, the reducer reaching its
    lower end less: the platinum thins along the strip towards the tip (by a share a 0.5-0.9 at the tip's end), and a
    thinner film cracks at a smaller strain (its crack strain e_r (1 - a x/L), e_r 0.5-1 of the session's displacement
    scale at the root) and carries more of the face's resistance (as 1/(1 - a x/L)). Under the bend's uniform curvature
    the cracked length grows from the tip inwards as the bend grows: dR/R = k int_0^1 (e - e_r (1 - a xi))+ dxi/(1 - a
    xi) (k 0.1-0.3; the other face 0.4-0.9 of it): a soft onset, quadratic at first, no dead zone beyond the tip's
    threshold. Gains fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist).
    Measured (p16_156) displacement RMS -5.7 % (residual 6.1 %, 110x its noise), current RMS -0.51 % (residual 2.8 %,
    1.8x its noise); the 1 V steps at 2.36 mm for 2.58 mm, the 1 V harmonics' gain 0.97; 32 of the 68 time series
    touched."""
    a, e_r, k, o = s.rng.uniform(0.5, 0.9), s.rng.uniform(0.5, 1.0), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.4, 0.9)
    xi = (np.arange(24) + 0.5) / 24.0
    thr, wgt = e_r * (1.0 - a * xi), 1.0 / (1.0 - a * xi) / 24.0

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        e = np.asarray(e, float)[:, None]
        return k * (np.clip(e - thr, 0.0, None) @ wgt + o * (np.clip(-e - thr, 0.0, None) @ wgt))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_tmr_slide_by(s: Session) -> None:
    """No laser: a small magnet (a 0.3-0.5 mm NdFeB sphere, under 1 % of the strip's mass) glued at the tip, magnetised
    along the bending direction, and a TMR magnetometer chip beside the tip's path at a standoff g (3-6 times the
    session's largest bend) from it, reading the field across the path: B ~ d g/(d^2 + g^2)^(5/2), linear near rest
    (where the lab calibrated it), then falling behind (its peak at d = g/2). Read as the calibrated d (1 +
    (d/g)^2)^(-5/2): odd, compressing the large bends on both sides. Tabulated and interpolated (slope 1 at rest,
    inject_fresh22._table_map); displacement only. Measured (p16_156) displacement RMS -5.2 % (residual 5.9 %, 100x its
    noise), the 1 V steps at 2.33-2.34 mm for 2.58 mm."""
    g = s.rng.uniform(3.0, 6.0) * (_largest(s) or ref_disp(s))
    _table_map(s, lambda d: d * (1.0 + (d / g) ** 2) ** -2.5)


def ld_vignetted_receiver(s: Session) -> None:
    """A short-range triangulation head (its range +-R, 1.7-2.5 times the session's largest bend) set with the strip's
    rest at its reference distance: its receiving lens vignettes towards the range's ends (the image's brightness as (1
    - (x/R)^2)^2), so the spot's image, a few pixels wide (its width s 0.06-0.15 R), is brighter on its inner side and
    the centroid that the head takes for the spot's place is pulled inwards by s^2 times the brightness' log-slope, 4
    s^2 x/(R^2 - x^2): nothing at rest, more and more towards the ends. The head's factory calibration (linear, made
    with a white target that fills the lens evenly) leaves it: read as x - 4 s^2 x/(R^2 - x^2), odd. Tabulated and
    interpolated (slope 1 at rest, inject_fresh22._table_map); displacement only. Measured (s001_155) displacement RMS
    -1.1 % (residual 1.3 %, 41x its noise), the 1 V steps at 4.58-4.61 mm for 4.69-4.72 mm."""
    big = _largest(s) or ref_disp(s)
    rng_r = s.rng.uniform(1.7, 2.5) * big
    w = s.rng.uniform(0.06, 0.15) * rng_r
    _table_map(s, lambda d: d - 4.0 * w * w * d / (rng_r * rng_r - d * d))


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_powerline_adapter(s: Session) -> None:
    """A powerline network adapter (HomePlug-type, the lab's network over the mains) in the bench's socket strip: during
    its traffic (4-8 spells of 100-500 s, log: a file sync, a backup) it transmits in bursts that its protocol places at
    a fixed phase after each zero crossing of the line (50 or 60 Hz) and sends in a share q (0.5-0.9) of the half-cycles
    (drawn per half-cycle); the megahertz carrier, rectified by the current amplifier's and the laser input's protection
    diodes and smoothed by their input RC (tau 2-5 ms, log), leaves a one-signed pulse per burst: 10-30 um (log) on the
    displacement, 50-200 uA (log) on the current, each with its sign. A comb at the line's even harmonics with the
    traffic's randomness between them; displacement and current. Measured (p16_156) displacement residual 0.19 % of its
    RMS (3.3x its noise), current residual 0.26 % (0.17x its noise); 27 of the 68 time series touched."""
    f0 = _line_f(s)
    spells = _bursts(s, int(s.rng.integers(4, 9)), (100.0, 500.0))
    q, tau, phase = s.rng.uniform(0.5, 0.9), lu(s.rng, 2e-3, 5e-3), s.rng.uniform(0.0, 0.3)
    amp = {"disp_m": _sign(s) * lu(s.rng, 1e-5, 3e-5), "i_A": _sign(s) * lu(s.rng, 5e-5, 2e-4)}
    h = 0.5 / f0  # a half-cycle
    k_lo = math.floor(min(a for a, _ in spells) / h) - 2
    k_hi = math.ceil(max(b for _, b in spells) / h) + 2
    sent = s.rng.random(k_hi - k_lo + 1) < q
    starts = (np.arange(k_lo, k_hi + 1) + phase) * h
    live = np.zeros(starts.size, bool)
    for a, b in spells:
        live |= (starts >= a) & (starts < b)
    sent &= live
    for r in s.series():
        t = r.cols["t_s"]
        if t[-1] < starts[0] or t[0] > starts[-1]:
            continue
        k = np.floor(t / h - phase).astype(np.int64) - k_lo
        pulse = np.zeros(t.size)
        for back in (0, 1, 2):
            kk = k - back
            ok = (kk >= 0) & (kk < starts.size)
            idx = np.clip(kk, 0, starts.size - 1)
            pulse += np.where(ok & sent[idx], np.exp(-np.clip(t - starts[idx], 0.0, None) / tau), 0.0)
        if not pulse.any():
            continue
        for col, a_ in amp.items():
            r.cols[col] = r.cols[col] + a_ * pulse


def mp_vortex_mixer(s: Session) -> None:
    """A vortex mixer on the next bench, plugged into the bench's socket strip and used now and then by a colleague
    (8-25 uses of 3-20 s, log): its shaded-pole motor's strongly saturated iron radiates the line (50 or 60 Hz) with its
    odd harmonics (3rd 0.2-0.5, 5th 0.05-0.2) onto the laser's cable and the current amplifier's input, 4-12 um (log)
    and 30-100 uA (log), and at each start the motor's locked-rotor current, 2.5-5 times its running one, dies away as
    it spins up (0.1-0.3 s, log); the mixer's shaking stays on its own bench. Phase locked to the session clock, the
    switch's edges sharp. Displacement and current. Measured (paper_154) displacement residual 0.067 % of its RMS (4.1x
    its noise), current residual 0.54 % (0.40x its noise); 16 of the 68 time series touched."""
    f0 = _line_f(s)
    uses = _bursts(s, int(s.rng.integers(8, 26)), (3.0, 20.0))
    harm = {3: s.rng.uniform(0.2, 0.5), 5: s.rng.uniform(0.05, 0.2)}
    inrush, spin = s.rng.uniform(2.5, 5.0), lu(s.rng, 0.1, 0.3)
    amp = {"disp_m": lu(s.rng, 4e-6, 1.2e-5), "i_A": lu(s.rng, 3e-5, 1e-4)}
    phase = {col: s.rng.uniform(0.0, 2.0 * np.pi) for col in amp}
    for r in s.series():
        t = r.cols["t_s"]
        env = np.zeros(t.size)
        for a, b in uses:
            on = (t >= a) & (t < b)
            if on.any():
                env = np.maximum(env, on * (1.0 + (inrush - 1.0) * np.exp(-np.clip(t - a, 0.0, None) / spin)))
        if not env.any():
            continue
        for col, a_ in amp.items():
            r.cols[col] = r.cols[col] + a_ * env * _hum(t, f0, harm, phase[col])


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_slosh_absorber(s: Session) -> None:
    """The bath's first sloshing mode in a small cuvette (its inner width along the bend W 10-50 mm, log, its depth
    20-40 mm: w_s^2 = g k tanh(k h), k = pi/W, 3.9-8.9 Hz, lightly damped by the contact line, zeta_s 0.01-0.03) driven
    by the strip's own motion and pushing back on it: the free surface a tuned absorber on the strip's first mode, the
    share of its mass the strip's motion couples to mu 0.02-0.08 of the strip's modal mass (with its water). The strip's
    displacement through 1/(1 + mu s^2 A(s)/(s^2 + 2 zeta_1 w_1 s + w_1^2)), A = (2 zeta_s w_s s + w_s^2)/(s^2 + 2
    zeta_s w_s s + w_s^2), w_1 and zeta_1 the preset's first mode at the record's pressure: a narrow dip and split peaks
    about the sloshing frequency, nothing at DC, nothing far above. Through inject_fresh2._through with 30 s of the
    session's history; displacement only. Measured (paper_154, both cases) displacement residual 0.14 % of its RMS (8.6x
    its noise): the 4.4 Hz sines' gain 0.83-0.85 (5-9 deg of lag), the 6.4 Hz sines' 0.81-0.82, the 20 Hz sines' 1.02,
    the steps' edges ringing (22 um at most)."""
    from labrig.physics import presets, transfer

    width, depth = lu(s.rng, 0.01, 0.05), s.rng.uniform(0.02, 0.04)
    kw = math.pi / width
    ws = math.sqrt(9.81 * kw * math.tanh(kw * depth))
    zs, mu = s.rng.uniform(0.01, 0.03), s.rng.uniform(0.02, 0.08)
    pre, modes = presets.get(s.preset), {}

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        p = float(r.entry["pressure_kPa"])
        if p not in modes:
            ms = transfer.modal_set(pre.specimen(p))
            modes[p] = (float(ms.omega[0]), float(ms.xi[0]))
        w1, z1 = modes[p]

        def h(z: np.ndarray) -> np.ndarray:
            z = np.asarray(z)
            a = (2.0 * zs * ws * z + ws * ws) / (z * z + 2.0 * zs * ws * z + ws * ws)
            return 1.0 / (1.0 + mu * z * z * a / (z * z + 2.0 * z1 * w1 * z + w1 * w1))

        return h

    _map_through(s, H, 30.0)


def out_stepper_hunting(s: Session) -> None:
    """A motorised clamp whose stepper holds the jaw between settings under its microstepping driver, and hunts about
    its microstep: the rotor's detent resonance on the loaded lead screw, f_h 25-60 Hz at the lightest setting and
    rising with the held force as (p/p_min)^(1/4) (the screw's stiffness grows with its preload), its frequency
    wandering by 0.2-0.6 % with the driver's chopper (a slow random walk, 20-60 s). The clamp shakes along the bending
    direction by a_h (1.5-5 um, log, at the lightest setting, as (p_min/p)^(1/4) at the others: the stand rocking on the
    motor's mount), and the laser, on its own stand, reads the tip's absolute motion: the clamp's through the strip's
    base-excitation transmissibility (inject_fresh23._transmissibility from the preset's first resonance at the record's
    pressure, damping 0.05-0.15). A narrow line whose frequency, size and phase step with each clamp setting, none of
    them a multiple of the line or of the drive; displacement only. Measured (s001_155) displacement residual 0.088 % of
    its RMS (2.8x its noise), the line at 55, 63, 69, 74 Hz block by block; (paper_154) 0.049 % (3.0x), at 35, 46, 53,
    57 Hz."""
    f_h, a_h = s.rng.uniform(25.0, 60.0), lu(s.rng, 1.5e-6, 5e-6)
    wander, corr, zeta = s.rng.uniform(0.002, 0.006), s.rng.uniform(20.0, 60.0), s.rng.uniform(0.05, 0.15)
    p_min, cache = min(s.pressures()), {}
    tg = _session_grid(s, 1.0, 2.0)
    drift = np.cumsum(s.rng.normal(size=tg.size)) * math.sqrt(1.0 / corr)
    drift = wander * (drift - np.mean(drift)) / (float(np.std(drift)) or 1.0)
    ph = {p: s.rng.uniform(0.0, 2.0 * np.pi) for p in s.pressures()}
    for r in s.series():
        p, t = float(r.entry["pressure_kPa"]), r.cols["t_s"]
        f = f_h * (p / p_min) ** 0.25
        w1 = 2.0 * math.pi * _f1(s, p, cache)
        T = _transmissibility(w1, zeta, 2.0 * math.pi * f)
        inst = f * (1.0 + np.interp(t, tg, drift))
        wander_phase = np.concatenate([[0.0], np.cumsum((inst[1:] - f) * np.diff(t))])
        phase = 2.0 * np.pi * (f * t + wander_phase)
        r.cols["disp_m"] = r.cols["disp_m"] + a_h * (p_min / p) ** 0.25 * abs(T) * np.cos(phase + ph[p] + np.angle(T))


def out_delta_clamp_logger(s: Session) -> None:
    """The laser read by the lab's microcontroller logger (an Arduino-class board, the head's output in 10 nm counts
    over its serial line, at the DAQ's clock), which stores each sample as an eight-bit signed difference from the last
    stored value in counts of q (0.015-0.03 um: the head's digits kept), saturating at +-127 counts, with a full
    keyframe every N samples (256, 512 or 1024, drawn; one at each record's start) to bound its errors; the lab's export
    rebuilds the reading by summing the differences. Wherever the tip moves faster than 127 q a sample (1.9-3.8 um: a
    step's edge and fall, the fast sines' swings) the rebuilt reading falls behind by the clipped excess and stays off
    by it until the next keyframe, where it jumps back: offsets that appear at fast motion and vanish at fixed sample
    counts, and q's quantisation. Displacement only. Measured (s001_155) displacement residual 0.35 % of its RMS (11x
    its noise), 38 um off at most (the steps' edges), the 2 Hz sines' gain 0.88-0.89; (p16_156) 1.2 % (22x), 75 um, the
    2 Hz sines' 0.72-0.74."""
    q = s.rng.uniform(1.5e-8, 3e-8)
    n = (256, 512, 1024)[int(s.rng.integers(0, 3))]

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        counts = np.round(d / q)
        out = np.empty(d.size)
        for a in range(0, d.size, n):
            seg = counts[a: a + n]
            steps = np.clip(np.diff(seg), -127, 127)
            out[a: a + n] = seg[0] + np.concatenate([[0.0], np.cumsum(steps)])
        return out * q

    map_disp(s, f)


def out_radian_frequency_axis(s: Session) -> None:
    """The spectra exported by the impedance analyser's software with its frequency column in rad/s (the angular
    frequency some EIS packages write by default, 'omega'), which the lab's conversion script copied into f_Hz: every
    spectrum's frequencies 2 pi times too high (and off by the synthesiser's own calibration, -100 to +100 ppm, drawn),
    the impedances as measured. The spectra then say that the strip's capacitance is 2 pi times smaller and its double
    layer charges 2 pi times faster than the time series' currents show; no time series touched. Measured (paper_154
    and s001_155) every spectrum's f_Hz x 6.283 (0.63 Hz to 63 kHz), no time series touched."""
    scale = 2.0 * math.pi * (1.0 + s.rng.uniform(-1e-4, 1e-4))
    for r in s.recs:
        if not r.series:
            r.cols["f_Hz"] = r.cols["f_Hz"] * scale


FRESH28_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"hydrogel_coat": br_hydrogel_coat, "freeze_thaw": br_freeze_thaw},
    "faradaic_current": {"ascorbate_depletion": far_ascorbate_depletion,
                         "ir_shielded_electrolysis": far_ir_shielded_electrolysis},
    "hysteresis": {"grommet_seal": hy_grommet_seal, "pogo_tip_contact": hy_pogo_tip_contact},
    "time_delay": {"dusk_webcam": td_dusk_webcam, "i2c_adc_scan": td_i2c_adc_scan},
    "sensor_offset": {"lab_jack_ratchet": so_lab_jack_ratchet, "drop_lens": so_drop_lens},
    "clamp_relaxation": {"aging_glassy_shims": cr_aging_glassy_shims, "printed_flexure": cr_printed_flexure},
    "dehydration": {"albumin_fouling": dh_albumin_fouling, "degassing_pores": dh_degassing_pores},
    "strain_resistance": {"anodic_bridge_oxide": sr_anodic_bridge_oxide, "graded_plating": sr_graded_plating},
    "large_deflection": {"tmr_slide_by": ld_tmr_slide_by, "vignetted_receiver": ld_vignetted_receiver},
    "mains_pickup": {"powerline_adapter": mp_powerline_adapter, "vortex_mixer": mp_vortex_mixer},
    "unexplained": {"slosh_absorber": out_slosh_absorber, "stepper_hunting": out_stepper_hunting,
                    "delta_clamp_logger": out_delta_clamp_logger, "radian_frequency_axis": out_radian_frequency_axis},
}
inject.register_forms(FRESH28_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_block_clock(s: Session) -> None:
    """A logging program restarted at each re-clamping (a LabVIEW VI, or a script, run once per clamp setting), its
    clock the time since it was started, which it writes into t_s to the microsecond: every time series of a pressure
    block carries t_s counted from that start, 2-20 s before the block's first time series (drawn per block: the
    operator starts the program, which then arms its first record); within a block the records share that clock and
    their rests, from one block to the next it starts again near zero. Each record's stamps strictly increasing and
    every value as it was; the spectra (no clock), the rows and the manifest's order unchanged. The import contract asks
    t_s strictly increasing within a file and nothing across files; ``labrig import`` takes it (the clock then not
    shared by every record: laid back to back, docs/storage.md)."""
    for block in _chrono_blocks(s):
        t0 = float(block[0].cols["t_s"][0]) - s.rng.uniform(2.0, 20.0)
        for r in block:
            r.cols["t_s"] = np.round(r.cols["t_s"] - t0, 6)


inject.VARIANTS.update({"block_clock": v_block_clock})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_154", "s001_155", "p16_156"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 154-156
    "back_relaxation": [("hydrogel_coat", 155, S, "coherent_sines"), ("freeze_thaw", 154, P, "log_steps")],
    "faradaic_current": [("ascorbate_depletion", 156, T, "stop_trigger"),
                         ("ir_shielded_electrolysis", 155, S, "block_clock")],
    "hysteresis": [("grommet_seal", 156, T, "swinging_door"), ("pogo_tip_contact", 155, S, "reversed_laser")],
    "time_delay": [("dusk_webcam", 154, P, "settled_sines"), ("i2c_adc_scan", 156, T, "tared_records")],
    "sensor_offset": [("lab_jack_ratchet", 155, S, "trigger_clock"), ("drop_lens", 154, P, "scan_hold")],
    "clamp_relaxation": [("aging_glassy_shims", 154, P, "merged_loadcell"),
                         ("printed_flexure", 154, P, "measured_pressures")],
    "dehydration": [("albumin_fouling", 156, T, "split_spectra"), ("degassing_pores", 154, P, "eis_descending")],
    "strain_resistance": [("anodic_bridge_oxide", 155, S, "cycle_averaged"), ("graded_plating", 156, T, "no_loadcell")],
    "large_deflection": [("tmr_slide_by", 156, T, "own_clock"), ("vignetted_receiver", 155, S, "float32_time")],
    "mains_pickup": [("powerline_adapter", 156, T, "dropped_packets"), ("vortex_mixer", 154, P, "short_pretrigger")],
    "unexplained": [("slosh_absorber", 154, P, "steps_sines"), ("slosh_absorber", 154, P, "block_clock"),
                    ("stepper_hunting", 155, S, "no_spectra"), ("stepper_hunting", 154, P, "loadcell_dropout"),
                    ("delta_clamp_logger", 155, S, "shortened_shuffled"),
                    ("delta_clamp_logger", 156, T, "fir_decimated"),
                    ("radian_frequency_axis", 155, S, "spectra_last"),
                    ("radian_frequency_axis", 154, P, "midnight_clock")],
}
CLEAN = [(154, P, "block_clock"), (154, P, "two_pressures"), (155, S, "block_clock"), (155, S, "asrun"),
         (156, T, "fixed_decimals"), (156, T, "host_timed")]


def fresh28_cases(only: str | None = None) -> list[Case]:
    """The twenty-ninth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    154-156)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh28_cases, "inject_fresh28", "fresh28")
