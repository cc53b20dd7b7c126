"""The width of integers, the same at every stage: literals, constant folding, state and
values at run time. (The engine, which generated drivers carry alone, keeps its own copy
of the number; a test checks that the two agree.)"""

MAX_INT = (1 << 64) - 1
"""The largest int rdisc keeps, and its negation the smallest: 64 bits and a sign."""

# The most elements an array holds: a robot has tens of joints, not thousands, and every
# array's values are written, read and copied whole.
MAX_ARRAY = 1024
