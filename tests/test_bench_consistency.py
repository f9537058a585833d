"""Cross-instrument consistency on the simulated bench: every instrument sees the same strip."""

import numpy as np

from labrig import signals
from labrig.physics import presets, timeresp, transfer
from labrig.simulate import simulated_rig


def test_daq_step_moves_the_serial_laser_as_the_physics_predicts():
    fs = 200.0
    drive = signals.step(1.0, 12.0, fs, t_on_s=1.0, t_off_s=9.0)  # on for 8 s, then back to 0 V
    with simulated_rig(time_scale=20.0) as (rig, sims):
        t0 = rig.clock.now()
        out = rig.daq.run_finite(drive, fs)
        before = rig.clock.now()
        laser = rig.laser.read_displacement()
        after = rig.clock.now()
        record_start = sims.bench._trace.t0  # when the DAQ's hardware clock started the record
    sp = presets.get("paper").specimen(3062)
    # the physics: the same drive, then rest, up to the moment the laser answered
    tail = int((after - record_start) * fs) + 2
    u = np.concatenate([drive, np.zeros(max(tail - drive.size, 0) + 10)])
    y = timeresp.simulate(lambda s: transfer.displacement_tf(s, sp), u, fs)
    k0, k1 = int((before - record_start) * fs), int((after - record_start) * fs) + 1
    window = y[max(k0 - 1, 0) : k1 + 1]
    lo, hi = window.min() - 5e-6, window.max() + 5e-6  # laser noise and 0.1 um resolution
    assert lo <= laser <= hi, (laser, lo, hi)
    # the DAQ's analog laser channel saw the same strip during the record
    assert np.allclose(out["disp_m"], y[: drive.size], atol=3e-5)
    assert out["disp_m"][int(8.9 * fs)] > 3e-3  # the step really bent it
    assert t0 <= record_start <= before


def test_impedance_analyser_and_daq_current_agree():
    """The analyser's Z and the DAQ's V/I at the same frequency describe one strip."""
    f0, fs = 2.0, 400.0
    with simulated_rig() as (rig, sims):
        rig.analyzer.configure_list(np.array([f0]), 0.05)
        _, z = rig.analyzer.measure()
        v = signals.sine(0.05, f0, 10.0, fs)
        out = rig.daq.run_finite(np.append(v, 0.0), fs)
    t = out["t_s"]
    tail = t > 5.0
    ph = np.exp(-2j * np.pi * f0 * t[tail])
    z_daq = np.mean(out["v_V"][tail] * ph) / np.mean(out["i_A"][tail] * ph)
    assert abs(z_daq / z[0] - 1) < 0.03
