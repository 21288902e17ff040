"""[sample]: inputs drawn from distributions with units into one ``sample`` dimension; the
designs (Latin hypercube strata, Saltelli blocks); the same seed gives the same dataset
whatever the chunking or the workers; ``analyze``: statistics and Sobol' indices."""
import math

import numpy as np
import pytest
import xarray as xr
from jsonschema import Draft7Validator

import bearing_sweep
from bearing_sweep import cli, sample, spec
from bearing_sweep.compute import Executor, run_sweep
from bearing_sweep.schema import schema
from bearing_sweep.testing import assert_chunking_invariant, assert_same_numbers

HEAD = '[sweep]\nmodel = "crb_radial"\nbearing = "paper000-D"\n'


def drawn(sample_table: str, extra: str = "") -> dict:
    """The sample axis' values of a crb_radial definition, each input in its declared unit."""
    sweep = spec.parse(HEAD + extra + "[sample]\n" + sample_table, "sample.toml")
    axis = sweep.axes[0]
    assert axis.name == "sample"
    return {name: np.array([v.shown for v in values]) for name, values in axis.values.items()}


def normal_cdf(x):
    return 0.5 * (1 + math.erf(x / math.sqrt(2)))


def normal_pdf(x):
    return math.exp(-0.5 * x * x) / math.sqrt(2 * math.pi)


def test_moments_and_bounds_match_the_distributions():
    n = 20000
    values = drawn(f"""
        n = {n}
        method = "random"
        seed = 5
        radial_load = {{ distribution = "uniform", low = "1 kN", high = "8 kN" }}
        clearance = {{ distribution = "normal", mean = "0.02 mm", std = "4 um" }}
        crown = {{ distribution = "truncated_normal", mean = "4 um", std = "2 um", low = "3 um", high = "9 um" }}
        speed = {{ distribution = "triangular", low = "1000 rpm", mode = "2000 rpm", high = "6000 rpm" }}
        """.replace("        ", ""))
    # Random draws: the sample mean lies within 5 standard errors (a 1 in 10^6 miss).
    def check(x, mean, std, low=-np.inf, high=np.inf):
        assert low <= x.min() and x.max() <= high
        assert abs(x.mean() - mean) < 5 * std / math.sqrt(n), (x.mean(), mean)
        assert abs(x.std() / std - 1) < 0.03  # the std's relative standard error is 0.5 %

    # In the declared units: radial_load in N, clearance and crown in mm, speed in r/min.
    check(values["radial_load"], 4500.0, 7000.0 / math.sqrt(12), 1000.0, 8000.0)
    check(values["clearance"], 0.02, 0.004)
    # Truncated normal: mean and variance from the standard formulas (Johnson, Kotz &
    # Balakrishnan, Continuous Univariate Distributions 1, 2nd ed., 1994, eq. 13.134-13.135).
    a, b = (3 - 4) / 2, (9 - 4) / 2
    z = normal_cdf(b) - normal_cdf(a)
    mean = 4 + 2 * (normal_pdf(a) - normal_pdf(b)) / z
    var = 4 * (1 + (a * normal_pdf(a) - b * normal_pdf(b)) / z
               - ((normal_pdf(a) - normal_pdf(b)) / z) ** 2)
    check(values["crown"] * 1000, mean, math.sqrt(var), 3.0, 9.0)
    # Triangular: mean (a + c + b) / 3, variance (a² + b² + c² - ab - ac - bc) / 18.
    low, mode, high = 1000.0, 2000.0, 6000.0
    var = (low**2 + mode**2 + high**2 - low * mode - low * high - mode * high) / 18
    check(values["speed"], (low + mode + high) / 3, math.sqrt(var), low, high)


def test_a_tolerance_band_as_a_drawing_writes_it():
    values = drawn("""
        n = 20000
        method = "random"
        crown = { distribution = "tolerance", nominal = "4 um", upper = "+2 um", lower = "-1 um" }
        clearance = { distribution = "tolerance", nominal = "20 um", upper = "+6 um", lower = "-6 um", distribution_within = "normal" }
        """.replace("        ", ""), '[fixed]\nradial_load = "4 kN"\n')
    crown = values["crown"] * 1000  # um
    assert crown.min() >= 3.0 and crown.max() <= 6.0  # 4 um -1/+2
    assert abs(crown.mean() - 4.5) < 5 * (3 / math.sqrt(12)) / math.sqrt(20000)
    clearance = values["clearance"] * 1000
    assert clearance.min() >= 14.0 and clearance.max() <= 26.0  # cut at the band
    # Within normal: the band is +-3 sigma (sigma 2 um), the normal cut there; the cut
    # shrinks the std by sqrt(1 - 6 phi(3) / (2 Phi(3) - 1)) = 0.9866.
    shrink = math.sqrt(1 - 6 * normal_pdf(3) / (2 * normal_cdf(3) - 1))
    assert abs(clearance.std() / (2.0 * shrink) - 1) < 0.03
    assert abs(clearance.mean() - 20.0) < 5 * 2.0 / math.sqrt(20000)


def test_latin_hypercube_puts_one_sample_in_each_stratum():
    n = 50
    values = drawn(f"""
        n = {n}
        method = "latin_hypercube"
        seed = 2
        radial_load = {{ distribution = "uniform", low = "1 kN", high = "6 kN" }}
        crown = {{ distribution = "uniform", low = "0 um", high = "10 um" }}
        """.replace("        ", ""))
    for name, (low, high) in {"radial_load": (1000, 6000), "crown": (0, 0.01)}.items():
        strata = np.floor((values[name] - low) / (high - low) * n).astype(int)
        assert sorted(strata) == list(range(n)), name


def test_a_pattern_is_drawn_entry_by_entry():
    sweep = spec.parse("""
        [sweep]
        model = "crb_runout"
        bearing = "paper004-NU208-1"
        [sample]
        n = 16
        method = "sobol"
        roller_diameter_error = { distribution = "tolerance", nominal = "0 um", upper = "+1 um", lower = "-1 um" }
        """.replace("        ", ""), "pattern.toml")
    values = sweep.axes[0].si["roller_diameter_error"]
    rollers = sweep.fixed["roller_count"].si
    assert values.shape == (16, rollers)
    assert np.abs(values).max() <= 1e-6
    assert np.unique(values).size == values.size  # each entry its own draw


def test_the_saltelli_design_swaps_one_input_per_block_in_each_replicate():
    n, replicates = 16, sample.SALTELLI_REPLICATES
    values = drawn(f"""
        n = {n}
        method = "saltelli"
        seed = 4
        radial_load = {{ distribution = "uniform", low = "1 kN", high = "8 kN" }}
        crown = {{ distribution = "uniform", low = "0 um", high = "8 um" }}
        """.replace("        ", ""))
    load, crown = (values[name].reshape(4, replicates, n) for name in ("radial_load", "crown"))
    # Blocks A, B, AB_radial_load (A with B's loads), AB_crown (A with B's crowns).
    np.testing.assert_array_equal(load[2], load[1])
    np.testing.assert_array_equal(crown[2], crown[0])
    np.testing.assert_array_equal(load[3], load[0])
    np.testing.assert_array_equal(crown[3], crown[1])
    assert not np.any(load[0] == load[1])
    # Each replicate's A and B are a scrambled Sobol' net of n points: one point in each of
    # the n equal strata of every input; the replicates are scrambled apart.
    for name, blocks, (low, high) in (("radial_load", load, (1000, 8000)),
                                      ("crown", crown, (0, 0.008))):
        strata = np.floor((blocks[:2] - low) / (high - low) * n).astype(int)
        assert (np.sort(strata, axis=-1) == np.arange(n)).all(), name
        assert len({tuple(one) for one in blocks[0]}) == replicates, name


def test_a_saltelli_design_below_the_smallest_analyze_can_use_is_refused():
    for n in (1, 2, sample.SALTELLI_MIN_N // 2):
        with pytest.raises(spec.SpecError, match=rf"sample\.n: {n}: a saltelli design needs at "
                           rf"least {sample.SALTELLI_MIN_N} base samples"):
            drawn(f'n = {n}\nmethod = "saltelli"\n'
                  'radial_load = { distribution = "uniform", low = "1 kN", high = "8 kN" }\n')
    assert drawn(f'n = {sample.SALTELLI_MIN_N}\nmethod = "saltelli"\n'
                 'radial_load = { distribution = "uniform", low = "1 kN", high = "8 kN" }\n')[
        "radial_load"].size == sample.SALTELLI_MIN_N * sample.SALTELLI_REPLICATES * 3
    # The other designs take any n (a power of 2 for sobol).
    assert drawn('n = 1\nmethod = "sobol"\n'
                 'radial_load = { distribution = "uniform", low = "1 kN", high = "8 kN" }\n')[
        "radial_load"].size == 1


SALTELLI = HEAD + """
[fixed]
speed = "5000 rpm"
[axes]
slices = [20, 30]
[sample]
n = 16
method = "saltelli"
seed = 7
radial_load = { distribution = "uniform", low = "1 kN", high = "8 kN" }
clearance = { distribution = "normal", mean = "0.02 mm", std = "0.004 mm" }
"""


def test_the_file_holds_the_samples_their_units_and_the_design(tmp_path, assert_cf_labelled):
    output = tmp_path / "sampled.nc"
    bearing_sweep.run(SALTELLI, output=output, workers=0, progress=False).close()
    with xr.open_dataset(output) as data:
        assert data.radial_stiffness.dims == ("sample", "slices")
        replicates = sample.SALTELLI_REPLICATES
        assert data.sizes["sample"] == 16 * replicates * (2 + 2)
        assert data.radial_load.attrs["units"] == "N"
        assert data.radial_load.attrs["distribution"] == "uniform(low=1000 N, high=8000 N)"
        assert data.clearance.attrs["units"] == "mm"
        assert data.attrs["sample_method"] == "saltelli"
        assert data.attrs["sample_inputs"] == "radial_load clearance"
        block = data.saltelli_block
        assert block.attrs["flag_meanings"] == "A B AB_radial_load AB_clearance"
        np.testing.assert_array_equal(block.values, np.repeat([0, 1, 2, 3], 16 * replicates))
        assert data.attrs["sample_replicates"] == replicates
        np.testing.assert_array_equal(data.saltelli_replicate.values,
                                      np.tile(np.repeat(np.arange(replicates), 16), 4))
        assert_cf_labelled(data)
        analyzed = bearing_sweep.analyze(data)
    assert_cf_labelled(analyzed)
    assert analyzed.radial_stiffness.attrs["units"] == "N/mm"
    assert analyzed.first_order.dims == ("output", "input", "slices")
    assert list(analyzed.input.values) == ["radial_load", "clearance"]


def test_the_same_seed_gives_the_same_dataset_whatever_the_chunks_and_workers(tmp_path):
    assert_chunking_invariant(SALTELLI, tmp_path, chunk_size=37)  # across blocks and replicates
    local = bearing_sweep.run(SALTELLI, workers=2, progress=False)
    with Executor(workers=0) as executor:
        path = tmp_path / "in_process.nc"
        run_sweep(spec.parse(SALTELLI), path, executor, chunk_size=41, progress=False)
    with xr.open_dataset(path) as in_process:
        assert_same_numbers(in_process.load(), local)
        np.testing.assert_array_equal(in_process.radial_load, local.radial_load)
    other_seed = spec.parse(SALTELLI.replace("seed = 7", "seed = 8"))
    assert not np.array_equal(other_seed.axes[0].si["radial_load"],
                              local.radial_load.values * 1.0)


def test_a_sweep_analysed_end_to_end_gives_the_ishigami_functions_indices(ishigami_sweep,
                                                                          ishigami_indices):
    data = ishigami_sweep(128, seed=3)
    analyzed = bearing_sweep.analyze(data)
    assert analyzed.first_order.dims == ("output", "input", "a")
    for a in (7.0, 5.0):
        one = analyzed.sel(output="y", a=a)
        for name, expected in zip(("first_order", "total_order"), ishigami_indices(a)):
            found = one[name].transpose("input").values
            low, high = one[f"{name}_interval"].transpose("bound", "input").values
            # 8 replicates of 128 base samples: an index within 0.06 of the analytic one
            # (over seeds its error's standard deviation is 0.01-0.03 at this size), and
            # within twice its 95 % interval's half width (Student's t with 7 degrees of
            # freedom exceeds 4.7 once in 500).
            assert np.all(np.abs(found - expected) < 0.06), (a, name, found, expected)
            assert np.all(np.abs(found - expected) <= high - low), (a, name)
            assert np.all((low < found) & (found < high))
    assert analyzed.first_order.attrs["units"] == "1"
    assert int(analyzed.failed_evaluations.sum()) == 0
    # Statistics over A and B: the mean of y is a / 2 (sin^2 averages 1/2; the rest is odd).
    mean = analyzed.y.sel(statistic="mean", a=7.0)
    assert abs(float(mean) - 3.5) < 0.1


def test_failed_evaluations_make_an_outputs_indices_nan_and_are_counted(ishigami_model):
    data = bearing_sweep.run("""
[sweep]
model = "ishigami"
[sample]
n = 16
method = "saltelli"
x1 = { distribution = "uniform", low = 0, high = 1 }
x2 = { distribution = "uniform", low = 0, high = 1 }
x3 = { distribution = "uniform", low = 0, high = 1 }
""", workers=0, progress=False)
    data["y"][3] = np.nan
    analyzed = bearing_sweep.analyze(data)
    assert int(analyzed.failed_evaluations.sel(output="y")) == 1
    assert analyzed.first_order.isnull().all() and analyzed.total_order.isnull().all()
    assert analyzed.y.sel(statistic="mean").notnull()  # statistics leave the NaN out


def test_statistics_of_a_latin_hypercube_sample_through_the_cli(tmp_path, capsys):
    definition = tmp_path / "lhs.toml"
    definition.write_text(HEAD + """
[fixed]
speed = "5000 rpm"
[sample]
n = 20
method = "latin_hypercube"
radial_load = { distribution = "uniform", low = "1 kN", high = "8 kN" }
""")
    result = tmp_path / "lhs.nc"
    assert cli.main(["run", str(definition), "-o", str(result), "--workers", "0",
                     "--quiet"]) == 0
    assert cli.main(["analyze", str(result)]) == 0
    with xr.open_dataset(tmp_path / "lhs_analysis.nc") as analyzed, \
            xr.open_dataset(result) as data:
        assert "first_order" not in analyzed
        stiffness = data.radial_stiffness.values
        np.testing.assert_allclose(analyzed.radial_stiffness.sel(statistic="p50"),
                                   np.median(stiffness))
        np.testing.assert_allclose(analyzed.radial_stiffness.sel(statistic="std"),
                                   np.std(stiffness, ddof=1))
        assert analyzed.radial_stiffness.attrs["units"] == "N/mm"
        assert int(analyzed.valid_samples) == 20
    capsys.readouterr()
    assert cli.main(["analyze", str(result), "-o", str(result)]) == 2
    assert cli.main(["analyze", str(definition)]) == 2
    grid = tmp_path / "grid.nc"
    definition.write_text(HEAD + '[fixed]\nradial_load = "4 kN"\n')
    assert cli.main(["run", str(definition), "-o", str(grid), "--workers", "0", "--quiet"]) == 0
    capsys.readouterr()
    assert cli.main(["analyze", str(grid)]) == 2
    assert "not a sampled result" in capsys.readouterr().err


def test_the_schema_accepts_a_sample_table_and_refuses_an_unknown_distribution():
    import tomllib

    document = tomllib.loads(SALTELLI)
    validator = Draft7Validator(schema("crb_radial"))
    assert list(validator.iter_errors(document)) == []
    document["sample"]["radial_load"]["distribution"] = "lognormal"
    assert list(validator.iter_errors(document))


def test_the_figure_helpers_draw_indices_and_distributions(ishigami_model, tmp_path):
    from bearing_sweep.plotting import histogram, sobol_bars, subplots

    data = bearing_sweep.run("""
[sweep]
model = "ishigami"
[sample]
n = 32
method = "saltelli"
x1 = { distribution = "uniform", low = -3, high = 3 }
x2 = { distribution = "uniform", low = -3, high = 3 }
x3 = { distribution = "uniform", low = -3, high = 3 }
""", workers=0, progress=False)
    figure, (left, right) = subplots(1, 2)
    sobol_bars(left, bearing_sweep.analyze(data), "y")
    histogram(right, data, "x1")
    assert len(left.patches) == 6  # first-order and total bars of three inputs
    # A and B only: 8 replicates of 32 base samples each
    assert sum(p.get_height() for p in right.patches) == 2 * sample.SALTELLI_REPLICATES * 32


def test_a_pattern_no_count_sizes_draws_one_value_for_all_its_entries():
    # A raceway's harmonics have no count that sets their number; a broadcast pattern given
    # one value has one entry standing for all, so one drawn value per sample is that value.
    from bearing_sweep.spec import parse

    sweep = parse('[sweep]\nmodel = "crb_runout"\nbearing = "paper004-NU208-1"\n'
                  '[fixed]\ninner_roundness_order = 2\n'
                  '[sample]\nn = 8\nmethod = "random"\nseed = 3\n'
                  'inner_roundness_amplitude = { distribution = "uniform", low = "0 um", '
                  'high = "1 um" }\n')
    (axis,) = sweep.axes
    drawn = axis.si["inner_roundness_amplitude"]
    assert drawn.shape == (8, 1)
    assert ((drawn >= 0.0) & (drawn <= 1e-6)).all() and np.ptp(drawn) > 0.0
