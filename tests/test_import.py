"""``labrig import``: a manifest of CSVs becomes a session like a measured one; every bad input is exit 2, one line."""

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from labrig.cli import main
from labrig.store import SessionReader

EXAMPLE = Path(__file__).parent / "data" / "import_example"


def run_cli(*args):
    return subprocess.run([sys.executable, "-m", "labrig", *map(str, args)], capture_output=True, text=True)


def csv_columns(path):
    header = path.read_text().splitlines()[0].split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {name: data[:, k] for k, name in enumerate(header)}


def write_time_series(path, t, v, i, d):
    """A time-series CSV of the import format (``csv_columns`` reads it back)."""
    np.savetxt(path, np.column_stack([t, v, i, d]), delimiter=",", header="t_s,v_V,i_A,disp_m", comments="", fmt="%.10g")


def test_good_manifest_round_trips_every_value(tmp_path):
    out = tmp_path / "imported.h5"
    r = run_cli("import", EXAMPLE / "manifest.toml", "--out", out)
    assert r.returncode == 0, r.stderr
    assert "wrote 5 records" in r.stdout
    with SessionReader(out) as s:
        assert s.exit_status == "success" and s.incomplete() == []
        assert s.sample == {"length_m": 0.03, "width_m": 0.004, "thickness_m": 0.00022, "clamp_area_m2": 1.6e-5, "medium": "water"}
        steps = s.steps()
        assert [(x.name, x.kind, x.status) for x in steps] == [
            ("p612/step", "step", "done"), ("p612/sine_2Hz", "stepped_sine", "done"), ("p612/eis", "eis", "done"),
            ("p3062/step", "step", "done"), ("p3062/eis", "eis", "done")]
        meta = steps[1].metadata
        assert (meta["pressure_kPa"], meta["frequency_Hz"], meta["amplitude_V"], meta["temperature_C"]) == (612, 2.0, 0.5, 25.0)
        assert meta["fs_Hz"] == pytest.approx(100.0) and meta["source_file"] == "p612_sine_2Hz.csv"
        for step, stream, csv in [(0, "daq", "p612_step.csv"), (1, "daq", "p612_sine_2Hz.csv"), (2, "eis", "p612_eis.csv"),
                                  (3, "daq", "p3062_step.csv"), (4, "eis", "p3062_eis.csv")]:
            got, want = s.stream(step, stream), csv_columns(EXAMPLE / csv)
            assert set(got) == set(want)
            for name in want:
                assert np.array_equal(got[name], want[name]), (csv, name)  # bit-identical, not approximately
        assert s.stream(2, "eis").units == {"f_Hz": "Hz", "z_re_ohm": "ohm", "z_im_ohm": "ohm"}
    r = run_cli("inspect", out, "--json")
    assert r.returncode == 0 and json.loads(r.stdout)["steps"][3]["pressure_kPa"] == 3062


def test_optional_force_column_becomes_a_force_stream(tmp_path):
    (tmp_path / "r.csv").write_text("t_s,v_V,i_A,disp_m,force_N\n0,0,0,0,9.8\n0.5,1,1e-3,2e-5,9.7\n1.0,1,1e-3,3e-5,9.6\n")
    (tmp_path / "m.toml").write_text(SPECIMEN + '[[record]]\nkind = "free"\npressure_kPa = 612\nfile = "r.csv"\n')
    assert main(["import", str(tmp_path / "m.toml"), "--out", str(tmp_path / "s.h5")]) == 0
    with SessionReader(tmp_path / "s.h5") as s:
        assert s.stream(0, "force")["force_N"].tolist() == [9.8, 9.7, 9.6]
        assert s.stream(0, "daq")["disp_m"].tolist() == [0, 2e-5, 3e-5]


def test_existing_output_needs_force(tmp_path):
    out = tmp_path / "s.h5"
    out.write_bytes(b"precious")
    r = run_cli("import", EXAMPLE / "manifest.toml", "--out", out)
    assert r.returncode == 2 and "already exists" in r.stderr and out.read_bytes() == b"precious"
    assert main(["import", str(EXAMPLE / "manifest.toml"), "--out", str(out), "--force"]) == 0


SPECIMEN = """[specimen]
length_m = 0.030
width_m = 0.004
thickness_m = 0.00022
clamp_area_m2 = 1.6e-5
medium = "water"
"""
STEP = '[[record]]\nkind = "step"\npressure_kPa = 612\nfile = "a.csv"\n'
GOOD_CSV = "t_s,v_V,i_A,disp_m\n0,0,0,0\n0.01,1,1e-3,1e-6\n0.02,1,1e-3,2e-6\n"

# (name, manifest text, {csv file: text}, the file the message must name, what it must say)
BAD = [
    ("unknown_record_key", STEP.replace("pressure_kPa", "pressure_kpa"), {}, "m.toml", "record #1 (a.csv): unknown key 'pressure_kpa'"),
    ("unknown_specimen_key", STEP, {}, "m.toml", "[specimen]: unknown key 'lenght_m'"),
    ("unknown_top_key", STEP + "\n[extra]\nx = 1\n", {}, "m.toml", "unknown key 'extra'"),
    ("wrong_kind", STEP.replace('"step"', '"sweep"'), {}, "m.toml", "record #1 (a.csv), field kind"),
    ("negative_pressure", STEP.replace("612", "-612"), {}, "m.toml", "field pressure_kPa: Input should be greater than 0"),
    ("missing_field", STEP.replace('file = "a.csv"\n', ""), {}, "m.toml", "record #1, field file: missing"),
    ("sine_without_frequency", STEP.replace('"step"', '"stepped_sine"'), {}, "m.toml", "needs frequency_Hz"),
    ("not_toml", STEP + "pressure_kPa = = 3\n", {}, "m.toml", "not valid TOML"),
    ("missing_csv", STEP, None, "a.csv", "no such file"),
    ("missing_column", STEP, {"a.csv": "t_s,v_V,i_A\n0,0,0\n1,1,1\n"}, "a.csv", "missing column 'disp_m'"),
    ("unknown_column", STEP, {"a.csv": "t_s,v_V,i_A,disp_mm\n0,0,0,0\n1,1,1,1\n"}, "a.csv", "line 1, column 4: unknown column name"),
    ("non_numeric", STEP, {"a.csv": GOOD_CSV + "0.03,1,abc,3e-6\n"}, "a.csv", "line 5, column i_A: not a number"),
    ("nan", STEP, {"a.csv": GOOD_CSV + "0.03,nan,1e-3,3e-6\n"}, "a.csv", "line 5, column v_V: nan"),
    ("unequal_lengths", STEP, {"a.csv": GOOD_CSV + "0.03,1,1e-3\n"}, "a.csv", "line 5: 3 cells, the header has 4"),
    ("time_not_increasing", STEP, {"a.csv": GOOD_CSV + "0.02,1,1e-3,3e-6\n"}, "a.csv", "line 5, column t_s: not increasing"),
    ("empty_csv", STEP, {"a.csv": ""}, "a.csv", "empty file"),
    ("header_only", STEP, {"a.csv": "t_s,v_V,i_A,disp_m\n"}, "a.csv", "no data rows"),
    ("eis_negative_frequency", STEP.replace('"step"', '"eis"'), {"a.csv": "f_Hz,z_re_ohm,z_im_ohm\n1,2,3\n-1,2,3\n"}, "a.csv",
     "line 3, column f_Hz: must be positive"),
]


@pytest.mark.parametrize("name,manifest,csvs,names,says", BAD, ids=[b[0] for b in BAD])
def test_bad_manifest_or_csv_is_exit_2_with_one_line(tmp_path, capsys, name, manifest, csvs, names, says):
    specimen = SPECIMEN.replace("length_m", "lenght_m") if name == "unknown_specimen_key" else SPECIMEN
    (tmp_path / "m.toml").write_text(specimen + manifest)
    for fname, body in ({"a.csv": GOOD_CSV} if csvs == {} else csvs or {}).items():
        (tmp_path / fname).write_text(body)
    out = tmp_path / "s.h5"
    code = main(["import", str(tmp_path / "m.toml"), "--out", str(out)])  # the entry point python -m labrig runs
    err = capsys.readouterr().err
    assert code == 2, err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err, err
    assert str(tmp_path / names) in err and says in err, err
    assert not out.exists() and not list(tmp_path.glob("*.part"))


def test_bad_input_through_the_real_command_line(tmp_path):
    r = run_cli("import", tmp_path / "none.toml", "--out", tmp_path / "s.h5")
    assert r.returncode == 2 and r.stderr.strip() == f"labrig: error: {tmp_path / 'none.toml'}: no such file"
    shutil.copytree(EXAMPLE, tmp_path / "ex")
    (tmp_path / "ex" / "p612_eis.csv").write_text("f_Hz,z_re_ohm,z_im_ohm\n1,2,3\n2,inf,3\n")
    r = run_cli("import", tmp_path / "ex" / "manifest.toml", "--out", tmp_path / "s.h5")
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1
    assert "p612_eis.csv: line 3, column z_re_ohm: inf" in r.stderr


def test_a_sine_records_layout_is_read_when_the_manifest_says_it(tmp_path):
    """`settle_cycles` and `cycles` (what `labrig export` writes from the runner's metadata) set where the estimator
    demodulates; without them it guesses a third of the whole cycles as settling."""
    from labrig.estimate.session_data import load_session, sine_cycles

    shutil.copytree(EXAMPLE, tmp_path / "m")
    manifest = tmp_path / "m" / "manifest.toml"
    said = manifest.read_text().replace('label = "p612/sine_2Hz"', 'label = "p612/sine_2Hz"\nsettle_cycles = 0\ncycles = 6')
    got = []
    for text in (manifest.read_text(), said):
        manifest.write_text(text)
        out = tmp_path / f"s{len(text)}.h5"
        assert main(["import", str(manifest), "--out", str(out)]) == 0
        (rec,) = [r for p in load_session(out).pressures for r in p.records if r.kind == "stepped_sine"]
        got.append(sine_cycles(rec))
    assert got[0][0] >= 2 and got[0][1] is None  # 4 s at 2 Hz: a third of its 7-8 whole cycles guessed as settling
    assert got[1] == (0.0, 6.0)


def test_a_reading_held_through_a_record_is_left_out_with_a_note(tmp_path):
    """A sine whose displacement holds one value once it has settled (a frozen logger, a sensor out of range; here up
    to a float's rounding, as a tare leaves it) carries no noise to weigh it by: left out, named in the notes, and the
    fit reads the rest. One reading that moves by its last digit is kept."""
    from labrig.analysis import load_and_fit
    from labrig.estimate.session_data import load_session

    shutil.copytree(EXAMPLE, tmp_path / "m")
    sine = tmp_path / "m" / "p612_sine_2Hz.csv"
    cols = csv_columns(sine)
    out = {}
    for name, d in {"held": np.where(cols["t_s"] < 1.0, cols["disp_m"], 1.5e-7 + 1e-22 * (cols["t_s"] > 3)),
                    "moving": np.where(cols["t_s"] < 1.0, cols["disp_m"], 1.5e-7 + 1e-9 * (cols["t_s"] > 3))}.items():
        write_time_series(sine, cols["t_s"], cols["v_V"], cols["i_A"], d)
        out[name] = tmp_path / f"{name}.h5"
        assert main(["import", str(tmp_path / "m" / "manifest.toml"), "--out", str(out[name])]) == 0
    held, moving = load_session(out["held"]), load_session(out["moving"])
    assert [r.kind for r in held.all_records()] == ["step", "step"]
    assert any("p612/sine_2Hz: displacement constant through the record" in n for n in held.notes), held.notes
    assert "stepped_sine" in [r.kind for r in moving.all_records()]
    fit = load_and_fit(out["held"], "fit")[1]
    assert sorted(fit.specimens) == [612.0, 3062.0] and np.isfinite(fit.line["R"].value), fit.notes


def test_a_faster_scan_clock_holding_each_sample_reads_as_the_samples(tmp_path):
    """A logger that writes every CSV on a 1 kHz scan clock of its own, each row the latest 100 Hz sample of every channel
    (nine rows in ten repeats): the repeats are left out with a note, the records come back with their own samples on
    their own clock, and the sine's estimate is the one of the record as the DAQ wrote it."""
    from labrig.estimate.session_data import load_session

    shutil.copytree(EXAMPLE, tmp_path / "m")
    for csv in ("p612_sine_2Hz.csv", "p612_step.csv", "p3062_step.csv"):
        cols = csv_columns(tmp_path / "m" / csv)
        t = cols["t_s"]
        ticks = 0.00037 + np.arange(int((t[-1] - 0.00037) * 1000) + 1) / 1000.0  # the scan's phase not the DAQ's
        idx = np.searchsorted(t, ticks + 1e-9, side="right") - 1
        write_time_series(tmp_path / "m" / csv, ticks, *(cols[k][idx] for k in ("v_V", "i_A", "disp_m")))
    got = {}
    for name, folder in (("as_written", EXAMPLE), ("scanned", tmp_path / "m")):
        assert main(["import", str(folder / "manifest.toml"), "--out", str(tmp_path / f"{name}.h5")]) == 0
        got[name] = load_session(tmp_path / f"{name}.h5")
    a, b = got["as_written"], got["scanned"]
    assert not any("scan clock" in n for n in a.notes)
    assert any("3 records logged on a scan clock faster than their samples" in n for n in b.notes), b.notes
    for ra, rb in zip(a.all_records(), b.all_records()):
        assert rb.t.size == ra.t.size - 1 or rb.t.size == ra.t.size, ra.name  # the last sample may fall past the scan's end
        assert rb.fs == pytest.approx(ra.fs, rel=1e-3)
    (sa,), (sb,) = a.pressures[0].sines, b.pressures[0].sines
    assert abs(sb.H_disp / sa.H_disp - 1) < 1e-3 and abs(sb.H_cur / sa.H_cur - 1) < 1e-3


@pytest.mark.parametrize("preset", ["paper", "seed001"])
def test_an_imported_strip_gets_the_prior_of_a_strip_of_its_own_geometry(preset):
    """An import carries the specimen's geometry, not a preset name: the fit's prior must then be what the preset
    of that geometry would give (the line's per-length values scale with width), else every strip not 4 mm wide
    is misfit from the start (R_s is held at its prior)."""
    import dataclasses

    from labrig.fit.seed000 import base_specimen
    from labrig.physics import presets

    want = presets.get(preset).base
    g = want.geometry
    sample = {"length_m": g.length, "width_m": g.width, "thickness_m": g.thickness, "clamp_area_m2": g.clamp_area,
              "medium": "air" if want.fluid.name == "air" else "water"}
    got = base_specimen(sample)
    assert dataclasses.replace(got, clamp=want.clamp, Kt_bar=want.Kt_bar, pressure=want.pressure) == want


def test_a_spectrum_in_two_bands_reads_as_one_and_a_repeat_as_the_later(tmp_path):
    """A lab measuring the low band on a potentiostat's FRA and the high band on an impedance analyser lists two
    spectra at one pressure (here the high band first, their joint frequency in both): the fit sees the whole
    spectrum. A spectrum measured again at a pressure is the later moment, used alone, with a note."""
    from labrig.estimate.session_data import load_session

    ex = tmp_path / "ex"
    shutil.copytree(EXAMPLE, ex)
    whole = csv_columns(ex / "p612_eis.csv")
    rows = (ex / "p612_eis.csv").read_text().splitlines()
    (ex / "p612_fra.csv").write_text("\n".join(rows[:12]) + "\n")  # 11 points up to f[10]
    (ex / "p612_analyser.csv").write_text("\n".join([rows[0], *rows[11:]]) + "\n")  # f[10] on
    z3 = csv_columns(ex / "p3062_eis.csv")
    np.savetxt(ex / "p3062_again.csv", np.column_stack([z3["f_Hz"], 1.1 * z3["z_re_ohm"], 1.1 * z3["z_im_ohm"]]),
               delimiter=",", header="f_Hz,z_re_ohm,z_im_ohm", comments="", fmt="%.10g")
    m = (ex / "manifest.toml").read_text().replace('file = "p612_eis.csv"', 'file = "p612_analyser.csv"')
    m += '\n[[record]]\nkind = "eis"\npressure_kPa = 612\nfile = "p612_fra.csv"\n'
    m += '\n[[record]]\nkind = "eis"\npressure_kPa = 3062\nfile = "p3062_again.csv"\n'
    (ex / "manifest.toml").write_text(m)
    assert main(["import", str(ex / "manifest.toml"), "--out", str(tmp_path / "s.h5")]) == 0
    sd = load_session(tmp_path / "s.h5")
    eis = {p.pressure_kPa: p.eis for p in sd.pressures}
    np.testing.assert_allclose(eis[612][0], whole["f_Hz"], rtol=1e-9)
    np.testing.assert_allclose(eis[612][1], whole["z_re_ohm"] + 1j * whole["z_im_ohm"], rtol=1e-9)
    np.testing.assert_allclose(eis[3062][1], 1.1 * (z3["z_re_ohm"] + 1j * z3["z_im_ohm"]), rtol=1e-8)
    assert any("repeats the one before it at 3062 kPa" in n for n in sd.notes)


def test_a_spectrum_written_in_passes_reads_as_their_average_ascending(tmp_path):
    """An analyser that sweeps each spectrum twice from the top down and writes both passes into one file: every
    frequency twice, in no ascending order. The analysis reads one spectrum, ascending, each frequency the mean of its
    passes (a note says so), the stored record keeps every row, and the drying's admittance trace (a spline in log f)
    reads on it."""
    from types import SimpleNamespace

    from labrig.diagnose.features import Features, SpectrumFeature
    from labrig.diagnose.wet_strip import conductance_loss
    from labrig.estimate.session_data import load_session

    ex = tmp_path / "ex"
    shutil.copytree(EXAMPLE, ex)
    z = csv_columns(ex / "p612_eis.csv")
    f, zc = z["f_Hz"][::-1], (z["z_re_ohm"] + 1j * z["z_im_ohm"])[::-1]
    second = zc * (1 + 0.002 * np.cos(np.arange(f.size)))  # the second pass, within the analyser's repeatability
    both = np.r_[zc, second]
    np.savetxt(ex / "p612_eis.csv", np.column_stack([np.r_[f, f], both.real, both.imag]), delimiter=",",
               header="f_Hz,z_re_ohm,z_im_ohm", comments="", fmt="%.12g")
    assert main(["import", str(ex / "manifest.toml"), "--out", str(tmp_path / "s.h5")]) == 0
    with SessionReader(tmp_path / "s.h5") as s:
        assert s.stream(2, "eis")["f_Hz"].size == 2 * f.size
    sd = load_session(tmp_path / "s.h5")
    got_f, got_z = sd.pressures[0].eis
    np.testing.assert_allclose(got_f, z["f_Hz"], rtol=1e-9)
    np.testing.assert_allclose(got_z, ((zc + second) / 2)[::-1], rtol=1e-9)
    assert any(f"{f.size} of the spectrum's frequencies measured more than once" in n for n in sd.notes)
    feats = Features(t0=0.0, t1=100.0, spectra=[SpectrumFeature(612.0, got_f, got_z, 1e-3, 0.0)])
    feats.sines = [SimpleNamespace(pressure_kPa=612.0, f=float(fq), t_start=10.0 * k, Hi=complex(1 / np.interp(fq, got_f, got_z)))
                   for k, fq in enumerate(got_f[(got_f > got_f[0]) & (got_f < got_f[-1])][:5])]
    assert conductance_loss(feats, lambda t: np.asarray(t, float) / 100.0, {612.0}) is not None


def test_pressures_read_on_each_record_group_into_their_clamp_settings(tmp_path):
    """A lab that writes the load cell's reading on each record, not the setpoint, gives a relaxing clamp a new
    pressure on every record: the records of one setting are still one setting (its pressure the first record's
    reading, the clamp as set), two
    settings stay two, and the loader says what it grouped."""
    from labrig.estimate.session_data import clamp_settings, load_session

    ex = tmp_path / "ex"
    shutil.copytree(EXAMPLE, ex)
    m = (ex / "manifest.toml").read_text().split("[[record]]")
    read = iter([611.8, 604.9, 598.2, 3049.5, 3031.0])  # the manifest's records in order, each as the load cell read it
    m = [m[0]] + [re.sub(r"pressure_kPa = \d+", lambda _: f"pressure_kPa = {next(read)}", part) for part in m[1:]]
    (ex / "manifest.toml").write_text("[[record]]".join(m))
    assert main(["import", str(ex / "manifest.toml"), "--out", str(tmp_path / "s.h5")]) == 0
    sd = load_session(tmp_path / "s.h5")
    assert [p.pressure_kPa for p in sd.pressures] == [611.8, 3049.5]
    assert len(sd.pressures[0].records) == 2 and sd.pressures[0].eis is not None and sd.pressures[1].eis is not None
    assert any("5 distinct clamp pressures read on the records, grouped into 2 clamp settings" in n for n in sd.notes)
    # each record carries its setting (what the diagnosis' features and split group by), its own reading beside
    for p in sd.pressures:
        assert all(r.meta["pressure_kPa"] == p.pressure_kPa for r in p.records)
    assert [r.meta.get("pressure_read_kPa") for r in sd.pressures[0].records] == [None, 604.9]  # the step, then the sine
    # seed 001's closest settings (500 ... 1700 kPa, 1300 -> 1700 the nearest) and setpoints stay as they are
    assert clamp_settings([500.0, 900.0, 1300.0, 1700.0, 1300.0]) == {500.0: 500.0, 900.0: 900.0, 1300.0: 1300.0, 1700.0: 1700.0}


def test_a_logger_restarted_at_each_clamp_setting_keeps_each_blocks_rests(tmp_path):
    """A logging program run once per clamp setting, its clock from its own start: the 612 kPa block's two records
    on one clock (a 30 s rest between them, from 5 s), the 3062 kPa record on a new one (from 3 s). Each block keeps
    its rests, the blocks follow back to back, every record's stored ``t_s`` counts from its start (as a run stores
    it), and the session exported again is one clock that ``labrig import`` reads the same."""
    from labrig.importer import placement
    from labrig.store import SessionReader

    ex = tmp_path / "ex"
    shutil.copytree(EXAMPLE, ex)
    clocks = {"p612_step.csv": 5.0, "p612_sine_2Hz.csv": None, "p3062_step.csv": 3.0}
    t0, spans = 0.0, []
    for name, restart in clocks.items():
        c = csv_columns(ex / name)
        t0 = restart if restart is not None else t0 + 30.0
        write_time_series(ex / name, np.round(t0 + c["t_s"], 6), c["v_V"], c["i_A"], c["disp_m"])
        spans.append((t0, t0 + c["t_s"][-1]))
        t0 += c["t_s"][-1]
    assert main(["import", str(ex / "manifest.toml"), "--out", str(tmp_path / "s.h5")]) == 0
    with SessionReader(tmp_path / "s.h5") as r:
        steps = [st for st in r.steps() if st.kind != "eis"]
        starts = np.array([st.t_start for st in steps])
        assert all(r.stream(st, "daq")["t_s"][0] == 0.0 for st in steps)
    np.testing.assert_allclose(starts[:2], [spans[0][0], spans[1][0]], atol=1e-6)  # the first block's clock and rest
    assert starts[2] == pytest.approx(spans[1][1], abs=1e-6)  # the second block right after the first ended
    assert main(["export", str(tmp_path / "s.h5"), "--out", str(tmp_path / "back")]) == 0
    assert main(["import", str(tmp_path / "back" / "manifest.toml"), "--out", str(tmp_path / "s2.h5")]) == 0
    with SessionReader(tmp_path / "s2.h5") as r:
        again = np.array([st.t_start for st in r.steps() if st.kind != "eis"])
    np.testing.assert_allclose(again, starts, atol=1e-5)
    # a CSV per record from 0: each its own clock, back to back (as before); one clock throughout: its times
    from types import SimpleNamespace as NS

    def recs(*spans):
        return [NS(kind="step") for _ in spans], [NS(columns={"t_s": np.array(sp)}) for sp in spans]

    assert placement(*recs((0.0, 4.0), (0.0, 4.0), (0.0, 4.0))) == ([0.0, 4.0, 8.0], 3)
    assert placement(*recs((10.0, 14.0), (20.0, 24.0), (30.0, 34.0))) == ([10.0, 20.0, 30.0], 1)
    assert placement(*recs((-0.5, 3.5), (-0.5, 3.5))) == ([0.0, 4.0], 2)  # a trigger's clock: from the session's 0


def test_records_of_one_clock_listed_out_of_order_keep_their_moments(tmp_path):
    """A manifest that lists its records out of time order (written by hand, or sorted by name), the CSVs on one clock
    whose records never overlap: each record starts at its own first stamp, so the rests and the order in time are
    the session's, not the manifest's (before, any step back laid every record back to back and lost every rest)."""
    from labrig.store import SessionReader

    ex = tmp_path / "ex"
    shutil.copytree(EXAMPLE, ex)
    firsts = {"p612_step.csv": 100.0, "p612_sine_2Hz.csv": 140.0, "p3062_step.csv": 400.0}
    for name, t0 in firsts.items():
        c = csv_columns(ex / name)
        write_time_series(ex / name, np.round(t0 + c["t_s"], 6), c["v_V"], c["i_A"], c["disp_m"])
    parts = (ex / "manifest.toml").read_text().split("[[record]]")
    head, recs = parts[0], parts[1:]
    (ex / "manifest.toml").write_text("[[record]]".join([head] + recs[3:] + recs[:3]))  # 3062 kPa listed first
    assert main(["import", str(ex / "manifest.toml"), "--out", str(tmp_path / "s.h5")]) == 0
    with SessionReader(tmp_path / "s.h5") as r:
        got = {st.metadata["source_file"]: st.t_start for st in r.steps() if st.kind != "eis"}
    assert got == pytest.approx(firsts)


def test_a_clock_of_the_time_of_day_is_carried_past_midnight(tmp_path):
    """A logger that stamps rows with the time of day, the session run through midnight during a rest: the records
    after it read near 0 again. They are carried a day on, so every rest between records is kept as it was measured,
    and each record's ``t_s`` counts from its start as on one clock; a per-record clock (each CSV from 0) is still laid
    back to back."""
    from labrig.importer import day_unwrapped
    from labrig.store import SessionReader

    ex = tmp_path / "ex"
    shutil.copytree(EXAMPLE, ex)
    series = ["p612_step.csv", "p612_sine_2Hz.csv", "p3062_step.csv"]
    t0, rest = 86400.0 - 10.0, 30.0  # midnight falls in the first rest
    moments = []
    for name in series:
        c = csv_columns(ex / name)
        write_time_series(ex / name, np.round((t0 + c["t_s"]) % 86400.0, 5), c["v_V"], c["i_A"], c["disp_m"])
        moments.append(t0)
        t0 += c["t_s"][-1] + rest
    assert main(["import", str(ex / "manifest.toml"), "--out", str(tmp_path / "s.h5")]) == 0
    with SessionReader(tmp_path / "s.h5") as r:
        steps = [st for st in r.steps() if st.kind != "eis"]
        starts = np.array([st.t_start for st in steps])
        np.testing.assert_allclose(starts - starts[0], np.array(moments) - moments[0], atol=1e-4)
        assert all(r.stream(st, "daq")["t_s"][0] == 0.0 for st in steps)
    assert day_unwrapped([(0.0, 4.0), (0.0, 4.0)]) == [(0.0, 4.0), (0.0, 4.0)]  # each CSV from 0: no day added
    assert day_unwrapped([(86000.0, 86390.0), None, (20.0, 60.0)]) == [(86000.0, 86390.0), None, (86420.0, 86460.0)]
