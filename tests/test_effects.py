"""The effect catalogue on the simulated bench: each effect's raw signature is there when it is switched
on and absent when it is off, strengths come from the seed, '+' combines, and no truth reaches a session."""

from __future__ import annotations

from dataclasses import dataclass

import h5py
import numpy as np
import pytest

from labrig import signals
from labrig.physics import transfer
from mock_devices import effects as fx
from mock_devices import scenarios
from mock_devices.world import World, Noise

CATALOGUE = (
    "back_relaxation", "faradaic_current", "hysteresis", "time_delay", "sensor_offset",
    "clamp_relaxation", "dehydration", "strain_resistance", "large_deflection", "mains_pickup",
)
SEEDS = (0, 1, 2)


@dataclass
class FakeClock:
    """Simulated time that moves only when a test says so."""

    t: float = 0.0
    time_scale: float = 1.0

    def now(self) -> float:
        return self.t

    def sleep(self, seconds: float) -> None:
        self.t += max(seconds, 0.0)


def bench(scenario: str = "none", seed: int = 0, noise: Noise | None = None, **kw) -> World:
    """A fresh bench with default (realistic) noise; the noise seed is fixed so on/off differ only by the effect."""
    return World(FakeClock(), seed=7, effects=scenarios.effects_for(scenario, seed), noise=noise, **kw)


def harmonics(x: np.ndarray, fs: float, f: float, n: int = 5) -> np.ndarray:
    """Complex amplitudes of harmonics 1..n of f in x, fitted jointly with a cubic trend: the CPE's slow
    drift from rest would otherwise leak into the harmonics."""
    t = np.arange(x.size) / fs
    tn = t / t[-1] - 0.5
    cols = [tn**p for p in range(4)] + [g(2 * np.pi * k * f * t) for k in range(1, n + 1) for g in (np.cos, np.sin)]
    c = np.linalg.lstsq(np.stack(cols, axis=1), x, rcond=None)[0][4:]
    return c[0::2] - 1j * c[1::2]


def tone(x: np.ndarray, fs: float, f: float) -> complex:
    """Complex amplitude at f of a steady record (whole number of cycles of every tone)."""
    return 2 * np.mean(x * np.exp(-2j * np.pi * f * np.arange(x.size) / fs))


def sine_run(scenario: str, seed: int, amp: float, f: float, fs: float, cycles: int = 6, keep: int = 3):
    """Voltage, current and displacement over the last ``keep`` cycles of a sine from rest."""
    v = signals.sine(amp, f, cycles / f, fs)
    r = bench(scenario, seed).run_record(0.0, fs, v)
    n = int(round(keep * fs / f))
    return {k: x[-n:] for k, x in r.items()}


def harmonic_ratio(x: np.ndarray, fs: float, f: float, k: int) -> float:
    h = harmonics(x, fs, f)
    return abs(h[k - 1]) / abs(h[0])


def step_run(scenario: str, seed: int = 0, amp: float = 1.0, fs: float = 50.0, t0: float = 0.0, b: World | None = None):
    drive = signals.step(amp, 61.0, fs, t_on_s=1.0, t_off_s=31.0)
    return (b or bench(scenario, seed)).run_record(t0, fs, drive)


# ------------------------------------------------------------------------------------------- scenarios
def test_every_catalogue_name_is_a_scenario_and_one_effect():
    assert set(scenarios.names()) == set(CATALOGUE) | {"none"}
    assert scenarios.effects_for("none", 0) == []
    for name in CATALOGUE:
        (e,) = scenarios.effects_for(name, 0)
        assert e.name == name and fx.CATALOGUE[name] is type(e)
        assert e.__doc__ and "-" in e.__doc__  # the docstring gives the physics and the ranges
    with pytest.raises(KeyError, match="unknown scenario"):
        scenarios.effects_for("back_relaxation+nope", 0)


@pytest.mark.parametrize("name", CATALOGUE)
def test_strengths_are_reproducible_from_the_seed_and_vary_between_seeds(name):
    draws = [vars(scenarios.effects_for(name, s)[0]) for s in (11, 11, 12)]
    assert draws[0] == draws[1]
    assert draws[0] != draws[2]


def test_combinations_hold_each_part_as_drawn_alone_in_physical_order():
    both = scenarios.effects_for("mains_pickup+back_relaxation", 4)
    assert [e.name for e in both] == ["back_relaxation", "mains_pickup"]  # strip before pickup
    assert vars(both[0]) == vars(scenarios.effects_for("back_relaxation", 4)[0])
    assert vars(both[1]) == vars(scenarios.effects_for("mains_pickup", 4)[0])
    twice = scenarios.effects_for("time_delay+time_delay", 4)
    assert twice[0].tau != twice[1].tau


# ------------------------------------------------------------------------------------------ signatures
@pytest.mark.parametrize("seed", SEEDS)
def test_back_relaxation_step_peaks_then_decays(seed):
    on = slice(int(1.0 * 50), int(31.0 * 50))  # 50 Hz: 1 s .. 31 s
    d = step_run("back_relaxation", seed)["disp_m"][on]
    lin = step_run("none")["disp_m"][on]
    assert np.argmax(lin) > 0.97 * lin.size  # the linear strip keeps rising for 30 s (CPE)
    k = int(np.argmax(d))
    assert k < 0.8 * d.size and d[-1] < 0.85 * d[k]  # peaks, then gives back >= 15 %


@pytest.mark.parametrize("seed", SEEDS)
def test_faradaic_current_odd_harmonics_and_steady_dc(seed):
    fs, f = 100.0, 0.5
    on = sine_run("faradaic_current", seed, 1.5, f, fs)["i_A"]
    off = sine_run("none", seed, 1.5, f, fs)["i_A"]
    assert harmonic_ratio(on, fs, f, 3) > 10 * harmonic_ratio(off, fs, f, 3)
    assert harmonic_ratio(on, fs, f, 3) > 3e-3
    # during a step the extra current is a steady DC (it does not decay like charging current)
    extra = step_run("faradaic_current", seed)["i_A"] - step_run("none")["i_A"]
    early, late = np.mean(extra[int(10 * fs / 2) : int(12 * fs / 2)]), np.mean(extra[int(28 * fs / 2) : int(30 * fs / 2)])
    assert late > 5e-5 and abs(late / early - 1) < 0.05
    # it grows faster than V: the 1.5 V fundamental is not 1.5 x the 1 V one
    on1 = sine_run("faradaic_current", seed, 1.0, f, fs)["i_A"]
    off1 = sine_run("none", seed, 1.0, f, fs)["i_A"]
    g15, g10 = abs(harmonics(on, fs, f)[0] - harmonics(off, fs, f)[0]), abs(harmonics(on1, fs, f)[0] - harmonics(off1, fs, f)[0])
    assert g15 > 1.6 * g10


def loop_area(r, fs: float, f: float) -> float:
    """Area of the V-delta loop over one cycle, per unit of the box ptp(V) x ptp(delta)."""
    n = int(round(fs / f))
    v, d = r["v_V"][-n:], r["disp_m"][-n:]
    d = d - np.polyval(np.polyfit(np.arange(n), d, 1), np.arange(n)) + np.mean(d)  # drift is not loop
    return abs(np.sum(0.5 * (d + np.roll(d, 1)) * (v - np.roll(v, 1)))) / (np.ptp(v) * np.ptp(d))


@pytest.mark.parametrize("seed", SEEDS)
def test_hysteresis_loop_stays_as_frequency_falls(seed):
    fs = 25.0
    extra = []
    for f in (0.05, 0.02):
        on, off = (sine_run(s, seed, 1.0, f, fs, cycles=3, keep=1) for s in ("hysteresis", "none"))
        extra.append(loop_area(on, fs, f) - loop_area(off, fs, f))
    assert min(extra) > 0.012  # the loop widens by >= 1.2 % of its box ...
    assert extra[1] > 0.7 * extra[0]  # ... and does not shrink as f -> 0 (rate independent)
    # and the current does not see it
    on, off = (sine_run(s, seed, 1.0, 0.2, fs, cycles=3, keep=1) for s in ("hysteresis", "none"))
    assert np.allclose(on["i_A"], off["i_A"])


@pytest.mark.parametrize("seed", SEEDS)
def test_time_delay_phase_linear_in_f_gain_unchanged(seed):
    fs, freqs, amps = 1000.0, np.array([1.0, 5.0, 10.0, 20.0]), (0.1, 0.3, 1.0, 1.0)  # ~ equal displacement
    v = sum(a * np.sin(2 * np.pi * f * np.arange(int(10 * fs)) / fs) for a, f in zip(amps, freqs))
    on, off = (bench(s, seed).run_record(0.0, fs, v)["disp_m"][int(2 * fs) :] for s in ("time_delay", "none"))
    ratio = np.array([tone(on, fs, f) / tone(off, fs, f) for f in freqs])
    assert np.allclose(np.abs(ratio), 1.0, atol=0.02)
    phase = np.unwrap(np.angle(ratio))
    slope = np.polyfit(freqs, phase, 1)[0]
    tau = -slope / (2 * np.pi)
    assert 5e-3 <= tau <= 40e-3
    assert tau == pytest.approx(scenarios.effects_for("time_delay", seed)[0].tau, rel=0.02)
    assert np.max(np.abs(phase + 2 * np.pi * freqs * tau)) < 0.02  # linear through the origin


@pytest.mark.parametrize("seed", SEEDS)
def test_sensor_offset_scales_gain_resonance_stays(seed):
    fs = 200.0
    freqs = np.array([0.5, *np.arange(2.5, 5.01, 0.25)])
    t = np.arange(int(24 * fs)) / fs
    v = sum(0.1 * np.sin(2 * np.pi * f * t + k) for k, f in enumerate(freqs))
    on, off = (bench(s, seed).run_record(0.0, fs, v) for s in ("sensor_offset", "none"))
    h_on, h_off = (np.array([abs(tone(r["disp_m"][int(4 * fs) :], fs, f)) for f in freqs]) for r in (on, off))
    assert 0.3 < h_on[0] / h_off[0] < 0.85  # (x_m/L)^2-like quasi-static scaling
    assert np.argmax(h_on[1:]) == np.argmax(h_off[1:])  # the resonance does not move
    assert bench("sensor_offset", seed).specimen().x_sensor < bench().specimen().x_sensor
    assert transfer.modal_set(bench("sensor_offset", seed).specimen()).f_Hz[0] == pytest.approx(
        transfer.modal_set(bench().specimen()).f_Hz[0], rel=1e-9
    )


@pytest.mark.parametrize("seed", SEEDS)
def test_clamp_relaxation_force_falls_and_the_clamp_step_still_passes(seed):
    b_on, b_off = bench("clamp_relaxation", seed, noise=Noise(force_N=0.0)), bench(noise=Noise(force_N=0.0))
    for b in (b_on, b_off):
        b.set_clamp_force(68.6)  # 4287 kPa from 3062 kPa: the paper's largest step up
    # the runner's clamp step: within 0.5 N of target for 2 s, inside the first seconds after arriving
    ok = [abs(b_on.clamp_force_now() - 68.6) <= 0.5 for b_on.clock.t in np.arange(0.0, 40.0, 0.1)]
    assert any(all(ok[k : k + 21]) for k in range(len(ok) - 21))
    start, kt0 = b_on.clamp_force_now(), b_on.specimen().Kt_bar
    b_on.clock.t = b_off.clock.t = 640.0  # a long record later
    b_on.run_record(600.0, 50.0, np.zeros(2000))
    assert b_on.clamp_force_now() < 0.985 * start
    assert b_off.clamp_force_now() == pytest.approx(68.6, abs=1e-6)
    assert b_on.specimen().Kt_bar != pytest.approx(kt0, rel=1e-3)  # f1 drifts with the force


@pytest.mark.parametrize("seed", SEEDS)
def test_dehydration_same_step_later_is_smaller(seed):
    b = bench("dehydration", seed)
    first = np.max(step_run("", b=b)["disp_m"])
    later = np.max(step_run("", b=b, t0=2000.0)["disp_m"])
    ref = bench()
    assert later < 0.75 * first
    assert np.max(step_run("", b=ref, t0=2000.0)["disp_m"]) == pytest.approx(np.max(step_run("", b=bench())["disp_m"]), rel=0.01)
    z = lambda bb, t: abs(bb.impedance(np.array([0.1]), 0.01, 0.0)[0])  # noqa: E731
    b.clock.t = 2000.0
    assert z(b, 2000.0) > 1.1 * z(bench("dehydration", seed), 0.0)


@pytest.mark.parametrize("seed", SEEDS)
def test_large_deflection_gain_falls_with_amplitude_and_odd_harmonics(seed):
    p1, p2 = (np.max(step_run("large_deflection", seed, a)["disp_m"]) for a in (1.0, 2.0))
    l1, l2 = (np.max(step_run("none", seed, a)["disp_m"]) for a in (1.0, 2.0))
    assert l2 == pytest.approx(2 * l1, rel=2e-3)
    assert p2 < 0.96 * 2 * p1
    fs, f = 50.0, 0.1
    on, off = (sine_run(s, seed, 2.0, f, fs, cycles=4, keep=2)["disp_m"] for s in ("large_deflection", "none"))
    assert harmonic_ratio(on, fs, f, 3) > 5 * harmonic_ratio(off, fs, f, 3)


@pytest.mark.parametrize("seed", SEEDS)
def test_strain_resistance_even_harmonics_and_amplitude_dependent_phase(seed):
    fs, f = 50.0, 0.2
    on, off = (sine_run(s, seed, 1.5, f, fs) for s in ("strain_resistance", "none"))
    for ch in ("i_A", "disp_m"):
        assert harmonic_ratio(on[ch], fs, f, 2) > 5 * harmonic_ratio(off[ch], fs, f, 2)
    on_lo, off_lo = (sine_run(s, seed, 0.25, f, fs) for s in ("strain_resistance", "none"))

    def phase_shift(a, b):  # phase of the current's fundamental, with vs without
        return np.angle(harmonics(a["i_A"], fs, f)[0] / harmonics(b["i_A"], fs, f)[0])

    assert abs(phase_shift(on, off)) > 3 * abs(phase_shift(on_lo, off_lo)) + 1e-4


@pytest.mark.parametrize("seed", SEEDS)
def test_mains_pickup_narrow_line(seed):
    fs = 500.0
    e = scenarios.effects_for("mains_pickup", seed)[0]
    on, off = (bench(s, seed).run_record(100.0, fs, np.zeros(int(20 * fs))) for s in ("mains_pickup", "none"))
    for ch, noise in (("disp_m", 0.5e-6), ("i_A", 2e-6)):
        spec_on = np.abs(np.fft.rfft(on[ch] * np.hanning(on[ch].size)))
        spec_off = np.abs(np.fft.rfft(off[ch] * np.hanning(off[ch].size)))
        freqs = np.fft.rfftfreq(on[ch].size, 1 / fs)
        for k in (1, 3):
            line = np.abs(freqs - k * e.f_line) < 0.2
            floor = np.median(spec_on)
            assert spec_on[line].max() > 20 * floor and spec_off[line].max() < 5 * floor
        assert np.std(on[ch]) > np.std(off[ch])


# ------------------------------------------------------------------------------------------- combined
def test_back_relaxation_plus_mains_shows_both():
    fs = 500.0
    both, alone = step_run("back_relaxation+mains_pickup", 5, fs=fs), step_run("back_relaxation", 5, fs=fs)
    d = both["disp_m"][int(fs) : int(31 * fs)]
    assert np.argmax(d) < 0.8 * d.size  # back relaxation: peaks within the on phase
    f_line = scenarios.effects_for("mains_pickup", 5)[0].f_line
    x = [r["disp_m"] for r in (both, alone)]
    freqs = np.fft.rfftfreq(x[0].size, 1 / fs)
    line = np.abs(freqs - f_line) < 0.2
    spec = [np.abs(np.fft.rfft(xi * np.hanning(xi.size)))[line].max() for xi in x]
    assert spec[0] > 5 * spec[1]


# --------------------------------------------------------------------------------------- no truth leaks
def truth_hits(path, words: tuple[str, ...], secrets: np.ndarray) -> list[str]:
    """Every place in an HDF5 file (names, attributes, datasets, transcripts) that names a word or holds a secret value."""
    found: list[str] = []

    def scan(where: str, value) -> None:
        if isinstance(value, bytes):
            value = value.decode("utf-8", "replace")
        if isinstance(value, str):
            low = value.lower()
            found.extend(f"{where}: {w}" for w in words if w in low)
            for x in secrets:  # the parameter printed in any usual format
                found.extend(f"{where}: {x}" for fmt in ("{!r}", "{:.6g}", "{:.4g}") if fmt.format(x) in value)
            return
        arr = np.asarray(value)
        if arr.dtype.kind in "OSU":
            for x in arr.ravel():
                scan(where, x)
        elif arr.dtype.kind == "f" and arr.size and np.isclose(arr.ravel()[:, None], secrets[None, :], rtol=1e-9, atol=0).any():
            found.append(f"{where}: a parameter value")

    def visit(name: str, obj) -> None:
        scan(f"name {name}", name)
        for k, a in obj.attrs.items():
            scan(f"{name}@{k}", k)
            scan(f"{name}@{k}", a)
        if isinstance(obj, h5py.Dataset):
            scan(name, obj[()])

    with h5py.File(path, "r") as h5:
        h5.visititems(visit)
        for k, a in h5.attrs.items():
            scan(f"/@{k}", a)
    return found


def test_no_scenario_truth_in_the_session(tmp_path):
    from labrig.session_run import RunRequest, execute

    (effect,) = scenarios.effects_for("back_relaxation", 3)
    path = tmp_path / "s.h5"
    execute(RunRequest("step", path, effects=[effect]))
    words = ("back_relaxation", "backrelaxation", "k2", "tau2", "effect", "scenario")
    secrets = np.array([effect.K2, effect.tau2])
    with h5py.File(path, "r") as h5:  # the session is real: a step record and transcripts
        names: list[str] = []
        h5.visit(names.append)
        assert any("step" in n for n in names) and any("transcript" in n.lower() for n in names), names
    assert truth_hits(path, words, secrets) == []
    # the scanner itself finds a planted value, a planted name and a planted dataset
    for plant in ("attr", "text", "data"):
        bad = tmp_path / f"{plant}.h5"
        bad.write_bytes(path.read_bytes())
        with h5py.File(bad, "a") as h5:
            grp = h5[next(iter(h5.keys()))]
            if plant == "attr":
                grp.attrs["note"] = effect.tau2
            elif plant == "text":
                grp.attrs["note"] = "bench: back_relaxation"
            else:
                grp.create_dataset("x", data=np.array([1.0, effect.K2]))
        assert truth_hits(bad, words, secrets), plant
