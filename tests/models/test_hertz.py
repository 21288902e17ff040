"""Hertz point contact: closed forms, the classical coefficient table, the approximation."""
import numpy as np
import pytest

from bearing_sweep.models.contact import _curvature_difference, ellipse_parameters, hertz_point
from bearing_sweep.models.registry import CONVERGED, OUT_OF_VALIDITY
from bearing_sweep import spec
from bearing_sweep.spec import SpecError

STEEL = dict(youngs_modulus=207e9, poisson_ratio=0.3)


def reduced_modulus(e=207e9, nu=0.3):
    return 1.0 / (2 * (1 - nu**2) / e)


def test_sphere_on_flat_is_the_classical_circle():
    # Hertz (1881), e.g. Johnson, Contact Mechanics, eq. 4.22-4.24: a = (3QR/(4E*))^(1/3),
    # delta = a^2/R, p0 = 3Q/(2 pi a^2).
    radius, load = 0.01, 250.0
    result = hertz_point(load, 1 / radius, 1 / radius, **STEEL)
    a = (3 * load * radius / (4 * reduced_modulus())) ** (1 / 3)
    assert result["semi_major"] == pytest.approx(a, rel=1e-12)
    assert result["semi_minor"] == pytest.approx(a, rel=1e-12)
    assert result["approach"] == pytest.approx(a**2 / radius, rel=1e-12)
    assert result["max_pressure"] == pytest.approx(3 * load / (2 * np.pi * a**2), rel=1e-12)
    assert result["ellipticity"] == 1.0


def test_crossed_cylinders_touch_like_a_sphere_on_a_flat():
    # Two equal cylinders crossed at right angles have the relative curvature of a sphere of the
    # same radius on a flat: a circular contact.
    radius = 0.005
    crossed = hertz_point(80.0, 1 / radius, 0.0, 0.0, 1 / radius, **STEEL)
    sphere = hertz_point(80.0, 1 / radius, 1 / radius, **STEEL)
    for name in ("semi_major", "semi_minor", "approach", "max_pressure"):
        assert crossed[name] == pytest.approx(sphere[name], rel=1e-12)


# Tabelle A.2, "Koeffizienten zur Hertz'schen Theorie", after E. Braendlein et al., Die
# Waelzlagerpraxis, 3rd ed. (1998): the coefficients xi, eta, psi/xi of a, b and delta against
# cos tau = F(rho), i.e. Harris' a*, b*, delta*. Three significant figures.
TABLE = [
    (0.000, 1.00, 1.000, 1.000), (0.100, 1.07, 0.938, 0.997), (0.300, 1.24, 0.824, 0.979),
    (0.500, 1.48, 0.718, 0.938), (0.700, 1.91, 0.607, 0.859), (0.800, 2.30, 0.544, 0.792),
    (0.850, 2.60, 0.507, 0.745), (0.900, 3.09, 0.461, 0.680), (0.920, 3.40, 0.438, 0.646),
    (0.940, 3.83, 0.412, 0.603), (0.950, 4.12, 0.396, 0.577), (0.960, 4.51, 0.378, 0.546),
    (0.970, 5.05, 0.357, 0.509), (0.980, 5.94, 0.328, 0.459), (0.990, 7.76, 0.287, 0.384),
    (0.995, 10.15, 0.251, 0.320), (0.999, 18.53, 0.185, 0.207),
]


@pytest.mark.parametrize("difference, a_star, b_star, delta_star", TABLE)
def test_dimensionless_coefficients_match_the_classical_table(difference, a_star, b_star,
                                                              delta_star):
    # a* = (2 k^2 E / pi)^(1/3), b* = (2E / (pi k))^(1/3), delta* = (2K/pi)(pi/(2 k^2 E))^(1/3)
    # (Harris, ch. 6). Tolerance 0.6 %: the table's three figures.
    k, second, first, converged = ellipse_parameters(np.array([difference]))
    assert converged.all()
    assert (2 * k**2 * second / np.pi) ** (1 / 3) == pytest.approx(a_star, rel=6e-3)
    assert (2 * second / (np.pi * k)) ** (1 / 3) == pytest.approx(b_star, rel=6e-3)
    assert (2 * first / np.pi * (np.pi / (2 * k**2 * second)) ** (1 / 3) ==
            pytest.approx(delta_star, rel=6e-3))


def test_the_solved_ellipticity_satisfies_the_defining_equation():
    # F(rho) = [(k^2 + 1) E(e) - 2 K(e)] / [(k^2 - 1) E(e)], e^2 = 1 - 1/k^2 (Harris eq. 6.28),
    # evaluated here in k with scipy directly.
    from scipy.special import ellipe, ellipk

    difference = np.linspace(0.001, 0.9999, 200)
    k, _, _, converged = ellipse_parameters(difference)
    m = 1 - 1 / k**2
    recovered = ((k**2 + 1) * ellipe(m) - 2 * ellipk(m)) / ((k**2 - 1) * ellipe(m))
    assert converged.all()
    np.testing.assert_allclose(recovered, difference, rtol=1e-9)


def test_curvature_difference_slope_is_its_derivative():
    m = np.array([2e-5, 5e-4, 0.1, 0.5, 0.9, 0.99, 0.9999])
    step = 1e-4 * np.minimum(m, 1 - m)
    plus, _ = _curvature_difference(m + step)
    minus, _ = _curvature_difference(m - step)
    _, slope = _curvature_difference(m)
    np.testing.assert_allclose(slope, (plus - minus) / (2 * step), rtol=1e-5)
    # The series below the switch and the closed form above it meet.
    below, _ = _curvature_difference(np.array([1e-4 * (1 - 1e-12)]))
    above, _ = _curvature_difference(np.array([1e-4 * (1 + 1e-12)]))
    assert below[0] == pytest.approx(above[0], rel=1e-7)


def test_hamrock_brewe_closed_forms_stay_near_the_exact_solution():
    # Over the radius ratios Ry/Rx = 1..100 that Hamrock and Brewe fitted, the closed forms are
    # within 2.7 % (a), 1.2 % (b), 4.1 % (delta), 1.6 % (p0) of the exact solution here; the
    # bound asserted is 5 %, and the circle (ratio 1) is exact.
    ratio = np.logspace(0, 2, 300)
    exact = hertz_point(100.0, ratio, 1.0, **STEEL)
    approximate = hertz_point(100.0, ratio, 1.0, formula="hamrock_brewe", **STEEL)
    for name in ("semi_major", "semi_minor", "approach", "max_pressure"):
        error = np.abs(approximate[name] / exact[name] - 1)
        assert error.max() < 0.05, name
        assert error[0] < 1e-12, name
    # Orientation does not matter: swapping x and y gives the same ellipse.
    swapped = hertz_point(100.0, 1.0, ratio, **STEEL)
    np.testing.assert_allclose(swapped["semi_major"], exact["semi_major"], rtol=1e-12)


def test_hamrock_brewe_beyond_its_accuracy_is_out_of_validity():
    # Up to Ry/Rx = 70 every output lies within 3 % of the exact ellipse and the point is
    # within validity; beyond, the approach errs by more (4.1 % at 100, 12.7 % at 1000) and
    # the point is flagged, its values kept. The exact formula is not judged by the ratio.
    ratio = np.concatenate([np.linspace(1.0, 69.99, 200), [70.01, 100.0, 1000.0]])
    exact = hertz_point(1.0, ratio, 1.0, **STEEL)  # a small contact even on R = 1 mm
    approximate = hertz_point(1.0, ratio, 1.0, formula="hamrock_brewe", **STEEL)
    error = np.max([np.abs(approximate[name] / exact[name] - 1) for name in (
        "semi_major", "semi_minor", "approach", "max_pressure")], axis=0)
    inside = ratio <= 70.0
    assert error[inside].max() < 0.03 and error[-2:].min() > 0.04
    assert (exact["status"] == CONVERGED).all()
    np.testing.assert_array_equal(approximate["status"],
                                  np.where(inside, CONVERGED, OUT_OF_VALIDITY))
    assert np.isfinite(approximate["approach"]).all()
    swapped = hertz_point(1.0, 1.0, ratio, formula="hamrock_brewe", **STEEL)
    np.testing.assert_array_equal(swapped["status"], approximate["status"])


def test_approach_follows_the_load_to_the_power_two_thirds():
    loads = np.array([10.0, 100.0, 1000.0])
    # A 8 mm ball in a 4.2 mm groove of a 40 mm inner raceway.
    result = hertz_point(loads, 1 / 0.004, 1 / 0.004, 1 / 0.02, -1 / 0.0042, **STEEL)
    np.testing.assert_allclose(result["approach"], (loads / result["contact_constant"]) ** (2 / 3))
    np.testing.assert_allclose(result["approach"] / result["approach"][0], (loads / 10) ** (2 / 3))
    assert np.all(result["status"] == 0)


def test_a_second_material_softens_the_contact():
    steel = hertz_point(100.0, 200.0, 200.0, **STEEL)
    ceramic_on_steel = hertz_point(100.0, 200.0, 200.0, youngs_modulus_2=310e9,
                                   poisson_ratio_2=0.26, **STEEL)
    assert ceramic_on_steel["approach"] < steel["approach"]
    assert ceramic_on_steel["max_pressure"] > steel["max_pressure"]


def test_bodies_that_do_not_touch_at_a_point_are_flagged_infeasible():
    result = hertz_point(np.array([100.0, 100.0]), 250.0, 250.0, 0.0, np.array([-100.0, -300.0]))
    assert result["status"].tolist() == [0, 2]
    assert np.isnan(result["approach"][1]) and np.isfinite(result["approach"][0])


def test_a_line_contact_is_refused_before_computing():
    text = ('[sweep]\nmodel = "hertz_point"\n[fixed]\nload = "100 N"\n'
            'curvature_1x = "0.2 1/mm"\ncurvature_1y = "0 1/mm"\n')
    with pytest.raises(SpecError, match="the bodies must touch at a point"):
        spec.parse(text)
    ball_in_groove = text.replace('"0 1/mm"', '"0.2 1/mm"') + 'curvature_2y = "-0.19 1/mm"\n'
    assert spec.parse(ball_in_groove).fixed["curvature_2y"].si == pytest.approx(-190.0)


def _steel_star():
    return 207e9 / (2 * (1 - 0.3**2))


@pytest.mark.parametrize("pressure, status", [(4100e6, 0), (4300e6, 4)])
def test_a_pressure_beyond_iso_76s_4200_mpa_is_out_of_validity(pressure, status):
    # Sphere (R = 10 mm) on a flat, Johnson eq. 4.24: p0 = (6 Q E*^2 / (pi^3 R^2))^(1/3),
    # so Q = p0^3 pi^3 R^2 / (6 E*^2). Here a/R = pi p0 / (2 E*) < 0.06: only the pressure
    # limit (ISO 76: 4200 MPa for ball bearings) decides.
    radius = 0.01
    load = pressure**3 * np.pi**3 * radius**2 / (6 * _steel_star() ** 2)
    result = hertz_point(load, 1 / radius, 1 / radius, **STEEL)
    assert result["max_pressure"] == pytest.approx(pressure, rel=1e-9)
    assert result["status"] == status
    assert np.isfinite(result["semi_major"])  # the values are kept


@pytest.mark.parametrize("ratio, status", [(0.45, 0), (0.55, 4)])
def test_a_contact_large_against_the_radius_is_out_of_validity(ratio, status):
    # A soft sphere (E = 1 GPa) on a flat: a = (3 Q R / (4 E*))^(1/3) (Johnson eq. 4.22), so
    # Q = 4 E* a^3 / (3 R); the pressure stays far below 4200 MPa and a/R decides (limit 0.5).
    radius, soft = 0.01, dict(youngs_modulus=1e9, poisson_ratio=0.3)
    star = 1e9 / (2 * (1 - 0.3**2))
    load = 4 * star * (ratio * radius) ** 3 / (3 * radius)
    result = hertz_point(load, 1 / radius, 1 / radius, **soft)
    assert result["semi_major"] == pytest.approx(ratio * radius, rel=1e-9)
    assert result["status"] == status


def test_an_absurd_load_is_out_of_validity_with_its_values_kept():
    # Issue 11: 1e9 N gave a semi-axis of metres and hundreds of GPa, "converged".
    result = hertz_point(np.array([100.0, 1e9]), 1 / 0.004, 1 / 0.004, 1 / 0.02, -1 / 0.0042,
                         **STEEL)
    assert result["status"].tolist() == [0, 4]
    assert result["max_pressure"][1] > 1e11 and np.isfinite(result["approach"][1])


def test_a_nan_load_fails_the_point():
    result = hertz_point(np.array([100.0, np.nan]), 250.0, 250.0, **STEEL)
    assert result["status"].tolist() == [0, 1]


def test_the_formula_choice_is_selectable_in_a_dataset():
    # The input was called `method`, which xarray's .sel() takes as its own keyword: a
    # dimension of that name could not be selected by label.
    import xarray as xr

    from bearing_sweep.models.registry import get_model

    choice = next(i for i in get_model("hertz_point").inputs if i.kind == "choice")
    data = xr.DataArray([1.0, 2.0], dims=choice.name, coords={choice.name: list(choice.choices)})
    assert float(data.sel({choice.name: "hamrock_brewe"})) == 2.0
    assert float(data.sel(**{choice.name: "hamrock_brewe"})) == 2.0
