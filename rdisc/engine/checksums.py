"""The checksums frames carry: sums (plain or negated, Modbus ASCII's LRC), XORs, the 8-bit
Fletcher pair (UBX) and CRCs of 1 to 64 bits, a CRC's table computed once so that checking a
reply costs one lookup a byte.
"""

from __future__ import annotations


def _reflect(value: int, width: int) -> int:
    result = 0
    for _ in range(width):
        result = (result << 1) | (value & 1)
        value >>= 1
    return result


class Checksum:
    """A sum, an XOR, a negated sum ("lrc"), a Fletcher pair or a table-driven CRC over bytes,
    in `width` bits, then optionally inverted and masked. "fletcher8" is 16 bits: the running
    sum of the bytes (CK_A) in the low byte, the sum of those sums (CK_B) in the high one."""

    __slots__ = ("_init", "_lift", "_reflect_in", "_reflect_out", "_table", "_xorout", "inverted", "kind", "mask", "width")

    def __init__(self, kind: str, width: int, poly: int = 0, init: int = 0, reflect_in: bool = False,
                 reflect_out: bool = False, xorout: int = 0, inverted: bool = False, mask: int | None = None) -> None:
        self.kind = kind
        self.width = width
        self.inverted = inverted
        self.mask = mask
        self._reflect_in = reflect_in
        self._reflect_out = reflect_out
        self._xorout = xorout
        # A CRC narrower than a byte runs (unreflected) in the top bits of an 8-bit register.
        self._lift = max(0, 8 - width) if kind == "crc" and not reflect_in else 0
        self._init = _reflect(init, width) if reflect_in else init << self._lift
        self._table: tuple[int, ...] = (_crc_table(width + self._lift, poly << self._lift, reflect_in, width)
                                        if kind == "crc" else ())

    def __call__(self, data: bytes) -> int:
        full = (1 << self.width) - 1
        if self.kind == "sum":
            value = sum(data) & full
        elif self.kind == "xor":
            value = 0
            for byte in data:
                value ^= byte
            value &= full
        elif self.kind == "lrc":
            value = -sum(data) & full
        elif self.kind == "fletcher8":
            first = second = 0
            for byte in data:
                first = (first + byte) & 0xFF
                second = (second + first) & 0xFF
            value = second << 8 | first
        else:
            value = self._crc(data)
        if self.inverted:
            value ^= full
        return value if self.mask is None else value & self.mask

    def _crc(self, data: bytes) -> int:
        table, width, reg = self._table, self.width + self._lift, self._init
        full = (1 << width) - 1
        if self._reflect_in:
            for byte in data:
                reg = table[(reg ^ byte) & 0xFF] ^ (reg >> 8)
            if not self._reflect_out:
                reg = _reflect(reg, width)
        else:
            shift = width - 8
            for byte in data:
                reg = table[((reg >> shift) ^ byte) & 0xFF] ^ ((reg << 8) & full)
            reg >>= self._lift
            if self._reflect_out:
                reg = _reflect(reg, self.width)
        return reg ^ self._xorout


def _crc_table(width: int, poly: int, reflected: bool, bits: int) -> tuple[int, ...]:
    """The register after each byte value; `bits`: the CRC's own width (`width` is wider when
    an unreflected CRC narrower than a byte is lifted to the top of a byte)."""
    full = (1 << width) - 1
    table = []
    if reflected:
        rpoly = _reflect(poly, bits)
        for byte in range(256):
            reg = byte
            for _ in range(8):
                reg = (reg >> 1) ^ rpoly if reg & 1 else reg >> 1
            table.append(reg)
    else:
        top = 1 << (width - 1)
        for byte in range(256):
            reg = byte << (width - 8)
            for _ in range(8):
                reg = ((reg << 1) ^ poly) & full if reg & top else (reg << 1) & full
            table.append(reg)
    return tuple(table)
