"""The DAQmx status codes the simulated card reports, each under its name in ``nidaqmx.error_codes.DAQmxErrors``.

``tests/test_daq_ni_examples.py`` checks every (name, code) pair here against the installed nidaqmx, so a code
cannot drift from NI's table. Messages follow NI-DAQmx's wording (shortened).
"""

from __future__ import annotations

import numpy as np

# name in DAQmxErrors -> (code, message)
CODES: dict[str, tuple[int, str]] = {
    "SAMPLES_NO_LONGER_AVAILABLE": (-200279, "Attempted to read samples that are no longer available. The requested "
                                    "sample was previously available, but has since been overwritten."),
    "SAMPLES_NOT_YET_AVAILABLE": (-200284, "Some or all of the samples requested have not yet been acquired."),
    "SAMPLES_WILL_NEVER_BE_AVAILABLE": (-200278, "Attempted to read a sample beyond the final sample acquired."),
    "WAIT_UNTIL_DONE_DOES_NOT_INDICATE_DONE": (-200560, "Wait Until Done did not indicate that the task was done "
                                               "within the specified timeout."),
    "INVALID_TASK": (-200088, "Task specified is invalid or does not exist."),
    "PHYSICAL_CHAN_DOES_NOT_EXIST": (-200170, "Physical channel specified does not exist on this device."),
    "INVALID_DEVICE_ID": (-200220, "Device identifier is invalid."),
    "ATTRIBUTE_NOT_SUPPORTED_IN_TASK_CONTEXT": (-200452, "Specified property is not supported by the device or is "
                                                "not applicable to the task."),
    "OUTPUT_BUFFER_EMPTY": (-200462, "Generation cannot be started, because the output buffer is empty."),
    "WRITE_NO_OUTPUT_CHANS_IN_TASK": (-200459, "Write cannot be performed because this task does not contain any "
                                      "output channels."),
    "INVALID_AO_DATA_WRITE": (-200561, "Attempted writing analog data that is too large or too small."),
    "CAN_NOT_PERFORM_OP_WHILE_TASK_RUNNING": (-200479, "Specified operation cannot be performed while the task is "
                                              "running."),
    "PAL_RESOURCE_RESERVED": (-50103, "The specified resource is reserved. The operation could not be completed as "
                              "specified."),
    "INVALID_ROUTING_SOURCE_TERMINAL_NAME_ROUTING": (-89120, "Source terminal to be routed could not be found on the "
                                                     "device. Make sure the terminal name is valid for the device."),
    "DEV_CANNOT_BE_ACCESSED": (-201003, "Device cannot be accessed. Possible causes: device is no longer present in "
                               "the system."),
    "READ_BUFFER_TOO_SMALL": (-200229, "Buffer is too small to fit read data."),
    "CANNOT_WRITE_WHEN_AUTO_START_FALSE_AND_TASK_NOT_RUNNING": (-200846, "Write cannot be performed when the auto "
                                                                "start input to DAQmx Write is false, task is not "
                                                                "running, and timing for the task is on demand."),
    "CANT_RESET_EXPIRED_WATCHDOG": (-200644, "Watchdog timer cannot be reset because it has already expired. Clear "
                                    "the expiration first."),
    "WRITE_FAILED_BECAUSE_WATCHDOG_EXPIRED": (-200678, "Write failed, because the watchdog timer expired."),
    "WATCHDOG_TIMEOUT_OUT_OF_RANGE_AND_NOT_SPECIAL_VAL": (-200668, "Watchdog timer timeout is out of range and not "
                                                          "-1 (never expires)."),
    "ACTION_NOT_SUPPORTED_TASK_NOT_WATCHDOG": (-200635, "Action is not supported: the task is not a watchdog timer "
                                               "task."),
    "WATCHDOG_CHANNEL_EXPIRATION_STATE_NOT_SPECIFIED": (-209813, "An expiration state was not specified for a "
                                                        "channel of the watchdog task."),
    "AUTO_START_READ_NOT_ALLOWED_EVENT_REGISTERED": (-200984, "Auto start is not allowed for reads when an Every N "
                                                     "Samples event is registered."),
}
ERR_MESSAGES: dict[int, str] = {code: msg for code, msg in CODES.values()}
ERR = {name: code for name, (code, _) in CODES.items()}


class DaqmxError(Exception):
    """A DAQmx status code the server reports (negative = error). ``partial``: samples a partial read returns."""

    def __init__(self, code: int, message: str | None = None, samps_per_chan_read: int | None = None,
                 partial: np.ndarray | None = None):
        self.code = code
        self.message = message or ERR_MESSAGES.get(code, f"DAQmx error {code}")
        self.samps_per_chan_read = samps_per_chan_read
        self.partial = partial
        super().__init__(f"{code}: {self.message}")
