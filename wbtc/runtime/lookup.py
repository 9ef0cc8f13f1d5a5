"""Webots lookup tables, noise and resolution, shared by every sensor model.

A table's rows are [input, output, noise]: inputs below the first row or above the last are
clamped (no extrapolation), values in between interpolate both output and noise linearly; noise
is relative (value × (1 + noise × N(0, 1))); an empty table passes the value through.
`resolution` (when not -1) rounds the result to its multiples.
"""

from __future__ import annotations

import math
from bisect import bisect_left

import numpy as np


class LookupTable:
    """One sensor's lookup table."""

    def __init__(self, rows: list | np.ndarray | None) -> None:
        table = np.asarray(rows if rows is not None else [], dtype=float).reshape(-1, 3)
        # Plain lists: bisect on a few floats beats numpy's per-call overhead.
        self._in, self._out, self._noise = (table[:, k].tolist() for k in range(3))

    @property
    def empty(self) -> bool:
        """True when the table has no rows (values pass through)."""
        return not self._in

    @property
    def max_input(self) -> float:
        """The largest input: a distance sensor's range."""
        return max(self._in) if self._in else 0.0

    def __call__(self, x: float) -> tuple[float, float]:
        """Output and relative noise for input `x`."""
        inputs, outputs, noises = self._in, self._out, self._noise
        x = float(x)  # plain floats out, whatever came in (numpy scalars do not cross the wire)
        if not inputs:
            return x, 0.0
        if x <= inputs[0]:
            return outputs[0], noises[0]
        if x >= inputs[-1]:
            return outputs[-1], noises[-1]
        i = bisect_left(inputs, x) - 1
        t = (x - inputs[i]) / (inputs[i + 1] - inputs[i])
        return outputs[i] + t * (outputs[i + 1] - outputs[i]), noises[i] + t * (noises[i + 1] - noises[i])


def apply(table: LookupTable, x: float, rng: np.random.Generator | None, resolution: float = -1.0) -> float:
    """The sensor value for input `x`: lookup, multiplicative noise (when `rng`), resolution."""
    value, noise = table(x)
    if rng is not None and noise != 0.0:
        value *= 1.0 + noise * float(rng.standard_normal())
    return quantize(value, resolution)


def quantize(value: float, resolution: float) -> float:
    """Round to a multiple of `resolution` (-1 or 0: unchanged)."""
    if resolution is None or resolution <= 0 or not math.isfinite(value):
        return value
    return round(value / resolution) * resolution
