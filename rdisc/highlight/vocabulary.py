"""The words and token patterns of RDIS, read from grammar/rdis.lark (and the Model's types, the
engine's functions, the struct codes of rdisc's formats), for the TextMate grammar and the Pygments lexer.

Written by `python -m rdisc.highlight.writer`: do not edit; rerun it after changing the grammar
(a test holds this file equal to what it writes).
"""

# fmt: off
# The grammar's keywords by kind, and the other words a description reads.
WORDS: dict[str, tuple[str, ...]] = {
    'declaration': ('import', 'robot', 'state', 'sensor', 'setting', 'connection', 'primitive', 'interface', 'adapter', 'input', 'output', 'const', 'enum', 'frame', 'link', 'joint', 'transmission', 'actuator'),
    'constant': ('True', 'False'),
    'operator': ('or', 'and', 'in', 'not'),
    'control': ('for', 'if', 'else'),
    'unit': ('ms', 's', 'Hz'),
    'keyword': ('address', 'adhoc', 'after', 'at', 'author', 'axis', 'baud', 'bits', 'break', 'cache', 'centre', 'checksum', 'code', 'collision', 'color', 'command', 'covariance', 'damping', 'databits', 'delay', 'description', 'each', 'effort', 'either', 'error', 'escape', 'every', 'expect', 'field', 'filter', 'format', 'friction', 'from', 'header', 'hex', 'inertia', 'init', 'inverted', 'kalman', 'keepalive', 'length', 'limit', 'lines', 'literal', 'mask', 'mass', 'measure', 'measurement', 'mimic', 'multiplier', 'noise', 'offset', 'on', 'optional', 'out', 'over', 'pack', 'parity', 'payload', 'periodic', 'poly', 'priority', 'process', 'reflect', 'regex', 'replies', 'reply', 'request', 'retry', 'ros', 'rpy', 'seed', 'skip', 'spawn', 'startup', 'stopbits', 'stuff', 'tag', 'terminate', 'terminator', 'threading', 'timeout', 'to', 'transition', 'triggers', 'trimmed', 'unit', 'unmatched', 'unpack', 'until', 'velocity', 'version', 'visual', 'when', 'width', 'within', 'xor', 'xorout'),
    'type': ('int', 'float', 'bool', 'string', 'bytes'),
    'function': ('abs', 'ascii', 'atan2', 'bitset', 'bool', 'byte', 'clamp', 'cos', 'encode', 'f32be', 'f32le', 'f64be', 'f64le', 'float', 'from_f32be', 'from_f32le', 'from_f64be', 'from_f64le', 'from_nibbles', 'hex', 'hypot', 'int', 'int_be', 'int_le', 'len', 'max', 'min', 'nibbles', 'pack7', 'round', 'sin', 'sqrt', 'str', 'unhex', 'unpack7', 'upper'),
    'struct_code': ('b', 'c', 'd', 'e', 'f', 'h', 'i', 'l', 'n', 'p', 'q', 's', 'x', 'B', 'H', 'I', 'L', 'N', 'Q', 'Z', '?'),
}

# The grammar's terminals, as regular expressions.
PATTERNS: dict[str, str] = {
    'name': '[A-Za-z][A-Za-z0-9_]*',
    'hexadecimal': '0[xX][0-9a-fA-F_]+',
    'binary': '0[bB][01_]+',
    'octal': '0[oO][0-7_]+',
    'decimal': '[0-9][0-9_]*',
    'float': '([0-9][0-9_]*\\.(?!\\.)[0-9_]*|\\.[0-9][0-9_]*)([eE][+-]?[0-9]+)?|[0-9][0-9_]*[eE][+-]?[0-9]+',
    'doc_comment': '\\/\\/\\/[^\n]*',
    'comment': '#[^\n]*',
    'operator': '(?:<<|>>)|\\*\\*|(?:==|!=|<=|>=|<|>)|(?://|\\*|/|%)|\\||\\^|\\&|(?:\\+|\\-)|\\~',
}

# The grammar's punctuation, longest first.
PUNCTUATION: tuple[str, ...] = ('->', '..', '(', ')', ',', '.', ':', ';', '=', '[', ']', '{', '}')
