"""The lowest vertex of each upper envelope of :func:`models.runout.lowest_centre`, one row at a
time, compiled.

Vectorised over rows, every pair of rollers costs array operations over all rows and all
rollers, most of them for pairs that bound no row's minimum; row by row, a pair is taken only
where one line falls and the other rises. The arithmetic is that of the vectorised function,
operation for operation and in its order (pairs left by right, each envelope the maximum over
the rollers, NaN as ``numpy.max`` propagates it), compiled without ``fastmath``
(:mod:`models.kernels`): the same numbers to the bit.
"""
from __future__ import annotations

import numpy as np

from .kernels import compiler

njit = compiler(globals())  # numba's, or none where this source runs interpreted


@njit(cache=True, error_model="numpy")
def lowest_vertices(slope, intercept, active, tie, best_x, best_y):
    """For each row of the ``(rows, Z)`` lines ``y = slope x + intercept`` of which ``active``
    count, the lowest vertex of their upper envelope where a falling line meets a rising one,
    written into ``best_x`` and ``best_y`` (NaN and inf where there is none); ``tie``: how
    close lines count as meeting [m]."""
    rows, count = slope.shape
    for row in range(rows):
        for left in range(count):
            if not (active[row, left] and slope[row, left] <= 0.0):
                continue
            for right in range(count):
                if not (active[row, right] and slope[row, right] >= 0.0
                        and slope[row, right] > slope[row, left]):
                    continue
                x = (intercept[row, left] - intercept[row, right]) / (
                    slope[row, right] - slope[row, left])
                envelope = -np.inf
                for line in range(count):
                    below = 0.0 if active[row, line] else -np.inf
                    height = slope[row, line] * x + intercept[row, line] + below
                    if height != height:  # NaN: the maximum is NaN, as numpy's
                        envelope = height
                        break
                    if height > envelope:
                        envelope = height
                on_envelope = envelope <= slope[row, left] * x + intercept[row, left] + tie
                if on_envelope and envelope < best_y[row]:
                    best_x[row] = x
                    best_y[row] = envelope
