"""cage_dynamics: the transient settles on the steady state where their assumptions meet."""
import numpy as np
import pytest

from bearing_sweep.models import cage_dynamics_rhs as rhs
from bearing_sweep.models.cage_dynamics import EXCURSION_LIMIT, cage_dynamics, run_validity
from bearing_sweep.models.cage_slip import cage_slip

MM, RPM = 1e-3, 2 * np.pi / 60
TEST = dict(roller_count=13, inner_raceway_diameter=44 * MM, roller_diameter=10 * MM,
            roller_length=11 * MM, effective_length=7.2 * MM, clearance=0.02 * MM,
            cage_inner_diameter=48.5 * MM, cage_outer_diameter=59 * MM, cage_width=13 * MM,
            pocket_friction=0.0)


def test_a_rigidly_guided_cage_settles_on_the_steady_slip():
    # The steady model moves every roller with the cage and lets the cage neither whirl nor
    # play in its pockets: a very heavy cage with tight pockets does the same.
    tight = dict(TEST, pocket_clearance=0.01 * MM)
    steady = cage_slip(800.0, 12000 * RPM, **tight)["cage_slip"][0]
    transient = cage_dynamics(800.0, 12000 * RPM, **tight, cage_density=8.6e6,
                              duration=0.04, output_interval=2e-4)
    assert transient["status"][0] == 0
    assert transient["mean_cage_slip"][0] == pytest.approx(steady, rel=0.02)


def test_a_whirling_cage_slips_somewhat_more_than_the_steady_estimate():
    # With the real cage and pocket play the cage whirls and the rollers rattle in their
    # pockets; that costs traction, so the transient slip is higher, but of the same order.
    steady = cage_slip(800.0, 12000 * RPM, **TEST)["cage_slip"][0]
    transient = cage_dynamics(800.0, 12000 * RPM, **TEST, duration=0.04,
                              output_interval=2e-4)
    assert steady < transient["mean_cage_slip"][0] < 1.5 * steady
    slip = transient["cage_slip"][0]
    assert np.isfinite(slip).all() and slip.shape == (201,)
    assert transient["roller_slip"].shape == (1, 201, 13)


def test_the_gap_between_the_planar_and_the_steady_slip_is_the_rollers_play_in_the_pockets():
    # The symmetric case (paper002-test's bearing, 2 kN, 6000 r/min, no eccentricity, the
    # real cage, films and pocket friction): the steady model holds every roller at the
    # cage's orbit speed, the planar one lets it move across its pocket clearance. Closing
    # the clearance closes the gap between them, and nothing else is needed.
    bearing = dict(TEST, pocket_friction=0.1, roller_density=7820.0, poisson_ratio=0.28,
                   end_film_thickness=0.015 * MM)
    gaps = []
    for clearance in (0.1, 0.03, 0.01, 0.003):
        tight = dict(bearing, pocket_clearance=clearance * MM)
        steady = cage_slip(2000.0, 6000 * RPM, **tight)["cage_slip"][0]
        planar = cage_dynamics(2000.0, 6000 * RPM, **tight, duration=0.1,
                               output_interval=2e-4)
        assert planar["status"][0] == 0
        gaps.append(planar["mean_cage_slip"][0] / steady - 1.0)
    assert gaps[0] > 0.5  # at the preset's 0.1 mm: the rollers' play nearly doubles it
    assert all(later < earlier for earlier, later in zip(gaps, gaps[1:]))
    assert abs(gaps[-1]) < 0.02


def test_radial_eccentricity_steadies_the_whirl():
    # Paper 002, section 3 (Fig. 18): 2 mm radial eccentricity of the cage's mass makes the
    # whirl regular, its centre's speed nearly constant.
    runs = cage_dynamics(800.0, 12000 * RPM, **TEST, cage_eccentricity=np.array([0.0, 2 * MM]),
                         duration=0.04, output_interval=2e-4)
    free, eccentric = runs["whirl_deviation_ratio"]
    assert eccentric < 0.2 * free


@pytest.mark.parametrize("pushed", [False, True])
def test_the_pocket_couples_conserve_angular_momentum(pushed):
    # No loads, traction, drag, end films or gravity: only the pockets act between rollers
    # and cage (their film and, where a roller presses on its pocket, friction and the normal
    # force). The rate of the angular momentum about the axis, counted with the orbit, is
    # then zero: cage J phi'' plus each roller's m r_m^2 theta'' less its J_R omega_R'' (its
    # spin counts opposite to the orbit).
    count = 13
    p = np.zeros(rhs.PARAMETERS)
    p[rhs.R_INNER], p[rhs.R_OUTER], p[rhs.R_ROLLER], p[rhs.R_PITCH] = 0.022, 0.032, 0.005, 0.027
    p[rhs.CONTACT], p[rhs.HALF_PLAY] = 1e9, 1e-5
    p[rhs.M_ROLLER], p[rhs.J_ROLLER] = 0.0067, 8.4e-8
    p[rhs.POCKET_FILM], p[rhs.MU_POCKET] = 7e-7, 0.1
    p[rhs.M_RING], p[rhs.M_CAGE], p[rhs.J_CAGE] = 0.1, 0.05, 1.8e-5
    p[rhs.HALF_POCKET], p[rhs.K_POCKET], p[rhs.C_POCKET] = 5e-5, 5e7, 10.0
    p[rhs.TRACTION_C] = 1.0  # with A = B = D = 0: no traction
    state = np.zeros(4 + 3 * count + 6)
    rollers = 4 + 3 * np.arange(count)
    state[rollers] = 2 * np.pi * np.arange(count) / count
    state[rollers + 2] = np.linspace(500.0, 2500.0, count)  # spins
    if pushed:  # roller 1 ahead of its pocket by 0.27 mm, 0.22 mm into the pocket's wall
        state[rollers[0]] += 0.01
    out = rhs.derivatives(0.0, state, p, count)
    cage = 4 + 3 * count
    rate = p[rhs.J_CAGE] * out[cage + 5] + np.sum(
        p[rhs.M_ROLLER] * p[rhs.R_PITCH]**2 * out[rollers + 1]
        - p[rhs.J_ROLLER] * out[rollers + 2])
    couples = p[rhs.POCKET_FILM] * state[rollers + 2].sum()  # the film's alone
    assert abs(p[rhs.J_CAGE] * out[cage + 5]) > 0.5 * couples
    assert abs(rate) < 1e-12 * couples


@pytest.mark.parametrize("model", ["cage_dynamics", "cage_dynamics_6dof"])
@pytest.mark.parametrize("fixed, words", [
    # the reproduction: a mass centre 1 m off a 59 mm cage
    ('cage_eccentricity = "1 m"', "has its mass centre no farther"),
    ('cage_eccentricity = "29.5 mm"', "has its mass centre no farther"),
    # A ring cage of 48.5-59 mm has J = m (Ro^2 + Ri^2) / 2 about its mass centre; with all
    # its mass within Ro, J + m e^2 <= m Ro^2: e at most sqrt((59^2 - 48.5^2) / 8) = 11.88 mm.
    ('cage_eccentricity = "12 mm"', "has its mass centre no farther"),
    # the 11 mm rollers need pockets at least as wide
    ('cage_width = "10 mm"', "cage_width must be at least roller_length"),
    ('pocket_clearance = "1 m"', "pockets do not fit"),
    # cages are of polymers (polyamide, 1140 kg/m^3) to bronze (8900)
    ('cage_density = "1 kg/m^3"', "cage_density"),
    ('cage_density = "20000 kg/m^3"', "cage_density"),
])
def test_a_cage_that_cannot_be_is_refused_before_computing(model, fixed, words):
    from bearing_sweep import spec

    text = (f'[sweep]\nmodel = "{model}"\nbearing = "paper002-test"\n[fixed]\n{fixed}\n'
            'speed = "9000 rpm"\n'
            '[axes]\nradial_load = ["400 N", "800 N"]\n')
    with pytest.raises(spec.SpecError, match=words):
        spec.parse(text)
    if model == "cage_dynamics_6dof":  # half the 13 mm cage's width: 6.5 mm
        with pytest.raises(spec.SpecError, match="mass centre lies within its outline"):
            spec.parse(text.replace(fixed, 'cage_axial_eccentricity = "-7 mm"'))
        spec.parse(text.replace(fixed, 'cage_axial_eccentricity = "-6 mm"'))
    spec.parse(text.replace(fixed, 'cage_eccentricity = "11.5 mm"'))
    spec.parse(text.replace(fixed, 'cage_width = "11 mm"'))


def test_a_cage_softer_than_any_cage_material_is_refused():
    from bearing_sweep import spec

    text = ('[sweep]\nmodel = "cage_dynamics_6dof"\nbearing = "paper002-test"\n[fixed]\n'
            'speed = "9000 rpm"\nradial_load = "800 N"\ncage_youngs_modulus = "1e-6 GPa"\n')
    with pytest.raises(spec.SpecError, match="cage_youngs_modulus"):
        spec.parse(text)
    assert spec.parse(text.replace("1e-6 GPa", "3 GPa")).model.name == "cage_dynamics_6dof"


def test_the_steady_starts_validity_is_carried_through_the_transient():
    # A pocket clearance of 0.6 mm, 12 % of the roller radius, is beyond cage_slip's thin
    # films: the run from that steady state is out of validity too, its values kept.
    result = cage_dynamics(800.0, 12000 * RPM, **dict(TEST, pocket_clearance=0.6 * MM),
                           duration=2e-3, output_interval=5e-4)
    from bearing_sweep.models.registry import CONVERGED, OUT_OF_VALIDITY

    assert result["status"].tolist() == [CONVERGED | OUT_OF_VALIDITY]
    assert np.isfinite(result["cage_slip"]).all()


# -- A run's own state out of the model's validity (both transient models: run_validity)

def test_a_cage_with_no_pocket_stiffness_to_hold_it_falls_out_of_validity():
    # A pocket contact of 1e-3 N/m cannot hold the cage up: over 0.1 s it falls through the
    # rollers, far beyond its pocket and diametral clearances, and the run says so. The same
    # run with the default stiffness stays within them.
    falling, held = (cage_dynamics(800.0, 12000 * RPM, **TEST, pocket_stiffness=stiffness,
                                   duration=0.1, output_interval=1e-3)
                     for stiffness in (1e-3, 5e7))
    from bearing_sweep.models.registry import CONVERGED, OUT_OF_VALIDITY

    limit = EXCURSION_LIMIT * (0.1 * MM + TEST["clearance"])
    assert np.hypot(falling["cage_centre_x"], falling["cage_centre_y"]).max() > limit
    assert falling["status"].tolist() == [CONVERGED | OUT_OF_VALIDITY]
    assert np.hypot(held["cage_centre_x"], held["cage_centre_y"]).max() < limit
    assert held["status"].tolist() == [CONVERGED]


def test_a_cage_run_at_a_crawl_is_out_of_validity():
    # At 0.01 r/min, with the pockets' default friction, the traction cannot drive the
    # rollers over 5 ms: the settled mean cage slip lies far beyond -100 %, which no running
    # bearing has.
    crawl = cage_dynamics(800.0, 0.01 * RPM, **dict(TEST, pocket_friction=0.1),
                          duration=5e-3, output_interval=1e-4)
    from bearing_sweep.models.registry import CONVERGED, OUT_OF_VALIDITY

    assert abs(crawl["mean_cage_slip"][0]) > 1.0
    assert crawl["status"].tolist() == [CONVERGED | OUT_OF_VALIDITY]


@pytest.mark.parametrize("slips, centre, inside", [
    ((0.02, 0.25), (0.0, 0.0), True),
    ((-1.0, 1.0), (0.0, 0.0), True),  # the bounds themselves
    ((-1.0001, 0.25), (0.0, 0.0), False),
    ((0.02, 1.0001), (0.0, 0.0), False),
    ((np.nan, 0.25), (0.0, 0.0), False),
    ((0.02, 0.25), (0.24e-3, 0.0), True),  # within 2 x (0.1 + 0.02) mm
    ((0.02, 0.25), (0.17e-3, 0.17e-3), False),  # 0.2404 mm from the axis
    ((0.02, 0.25), (np.nan, 0.0), False),
])
def test_run_validity_bounds_the_slips_and_the_cages_excursion(slips, centre, inside):
    from bearing_sweep.models.registry import OUT_OF_VALIDITY

    found = run_validity(*slips, np.array([0.0, centre[0]]), np.array([0.0, centre[1]]),
                         0.1 * MM, 0.02 * MM, np.linspace(0.0, 2.0, 21), 0.5, 1e9)
    assert found == (0 if inside else OUT_OF_VALIDITY)


@pytest.mark.parametrize("last, inside", [(4.0, True), (4.2, True), (3.9, False)])
def test_run_validity_wants_a_settled_half_of_two_roller_passes(last, inside):
    # Samples every 0.1 s to ``last``, a roller passing every 1 s: the settled half runs
    # from the first sample at or after half the last one (2.0 s, 2.1 s, 2.0 s).
    from bearing_sweep.models.registry import OUT_OF_VALIDITY

    times = np.arange(round(last / 0.1) + 1) * 0.1
    found = run_validity(0.02, 0.25, np.zeros(times.size), np.zeros(times.size), 0.1 * MM,
                         0.02 * MM, times, 1.0, 1e9)
    assert found == (0 if inside else OUT_OF_VALIDITY)


@pytest.mark.parametrize("pressure, inside", [(3999e6, True), (4000e6, True), (4001e6, False),
                                              (np.nan, False)])
def test_run_validity_bounds_the_raceway_pressure_at_iso_76s_4000_mpa(pressure, inside):
    from bearing_sweep.models.registry import OUT_OF_VALIDITY

    found = run_validity(0.02, 0.25, np.zeros(2), np.zeros(2), 0.1 * MM, 0.02 * MM,
                         np.linspace(0.0, 2.0, 21), 0.5, pressure)
    assert found == (0 if inside else OUT_OF_VALIDITY)


def test_the_planar_raceway_pressure_is_the_load_distributions_and_a_heavy_ring_shows():
    # The planar run's largest roller pressure against crb_radial's static load distribution
    # of the same bearing (one slice: the planar model's uncrowned roller); a 60 kg inner
    # ring's weight, 589 N beside the 800 N load, raises it as 1389 N would.
    from bearing_sweep.models.cylindrical import crb_radial

    runs = [cage_dynamics(800.0, 12000 * RPM, **TEST, inner_ring_mass=mass, duration=0.02,
                          output_interval=1e-4) for mass in (0.1, 60.0)]
    static = [float(crb_radial(load, 13, 54.01 * MM, 10 * MM, 7.2 * MM, clearance=0.02 * MM,
                               slices=1, speed=12000 * RPM, roller_density=7850.0,
                               )["largest_contact_pressure"])
              for load in (800.0 + 0.1 * 9.81, 800.0 + 60 * 9.81)]
    for run, expected in zip(runs, static):
        assert run["largest_contact_pressure"][0] == pytest.approx(expected, rel=0.03)


def test_a_slow_run_too_short_to_settle_is_out_of_validity():
    # At 100 r/min the kinematic cage speed (1 - D/d_m) omega_i / 2 = 4.27 rad/s brings a
    # roller past a point every 2 pi / (13 x 4.27) = 0.113 s. Over 5 ms the planar run's
    # mean cage slip lies several per cent from its value over 2 s (about -0.1 %), and the
    # run is flagged; at 12000 r/min (0.94 ms a roller pass) 5 ms settle.
    from bearing_sweep.models.registry import CONVERGED, OUT_OF_VALIDITY

    short, settled = (cage_dynamics(800.0, speed * RPM, **TEST, duration=5e-3,
                                    output_interval=5e-5) for speed in (100, 12000))
    assert abs(short["mean_cage_slip"][0]) > 0.02
    assert short["status"].tolist() == [CONVERGED | OUT_OF_VALIDITY]
    assert settled["status"].tolist() == [CONVERGED]
