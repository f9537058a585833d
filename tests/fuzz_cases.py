"""Seeded fuzz cases over everything a user hands labrig (issue 17 item 7), and how each outcome is classified.

Families: protocol TOML files, rig files, import manifests, their CSVs, sample tables (the manifest's
``[specimen]`` and the rig's ``[sample]``, DESIGN.md 6) and hostile session files. Each ``Case`` is a set
of files written under a temporary folder and a ``labrig`` command line; ``expect`` says what a correct
labrig does with it:

* ``"refuse"``: the input is garbage by an oracle written here from the bench's real limits (not read from
  labrig's models): exit 2 with one line, no traceback. Exit 0 is "exit 0 on garbage".
* ``"either"``: a plausible value (in range by the oracle, but maybe refused by a cross-field rule or the
  plan budget): exit 0 or exit 2 are both correct; a rig file pointing at dead addresses may give exit 3.
* ``"accept"``: valid input, exit 0 (exit 3 for a rig pointing at dead addresses).

``classify`` turns (expect, exit code, stderr, timed out) into one outcome: refused, accepted, traceback,
hang, exit0_on_garbage, multi_line (exit 2 but more than one line), leak (a canary from a file's content
appears in the output), refused_valid, or failed_mid_run (exit 1 or 3 where a refusal was due).
Used by tests/test_fuzz.py (a fast seeded subset, in process) and bench/fuzz.py (the long run, subprocesses).
"""

from __future__ import annotations

import gzip
import math
import os
import random
import shutil
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data"
CANARY = "CANARY_5ec4e7_DO_NOT_PRINT"  # written into files a case must not echo

OUTCOMES = ("refused", "accepted", "traceback", "hang", "exit0_on_garbage", "multi_line", "leak", "refused_valid", "failed_mid_run")
BAD = ("traceback", "hang", "exit0_on_garbage", "multi_line", "leak", "failed_mid_run")


@dataclass
class Case:
    family: str  # protocol | rig | manifest | csv | sample | session
    name: str
    argv: list[str]  # "{dir}" is replaced by the case's folder
    expect: str  # refuse | either | accept
    files: dict[str, bytes] = field(default_factory=dict)
    setup: Callable[[Path], None] | None = None  # FIFOs, symbolic links, hostile HDF5 files
    runs_bench: bool = False  # may start the simulated bench (slow: subprocess only in the suite)
    ok_codes: tuple[int, ...] = ()  # other exit codes that are correct for this case (3: dead rig addresses)

    def materialise(self, folder: Path) -> list[str]:
        folder.mkdir(parents=True, exist_ok=True)
        for rel, data in self.files.items():
            p = folder / rel
            p.parent.mkdir(parents=True, exist_ok=True)
            p.write_bytes(data)
        if self.setup is not None:
            self.setup(folder)
        return [a.replace("{dir}", str(folder)) for a in self.argv]


def classify(case: Case, code: int | None, out: str, err: str, timed_out: bool) -> str:
    if timed_out:
        return "hang"
    if "Traceback (most recent call last)" in err or "Traceback (most recent call last)" in out:
        return "traceback"
    if CANARY in err or CANARY in out:
        return "leak"
    lines = [ln for ln in err.strip().splitlines() if ln.strip()]
    if code == 2:
        if len(lines) != 1:
            return "multi_line"
        return "refused_valid" if case.expect == "accept" else "refused"
    if code == 0:
        return "exit0_on_garbage" if case.expect == "refuse" else "accepted"
    if code in case.ok_codes:
        return "accepted"
    if code is not None and code < 0:
        return "traceback"  # killed by a signal (a crash in a C library)
    return "failed_mid_run"


# ---------------------------------------------------------------------------------------------- values


def toml_value(v: Any) -> str:
    """A Python value as TOML text (inf and nan included: TOML has them)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, int):
        return str(v)
    if isinstance(v, str):
        out = v.replace("\\", "\\\\").replace('"', '\\"')
        out = "".join(c if 0x20 <= ord(c) != 0x7F else f"\\u{ord(c):04x}" for c in out)
        return f'"{out}"'
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k} = {toml_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(type(v))


def dump_toml(data: dict[str, Any]) -> bytes:
    """Top-level scalars first, then tables and arrays of tables (enough for labrig's files)."""
    lines = [f"{k} = {toml_value(v)}" for k, v in data.items() if not isinstance(v, dict) and not _is_table_list(v)]
    for k, v in data.items():
        if isinstance(v, dict):
            lines += _table(k, v)
        elif _is_table_list(v):
            for item in v:
                lines.append(f"\n[[{k}]]")
                lines += [f"{kk} = {toml_value(vv)}" for kk, vv in item.items()]
    return ("\n".join(lines) + "\n").encode()


def _table(name: str, d: dict[str, Any]) -> list[str]:
    lines = [f"\n[{name}]"] + [f"{k} = {toml_value(v)}" for k, v in d.items() if not isinstance(v, dict)]
    for k, v in d.items():
        if isinstance(v, dict):
            lines += _table(f"{name}.{k}", v)
    return lines


def _is_table_list(v: Any) -> bool:
    return isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v)


@dataclass(frozen=True)
class Range:
    """The oracle for one numeric field: what the bench and physics allow (lo, hi, open at lo?), an integer?
    and a typical sub-range in-range picks come from (so a plausible case runs in seconds)."""

    lo: float
    hi: float
    lo_open: bool = False
    integer: bool = False
    typ: tuple[float, float] | None = None

    def inside(self, v: float) -> bool:
        return (v > self.lo if self.lo_open else v >= self.lo) and v <= self.hi

    def pick(self, rng: random.Random) -> float | int:
        a, b = self.typ or (self.lo, self.hi)
        if self.integer:
            return rng.randint(int(max(a, self.lo + (1 if self.lo_open else 0))), int(b))
        if a > 0 and b / a > 100:
            return float(f"{math.exp(rng.uniform(math.log(a), math.log(b))):.4g}")
        v = rng.uniform(a, b)
        return float(f"{v:.4g}") if self.inside(float(f"{v:.4g}")) else b


GARBAGE: list[tuple[str, Any]] = [
    ("inf", math.inf), ("-inf", -math.inf), ("nan", math.nan), ("true", True), ("false", False),
    ("string", "1.0"), ("empty string", ""), ("list", [1.0]), ("table", {"x": 1}), ("NUL string", "a\x00b"),
]


def out_of_range(r: Range, rng: random.Random) -> tuple[str, float]:
    choices = [("1e12", 1e12), ("1e300", 1e300), ("-1e9", -1e9), ("-5", -5.0)]
    if r.lo > -1e6:
        choices.append(("below lo", r.lo - max(abs(r.lo), 1.0)))
    if r.lo_open:
        choices.append(("lo (open)", r.lo))
    if r.hi < 1e12:
        choices.append(("over hi", r.hi * 1.5 + 1.0))
    name, v = rng.choice(choices)
    if r.inside(v):  # e.g. -5 for a bias within +-10 V
        return "1e12", 1e12
    return name, v


# ---------------------------------------------------------------------------------------------- protocols

# the bench's limits, written from the instruments (not from labrig's models): DAQ AO +-10 V and the default
# safety.max_drive_V 2 V, a 98 N load cell with safety.max_force_N 90 N over the paper's 16 mm^2 clamp (5625 kPa),
# the analyser's 201-point segment table, 10 uHz..1 MHz and 5 mV..1 V, DAQ sample clock up to 100 kHz
DRIVE = Range(-2.0, 2.0, typ=(-1.5, 1.5))
PROTOCOL_ORACLE: dict[tuple[str, str], Range] = {
    ("", "pressure_kPa"): Range(0, 5625, lo_open=True, typ=(300, 5000)),
    ("", "rest_s"): Range(0, 3600, typ=(0, 30)),
    ("clamp", "pressures_kPa"): Range(0, 5625, lo_open=True, typ=(300, 5000)),
    ("clamp", "tolerance_N"): Range(0, 98, lo_open=True, typ=(0.2, 2)),
    ("clamp", "hold_s"): Range(0, 3600, typ=(0, 5)),
    ("clamp", "timeout_s"): Range(0, 3600, lo_open=True, typ=(60, 300)),
    ("clamp", "settle_s"): Range(0, 3600, typ=(0, 60)),
    ("eis", "f_start_Hz"): Range(1e-5, 1e6, typ=(0.05, 10)),
    ("eis", "f_stop_Hz"): Range(1e-5, 1e6, typ=(100, 1e5)),
    ("eis", "points"): Range(2, 201, integer=True, typ=(2, 60)),
    ("eis", "ac_V"): Range(5e-3, 1.0, typ=(5e-3, 0.1)),
    ("eis", "bias_V"): Range(-1.5, 1.5, typ=(-0.5, 0.5)),
    ("step", "amplitude_V"): DRIVE,
    ("step", "on_s"): Range(0, 3600, lo_open=True, typ=(1, 30)),
    ("step", "off_s"): Range(0, 3600, typ=(0, 30)),
    ("step", "fs_Hz"): Range(1, 1e5, typ=(50, 2000)),
    ("harmonic", "amplitude_V"): DRIVE,
    ("harmonic", "frequency_Hz"): Range(0, 4e4, lo_open=True, typ=(0.1, 20)),
    ("harmonic", "cycles"): Range(0, 1e5, lo_open=True, typ=(1, 10)),
    ("harmonic", "fs_Hz"): Range(1, 1e5, typ=(100, 2000)),
    ("stepped_sine", "amplitude_V"): DRIVE,
    ("stepped_sine", "f_start_Hz"): Range(1e-3, 800, typ=(0.1, 2)),
    ("stepped_sine", "f_stop_Hz"): Range(1e-3, 800, typ=(5, 40)),
    ("stepped_sine", "points"): Range(1, 200, integer=True, typ=(1, 12)),
    ("stepped_sine", "settle_cycles"): Range(0, 1e4, typ=(0, 4)),
    ("stepped_sine", "settle_min_s"): Range(0, 3600, typ=(0, 3)),
    ("stepped_sine", "measure_cycles"): Range(0, 1e4, lo_open=True, typ=(1, 6)),
    ("stepped_sine", "min_record_s"): Range(0, 3600, typ=(0, 3)),
    ("multisine", "rms_V"): Range(0, 0.5, lo_open=True, typ=(0.05, 0.4)),
    ("multisine", "f_min_Hz"): Range(0, 4e4, lo_open=True, typ=(0.1, 0.5)),
    ("multisine", "f_max_Hz"): Range(0, 4e4, lo_open=True, typ=(5, 40)),
    ("multisine", "period_s"): Range(0, 3600, lo_open=True, typ=(10, 20)),
    ("multisine", "periods"): Range(1, 1000, integer=True, typ=(1, 3)),
    ("multisine", "realisations"): Range(1, 100, integer=True, typ=(1, 3)),
    ("multisine", "fs_Hz"): Range(1, 1e5, typ=(200, 2000)),
    ("multisine", "seed"): Range(0, 2**32 - 1, integer=True, typ=(0, 10**6)),
    ("multisine", "lead_in_s"): Range(0, 3600, typ=(0, 5)),
    ("multisine", "lines_per_octave"): Range(0, 1000, typ=(0, 6)),
    ("multisine", "skip_one_in"): Range(1, 100, integer=True, typ=(1, 6)),
    ("multisine", "emphasis_Hz"): Range(0, 1e5, typ=(0, 10)),
    ("amplitude_series", "amplitudes_V"): DRIVE,
    ("amplitude_series", "frequency_Hz"): Range(0, 4e4, lo_open=True, typ=(0.2, 5)),
    ("amplitude_series", "cycles"): Range(0, 1e5, lo_open=True, typ=(1, 6)),
    ("amplitude_series", "fs_Hz"): Range(1, 1e5, typ=(100, 1000)),
    ("amplitude_series", "rest_s"): Range(0, 3600, typ=(0, 20)),
}
SHORT_PROTOCOLS = ("eis", "step", "harmonic", "stepped-sine", "multisine", "amplitude-series")


def preset(name: str) -> dict[str, Any]:
    return tomllib.loads((ROOT / "protocols" / "presets" / f"{name}.toml").read_text())


def _leaves(d: dict[str, Any], table: str = "") -> list[tuple[str, str]]:
    out = []
    for k, v in d.items():
        if isinstance(v, dict):
            out += _leaves(v, k)
        elif k != "protocol":
            out.append((table, k))
    return out


def _set(d: dict[str, Any], table: str, key: str, value: Any) -> None:
    (d[table] if table else d)[key] = value


def _get(d: dict[str, Any], table: str, key: str) -> Any:
    return (d[table] if table else d)[key]


def protocol_cases(rng: random.Random, n: int) -> list[Case]:
    cases = []
    for k in range(n):
        r = rng.random()
        name = rng.choice(SHORT_PROTOCOLS + ("paper-sweep",) * 2)
        data = preset(name)
        if name == "paper-sweep" and rng.random() < 0.5:
            data["amplitude_series"] = preset("amplitude-series")["amplitude_series"]
        table, key = rng.choice(_leaves(data))
        oracle = PROTOCOL_ORACLE.get((table, key)) or PROTOCOL_ORACLE.get(("", key))
        old = _get(data, table, key)
        is_list = isinstance(old, list)
        expect, what = "refuse", ""
        if r < 0.30:
            what, v = rng.choice(GARBAGE)
            _set(data, table, key, [old[0], v] if is_list and rng.random() < 0.5 else v)
        elif r < 0.55 and oracle is not None:
            what, v = out_of_range(oracle, rng)
            v = int(v) if oracle.integer and abs(v) < 1e18 and float(v).is_integer() else v
            _set(data, table, key, [v] if is_list else v)
        elif r < 0.62:
            what = "unknown key"
            (data[table] if table else data)[key + rng.choice(["_", "x", "s"])] = 1.0
        elif r < 0.66:
            what = "protocol name"
            data["protocol"] = rng.choice(["nope", "", "eis ", "EIS", "paper_sweep"])
        elif r < 0.70:
            what = "empty list" if is_list else "removed"
            if is_list:
                _set(data, table, key, [])
            else:
                del (data[table] if table else data)[key]
                expect = "either"
        elif oracle is not None and name != "paper-sweep":
            what, expect = "in range", "either"
            v = oracle.pick(rng)
            _set(data, table, key, [v] if is_list else v)
        else:
            what = "whole-file garbage"
            cases.append(_garbage_file_case("protocol", k, rng, lambda p: ["run", p, "--sim", "--quiet", "--out", "{dir}/out.h5"]))
            continue
        text = dump_toml(data)
        cases.append(Case("protocol", f"{name}: {table + '.' if table else ''}{key} = {what}", ["run", "{dir}/p.toml", "--sim", "--quiet", "--out", "{dir}/out.h5"],
                          expect, {"p.toml": text}, runs_bench=expect != "refuse"))
    return cases


def _garbage_bytes(rng: random.Random) -> tuple[str, bytes]:
    kind = rng.choice(["random bytes", "not UTF-8", "NUL bytes", "deep nesting", "huge", "empty", "secret"])
    if kind == "random bytes":
        return kind, bytes(rng.getrandbits(8) for _ in range(rng.randint(1, 400)))
    if kind == "not UTF-8":
        return kind, b'protocol = "eis"\n# caf\xe9\n'
    if kind == "NUL bytes":
        return kind, b'protocol = "eis\x00"\n'
    if kind == "deep nesting":
        return kind, b"a = " + b"[" * 5000 + b"]" * 5000 + b"\n"
    if kind == "huge":
        return kind, b"# " + b"x" * (3 << 20) + b"\n"
    if kind == "empty":
        return kind, b""
    return kind, f"{CANARY}=1\nPATH=/usr/bin\n".encode()


def _garbage_file_case(family: str, k: int, rng: random.Random, argv: Callable[[str], list[str]]) -> Case:
    kind, data = _garbage_bytes(rng)
    special = rng.random()
    if special < 0.15:
        return Case(family, f"{family} file is /dev/zero", argv("/dev/zero"), "refuse")
    if special < 0.25:
        return Case(family, f"{family} file is a FIFO", argv("{dir}/fifo.toml"), "refuse", setup=lambda d: os.mkfifo(d / "fifo.toml"))
    if special < 0.30:
        return Case(family, f"{family} file is a directory", argv("{dir}/adir"), "refuse", setup=lambda d: (d / "adir").mkdir())
    return Case(family, f"{family} file: {kind}", argv("{dir}/f.toml"), "refuse", {"f.toml": data})


# ---------------------------------------------------------------------------------------------- rig and sample files

DEAD = "127.0.0.1:9"  # loopback discard port: nothing listens, a connection is refused at once
RIG_BASE: dict[str, Any] = {
    "clock": {"time_scale": 1000.0, "epoch_wall": 1.7e9},
    "sample": {"preset": "paper"},
    "safety": {"max_drive_V": 2.0, "max_current_A": 0.2, "max_force_N": 90.0},
    "instruments": {
        "keyence": {"address": f"socket://{DEAD}", "dialect": "LK-G"},
        "loadcell": {"address": f"socket://{DEAD}"},
        "clamp": {"mode": "operator"},
        "impedance": {"address": "TCPIP::127.0.0.1::9::SOCKET", "model": "IM3590"},
        "daq": {"address": DEAD, "device": "Dev1", "current_gain_A_per_V": 1e-3, "displacement_m_per_V": 1e-3},
    },
}
RIG_ORACLE: dict[tuple[str, str], Range] = {
    ("clock", "time_scale"): Range(0.1, 1e5, typ=(1, 5000)),  # slower than a tenth of real time is no bench
    ("clock", "epoch_wall"): Range(0, 4e9, typ=(1e9, 2e9)),
    ("safety", "max_drive_V"): Range(0, 10, lo_open=True, typ=(0.5, 5)),
    ("safety", "max_current_A"): Range(0, 10, lo_open=True, typ=(0.01, 1)),
    ("safety", "max_force_N"): Range(0, 98, lo_open=True, typ=(10, 95)),
    ("daq", "current_gain_A_per_V"): Range(0, 100, lo_open=True, typ=(1e-6, 1)),
    ("daq", "displacement_m_per_V"): Range(0, 1, lo_open=True, typ=(1e-5, 1e-2)),
}


def _rig_leaves() -> list[tuple[str, str]]:
    out = [(t, k) for t in ("clock", "sample", "safety") for k in RIG_BASE[t]]
    return out + [(f"instruments.{i}", k) for i, d in RIG_BASE["instruments"].items() for k in d]


def _rig_table(data: dict[str, Any], table: str) -> dict[str, Any]:
    d = data
    for part in table.split("."):
        d = d[part]
    return d


def rig_cases(rng: random.Random, n: int) -> list[Case]:
    import copy

    cases = []
    argv = ["run", "eis", "--rig", "{dir}/rig.toml", "--quiet", "--out", "{dir}/out.h5"]
    for k in range(n):
        data = copy.deepcopy(RIG_BASE)
        table, key = rng.choice(_rig_leaves())
        oracle = RIG_ORACLE.get((table.split(".")[-1], key))
        r = rng.random()
        expect = "refuse"
        if r < 0.35:
            what, v = rng.choice(GARBAGE)
            _rig_table(data, table)[key] = v
        elif r < 0.6 and oracle is not None:
            what, v = out_of_range(oracle, rng)
            _rig_table(data, table)[key] = v
        elif r < 0.68:
            what = "unknown key"
            _rig_table(data, table)[key + "_"] = 1.0
        elif r < 0.75:
            what, v = "address garbage", rng.choice(["", "a\x00b", "x" * 5000, "\n"])
            table, key = "instruments.impedance", "address"
            _rig_table(data, table)[key] = v
        elif r < 0.8:
            what = "sample preset"
            data["sample"]["preset"] = rng.choice(["nope", "", "PAPER", "paper\x00"])
        elif r < 0.9 and oracle is not None:
            what, expect = "in range", "either"
            _rig_table(data, table)[key] = oracle.pick(rng)
        else:
            cases.append(_garbage_file_case("rig", k, rng, lambda p: ["run", "eis", "--rig", p, "--quiet", "--out", "{dir}/out.h5"]))
            continue
        cases.append(Case("rig", f"rig {table}.{key} = {what}", argv, expect, {"rig.toml": dump_toml(data)}, ok_codes=(3,)))
    return cases


# ---------------------------------------------------------------------------------------------- import manifests, CSVs, specimens

SPECIMEN_ORACLE = {
    "length_m": Range(0, 1, lo_open=True, typ=(0.01, 0.05)),
    "width_m": Range(0, 1, lo_open=True, typ=(0.002, 0.01)),
    "thickness_m": Range(0, 0.01, lo_open=True, typ=(1e-4, 5e-4)),
    "clamp_area_m2": Range(0, 0.01, lo_open=True, typ=(1e-5, 5e-5)),
}
RECORD_ORACLE = {
    "pressure_kPa": Range(0, 1e5, lo_open=True, typ=(100, 5000)),
    "frequency_Hz": Range(0, 1e7, lo_open=True, typ=(0.1, 20)),
    "amplitude_V": Range(0, 1000, lo_open=True, typ=(0.1, 2)),
    "temperature_C": Range(-273.15, 1000, lo_open=True, typ=(5, 60)),
}


def example_files() -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in (DATA / "import_example").iterdir() if p.is_file()}


def manifest_cases(rng: random.Random, n: int) -> list[Case]:
    cases = []
    argv = ["import", "{dir}/ex/manifest.toml", "--out", "{dir}/out.h5"]
    for k in range(n):
        files = {f"ex/{k2}": v for k2, v in example_files().items()}
        m = tomllib.loads(files["ex/manifest.toml"].decode())
        r = rng.random()
        expect, setup, extra = "refuse", None, []
        rec = rng.choice(m["record"])
        if r < 0.2:
            key = rng.choice(list(RECORD_ORACLE) + ["kind", "file", "label"])
            what, v = rng.choice(GARBAGE)
            rec[key] = v
            name = f"record {key} = {what}"
            if key == "label" and what == "string":
                expect = "either"  # "1.0" is a fine label
        elif r < 0.35:
            key = rng.choice(list(RECORD_ORACLE))
            what, v = out_of_range(RECORD_ORACLE[key], rng)
            rec[key] = v
            name = f"record {key} = {what}"
        elif r < 0.5:
            key = rng.choice(list(SPECIMEN_ORACLE) + ["medium"])
            if key == "medium" or rng.random() < 0.5:
                what, v = rng.choice(GARBAGE + [("oil", "oil")])
            else:
                what, v = out_of_range(SPECIMEN_ORACLE[key], rng)
            m["specimen"][key] = v
            name = f"specimen {key} = {what}"
        elif r < 0.72:
            target = rng.choice(["/etc/passwd", "/proc/self/environ", "/dev/zero", "../secret.csv", "../../../../../etc/hostname",
                                 "link.csv", "fifo.csv", "adir", "nonexistent.csv", "/dev/stdin"])
            rec["file"] = target
            name = f"record file = {target}"
            if target == "link.csv":
                setup = lambda d: (d / "secret.csv").write_text(f"t_s,v_V,i_A,disp_m\n{CANARY}\n") or os.symlink(d / "secret.csv", d / "ex" / "link.csv")  # noqa: E731
            elif target == "fifo.csv":
                setup = lambda d: os.mkfifo(d / "ex" / "fifo.csv")  # noqa: E731
            elif target == "adir":
                setup = lambda d: (d / "ex" / "adir").mkdir()  # noqa: E731
            elif target == "../secret.csv":
                setup = lambda d: (d / "secret.csv").write_text(f"{CANARY},v_V\n1,2\n")  # noqa: E731
            if target != "nonexistent.csv" and target != "adir" and target != "fifo.csv" and rng.random() < 0.3:
                extra = ["--allow-outside"]  # allowed outside, still a device, a FIFO or not a CSV: refused
        elif r < 0.8:
            name = "in range"
            if rng.random() < 0.5:
                key = rng.choice(list(RECORD_ORACLE))
                rec[key] = RECORD_ORACLE[key].pick(rng)
                name = f"record {key} in range"
            else:
                key = rng.choice(list(SPECIMEN_ORACLE))
                m["specimen"][key] = SPECIMEN_ORACLE[key].pick(rng)
                name = f"specimen {key} in range"
            expect = "either"
        else:
            cases.append(csv_case(rng, k, files, m, rec))
            continue
        files["ex/manifest.toml"] = dump_toml(m)
        fam = "sample" if name.startswith("specimen") else "manifest"
        cases.append(Case(fam, name, argv + extra, expect, files, setup))
    return cases


def csv_case(rng: random.Random, k: int, files: dict[str, bytes], m: dict[str, Any], rec: dict[str, Any]) -> Case:
    path = f"ex/{rec['file']}"
    text = files[path].decode()
    lines = text.splitlines()
    expect = "refuse"
    kind = rng.choice(["cell inf", "cell nan", "cell true", "cell text", "cell NUL", "secret header", "short row", "long row",
                       "huge line", "huge quoted field", "not UTF-8", "empty", "header only", "time backwards", "random bytes",
                       "BOM", "reordered columns", "blank lines", "CRLF", "extra spaces"])
    row = rng.randint(1, len(lines) - 1)
    cells = lines[row].split(",")
    col = rng.randrange(len(cells))
    if kind.startswith("cell"):
        cells[col] = {"cell inf": "inf", "cell nan": "NaN", "cell true": "true", "cell text": f"{CANARY}", "cell NUL": "1\x002"}[kind]
        lines[row] = ",".join(cells)
    elif kind == "secret header":
        lines[0] = lines[0] + "," + CANARY
    elif kind == "short row":
        lines[row] = ",".join(cells[:-1])
    elif kind == "long row":
        lines[row] = lines[row] + ",1"
    elif kind == "huge line":
        lines[row] = "1," * 2_000_000 + "1"
    elif kind == "huge quoted field":
        lines[row] = '"' + "9" * 300_000 + '",1,1,1'
    elif kind == "empty":
        lines = []
    elif kind == "header only":
        lines = lines[:1]
    elif kind == "time backwards" and lines[0].startswith("t_s") and len(lines) > 3:
        lines[2], lines[3] = lines[3], lines[2]
    elif kind == "time backwards":
        lines[row] = lines[row].replace(cells[0], "-" + cells[0], 1)  # a negative frequency
    elif kind in ("reordered columns", "blank lines", "CRLF", "extra spaces"):
        expect = "accept"
        if kind == "reordered columns":
            table = [ln.split(",") for ln in lines]
            order = list(range(len(table[0])))
            rng.shuffle(order)
            lines = [",".join(r[i] for i in order) for r in table]
        elif kind == "blank lines":
            lines.insert(row, "")
        elif kind == "extra spaces":
            lines[0] = ", ".join(lines[0].split(","))
    data = ("\r\n" if kind == "CRLF" else "\n").join(lines).encode() + (b"\n" if lines else b"")
    if kind == "not UTF-8":
        data = data.replace(b"0", b"\xff", 1)
    elif kind == "random bytes":
        data = bytes(rng.getrandbits(8) for _ in range(500))
    elif kind == "BOM":
        data = b"\xef\xbb\xbf" + data
        expect = "either"
    files = dict(files)
    files[path] = data
    files["ex/manifest.toml"] = dump_toml(m)
    return Case("csv", f"{rec['file']}: {kind}", ["import", "{dir}/ex/manifest.toml", "--out", "{dir}/out.h5"], expect, files)


def sample_cases(rng: random.Random, n: int) -> list[Case]:
    """The strip's description: the rig's [sample] table (preset and, once the operator's fields land, the
    specimen fields of DESIGN.md 6), fuzzed on a rig with dead addresses (exit 3 once it is accepted)."""
    import copy

    cases = []
    for k in range(n):
        data = copy.deepcopy(RIG_BASE)
        key = rng.choice(["preset", "name", "temperature_C", "length_m", "operator"])
        what, v = rng.choice(GARBAGE + [("unknown preset", "nope"), ("long", "p" * 10_000)])
        if key == "operator":
            data["sample"]["operator"] = {"name": v}
        else:
            data["sample"][key] = v
        cases.append(Case("sample", f"rig [sample] {key} = {what}", ["run", "eis", "--rig", "{dir}/rig.toml", "--quiet", "--out", "{dir}/out.h5"],
                          "refuse", {"rig.toml": dump_toml(data)}, ok_codes=(3,)))
    return cases


# ---------------------------------------------------------------------------------------------- hostile sessions

SESSION_COMMANDS = [
    ["inspect", "{dir}/s.h5"],
    ["inspect", "{dir}/s.h5", "--json"],
    ["fit", "{dir}/s.h5", "--json"],
    ["export", "{dir}/s.h5", "--out", "{dir}/exp"],
    ["report", "{dir}/s.h5", "--out", "{dir}/r.html"],
    ["diagnose", "{dir}/s.h5", "--json"],
    ["replay", "{dir}/s.h5", "--check"],
]


def base_session(name: str, folder: Path) -> Path:
    """A real session (tests/data/sessions/*.h5.gz, recorded on the simulated bench) unpacked under ``folder``."""
    out = folder / f"{name}.h5"
    if not out.exists():
        with gzip.open(DATA / "sessions" / f"{name}.h5.gz", "rb") as src, open(out, "wb") as dst:
            shutil.copyfileobj(src, dst)
    return out


def _objects(f: Any) -> tuple[list[str], list[str]]:
    import h5py

    groups, datasets = [], []
    f.visititems(lambda n, o: (groups if isinstance(o, h5py.Group) else datasets).append(n))
    return groups, datasets


def _attr_owners(f: Any) -> list[tuple[str, str]]:
    out = []
    f.visititems(lambda n, o: out.extend((n, a) for a in o.attrs))
    return out


def hostile_mutation(rng: random.Random) -> tuple[str, str, Callable[[Any, random.Random], None]]:
    """(name, expect, mutate(h5py.File, rng)). ``expect`` "refuse" for hostile, "either" for damage the
    reader may survive, "accept" for a harmless addition."""
    import h5py

    def pick_ds(f: Any, kinds: str = "") -> str:
        _, ds = _objects(f)
        ds = [d for d in ds if not kinds or f[d].dtype.kind in kinds]
        return rng.choice(ds)

    def external_link(f, rng):
        f["entry/evil"] = h5py.ExternalLink("/etc/passwd", "/x")

    def external_replaces(f, rng):
        d = pick_ds(f)
        del f[d]
        f[d] = h5py.ExternalLink(rng.choice(["/etc/passwd", "other.h5", "/dev/zero"]), "/data")

    def soft_cycle(f, rng):
        g, _ = _objects(f)
        f[rng.choice(g) + "/loop"] = h5py.SoftLink("/entry")

    def soft_replaces(f, rng):
        d = pick_ds(f)
        del f[d]
        f[d] = h5py.SoftLink("/entry/nothing/here")

    def hard_cycle(f, rng):
        g, _ = _objects(f)
        f[rng.choice(g) + "/up"] = f["entry"]

    def delete_ds(f, rng):
        del f[pick_ds(f)]

    def delete_group(f, rng):
        g, _ = _objects(f)
        del f[rng.choice([x for x in g if x != "entry"])]

    def delete_attr(f, rng):
        n, a = rng.choice([x for x in _attr_owners(f) if x[1] != "NX_class"])
        del f[n].attrs[a]

    def attr_wrong_type(f, rng):
        n, a = rng.choice(_attr_owners(f))
        f[n].attrs[a] = rng.choice([np.float64(np.nan), np.int64(-1), np.arange(3.0), b"\xff\xfe", "[[[", "{}", np.int64(2**62), "x" * 100_000])

    def json_garbage(f, rng):
        owners = [x for x in _attr_owners(f) if x[1].endswith("json")]
        n, a = rng.choice(owners)
        f[n].attrs[a] = rng.choice(["{", "[]", "null", "1e999", '{"pressure_kPa": "high"}', '{"fs_Hz": [1, "a"]}', "[" * 100_000 + "]" * 100_000,
                                    '{"frequency_Hz": null}', '{"pressure_kPa": NaN}', np.bytes_(b"{\x00}")])

    def ds_wrong_type(f, rng):
        d = pick_ds(f)
        del f[d]
        f[d] = rng.choice([np.array("text"), np.arange(6.0).reshape(2, 3), np.zeros(3, dtype=[("a", "f8"), ("b", "i4")]),
                           np.array([1 + 2j]), np.float64(1.0), np.zeros((0,)), np.array([b"abc"])])

    def ds_to_group(f, rng):
        d = pick_ds(f)
        del f[d]
        f.create_group(d)

    def huge_ds(f, rng):
        d = pick_ds(f, "f")
        del f[d]
        f.create_dataset(d, shape=(10**11,), maxshape=(None,), dtype="f8", chunks=(65536,))

    def committed_garbage(f, rng):
        _, ds = _objects(f)
        d = rng.choice([x for x in ds if x.endswith("committed_rows")] or ds)
        del f[d]
        f[d] = rng.choice([np.int64(-5), np.int64(10**15), np.float64(np.nan), np.array("x")])

    def index_garbage(f, rng):
        g = rng.choice([x for x in _objects(f)[0] if x.count("/") == 2 and x.startswith("entry/steps/")])
        f[g].attrs["index"] = rng.choice([np.int64(-1), np.int64(0), np.int64(10**12), "1", np.float64(1.5)])

    def status_garbage(f, rng):
        _, ds = _objects(f)
        d = rng.choice([x for x in ds if x.endswith("/status") or x.endswith("exit_status")])
        f[d][()] = rng.choice([b"exploded", b"\xff\xff", b""])

    def columns_garbage(f, rng):
        g = rng.choice([x for x in _objects(f)[0] if "columns" in f[x].attrs])
        f[g].attrs["columns"] = rng.choice([np.array([b"../../provenance"], dtype=h5py.string_dtype()), np.array([b"nope"], dtype=h5py.string_dtype()),
                                            np.array([], dtype=h5py.string_dtype()), np.arange(2)])

    def virtual_ds(f, rng):
        layout = h5py.VirtualLayout(shape=(4,), dtype="f8")
        layout[:] = h5py.VirtualSource("/etc/passwd", "x", shape=(4,))
        d = pick_ds(f, "f")
        del f[d]
        f.create_virtual_dataset(d, layout, fillvalue=0)

    def external_storage(f, rng):
        d = pick_ds(f, "f")
        del f[d]
        f.create_dataset(d, shape=(16,), dtype="u1", external=[("/etc/passwd", 0, h5py.h5f.UNLIMITED)])

    def nan_stream(f, rng):
        d = rng.choice([x for x in _objects(f)[1] if "/steps/" in x and f[x].ndim == 1 and f[x].dtype.kind == "f"])
        arr = f[d][()]
        if arr.size:
            arr[rng.randrange(arr.size)] = rng.choice([np.nan, np.inf, -1e308])
            f[d][...] = arr

    def harmless_attr(f, rng):
        f["entry"].attrs["note_from_viewer"] = "opened in HDFView"

    def harmless_group(f, rng):
        g = f.create_group("entry/extra_notes")
        g["n"] = np.arange(3.0)

    table = [
        ("external link", "refuse", external_link), ("external link replaces a dataset", "refuse", external_replaces),
        ("soft link cycle", "refuse", soft_cycle), ("dangling soft link", "refuse", soft_replaces), ("hard link cycle", "refuse", hard_cycle),
        ("dataset deleted", "either", delete_ds), ("group deleted", "either", delete_group), ("attribute deleted", "either", delete_attr),
        ("attribute of the wrong type", "either", attr_wrong_type), ("JSON garbage", "either", json_garbage),
        ("dataset of the wrong type or shape", "either", ds_wrong_type), ("dataset replaced by a group", "either", ds_to_group),
        ("1e11-row dataset", "refuse", huge_ds), ("committed_rows garbage", "either", committed_garbage),
        ("step index garbage", "either", index_garbage), ("status garbage", "either", status_garbage),
        ("stream columns garbage", "either", columns_garbage), ("virtual dataset reading /etc/passwd", "refuse", virtual_ds),
        ("dataset stored in /etc/passwd", "refuse", external_storage), ("non-finite sample in a stream", "either", nan_stream),
        ("harmless extra attribute", "accept", harmless_attr), ("harmless extra group", "accept", harmless_group),
    ]
    return rng.choice(table)


def session_cases(rng: random.Random, n: int, commands: list[list[str]] | None = None) -> list[Case]:
    cases = []
    for k in range(n):
        r = rng.random()
        base = rng.choice(["eis", "step", "stepped-sine"])
        argv = rng.choice(commands or SESSION_COMMANDS)
        if r < 0.12:
            kind = rng.choice(["truncated", "bytes flipped", "not HDF5", "empty", "FIFO", "HDF5 but not a session"])
            # flipped bits in sample data are undetectable without checksums (labrig writes none): either outcome is right
            expect = "either" if kind == "bytes flipped" else "refuse"
            cases.append(Case("session", f"{base}: {kind} / {argv[0]}", argv, expect, setup=_file_damage(base, kind, rng.randrange(2**32))))
            continue
        name, expect, mutate = hostile_mutation(rng)
        seed = rng.randrange(2**32)
        cases.append(Case("session", f"{base}: {name} / {' '.join(argv[:1] + argv[2:])}", argv, expect,
                          setup=_mutated(base, mutate, seed), ok_codes=(1,) if argv[0] == "replay" else ()))
    return cases


def _mutated(base: str, mutate: Callable[[Any, random.Random], None], seed: int) -> Callable[[Path], None]:
    def setup(folder: Path) -> None:
        import h5py

        src = base_session(base, folder.parent)
        for attempt in range(10):  # a mutation that does not apply to this file (nothing to pick) draws again
            shutil.copy(src, folder / "s.h5")
            try:
                with h5py.File(folder / "s.h5", "a") as f:
                    mutate(f, random.Random(seed + attempt))
                return
            except (IndexError, ValueError, TypeError, KeyError):
                continue
        raise RuntimeError(f"could not apply the mutation to {base}")

    return setup


def _file_damage(base: str, kind: str, seed: int) -> Callable[[Path], None]:
    def setup(folder: Path) -> None:
        import h5py

        target = folder / "s.h5"
        if kind == "FIFO":
            os.mkfifo(target)
            return
        if kind == "HDF5 but not a session":
            with h5py.File(target, "w") as f:
                f["entry/x"] = 1
            return
        data = bytearray(base_session(base, folder.parent).read_bytes())
        rng = random.Random(seed)
        if kind == "truncated":
            data = data[: rng.randrange(1, len(data))]
        elif kind == "bytes flipped":
            for _ in range(rng.randint(1, 8)):
                data[rng.randrange(2048, len(data))] ^= 1 << rng.randrange(8)
        elif kind == "not HDF5":
            data = bytearray(f"{CANARY}\n".encode() * 10)
        elif kind == "empty":
            data = bytearray()
        target.write_bytes(bytes(data))

    return setup


# ---------------------------------------------------------------------------------------------- all of it


def all_cases(seed: int, n: int, families: tuple[str, ...] = ("protocol", "rig", "manifest", "sample", "session")) -> list[Case]:
    """``n`` cases spread over the families (import manifests include their CSVs), seeded."""
    rng = random.Random(seed)
    share = {"protocol": 0.25, "rig": 0.12, "manifest": 0.28, "sample": 0.05, "session": 0.30}
    total = sum(share[f] for f in families)
    out: list[Case] = []
    for fam in families:
        k = max(1, round(n * share[fam] / total))
        sub = random.Random(rng.randrange(2**32))
        out += {"protocol": protocol_cases, "rig": rig_cases, "manifest": manifest_cases, "sample": sample_cases, "session": session_cases}[fam](sub, k)
    return out
