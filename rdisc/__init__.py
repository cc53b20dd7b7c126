"""rdisc: the toolchain for RDIS, the Robot Device Interface Specification."""

__version__ = "0.1.0"
