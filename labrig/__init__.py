"""labrig: instrument control, acquisition, fitting and diagnosis for IPMC actuators."""

__version__ = "0.1.0"
