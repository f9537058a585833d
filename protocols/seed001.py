"""Seed 001's experiment on seed 001's strip (in air, 3 kHz): the records that identify both Hammerstein stages.

Seed 001 (Caponetto et al., section 3) cites variable-amplitude sines [25, 26] and variable-amplitude steps [27]
for the nonlinearity, and identifies the electric stage first (current) and then the electromechanical stage
(displacement). One session therefore holds, at one fixed clamp:

* sines of one slow frequency at several amplitudes: the electric stage and its amplitude dependence;
* steps at several amplitudes: the static I-V trend (the steady current after the double layer charged,
  seed 001 Fig. 1) and the integrator's leak;
* a broadband odd multisine around the first mode (~23 Hz in air): the linear electromechanical stage.

Each record is marked ``role = "fit"`` or ``role = "heldout"`` (metadata): the held-out ones (one amplitude of
the sines and steps, one multisine realisation) are never used to fit and measure the prediction error.
"""

from __future__ import annotations

from typing import Iterator

from pydantic import Field, model_validator

from labrig.records import RecordKind

from protocols.config import ClampSettings, Strict
from protocols.steps import Settle, Step, clamp_steps, multisine_record, sine_record, step_record


class Seed001Settings(Strict):
    fs_Hz: float = Field(3000.0, gt=0)  # seed 001's DAQ rate
    sine_amplitudes_V: list[float] = Field(default=[0.5, 1.0, 1.5, 2.0], min_length=2)
    sine_frequency_Hz: float = Field(0.5, gt=0)
    sine_cycles: float = Field(3.0, gt=0)
    step_amplitudes_V: list[float] = Field(default=[0.5, 1.0, 1.5, 2.0], min_length=2)
    step_on_s: float = Field(5.0, gt=0)
    step_off_s: float = Field(10.0, ge=0)
    multisine_rms_V: float = Field(0.45, gt=0)
    multisine_f_min_Hz: float = Field(0.2, gt=0)
    multisine_f_max_Hz: float = Field(60.0, gt=0)
    multisine_period_s: float = Field(10.0, gt=0)
    multisine_realisations: int = Field(2, ge=1)
    heldout_amplitude_V: float | None = 1.5  # sines and steps of this amplitude are held out (None: none)
    rest_s: float = Field(30.0, ge=0)  # at 0 V between records: the slow tail (minutes in the CPE) mostly gone

    @model_validator(mode="after")
    def _check(self):
        if self.multisine_f_max_Hz * 2.5 > self.fs_Hz:
            raise ValueError("fs_Hz must be at least 2.5 x multisine_f_max_Hz")
        if self.multisine_f_min_Hz * self.multisine_period_s < 1:
            raise ValueError("multisine_period_s is too short for multisine_f_min_Hz")
        return self


class Seed001Protocol(Strict):
    """At one clamping pressure. 1000 kPa on seed 001's 10 x 5 mm clamp is 50 N (the rig allows 90 N)."""

    pressure_kPa: float = Field(1000.0, gt=0)
    clamp: ClampSettings = ClampSettings(pressures_kPa=[1000.0], settle_s=10.0)
    seed001: Seed001Settings = Seed001Settings()


def _role(s: Seed001Settings, amplitude_V: float) -> str:
    return "heldout" if s.heldout_amplitude_V is not None and abs(amplitude_V - s.heldout_amplitude_V) < 1e-9 else "fit"


def seed001_plan(cfg: Seed001Protocol, clamp_area_m2: float) -> Iterator[Step]:
    c, s = cfg.clamp, cfg.seed001
    yield from clamp_steps("", cfg.pressure_kPa, clamp_area_m2, c.tolerance_N, c.hold_s, c.timeout_s, c.settle_s)
    meta = {"pressure_kPa": cfg.pressure_kPa, "series": "amplitude", "protocol_part": "seed001"}
    k = 0

    def rest() -> Iterator[Step]:
        nonlocal k
        k += 1
        if s.rest_s > 0:
            yield Step(f"rest_{k}", RecordKind.SETTLE, Settle(s.rest_s), {"pressure_kPa": cfg.pressure_kPa})

    for a in s.sine_amplitudes_V:
        yield sine_record("", RecordKind.HARMONIC, a, s.sine_frequency_Hz, s.sine_cycles, s.fs_Hz, role=_role(s, a), **meta)
        yield from rest()
    for a in s.step_amplitudes_V:
        yield step_record("", a, s.step_on_s, s.step_off_s, s.fs_Hz, role=_role(s, a), **meta)
        yield from rest()
    for r in range(s.multisine_realisations):
        role = "heldout" if r == s.multisine_realisations - 1 and s.multisine_realisations > 1 else "fit"
        yield multisine_record("", s.multisine_rms_V, s.multisine_f_min_Hz, s.multisine_f_max_Hz, s.multisine_period_s, 1, s.fs_Hz, 1, r,
                               lines_per_octave=6.0, skip_one_in=1, emphasis_Hz=5.0, lead_in_s=2.0, role=role,
                               **{**meta, "series": "broadband"})
        yield from rest()
