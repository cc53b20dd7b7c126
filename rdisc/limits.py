"""The width of integers, the same at every stage: literals, constant folding, state and
values at run time, defined with the operations that keep it (rdisc.engine.operations). (The
engine, which generated drivers carry alone, keeps its own copy of the number; a test checks
that the two agree.)"""

from rdisc.engine.operations import MAX_INT

__all__ = ["MAX_ARRAY", "MAX_INT"]

# The most elements an array holds: a robot has tens of joints, not thousands, and every
# array's values are written, read and copied whole.
MAX_ARRAY = 1024
