"""NI's own nidaqmx-python examples, replayed against the simulated DAQ over the real transport.

Each test is the call sequence of one example of github.com/ni/nidaqmx-python (folder ``examples/``), written
anew as facts (the calls in order, with the device renamed ``SimDev1``), through the unmodified nidaqmx
package and gRPC:

* ``synchronization/multi_function/ai_ao_sync.py``: continuous AI with an Every N Samples event that reads N in
  the callback; continuous AO on the same rate, start trigger ``"ai/StartTrigger"`` (relative terminal),
  ``ao.timing.samp_clk_rate`` read back, ``ao.write(sine)``, ``ao.start()``, ``ai.start()``, stop both;
* ``analog_in/voltage_acq_int_clk.py``: finite AI, ``task.read(READ_ALL_AVAILABLE)`` without a start;
* ``analog_out/voltage_update.py``: on-demand ``task.write(1.1)`` (auto start);
* ``analog_in/cont_voltage_acq_int_clk.py``: continuous AI, ``task.start()``, ``task.read(10)`` in a loop;
* NI-DAQmx's watchdog sequence (``nidaqmx.system.WatchdogTask``: create with a timeout,
  ``cfg_watchdog_ao_expir_states``, ``start``, ``reset_timer``, ``expired``, ``clear_expiration``).
"""

from __future__ import annotations

import threading
from typing import Iterator

import grpc
import nidaqmx
import numpy as np
import pytest
from nidaqmx.constants import (READ_ALL_AVAILABLE, AcquisitionType, Edge, SampleTimingType, TriggerType,
                               WatchdogAOExpirState)
from nidaqmx.error_codes import DAQmxErrors
from nidaqmx.errors import DaqError, DaqReadError
from nidaqmx.stream_readers import AnalogSingleChannelReader
from nidaqmx.system.watchdog import WatchdogTask
from nidaqmx.types import AOExpirationState

from labrig.clock import ScaledClock
from mock_devices.daq_errors import CODES
from mock_devices.daq_grpc import SimDaq, StandInBench


@pytest.fixture(params=[10.0], ids=["10x"])
def sim(request: pytest.FixtureRequest) -> Iterator[SimDaq]:
    """A simulated card at 10x (fast enough, slow enough that a loaded machine keeps up with 1 kHz)."""
    with SimDaq(StandInBench(ScaledClock(request.param)), noise_V=0.0) as s:
        yield s


@pytest.fixture
def channel(sim: SimDaq) -> Iterator[grpc.Channel]:
    ch = grpc.insecure_channel(sim.address)
    yield ch
    ch.close()


def opts(channel: grpc.Channel, name: str) -> nidaqmx.GrpcSessionOptions:
    return nidaqmx.GrpcSessionOptions(grpc_channel=channel, session_name=name)


def new_task(channel: grpc.Channel, name: str) -> nidaqmx.Task:
    return nidaqmx.Task(name, grpc_options=opts(channel, name))


def test_status_codes_are_nidaqmx_codes() -> None:
    """Every status the simulator reports is the code nidaqmx's table gives under that name."""
    for name, (code, _) in CODES.items():
        assert DAQmxErrors[name].value == code, name


@pytest.mark.parametrize("sim", [2.0], indirect=True, ids=["2x"])  # DAQmx's default buffer = 5 wall s at 2x
def test_ai_ao_sync_with_relative_trigger_terminal(sim: SimDaq, channel: grpc.Channel) -> None:
    """ai_ao_sync.py: AO armed on "ai/StartTrigger" starts on AI's first sample clock edge."""
    n, fs, events = 1000, 1000.0, 3
    got: list[np.ndarray] = []
    done = threading.Event()
    with new_task(channel, "ai") as ai, new_task(channel, "ao") as ao:
        def callback(task_handle, event_type, number_of_samples, callback_data):  # noqa: ANN001
            got.append(np.asarray(ai.read(number_of_samples_per_channel=number_of_samples)))
            if len(got) >= events:
                done.set()
            return 0

        ai.ai_channels.add_ai_voltage_chan("SimDev1/ai0")
        ai.timing.cfg_samp_clk_timing(fs, sample_mode=AcquisitionType.CONTINUOUS)
        ai.register_every_n_samples_acquired_into_buffer_event(n, callback)
        ao.ao_channels.add_ao_voltage_chan("SimDev1/ao0")
        ao.timing.cfg_samp_clk_timing(fs, sample_mode=AcquisitionType.CONTINUOUS)
        ao.triggers.start_trigger.cfg_dig_edge_start_trig("ai/StartTrigger")
        rate = ao.timing.samp_clk_rate
        assert rate == fs
        sine = np.sin(10.0 * np.linspace(0.0, 2 * np.pi * n / rate, n, endpoint=False))
        ao.write(sine)  # several samples: no auto start
        assert sim.ao_output_V() == 0.0  # written, not started
        ao.start()
        ai.start()
        assert done.wait(20.0), "every-N-samples events did not arrive"
        ai.stop()
        ao.stop()
        assert ao.triggers.start_trigger.dig_edge_src == "/SimDev1/ai/StartTrigger"
        assert ao.triggers.start_trigger.trig_type == TriggerType.DIGITAL_EDGE
    record = np.concatenate(got[:events])
    assert record.size == events * n
    # AO started on AI's start edge: AI sample k reads AO sample k of the regenerated buffer
    np.testing.assert_allclose(record, np.tile(sine, events), atol=1e-3)


def test_finite_read_all_without_start_returns_to_idle(sim: SimDaq, channel: grpc.Channel) -> None:
    """voltage_acq_int_clk.py: Read starts the finite task implicitly and the task is done afterwards,
    so another task may use the channel at once."""
    with new_task(channel, "fin") as task:
        task.ai_channels.add_ai_voltage_chan("SimDev1/ai0")
        task.timing.cfg_samp_clk_timing(1000.0, sample_mode=AcquisitionType.FINITE, samps_per_chan=50)
        data = task.read(READ_ALL_AVAILABLE)
        assert len(data) == 50
        assert task.is_task_done()
        with new_task(channel, "other") as other:  # the channel is free again: no -50103
            other.ai_channels.add_ai_voltage_chan("SimDev1/ai0")
            other.timing.cfg_samp_clk_timing(1000.0, sample_mode=AcquisitionType.FINITE, samps_per_chan=5)
            other.start()
            assert len(other.read(5)) == 5


def test_on_demand_write_auto_start_frees_the_channel(sim: SimDaq, channel: grpc.Channel) -> None:
    """voltage_update.py: task.write(1.1) puts 1.1 V out now; the auto-started task returns to its earlier
    state, so a timed AO task on the same channel starts while the first task still exists."""
    with new_task(channel, "upd") as task:
        task.ao_channels.add_ao_voltage_chan("SimDev1/ao0")
        assert task.write(1.1) == 1
        assert sim.ao_output_V() == pytest.approx(1.1)
        with new_task(channel, "timed") as timed:
            timed.ao_channels.add_ao_voltage_chan("SimDev1/ao0")
            timed.timing.cfg_samp_clk_timing(1000.0, sample_mode=AcquisitionType.FINITE, samps_per_chan=10)
            timed.write(np.full(10, 0.25), auto_start=True)
            timed.wait_until_done(timeout=5.0)
        assert sim.ao_output_V() == pytest.approx(0.25)  # a finished generation holds its last sample
        with pytest.raises(DaqError) as e:  # on demand, no auto start, not started: NI refuses the write
            task.write(0.5, auto_start=False)
        assert e.value.error_code == DAQmxErrors.CANNOT_WRITE_WHEN_AUTO_START_FALSE_AND_TASK_NOT_RUNNING.value


def test_an_explicitly_started_on_demand_task_reserves_the_channel(sim: SimDaq, channel: grpc.Channel) -> None:
    with new_task(channel, "held") as task, new_task(channel, "timed") as timed:
        task.ao_channels.add_ao_voltage_chan("SimDev1/ao0")
        task.start()
        task.write(0.3, auto_start=False)
        timed.ao_channels.add_ao_voltage_chan("SimDev1/ao0")
        timed.timing.cfg_samp_clk_timing(1000.0, samps_per_chan=10)
        timed.write(np.zeros(10), auto_start=False)
        with pytest.raises(DaqError) as e:
            timed.start()
        assert e.value.error_code == DAQmxErrors.PAL_RESOURCE_RESERVED.value


def test_continuous_reads_then_a_partial_read() -> None:
    """cont_voltage_acq_int_clk.py, then a read asking for more than arrives in its timeout: DAQmx returns what
    was acquired with -200284 and those samples are consumed (the next read continues after them)."""
    with SimDaq(StandInBench(ScaledClock(1.0)), noise_V=0.0) as sim:
        ch = grpc.insecure_channel(sim.address)
        sim.device.ao_level["ao0"] = 0.75
        with new_task(ch, "cont") as task:
            task.ai_channels.add_ai_voltage_chan("SimDev1/ai0")
            task.timing.cfg_samp_clk_timing(1000.0, sample_mode=AcquisitionType.CONTINUOUS, samps_per_chan=50)
            task.start()
            for _ in range(3):
                assert np.allclose(task.read(number_of_samples_per_channel=10), 0.75, atol=1e-3)
            pos = task.in_stream.curr_read_pos
            assert pos == 30
            buf = np.full(5000, np.nan)
            with pytest.raises(DaqReadError) as e:
                AnalogSingleChannelReader(task.in_stream).read_many_sample(buf, 5000, timeout=0.2)
            k = e.value.samps_per_chan_read
            assert e.value.error_code == DAQmxErrors.SAMPLES_NOT_YET_AVAILABLE.value
            assert 0 < k < 5000
            np.testing.assert_allclose(buf[:k], 0.75, atol=1e-3)  # the partial samples arrived with the error
            assert task.in_stream.curr_read_pos == pos + k
        ch.close()


def test_timing_and_trigger_attributes_read_back(sim: SimDaq, channel: grpc.Channel) -> None:
    with new_task(channel, "ao") as ao, new_task(channel, "ai") as ai:
        ao.ao_channels.add_ao_voltage_chan("SimDev1/ao0")
        assert ao.timing.samp_timing_type == SampleTimingType.ON_DEMAND
        ao.timing.cfg_samp_clk_timing(2000.0, sample_mode=AcquisitionType.FINITE, samps_per_chan=123)
        assert ao.timing.samp_timing_type == SampleTimingType.SAMPLE_CLOCK
        assert (ao.timing.samp_clk_rate, ao.timing.samp_quant_samp_mode, ao.timing.samp_quant_samp_per_chan) == (
            2000.0, AcquisitionType.FINITE, 123)
        assert ao.timing.samp_clk_active_edge == Edge.RISING
        assert ao.triggers.start_trigger.trig_type == TriggerType.NONE
        ao.triggers.start_trigger.cfg_dig_edge_start_trig("/SimDev1/ai/StartTrigger", trigger_edge=Edge.FALLING)
        st = ao.triggers.start_trigger
        assert (st.trig_type, st.dig_edge_src, st.dig_edge_edge) == (
            TriggerType.DIGITAL_EDGE, "/SimDev1/ai/StartTrigger", Edge.FALLING)
        st.dig_edge_src = "ao/StartTrigger"  # a property write, relative terminal
        assert st.dig_edge_src == "/SimDev1/ao/StartTrigger"
        ao.triggers.start_trigger.disable_start_trig()
        assert st.trig_type == TriggerType.NONE
        ai.ai_channels.add_ai_voltage_chan("SimDev1/ai0:2")
        ai.timing.samp_clk_rate = 500.0
        assert ai.timing.samp_clk_rate == 500.0
        assert ai.timing.samp_clk_max_rate == pytest.approx(1e6 / 3)


@pytest.mark.parametrize("source", ["ai/StartTriger", "/OtherDev/ai/StartTrigger", "SimDev1/ai/StartTrigger"])
def test_unknown_trigger_terminal_fails_at_start_with_the_routing_code(channel: grpc.Channel, source: str) -> None:
    with new_task(channel, "ao") as ao:
        ao.ao_channels.add_ao_voltage_chan("SimDev1/ao0")
        ao.timing.cfg_samp_clk_timing(1000.0, samps_per_chan=10)
        ao.triggers.start_trigger.cfg_dig_edge_start_trig(source)  # DAQmx checks routes when the task starts
        ao.write(np.zeros(10))
        with pytest.raises(DaqError) as e:
            ao.start()
        assert e.value.error_code == DAQmxErrors.INVALID_ROUTING_SOURCE_TERMINAL_NAME_ROUTING.value


@pytest.mark.parametrize("sim", [2.0], indirect=True, ids=["2x"])  # room for a loaded machine's delays
def test_acquisition_is_causal(sim: SimDaq, channel: grpc.Channel) -> None:
    """AI started first, then an on-demand write and later a timed AO without a shared trigger: each sample
    reads what AO put out at its own instant (0 V, then the step, then the waveform)."""
    fs, n = 1000.0, 3000
    clock = sim.device.bench.clock
    with new_task(channel, "ai") as ai, new_task(channel, "step") as step, new_task(channel, "wave") as wave:
        ai.ai_channels.add_ai_voltage_chan("SimDev1/ai0")
        ai.timing.cfg_samp_clk_timing(fs, sample_mode=AcquisitionType.FINITE, samps_per_chan=n)
        step.ao_channels.add_ao_voltage_chan("SimDev1/ao0")
        wave.ao_channels.add_ao_voltage_chan("SimDev1/ao0")
        wave.timing.cfg_samp_clk_timing(fs, sample_mode=AcquisitionType.CONTINUOUS, samps_per_chan=100)
        wave.write(np.linspace(-1.0, 1.0, 100), auto_start=False)
        ai.start()
        t_ai = ai_t0 = sim.device.tasks["ai"].t0
        clock.sleep_until(t_ai + 0.8)
        a = clock.now()
        step.write(0.5)
        b = clock.now()
        clock.sleep_until(t_ai + 1.8)
        wave.start()
        t_wave = sim.device.tasks["wave"].t0
        v = np.asarray(ai.read(READ_ALL_AVAILABLE, timeout=10.0))
    k_a, k_b = int((a - ai_t0) * fs), int(np.ceil((b - ai_t0) * fs))
    assert np.allclose(v[:k_a], 0.0, atol=1e-3)
    k_w = int(np.ceil((t_wave - ai_t0) * fs - 1e-6))
    assert 0 < k_a <= k_b < k_w < n - 100  # the write and the AO start happened inside the record
    assert np.allclose(v[k_b + 1:k_w], 0.5, atol=1e-3)
    expected = np.linspace(-1.0, 1.0, 100)[np.arange(n - k_w) % 100]
    np.testing.assert_allclose(v[k_w:], expected, atol=1e-3)


def test_watchdog_task_sequence(sim: SimDaq, channel: grpc.Channel) -> None:
    """nidaqmx.system.WatchdogTask as NI documents it: expiry puts the AO channel at its expiration state and
    locks it (-200678 on write, -200644 on reset) until Clear Expiration."""
    clock = sim.device.bench.clock
    with new_task(channel, "out") as out:
        out.ao_channels.add_ao_voltage_chan("SimDev1/ao0")
        out.write(2.0)
        wd = WatchdogTask("SimDev1", "wd", timeout=2.0, grpc_options=opts(channel, "wd"))
        try:
            (state,) = wd.cfg_watchdog_ao_expir_states(
                [AOExpirationState("SimDev1/ao0", 0.0, WatchdogAOExpirState.VOLTAGE)])
            assert (state.ao_state, state.ao_output_type) == (0.0, WatchdogAOExpirState.VOLTAGE)
            assert wd.timeout == 2.0
            wd.start()
            for _ in range(12):  # reset well within the timeout (1.5 rig s = 150 ms wall of slack for a loaded
                clock.sleep(0.5)  # machine): no expiry over 3 timeouts
                wd.reset_timer()
            assert not wd.expired and sim.ao_output_V() == 2.0
            t_sent = clock.now()
            wd.reset_timer()  # the last reset, received by the card between t_sent and t_last
            t_last = clock.now()
            while not wd.expired:
                clock.sleep(0.1)
            expired_at = sim.device.tasks["wd"].wd.expired_at
            assert t_sent + 2.0 <= expired_at <= t_last + 2.0  # one timeout on the bench clock after the last reset
            assert sim.ao_output_V() == 0.0
            for call, code in ((lambda: out.write(1.0), "WRITE_FAILED_BECAUSE_WATCHDOG_EXPIRED"),
                               (wd.reset_timer, "CANT_RESET_EXPIRED_WATCHDOG")):
                with pytest.raises(DaqError) as e:
                    call()
                assert e.value.error_code == DAQmxErrors[code].value
            wd.clear_expiration()
            assert not wd.expired
            out.write(1.0)
            assert sim.ao_output_V() == 1.0
            wd.stop()
        finally:
            wd.close()


def test_watchdog_expiry_voids_samples_computed_ahead(sim: SimDaq, channel: grpc.Channel) -> None:
    """A finite record running through the expiry reads the drive until the expiry, 0 V after it."""
    fs, n = 1000.0, 8000  # 8 rig s; the timer (3 rig s) expires mid-record even if ai.start comes 0.3 s wall late
    with new_task(channel, "ai") as ai, new_task(channel, "out") as out:
        out.ao_channels.add_ao_voltage_chan("SimDev1/ao0")
        out.write(1.5)
        wd = WatchdogTask("SimDev1", "wd", timeout=3.0, grpc_options=opts(channel, "wd"))
        try:
            wd.cfg_watchdog_ao_expir_states([AOExpirationState("SimDev1/ao0", 0.0, WatchdogAOExpirState.VOLTAGE)])
            ai.ai_channels.add_ai_voltage_chan("SimDev1/ai0")
            ai.timing.cfg_samp_clk_timing(fs, sample_mode=AcquisitionType.FINITE, samps_per_chan=n)
            wd.start()
            ai.start()
            t_ai = sim.device.tasks["ai"].t0
            v = np.asarray(ai.read(READ_ALL_AVAILABLE, timeout=10.0))
            k = int(np.ceil((sim.device.tasks["wd"].wd.expired_at - t_ai) * fs))
        finally:
            wd.close()
    assert 0 < k < n
    assert np.allclose(v[:k], 1.5, atol=1e-3) and np.allclose(v[k:], 0.0, atol=1e-3)
