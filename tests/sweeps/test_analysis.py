"""``analyze``: Sobol' intervals that hold what they claim (randomized quasi-Monte Carlo over
the design's replicates), a design taken in its order whatever the rows' order and refused
when it is not whole, one line for a result it cannot read, and its output in the format its
name says, CF-labelled."""
import math

import numpy as np
import pytest
import xarray as xr

import bearing_sweep
from bearing_sweep import analysis, cli, sample
from bearing_sweep.spec import SpecError

REPLICATES = sample.SALTELLI_REPLICATES
SEEDS = 40


# -- the estimator and its intervals, on arrays ---------------------------------------------------
def linear(x, weights=(1.0, 2.0, 3.0)):
    return x @ np.asarray(weights)


def linear_indices(weights=(1.0, 2.0, 3.0)):
    """An additive function of independent inputs: no interactions, each input's index
    (first-order and total alike) its share of the variance, c_i^2 var(x_i) / sum of them
    (Saltelli et al., Global Sensitivity Analysis: The Primer, Wiley 2008, section 4.1,
    doi:10.1002/9780470725184); the inputs are uniform on [0, 1], of equal variance."""
    share = np.square(weights) / np.sum(np.square(weights))
    return share, share


def ishigami_unit(x):
    """The Ishigami function (a = 7, b = 0.1) of inputs uniform on [0, 1], stretched to
    [-pi, pi]."""
    x = np.pi * (2 * x - 1)
    return np.sin(x[:, 0]) + 7 * np.sin(x[:, 1]) ** 2 + 0.1 * x[:, 2] ** 4 * np.sin(x[:, 0])


G_COEFFICIENTS = np.array([0.0, 1.0, 4.5, 9.0])


def sobol_g(x):
    return np.prod((np.abs(4 * x - 2) + G_COEFFICIENTS) / (1 + G_COEFFICIENTS), axis=1)


def sobol_g_indices():
    """Sobol' G function's indices: partial variances V_i = 1 / (3 (1 + a_i)^2), the total
    variance prod(1 + V_i) - 1 (Saltelli & Sobol', Reliab. Eng. Syst. Saf. 50(3), 225-239,
    1995, doi:10.1016/0951-8320(95)00099-2)."""
    partial = 1 / (3 * (1 + G_COEFFICIENTS) ** 2)
    total_variance = np.prod(1 + partial) - 1
    return partial / total_variance, partial * np.prod(1 + partial) / (1 + partial) \
        / total_variance


@pytest.fixture(scope="module")
def functions(ishigami_indices):
    """Each test function by name: (function of inputs uniform on [0, 1], how many inputs,
    its exact first-order and total indices)."""
    return {"linear": (linear, 3, linear_indices()),
            "ishigami": (ishigami_unit, 3, ishigami_indices(7.0)),
            "sobol_g": (sobol_g, 4, sobol_g_indices())}


def estimated(function, inputs: int, n: int, seed: int, replicates: int = REPLICATES):
    """The indices and intervals of ``function`` from the design a sweep draws."""
    points = sample.saltelli_blocks(n, [1] * inputs, seed, replicates)
    values = function(points).reshape(inputs + 2, 1, replicates * n)
    return analysis.sobol_indices(values[0], values[1], values[2:], replicates)


def over_seeds(test_function: tuple, n: int, replicates: int = REPLICATES):
    """Estimates (seeds, 2 inputs: first-order then total), intervals (seeds, 2 inputs, 2)
    and the exact values (2 inputs) of one test function (an item of ``functions``)."""
    function, inputs, exact = test_function
    found = [estimated(function, inputs, n, seed, replicates) for seed in range(SEEDS)]
    values = np.array([np.concatenate([f["first_order"][0], f["total_order"][0]])
                       for f in found])
    intervals = np.array([np.concatenate([f["first_order_interval"][0],
                                          f["total_order_interval"][0]]) for f in found])
    return values, intervals, np.concatenate(exact)


@pytest.mark.parametrize("n", [sample.SALTELLI_MIN_N, 128])
def test_the_intervals_hold_the_exact_index_about_95_percent_of_the_time(n, functions):
    held = []
    for name, test_function in functions.items():
        _, intervals, exact = over_seeds(test_function, n)
        inside = (intervals[..., 0] <= exact) & (exact <= intervals[..., 1])
        # Each index: at least 34 of the 40 seeds' intervals hold it (a 95 % interval falls
        # below with probability 0.003).
        assert inside.sum(axis=0).min() >= 34, (name, inside.sum(axis=0))
        held.append(inside)
    # All 800 intervals: 92-98 % (a binomial's 0.1 and 99.9 % points are 92.4 and 97.4 %);
    # intervals too wide to be of use, as a bootstrap gave, would hold it nearly always.
    assert 0.92 <= np.mean(np.concatenate(held, axis=1)) <= 0.98


@pytest.mark.parametrize("n", [sample.SALTELLI_MIN_N, 128])
def test_the_intervals_are_as_wide_as_the_estimates_spread_over_seeds(n, functions):
    for name, test_function in functions.items():
        values, intervals, _ = over_seeds(test_function, n)
        half_width = np.mean((intervals[..., 1] - intervals[..., 0]) / 2, axis=0)
        spread = 1.96 * np.std(values, axis=0, ddof=1)  # a 95 % interval's half width
        ratio = half_width / spread
        assert np.all((0.5 <= ratio) & (ratio <= 2.0)), (name, ratio)


def test_the_replicated_estimate_is_at_least_as_good_as_one_scrambling(functions):
    # The design before the replicates: one scrambled sequence of n base samples.
    for name, test_function in functions.items():
        replicated, _, exact = over_seeds(test_function, 64)
        single, _, _ = over_seeds(test_function, 64, replicates=1)
        error, single_error = (np.sqrt(np.mean((v - exact) ** 2, axis=0))
                               for v in (replicated, single))
        assert np.all(error <= single_error), (name, error, single_error)


def test_no_interval_from_one_replicate_nor_for_an_output_that_does_not_vary():
    found = estimated(linear, 3, 16, seed=0, replicates=1)
    assert np.isfinite(found["first_order"]).all()
    assert np.isnan(found["first_order_interval"]).all()
    constant = np.ones((1, 16 * REPLICATES))
    found = analysis.sobol_indices(constant, constant, np.stack([constant] * 2), REPLICATES)
    assert np.isnan(found["total_order_interval"]).all()


# -- a Saltelli result: taken in its design's order, or refused ---------------------------------
DESIGN_SIZE = 16 * REPLICATES * 5


@pytest.fixture
def saltelli(ishigami_sweep):
    return ishigami_sweep(16, seed=5)


def same_indices(expected: xr.Dataset, found: xr.Dataset):
    for name in ("first_order", "total_order", "first_order_interval", "total_order_interval",
                 "y", "valid_samples"):
        xr.testing.assert_equal(expected[name], found[name])


def test_reordered_samples_give_the_indices_of_the_design_in_order(saltelli, tmp_path):
    expected = bearing_sweep.analyze(saltelli)
    shuffled = saltelli.isel(sample=np.random.default_rng(1).permutation(DESIGN_SIZE))
    for reordered in (saltelli.sortby("x1"), saltelli.sortby("sample", ascending=False),
                      shuffled, shuffled.transpose("a", "sample")):
        same_indices(expected, bearing_sweep.analyze(reordered))
    path = tmp_path / "sorted.nc"
    saltelli.sortby("x2").to_netcdf(path)
    same_indices(expected, bearing_sweep.analyze(path))


def refused(data, message: str):
    with pytest.raises(SpecError, match=message) as raised:
        bearing_sweep.analyze(data)
    assert "\n" not in str(raised.value)


def test_a_saltelli_result_that_is_not_its_whole_design_is_refused(saltelli):
    refused(saltelli.isel(sample=slice(0, 30)),
            r"holds 30 samples of its saltelli design \(n = 16, 8 replicates, 3 inputs: 640 "
            r"samples\): samples 30-639 are missing; the Sobol' indices need the whole design")
    one_block_less = saltelli.isel(sample=np.flatnonzero(saltelli.saltelli_block.values != 3))
    refused(one_block_less, "holds 512 samples .*: samples 384-511 are missing")
    refused(xr.concat([saltelli, saltelli.isel(sample=[5])], "sample"),
            "sample 5 appears 2 times: the same sample repeated, or samples of several draws")
    refused(xr.concat([saltelli, saltelli], "sample"), "sample 0 appears 2 times")
    other = saltelli.assign_coords(sample=saltelli.sample + DESIGN_SIZE)
    refused(xr.concat([saltelli, other], "sample"), "samples 640-1279 are not of it")
    refused(saltelli.assign_attrs(sample_size=32), "holds 640 samples of its saltelli design "
            r"\(n = 32, 8 replicates, 3 inputs: 1280 samples\): samples 640-1279 are missing")


def test_a_saltelli_result_whose_rows_are_not_the_designs_is_refused(saltelli):
    renumbered = saltelli.sortby("x1").assign_coords(sample=np.arange(DESIGN_SIZE))
    refused(renumbered, "the coordinate saltelli_block does not follow its saltelli design "
            r"\(.*\) in the order of their numbers")
    # Its blocks and replicates marked again as the design has them: the values tell.
    marks = {name: ("sample", saltelli[name].values, saltelli[name].attrs)
             for name in ("saltelli_block", "saltelli_replicate")}
    refused(renumbered.assign_coords(marks),
            "the block AB_x1 does not hold B's values of x1, as Saltelli's design does")
    refused(saltelli.drop_vars("saltelli_replicate"),
            "the coordinate saltelli_replicate is missing")
    refused(saltelli.drop_vars("x2"), "no coordinate x2 along the samples")
    refused(saltelli.drop_vars("sample"), "the samples have no numbers")


@pytest.mark.parametrize("change, message", [
    (lambda d: d.drop_attrs(deep=False), "has a sample dimension but no attribute sample_method"),
    (lambda d: d.assign_attrs(sample_method="sobolev"), "sample_method = 'sobolev' is not a "
                                                        "design bearing-sweep draws"),
    (lambda d: d.drop_vars("status"), "no status variable over the samples"),
    (lambda d: d.assign(status=d.status.drop_attrs()), "no status variable over the samples "
                                                        "with its flag_values"),
    (lambda d: d.assign_attrs(sample_size="16"), r"attribute sample_size = '16': expected a "
                                                  "positive integer"),
    (lambda d: d.assign_attrs(sample_size=0), "attribute sample_size = 0"),
    (lambda d: d.assign_attrs(sample_replicates=1.5), "attribute sample_replicates = 1.5"),
    (lambda d: d.assign_attrs(sample_inputs=""), "no attribute sample_inputs"),
    (lambda d: d.isel(sample=0), "not a sampled result"),
])
def test_a_result_without_what_analyze_needs_is_named_in_one_line(saltelli, change, message):
    refused(change(saltelli), message)


def test_a_design_of_one_replicate_gives_indices_without_intervals(ishigami_sweep, monkeypatch,
                                                                    tmp_path, capsys):
    # As a file written before the design had replicates: no replicate coordinate either.
    monkeypatch.setattr(sample, "SALTELLI_REPLICATES", 1)
    data = ishigami_sweep(64, seed=0)
    old = data.drop_vars("saltelli_replicate")
    old.attrs = {k: v for k, v in data.attrs.items() if k != "sample_replicates"}
    analyzed = bearing_sweep.analyze(old)
    assert np.isfinite(analyzed.first_order).all()
    assert analyzed.first_order_interval.isnull().all()
    old.to_netcdf(tmp_path / "old.nc")
    assert cli.main(["analyze", str(tmp_path / "old.nc")]) == 0
    assert "no interval: a design of one replicate" in capsys.readouterr().out


# -- other designs: statistics of any set of their samples ----------------------------------------
def sampled(method: str, axes: str = "", n: int = 16) -> str:
    return f"""
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
speed = "5000 rpm"
{axes}
[sample]
n = {n}
method = "{method}"
seed = 2
radial_load = {{ distribution = "uniform", low = "1 kN", high = "8 kN" }}
clearance = {{ distribution = "tolerance", nominal = "20 um", upper = "+6 um", lower = "-6 um" }}
"""


def test_statistics_of_a_selection_in_any_order_are_those_of_its_samples(capsys, tmp_path):
    data = bearing_sweep.run(sampled("random", n=40), workers=0, progress=False)
    chosen = np.random.default_rng(3).permutation(40)[:25]
    in_order = bearing_sweep.analyze(data.isel(sample=np.sort(chosen)))
    shuffled = bearing_sweep.analyze(data.isel(sample=chosen))
    xr.testing.assert_allclose(in_order.radial_stiffness, shuffled.radial_stiffness)
    np.testing.assert_allclose(shuffled.radial_stiffness.sel(statistic="mean"),
                               data.radial_stiffness.isel(sample=chosen).mean())
    assert shuffled.attrs["samples_analyzed"] == 25 and shuffled.attrs["sample_size"] == 40
    data.isel(sample=chosen).to_netcdf(tmp_path / "chosen.nc")
    assert cli.main(["analyze", str(tmp_path / "chosen.nc")]) == 0
    assert "statistics of 25 samples of each output (a selection of the 40 drawn)" in \
        capsys.readouterr().out
    refused(xr.concat([data, data.isel(sample=[7])], "sample", data_vars="all"),
            "sample 7 appears 2 times: the same sample repeated, or samples of several draws")


# -- the output: the format its name says, CF-labelled ---------------------------------------------
@pytest.fixture(scope="module")
def results(tmp_path_factory):
    """A result of every design, with and without another axis (crb_radial's roller_load
    has a dimension of its own)."""
    folder = tmp_path_factory.mktemp("designs")
    made = {}
    for method in sample.METHODS:
        for axes in ("", "[axes]\nslices = [20, 30]"):
            path = folder / f"{method}{'-axes' if axes else ''}.nc"
            bearing_sweep.run(sampled(method, axes), output=path, workers=0,
                              progress=False).close()
            made[path.stem] = path
    return made


def test_an_analysis_of_every_design_reads_back_as_netcdf_and_zarr(results, tmp_path,
                                                                   assert_cf_labelled):
    formats = ((".nc", "netcdf4"), (".zarr", "zarr"), (".ZARR", "zarr"))
    for index, (name, path) in enumerate(results.items()):
        suffix, engine = formats[index % len(formats)]  # each format in turn
        output = tmp_path / f"{name}_analysis{suffix}"
        analyzed = bearing_sweep.analyze(path, output=output)
        assert output.is_dir() == (engine == "zarr"), output
        with xr.open_dataset(output, engine=engine) as written:
            xr.testing.assert_identical(written.load(), analyzed)
        assert_cf_labelled(analyzed)
        for variable in {**analyzed.coords, **analyzed.data_vars}.values():
            if "flag_values" in variable.attrs:  # CF 3.5: of the variable's type
                assert np.asarray(variable.attrs["flag_values"]).dtype == variable.dtype
        assert set(analyzed.valid_samples.attrs) == {"long_name", "units", "comment"}
        assert analyzed.roller_load.dims[-1] == "roller"
        assert ("first_order" in analyzed) == name.startswith("saltelli")
        assert list(tmp_path.glob(".*")) == []  # nothing left beside the outputs


def test_an_output_whose_name_says_another_format_is_refused(results, tmp_path, capsys):
    result = results["random"]
    for output in ("analysis.h5", "analysis.csv", "analysis", ".zarr"):
        with pytest.raises(SpecError, match="an analysis is written as a netCDF file "
                                            r"\(\.nc, \.nc4\) or a zarr store \(\.zarr\)"):
            bearing_sweep.analyze(result, output=tmp_path / output)
        assert cli.main(["analyze", str(result), "-o", str(tmp_path / output)]) == 2
        assert len(capsys.readouterr().err.strip().splitlines()) == 1
    with pytest.raises(SpecError, match="output=5: expected a path"):
        bearing_sweep.analyze(result, output=5)
    with pytest.raises(SpecError, match="result=5: expected a sampled result"):
        bearing_sweep.analyze(5)
    assert list(tmp_path.iterdir()) == []
    assert cli.main(["analyze", str(result), "-o", str(tmp_path / "a.zarr")]) == 0
    assert (tmp_path / "a.zarr" / ".zmetadata").is_file()
    assert math.isfinite(float(xr.open_dataset(tmp_path / "a.zarr", engine="zarr")
                               .radial_stiffness.sel(statistic="mean")))


def test_an_analysis_replaces_an_earlier_analysis_only_and_a_run_a_run_only(tmp_path, capsys):
    import shutil

    result = tmp_path / "r.nc"
    definition = tmp_path / "r.toml"
    definition.write_text(sampled("random", n=8))
    assert cli.main(["run", str(definition), "-o", str(result), "--workers", "0",
                     "--quiet"]) == 0
    other = tmp_path / "other.nc"
    shutil.copy(result, other)
    before = other.read_bytes()
    assert cli.main(["analyze", str(result), "-o", str(other)]) == 2  # a run: not replaced
    assert "is not an analysis written by bearing-sweep (it is the result of a run" in \
        capsys.readouterr().err
    assert other.read_bytes() == before
    analysis = tmp_path / "a.nc"
    assert cli.main(["analyze", str(result), "-o", str(analysis)]) == 0
    assert cli.main(["analyze", str(result), "-o", str(analysis)]) == 0  # its own: replaced
    capsys.readouterr()
    assert cli.main(["run", str(definition), "-o", str(analysis), "--workers", "0"]) == 2
    assert "it is an analysis, not the result of a run" in capsys.readouterr().err
    with xr.open_dataset(analysis) as kept:
        assert "statistic" in kept.dims
