"""The ``[sample]`` of a rig file: a preset (the default) or a described strip with its operator."""

import pytest

from labrig.errors import BadInput
from labrig.rig import Rig, parse_rig

INSTRUMENTS = {"keyence": {"address": "socket://127.0.0.1:1"}, "loadcell": {"address": "socket://127.0.0.1:2"},
               "impedance": {"address": "TCPIP::127.0.0.1::3::SOCKET", "model": "IM3590"}, "daq": {}}
STRIP = {"name": "strip-C2", "length_m": 0.04, "width_m": 0.01, "thickness_m": 0.0002, "clamp_area_m2": 2e-5,
         "medium": "air", "batch": "B"}


def rig(sample):
    cfg = parse_rig({"instruments": INSTRUMENTS, **({"sample": sample} if sample is not None else {})}, "rig.toml")
    return Rig(cfg, None)  # sample_info needs no instrument


def test_the_preset_stays_the_default():
    r = rig(None)
    assert r.sample_info()["preset"] == "paper" and r.user_info() == {}


def test_a_described_strip_in_the_rig_file_sets_the_sample_the_user_and_the_clamp_area():
    r = rig({"specimen": STRIP, "operator": {"name": "B. Tech"}})
    assert r.sample_info() == STRIP and r.user_info() == {"name": "B. Tech"}
    assert r.clamp_area_m2 == 2e-5


@pytest.mark.parametrize("bad, where", [
    ({**STRIP, "length_m": float("inf")}, "sample.specimen.length_m"),
    ({**STRIP, "medium": "oil"}, "sample.specimen.medium"),
    ({k: v for k, v in STRIP.items() if k != "name"}, "sample.specimen.name"),
    ({**STRIP, "name": "a\x00b"}, "sample.specimen.name"),
])
def test_a_bad_strip_names_the_field(bad, where):
    with pytest.raises(BadInput, match=f"rig.toml: {where}"):
        rig({"specimen": bad})
