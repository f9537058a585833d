"""Protocol settings as pydantic models: unknown keys are errors, so a typo is never silently ignored."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field, model_validator


class Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class ClampSettings(Strict):
    pressures_kPa: list[float] = Field(default=[612.0, 1837.0, 3062.0, 4287.0], min_length=1)
    tolerance_N: float = Field(0.5, gt=0)
    hold_s: float = Field(2.0, ge=0)
    timeout_s: float = Field(180.0, gt=0)
    settle_s: float = Field(60.0, ge=0)

    @model_validator(mode="after")
    def _positive(self):
        bad = [p for p in self.pressures_kPa if not p > 0]
        if bad:
            raise ValueError(f"pressures_kPa must be positive, got {bad[0]}")
        return self


class EisSettings(Strict):
    f_start_Hz: float = Field(0.1, gt=0)
    f_stop_Hz: float = Field(10000.0, gt=0)
    points: int = Field(31, ge=2, le=1601)
    ac_V: float = Field(0.01, gt=0)
    bias_V: float = 0.0

    @model_validator(mode="after")
    def _order(self):
        if self.f_stop_Hz <= self.f_start_Hz:
            raise ValueError("f_stop_Hz must be above f_start_Hz")
        return self


class StepSettings(Strict):
    amplitude_V: float = 1.0
    on_s: float = Field(30.0, gt=0)
    off_s: float = Field(30.0, ge=0)
    fs_Hz: float = Field(500.0, gt=0)


class HarmonicSettings(Strict):
    amplitude_V: float = 1.0
    frequency_Hz: float = Field(0.1, gt=0)
    cycles: float = Field(3.0, gt=0)
    fs_Hz: float = Field(200.0, gt=0)


class SteppedSineSettings(Strict):
    amplitude_V: float = 0.5
    f_start_Hz: float = Field(0.1, gt=0)
    f_stop_Hz: float = Field(20.0, gt=0)
    points: int = Field(15, ge=1, le=200)
    settle_cycles: float = Field(2.0, ge=0)
    settle_min_s: float = Field(2.0, ge=0)  # the first mode's ring-down (~0.3 s in water) must be over
    measure_cycles: float = Field(4.0, gt=0)
    min_record_s: float = Field(2.0, ge=0)

    @model_validator(mode="after")
    def _order(self):
        if self.f_stop_Hz < self.f_start_Hz:
            raise ValueError("f_stop_Hz must not be below f_start_Hz")
        return self


class MultisineSettings(Strict):
    """Odd random-phase multisine (protocols/multisine.py). The defaults are the design docs/estimation.md
    measures against the stepped sine: same RMS as its 0.5 V sine, 0.1 Hz as line 1 of a 10 s period, a
    log grid of 3 lines per octave, +6 dB/octave above 3 Hz, 1 kHz, a 2 s lead-in, 2 periods x 2 realisations."""

    rms_V: float = Field(0.35, gt=0)
    f_min_Hz: float = Field(0.1, gt=0)
    f_max_Hz: float = Field(20.0, gt=0)
    period_s: float = Field(10.0, gt=0)
    periods: int = Field(2, ge=1)  # measured periods after the lead-in; with lead_in_s = 0 the first is a transient period
    realisations: int = Field(2, ge=1)
    fs_Hz: float = Field(1000.0, gt=0)
    seed: int = 1
    lead_in_s: float = Field(2.0, ge=0)  # cyclic prefix before the periods (the estimator removes the slow tails)
    lines_per_octave: float = Field(3.0, ge=0)  # 0: every odd line of the period grid
    skip_one_in: int = Field(1, ge=1)  # one grid line in each group of this many is left out (1: none; a log grid leaves plenty)
    emphasis_Hz: float = Field(3.0, ge=0)  # line amplitudes sqrt(1 + (f/emphasis_Hz)^2); 0: flat

    @model_validator(mode="after")
    def _band(self):
        if self.f_max_Hz * 2.5 > self.fs_Hz:
            raise ValueError("fs_Hz must be at least 2.5 x f_max_Hz")
        if self.f_min_Hz * self.period_s < 1:
            raise ValueError("period_s is too short for f_min_Hz (need period_s >= 1/f_min_Hz)")
        if self.lead_in_s >= self.period_s:
            raise ValueError("lead_in_s must be shorter than period_s (use more periods instead)")
        if self.lead_in_s == 0 and self.periods < 2:
            raise ValueError("periods must be at least 2 without a lead-in (the first period is the transient)")
        return self


class AmplitudeSeriesSettings(Strict):
    amplitudes_V: list[float] = Field(default=[0.25, 0.5, 1.0, 1.5], min_length=2)
    test: str = Field("harmonic", pattern="^(harmonic|step|multisine)$")
    frequency_Hz: float = Field(0.5, gt=0)
    cycles: float = Field(4.0, gt=0)
    fs_Hz: float = Field(500.0, gt=0)
    rest_s: float = Field(20.0, ge=0)
