"""rdisc: the toolchain for RDIS, the Robot Device Interface Specification."""

__version__ = "0.1.0"

# `typing.TYPE_CHECKING` without importing `typing` (a twentieth of a cold `rdisc check`): the modules
# a check imports say `from rdisc import TYPE_CHECKING`, and type checkers read `if TYPE_CHECKING:` by
# its name as true (a test holds that `rdisc check` imports no `typing`).
TYPE_CHECKING = False
