"""``labrig model``: evaluate the seed-000 model for a preset without writing code."""

from __future__ import annotations

from dataclasses import replace

import click
import numpy as np

from labrig import signals
from labrig.cli.common import MultiValueOption, print_json, write_csv
from labrig.errors import BadInput
from labrig.physics import impedance as imp
from labrig.physics import hammerstein, presets, timeresp, transfer
from labrig.physics.params import Specimen

_preset = click.option("--preset", default="paper", show_default=True, help=f"one of: {', '.join(presets.names())}")
_pressure = click.option("--pressure", "pressure_kPa", type=float, default=None, help="clamping pressure in kPa (default: the preset's)")


def _specimen(preset: str, pressure_kPa: float | None, **changes) -> Specimen:
    try:
        p = presets.get(preset)
    except KeyError as exc:
        raise BadInput(f"--preset: {exc.args[0]}") from None
    if pressure_kPa is not None and not pressure_kPa > 0:
        raise BadInput(f"--pressure: must be positive, got {pressure_kPa}")
    return p.specimen(pressure_kPa, **changes)


def _freqs(fmin: float, fmax: float, points: int) -> np.ndarray:
    if not (0 < fmin < fmax) or points < 2:
        raise BadInput(f"frequency range: need 0 < --fmin < --fmax and --points >= 2 (got {fmin}, {fmax}, {points})")
    return np.geomspace(fmin, fmax, points)


@click.group()
def model() -> None:
    """Evaluate the model: modes, impedance, FRF and time responses."""


@model.command()
@_preset
@click.option("--kt", "kt", cls=MultiValueOption, type=float, help="non-dimensional torsional spring(s) K_t bar")
@click.option("--pressure", "pressures", cls=MultiValueOption, type=float, help="clamping pressure(s) in kPa (K_t bar from the clamp law)")
@click.option("-n", "--n-modes", default=3, show_default=True, type=click.IntRange(1, 30))
@click.option("--json", "as_json", is_flag=True, help="print one JSON object")
def modes(preset: str, kt: tuple[float, ...], pressures: tuple[float, ...], n_modes: int, as_json: bool) -> None:
    """Natural frequencies (eq. 30, 33) for K_t bar values or clamping pressures."""
    if kt and pressures:
        raise BadInput("give --kt or --pressure, not both")
    base = _specimen(preset, None)
    if not kt and not pressures:
        pressures = presets.PAPER_PRESSURES_KPA
    rows = []
    for value in kt or pressures:
        if not value > 0:
            raise BadInput(f"{'--kt' if kt else '--pressure'}: must be positive, got {value}")
        sp = base.with_(Kt_bar=value) if kt else _specimen(preset, value)
        ms = transfer.modal_set(sp.with_(n_modes=max(n_modes, 1)))
        rows.append((None if kt else value, sp.Kt_bar, ms.beta_L[0], ms.f_Hz, ms.xi))
    out = {
        "preset": preset,
        "pressure_kPa": [r[0] for r in rows] if pressures else None,
        "Kt_bar": [r[1] for r in rows],
        "beta1_L": [r[2] for r in rows],
        "f1_Hz": [r[3][0] for r in rows],
        "modes_Hz": [r[3][:n_modes] for r in rows],
        "xi": [r[4][:n_modes] for r in rows],
    }
    if as_json:
        print_json(out)
        return
    click.echo(f"preset {preset}: modes of the torsional-spring cantilever (eq. 30, 33)")
    for r in rows:
        head = f"p = {r[0]:7.0f} kPa  " if r[0] is not None else ""
        freqs = ", ".join(f"{f:.3f}" for f in r[3][:n_modes])
        click.echo(f"  {head}K_t bar = {r[1]:6.3f}  beta1 L = {r[2]:.4f}  f = [{freqs}] Hz  xi1 = {r[4][0]:.3f}")


@model.command("impedance")
@_preset
@_pressure
@click.option("--fmin", default=0.01, show_default=True, type=float)
@click.option("--fmax", default=1e4, show_default=True, type=float)
@click.option("--points", default=200, show_default=True, type=int)
@click.option("--form", type=click.Choice(["exact", "lowfreq"]), default="exact", show_default=True, help="eq. 12 or eq. 13")
@click.option("--out", required=True, type=click.Path(dir_okay=False), help="CSV: f_Hz, z_re_ohm, z_im_ohm")
def impedance_cmd(preset: str, pressure_kPa: float | None, fmin: float, fmax: float, points: int, form: str, out: str) -> None:
    """Impedance spectrum Z(f) (eq. 12 or 13) to CSV, in the import format of EIS records."""
    sp = _specimen(preset, pressure_kPa)
    f = _freqs(fmin, fmax, points)
    z = (imp.impedance if form == "exact" else imp.impedance_lowfreq)(2j * np.pi * f, sp)
    write_csv(out, ["f_Hz", "z_re_ohm", "z_im_ohm"], [f, z.real, z.imag])
    click.echo(f"wrote {points} points of Z(f) (eq. {'12' if form == 'exact' else '13'}) to {out}")


@model.command("frf")
@_preset
@_pressure
@click.option("--fmin", default=0.1, show_default=True, type=float)
@click.option("--fmax", default=20.0, show_default=True, type=float)
@click.option("--points", default=200, show_default=True, type=int)
@click.option("--out", required=True, type=click.Path(dir_okay=False))
def frf_cmd(preset: str, pressure_kPa: float | None, fmin: float, fmax: float, points: int, out: str) -> None:
    """Displacement FRF H(j omega) (eq. 38) and current per volt 1/Z to CSV."""
    sp = _specimen(preset, pressure_kPa)
    f = _freqs(fmin, fmax, points)
    h = transfer.frf(f, sp)
    y = transfer.admittance_tf(2j * np.pi * f, sp)
    write_csv(
        out,
        ["f_Hz", "disp_mag_m_per_V", "disp_phase_deg", "cur_mag_A_per_V", "cur_phase_deg"],
        [f, np.abs(h), np.degrees(np.unwrap(np.angle(h))), np.abs(y), np.degrees(np.angle(y))],
    )
    click.echo(f"wrote the FRF at {points} frequencies to {out}")


@model.command("response")
@_preset
@_pressure
@click.option("--kind", type=click.Choice(["step", "harmonic", "swept", "multisine"]), default="step", show_default=True)
@click.option("--amplitude", "amplitude_V", default=1.0, show_default=True, type=float, help="V (rms for multisine)")
@click.option("--frequency", "frequency_Hz", default=0.1, show_default=True, type=float, help="harmonic frequency, Hz")
@click.option("--fmin", default=0.1, show_default=True, type=float, help="swept / multisine lowest frequency, Hz")
@click.option("--fmax", default=20.0, show_default=True, type=float)
@click.option("--duration", "duration_s", default=30.0, show_default=True, type=float)
@click.option("--fs", default=1000.0, show_default=True, type=float, help="sample rate, Hz")
@click.option("--seed", default=0, show_default=True, type=int, help="multisine phases")
@click.option("--out", required=True, type=click.Path(dir_okay=False), help="CSV: t_s, v_V, i_A, disp_m")
@click.option("--model", "which", type=click.Choice(["seed000", "hammerstein"]), default="seed000", show_default=True,
              help="seed 000's distributed model, or seed 001's Hammerstein grey box (the preset's parameters)")
@click.option("--law", type=click.Choice(sorted(hammerstein.LAWS)), default=None, help="hammerstein: the electric law (default: the preset's)")
@click.option("--noise", "noise_rel", default=0.0, show_default=True, type=float,
              help="white noise added to current and displacement, as a fraction of each one's std (seeded by --seed)")
def response_cmd(preset, pressure_kPa, kind, amplitude_V, frequency_Hz, fmin, fmax, duration_s, fs, seed, out, which, law, noise_rel) -> None:
    """Time response (current and tip displacement) to a step, sine, sweep or multisine, to CSV."""
    sp = _specimen(preset, pressure_kPa)
    if not noise_rel >= 0:
        raise BadInput(f"--noise: must be >= 0, got {noise_rel}")
    if which != "hammerstein" and law is not None:
        raise BadInput("--law applies to --model hammerstein")
    if not (duration_s > 0 and fs > 0):
        raise BadInput("--duration and --fs must be positive")
    if kind == "step":
        v = signals.step(amplitude_V, duration_s, fs, t_on_s=min(1.0, duration_s / 10))
    elif kind == "harmonic":
        v = signals.sine(amplitude_V, frequency_Hz, duration_s, fs)
    elif kind == "swept":
        v = signals.swept_sine(amplitude_V, fmin, fmax, duration_s, fs)
    else:
        ms = signals.odd_multisine(amplitude_V, fmin, fmax, duration_s, fs, np.random.default_rng(seed))
        v = ms.period_V
    if which == "hammerstein":  # seed 001's grey box, from rest (labrig.physics.hammerstein)
        hp = presets.get(preset).hammerstein
        cur, disp = hammerstein.simulate(replace(hp, law=law) if law else hp, v, fs)
    else:
        disp, cur = timeresp.simulate_many([lambda s: transfer.displacement_tf(s, sp), lambda s: transfer.admittance_tf(s, sp)], v, fs)
    if noise_rel > 0:
        rng = np.random.default_rng([seed, 1])
        cur, disp = (x + noise_rel * x.std() * rng.standard_normal(x.size) for x in (cur, disp))
    write_csv(out, ["t_s", "v_V", "i_A", "disp_m"], [np.arange(v.size) / fs, v, cur, disp])
    click.echo(f"wrote {v.size} samples ({kind}, {duration_s:g} s at {fs:g} Hz) to {out}; peak |disp| = {np.abs(disp).max() * 1e3:.3f} mm")


@model.command("optimum")
@_preset
@click.option("--pressure", "pressures", cls=MultiValueOption, type=float, help="kPa (default: the paper's four)")
@click.option("--printed", is_flag=True, help="use eq. 17 and eq. 34 as printed (total-current charge, f_app = M'')")
@click.option("--json", "as_json", is_flag=True)
def optimum_cmd(preset: str, pressures: tuple[float, ...], printed: bool, as_json: bool) -> None:
    """Model actuation against clamping pressure: 1 V step peak (30 s), 1 V / 0.1 Hz amplitude, |H(f1)|."""
    fs = 200.0
    rows = []
    for p in pressures or presets.PAPER_PRESSURES_KPA:
        sp = _specimen(preset, p, **({"charge": "total", "modal_force": "paper"} if printed else {}))
        step = timeresp.simulate(lambda s: transfer.displacement_tf(s, sp), signals.step(1.0, 30.0, fs), fs)
        f1 = transfer.modal_set(sp).f_Hz[0]
        rows.append(
            {
                "pressure_kPa": p,
                "step_peak_m": float(np.abs(step).max()),
                "harmonic_0p1Hz_m": float(abs(transfer.frf(np.array([0.1]), sp)[0])),
                "f1_Hz": f1,
                "frf_at_f1_m_per_V": float(abs(transfer.frf(np.array([f1]), sp)[0])),
            }
        )
    best = max(rows, key=lambda r: r["step_peak_m"])["pressure_kPa"]
    if as_json:
        print_json({"preset": preset, "printed": printed, "rows": rows, "optimum_pressure_kPa": best})
        return
    click.echo(f"{'kPa':>8} {'step peak mm':>13} {'0.1 Hz mm':>10} {'f1 Hz':>7} {'|H(f1)| mm/V':>13}")
    for r in rows:
        click.echo(
            f"{r['pressure_kPa']:8.0f} {r['step_peak_m'] * 1e3:13.4f} {r['harmonic_0p1Hz_m'] * 1e3:10.4f} {r['f1_Hz']:7.3f} {r['frf_at_f1_m_per_V'] * 1e3:13.4f}"
        )
    click.echo(f"largest step response at {best:g} kPa")
