"""The bound's per-object sums as one integer addition, exactly equal to ``math.fsum``.

:meth:`.Space.sums` adds, for each of the bound's mixing weights, one tabulated value
per object, with ``math.fsum`` so that the result does not depend on the objects' order
(see :mod:`.space`). Every tabulated value is a float ``m * 2**e`` with an integer
``m``; scaled by ``2**-E`` (``E`` the least exponent of any value) each is an integer, so
their sum is exact in Python's integers, and converting it back (``int`` to ``float``
rounds to nearest, ties to even, like ``fsum``; scaling by a power of two is exact) gives
the same float ``fsum`` returns. The five weights' integers are packed side by side in one
integer (fields wide enough that no sum carries into the next), so a state's five sums
cost one ``sum`` over its objects (five fields that fit 64 bits each are laid out 64
bits apart, so one ``struct`` call reads them back). A dead end (an infinite value) sets a flag above the
fields. A test checks the sums against ``fsum`` on seeded walks.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from math import ldexp
from operator import getitem
from struct import Struct

_FIVE = Struct("<5Q")
"""Five little-endian 64-bit fields: the packed sums of the bound's five weights read in one call."""

Tables = Sequence[Sequence[Sequence[Sequence[float]]]]
"""``tables[k][robot_at][o][status]`` (see :attr:`.Space.tables`)."""


class ExactSums:
    """Packed integer tables for the plain and the offer tables of a space.

    ``packed`` is None when some value is negative, or when the values lie so far apart
    (over about 2**1000 between the least and the largest) that the largest, scaled by
    the least one's ``2**-exp``, would not be a float; :meth:`.Space.sums` then keeps to
    ``fsum``.
    """

    def __init__(self, plain: Tables, offer: Tables, n_objects: int) -> None:
        self.k = len(plain)
        values = [v for tabs in (plain, offer) for tab in tabs for per_at in tab for row in per_at for v in row]
        finite = [v for v in values if v != math.inf]
        self.packed: tuple[list[list[list[int]]], list[list[list[int]]]] | None = None
        if any(not (v >= 0.0) or math.isinf(v) for v in finite):
            return
        nonzero = [v for v in finite if v > 0.0]
        self.exp = min((math.frexp(v)[1] - 53 for v in nonzero), default=0)
        if max((math.frexp(v)[1] for v in nonzero), default=0) - self.exp > 1023:
            return  # values too far apart: scaled by ``2**-exp`` the largest is no float (fsum keeps them)
        top = max((int(ldexp(v, -self.exp)) for v in nonzero), default=0)
        self.width = (top * max(n_objects, 1)).bit_length() + 1
        self.fields = self.k == 5 and self.width <= 64
        """Five fields that fit 64 bits each: laid out 64 bits apart and read back with :data:`_FIVE`."""
        if self.fields:
            self.width = 64
        self.mask = (1 << self.width) - 1
        self.flag = 1 << (self.width * self.k)
        self.shifts = tuple(k * self.width for k in range(self.k))
        self.scale = ldexp(1.0, self.exp)
        """``2**exp`` (0.0 where it is below the least subnormal: :meth:`_decode` then uses ``ldexp``)."""
        self.packed = (self._pack(plain), self._pack(offer))

    def _pack(self, tabs: Tables) -> list[list[list[int]]]:
        out = []
        for at in range(len(tabs[0])):
            per_o = []
            for o in range(len(tabs[0][at])):
                row = []
                for st in range(len(tabs[0][at][o])):
                    vals = [tab[at][o][st] for tab in tabs]
                    if math.inf in vals:
                        row.append(self.flag)
                        continue
                    packed = 0
                    for k, v in enumerate(vals):
                        scaled = ldexp(v, -self.exp)
                        assert scaled == int(scaled), v  # exact by construction of ``exp``
                        packed |= int(scaled) << (k * self.width)
                    row.append(packed)
                per_o.append(row)
            out.append(per_o)
        return out

    def sums(self, offer: bool, at: int, statuses: Sequence[int]) -> tuple[float, ...] | None:
        """Per mixing weight, ``fsum`` of the objects' values (None: some value is infinite)."""
        assert self.packed is not None
        return self._decode(sum(map(getitem, self.packed[offer][at], statuses)))

    def of_places(self, offer: bool, at: int, where: Sequence[int], obj: int, status: int) -> tuple[float, ...] | None:
        """:meth:`sums` of the statuses ``where`` with object ``obj`` (if ``obj >= 0``) in ``status``.

        The search's states give places, and at most one object's status differs from its
        place (the offered one): its term is swapped in the integer sum, which is exact,
        instead of building a list of statuses.
        """
        assert self.packed is not None
        row = self.packed[offer][at]
        total = sum(map(getitem, row, where))
        if obj >= 0:
            values = row[obj]
            total += values[status] - values[where[obj]]
        return self._decode(total)

    def _decode(self, total: int) -> tuple[float, ...] | None:
        """The packed fields as floats: each field's integer rounded to a float (as ``fsum``
        rounds), times ``2**exp``. Five 64-bit fields are read with one ``struct`` call and
        multiplied by ``2**exp``: a product with a power of two that is itself a float is
        rounded once, correctly, as ``ldexp`` rounds (an int times a float rounds the int to a
        float first, as ``float()`` does); other layouts, or a power that underflows to 0, use
        ``ldexp``."""
        if total >= self.flag:
            return None
        scale = self.scale
        if self.fields and scale:
            s0, s1, s2, s3, s4 = _FIVE.unpack(total.to_bytes(40, "little"))
            return (s0 * scale, s1 * scale, s2 * scale, s3 * scale, s4 * scale)
        mask, exp = self.mask, self.exp
        return tuple([ldexp(float((total >> s) & mask), exp) for s in self.shifts])
