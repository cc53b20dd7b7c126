"""Types and rules of every declaration, and the Model built from them.

`check` (description.py) walks the declarations once, typing every expression
(rdisc.semantics.types) and checking the rules of the thesis model, a module per kind of
declaration: declarations (constants, tables, enums, adapters, state), connections (and
settings), layouts (templates and frames), replies (and post-actions), primitives,
interfaces (and inputs and outputs), each over pieces (types, parameters, calls). The
Model is returned only when no error was found.
"""
