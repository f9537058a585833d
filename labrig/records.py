"""What a step of a session is: its kind, one enum from the protocols to the fit.

The kinds are stored in the session file as the plain strings they are (``/entry/<step>@kind``, the import
manifest's ``kind``); a ``StrEnum`` member equals its string, so a kind read back from a file compares equal to
the member. Convert with ``str()`` where a library wants a plain string (h5py attributes).
"""

from __future__ import annotations

from enum import StrEnum


class RecordKind(StrEnum):
    CLAMP = "clamp"  # bring the clamp to a force and hold it (the load cell's stream only)
    SETTLE = "settle"  # rest at 0 V (the load cell's stream only)
    EIS = "eis"  # an impedance spectrum from the analyser
    STEP = "step"  # a voltage step (DAQ time series)
    HARMONIC = "harmonic"  # a sine at one frequency and amplitude (seed 001's amplitude series)
    STEPPED_SINE = "stepped_sine"  # one record per drive frequency of a stepped-sine FRF
    MULTISINE = "multisine"  # periodic random-phase multisine (the BLA)
    FREE = "free"  # any other drive (imported time series)


TIME_KINDS = (RecordKind.STEP, RecordKind.HARMONIC, RecordKind.STEPPED_SINE, RecordKind.MULTISINE, RecordKind.FREE)
DATA_KINDS = TIME_KINDS + (RecordKind.EIS,)  # kinds that hold measured data a fit reads (an import manifest's kinds)
SINE_KINDS = (RecordKind.STEPPED_SINE, RecordKind.HARMONIC)  # demodulated at their frequency_Hz
HOLD_KINDS = (RecordKind.CLAMP, RecordKind.SETTLE)  # steps that set the bench up and measure nothing to fit
