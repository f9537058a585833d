"""Instrument drivers. Each takes an address and cannot tell a real instrument from a simulated one.

Drivers talk to hardware only through pyserial, pyvisa and nidaqmx, and never import mock_devices.
"""
