"""crb_runout: perfect bearings, odd orders, size errors, and a direct search to check it."""
import numpy as np
import pytest
from scipy.optimize import minimize

from bearing_sweep.models.registry import CONVERGED, NOT_CONVERGED, OUT_OF_VALIDITY
from bearing_sweep.models.runout import crb_runout, roller_angles

MM, UM = 1e-3, 1e-6
#: NU208 number 1 of paper 004, Table 1 (the smaller roller diameter of its range).
NU208 = dict(inner_raceway_diameter=49.481 * MM, outer_raceway_diameter=71.555 * MM,
             roller_diameter=10.998 * MM, roller_count=14)
CLEARANCE = (71.555 - 49.481) / 2 * MM - 10.998 * MM  # radial, 39 um


def test_a_perfect_bearing_has_no_runout_and_the_classical_roller_passage():
    # Without errors the inner ring rests on two rollers, at a vertex of the regular polygon
    # the rollers bound: always g / cos(pi/Z) from the outer ring's centre, so the centre
    # distance never changes; its height swings between g and g / cos(pi/Z) as the rollers
    # pass under it (the roller-passage runout of a dial gauge on top).
    result = crb_runout(**NU208, steps_per_revolution=3600)
    assert result["status"][0] == CONVERGED
    assert result["runout"][0] < 1e-9 * UM
    distance = np.hypot(result["center_x"], result["center_y"])
    assert distance == pytest.approx(CLEARANCE / np.cos(np.pi / 14), rel=1e-12)
    assert result["vertical_runout"][0] == pytest.approx(
        CLEARANCE * (1 / np.cos(np.pi / 14) - 1), rel=5e-3)  # steps miss the exact top
    tight = crb_runout(**{**NU208, "outer_raceway_diameter": (49.481 + 2 * 10.998) * MM})
    assert np.abs(tight["center_y"]).max() < 1e-9 * UM


@pytest.mark.parametrize("roller_count", [12, 13, 16])
def test_no_runout_either_when_a_roller_passes_right_under_the_ring(roller_count):
    # With Z a multiple of 4 a roller sits exactly at the bottom at the start: the ring rests
    # at an end of that roller's flat, not in the middle of it.
    result = crb_runout(**{**NU208, "roller_count": roller_count}, steps_per_revolution=720)
    assert result["runout"][0] < 1e-9 * UM


def test_odd_roller_orders_leave_the_runout_unchanged():
    # An odd harmonic adds to the roller's radius on one side what it takes on the other.
    errors = np.linspace(0.0, 1.3, 14) * UM
    base = crb_runout(**NU208, roller_diameter_error=errors)["runout"][0]
    for order in (3, 5, 7, 15):
        result = crb_runout(**NU208, roller_diameter_error=errors,
                            roller_roundness_order=order, roller_roundness_amplitude=1 * UM,
                            roller_roundness_phase=np.linspace(0, 3, 14))
        assert result["runout"][0] == pytest.approx(base, abs=1e-9 * UM)
    even = crb_runout(**NU208, roller_diameter_error=errors, roller_roundness_order=4,
                      roller_roundness_amplitude=1 * UM)["runout"][0]
    assert even > base + 0.1 * UM


def test_runout_grows_in_proportion_to_a_single_rollers_size_error():
    # For small errors the runout is proportional to the error; the slope falls slowly as the
    # span of cage angles in which the large roller carries the ring widens with it.
    ratios = []
    for error in (0.05, 0.1, 0.2):
        errors = np.zeros(14)
        errors[0] = error * UM
        ratios.append(crb_runout(**NU208, roller_diameter_error=errors)["runout"][0]
                      / (error * UM))
    assert max(ratios) / min(ratios) < 1.02
    assert 0.45 < ratios[0] < 0.55


def _direct_lowest_centre(step_rotation, errors, order, amplitude, phase):
    """Lowest non-penetrating centre by a general constrained minimiser, exact distances."""
    di, de, d = (NU208[k] for k in ("inner_raceway_diameter", "outer_raceway_diameter",
                                    "roller_diameter"))
    azimuth, spin = roller_angles(step_rotation, 14, d, 0.5 * (di + de))

    def radius(j, direction):  # roller j's radius towards ``direction`` (eq. 6)
        return 0.5 * (d + errors[j]) + amplitude * np.cos(order * (direction + spin) + phase)

    lower = [j for j in range(14) if np.sin(azimuth[j]) < -1e-9]
    # Each lower roller rests on the outer raceway along its radius line.
    centres = {j: (0.5 * de - radius(j, azimuth[j])) * np.array(
        [np.cos(azimuth[j]), np.sin(azimuth[j])]) for j in lower}

    def gap(c, j):
        towards = centres[j] - c
        direction = np.arctan2(towards[1], towards[0])
        return np.hypot(*towards) - radius(j, direction + np.pi) - 0.5 * di

    # In micrometres, so that the minimiser's steps and tolerances are of order one.
    constraints = [{"type": "ineq", "fun": lambda c, j: gap(c * UM, j) / UM, "args": (j,)}
                   for j in lower]
    found = minimize(lambda c: c[1], x0=np.array([0.0, 0.0]), constraints=constraints,
                     method="SLSQP", options={"ftol": 1e-10, "maxiter": 500})
    assert found.success, found.message
    return found.x * UM


def test_the_vectorised_solution_equals_a_direct_search():
    rng = np.random.default_rng(7)
    errors = rng.uniform(0, 2, 14) * UM
    settings = dict(order=4, amplitude=0.8 * UM, phase=0.3)
    steps = 90
    result = crb_runout(**NU208, roller_diameter_error=errors, revolutions=1,
                        steps_per_revolution=steps, roller_roundness_order=settings["order"],
                        roller_roundness_amplitude=settings["amplitude"],
                        roller_roundness_phase=settings["phase"])
    for step in range(0, steps, 9):
        rotation = 2 * np.pi * step / steps
        direct = _direct_lowest_centre(rotation, errors, **settings)
        ours = np.array([result["center_x"][0, step], result["center_y"][0, step]])
        # Contacts on the radius lines against exact directions: the centre distance and
        # height agree to a few nanometres; the horizontal position, which two rollers 26 deg
        # apart fix 4.4 times less firmly, to about 10 nm.
        assert np.hypot(*ours) == pytest.approx(np.hypot(*direct), abs=0.003 * UM)
        assert ours[1] == pytest.approx(direct[1], abs=0.005 * UM)
        assert ours[0] == pytest.approx(direct[0], abs=0.02 * UM)


def test_the_runout_does_not_depend_on_the_step_count_once_converged():
    kwargs = dict(roller_roundness_order=4, roller_roundness_amplitude=0.5 * UM,
                  roller_diameter_error=np.linspace(0, 1, 14) * UM)
    coarse = crb_runout(**NU208, steps_per_revolution=3600, **kwargs)["runout"][0]
    fine = crb_runout(**NU208, steps_per_revolution=14400, **kwargs)["runout"][0]
    assert coarse == pytest.approx(fine, rel=2e-3)


def test_even_orders_peak_at_multiples_of_the_roller_count():
    # Paper 004, section 3.2: same phase on every roller; Z = 14 has maxima at n = 14, 28 and
    # minima at n = 6, 8, 20, 22 among the even orders; odd orders give nearly nothing.
    orders = np.arange(2, 31)
    runout = np.array([crb_runout(**NU208, roller_roundness_order=n,
                                  roller_roundness_amplitude=0.5 * UM)["runout"][0]
                       for n in orders])
    even = orders % 2 == 0
    assert np.all(runout[~even] < 1e-9 * UM)
    peaks = orders[even][np.argsort(runout[even])[-2:]]
    assert sorted(peaks) == [14, 28]
    lows = orders[even][np.argsort(runout[even])[:4]]
    assert sorted(lows) == [6, 8, 20, 22]


def test_a_pattern_of_the_wrong_length_is_an_error():
    with pytest.raises(ValueError, match="4 values for 14 rollers"):
        crb_runout(**NU208, roller_diameter_error=np.zeros(4))


def test_a_nan_input_fails_the_point_as_not_converged():
    # No resting position can be found from a NaN; model_error is kept for exceptions.
    result = crb_runout(**{**NU208, "roller_diameter": np.array([10.998 * MM, np.nan])},
                        revolutions=1, steps_per_revolution=180)
    assert result["status"].tolist() == [CONVERGED, NOT_CONVERGED]
    assert np.isnan(result["runout"][1])


def test_a_zero_clearance_written_in_mm_is_accepted():
    # Issue 11: NU208 number 1 with de = 71.478 mm = di + 2 D has zero clearance, but in
    # metres the difference came out -3.5e-18 m and the definition was refused.
    from bearing_sweep import spec

    text = ('[sweep]\nmodel = "crb_runout"\nbearing = "paper004-NU208-1"\n[fixed]\n'
            'outer_raceway_diameter = "71.478 mm"\n')
    sweep = spec.parse(text)
    arguments = {name: value.si for name, value in sweep.fixed.items() if value is not None}
    result = crb_runout(**arguments)
    assert result["status"][0] == CONVERGED
    assert result["runout"][0] < 1e-9 * UM
    tight = text.replace("71.478 mm", "71.4779 mm")  # 0.1 um of interference: refused
    with pytest.raises(spec.SpecError, match="must not be negative"):
        spec.parse(tight)


def test_selective_assembly_alternates_the_rollers_by_size_with_their_roundness():
    # Paper 004, Table 3: row 20 is row 19's roller set put in smallest, largest, second
    # smallest... order; each roller keeps its own roundness when moved.
    row19 = np.arange(1, 15) * 0.1 * UM
    row20 = np.array([0.1, 1.4, 0.2, 1.3, 0.3, 1.2, 0.4, 1.1, 0.5, 1, 0.6, 0.9, 0.7, 0.8]) * UM
    amplitude = np.arange(1, 15) * 0.05 * UM  # roller j's oval, 0.05 j um: moves with it
    phase = np.linspace(0.0, 3.0, 14)
    settings = dict(roller_roundness_order=2, steps_per_revolution=180)
    selected = crb_runout(**NU208, roller_diameter_error=row19, roller_arrangement="alternating",
                          roller_roundness_amplitude=amplitude, roller_roundness_phase=phase,
                          **settings)
    moved = np.rint(row20 / (0.1 * UM)).astype(int) - 1  # which roller of row 19 sits where
    by_hand = crb_runout(**NU208, roller_diameter_error=row20,
                         roller_roundness_amplitude=amplitude[moved],
                         roller_roundness_phase=phase[moved], **settings)
    assert selected["assembly_order"][0] == pytest.approx(moved + 1)
    assert selected["runout"][0] == by_hand["runout"][0]
    as_given = crb_runout(**NU208, roller_diameter_error=row19,
                          roller_roundness_amplitude=amplitude, roller_roundness_phase=phase,
                          **settings)
    assert as_given["runout"][0] != by_hand["runout"][0]


def _definition(**fixed):
    from bearing_sweep import spec

    lines = "\n".join(f'{name} = "{value}"' for name, value in fixed.items())
    return spec.parse('[sweep]\nmodel = "crb_runout"\nbearing = "paper004-NU208-1"\n'
                      f"[fixed]\n{lines}\n[axes]\nphase_seed = [0, 1]\n")


@pytest.mark.parametrize("fixed, words", [
    # the reproduction: a 10 mm amplitude on a 5.5 mm roller radius
    (dict(roller_roundness_order=2, roller_roundness_amplitude="10 mm"), "roller's radius"),
    (dict(roller_diameter_error="-11 mm"), "roller's radius"),
    (dict(inner_roundness_order=3, inner_roundness_amplitude="25 mm"), "raceway's radius"),
])
def test_a_profile_with_a_negative_radius_is_refused_before_computing(fixed, words):
    from bearing_sweep.spec import SpecError

    with pytest.raises(SpecError, match=words):
        _definition(**fixed)


def test_a_large_clearance_puts_the_point_out_of_validity():
    # Outer raceway 100 mm on NU208 (a radial clearance of 14 mm): the centre drops by
    # millimetres and the distances the linear contact conditions take vary by about 0.3 um
    # from step to step, against a runout of 1.8 um (paper 004 section 1.4: micrometre
    # errors against radii of centimetres). The same errors in the real bearing hold.
    waviness = dict(roller_roundness_order=2.0, roller_roundness_amplitude=0.5 * UM,
                    steps_per_revolution=360)
    wide = crb_runout(**{**NU208, "outer_raceway_diameter": 100 * MM}, **waviness)
    assert wide["status"][0] == OUT_OF_VALIDITY and np.isfinite(wide["runout"][0])
    assert crb_runout(**NU208, **waviness)["status"][0] == CONVERGED


def test_a_roller_without_room_between_the_rings_is_out_of_validity():
    # No clearance and one roller 2 um oversize: wherever it passes over the top it is
    # squeezed between the rings, a preload the unloaded model does not hold.
    tight = {**NU208, "outer_raceway_diameter": (49.481 + 2 * 10.998) * MM}
    error = np.zeros(14)
    error[0] = 2 * UM
    squeezed = crb_runout(**tight, roller_diameter_error=error, steps_per_revolution=180)
    assert squeezed["status"][0] == OUT_OF_VALIDITY
    undersize = crb_runout(**tight, roller_diameter_error=-error, steps_per_revolution=180)
    assert undersize["status"][0] == CONVERGED


def test_a_profile_that_is_not_convex_is_out_of_validity():
    # r = R + C cos(30 theta) curves inwards at its troughs where 901 C >= R (5.499 mm):
    # 6.5 um does, 5.5 um does not (nor does paper 004's 0.5 um roundness).
    for amplitude, status in ((6.5 * UM, OUT_OF_VALIDITY), (5.5 * UM, CONVERGED)):
        result = crb_runout(**NU208, roller_roundness_order=30.0,
                            roller_roundness_amplitude=amplitude, steps_per_revolution=2400)
        assert result["status"][0] == status, amplitude


@pytest.mark.parametrize("outer", ["100 mm", "82.48 mm"])
def test_a_clearance_as_large_as_a_roller_is_refused_before_computing(outer):
    # The reproduction: an outer raceway of 100 mm on NU208 (the preset's round parts) leaves
    # a diametral clearance of 28.5 mm against 11 mm rollers, and gave 366.5 um of vertical
    # runout, "converged". 82.48 mm leaves 11.0035 mm, just more than the roller diameter.
    from bearing_sweep.spec import SpecError

    with pytest.raises(SpecError, match="must be smaller than the roller diameter"):
        _definition(outer_raceway_diameter=outer)
    assert _definition(outer_raceway_diameter="82.47 mm").model.name == "crb_runout"


def test_a_clearance_no_bearing_has_is_out_of_validity():
    # The preset's round parts (nothing for the linearisation check to see): 80 mm (8.5 mm of
    # clearance) and 71.65 mm (0.172 mm) are beyond ISO 5753-1's largest clearance for a
    # bearing of NU208's size (group 5: 0.125 mm), values kept; the preset's 0.077 mm and
    # 0.124 mm are within.
    preset = {**NU208, "roller_diameter": 10.9985 * MM}
    tight = 49.481 + 2 * 10.9985  # the outer raceway diameter of zero clearance [mm]
    outer = np.array([71.555, tight + 0.124, tight + 0.126, 71.65, 80.0]) * MM
    result = crb_runout(**{**preset, "outer_raceway_diameter": outer})
    assert result["status"].tolist() == [CONVERGED, CONVERGED, OUT_OF_VALIDITY,
                                         OUT_OF_VALIDITY, OUT_OF_VALIDITY]
    assert np.isfinite(result["vertical_runout"]).all()
    # Rollers all 0.1 mm undersize leave the preset's raceways 0.277 mm of play.
    undersize = crb_runout(**preset, roller_diameter_error=-0.1 * MM)
    assert undersize["status"].tolist() == [OUT_OF_VALIDITY]
    one = crb_runout(**preset, roller_diameter_error=np.r_[-0.1 * MM, np.zeros(13)])
    assert one["status"].tolist() == [CONVERGED]  # the others hold the play


def test_describe_states_the_validity_it_applies():
    from bearing_sweep import describe

    description = describe("crb_runout")
    validity = description["validity"]
    assert "preload" in validity and "1 %" in validity and "convex" in validity
    assert "ISO 5753-1" in validity
    assert any("smaller than the roller diameter" in c for c in description["conditions"])


@pytest.mark.parametrize("errors", [
    dict(roller_diameter_error=np.linspace(0.0, 1.3, 14) * UM),
    dict(outer_roundness_order=5, outer_roundness_amplitude=1 * UM),
    dict(roller_roundness_order=4, roller_roundness_amplitude=1 * UM,
         roller_roundness_phase=np.linspace(0.0, 3.0, 14))])
def test_too_few_rotation_steps_are_out_of_validity(errors):
    # Sampled runouts err as 1/steps (the extremes lie at kinks): 8 steps a revolution miss
    # a tenth of an outer raceway's order-5 or a roller's order-4 runout. A point is flagged
    # below 30 steps per period of the fastest motion of the centre; every point left
    # within validity lies within 3.3 % of 3600 steps.
    fine = crb_runout(**NU208, **errors, steps_per_revolution=3600)["runout"][0]
    flagged = []
    for steps in (8, 24, 60, 171, 172, 360, 720):
        result = crb_runout(**NU208, **errors, steps_per_revolution=steps)
        flagged.append(result["status"][0] == OUT_OF_VALIDITY)
        if not flagged[-1]:
            assert result["runout"][0] == pytest.approx(fine, rel=0.033)
    assert flagged[:4] == [True] * 4 and not flagged[-1]
    # The rollers pass the bottom Z (1 - D/dm) / 2 = 5.73 times a revolution: 172 steps.
    assert flagged[4] == ("roller_roundness_order" in errors)
    low = crb_runout(**NU208, **errors, steps_per_revolution=8)["runout"][0]
    if "roller_diameter_error" not in errors:
        assert abs(low - fine) > 0.05 * fine


@pytest.mark.parametrize("seed", range(4))
def test_the_compiled_envelope_gives_the_vectorised_numbers_to_the_bit(seed):
    from bearing_sweep.models import runout, runout_envelope

    rng = np.random.default_rng(seed)
    rows, count = 400, 3 + 5 * seed
    slope, intercept = rng.normal(size=(rows, count)), rng.normal(size=(rows, count)) * 1e-6
    active = rng.random((rows, count)) < 0.7
    slope[::3, 0] = 0.0  # a roller right at the bottom: a flat piece of the envelope
    intercept[::4, 1] = intercept[::4, 2]  # lines that meet where a third does
    slope[::5, 1] = slope[::5, 2]  # parallel lines
    intercept[7, 0] = np.nan  # a failed point's lines
    slope = np.where(active, slope, 0.0)
    with np.errstate(invalid="ignore"):
        expected = runout.lowest_centre_vectorised(slope, intercept, active)
    best_x, best_y = np.full(rows, np.nan), np.full(rows, np.inf)
    runout_envelope.lowest_vertices(slope, intercept, active, runout._TIE, best_x, best_y)
    assert np.isfinite(best_y).sum() > rows // 2  # most rows have a lowest vertex
    assert best_x.tobytes() == expected[0].tobytes()
    assert np.where(np.isfinite(best_y), best_y, np.nan).tobytes() == expected[1].tobytes()


def test_a_sweep_gives_the_same_runout_vectorised_and_compiled(monkeypatch):
    from bearing_sweep.models import runout, runout_envelope

    inputs = dict(inner_raceway_diameter=50e-3, outer_raceway_diameter=70e-3,
                  roller_diameter=10e-3, roller_count=14,
                  roller_diameter_error=np.linspace(-1e-6, 1e-6, 14),
                  roller_roundness_order=np.arange(2.0, 6.0)[:, None],
                  roller_roundness_amplitude=0.5e-6, steps_per_revolution=360)
    results = []
    for compiled in (None, runout_envelope):
        monkeypatch.setattr(runout._ENVELOPE, "compiled_for", lambda rows: compiled)
        results.append(crb_runout(**inputs))
    for name in results[0]:
        assert np.asarray(results[0][name]).tobytes() == np.asarray(results[1][name]).tobytes()
