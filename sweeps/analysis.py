"""What a sampled result says: summary statistics of every output over its samples, and, for
a Saltelli design, first-order and total Sobol' indices of every scalar output with bootstrap
confidence intervals.

The estimator is scipy.stats.sobol_indices (Saltelli et al. 2010), given the model's
evaluations of the blocks A, B and AB that the ``saltelli_block`` coordinate marks; its
confidence intervals are scipy.stats.bootstrap's over the base samples (percentile intervals:
BCa's jackknife would hand the estimator n - 1 samples, which it refuses, not being a power of
2), seeded so that the same file always gives the same numbers.
"""
from __future__ import annotations

import warnings
from datetime import datetime, timezone

import numpy as np
import xarray as xr

from .dependence import held_points, on_grid
from .labels import CONVENTIONS
from .spec import SpecError

#: The statistics over the samples, in the output's own unit.
STATISTICS = ("mean", "std", "p5", "p50", "p95")
#: Confidence level of the indices' intervals, and bootstrap resamples (scipy's defaults).
CONFIDENCE_LEVEL = 0.95
RESAMPLES = 999
#: Seed of the bootstrap's resampling.
BOOTSTRAP_SEED = 0


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
        ``data`` is not a sampled result.
    """
    if "sample" not in data.dims or "sample_method" not in data.attrs:
        raise SpecError(f"{where}: not a sampled result (no sample dimension: a definition "
                        "with a [sample] table gives one)")
    data = on_grid(data)  # an output stored on fewer axes than the grid has: per sample
    outputs = [name for name, v in data.data_vars.items()
               if v.attrs.get("coverage_content_type") == "modelResult"]
    axes = [d for d in data["status"].dims if d != "sample"]
    saltelli = data.attrs["sample_method"] == "saltelli"
    # Statistics of the inputs' distribution: in Saltelli's design, A and B are independent
    # samples; the AB blocks repeat their values.
    independent = data.isel(sample=slice(0, 2 * int(data.attrs["sample_size"]))) if saltelli \
        else data
    variables = {name: _statistics(independent[name]) for name in outputs}
    for name in outputs:  # entries of different units name theirs in a companion variable
        companion = data[name].attrs.get("ancillary_variables")
        if companion in data:
            variables[name].attrs["ancillary_variables"] = companion
            variables[companion] = data[companion]
    held = held_points(independent["status"])
    variables["valid_samples"] = held.sum("sample").astype(np.int64).assign_attrs(
        long_name="samples whose values hold", units="1",
        comment="samples whose status keeps values (converged, out_of_validity, "
                "no_root_in_range); the statistics leave NaN values out")
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
                                            "sample_inputs") if key in data.attrs},
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


def _indices(data: xr.DataArray, outputs: list[str], axes: list[str]) -> xr.Dataset:
    """First-order and total Sobol' indices of each scalar output, at each point of the other
    axes, with their bootstrap intervals."""
    from scipy import stats  # here: scipy.stats costs a second to import

    n = int(data.attrs["sample_size"])
    inputs = data.attrs["sample_inputs"].split()
    d = len(inputs)
    shape = tuple(data.sizes[a] for a in axes)
    # (output, other axes) flattened into the estimator's s outputs; samples in blocks.
    evaluations = np.stack([data[name].transpose("sample", *axes).values.reshape(
        (d + 2) * n, -1).T for name in outputs]).reshape(-1, d + 2, n)
    failed = np.isnan(evaluations).sum(axis=(1, 2))
    complete = failed == 0
    first = np.full((evaluations.shape[0], d), np.nan)
    total = first.copy()
    first_interval = np.full(first.shape + (2,), np.nan)
    total_interval = first_interval.copy()
    if complete.any():
        f = evaluations[complete]
        blocks = {"f_A": f[:, 0], "f_B": f[:, 1], "f_AB": np.moveaxis(f[:, 2:], 1, 0)}
        columns = f.shape[0]

        def estimate(index):
            found = stats.sobol_indices(func={k: v[..., index] for k, v in blocks.items()},
                                        n=n)
            return np.stack([np.reshape(found.first_order, (columns, d)),
                             np.reshape(found.total_order, (columns, d))])

        both = estimate(slice(None))
        first[complete], total[complete] = both
        with warnings.catch_warnings():
            # A constant output has indices of 0 and a degenerate bootstrap: NaN intervals.
            warnings.simplefilter("ignore")
            interval = stats.bootstrap(
                [np.arange(n)], estimate, method="percentile", n_resamples=RESAMPLES,
                confidence_level=CONFIDENCE_LEVEL, vectorized=False,
                rng=np.random.default_rng(BOOTSTRAP_SEED)).confidence_interval
        first_interval[complete] = np.stack([interval.low[0], interval.high[0]], axis=-1)
        total_interval[complete] = np.stack([interval.low[1], interval.high[1]], axis=-1)
    dims = ("output", *axes, "input")
    sizes = (len(outputs), *shape, d)

    def index(values, label, extra=()):
        return (dims + extra, values.reshape(sizes + values.shape[2:]), {
            "long_name": label, "units": "1",
            "comment": "Saltelli et al. 2010 (doi:10.1016/j.cpc.2009.09.018) through "
                       "scipy.stats.sobol_indices; NaN where an evaluation it needs failed"})

    interval_attrs = {"comment": f"{CONFIDENCE_LEVEL:.0%} confidence interval, percentile "
                                 "bootstrap "
                                 f"of {RESAMPLES} resamples of the base samples"}
    result = xr.Dataset({
        "first_order": index(first, "first-order Sobol index"),
        "total_order": index(total, "total Sobol index"),
        "first_order_interval": index(first_interval, "first-order index interval",
                                      ("bound",)),
        "total_order_interval": index(total_interval, "total index interval", ("bound",)),
        "failed_evaluations": (("output", *axes), failed.reshape((len(outputs), *shape)), {
            "long_name": "failed model evaluations", "units": "1",
            "comment": f"NaN values among the {(d + 2) * n} evaluations the indices need; "
                       "the indices are NaN unless it is 0"}),
    }, coords={"output": ("output", outputs, {"long_name": "output of the model"}),
               "input": ("input", inputs, {"long_name": "sampled input"}),
               "bound": ("bound", ["low", "high"], {"long_name": "end of the interval"}),
               **{a: data[a] for a in axes}})
    for name in ("first_order_interval", "total_order_interval"):
        result[name].attrs.update(interval_attrs)
    return result.transpose("output", "input", *axes, ...)
