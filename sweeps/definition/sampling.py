"""The [sample] table: the sampled inputs' distributions, checked against each input's valid
range, and the ``sample`` axis drawn from them (the designs themselves: :mod:`..sample`)."""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..models.registry import Input, Model
from .. import sample, units
from .axes import MAX_AXIS_VALUES, Axis
from .tables import MAX_INTEGER, short, suggestion
from .values import Value, ValueReader, convert_written

#: The keys of a [sample] table that are not sampled parameters.
SAMPLE_SETTINGS = ("n", "method", "seed")


@dataclass(frozen=True)
class Sampling:
    """How the ``sample`` axis was drawn, for the file's attributes and ``analyze``."""

    method: str
    n: int  # samples asked for; Saltelli's design holds replicates * n * (inputs + 2)
    seed: int
    distributions: dict  # sampled input -> its distribution in words, in the declared unit
    #: Saltelli's design: the name of each block of ``replicates * n`` samples (A, B,
    #: AB_<input>...), and its independent scramblings (``sample.saltelli_blocks``).
    blocks: tuple[str, ...] | None = None
    replicates: int = 1


class SampleReader:
    """Reads one model's [sample] table; ``claim(name, key)`` marks an input as given (once
    only) at ``key``."""

    def __init__(self, values: ValueReader, model: Model, claim):
        self.values = values
        self.fail = values.fail
        self.model = model
        self.inputs = {i.name: i for i in model.inputs}
        self.claim = claim

    def sampled(self, table: dict) -> dict:
        """The parameters a [sample] table draws, each claimed (given only once)."""
        model, inputs = self.model, self.inputs
        sampled = {}
        for name, raw in table.items():
            if name in SAMPLE_SETTINGS:
                continue
            key = f"sample.{name}"
            if name not in inputs:
                self.fail(key, f"unknown key: neither a setting ({', '.join(SAMPLE_SETTINGS)}) "
                          f"nor a parameter of model {model.name}"
                          + suggestion(name, list(SAMPLE_SETTINGS) + list(inputs))
                          + f" (`bearing-sweep describe {model.name}` lists them)")
            self.claim(name, key)
            spec = inputs[name]
            if spec.structural:
                self.fail(key, f"{name!r} is a {spec.kind} and cannot be sampled (only numbers "
                          "and quantities can); vary it on an axis")
            if not isinstance(raw, dict) or not isinstance(raw.get("distribution"), str):
                self.fail(key, "expected a table naming its distribution, e.g. { distribution = "
                          "\"uniform\", low = ..., high = ... } (distributions: "
                          f"{', '.join(sample.DISTRIBUTIONS)})")
            sampled[name] = raw
        return sampled

    def settings(self, table: dict) -> tuple[int, str, int]:
        """The table's ``n``, ``method`` and ``seed``, checked against each other."""
        n = table.get("n")
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            self.fail("sample.n", f"{'missing' if n is None else repr(n)}: expected the number "
                      "of samples, a positive integer")
        method = table.get("method")
        if method not in sample.METHODS:
            self.fail("sample.method", ("missing" if method is None else f"{method!r} is not "
                      "accepted") + suggestion(str(method), sample.METHODS)
                      + f" (methods: {', '.join(sample.METHODS)})")
        seed = table.get("seed", 0)
        if isinstance(seed, bool) or not isinstance(seed, int) or not 0 <= seed <= MAX_INTEGER:
            self.fail("sample.seed", f"{short(repr(seed))}: expected an integer from 0 to "
                      f"{MAX_INTEGER} (the same seed draws the same samples)")
        if method == "saltelli" and n < sample.SALTELLI_MIN_N:
            self.fail("sample.n", f"{n}: a saltelli design needs at least "
                      f"{sample.SALTELLI_MIN_N} base samples (each of its "
                      f"{sample.SALTELLI_REPLICATES} replicates needs so many for Sobol' "
                      "indices whose intervals hold)")
        if method in sample.POWER_OF_TWO and n & (n - 1):
            below = 1 << (n.bit_length() - 1)
            self.fail("sample.n", f"{n}: a {method} design needs a power of 2 (its balance "
                      f"depends on it); take {below} or {2 * below}")
        return n, method, seed

    def sample_axis(self, table: dict, sampled: dict, fixed: dict) -> tuple[Axis, Sampling]:
        """The ``sample`` axis: a zipped axis of the drawn values, numbered from 0."""
        model = self.model
        n, method, seed = self.settings(table)
        if not sampled:
            self.fail("sample", "no parameter to sample: give at least one, e.g. radial_load = "
                      "{ distribution = \"uniform\", low = \"1 kN\", high = \"8 kN\" }")
        replicates = sample.SALTELLI_REPLICATES if method == "saltelli" else 1
        size = n * replicates * (len(sampled) + 2) if method == "saltelli" else n
        if size > MAX_AXIS_VALUES:
            self.fail("sample.n", f"{n}: the design would have {size} samples, more than "
                      f"{MAX_AXIS_VALUES:.0e}")
        distributions = {name: self.distribution(model.input(name), raw, f"sample.{name}")
                         for name, raw in sampled.items()}
        widths = [self.sampled_length(model.input(name), fixed) for name in sampled]
        if method == "saltelli":
            cube = sample.saltelli_blocks(n, widths, seed, replicates)
        else:
            cube = sample.unit_hypercube(method, n, sum(widths), seed)
        values, column = {}, 0
        for (name, distribution), width in zip(distributions.items(), widths):
            spec = model.input(name)
            drawn = distribution.frozen().ppf(cube[:, column:column + width])
            column += width
            if not spec.dims:
                drawn = drawn[:, 0]
            si = units.to_si(drawn, units.parse_unit(spec.unit))
            values[name] = [Value(s if spec.dims else float(s), d if spec.dims else float(d),
                                  spec.unit) for s, d in zip(si, drawn)]
        blocks = tuple(sample.block_meanings(list(sampled))) if method == "saltelli" else None
        sampling = Sampling(method, n, seed, {name: d.text(model.input(name).unit)
                                              for name, d in distributions.items()}, blocks,
                            replicates)
        return Axis("sample", values, list(range(size))), sampling

    def distribution(self, spec: Input, raw: dict, key: str) -> sample.Distribution:
        """A sampled parameter's distribution, its parameters in the declared unit, checked
        against the parameter's valid range."""
        name = raw["distribution"]
        if name not in sample.DISTRIBUTIONS:
            self.fail(f"{key}.distribution", f"{name!r} is not accepted"
                      + suggestion(name, sample.DISTRIBUTIONS)
                      + f" (distributions: {', '.join(sample.DISTRIBUTIONS)})")
        wanted = sample.DISTRIBUTIONS[name]
        accepted = {"distribution"} | {p for p, _ in wanted} | (
            {"distribution_within"} if name == "tolerance" else set())
        for extra in raw:
            if extra not in accepted:
                self.fail(f"{key}.{extra}", f"not a parameter of a {name} distribution"
                          + suggestion(extra, accepted)
                          + f" (it takes {', '.join(p for p, _ in wanted)})")
        missing = [p for p, _ in wanted if p not in raw]
        if missing:
            self.fail(key, f"a {name} distribution needs {', '.join(missing)} (it takes "
                      f"{', '.join(p for p, _ in wanted)})")
        within = raw.get("distribution_within", "uniform")
        if within not in sample.WITHIN:
            self.fail(f"{key}.distribution_within", f"{within!r} is not accepted (accepted: "
                      f"{', '.join(repr(w) for w in sample.WITHIN)})")
        scalar = replace(spec, dims=(), broadcast=False)
        parameters = {}
        for parameter, kind in wanted:  # a "difference" is a width: "2 K" on a degC input
            value = self.values.value(scalar, raw[parameter], f"{key}.{parameter}",
                                      check_range=False)
            parameters[parameter] = float(convert_written(value.shown, value.unit, spec.unit,
                                                          difference=kind == "difference"))
        distribution = sample.Distribution(name, parameters, within)
        problem = distribution.problem()
        if problem:
            self.fail(key, f"{problem} ({distribution.text(spec.unit)})")
        low, high = distribution.support()
        below = spec.minimum is not None and (
            low <= spec.minimum if spec.exclusive_minimum else low < spec.minimum)
        above = spec.maximum is not None and high > spec.maximum
        if below or above:
            end = low if below else high
            reach = (f"has no {'lower' if below else 'upper'} bound" if np.isinf(end) else
                     f"reaches {end:g}" + ("" if spec.unit in ("", "1") else f" {spec.unit}"))
            self.fail(key, f"a {name} distribution {reach}, outside the valid range of "
                      f"{spec.name} ({spec.range_text()}); keep it within the range (a "
                      "truncated_normal with low and high, or a bounded distribution)")
        return distribution

    def sampled_length(self, spec: Input, fixed: dict) -> int:
        """How many values one sample of ``spec`` draws: 1, or one per entry of a pattern
        whose length a fixed count sets. A pattern no count sizes that takes one value for
        all its entries (a raceway's single harmonic, say) draws that one value."""
        if not spec.dims:
            return 1
        model = self.model
        count = model.dim_sizes.get(spec.dims[0])
        key = f"sample.{spec.name}"
        if not isinstance(count, str) or count not in {i.name for i in model.inputs}:
            if spec.broadcast:
                return 1
            self.fail(key, f"sampling of the pattern {spec.name!r} is not supported: no count "
                      f"sets its length (one value per {spec.dims[0]})")
        if fixed.get(count) is None:
            self.fail(key, f"sampling the pattern {spec.name!r} needs {count!r} fixed (it sets "
                      f"the pattern's length), not on an axis or sampled")
        return int(fixed[count].si)
