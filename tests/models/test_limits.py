"""The limits of real bearings the models share: viscosity index, ISO 5753-1 clearances, speed
factor, the steel of the default contact constants, the densities of rolling elements."""
import numpy as np
import pytest

from bearing_sweep.models.limits import (beyond_speed_factor, clearance_beyond_bearings,
                                         largest_clearance, not_steel)
from bearing_sweep.models.lubrication import implausible_viscosity_index, viscosity_index

MM2 = 1e-6  # mm^2/s in m^2/s
RPM = 2 * np.pi / 60


@pytest.mark.parametrize("nu40, nu100, expected", [
    # ASTM D2270-10 (ISO 2909), its worked examples: procedure A (VI up to 100) and B (above).
    (73.30, 8.86, 92),
    (22.83, 5.05, 156),
])
def test_the_viscosity_index_of_the_standards_examples(nu40, nu100, expected):
    assert round(float(viscosity_index(nu40 * MM2, nu100 * MM2))) == expected


@pytest.mark.parametrize("nu100", [2.0, 4.2, 8.6, 14.9, 30.0, 70.0])
def test_an_oil_on_a_reference_line_has_its_index(nu100):
    # ASTM D2270 Table 1 at its rows: an oil whose viscosity at 40 deg C is L has VI 0, one
    # whose viscosity is H has VI 100 (the definition of the two reference series).
    table = {2.0: (7.994, 6.394), 4.2: (27.75, 21.21), 8.6: (113.9, 66.48),
             14.9: (293.0, 148.2), 30.0: (1023.0, 421.7), 70.0: (4905.0, 1558.0)}
    low, high = table[nu100]
    assert float(viscosity_index(low * MM2, nu100 * MM2)) == pytest.approx(0.0, abs=1e-9)
    assert float(viscosity_index(high * MM2, nu100 * MM2)) == pytest.approx(100.0, abs=1e-9)


def test_above_70_the_standards_formulas_hold():
    # ASTM D2270, 6.1: L = 0.8353 Y^2 + 14.67 Y - 216, H = 0.1684 Y^2 + 11.85 Y - 97 above 70.
    y = 100.0
    low, high = 0.8353 * y**2 + 14.67 * y - 216, 0.1684 * y**2 + 11.85 * y - 97
    assert float(viscosity_index(low * MM2, y * MM2)) == pytest.approx(0.0, abs=1e-9)
    assert float(viscosity_index(high * MM2, y * MM2)) == pytest.approx(100.0, abs=1e-9)


def test_viscosities_no_lubricant_has_are_implausible():
    nu40 = np.array([3520.0, 26.0, 68.0, 3520.0, 1.98, 3520.0, 2.2]) * MM2
    nu100 = np.array([3519.0, 5.4, 8.7, 2.0, 1.0, 1.0, 0.3]) * MM2
    # the reproduction (VI 811), a 4050 turbine oil (149), ISO VG 68 mineral oil (99), a
    # VG 3200 oil thinning to 2 mm^2/s (VI far below -100); below 2 mm^2/s, where ISO 2909
    # defines no index, a VG 2 oil of 1 mm^2/s at 100 deg C is one, a VG 3200 oil there or
    # a VG 2 oil thinning to 0.3 mm^2/s (7 times; water thins 2.2 times) none
    assert implausible_viscosity_index(nu40, nu100).tolist() == [True, False, False, True,
                                                                 False, True, True]
    assert np.isnan(viscosity_index(nu40, nu100)[4:]).all()


@pytest.mark.parametrize("bore, largest", [
    # ISO 5753-1:2009, cylindrical roller bearings with a cylindrical bore, group 5 upper
    # values: bore up to 24 mm 90 um, over 30 incl. 40 mm 105 um, over 40 incl. 50 mm 125 um,
    # over 900 incl. 1000 mm 1405 um.
    (10.0, 90.0), (24.0, 90.0), (40.0, 105.0), (40.5, 125.0), (49.481, 125.0),
    (1000.0, 1405.0), (2000.0, 2810.0),
])
def test_the_largest_clearance_is_iso_5753_group_5(bore, largest):
    assert float(largest_clearance(bore * 1e-3)) == pytest.approx(largest * 1e-6, rel=1e-12)


def test_a_clearance_beyond_every_group_is_beyond_bearings():
    inner = 49.481e-3  # NU208 (paper 004): 125 um at most
    assert clearance_beyond_bearings(np.array([0.077, 0.124, 0.126, 8.5]) * 1e-3,
                                     inner).tolist() == [False, False, True, True]
    assert not clearance_beyond_bearings(-0.01e-3, inner)  # a preload is not play
    assert not clearance_beyond_bearings(np.nan, inner)


def test_the_speed_factor_limit_is_n_dm():
    # 4e6 mm r/min: 61 538 r/min on a 65 mm pitch circle.
    speeds = np.array([10000.0, 61000.0, 62000.0, 1e300, np.nan]) * RPM
    assert beyond_speed_factor(speeds, 65e-3).tolist() == [False, False, True, True, False]


@pytest.mark.parametrize("modulus, poisson, far", [
    (207e9, 0.3, False), (206e9, 0.3, False), (207e9, 0.28, False), (190e9, 0.27, False),
    (215e9, 0.3, False),  # the bearing steels
    (310e9, 0.26, True),  # silicon nitride
    (1e3, 0.3, True),  # the reproduction: 1e-6 GPa
    (207e9, 0.5, True),
])
def test_steel_is_the_band_of_bearing_steels(modulus, poisson, far):
    assert bool(not_steel(modulus, poisson)) == far


def _own_models():
    from bearing_sweep.models.registry import get_model, own_entry_points

    return [get_model(name) for name in own_entry_points()]


def test_every_dimensionless_coefficient_has_a_valid_range():
    # A drag coefficient of 1e6 was accepted and gave 97.7 % cage slip: every coefficient of
    # every model declares both ends of its range (harmonic orders are counts, not
    # coefficients).
    for model in _own_models():
        for item in model.inputs:
            if item.kind == "quantity" and item.unit in ("1", ""):
                assert item.minimum is not None and item.maximum is not None, \
                    (model.name, item.name)


def test_every_model_that_takes_a_speed_states_its_limit():
    models = [m for m in _own_models() if any(i.name == "speed" for i in m.inputs)]
    assert len(models) == 7
    for model in models:
        assert "n dm above 4e6" in model.validity, model.name
