"""Rotational accuracy of a cylindrical roller bearing: inner-ring runout from the roundness and
size errors of rollers and raceways, quasi-static, unloaded, at low speed (paper 004).

Outer ring fixed, its centre the origin; y up, gravity along -y; angles counter-clockwise from
+x. The inner ring turns by ``alpha``; roller ``j`` sits at azimuth
``beta_j = 2 pi (j - 1) / Z + gamma_2`` (eq. 2-3). Gravity settles the rollers of the lower half
on the outer raceway and the inner ring on them: at each step the inner-ring centre takes its
lowest position in which it penetrates no roller, which is what the paper's stability criteria
1-3 select (no interference, rollers in contact on both sides of the vertical, least potential
energy).

Radii are a nominal value plus Fourier harmonics ``C cos(n theta + psi)`` (eq. 4-6). The
centre moves by micrometres against radii of centimetres, so each roller's condition of
no penetration is linear in the centre, ``c . e_j <= h_j``, with the contacts on the roller's
radius line; the lowest centre is then the minimum of the upper envelope of ``Z`` straight
lines, the best vertex of all pairs of rollers either side of the vertical. Against exact
distances and contact directions (a general minimiser in the tests) the centre distance
differs by less than 0.002 um for the paper's bearing with micrometre errors.
"""
from __future__ import annotations

import numpy as np

from .geometry import clearance_below_roller, elements_fit
from .kernels import Kernels
from .limits import CLEARANCE_VALIDITY, clearance_beyond_bearings
from .registry import (CONVERGED, NOT_CONVERGED, OUT_OF_VALIDITY, Constraint, DimCoordinate,
                       Input, Model, Output, combine_status)

SPINS = ("absolute", "paper")
ARRANGEMENTS = ("as_given", "alternating")
_TIE = 1e-13  # [m]: lines this close count as meeting
#: Rows (points times rotation steps) a process computes with the vectorised envelope before
#: it loads the compiled one: about as long as numba takes to import and load it.
VECTORISED_ROWS = 20_000
_ENVELOPE = Kernels(f"{__package__}.runout_envelope", VECTORISED_ROWS)
_ROUNDING = 1e-12  # [-]: a clearance this far below zero, relative to d_e, is zero
#: Largest error of the linear contact conditions, as a share of the runout, or below
#: LINEARISATION_FLOOR (a tenth of the 0.1 um to which paper 004 states runouts): where the
#: exact gaps at the centre found vary from step to step by more, the runout is not known to
#: that [-], [m]. Paper 004's bearing, its clearance and micrometre errors, stays below 0.002 um.
LINEARISATION_LIMIT, LINEARISATION_FLOOR = 0.01, 1e-8
#: Fewest rotation steps per period of the fastest component of the centre's motion (the
#: rollers passing the bottom, a raceway's or a roller's harmonic as the rollers meet it) [-].
#: A runout is a largest minus a smallest sample, and the extremes often lie at kinks (the
#: ring passing from one pair of rollers to the next), so the sampled runouts converge only
#: as 1/steps: our check of 40 random error sets on paper 004's NU208 (one or two raceway
#: harmonics of orders 1-39 and 0.2-2 um, roller roundness of orders 1-29 and 0.1-1 um,
#: diameter errors of +-1 um, 1-3 revolutions) against 2000 steps per period left both
#: runouts within 3.3 % and 0.09 um (the paper states runouts to 0.1 um) from 30 steps per
#: period on, within 1.5 % from 60 and 0.8 % from 120; 8 steps per period erred by 10 %, and
#: 8 steps a revolution for an inner raceway's order 14 (one a period) by half the runout.
STEPS_PER_PERIOD = 30


def roller_angles(rotation, roller_count, roller_diameter, pitch_diameter, spin="absolute"):
    """Azimuths and spin angles of the rollers when the inner ring has turned by ``rotation``.

    Parameters
    ----------
    rotation : array_like
        Inner-ring rotation ``alpha`` [rad], counter-clockwise.
    roller_count : int
    roller_diameter, pitch_diameter : float
        ``D``, ``d_m`` [m].
    spin : {'absolute', 'paper'}
        'paper': the spin angle of eq. 1, ``gamma_1 = (d_m^2 - D^2) / (2 d_m D) alpha``, which is
        the spin relative to the cage; 'absolute': ``gamma_1 - gamma_2``, the spin in the frame
        that only translates, in which eq. 6 writes the roller's profile.

    Returns
    -------
    azimuth : numpy.ndarray
        ``(..., Z)`` roller azimuths ``beta_j`` [rad] (eq. 2-3).
    spin_angle : numpy.ndarray
        ``(...)`` clockwise spin ``gamma`` [rad] of every roller.
    """
    rotation = np.asarray(rotation, dtype=float)
    ratio = roller_diameter / pitch_diameter
    orbit = 0.5 * rotation * (1.0 - ratio)  # eq. 2, cage angle
    spin_angle = (1.0 / ratio - ratio) * 0.5 * rotation  # eq. 1
    if spin == "absolute":
        spin_angle = spin_angle - orbit
    azimuth = 2.0 * np.pi * np.arange(roller_count) / roller_count + orbit[..., None]
    return azimuth, spin_angle


def harmonics(angle, order, amplitude, phase):
    """``sum_k C_k cos(n_k angle + psi_k)`` with the harmonics along the last axis [m]; zeros
    without a cosine where every amplitude is zero (a round raceway)."""
    if not np.any(amplitude):
        return np.zeros(np.broadcast_shapes(np.shape(angle) + (1,), np.shape(order),
                                            np.shape(amplitude), np.shape(phase))[:-1])
    return np.sum(amplitude * np.cos(order * angle[..., None] + phase), axis=-1)


def lowest_centre(slope, intercept, active):
    """Minimum of the upper envelope ``F(x) = max_j (s_j x + b_j)`` over the active lines.

    Computed by :func:`lowest_centre_vectorised`, or, once a process has computed
    ``VECTORISED_ROWS`` rows so, by the compiled :mod:`models.runout_envelope` (the same
    numbers, to the bit); parameters and returns as there.
    """
    slope, intercept, active = np.broadcast_arrays(slope, intercept, active)
    compiled = _ENVELOPE.compiled_for(slope.size // max(slope.shape[-1], 1))
    if compiled is None:
        return lowest_centre_vectorised(slope, intercept, active)
    shape, count = slope.shape[:-1], slope.shape[-1]
    best_x = np.full(int(np.prod(shape)), np.nan)
    best_y = np.full(best_x.size, np.inf)
    compiled.lowest_vertices(*(np.ascontiguousarray(a.reshape(-1, count), dtype=kind)
                               for a, kind in ((slope, float), (intercept, float),
                                               (active, bool))), _TIE, best_x, best_y)
    best_x, best_y = best_x.reshape(shape), best_y.reshape(shape)
    return best_x, np.where(np.isfinite(best_y), best_y, np.nan)


def lowest_centre_vectorised(slope, intercept, active):
    """Minimum of the upper envelope ``F(x) = max_j (s_j x + b_j)`` over the active lines,
    vectorised over the leading axes.

    Parameters
    ----------
    slope, intercept : numpy.ndarray
        ``(..., Z)`` lines ``y = s_j x + b_j``.
    active : numpy.ndarray of bool
        ``(..., Z)`` which lines count.

    Returns
    -------
    x, y : numpy.ndarray
        ``(...)`` the lowest point of the envelope, NaN where no line of negative and one of
        positive slope bound it.

    Notes
    -----
    The envelope is convex; its minimum is where a line of falling slope meets one of rising
    slope, both on the envelope there: the lowest such vertex. Where the minimum is a flat
    piece (a roller right at the bottom), its ends are the vertices taken: on the exact,
    slightly domed contact the ring rolls off the middle to one of them.
    """
    falling = active & (slope <= 0.0)
    rising = active & (slope >= 0.0)
    lines = np.where(active, 0.0, -np.inf)
    best_x = np.full(slope.shape[:-1], np.nan)
    best_y = np.full(slope.shape[:-1], np.inf)
    count = slope.shape[-1]
    for left in range(count):
        for right in range(count):
            pair = falling[..., left] & rising[..., right] & (
                slope[..., right] > slope[..., left])
            if not pair.any():
                continue
            with np.errstate(divide="ignore", invalid="ignore"):
                x = (intercept[..., left] - intercept[..., right]) / (
                    slope[..., right] - slope[..., left])
            envelope = np.max(slope * x[..., None] + intercept + lines, axis=-1)
            # Only a crossing on the envelope is a vertex: where a third line lies exactly as
            # high (a roller right at the bottom), the crossing beneath it is not a resting
            # place, the envelope's vertices beside it are.
            on_envelope = envelope <= slope[..., left] * x + intercept[..., left] + _TIE
            better = pair & on_envelope & (envelope < best_y)
            best_x = np.where(better, x, best_x)
            best_y = np.where(better, envelope, best_y)
    return best_x, np.where(np.isfinite(best_y), best_y, np.nan)


def _per_roller(value, points, roller_count, name):
    """A per-roller pattern as ``(points, Z)``: one value stands for every roller."""
    value = np.asarray(value, dtype=float)
    value = value.reshape((points if value.ndim > 1 else 1, -1))
    if value.shape[-1] not in (1, roller_count):
        raise ValueError(f"{name} has {value.shape[-1]} values for {roller_count} rollers")
    return np.broadcast_to(value, (points, roller_count))


def _harmonic_set(order, amplitude, phase, points):
    """A ring's harmonics as three ``(points, 1, 1, k)`` arrays (against steps and rollers)."""
    arrays = [np.asarray(a, dtype=float) for a in (order, amplitude, phase)]
    arrays = [a.reshape((points if a.ndim > 1 else 1, -1)) for a in arrays]
    size = max(a.shape[-1] for a in arrays)
    return [np.broadcast_to(a, (points, size))[:, None, None, :] for a in arrays]


def crb_runout(inner_raceway_diameter, outer_raceway_diameter, roller_diameter, roller_count,
               roller_diameter_error=0.0, roller_roundness_order=0.0,
               roller_roundness_amplitude=0.0, roller_roundness_phase=0.0,
               inner_roundness_order=0.0, inner_roundness_amplitude=0.0,
               inner_roundness_phase=0.0, outer_roundness_order=0.0,
               outer_roundness_amplitude=0.0, outer_roundness_phase=0.0, revolutions=3,
               steps_per_revolution=360, roller_spin="absolute", phase_seed=0, order_seed=0,
               roller_arrangement="as_given"):
    """Inner-ring runout of an unloaded cylindrical roller bearing turning slowly.

    Parameters
    ----------
    inner_raceway_diameter, outer_raceway_diameter, roller_diameter : array_like
        ``d_i``, ``d_e``, ``D`` [m]; the pitch diameter is ``(d_i + d_e) / 2``.
    roller_count : int
    roller_diameter_error : array_like
        Each roller's diameter minus ``D`` [m], ``(Z,)`` (or one value for all).
    roller_roundness_order, roller_roundness_amplitude, roller_roundness_phase : array_like
        One harmonic per roller (eq. 6): order ``n`` (0: none), amplitude ``C`` [m] (peak
        deviation of the radius), phase ``psi`` [rad]; ``(Z,)`` or one value for all.
    inner_roundness_order, inner_roundness_amplitude, inner_roundness_phase,
    outer_roundness_order, outer_roundness_amplitude, outer_roundness_phase : array_like
        The raceways' harmonics (eq. 4-5), one entry per harmonic: order, amplitude [m],
        phase [rad].
    revolutions, steps_per_revolution : int
        Inner-ring revolutions computed and steps in each.
    roller_spin : {'absolute', 'paper'}
        See :func:`roller_angles`.
    phase_seed : int
        0: the roller phases as given; else every roller's phase drawn uniformly from this
        seed (a Monte Carlo sample of phases).
    order_seed : int
        0: the diameter errors in the order given; else shuffled by this seed (an assembly
        order).
    roller_arrangement : {'as_given', 'alternating'}
        ``'alternating'``: selective assembly, the rollers sorted by diameter error and put
        in smallest, largest, second smallest, second largest... (Table 3 row 20), each
        roller with its own roundness (order, amplitude, phase); applied after
        ``order_seed``.

    Returns
    -------
    dict of numpy.ndarray
        ``runout`` [m], the largest minus the smallest distance between the ring centres (as
        the paper defines it); ``vertical_runout`` [m], the same for the vertical position (a
        dial gauge above); ``center_x``, ``center_y`` ``(N, steps)`` [m]; ``rotation_angle``
        ``(N, steps)`` [rad]; ``assembly_order`` ``(N, Z)``: which given error each roller
        position has (1-based); ``status``: not converged where no resting position was
        found at some step (a NaN input); out of validity as below.

    Notes
    -----
    Validity: a point is ``out_of_validity`` (values kept) where, with the centre found, a
    roller (of the upper half too) has no room between the rings (a preload the unloaded
    model lacks); where the gaps of the resting rollers at that centre with the distances
    between the centres not linearised vary from step to step by more than 1 % of the runout
    and 0.01 um (the centre moves by more than micrometres against the radii: a large
    clearance or large errors); or where a roller's or the inner raceway's profile is not
    convex (``C (n^2 + 1) >= R``), so that a contact leaves the radius line; where the steps
    are fewer than :data:`STEPS_PER_PERIOD` (30) per period of the fastest component of the
    centre's motion (:func:`_fastest_component`: the rollers passing the bottom, or a
    raceway's or a roller's harmonic as the rollers meet it), which leaves the sampled
    runouts up to some 3 % from the continuous ones; and, whatever the outcome, where the
    clearance ``d_e - d_i - 2 D`` (with the largest roller's diameter error) exceeds the
    largest ISO 5753-1 gives a cylindrical roller bearing whose bore is at most ``d_i``
    (:func:`models.limits.clearance_beyond_bearings`): paper 004's NU208 has 0.05-0.08 mm,
    its model takes the centre's movement small against the radii, and a bearing with more
    play than any group of the standard is none the paper or the makers describe.

    References
    ----------
    .. [1] Paper 004, eq. 1-6 and section 1.4.
    """
    patterns = (roller_diameter_error, roller_roundness_order, roller_roundness_amplitude,
                roller_roundness_phase, inner_roundness_order, inner_roundness_amplitude,
                inner_roundness_phase, outer_roundness_order, outer_roundness_amplitude,
                outer_roundness_phase)
    # Patterns come as (points, entries) when they vary over the points, (entries,) if not.
    points = max([np.shape(p)[0] for p in patterns if np.ndim(p) > 1] + [np.size(
        inner_raceway_diameter), np.size(outer_raceway_diameter), np.size(roller_diameter)])
    inner, outer, diameter = (np.broadcast_to(np.asarray(a, dtype=float).reshape(-1), (points,))
                              for a in (inner_raceway_diameter, outer_raceway_diameter,
                                        roller_diameter))
    pitch = 0.5 * (inner + outer)
    error = _per_roller(roller_diameter_error, points, roller_count, "roller_diameter_error")
    order_index = np.broadcast_to(np.arange(roller_count), (points, roller_count))
    if order_seed:
        order_index = np.random.default_rng(order_seed).permutation(roller_count)[None, :]
        order_index = np.broadcast_to(order_index, (points, roller_count))
        error = np.take_along_axis(error, order_index, axis=-1)
    order, amplitude, phase = (_per_roller(v, points, roller_count, name) for v, name in (
        (roller_roundness_order, "roller_roundness_order"),
        (roller_roundness_amplitude, "roller_roundness_amplitude"),
        (roller_roundness_phase, "roller_roundness_phase")))
    if phase_seed:
        drawn = np.random.default_rng(phase_seed).uniform(0.0, 2.0 * np.pi, roller_count)
        phase = np.broadcast_to(drawn, (points, roller_count))
    if roller_arrangement == "alternating":
        # The whole roller moves: its roundness goes with its diameter.
        chosen = alternating_by_size(error)
        error, order, amplitude, phase = (np.take_along_axis(a, chosen, axis=-1) for a in (
            error, order, amplitude, phase))
        order_index = np.take_along_axis(order_index, chosen, axis=-1)
    rotation = 2.0 * np.pi * np.arange(revolutions * steps_per_revolution) / steps_per_revolution
    azimuth, spin = roller_angles(rotation[None, :], roller_count, diameter[:, None],
                                  pitch[:, None], roller_spin)  # (N, S, Z), (N, S)
    spin = spin[..., None]
    inner_set = _harmonic_set(inner_roundness_order, inner_roundness_amplitude,
                              inner_roundness_phase, points)
    outer_set = _harmonic_set(outer_roundness_order, outer_roundness_amplitude,
                              outer_roundness_phase, points)

    def roller_radius(direction):  # eq. 6, in the translating frame
        return 0.5 * (diameter[:, None, None] + error[:, None, :]) + amplitude[:, None, :] * \
            np.cos(order[:, None, :] * (direction + spin) + phase[:, None, :])

    def inner_radius(direction):  # eq. 4, the ring turned by alpha
        return 0.5 * inner[:, None, None] + harmonics(direction - rotation[None, :, None],
                                                      *inner_set)

    # The lower rollers rest on the outer raceway (eq. 5) along their radius lines; the
    # inner raceway and the rollers touch along the same lines.
    reach = 0.5 * outer[:, None, None] + harmonics(azimuth, *outer_set) - roller_radius(azimuth)
    room = reach - roller_radius(azimuth + np.pi) - inner_radius(azimuth)  # c . e_j <= h_j
    across, down = np.cos(azimuth), np.sin(azimuth)  # the radius lines' directions
    active = down < -1e-9
    with np.errstate(divide="ignore", invalid="ignore"):
        slope = np.where(active, -across / down, 0.0)
        intercept = np.where(active, room / down, 0.0)
    x, y = lowest_centre(slope, intercept, active)
    distance = np.hypot(x, y)
    found = np.all(np.isfinite(distance), axis=-1)
    runout = distance.max(axis=-1) - distance.min(axis=-1)
    # Validity. Every roller, those of the upper half too, must find room between the rings
    # with the centre found: else the rings squeeze it, a preload the unloaded model lacks.
    gap = room - (across * x[..., None] + down * y[..., None])
    squeezed = np.any(gap < -_TIE, axis=(-2, -1))
    # The gaps of the resting rollers at that centre with the distances between the centres
    # not linearised: the lowest is zero in the linear model; what it is instead bounds the
    # error of the centre's position (the second-order term |c_perp|^2 / (2 r) it drops).
    with np.errstate(invalid="ignore"):
        exact = np.hypot(reach * across - x[..., None], reach * down - y[..., None]) \
            - reach + room
        lowest = np.min(np.where(active, exact, np.inf), axis=-1)  # (N, S)
        # A gap common to every step moves the centre alike and leaves the runout as it is:
        # how much it changes from step to step bounds the runout's error.
        linearisation = np.ptp(lowest, axis=-1)
    inexact = linearisation > np.maximum(LINEARISATION_LIMIT * runout, LINEARISATION_FLOOR)
    rollers_bent = _not_convex(0.5 * (diameter[:, None] + error), order[..., None],
                               amplitude[..., None]).any(axis=-1)
    inner_bent = _not_convex(0.5 * inner, inner_set[0][:, 0, 0], inner_set[1][:, 0, 0])
    # Too few steps for the fastest component of the centre's motion.
    undersampled = steps_per_revolution < STEPS_PER_PERIOD * _fastest_component(
        roller_count, diameter, pitch, roller_spin, order, amplitude, inner_set, outer_set)
    outside = squeezed | inexact | rollers_bent | inner_bent | undersampled
    # The play the largest roller leaves: undersize rollers widen the clearance.
    loose = clearance_beyond_bearings(outer - inner - 2.0 * (diameter + error.max(axis=-1)),
                                      inner)
    return {
        "runout": runout,
        "vertical_runout": y.max(axis=-1) - y.min(axis=-1),
        "center_x": x, "center_y": y,
        "rotation_angle": np.broadcast_to(rotation, x.shape),
        "assembly_order": order_index + 1.0,
        "status": combine_status(np.where(found, CONVERGED, NOT_CONVERGED),
                                 np.where(outside, OUT_OF_VALIDITY, CONVERGED),
                                 np.where(loose, OUT_OF_VALIDITY, CONVERGED)),
    }


def _fastest_component(roller_count, diameter, pitch, spin, roller_order, roller_amplitude,
                       inner_set, outer_set):
    """Frequency of the fastest component of each point's centre motion, in cycles per
    inner-ring revolution, ``(N,)``: the rollers passing the bottom ``Z f_c``
    (``f_c = (1 - D/d_m)/2``, the cage's; with any error, and with clearance alone), and the
    harmonics that have an amplitude as the rollers meet them: the inner raceway's
    ``n (1 - f_c)``, the outer's ``n f_c``, a roller's ``n`` times its spin (eq. 1, in the
    frame ``spin`` names)."""
    cage = 0.5 * (1.0 - diameter / pitch)
    spin_rate = np.abs(roller_angles(np.ones(1), 1, diameter, pitch, spin)[1])

    def highest(order, amplitude):  # the largest order that has an amplitude
        return np.max(np.where(np.asarray(amplitude) != 0.0, np.abs(order), 0.0), axis=-1)

    inner = highest(inner_set[0][:, 0, 0], inner_set[1][:, 0, 0])
    outer = highest(outer_set[0][:, 0, 0], outer_set[1][:, 0, 0])
    return np.maximum.reduce([roller_count * cage, inner * (1.0 - cage), outer * cage,
                              highest(roller_order, roller_amplitude) * spin_rate])


def _not_convex(radius, order, amplitude):
    """Where a profile ``r = R + sum C cos(n theta + psi)`` (``radius`` ``R``, harmonics along
    the last axis of ``order`` and ``amplitude``) may curve the wrong way: a single harmonic
    does at its troughs where ``C (n^2 + 1) >= R`` (for n = 1 the limacon's ``C >= R/2``), and
    a contact there leaves the radius line the model takes it on."""
    return np.sum(np.asarray(amplitude) * (np.asarray(order) ** 2 + 1.0), axis=-1) >= radius


def alternating_by_size(error):
    """Which roller goes to each position, ``(N, Z)``: smallest, largest, second smallest,
    second largest... of each row of diameter errors (paper 004, Table 3 row 20), ties in the
    given order."""
    ascending = np.argsort(error, axis=-1, kind="stable")
    count = error.shape[-1]
    positions = np.empty(count, dtype=int)
    positions[0::2] = np.arange((count + 1) // 2)  # the smaller half, rising
    positions[1::2] = count - 1 - np.arange(count // 2)  # the larger half, falling
    return ascending[..., positions]


def _fits(inner_raceway_diameter, outer_raceway_diameter, roller_diameter, roller_count):
    return elements_fit(roller_count, 0.5 * (inner_raceway_diameter + outer_raceway_diameter),
                        roller_diameter)


def _rotation_angles(size, steps_per_revolution):
    """The rotation of every step [rad] when one step count serves the whole grid."""
    return 2.0 * np.pi * np.arange(size) / steps_per_revolution


def _clearance(inner_raceway_diameter, outer_raceway_diameter, roller_diameter):
    # Zero clearance written in mm may come out a few 1e-18 m negative in metres.
    clearance = outer_raceway_diameter - inner_raceway_diameter - 2.0 * roller_diameter
    return clearance >= -_ROUNDING * outer_raceway_diameter


def _clearance_below_roller(inner_raceway_diameter, outer_raceway_diameter, roller_diameter):
    return clearance_below_roller(
        outer_raceway_diameter - inner_raceway_diameter - 2.0 * roller_diameter, roller_diameter)


def _rollers_have_radius(roller_diameter, roller_diameter_error, roller_roundness_amplitude):
    # Every roller's radius stays positive whatever order or phase puts its largest negative
    # error against its deepest trough: D/2 + min(error)/2 - max(C) > 0.
    diameter = np.asarray(roller_diameter, dtype=float)
    error, amplitude = (np.asarray(a, dtype=float) for a in (roller_diameter_error,
                                                             roller_roundness_amplitude))
    error, amplitude = (a.min(axis=-1) if a.ndim > diameter.ndim else a for a in (
        error, -amplitude))
    return 0.5 * (diameter + error) + amplitude > 0.0


def _raceways_have_radius(inner_raceway_diameter, outer_raceway_diameter,
                          inner_roundness_amplitude, outer_roundness_amplitude):
    def troughs(amplitude, reference):  # the harmonics' amplitudes summed, per point
        amplitude = np.asarray(amplitude, dtype=float)
        return amplitude.sum(axis=-1) if amplitude.ndim > np.ndim(reference) else amplitude
    return (troughs(inner_roundness_amplitude, inner_raceway_diameter)
            < 0.5 * np.asarray(inner_raceway_diameter)) & (
        troughs(outer_roundness_amplitude, outer_raceway_diameter)
        < 0.5 * np.asarray(outer_raceway_diameter))


def _whole_orders(roller_roundness_order, inner_roundness_order, outer_roundness_order):
    return all(np.all(np.asarray(order) == np.round(order)) for order in (
        roller_roundness_order, inner_roundness_order, outer_roundness_order))


def _roundness(part: str, dims: tuple, per: str):
    return (
        Input(f"{part}_roundness_order", "1", f"{per} harmonic order n of the {part} profile "
              "(0: round)", default=0.0, kind="number", minimum=0.0, dims=dims, broadcast=True,
              label=f"{part} roundness order"),
        Input(f"{part}_roundness_amplitude", "um", f"{per} amplitude C of the {part} radius",
              default=0.0, minimum=0.0, dims=dims, broadcast=True,
              label=f"{part} roundness amplitude"),
        Input(f"{part}_roundness_phase", "deg", f"{per} phase psi of the {part} harmonic",
              default=0.0, dims=dims, broadcast=True, label=f"{part} roundness phase"),
    )


MODELS = [Model(
    name="crb_runout",
    function=crb_runout,
    summary="Cylindrical roller bearing, unloaded at low speed: inner-ring runout from the "
            "roundness and size errors of rollers and raceways.",
    reference="Paper 004, Influence of geometric error of rollers on rotational accuracy of "
              "cylindrical roller bearings, eq. 1-6, section 1.4",
    version="6",
    inputs=(
        Input("inner_raceway_diameter", "mm", "inner raceway diameter di", minimum=0.0,
              exclusive_minimum=True),
        Input("outer_raceway_diameter", "mm", "outer raceway diameter de", minimum=0.0,
              exclusive_minimum=True),
        Input("roller_diameter", "mm", "nominal roller diameter D", minimum=0.0,
              exclusive_minimum=True),
        Input("roller_count", "1", "number of rollers Z", kind="count", minimum=5, maximum=1000),
        Input("roller_diameter_error", "um", "each roller's diameter minus D", default=0.0,
              dims=("roller",), broadcast=True),
        *_roundness("roller", ("roller",), "each roller's"),
        *_roundness("inner", ("inner_harmonic",), "per harmonic:"),
        *_roundness("outer", ("outer_harmonic",), "per harmonic:"),
        Input("revolutions", "1", "inner-ring revolutions computed", default=3, kind="count",
              minimum=1, maximum=1000),
        Input("steps_per_revolution", "1", "rotation steps per revolution", default=360,
              kind="count", minimum=8, maximum=1_000_000),
        Input("roller_spin", "", "absolute: spin in the translating frame of eq. 6; paper: "
              "eq. 1 as printed (spin relative to the cage)", default="absolute",
              kind="choice", choices=SPINS),
        Input("phase_seed", "1", "0: roller phases as given; else drawn at random from this "
              "seed", default=0, kind="count", minimum=0,
              label="phase seed"),
        Input("order_seed", "1", "0: diameter errors in the order given; else shuffled by "
              "this seed", default=0, kind="count", minimum=0,
              label="order seed"),
        Input("roller_arrangement", "", "as_given: rollers in the order given; alternating: "
              "sorted by diameter error, smallest, largest, second smallest... (selective "
              "assembly)", default="as_given", kind="choice", choices=ARRANGEMENTS),
    ),
    outputs=(
        Output("runout", "um", "largest minus smallest distance between the ring centres",
               label="runout"),
        Output("vertical_runout", "um", "largest minus smallest height of the inner-ring "
               "centre",
               label="vertical runout"),
        Output("center_x", "um", "horizontal position of the inner-ring centre",
               dims=("angle",),
               label="inner-ring centre x"),
        Output("center_y", "um", "vertical position of the inner-ring centre", dims=("angle",),
               label="inner-ring centre y"),
        Output("rotation_angle", "deg", "inner-ring rotation alpha", dims=("angle",)),
        Output("assembly_order", "1", "which of the given diameter errors each roller position "
               "has", dims=("roller",),
               label="assembly order", dtype="int"),
    ),
    dim_sizes={"angle": "revolutions*steps_per_revolution", "roller": "roller_count"},
    dim_coordinates={"angle": DimCoordinate(("steps_per_revolution",), _rotation_angles, "deg",
                                            "inner-ring rotation")},
    constraints=(
        Constraint(("inner_raceway_diameter", "outer_raceway_diameter", "roller_diameter",
                    "roller_count"), _fits, "the rollers do not fit on the pitch circle"),
        Constraint(("inner_raceway_diameter", "outer_raceway_diameter", "roller_diameter"),
                   _clearance, "outer_raceway_diameter - inner_raceway_diameter - 2 "
                   "roller_diameter (the clearance) must not be negative: the model is "
                   "unloaded"),
        Constraint(("inner_raceway_diameter", "outer_raceway_diameter", "roller_diameter"),
                   _clearance_below_roller, "the clearance (outer_raceway_diameter - "
                   "inner_raceway_diameter - 2 roller_diameter) must be smaller than the roller "
                   "diameter"),
        Constraint(("roller_roundness_order", "inner_roundness_order", "outer_roundness_order"),
                   _whole_orders, "roundness orders must be whole numbers"),
        Constraint(("roller_diameter", "roller_diameter_error", "roller_roundness_amplitude"),
                   _rollers_have_radius, "a roller's radius would be negative: "
                   "roller_roundness_amplitude must stay below (roller_diameter + "
                   "roller_diameter_error) / 2 for every roller"),
        Constraint(("inner_raceway_diameter", "outer_raceway_diameter",
                    "inner_roundness_amplitude", "outer_roundness_amplitude"),
                   _raceways_have_radius, "a raceway's radius would be negative: the sum of "
                   "its roundness amplitudes must stay below half its diameter"),
    ),
    seconds_per_point=2.7e-3,  # measured by benchmarks/declared_costs.py
    points_per_call=8,
    validity="with the centre found, a roller without room between the rings (a preload: "
             "the model is unloaded); resting rollers' gaps that vary from step to step by "
             "more than 1 % of the runout and 0.01 um with the distances between the centres "
             "not linearised (paper 004's linear contact conditions, section 1.4, take "
             "micrometre errors against radii of centimetres); a roller or "
             "inner raceway profile that is not convex, C (n^2 + 1) >= R (a contact off the "
             "radius line); fewer than 30 rotation steps per period of the fastest component "
             "of the centre's motion: the rollers passing the bottom, Z (1 - D/dm)/2 per "
             "revolution, an inner raceway's harmonic n (1 + D/dm)/2, an outer one's "
             "n (1 - D/dm)/2, a roller's n times its spin (the sampled runouts converge as "
             "1/steps: from 30 on within 3.3 % and 0.09 um in our check, 8 steps a revolution "
             f"for an order of 14 gave half the runout); whatever the outcome, "
             f"{CLEARANCE_VALIDITY} (paper 004's NU208: 0.05-0.08 mm)",
)]
