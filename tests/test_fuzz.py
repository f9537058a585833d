"""Input that is not trusted (issue 17 items 5-7): the probe's findings one by one, a fast seeded fuzz subset run in
process through ``labrig.cli.main``, and servers a bad client cannot stall. The long run is bench/fuzz.py."""

from __future__ import annotations

import contextlib
import io
import signal
import socket
import time

import h5py
import pytest

import fuzz_cases as fc
from labrig.cli import main

SUBSET_SEED = 1717


class _Hang(Exception):
    pass


def run_in_process(case: fc.Case, folder, limit_s: int = 20) -> tuple[str, str]:
    """(outcome, stderr) of one case through the real entry point; SIGALRM turns a hang into an outcome."""
    argv = case.materialise(folder)
    out, err = io.StringIO(), io.StringIO()

    def alarm(signum, frame):
        raise _Hang

    old = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(limit_s)
    code, timed_out = None, False
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main(argv)
    except _Hang:
        timed_out = True
    except BaseException as exc:  # anything escaping main is a traceback for the user
        err.write(f"Traceback (most recent call last)\n{type(exc).__name__}: {exc}\n")
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
    return fc.classify(case, code, out.getvalue(), err.getvalue(), timed_out), err.getvalue()


def _refusal(tmp_path, argv: list[str]) -> str:
    case = fc.Case("probe", "probe", argv, "refuse")
    outcome, err = run_in_process(case, tmp_path)
    assert outcome == "refused", (outcome, err)
    return err.strip()


# ---------------------------------------------------------------------------------------------- the probe's findings

PROTOCOL_PROBES = [
    ('protocol = "step"\n[step]\nfs_Hz = inf\n', "step.fs_Hz: Input should be a finite number"),
    ('protocol = "step"\n[step]\nfs_Hz = 1e12\n', "step.fs_Hz: Input should be less than or equal to 100000"),
    ('protocol = "step"\n[step]\nfs_Hz = 100000.0\non_s = 3000\n', "is over the 5e+06 a record may hold"),
    ('protocol = "eis"\n[clamp]\nsettle_s = 1e9\n', "clamp.settle_s: Input should be less than or equal to 3600"),
    ('protocol = "eis"\n[eis]\npoints = 300\n', "eis.points: Input should be less than or equal to 201"),
    ('protocol = "eis"\npressure_kPa = -5\n', "pressure_kPa: Input should be greater than 0"),
    ('protocol = "eis"\npressure_kPa = true\n', "pressure_kPa: Input should be a valid number"),
    ('protocol = "multisine"\n[multisine]\nseed = -1\n', "multisine.seed: Input should be greater than or equal to 0"),
    ('protocol = "paper-sweep"\nrest_s = 3600.0\n[clamp]\npressures_kPa = [612, 700, 800, 900, 1000, 1100, 1200, 1300, 1400, 1500, 1600, 1700, 1800, 1900]\n',
     "of rig time by step"),
]


@pytest.mark.parametrize("text, says", PROTOCOL_PROBES, ids=[p[1][:30] for p in PROTOCOL_PROBES])
def test_protocol_garbage_is_refused_before_the_bench_starts(tmp_path, text, says):
    (tmp_path / "p.toml").write_text(text)
    line = _refusal(tmp_path, ["run", str(tmp_path / "p.toml"), "--sim", "--quiet", "--out", str(tmp_path / "o.h5")])
    assert str(tmp_path / "p.toml") in line and says in line, line
    assert not (tmp_path / "o.h5").exists()


RIG_PROBES = [
    ("clock", "time_scale", "inf", "clock.time_scale: Input should be a finite number"),
    ("clock", "epoch_wall", "nan", "clock.epoch_wall: Input should be a finite number"),
    ("safety", "max_drive_V", "inf", "safety.max_drive_V: Input should be a finite number"),
    ("safety", "max_current_A", "true", "safety.max_current_A: Input should be a valid number"),
    ("instruments.daq", "current_gain_A_per_V", "inf", "instruments.daq.current_gain_A_per_V: Input should be a finite number"),
]


@pytest.mark.parametrize("table, key, value, says", RIG_PROBES, ids=[f"{p[1]}={p[2]}" for p in RIG_PROBES])
def test_rig_garbage_is_refused_before_any_instrument_opens(tmp_path, table, key, value, says):
    text = fc.dump_toml(fc.RIG_BASE).decode()
    lines = text.splitlines()
    k = lines.index(f"[{table}]")
    lines = [ln for ln in lines if not ln.startswith(f"{key} =")]
    lines.insert(k + 1, f"{key} = {value}")
    (tmp_path / "rig.toml").write_text("\n".join(lines) + "\n")
    line = _refusal(tmp_path, ["run", "eis", "--rig", str(tmp_path / "rig.toml"), "--quiet", "--out", str(tmp_path / "o.h5")])
    assert says in line, line


def test_a_rig_file_that_is_not_utf8_is_one_line(tmp_path):
    (tmp_path / "rig.toml").write_bytes(b"[clock]\ntime_scale = 1000.0 # \xff\xfe\n")
    line = _refusal(tmp_path, ["run", "eis", "--rig", str(tmp_path / "rig.toml"), "--quiet", "--out", str(tmp_path / "o.h5")])
    assert "not UTF-8 text" in line


def _example(tmp_path, **record) -> str:
    files = {f"ex/{k}": v for k, v in fc.example_files().items()}
    import tomllib

    m = tomllib.loads(files["ex/manifest.toml"].decode())
    m["record"][0].update(record)
    files["ex/manifest.toml"] = fc.dump_toml(m)
    for rel, data in files.items():
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_bytes(data)
    return str(tmp_path / "ex" / "manifest.toml")


def test_a_nul_in_a_label_is_refused(tmp_path):
    line = _refusal(tmp_path, ["import", _example(tmp_path, label="p612\x00step"), "--out", str(tmp_path / "o.h5")])
    assert "record #1 (p612_step.csv), field label: contains a control character" in line


def test_manifest_files_stay_in_the_manifest_folder_and_no_content_is_printed(tmp_path):
    secret = tmp_path / "secret.csv"
    secret.write_text(f"{fc.CANARY},v_V\n1,2\n")
    for target in ("/proc/self/environ", "../secret.csv", "/etc/passwd"):
        line = _refusal(tmp_path / target.replace("/", "_"), ["import", _example(tmp_path / target.replace("/", "_"), file=target), "--out", str(tmp_path / "o.h5")])
        assert "is outside the manifest's folder" in line and "--allow-outside" in line
    # allowed outside: read, but the error still names the place, never the text
    line = _refusal(tmp_path / "a", ["import", _example(tmp_path / "a", file=str(secret)), "--out", str(tmp_path / "o.h5"), "--allow-outside"])
    assert "line 1, column 1: unknown column name" in line and fc.CANARY not in line
    for target in ("/dev/zero", "/proc/self/environ"):
        line = _refusal(tmp_path / "b", ["import", _example(tmp_path / "b", file=target), "--out", str(tmp_path / "o.h5"), "--allow-outside"])
        assert "PATH=" not in line and ("not a regular file" in line or "unknown column name" in line or "not CSV text" in line), line


def test_a_symlink_out_of_the_folder_is_outside(tmp_path):
    (tmp_path / "secret.csv").write_text(f"t_s,v_V,i_A,disp_m\n{fc.CANARY}\n")
    manifest = _example(tmp_path, file="link.csv")
    (tmp_path / "ex" / "link.csv").symlink_to(tmp_path / "secret.csv")
    line = _refusal(tmp_path, ["import", manifest, "--out", str(tmp_path / "o.h5")])
    assert "outside the manifest's folder" in line


HOSTILE = [
    ("external link", lambda f: f.__setitem__("entry/evil", h5py.ExternalLink("/etc/passwd", "/x")), "external link to another file"),
    ("soft link", lambda f: f.__setitem__("entry/steps/loop", h5py.SoftLink("/entry")), "soft link"),
    ("hard-link cycle", lambda f: f.__setitem__("entry/steps/up", f["entry"]), "linked twice"),
    ("allocation bomb", lambda f: (f.__delitem__("entry/end/wall"), f.create_dataset("entry/end/wall", shape=(10**11,), maxshape=(None,), dtype="f8", chunks=(65536,))),
     "elements is over"),
    ("metadata not JSON", lambda f: f["entry/steps/000_clamp"].attrs.__setitem__("metadata_json", "{"), "is not valid JSON"),
    ("pressure as text", lambda f: f["entry/steps/000_clamp"].attrs.__setitem__("metadata_json", '{"pressure_kPa": "high"}'), "is not a finite number"),
]


@pytest.mark.parametrize("name, mutate, says", HOSTILE, ids=[h[0] for h in HOSTILE])
@pytest.mark.parametrize("command", ["inspect", "fit", "export"])
def test_hostile_session_is_one_line(tmp_path, name, mutate, says, command):
    src = fc.base_session("eis", tmp_path)
    target = tmp_path / "s.h5"
    target.write_bytes(src.read_bytes())
    with h5py.File(target, "a") as f:
        mutate(f)
    argv = {"inspect": ["inspect", str(target)], "fit": ["fit", str(target), "--json"], "export": ["export", str(target), "--out", str(tmp_path / "exp")]}[command]
    line = _refusal(tmp_path / "case", argv)
    assert str(target) in line and says in line, line


def test_an_untouched_session_still_reads(tmp_path):
    src = fc.base_session("stepped-sine", tmp_path)
    case = fc.Case("session", "clean", ["inspect", str(src), "--json"], "accept")
    assert run_in_process(case, tmp_path / "c")[0] == "accepted"


# ---------------------------------------------------------------------------------------------- the fast fuzz subset


def _subset(per_family: int = 30) -> list[fc.Case]:
    cases = fc.all_cases(SUBSET_SEED, 300)
    quick: list[fc.Case] = []
    for c in cases:
        if sum(q.family == c.family for q in quick) >= per_family:
            continue
        if c.runs_bench or (c.family in ("rig", "sample") and c.expect != "refuse"):
            continue  # these start the simulated bench or wait on dead addresses: bench/fuzz.py runs them
        if c.family == "session" and c.argv[0] not in ("inspect", "export"):
            continue  # fit, diagnose, report and replay of a good session take seconds each: bench/fuzz.py
        quick.append(c)
    return quick


def test_fuzz_subset_no_traceback_hang_or_garbage_accepted(tmp_path):
    cases = _subset()
    t0 = time.monotonic()
    results = [(c, *run_in_process(c, tmp_path / f"c{k}")) for k, c in enumerate(cases)]
    bad = [f"{o}: [{c.family}] {c.name}: {err.strip()[-300:]}" for c, o, err in results if o in fc.BAD or o == "refused_valid"]
    assert not bad, "\n".join(bad)
    families = {c.family for c, *_ in results}
    assert {"protocol", "rig", "manifest", "session"} <= families, families
    assert sum(o == "refused" for _, o, _ in results) >= len(results) // 2  # the oracle says most are garbage
    assert time.monotonic() - t0 < 300  # a guard against a runaway case, not a speed target


# ---------------------------------------------------------------------------------------------- servers


def test_scpi_overlong_line_is_an_error_and_a_dropped_connection():
    from mock_devices.impedance_sim import DemoBench, ImpedanceAnalyzerSim
    from mock_devices.scpi_server import MAX_MESSAGE_BYTES

    with ImpedanceAnalyzerSim(DemoBench()) as sim:
        port = int(sim.resource_name.split("::")[2])
        bad = socket.create_connection(("127.0.0.1", port), timeout=5)
        good = socket.create_connection(("127.0.0.1", port), timeout=5)
        with pytest.raises(OSError):
            for _ in range(20_000_000 // 65536):  # 20 MB without a newline: the server closes long before the end
                bad.sendall(b"A" * 65536)
            bad.sendall(b"\n")
            bad.settimeout(5)
            assert bad.recv(1) == b""  # closed, not answered
            raise OSError("closed")
        good.sendall(b"SYST:ERR?\n")
        assert good.recv(4096).strip() == b'-363,"Input buffer overrun"'
        good.sendall(b"*IDN?\n")
        assert good.recv(4096).startswith(b"labrig,")
        # a line just under the cap is an ordinary (unknown) command
        good.sendall(b"X" * (MAX_MESSAGE_BYTES - 1) + b"\nSYST:ERR?\n")
        assert good.recv(4096).strip() == b'-113,"Undefined header"'
        bad.close()
        good.close()


def _queued(sock: socket.socket, which: str) -> int:
    """Bytes in a socket's kernel send queue (TIOCOUTQ) or receive queue (FIONREAD)."""
    import fcntl
    import termios

    return int.from_bytes(fcntl.ioctl(sock.fileno(), getattr(termios, which), b"\0\0\0\0"), "little")


def test_serial_client_that_never_reads_does_not_stall_the_others():
    from mock_devices.keyence_sim import KeyenceSim
    from mock_devices.serial_server import OUT_BUFFER_BYTES, FixedBench, TcpSerialServer

    with TcpSerialServer(KeyenceSim(FixedBench(displacement_m=1e-4))) as srv:
        port = int(srv.address.rsplit(":", 1)[1])
        bad = socket.socket()
        bad.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        bad.connect(("127.0.0.1", port))
        deadline = time.monotonic() + 5
        while not srv._clients and time.monotonic() < deadline:
            time.sleep(0.01)
        srv._clients[0].setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, 4096)  # the kernel buffers fill in KBs, not MBs
        with contextlib.suppress(OSError):  # (the old server dropped a client it had waited 1 s on)
            bad.sendall(b"M0\r" * 20000)  # 60 KB of whole requests whose ~260 KB of replies it never reads
        server_side = srv._clients[0]
        while (_queued(bad, "TIOCOUTQ") or _queued(server_side, "FIONREAD")) and time.monotonic() < deadline + 10:  # one serial line: let the server read them all first
            time.sleep(0.01)
        time.sleep(0.05)
        good = socket.create_connection(("127.0.0.1", port), timeout=2.0)  # before: the server sat 1 s in sendall, then dropped the client
        for _ in range(20):
            good.sendall(b"M0\r")
            reply = b""
            while not reply.endswith(b"\r"):
                reply += good.recv(64)
            assert reply.startswith(b"M0,"), reply
        assert server_side in srv._clients and all(len(out) <= OUT_BUFFER_BYTES for out in srv._out.values())
        bad.close()
        good.close()


RUN_OPTIONS = [
    (["--time-scale", "0"], "--time-scale"), (["--time-scale", "inf"], "--time-scale"), (["--time-scale", "nan"], "clock.time_scale"),
    (["--seed", "-1"], "--seed"), (["--preset", "nope"], "--preset"), (["--limit", "max_drive_V=inf"], "safety.max_drive_V"),
    (["--limit", "max_force_N=true"], "--limit"),
]


@pytest.mark.parametrize("extra, says", RUN_OPTIONS, ids=[" ".join(o[0]) for o in RUN_OPTIONS])
def test_run_options_garbage_is_one_line(tmp_path, extra, says):
    line = _refusal(tmp_path, ["run", "eis", "--sim", "--quiet", *extra, "--out", str(tmp_path / "o.h5")])
    assert says in line, line
