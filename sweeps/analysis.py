"""What a sampled result says: summary statistics of every output over its samples, and, for
a Saltelli design, first-order and total Sobol' indices of every scalar output with their
confidence intervals.

The estimator is scipy.stats.sobol_indices (Saltelli et al. 2010), given the model's
evaluations of the blocks A, B and AB that the ``saltelli_block`` coordinate marks. The
design is randomized quasi-Monte Carlo: ``sample.SALTELLI_REPLICATES`` independent
scramblings of a Sobol' sequence (the ``saltelli_replicate`` coordinate), each of the ``n``
base samples the definition asks for. The index is estimated from all of them together; its
interval is Student's t over the replicates' own estimates: index +- t(0.975, R - 1) s / sqrt(R),
s their standard deviation (Owen, Practical Quasi-Monte Carlo Integration, 2023, ch. 17;
L'Ecuyer & Lemieux, in Modeling Uncertainty, 2002, doi:10.1007/0-306-48102-2_20). A
bootstrap over the points of one sequence would not do: it takes them for independent
draws, whose error shrinks as 1/sqrt(n), while a scrambled Sobol' sequence's shrinks nearly
as 1/n, and at n = 256 its intervals came out about 17 times too wide.

Before estimating, the samples are put back in the design's order by their numbers (the
``sample`` coordinate): a Saltelli result must hold its whole design, each sample once, its
blocks, replicates and sampled values as the design made them, or it is refused (the indices
pair the rows of A, B and AB: any other set of rows gives numbers that mean nothing). The
statistics of another design hold for any set of its samples (a selection, in any order),
each sample once.
"""
from __future__ import annotations

import math
import warnings
from datetime import datetime, timezone

import numpy as np
import xarray as xr

from .dependence import held_points, on_grid
from .labels import CONVENTIONS
from .sample import METHODS, saltelli_rows
from .spec import SpecError

#: The statistics over the samples, in the output's own unit.
STATISTICS = ("mean", "std", "p5", "p50", "p95")
#: Confidence level of the indices' intervals.
CONFIDENCE_LEVEL = 0.95


def analyze(data: xr.Dataset, where: str = "the dataset") -> xr.Dataset:
    """Summary statistics and, for a Saltelli design, Sobol' indices of a sampled result.

    Parameters
    ----------
    data : xarray.Dataset
        A result of a sweep with a ``[sample]`` table (a ``sample`` dimension).
    where : str
        How to name ``data`` in an error message (its file).

    Returns
    -------
    xarray.Dataset
        Each output of the result over the dimension ``statistic`` (mean, std, p5, p50, p95
        over the samples, NaN samples left out) and the result's other axes, in its unit;
        ``valid_samples``: how many samples hold values (by their status). For a Saltelli
        design also ``first_order`` and ``total_order`` (output, input, other axes) and their
        ``*_interval`` (``bound``: low, high), and ``failed_evaluations``: an output's
        indices are NaN where any of the evaluations the estimator needs failed.

    Raises
    ------
    SpecError
        ``data`` is not a sampled result, or not the whole design its attributes describe.
    """
    method = _sample_method(data, where)
    saltelli = method == "saltelli"
    data = _in_design_order(data, where) if saltelli else _distinct_samples(data, where)
    data = on_grid(data)  # an output stored on fewer axes than the grid has: per sample
    outputs = [name for name, v in data.data_vars.items()
               if v.attrs.get("coverage_content_type") == "modelResult"]
    axes = [d for d in data["status"].dims if d != "sample"]
    # Statistics of the inputs' distribution: in Saltelli's design, A and B are independent
    # samples; the AB blocks repeat their values.
    independent = data.isel(sample=np.flatnonzero(data["saltelli_block"].values < 2)) \
        if saltelli else data
    variables = {name: _statistics(independent[name]) for name in outputs}
    for name in outputs:  # entries of different units name theirs in a companion variable
        companion = data[name].attrs.get("ancillary_variables")
        if companion in data:
            variables[name].attrs["ancillary_variables"] = companion
            variables[companion] = data[companion]
    held = held_points(independent["status"])
    valid = held.sum("sample").astype(np.int64)
    valid.attrs = {  # its own: not the status' flags
        "long_name": "samples whose values hold", "units": "1",
        "comment": "samples whose status keeps values (converged, out_of_validity, "
                   "no_root_in_range); the statistics leave NaN values out"}
    variables["valid_samples"] = valid
    analysis = xr.Dataset(variables)
    if saltelli:
        analysis = analysis.merge(_indices(data, [n for n in outputs
                                                  if set(data[n].dims) <= set(("sample", *axes))],
                                           axes))
    analysis["statistic"] = ("statistic", list(STATISTICS), {
        "long_name": "statistic over the samples",
        "comment": "mean; std: standard deviation (ddof 1); p5, p50, p95: the 5, 50 and 95 % "
                   "quantiles (linear interpolation)"})
    analysis.attrs = {
        "Conventions": CONVENTIONS,
        "title": f"statistics{' and Sobol indices' if saltelli else ''} of "
                 f"{data.attrs.get('title', 'a sampled sweep')}",
        "source": data.attrs.get("source", "bearing-sweep"),
        "history": f"{datetime.now(timezone.utc).isoformat(timespec='seconds')} "
                   + (f"bearing-sweep analyze {where}" if where != "the dataset"
                      else "bearing_sweep.analyze(dataset)"),
        **{key: data.attrs[key] for key in ("model", "model_version", "definition_sha256",
                                            "sample_method", "sample_size", "sample_seed",
                                            "sample_replicates", "sample_inputs")
           if key in data.attrs},
        "samples_analyzed": int(independent.sizes["sample"]),
    }
    for name in analysis.coords:
        analysis[name].encoding["_FillValue"] = None  # CF: no fill values on coordinates
    return analysis


def _statistics(values: xr.DataArray) -> xr.DataArray:
    """Mean, std and quantiles of ``values`` over ``sample``, NaN left out."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # all-NaN slices give NaN
        parts = [values.mean("sample"), values.std("sample", ddof=1),
                 *(values.quantile(q, "sample").drop_vars("quantile")
                   for q in (0.05, 0.5, 0.95))]
    combined = xr.concat(parts, "statistic", coords="minimal", compat="override")
    combined = combined.transpose("statistic", ...)
    attrs = {k: v for k, v in values.attrs.items() if k in ("units", "long_name", "comment")}
    return combined.assign_attrs(attrs)


# -- what a result must hold -------------------------------------------------------------------
def _sample_method(data: xr.Dataset, where: str) -> str:
    """The design of a sampled result, its attributes and status checked: one line each."""
    if "sample" not in data.dims:
        raise SpecError(f"{where}: not a sampled result (no sample dimension: a definition "
                        "with a [sample] table gives one)")
    if data.sizes["sample"] == 0:
        raise SpecError(f"{where}: holds no samples")
    method = data.attrs.get("sample_method")
    if method is None:
        raise SpecError(f"{where}: has a sample dimension but no attribute sample_method (the "
                        "design that drew it), as bearing-sweep run writes; its attributes "
                        "were lost (xarray keeps them with keep_attrs=True)")
    if method not in METHODS:
        raise SpecError(f"{where}: attribute sample_method = {method!r} is not a design "
                        f"bearing-sweep draws ({', '.join(METHODS)})")
    status = data.get("status")
    if status is None or "sample" not in status.dims or not {
            "flag_values", "flag_meanings"} <= set(status.attrs):
        raise SpecError(f"{where}: no status variable over the samples with its flag_values "
                        "and flag_meanings (which samples hold values), as bearing-sweep run "
                        "writes it")
    return method


def _count_attribute(data: xr.Dataset, name: str, where: str, default=None) -> int:
    value = data.attrs.get(name, default)
    if isinstance(value, np.ndarray) and value.size == 1:  # as netCDF4 reads a number
        value = value.item()
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)) \
            or value < 1:
        raise SpecError(f"{where}: attribute {name} = {value!r}: expected a positive integer, "
                        "as bearing-sweep run writes it")
    return int(value)


def _distinct_samples(data: xr.Dataset, where: str) -> xr.Dataset:
    """``data``, refused if a sample number appears more than once (the same sample twice,
    or samples of several draws: their statistics would not be those of one)."""
    if "sample" in data.coords:
        numbers, counts = np.unique(data["sample"].values, return_counts=True)
        if (counts > 1).any():
            raise SpecError(f"{where}: sample {numbers[counts > 1][0]} appears "
                            f"{counts[counts > 1][0]} times: the same sample repeated, or "
                            "samples of several draws")
    return data


def _in_design_order(data: xr.Dataset, where: str) -> xr.Dataset:
    """A Saltelli result's samples in the order of its design (:func:`sample.saltelli_rows`),
    by their numbers, checked whole: each sample once, none missing, its blocks, replicates
    and sampled values as the design made them."""
    n = _count_attribute(data, "sample_size", where)
    # A file of a version before the replicates holds one scrambling.
    replicates = _count_attribute(data, "sample_replicates", where, default=1)
    inputs = str(data.attrs.get("sample_inputs", "")).split()
    if not inputs:
        raise SpecError(f"{where}: no attribute sample_inputs (the sampled inputs, in the "
                        "design's order), as bearing-sweep run writes it")
    size = n * replicates * (len(inputs) + 2)
    design = (f"its saltelli design (n = {n}, {replicates} replicate"
              f"{'s' if replicates > 1 else ''}, {len(inputs)} inputs: {size} samples)")
    if "sample" not in data.coords or data["sample"].dtype.kind not in "iu":
        raise SpecError(f"{where}: the samples have no numbers (a sample coordinate of "
                        "integers): the Sobol' indices need them to pair the design's rows")
    _distinct_samples(data, where)
    numbers = data["sample"].values
    if numbers.size != size or numbers.min() != 0 or numbers.max() != size - 1:
        missing = np.setdiff1d(np.arange(size), numbers)
        extra = np.setdiff1d(numbers, np.arange(size))
        found = (f"samples {_ranges(missing)} are missing" if missing.size else "") + \
            (", " if missing.size and extra.size else "") + \
            (f"samples {_ranges(extra)} are not of it" if extra.size else "")
        raise SpecError(f"{where}: holds {numbers.size} samples of {design}: {found}; the "
                        "Sobol' indices need the whole design")
    data = data.isel(sample=np.argsort(numbers, kind="stable"))
    block, replicate = saltelli_rows(n, len(inputs), replicates)
    for name, expected in (("saltelli_block", block), ("saltelli_replicate", replicate)):
        if name == "saltelli_replicate" and replicates == 1 and name not in data.coords:
            continue
        if name not in data.coords or not np.array_equal(data[name].values, expected):
            raise SpecError(f"{where}: the coordinate {name} "
                            + ("is missing" if name not in data.coords else
                               f"does not follow {design} in the order of their numbers"))
    for name in inputs:
        if name not in data.coords or "sample" not in data[name].dims:
            raise SpecError(f"{where}: no coordinate {name} along the samples (a sampled "
                            "input of sample_inputs): the design cannot be checked")
    _check_swaps(data, inputs, n * replicates, where)
    return data


def _check_swaps(data: xr.Dataset, inputs: list[str], base: int, where: str):
    """Each block AB_i holds A's values but input i's, which are B's."""
    for name in inputs:
        values = data[name].transpose("sample", ...).values.reshape((len(inputs) + 2, base, -1))
        for i, swapped in enumerate(inputs):
            expected = values[1] if swapped == name else values[0]
            if not np.array_equal(values[2 + i], expected, equal_nan=True):
                raise SpecError(f"{where}: the block AB_{swapped} does not hold "
                                f"{'B' if swapped == name else 'A'}'s values of {name}, as "
                                "Saltelli's design does: not the samples of the design its "
                                "attributes describe")


def _ranges(numbers: np.ndarray, shown: int = 3) -> str:
    """``0-29, 31, 40-49 ...``: sorted integers as ranges, the first ``shown`` of them."""
    breaks = np.flatnonzero(np.diff(numbers) != 1) + 1
    runs = [(run[0], run[-1]) for run in np.split(numbers, breaks)]
    text = ", ".join(f"{a}" if a == b else f"{a}-{b}" for a, b in runs[:shown])
    return text + (" ..." if len(runs) > shown else "")


# -- Sobol' indices ----------------------------------------------------------------------------
def sobol_indices(f_a: np.ndarray, f_b: np.ndarray, f_ab: np.ndarray, replicates: int,
                  confidence_level: float = CONFIDENCE_LEVEL) -> dict[str, np.ndarray]:
    """First-order and total Sobol' indices of a replicated Saltelli design, with intervals.

    Parameters
    ----------
    f_a, f_b : numpy.ndarray
        The model's values on the blocks A and B, shape (outputs, replicates * n): each
        replicate's ``n`` rows together, ``n`` a power of 2.
    f_ab : numpy.ndarray
        Its values on the blocks AB, one per input, shape (inputs, outputs, replicates * n).
    replicates : int
        The design's independent scramblings.
    confidence_level : float
        Of the intervals.

    Returns
    -------
    dict
        ``first_order`` and ``total_order``, shape (outputs, inputs): scipy's estimator on
        all the replicates' rows together; ``first_order_interval`` and
        ``total_order_interval`` (outputs, inputs, 2): the estimate +- Student's t quantile
        (``replicates - 1`` degrees of freedom) times the standard deviation of the
        replicates' own estimates over sqrt(replicates); NaN with a single replicate and for
        an output of no variance (whose indices scipy gives as 0).
    """
    from scipy import stats  # here: only an analysis pays for importing it

    outputs, d = f_a.shape[0], f_ab.shape[0]
    rows = f_a.shape[1]
    n = rows // replicates

    def estimate(part) -> np.ndarray:
        found = stats.sobol_indices(func={"f_A": f_a[:, part], "f_B": f_b[:, part],
                                          "f_AB": f_ab[..., part]}, n=part.stop - part.start)
        return np.stack([np.reshape(found.first_order, (outputs, d)),
                         np.reshape(found.total_order, (outputs, d))])

    both = estimate(slice(0, rows))
    half = np.full(both.shape, np.nan)
    if replicates > 1:
        each = np.stack([estimate(slice(r * n, (r + 1) * n)) for r in range(replicates)])
        quantile = stats.t.ppf(0.5 + confidence_level / 2, replicates - 1)
        half = quantile * each.std(axis=0, ddof=1) / math.sqrt(replicates)
    constant = np.ptp(np.concatenate([f_a, f_b], axis=1), axis=1) == 0
    half[:, constant] = np.nan
    return {"first_order": both[0], "total_order": both[1],
            "first_order_interval": np.stack([both[0] - half[0], both[0] + half[0]], axis=-1),
            "total_order_interval": np.stack([both[1] - half[1], both[1] + half[1]], axis=-1)}


def _indices(data: xr.Dataset, outputs: list[str], axes: list[str]) -> xr.Dataset:
    """First-order and total Sobol' indices of each scalar output, at each point of the other
    axes, with their intervals (``data``: in the design's order)."""
    n = int(data.attrs["sample_size"])
    replicates = int(data.attrs.get("sample_replicates", 1))
    inputs = data.attrs["sample_inputs"].split()
    d = len(inputs)
    shape = tuple(data.sizes[a] for a in axes)
    base = replicates * n
    # (output, other axes) flattened into the estimator's s outputs; samples in blocks.
    evaluations = np.stack([data[name].transpose("sample", *axes).values.reshape(
        (d + 2) * base, -1).T for name in outputs]).reshape(-1, d + 2, base)
    failed = np.isnan(evaluations).sum(axis=(1, 2))
    complete = failed == 0
    found = {name: np.full((evaluations.shape[0], d) + extra, np.nan)
             for name, extra in (("first_order", ()), ("total_order", ()),
                                 ("first_order_interval", (2,)),
                                 ("total_order_interval", (2,)))}
    if complete.any():
        f = evaluations[complete]
        estimated = sobol_indices(f[:, 0], f[:, 1], np.moveaxis(f[:, 2:], 1, 0), replicates)
        for name, values in estimated.items():
            found[name][complete] = values
    dims = ("output", *axes, "input")
    sizes = (len(outputs), *shape, d)
    method = ("Saltelli et al. 2010 (doi:10.1016/j.cpc.2009.09.018) through "
              f"scipy.stats.sobol_indices, on the {replicates} replicates' samples together")

    def index(name, label, extra=()):
        values = found[name]
        return (dims + extra, values.reshape(sizes + values.shape[2:]), {
            "long_name": label, "units": "1",
            "comment": f"{method}; NaN where an evaluation it needs failed"})

    interval = (f"{CONFIDENCE_LEVEL:.0%} confidence interval: the index +- Student's t "
                f"quantile ({replicates - 1} degrees of freedom) times the standard deviation "
                f"of the {replicates} replicates' own estimates over sqrt({replicates}) "
                "(randomized quasi-Monte Carlo); NaN for a design of one replicate, an output "
                "of no variance or where an evaluation failed")
    result = xr.Dataset({
        "first_order": index("first_order", "first-order Sobol index"),
        "total_order": index("total_order", "total Sobol index"),
        "first_order_interval": index("first_order_interval", "first-order index interval",
                                      ("bound",)),
        "total_order_interval": index("total_order_interval", "total index interval",
                                      ("bound",)),
        "failed_evaluations": (("output", *axes), failed.reshape((len(outputs), *shape)), {
            "long_name": "failed model evaluations", "units": "1",
            "comment": f"NaN values among the {(d + 2) * base} evaluations the indices need; "
                       "the indices are NaN unless it is 0"}),
    }, coords={"output": ("output", outputs, {"long_name": "output of the model"}),
               "input": ("input", inputs, {"long_name": "sampled input"}),
               "bound": ("bound", ["low", "high"], {"long_name": "end of the interval"}),
               **{a: data[a] for a in axes}})
    for name in ("first_order_interval", "total_order_interval"):
        result[name].attrs["comment"] = interval
    return result.transpose("output", "input", *axes, ...)
