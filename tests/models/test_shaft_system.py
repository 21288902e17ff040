"""The shaft system model: a shaft on ball bearings and springs, checked against beam theory
in closed form, against statics, and against ball_5dof solving the same bearing alone."""
import numpy as np
import pytest

from bearing_sweep.models.ball import ball_5dof
from bearing_sweep.models.cylindrical import crb_radial
from bearing_sweep.models.profiles import crown_shape, slice_centres
from bearing_sweep.models.registry import CONVERGED, OUT_OF_VALIDITY, outcome
from bearing_sweep.models.shaft_bearings import RollerSupport
from bearing_sweep.definition.values import default_value
from bearing_sweep.models.shaft_mounting import SUPPORT_OPERATING_INPUTS
from bearing_sweep.models.shaft_system import assemble

#: The 71807AC of paper 001 (Table 1), in SI, with the paper's contact constant.
BEARING = {"ball_count": 25, "ball_diameter": 3.14e-3, "pitch_diameter": 41e-3,
           "contact_angle": np.radians(25.0), "inner_curvature_ratio": 0.52,
           "outer_curvature_ratio": 0.53, "clearance": 0.0, "youngs_modulus": 207e9,
           "poisson_ratio": 0.3, "contact_constant": 1.0649e10, "geometry": "jones",
           "pressure_limit": 4.2e9, "dynamic_load_rating": 4150.0}
LOAD = {"force_x": 0.0, "force_y": 0.0, "force_z": 0.0, "moment_y": 0.0, "moment_z": 0.0}
#: A bearing's fits and temperatures, at their defaults unless a test gives them: unmounted,
#: at 20 degC.
MOUNTING = {spec.name for spec in SUPPORT_OPERATING_INPUTS}


def solve(sections, supports, loads, **values):
    """The system's outputs at one point: ``supports`` and ``loads`` map names to their
    inputs (a support's with ``kind``), in SI."""
    model = assemble(sections, {name: s["kind"] for name, s in supports.items()}, list(loads))
    given = {"shaft_youngs_modulus": 210e9, "shaft_poisson_ratio": 0.3, "station_count": 21,
             "shaft_density": 7850.0, "gravity_x": 0.0, "gravity_y": 0.0, "gravity_z": 0.0,
             "speed": 0.0}
    given |= values
    for name, support in supports.items():
        given |= {f"supports_{name}_{key}": value for key, value in support.items()
                  if key != "kind"}
    for name, load in loads.items():
        given |= {f"loads_{name}_{key}": value for key, value in (LOAD | load).items()}
    given |= {spec.name: default_value(spec).si for spec in model.inputs
              if spec.name not in given and spec.name.split("_", 2)[-1] in MOUNTING}
    assert {i.name for i in model.inputs} == set(given)
    return {key: np.asarray(value)[0] for key, value in model.function(**given).items()}


def spring(position, radial, axial=0.0, tilt=0.0):
    return {"kind": "spring", "position": position, "radial_stiffness": radial,
            "axial_stiffness": axial, "tilt_stiffness": tilt}


def ball(position, direction="positive", **changed):
    return {"kind": "ball_5dof", "position": position, "axial_direction": direction,
            **BEARING, **changed}


def test_a_shaft_on_two_stiff_springs_bends_as_timoshenko_beam_theory_says():
    # Simply supported, a load P at mid-span L: the centre deflects
    # P L^3 / (48 E I) + P L / (4 kappa G A) (Roark's Formulas for Stress and Strain, 7th ed.,
    # Table 8.1 case 1e, and 8.10 for the shear term), plus each spring's P / (2 k).
    diameter, span, load, stiffness, E, nu = 0.04, 0.3, 5e3, 1e10, 210e9, 0.3
    result = solve([(0.4, diameter, 0.0)],
                   {"A": spring(0.05, stiffness, axial=1e8), "B": spring(0.35, stiffness)},
                   {"gear": {"position": 0.2, "force_y": load}}, station_count=9)
    area, inertia = np.pi * diameter**2 / 4, np.pi * diameter**4 / 64
    kappa, shear_modulus = 6 * (1 + nu) / (7 + 6 * nu), E / (2 * (1 + nu))
    expected = (load * span**3 / (48 * E * inertia) + load * span / (4 * kappa * shear_modulus
                                                                      * area)
                + load / (2 * stiffness))
    centre = list(np.linspace(0.0, 0.4, 9)).index(0.2)
    assert result["status"] == CONVERGED
    assert result["deflection"][centre, 0] == pytest.approx(expected, rel=1e-9)
    assert result["largest_deflection"] == pytest.approx(expected, rel=1e-9)  # symmetric
    assert result["slope"][centre, 0] == pytest.approx(0.0, abs=1e-12)
    assert result["support_load"][:, 1] == pytest.approx([load / 2, load / 2], rel=1e-9)


@pytest.mark.parametrize("case", range(3))
def test_what_the_supports_carry_balances_every_force_and_moment(case):
    generator = np.random.default_rng(case)
    loads = {f"load{i}": {"position": float(generator.uniform(0.0, 0.2)),
                          **dict(zip(LOAD, generator.uniform(-1, 1, 5) * [300, 2e3, 2e3, 20, 20]))}
             for i in range(2)}
    loads["load0"]["force_x"] = 400.0  # the bearing carries the thrust, one way
    result = solve([(0.12, 0.04, 0.0), (0.08, 0.035, 0.01)],
                   {"A": ball(0.02), "B": spring(0.18, 1e9, tilt=1e4)}, loads)
    assert outcome(result["status"]) == CONVERGED
    on_supports = result["support_load"]
    positions = np.array([0.02, 0.18])
    applied = np.array([[load[k] for k in LOAD] for load in loads.values()])
    at = np.array([load["position"] for load in loads.values()])
    assert on_supports[:, :3].sum(axis=0) == pytest.approx(applied[:, :3].sum(axis=0),
                                                           abs=1e-6)

    def moments(x, forces):  # about the shaft's left end: r x F with r along x, plus M
        return np.stack([-x * forces[:, 2] + forces[:, 3], x * forces[:, 1] + forces[:, 4]],
                        axis=-1).sum(axis=0)

    assert moments(positions, on_supports) == pytest.approx(moments(at, applied), abs=1e-6)


def test_a_bearing_on_the_shaft_is_the_bearing_ball_5dof_solves_under_the_same_loads():
    result = solve([(0.12, 0.04, 0.0), (0.08, 0.035, 0.01)],
                   {"A": ball(0.02), "B": spring(0.18, 1e9, axial=0.0)},
                   {"gear": {"position": 0.1, "force_x": 500.0, "force_y": 3e3,
                             "force_z": -1e3, "moment_y": 15.0}})
    assert outcome(result["status"]) == CONVERGED
    load = result["support_load"][0]
    alone = ball_5dof(**{k: v for k, v in BEARING.items() if k != "pressure_limit"},
                      axial_load=load[0], radial_load=load[1], radial_load_z=load[2],
                      moment_y=load[3], moment_z=load[4])
    assert result["support_displacement"][0] == pytest.approx(
        np.asarray(alone["displacement"]).ravel(), rel=1e-6, abs=1e-12)
    assert result["largest_contact_pressure"][0] == pytest.approx(
        np.ravel(alone["largest_contact_pressure"])[0], rel=1e-6)
    assert np.isnan(result["largest_contact_pressure"][1])  # a spring has no contacts
    assert result["reference_rating_life"][0] == pytest.approx(
        np.ravel(alone["reference_rating_life"])[0], rel=1e-6)
    assert np.isnan(result["reference_rating_life"][1])
    # the bearing's own stiffness at that equilibrium, a rotor-dynamics model's springs
    np.testing.assert_allclose(result["support_stiffness"][0],
                               np.asarray(alone["stiffness_matrix"]).reshape(5, 5),
                               rtol=1e-5, atol=1e-6 * np.abs(alone["stiffness_matrix"]).max())
    np.testing.assert_array_equal(result["support_stiffness"][1],
                                  np.diag([0.0, 1e9, 1e9, 0.0, 0.0]))


def test_a_bearing_mounted_on_the_shaft_has_the_clearance_ball_5dof_gives_it_mounted():
    # A 10 um shaft fit, the rings at 45 and 30 degC, the shaft hollow where the bearing
    # sits (its second section): ball_5dof with the same fits and the shaft's bore and
    # material gives the same operating clearance, and the same equilibrium.
    mounting = {"shaft_fit": 10e-6, "bore": 35e-3, "outside_diameter": 47e-3,
                "inner_ring_temperature": 318.15, "outer_ring_temperature": 303.15}
    result = solve([(0.02, 0.04, 0.0), (0.18, 0.035, 0.01)],
                   {"A": ball(0.1, clearance=-2e-6, **mounting),
                    "B": spring(0.19, 1e9, axial=0.0)},
                   {"gear": {"position": 0.15, "force_x": 500.0, "force_y": 2e3}},
                   speed=2 * np.pi * 6000 / 60)
    assert outcome(result["status"]) == CONVERGED
    load = result["support_load"][0]
    alone = ball_5dof(**{k: v for k, v in BEARING.items() if k != "pressure_limit"} | {
        "clearance": -2e-6}, **mounting, shaft_bore=0.01, shaft_youngs_modulus=210e9,
                      shaft_poisson_ratio=0.3, speed=2 * np.pi * 6000 / 60,
                      axial_load=load[0], radial_load=load[1], radial_load_z=load[2],
                      moment_y=load[3], moment_z=load[4])
    assert result["operating_clearance"][0] == pytest.approx(
        np.ravel(alone["operating_clearance"])[0], rel=1e-12)
    assert result["operating_clearance"][0] < -2e-6  # the fit and the warm inner ring
    assert result["support_displacement"][0] == pytest.approx(
        np.asarray(alone["displacement"]).ravel(), rel=1e-6, abs=1e-12)
    assert np.isnan(result["operating_clearance"][1])  # a spring has none


def test_an_unmounted_bearing_at_rest_and_20_degc_keeps_its_clearance_exactly():
    result = solve([(0.2, 0.04, 0.0)], {"A": ball(0.02, clearance=7e-6),
                                        "B": spring(0.18, 1e9, axial=1e8)},
                   {"gear": {"position": 0.1, "force_y": 1e3}})
    assert result["operating_clearance"][0] == 7e-6


def test_a_fit_lost_at_temperature_flags_the_point():
    # A light shaft fit, the shaft much warmer than the ring: the fit opens; the ring may
    # creep on its seat, so the point is out of validity, its values kept.
    result = solve([(0.2, 0.035, 0.0)],
                   {"A": ball(0.02, shaft_fit=2e-6, bore=35e-3, shaft_temperature=293.15,
                              inner_ring_temperature=353.15),
                    "B": spring(0.18, 1e9, axial=1e8)},
                   {"gear": {"position": 0.1, "force_y": 1e3}})
    assert result["status"] & OUT_OF_VALIDITY and np.isfinite(result["support_load"]).all()


def test_the_system_s_life_is_the_weibull_combination_of_its_bearings_lives():
    # A pair of bearings sharing a load: the system survives while both do,
    # L = (L_A^-e + L_B^-e)^(-1/e), e = 10/9 for ball bearings (Lundberg and Palmgren;
    # Harris and Kotzalas, Rolling Bearing Analysis, 5th ed., ch. 11), here by hand.
    result = solve([(0.2, 0.04, 0.0)], {"A": ball(0.03), "B": ball(0.17)},
                   {"gear": {"position": 0.08, "force_x": 400.0, "force_y": 1500.0}})
    assert outcome(result["status"]) == CONVERGED
    first, second = result["reference_rating_life"]
    e = 10 / 9
    assert result["system_reference_life"] == pytest.approx(
        (first**-e + second**-e) ** (-1 / e), rel=1e-12)
    assert result["system_reference_life"] < min(first, second)


def test_a_bearing_carries_thrust_one_way_as_mounted():
    shaft = [(0.2, 0.04, 0.0)]
    loads = {"gear": {"position": 0.1, "force_x": -500.0, "force_y": 2e3}}
    against = solve(shaft, {"A": ball(0.02), "B": spring(0.18, 1e9)}, loads)
    mounted = solve(shaft, {"A": ball(0.02, "negative"), "B": spring(0.18, 1e9)}, loads)
    # Nothing else holds the shaft axially: the bearing mounted against the thrust carries it
    # on the side of its grooves an angular contact ring cuts away, as ball_5dof does, and
    # the point is flagged outside validity.
    assert against["status"] == CONVERGED | OUT_OF_VALIDITY
    assert mounted["status"] == CONVERGED
    assert mounted["support_load"][0, 0] == pytest.approx(-500.0, rel=1e-9)


def test_a_bearing_past_its_validity_flags_the_point_and_keeps_its_values():
    result = solve([(0.2, 0.04, 0.0)], {"A": ball(0.02), "B": spring(0.18, 1e9)},
                   {"gear": {"position": 0.1, "force_x": 3e5}})
    assert result["status"] == CONVERGED | OUT_OF_VALIDITY
    assert result["largest_contact_pressure"][0] > 4.2e9  # [Pa], the limit given
    assert np.isfinite(result["support_load"]).all()


def test_a_system_with_no_support_or_no_section_is_refused():
    with pytest.raises(ValueError, match="at least one section and one support"):
        assemble([], {"A": "spring"}, [])
    with pytest.raises(ValueError, match="at least one section and one support"):
        assemble([(0.1, 0.02, 0.0)], {}, [])


def test_a_shaft_under_its_own_weight_bends_as_timoshenko_beam_theory_says():
    # Simply supported, a uniform load q = rho A g over the span L: the middle deflects
    # 5 q L^4 / (384 E I) + q L^2 / (8 kappa G A) (Roark's Formulas for Stress and Strain,
    # 7th ed., Table 8.1 case 2e, and 8.10 for the shear term), plus each spring's q L / (2 k);
    # each support carries half the weight. The shaft ends at the supports.
    diameter, span, density, gravity, stiffness, E, nu = 0.05, 1.2, 7850.0, -9.81, 1e11, \
        210e9, 0.3
    result = solve([(span, diameter, 0.0)],
                   {"A": spring(0.0, stiffness, axial=1e8), "B": spring(span, stiffness)},
                   {}, station_count=11, shaft_density=density, gravity_y=gravity)
    area, inertia = np.pi * diameter**2 / 4, np.pi * diameter**4 / 64
    kappa, shear_modulus = 6 * (1 + nu) / (7 + 6 * nu), E / (2 * (1 + nu))
    per_length = density * area * gravity
    expected = (5 * per_length * span**4 / (384 * E * inertia)
                + per_length * span**2 / (8 * kappa * shear_modulus * area)
                + per_length * span / (2 * stiffness))
    assert result["status"] == CONVERGED
    assert result["deflection"][5, 0] == pytest.approx(expected, rel=1e-9)
    assert result["support_load"][:, 1] == pytest.approx([per_length * span / 2] * 2,
                                                         rel=1e-9)
    assert result["deflection"][:, 1] == pytest.approx(0.0, abs=1e-18)  # nothing along z


def test_an_overhung_load_s_reactions_are_those_of_statics():
    # Supports at 0 and L, a load P at L + a beyond the second: R_A = -P a / L and
    # R_B = P (L + a) / L (Roark's Formulas for Stress and Strain, 7th ed., Table 8.1 case
    # 1a with the load outside the span), whatever the supports' stiffness.
    span, overhang, load = 0.3, 0.1, 2e3
    result = solve([(span + overhang, 0.04, 0.0)],
                   {"A": spring(0.0, 1e8, axial=1e8), "B": spring(span, 3e8)},
                   {"nose": {"position": span + overhang, "force_z": load}})
    assert result["support_load"][:, 2] == pytest.approx(
        [-load * overhang / span, load * (span + overhang) / span], rel=1e-9)


def test_a_two_span_shaft_on_three_stiff_supports_shares_a_mid_span_load_as_beam_theory():
    # Two equal spans, a load P at the middle of the first: the supports carry 13/32, 11/16
    # and -3/32 of P (Roark, Table 8.2 continuous beams; the three-moment equation). The
    # shaft is slender (span 2 m, 20 mm) so that shear, which the Euler-Bernoulli values leave
    # out, moves them by about (d/L)^2 = 1e-4 of P, and the springs are 1e8 times stiffer than
    # the shaft's bending.
    span, load = 2.0, 100.0
    supports = {"A": spring(0.0, 1e12, axial=1e6), "B": spring(span, 1e12),
                "C": spring(2 * span, 1e12)}
    result = solve([(2 * span, 0.02, 0.0)], supports,
                   {"mid": {"position": span / 2, "force_y": load}})
    assert result["support_load"][:, 1] == pytest.approx(
        [13 / 32 * load, 11 / 16 * load, -3 / 32 * load], abs=2e-4 * load)


def test_the_stiffness_at_a_load_is_the_derivative_of_the_equilibrium():
    # Central differences of the displacement under the load (its position at bearing A, so
    # that all five displacements there are outputs) against the inverse of the stiffness.
    shaft = [(0.12, 0.04, 0.0), (0.08, 0.035, 0.01)]
    supports = {"A": ball(0.05), "B": spring(0.18, 1e9, tilt=1e4)}
    applied = {"force_x": 600.0, "force_y": 2e3, "force_z": -800.0, "moment_y": 6.0,
               "moment_z": -4.0}

    def displacement(**change):
        loads = {"gear": {"position": 0.05, **{k: v + change.get(k, 0.0)
                                               for k, v in applied.items()}}}
        return solve(shaft, supports, loads)

    result = displacement()
    assert result["status"] == CONVERGED
    steps = {"force_x": 1.0, "force_y": 1.0, "force_z": 1.0, "moment_y": 0.01,
             "moment_z": 0.01}
    compliance = np.empty((5, 5))
    for column, (name, step) in enumerate(steps.items()):
        up = displacement(**{name: step})["support_displacement"][0]
        down = displacement(**{name: -step})["support_displacement"][0]
        compliance[:, column] = (up - down) / (2 * step)
    stiffness = result["stiffness_at_load"][0]
    assert np.linalg.inv(compliance) == pytest.approx(stiffness, rel=1e-4,
                                                      abs=1e-6 * np.abs(stiffness).max())
    assert stiffness == pytest.approx(stiffness.T, rel=1e-9, abs=1e-9 * np.abs(stiffness).max())


#: A cylindrical roller bearing in SI, as crb_radial takes it: 14 crowned rollers.
ROLLERS = {"roller_count": 14, "pitch_diameter": 65e-3, "roller_diameter": 10e-3,
           "effective_length": 9.6e-3, "clearance": 10e-6, "crown": 4e-6,
           "crown_profile": "logarithmic", "slices": 60, "slice_law": "uniform",
           "outer_contact": "crowned", "roller_density": 7850.0,
           "contact_constant": None, "youngs_modulus": 207e9, "poisson_ratio": 0.3,
           "pressure_limit": 4.0e9, "dynamic_load_rating": 48e3}


@pytest.mark.parametrize("speed", [0.0, 2 * np.pi * 12000 / 60])
def test_a_roller_bearing_on_the_shaft_is_the_one_crb_radial_solves_under_its_load(speed):
    # Loads in one plane: the shaft moves along y and tilts about z at the roller bearing,
    # which is crb_radial's bearing under its load with that misalignment. Spinning, the
    # rollers' centrifugal force loads the outer contacts more than the inner.
    rollers = ROLLERS
    result = solve([(0.3, 0.045, 0.0)],
                   {"front": ball(0.03), "rear": {"kind": "crb_radial", "position": 0.27,
                                                  **rollers}},
                   {"gear": {"position": 0.2, "force_x": 300.0, "force_y": 4e3}}, speed=speed)
    assert outcome(result["status"]) == CONVERGED
    on_rear, moved = result["support_load"][1], result["support_displacement"][1]
    assert moved[[2, 3]] == pytest.approx(0.0, abs=1e-15)  # in the plane
    assert on_rear[[0, 2, 3]] == pytest.approx(0.0, abs=1e-9)  # no thrust, nothing across
    assert abs(on_rear[4]) > 1e-3 * on_rear[1] * ROLLERS["effective_length"]  # a moment
    alone = crb_radial(radial_load=abs(on_rear[1]), speed=speed,
                       misalignment=moved[4] * np.sign(moved[1]), **{
                           k: v for k, v in rollers.items() if k != "pressure_limit"})
    assert np.ravel(alone["status"])[0] == CONVERGED
    assert abs(moved[1]) == pytest.approx(np.ravel(alone["radial_displacement"])[0], rel=1e-7)
    assert result["largest_contact_pressure"][1] == pytest.approx(
        np.ravel(alone["largest_contact_pressure"])[0], rel=1e-6)
    assert result["reference_rating_life"][1] == pytest.approx(
        np.ravel(alone["reference_rating_life"])[0], rel=1e-6)
    # a ball and a roller bearing: sum (L / L_i)^e_i = 1 with their own slopes
    lives, slopes = result["reference_rating_life"], np.array([10 / 9, 9 / 8])
    assert np.sum((result["system_reference_life"] / lives) ** slopes) == pytest.approx(
        1.0, rel=1e-12)


@pytest.mark.parametrize("speed", [0.0, 2 * np.pi * 12000 / 60])
def test_an_aligned_roller_bearing_is_crb_radials_law_along_the_displacement(speed):
    # Its stiffness: crb_radial's along the displacement, the secant F / delta across it.
    support = RollerSupport(speed=speed, **ROLLER_SUPPORT)
    moved = np.array([0.0, 12e-6, -7e-6, 0.0, 0.0])
    load, stiffness = (value[0] for value in support.loads(moved))
    delta = np.hypot(moved[1], moved[2])
    alone = crb_radial(radial_load=np.hypot(load[1], load[2]), speed=speed, **{
        k: v for k, v in ROLLERS.items() if k != "pressure_limit"})
    assert delta == pytest.approx(np.ravel(alone["radial_displacement"])[0], rel=1e-7)
    assert load[[0, 3, 4]] == pytest.approx(0.0, abs=1e-12 * load[1:3].max() * 0.01)
    # aligned, it resists a tilt all the same: as the tilt's central difference has it
    step = 1e-7
    tilted = [support.loads(moved + sign * step * np.eye(5)[4])[0][0] for sign in (1, -1)]
    assert stiffness[:, 4] == pytest.approx((tilted[0] - tilted[1]) / (2 * step), rel=1e-5,
                                            abs=1e-6 * np.abs(stiffness).max())
    assert stiffness[4, 4] > 0.0
    along = moved[1:3] / delta
    normal = np.array([-along[1], along[0]])
    assert load[1:3] @ normal == pytest.approx(0.0, abs=1e-12 * np.abs(load).max())
    plane = stiffness[1:3, 1:3]
    assert along @ plane @ along == pytest.approx(np.ravel(alone["radial_stiffness"])[0],
                                                  rel=1e-6)
    assert normal @ plane @ normal == pytest.approx(load[1:3] @ along / delta, rel=1e-9)
    assert along @ plane @ normal == pytest.approx(0.0, abs=1e-9 * np.abs(plane).max())


#: RollerSupport's inputs: ROLLERS without what only crb_radial takes.
ROLLER_SUPPORT = {k: v for k, v in ROLLERS.items() if k != "dynamic_load_rating"}


@pytest.mark.parametrize("speed", [0.0, 2 * np.pi * 12000 / 60])
@pytest.mark.parametrize("moved", [[0.0, 12e-6, 5e-6, 2e-4, -3e-4],
                                   [0.0, -3e-6, 9e-6, -1e-3, 4e-4],
                                   [0.0, 0.0, 0.0, 5e-4, 5e-4]])
def test_a_tilted_roller_bearing_s_stiffness_is_the_derivative_of_its_loads(speed, moved):
    # Central differences of the loads; the last displacement is centred, where the rollers
    # stay where they are. A ring tilted in a bearing with clearance may touch no roller.
    support = RollerSupport(speed=speed, **(ROLLER_SUPPORT | {"clearance": -5e-6}))
    moved = np.array(moved)
    load, stiffness = (value[0] for value in support.loads(moved))
    assert np.all(np.isfinite(load)) and np.abs(load[3:]).max() > 0.0
    steps = [0.0, 1e-9, 1e-9, 1e-7, 1e-7]
    difference = np.zeros((5, 5))
    for column in range(1, 5):
        step = np.eye(5)[column] * steps[column]
        if moved[1] == moved[2] == 0.0 and column in (1, 2):
            continue  # the rollers turn with a displacement from the centre
        difference[:, column] = (support.loads(moved + step)[0][0]
                                 - support.loads(moved - step)[0][0]) / (2 * steps[column])
    checked = [0, 3, 4] if moved[1] == moved[2] == 0.0 else range(5)
    assert stiffness[:, checked] == pytest.approx(difference[:, checked], rel=1e-5,
                                                  abs=1e-6 * np.abs(stiffness).max())


def test_a_tilted_roller_bearing_at_rest_carries_what_its_slices_carry_in_closed_form():
    # At rest both contacts of a roller are alike and share the total approach at each slice
    # equally: p_k = (t_j + m_j x_k) / 2 - crown_k, with t_j the ring's radial approach at the
    # roller's middle and m_j its tilt across the roller. Each contact carries
    # q_k = (K / k) p_k^(10/9) (paper 000, eq. 9 with the uniform law), the ring the sum.
    constant, length, crown, slices = 2.0e9, ROLLERS["effective_length"], 6e-6, 40
    support = RollerSupport(**(ROLLER_SUPPORT | {"contact_constant": constant, "crown": crown,
                                                 "slices": slices, "clearance": 4e-6}))
    moved = np.array([0.0, 9e-6, -4e-6, 3e-4, 6e-4])
    load = support.loads(moved)[0][0]
    psi = np.arctan2(moved[2], moved[1]) + 2 * np.pi * np.arange(14) / 14
    total = moved[1] * np.cos(psi) + moved[2] * np.sin(psi) - 2e-6
    tilt = moved[4] * np.cos(psi) - moved[3] * np.sin(psi)
    x = slice_centres(slices) * length / 2
    depth = np.maximum((total[:, None] + tilt[:, None] * x) / 2
                       - crown * crown_shape(slices, "logarithmic"), 0.0)
    slice_load = constant / slices * depth ** (10 / 9)
    roller, moment = slice_load.sum(axis=1), (slice_load * x).sum(axis=1)
    expected = [0.0, roller @ np.cos(psi), roller @ np.sin(psi), -moment @ np.sin(psi),
                moment @ np.cos(psi)]
    assert load == pytest.approx(expected, rel=1e-9, abs=1e-9 * np.abs(expected).max())


@pytest.mark.parametrize("speed_rpm, force", [(20000, 200.0), (35000, 200.0), (35000, 4e3)])
def test_a_roller_bearing_whose_rollers_fly_out_at_speed_still_finds_its_load(speed_rpm,
                                                                               force):
    # At speed the rollers' centrifugal force holds them on the outer ring: the inner ring
    # moves through a wider play before it carries anything, and at the start of Newton's
    # iteration the bearing may give the shaft no stiffness at all.
    speed = 2 * np.pi * speed_rpm / 60
    result = solve([(0.2, 0.035, 0.0)],
                   {"A": {"kind": "crb_radial", "position": 0.02, **ROLLERS},
                    "B": spring(0.18, 1e9, axial=1e8)},
                   {"gear": {"position": 0.1, "force_y": force}}, speed=speed)
    assert outcome(result["status"]) == CONVERGED
    on_a, on_b = result["support_load"][:, 1]
    moment = result["support_load"][0][4]
    assert on_a + on_b == pytest.approx(force, rel=1e-9)  # statics, B at 180 mm, free to tilt
    assert on_a * 0.16 - moment == pytest.approx(force * 0.08, rel=1e-9)  # about B
    moved = result["support_displacement"][0]
    alone = crb_radial(radial_load=abs(on_a), speed=speed,
                       misalignment=moved[4] * np.sign(moved[1]), **{
                           k: v for k, v in ROLLERS.items() if k != "pressure_limit"})
    assert abs(moved[1]) == pytest.approx(np.ravel(alone["radial_displacement"])[0], rel=1e-7)
