"""Sampling designs: points of the unit hypercube (scipy.stats.qmc, seeded) mapped through
each sampled input's distribution (scipy.stats inverse CDFs).

This module holds the arithmetic only; :mod:`bearing_sweep.spec` reads the ``[sample]`` table
(units, ranges, one clear line per mistake) and turns the drawn values into the ``sample``
axis of the grid.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: The designs a ``[sample]`` table may name.
METHODS = ("random", "latin_hypercube", "sobol", "halton", "saltelli")
#: Designs whose balance needs a power of 2 points (Sobol' sequences; Saltelli's design is
#: drawn from one, and scipy.stats.sobol_indices refuses any other ``n``).
POWER_OF_TWO = ("sobol", "saltelli")
#: Independent scramblings of a Saltelli design: its indices' intervals come from the spread
#: of their estimates (Student's t, one degree of freedom fewer), each replicate costing the
#: whole design again. With 8 the intervals were on average 1.1-1.4 times as wide as the
#: estimates' spread over seeds needs (the t quantile, 2.36 for 1.96); with 4, 1.5 times
#: and with 2, 4.7 times, their widths far more uneven (test functions of known indices).
SALTELLI_REPLICATES = 8
#: The fewest base samples a Saltelli replicate may have: over 1000 seeds the intervals of
#: three test functions of known indices (linear, Ishigami, Sobol' G) held the exact value
#: 93-95 % of the time from 16 on, down to 92 % at 8; 4 widened them to 2.4 times the spread.
SALTELLI_MIN_N = 16

#: Each distribution's parameters: (name, kind) with kind "value" (a value of the input) or
#: "difference" (a width: a standard deviation or a deviation from the nominal).
DISTRIBUTIONS = {
    "uniform": (("low", "value"), ("high", "value")),
    "normal": (("mean", "value"), ("std", "difference")),
    "truncated_normal": (("mean", "value"), ("std", "difference"), ("low", "value"),
                         ("high", "value")),
    "triangular": (("low", "value"), ("mode", "value"), ("high", "value")),
    "tolerance": (("nominal", "value"), ("upper", "difference"), ("lower", "difference")),
}
#: How the values spread within a tolerance band.
WITHIN = ("uniform", "normal")
#: A tolerance band with ``distribution_within = "normal"`` spans this many standard
#: deviations each side of its centre (the normal is cut at the band: parts outside it are
#: rejected by inspection).
BAND_SIGMAS = 3.0


@dataclass(frozen=True)
class Distribution:
    """One sampled input's distribution, its parameters in the input's declared unit."""

    name: str
    parameters: dict  # name -> float
    within: str = "uniform"  # a tolerance band's spread

    def frozen(self):
        """The scipy.stats distribution."""
        from scipy import stats  # here: only a sampled sweep pays for importing it

        p = self.parameters
        if self.name == "uniform":
            return stats.uniform(loc=p["low"], scale=p["high"] - p["low"])
        if self.name == "normal":
            return stats.norm(loc=p["mean"], scale=p["std"])
        if self.name == "truncated_normal":
            return stats.truncnorm((p["low"] - p["mean"]) / p["std"],
                                   (p["high"] - p["mean"]) / p["std"], loc=p["mean"],
                                   scale=p["std"])
        if self.name == "triangular":
            width = p["high"] - p["low"]
            return stats.triang((p["mode"] - p["low"]) / width, loc=p["low"], scale=width)
        low, high = p["nominal"] + p["lower"], p["nominal"] + p["upper"]
        if self.within == "normal":
            return stats.truncnorm(-BAND_SIGMAS, BAND_SIGMAS, loc=0.5 * (low + high),
                                   scale=(high - low) / (2 * BAND_SIGMAS))
        return stats.uniform(loc=low, scale=high - low)

    def support(self) -> tuple[float, float]:
        """The least and largest value it can draw (infinite for a normal)."""
        low, high = self.frozen().support()
        return float(low), float(high)

    def problem(self) -> str | None:
        """What makes the parameters inconsistent, in words, or None."""
        p = self.parameters
        if "std" in p and not p["std"] > 0:
            return "std must be positive"
        if self.name in ("uniform", "truncated_normal", "triangular") and not p["low"] < p["high"]:
            return "low must be below high"
        if self.name == "triangular" and not p["low"] <= p["mode"] <= p["high"]:
            return "mode must lie between low and high"
        if self.name == "tolerance" and not p["lower"] < p["upper"]:
            return "the lower deviation must be below the upper one"
        return None

    def text(self, unit: str) -> str:
        """``uniform(low=1000 N, high=8000 N)``: for the file's attributes."""
        shown = "" if unit in ("", "1") else f" {unit}"
        within = ", within=normal" if self.name == "tolerance" and self.within == "normal" else ""
        return f"{self.name}(" + ", ".join(f"{k}={v:g}{shown}" for k, v in
                                           self.parameters.items()) + within + ")"


def unit_hypercube(method: str, n: int, dimensions: int, seed: int) -> np.ndarray:
    """``n`` points of the unit hypercube of ``dimensions`` dimensions, shape (n, dimensions).

    ``random``: independent uniform draws; ``latin_hypercube``: one point in each of the
    ``n`` equal strata of every dimension (McKay, Beckman & Conover, Technometrics 21(2),
    1979); ``sobol`` and ``halton``: scrambled low-discrepancy sequences. The same seed gives
    the same points.
    """
    from scipy.stats import qmc  # here: only a sampled sweep pays for importing it

    rng = np.random.default_rng(seed)
    if method == "random":
        return rng.random((n, dimensions))
    engine = {"latin_hypercube": qmc.LatinHypercube, "sobol": qmc.Sobol,
              "halton": qmc.Halton}[method](dimensions, rng=rng)
    return engine.random(n)


def saltelli_blocks(n: int, groups: list[int], seed: int,
                    replicates: int = SALTELLI_REPLICATES) -> np.ndarray:
    """The unit-hypercube points of Saltelli's design for first-order and total Sobol'
    indices, shape (replicates * n * (len(groups) + 2), sum(groups)), in the order
    :func:`saltelli_rows` describes.

    Blocks of ``replicates * n`` rows: A, B, then for each input i the matrix A with input
    i's columns taken from B (``groups`` gives each input's number of columns: 1 for a
    scalar, one per entry for a pattern, whose columns are swapped together: the index of
    the whole pattern). A and B are the two halves of a scrambled Sobol' sequence of ``n``
    points in twice the dimensions, as in scipy.stats.sobol_indices (Saltelli et al.,
    Comput. Phys. Commun. 181(2), 259-270, 2010, doi:10.1016/j.cpc.2009.09.018, section 5);
    each replicate is its own, independent scrambling of that sequence (randomized
    quasi-Monte Carlo: the spread of the replicates' estimates is the estimate's error, which
    a bootstrap over the points of one sequence overstates many times), its ``n`` rows
    together in every block.
    """
    from scipy.stats import qmc

    columns = sum(groups)
    rng = np.random.default_rng(seed)
    both = np.concatenate([qmc.Sobol(2 * columns, rng=rng).random(n)
                           for _ in range(replicates)])
    a, b = both[:, :columns], both[:, columns:]
    blocks = [a, b]
    edges = np.cumsum([0] + list(groups))
    for start, stop in zip(edges[:-1], edges[1:]):
        mixed = a.copy()
        mixed[:, start:stop] = b[:, start:stop]
        blocks.append(mixed)
    return np.concatenate(blocks)


def saltelli_rows(n: int, inputs: int, replicates: int) -> tuple[np.ndarray, np.ndarray]:
    """The block (0: A, 1: B, 2 + i: AB of input i) and the replicate of each row of
    :func:`saltelli_blocks`' design, in its order: block by block, in each the replicates
    one after the other, each of ``n`` rows."""
    rows = np.arange(n * replicates * (inputs + 2))
    return rows // (n * replicates), rows // n % replicates


def block_meanings(inputs: list[str]) -> list[str]:
    """The name of each block of a Saltelli design, in order: ``A B AB_<input> ...``."""
    return ["A", "B"] + [f"AB_{name}" for name in inputs]
