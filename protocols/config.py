"""Protocol settings as pydantic models: unknown keys are errors, so a typo is never silently ignored.

Every value is also checked against the bench's real limits and against physical sense before anything
moves (docs/input_validation.md): finite numbers only, booleans never taken as numbers (``StrictModel``),
and bounds from the instruments: the DAQ's analog output range and sample rate, the impedance analyser's
frequency, level and segment-table limits (``drivers.impedance_analyzer.MAX_LIST_POINTS``). Durations are
bounded so a typo (``settle_s = 1e9``) cannot hang a run; the plan as a whole is bounded by the budget in
``protocols.registry`` (samples and rig time) before any drive array is built.
"""

from __future__ import annotations

from pydantic import ConfigDict, Field, model_validator

from drivers.impedance_analyzer import MAX_LIST_POINTS
from labrig.records import RecordKind
from labrig.validation import STRICT, StrictModel

# the bench's limits (docs/input_validation.md says where each comes from)
AO_RANGE_V = 10.0  # NI DAQ analog output range, +-10 V (drivers.daq ao_range_V)
FS_MIN_HZ, FS_MAX_HZ = 1.0, 100_000.0  # AI/AO sample clock: 3 AI channels of an M-series card (1.25 MS/s aggregate) with margin
EIS_F_MIN_HZ, EIS_F_MAX_HZ = 1e-5, 1e6  # the low-frequency analyser's range (paper's VersaSTAT 3: 10 uHz..1 MHz)
EIS_AC_MIN_V, EIS_AC_MAX_V = 5e-3, 1.0  # oscillator level (E4990A and IM3590: 5 mV..1 V)
EIS_BIAS_MAX_V = 10.0  # DC bias, +-10 V
MAX_PRESSURE_KPA = 1e5  # 100 MPa: far above any clamp; the rig's safety.max_force_N is the real limit
MAX_WAIT_S = 3600.0  # one settle, hold, rest or clamp timeout: an hour; longer is a typo, not a protocol
MAX_RECORD_S = 3600.0  # one drive record's on/off or cycles: an hour


class Strict(StrictModel):
    model_config = ConfigDict(**STRICT, frozen=True)


def _drive(default: float) -> float:
    return Field(default, ge=-AO_RANGE_V, le=AO_RANGE_V)


def _fs(default: float) -> float:
    return Field(default, ge=FS_MIN_HZ, le=FS_MAX_HZ)


class ClampSettings(Strict):
    pressures_kPa: list[float] = Field(default=[612.0, 1837.0, 3062.0, 4287.0], min_length=1, max_length=100)
    tolerance_N: float = Field(0.5, gt=0, le=98.0)  # the load cell's capacity (Dacell UMMA-K10, 98 N)
    hold_s: float = Field(2.0, ge=0, le=MAX_WAIT_S)
    timeout_s: float = Field(180.0, gt=0, le=MAX_WAIT_S)
    settle_s: float = Field(60.0, ge=0, le=MAX_WAIT_S)

    @model_validator(mode="after")
    def _positive(self):
        bad = [p for p in self.pressures_kPa if not 0 < p <= MAX_PRESSURE_KPA]
        if bad:
            raise ValueError(f"pressures_kPa must be positive and at most {MAX_PRESSURE_KPA:g} kPa, got {bad[0]}")
        return self


class EisSettings(Strict):
    f_start_Hz: float = Field(0.1, ge=EIS_F_MIN_HZ, le=EIS_F_MAX_HZ)
    f_stop_Hz: float = Field(10000.0, ge=EIS_F_MIN_HZ, le=EIS_F_MAX_HZ)
    points: int = Field(31, ge=2, le=MAX_LIST_POINTS)  # the analyser's segment table holds 201 frequencies
    ac_V: float = Field(0.01, ge=EIS_AC_MIN_V, le=EIS_AC_MAX_V)
    bias_V: float = Field(0.0, ge=-EIS_BIAS_MAX_V, le=EIS_BIAS_MAX_V)

    @model_validator(mode="after")
    def _order(self):
        if self.f_stop_Hz <= self.f_start_Hz:
            raise ValueError("f_stop_Hz must be above f_start_Hz")
        # log_freqs rounds to 6 digits: a grid denser than that repeats frequencies the segment table refuses
        if self.f_stop_Hz / self.f_start_Hz < (1 + 1e-5) ** (self.points - 1):
            raise ValueError("points too many for so narrow a band (the frequencies would repeat)")
        return self


class StepSettings(Strict):
    amplitude_V: float = _drive(1.0)
    on_s: float = Field(30.0, gt=0, le=MAX_RECORD_S)
    off_s: float = Field(30.0, ge=0, le=MAX_RECORD_S)
    fs_Hz: float = _fs(500.0)


class HarmonicSettings(Strict):
    amplitude_V: float = _drive(1.0)
    frequency_Hz: float = Field(0.1, gt=0, le=FS_MAX_HZ / 2.5)
    cycles: float = Field(3.0, gt=0, le=1e5)
    fs_Hz: float = _fs(200.0)

    @model_validator(mode="after")
    def _sampled(self):
        if self.fs_Hz < 2.5 * self.frequency_Hz:
            raise ValueError("fs_Hz must be at least 2.5 x frequency_Hz")
        if self.cycles / self.frequency_Hz > MAX_RECORD_S:
            raise ValueError(f"cycles / frequency_Hz is over {MAX_RECORD_S:g} s")
        return self


class SteppedSineSettings(Strict):
    amplitude_V: float = _drive(0.5)
    f_start_Hz: float = Field(0.1, ge=1e-3, le=800.0)  # fs_for caps the rate at 2 kHz: 2.5 samples per cycle at most
    f_stop_Hz: float = Field(20.0, ge=1e-3, le=800.0)
    points: int = Field(15, ge=1, le=200)
    settle_cycles: float = Field(2.0, ge=0, le=1e4)
    settle_min_s: float = Field(2.0, ge=0, le=MAX_WAIT_S)  # the first mode's ring-down (~0.3 s in water) must be over
    measure_cycles: float = Field(4.0, gt=0, le=1e4)
    min_record_s: float = Field(2.0, ge=0, le=MAX_RECORD_S)

    @model_validator(mode="after")
    def _order(self):
        if self.f_stop_Hz < self.f_start_Hz:
            raise ValueError("f_stop_Hz must not be below f_start_Hz")
        return self


class MultisineSettings(Strict):
    """Odd random-phase multisine (protocols/multisine.py). The defaults are the design docs/estimation.md
    measures against the stepped sine: same RMS as its 0.5 V sine, 0.1 Hz as line 1 of a 10 s period, a
    log grid of 3 lines per octave, +6 dB/octave above 3 Hz, 1 kHz, a 2 s lead-in, 2 periods x 2 realisations."""

    rms_V: float = Field(0.35, gt=0, le=AO_RANGE_V / 4)  # a multisine's crest factor is ~3-4: its peak stays in range
    f_min_Hz: float = Field(0.1, gt=0, le=FS_MAX_HZ / 2.5)
    f_max_Hz: float = Field(20.0, gt=0, le=FS_MAX_HZ / 2.5)
    period_s: float = Field(10.0, gt=0, le=MAX_RECORD_S)
    periods: int = Field(2, ge=1, le=1000)  # measured periods after the lead-in; with lead_in_s = 0 the first is a transient period
    realisations: int = Field(2, ge=1, le=100)
    fs_Hz: float = _fs(1000.0)
    seed: int = Field(1, ge=0, le=2**32 - 1)  # numpy's seed range
    lead_in_s: float = Field(2.0, ge=0, le=MAX_RECORD_S)  # cyclic prefix before the periods (the estimator removes the slow tails)
    lines_per_octave: float = Field(3.0, ge=0, le=1000)  # 0: every odd line of the period grid
    skip_one_in: int = Field(1, ge=1, le=100)  # one grid line in each group of this many is left out (1: none; a log grid leaves plenty)
    emphasis_Hz: float = Field(3.0, ge=0, le=FS_MAX_HZ)  # line amplitudes sqrt(1 + (f/emphasis_Hz)^2); 0: flat

    @model_validator(mode="after")
    def _band(self):
        if self.f_max_Hz * 2.5 > self.fs_Hz:
            raise ValueError("fs_Hz must be at least 2.5 x f_max_Hz")
        if self.f_min_Hz * self.period_s < 1:
            raise ValueError("period_s is too short for f_min_Hz (need period_s >= 1/f_min_Hz)")
        if self.f_min_Hz > self.f_max_Hz:
            raise ValueError("f_min_Hz must not be above f_max_Hz")
        if self.lead_in_s >= self.period_s:
            raise ValueError("lead_in_s must be shorter than period_s (use more periods instead)")
        if self.lead_in_s == 0 and self.periods < 2:
            raise ValueError("periods must be at least 2 without a lead-in (the first period is the transient)")
        return self


class AmplitudeSeriesSettings(Strict):
    amplitudes_V: list[float] = Field(default=[0.25, 0.5, 1.0, 1.5], min_length=2, max_length=100)
    test: str = Field(RecordKind.HARMONIC.value, pattern=f"^({RecordKind.HARMONIC}|{RecordKind.STEP}|{RecordKind.MULTISINE})$")
    frequency_Hz: float = Field(0.5, gt=0, le=FS_MAX_HZ / 2.5)
    cycles: float = Field(4.0, gt=0, le=1e5)
    fs_Hz: float = _fs(500.0)
    rest_s: float = Field(20.0, ge=0, le=MAX_WAIT_S)

    @model_validator(mode="after")
    def _sampled(self):
        bad = [a for a in self.amplitudes_V if not -AO_RANGE_V <= a <= AO_RANGE_V]
        if bad:
            raise ValueError(f"amplitudes_V must be within +-{AO_RANGE_V:g} V (the DAQ's output range), got {bad[0]}")
        if self.test == RecordKind.HARMONIC and self.fs_Hz < 2.5 * self.frequency_Hz:
            raise ValueError("fs_Hz must be at least 2.5 x frequency_Hz")
        if self.test == RecordKind.HARMONIC and self.cycles / self.frequency_Hz > MAX_RECORD_S:
            raise ValueError(f"cycles / frequency_Hz is over {MAX_RECORD_S:g} s")
        if self.test == RecordKind.MULTISINE and self.fs_Hz < 2.5:  # its band is 0.1 Hz .. min(20 Hz, fs / 2.5)
            raise ValueError("fs_Hz must be at least 2.5 Hz for the multisine test")
        return self
