"""Benchmark: FRF error against the true H(j omega) versus simulated experiment time, for the stepped sine
(the paper's method, preset ``stepped-sine``) and the multisine, side by side on the simulated bench.

Run: python bench/frf_time.py [--seeds N]
Target: the multisine reaches the stepped sine's accuracy over 0.1-20 Hz in at most one fifth of its time.

Both run through the real runner (``RunRequest``/``execute``: simulated instruments on their real wire
protocols) at 3062 kPa with the same drive RMS (0.5 V sine amplitude, 0.354 V RMS) and the same bench noise,
and are estimated by ``load_session`` (stepped sines: ``sine_estimate``; multisine: ``multisine_bla``).
Error: RMS over seeds and over the lines each method measures in 0.1-20 Hz of |H_hat / H - 1|, with H the
bench specimen's ``transfer.frf``. Experiment time: the drive records' duration (settling cycles, lead-in and
transient periods included; clamping and the rig's own overhead excluded, the same for both).
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np

from labrig.estimate.session_data import load_session
from labrig.physics import presets, transfer
from labrig.session_run import RunRequest, execute

PRESSURE_KPA = 3062.0
AMPLITUDE_V = 0.5  # the stepped sine's; the multisine gets the same RMS
BAND_HZ = (0.1, 20.0)
HEAD = f'protocol = "{{protocol}}"\npressure_kPa = {PRESSURE_KPA}\n'

# (label, protocol, table) - the stepped sine as the preset, measuring 1/4 to 2x its cycles and seconds
STEPPED = [(f"measure {c:g} cyc / {s:g} s", "stepped-sine", f"[stepped_sine]\namplitude_V = {AMPLITUDE_V}\nmeasure_cycles = {c}\nmin_record_s = {s}\n")
           for c, s in [(1, 0.5), (2, 1.0), (4, 2.0), (8, 4.0)]]
RMS = f"rms_V = {AMPLITUDE_V / np.sqrt(2):.6f}\n"
# the old preset's design (20 s period, every odd line, 200 Hz, a transient period dropped) at the same RMS
OLD = "period_s = 20.0\nfs_Hz = 200.0\nlead_in_s = 0.0\nlines_per_octave = 0\nskip_one_in = 4\nemphasis_Hz = 0\nrealisations = 1\n"
OLD_MS = [(f"old preset, {p - 1} period(s)", "multisine", f"[multisine]\n{RMS}{OLD}periods = {p}\n") for p in (2, 3, 5)]
# the new preset's design, one realisation: 10 s period (0.1 Hz is line 1), 3 lines/octave, +6 dB/octave above
# 3 Hz, 1 kHz (the stepped sine's rate at 20 Hz), a 2 s lead-in instead of a transient period
NEW = "period_s = 10.0\nfs_Hz = 1000.0\nlines_per_octave = 3.0\nskip_one_in = 1\nemphasis_Hz = 3.0\nlead_in_s = 2.0\nrealisations = 1\n"
NEW_MS = [(f"new preset, {p} period(s)", "multisine", f"[multisine]\n{RMS}{NEW}periods = {p}\n") for p in (1, 2, 3, 4)]
# what each change is worth: the new design at 2 periods with one choice put back
ABLATION = [(label, "multisine", f"[multisine]\n{RMS}{NEW.replace(a, b)}periods = {p}\n") for label, a, b, p in [
    ("new, 200 Hz sampling", "fs_Hz = 1000.0", "fs_Hz = 200.0", 2),
    ("new, flat line amplitudes", "emphasis_Hz = 3.0", "emphasis_Hz = 0", 2),
    ("new, every odd line", "lines_per_octave = 3.0", "lines_per_octave = 0", 2),
    ("new, transient period, no lead-in", "lead_in_s = 2.0", "lead_in_s = 0.0", 3),
]]

def measure(protocol: str, table: str, seed: int, tmp: Path, truth) -> tuple[float, np.ndarray, np.ndarray]:
    """(experiment time s, relative errors, |H_hat - H|^2 / sigma^2) of one run."""
    spec = tmp / f"{protocol}_{abs(hash(table))}_{seed}.toml"
    spec.write_text(HEAD.format(protocol=protocol) + table)
    out = tmp / (spec.stem + ".h5")
    res = execute(RunRequest(str(spec), out, seed=seed))
    if res.exit_code != 0:
        raise SystemExit(f"{spec.name}: run failed: {res.reason}")
    p = load_session(out).pressures[0]
    kind = "stepped_sine" if protocol == "stepped-sine" else "multisine"
    t_exp = sum(r.t.size / r.fs for r in p.of_kind(kind))
    f, h, _, sig = p.frf_lines("sines" if kind == "stepped_sine" else "multisine")
    band = (f >= BAND_HZ[0] - 1e-9) & (f <= BAND_HZ[1] + 1e-9)
    H = transfer.frf(f[band], truth)
    return t_exp, np.abs(h[band] / H - 1), np.abs(h[band] - H) ** 2 / sig[band] ** 2


def run(configs, seeds: list[int], tmp: Path, truth) -> list[dict]:
    rows = []
    for label, protocol, table in configs:
        times, errs, z2 = [], [], []
        for s in seeds:
            t_exp, e, z = measure(protocol, table, s, tmp, truth)
            times.append(t_exp)
            errs.append(e)
            z2.append(z)
        e = np.concatenate(errs)
        rows.append({"method": protocol, "label": label, "time_s": float(np.mean(times)), "err": float(np.sqrt(np.mean(e**2))),
                     "lines": len(errs[0]), "z2": float(np.mean(np.concatenate(z2)))})
    return rows


def time_at(err: float, curve: list[dict]) -> tuple[float, str]:
    """Multisine time reaching ``err``: log-log interpolation along its error curve (relation: = <= >)."""
    pts = sorted((r["time_s"], r["err"]) for r in curve)
    t, e = np.log([p[0] for p in pts]), np.log([p[1] for p in pts])
    if np.log(err) >= e[0]:
        return float(np.exp(t[0])), "<="
    for k in range(1, len(pts)):
        if np.log(err) >= e[k]:
            a = (np.log(err) - e[k - 1]) / (e[k] - e[k - 1])
            return float(np.exp(t[k - 1] + a * (t[k] - t[k - 1]))), "="
    return float(np.exp(t[-1])), ">"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=3, help="simulated benches per setting (noise draws)")
    args = ap.parse_args()
    seeds = list(range(1, args.seeds + 1))
    truth = presets.get("paper").specimen(PRESSURE_KPA)
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        ss = run(STEPPED, seeds, Path(tmp), truth)
        old = run(OLD_MS, seeds, Path(tmp), truth)
        ms = run(NEW_MS, seeds, Path(tmp), truth)
        abl = run(ABLATION, seeds, Path(tmp), truth)
    wall = time.perf_counter() - t0
    print(f"FRF error vs experiment time, {PRESSURE_KPA:g} kPa, drive RMS {AMPLITUDE_V / np.sqrt(2):.3f} V, {BAND_HZ[0]:g}-{BAND_HZ[1]:g} Hz, "
          f"{len(seeds)} seeds per row (RMS of |H_hat/H - 1| over each method's own lines)")
    print(f"{'method':13} {'setting':30} {'time s':>8} {'lines':>6} {'rms rel err':>12} {'mean z^2':>9}")
    for r in ss + old + ms + abl:
        print(f"{r['method']:13} {r['label']:30} {r['time_s']:8.1f} {r['lines']:6d} {r['err']:12.2e} {r['z2']:9.2f}")
    print("\nequal accuracy: the new multisine's time to reach each stepped sine's error (log-log interpolation)")
    worst = 0.0
    for r in ss:
        t_ms, rel = time_at(r["err"], ms)
        ratio = t_ms / r["time_s"]
        worst = max(worst, ratio)
        print(f"  stepped sine {r['label']:22} {r['time_s']:6.1f} s, err {r['err']:.2e} -> multisine {rel} {t_ms:5.1f} s: ratio {rel} {ratio:.3f} (1/{1 / ratio:.0f})")
    print(f"\nworst ratio {worst:.3f} (target <= 0.2: {'met' if worst <= 0.2 else 'NOT met'}); wall time {wall:.0f} s")


if __name__ == "__main__":
    main()
