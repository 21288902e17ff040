"""crb_radial against a compiled per-point kernel of the same equilibrium, at the sweeps' block.

The kernel, written here with numba, is what a user would write instead of the model: one
point at a time, each roller's force balance and the ring's radial balance solved by the
model's safeguarded Newton (``models.solvers.solve_increasing``, one entry), from the model's
starts (a roller's from a first-order prediction of its split: its last solution moved by what
its total approach gained, shared as its contacts' stiffnesses share it) and to its
tolerances, on the same equations (sliced crowned rollers with their distinct gaps,
centrifugal force, clearance; no misalignment). It computes what the model
computes for such a point apart from the lives (the grid gives no load rating): the
displacement, the implicit and the forward-difference stiffness, the roller loads and inner
approaches, each roller's largest contact pressure and the status, with every validity check
the status holds: pressure, approach, the forward difference's step and the slicing (the
model's estimate against four times as many slices, skipped where the point is already out of
validity). Each slice is summed only
while it touches (the gaps are sorted), and its ``(delta - c)^(1/9)`` is taken for a whole
roller at once by a loop the compiler vectorises, ``error_model="numpy"`` keeping division
checks out of it (numpy's own SIMD ``pow`` is otherwise faster than a scalar one). The model
compiles its rollers' balances the same way (``models.cylindrical_balance``); the kernel
shares none of its code on purpose, so that a slow part of the model would not slow the
baseline alike.

Both run on one core (CPU time of this process, which others' load on the shared cores
disturbs less than wall time) on the grid of benchmarks/crb_radial_throughput.py (bearing D of
paper 000, crown, speed, clearance) with as many loads as make one block of the model's
declared ``points_per_call``: the model through the engine's chunk path
(``bearing_sweep.evaluate.evaluate_chunk``, inputs built, outputs converted) and the kernel on
the same points, in interleaved pairs. The answers are compared first (the run fails beyond
``AGREEMENT``). Prints the median of the pairs' ratios of model over kernel time (goal: within
1.2x), and the model against the per-point scipy baseline of crb_radial_throughput.py.

Then end to end: ``bearing-sweep run --workers 0`` in this process over 20 000 points (the
definition parsed, the grid's inputs built, the outputs converted, a netCDF file written and
completed), less a run's fixed cost (that of a run of 8 points), against the kernel on the same
points, in interleaved pairs on CPU time (goal: within 1.2x).
"""
import contextlib
import io
import math
import os
import sys
import tempfile
import time

import numpy as np
from numba import njit

from bearing_sweep import cli, spec
from bearing_sweep.evaluate import evaluate_chunk
from bearing_sweep.grid import Grid
from bearing_sweep.models.contact import effective_modulus, palmgren_constant
from bearing_sweep.models.cylindrical import centrifugal_force
from bearing_sweep.models.profiles import distinct_slices

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from crb_radial_throughput import GEOMETRY, MM, per_point  # noqa: E402  the scipy baseline
from pairs import interleaved, ratio_line, timed  # noqa: E402

N = 10.0 / 9.0  # line-contact exponent
XTOL = 1e-13  # relative tolerance of every solve, as the model's
MAX_ITER = 200  # as solve_increasing's
CROWN, SPEED, SLICES, DENSITY = 0.004 * MM, 5000 * 2 * np.pi / 60, 60, 7850.0
MODULUS = effective_modulus(207e9, 0.3)
PRESSURE_LIMIT, APPROACH_LIMIT, PERTURBATION_ERROR = 4000e6, 0.02, 0.02
SLICING_ERROR, REFERENCE_SLICES = 0.02, 240  # the model's check of its slicing
CLEARANCES = 4  # clearances on the grid; the loads fill the model's block
# The solves stop within XTOL (relative) of the root, each at its own last iterate: the two
# codes may stop one Newton step apart where rounding differs, and the forward-difference
# stiffness divides a difference of loads by a small step (about tenfold the loads' error).
AGREEMENT = 1e-9
PAIRS = 9
#: Points of the end-to-end runs (as the issue measured them) and their pairs.
END_TO_END_POINTS, END_TO_END_PAIRS = 20_000, 9
# Bits of x^(-1/9) from those of x (the exponent field divided by -9; 3 % at worst), then
# Newton: four steps for x^(-1/9) without division, one for x^(1/9) (within 1 ulp of pow).
ROOT_MAGIC = 5118851384464337920


@njit(cache=True, error_model="numpy")
def ninth_roots(values, roots, count):
    """``roots[:count] = values[:count] ** (1/9)`` for positive values, in a loop of plain
    arithmetic that the compiler vectorises (``pow`` is a call it cannot)."""
    bits, guess = values.view(np.int64), roots.view(np.int64)
    for i in range(count):
        guess[i] = ROOT_MAGIC - bits[i] // 9
    for i in range(count):
        x, r = values[i], roots[i]
        for _ in range(4):  # r -> x^(-1/9)
            r8 = r * r
            r8 = r8 * r8
            r8 = r8 * r8
            r = r * (10.0 - x * r8 * r) * (1.0 / 9.0)
        r8 = r * r
        r8 = r8 * r8
        y = x * r8 * r8
        y8 = y * y
        y8 = y8 * y8
        y8 = y8 * y8
        roots[i] = y - (y - x / y8) * (1.0 / 9.0)


@njit(cache=True, error_model="numpy")
def sliced_contact(approach, gaps, counts, scale, work, roots):
    """Load and stiffness of a sliced contact, ``K/k sum (delta - c)^n``: the gaps are sorted,
    so the slices that touch come first."""
    touching = 0
    while touching < gaps.size and gaps[touching] < approach:
        work[touching] = approach - gaps[touching]
        touching += 1
    ninth_roots(work, roots, touching)
    load = slope = 0.0
    for i in range(touching):
        term = roots[i] * counts[i]
        load += work[i] * term
        slope += term
    return scale * load, scale * N * slope


@njit(cache=True, error_model="numpy")
def newton_step(state, x, value, slope):
    """One iteration of ``solve_increasing`` for one entry. ``state``: lower, upper, first
    lower, first upper, tolerance, lower end seen, upper end seen, pinned. Returns the next
    ``x`` (or the root), whether the entry is done and whether it converged."""
    lower, upper, first_lower, first_upper, xtol = state[0], state[1], state[2], state[3], \
        state[4]
    finite = math.isfinite(value)
    low = x if value <= 0.0 else lower
    high = x if value >= 0.0 else upper
    if value <= 0.0:
        state[5] = 1.0
    if value >= 0.0:
        state[6] = 1.0
    newton = x - value / slope
    step_to = newton if (newton > low and newton < high) else 0.5 * (low + high)
    small = abs(newton - x) <= xtol
    done = small or abs(step_to - x) <= xtol or value == 0.0
    probe_lower = done and not small and value > 0.0 and state[5] == 0.0
    probe_upper = done and not small and value < 0.0 and state[6] == 0.0
    outside = (probe_lower and x <= first_lower) or (probe_upper and x >= first_upper)
    pinned = state[7] != 0.0
    probe = (probe_lower or probe_upper) and not outside and not pinned
    if probe_lower:
        step_to = first_lower
    if probe_upper:
        step_to = first_upper
    done = (done and not probe) or not finite
    state[0], state[1] = low, high
    if done:
        return (x if finite else np.nan), True, finite and (not outside or pinned)
    return step_to, False, False


@njit(cache=True, error_model="numpy")
def start_solve(state, lower, upper, start, xtol):
    """Bracket and first point of a solve, as ``solve_increasing`` sets them."""
    state[0], state[1], state[2], state[3], state[4] = lower, upper, lower, upper, xtol
    state[5] = state[6] = 0.0
    state[7] = 0.0 if upper - lower > xtol else 1.0
    return min(max(start, lower), upper)


@njit(cache=True, error_model="numpy")
def roller_balance(total, available, split, gaps, counts, scale, centrifugal, work, roots,
                   state):
    """Inner approach of one roller with ``Qi(x) + Fc = Qo(total - x)``; returns it, ``Qi``,
    ``dQi``, ``dQo`` at it and whether it converged. ``split``: the roller's inner approach,
    total and their derivative at its last solution (NaN: none), the model's start."""
    last, last_total, share = split[0], split[1], split[2]
    start = last + share * (total - last_total) if math.isfinite(last) else 0.5 * available
    x = start_solve(state, 0.0, available, start, XTOL * available)
    qi = ki = ko = np.nan
    for _ in range(MAX_ITER):
        qi, ki = sliced_contact(x, gaps, counts, scale, work, roots)
        qo, ko = sliced_contact(total - x, gaps, counts, scale, work, roots)
        x, done, converged = newton_step(state, x, qi + centrifugal - qo, ki + ko)
        if done:
            return x, qi, ki, ko, converged
    return x, qi, ki, ko, False


@njit(cache=True, error_model="numpy")
def bearing_loads(displacement, cos, half_clearance, free, gaps, counts, scale, centrifugal,
                  split, roller_load, deflection, work, roots, state):
    """Radial load, radial stiffness and whether every roller converged at a displacement;
    fills each roller's load and inner approach and updates its ``split``."""
    load = stiffness = 0.0
    ok = True
    for j in range(cos.size):
        total = displacement * cos[j] - half_clearance
        available = total - free
        roller_stiffness = 0.0
        if available > 0.0:
            x, qi, ki, ko, converged = roller_balance(total, available, split[j], gaps, counts,
                                                      scale, centrifugal, work, roots, state)
            split[j, 0], split[j, 1] = x, total
            split[j, 2] = ko / (ko + ki) if ko + ki > 0.0 else 1.0
            roller_load[j], deflection[j] = qi, x
            roller_stiffness = ki * ko / (ko + ki)
            if roller_stiffness != roller_stiffness:  # 0/0 just at contact
                roller_stiffness = 0.0
            ok = ok and converged
        else:
            roller_load[j], deflection[j] = 0.0, available
        load += roller_load[j] * cos[j]
        stiffness += roller_stiffness * cos[j] ** 2
    return load, stiffness, ok


@njit(cache=True, error_model="numpy")
def contact_sums(approach, gaps, counts, slices, work, roots, sums):
    """What a sliced contact gives in units of its constant: load, stiffness, deepest
    penetration, the laminae's life sum ``sum pen^5 / k`` and its slope along the approach
    (``sums[:5]``); the gaps are sorted."""
    touching = 0
    while touching < gaps.size and approach - gaps[touching] > 1e-300:
        work[touching] = approach - gaps[touching]
        touching += 1
    ninth_roots(work, roots, touching)
    load = stiffness = life = slope = 0.0
    for t in range(touching):
        fourth = work[t] * work[t]
        fourth = fourth * fourth * counts[t]
        load += work[t] * roots[t] * counts[t]
        stiffness += roots[t] * counts[t]
        life += fourth * work[t]
        slope += fourth
    sums[0], sums[1] = load / slices, N * stiffness / slices
    sums[2] = work[0] if touching else 0.0
    sums[3], sums[4] = life / slices, 5.0 * slope / slices


@njit(cache=True, error_model="numpy")
def slicing_error(inner, outer, cos, gaps, counts, fine_gaps, fine_counts, work, roots, sums,
                  inner_stiffness):
    """The model's estimate of the error the slicing leaves (its ``_RollerSet.slicing_error``
    for aligned rollers): in the loaded rollers' radial load and stiffness, the largest line
    load (as pressure) and the life sum, the ``k`` slices against ``max(4 k, 240)``, the
    finer slicing's approach also moved by one Newton step to carry the coarser's load."""
    slices, fine_slices = counts.sum(), fine_counts.sum()
    load_coarse = load_fine = radial_coarse = radial_fine = error = 0.0
    for contact in range(2):
        pressure, life = np.zeros(4), np.zeros(4)  # coarse, fine; unmoved, then moved
        for j in range(cos.size):
            if not inner[j] > 0.0:
                continue
            approach = inner[j] if contact == 0 else outer[j]
            contact_sums(approach, gaps, counts, slices, work, roots, sums[0])
            contact_sums(approach, fine_gaps, fine_counts, fine_slices, work, roots, sums[1])
            if contact == 0:
                load_coarse += cos[j] * sums[0, 0]
                load_fine += cos[j] * sums[1, 0]
                inner_stiffness[j, 0], inner_stiffness[j, 1] = sums[0, 1], sums[1, 1]
            else:  # each roller's two contacts in series
                ki, ko = inner_stiffness[j, 0], sums[0, 1]
                if ki + ko > 0.0:
                    radial_coarse += cos[j] * cos[j] * (ki * ko / (ki + ko))
                ki, ko = inner_stiffness[j, 1], sums[1, 1]
                if ki + ko > 0.0:
                    radial_fine += cos[j] * cos[j] * (ki * ko / (ki + ko))
            shift = (sums[0, 0] - sums[1, 0]) / sums[1, 1]
            if not math.isfinite(shift):
                shift = 0.0
            for moved in range(2):
                step = shift if moved else 0.0
                pressure[2 * moved] = max(pressure[2 * moved], sums[0, 2] ** N)
                pressure[2 * moved + 1] = max(pressure[2 * moved + 1],
                                              max(sums[1, 2] + step, 0.0) ** N)
                life[2 * moved] += sums[0, 3]
                life[2 * moved + 1] += sums[1, 3] + step * sums[1, 4]
        for moved in range(2):
            departure = abs(math.sqrt(pressure[2 * moved] / pressure[2 * moved + 1]) - 1.0)
            if departure > error:
                error = departure
            departure = abs((life[2 * moved] / life[2 * moved + 1]) ** (-8.0 / 9.0) - 1.0)
            if departure > error:
                error = departure
    for departure in (abs(load_coarse / load_fine - 1.0), abs(radial_coarse / radial_fine - 1.0)):
        if departure > error:
            error = departure
    return error


@njit(cache=True, error_model="numpy")
def crb_points(load, half_clearance, crown, constant, centrifugal, perturbation, cos,
               gap_shape, counts, fine_shape, fine_counts, contact_length, diameter,
               inner_curvature, outer_curvature, displacement, stiffness,
               perturbation_stiffness, loaded_rollers, roller_load, deflection, pressure,
               status):
    """The equilibrium of every point, one after the other (outputs filled in place, SI)."""
    rollers, slices = cos.size, counts.sum()
    cos_max = cos.max()
    size = max(gap_shape.size, fine_shape.size)
    work, roots = np.empty(size), np.empty(size)
    sums, inner_stiffness = np.empty((2, 5)), np.empty((rollers, 2))
    inner_approach, outer_approach = np.empty(rollers), np.empty(rollers)
    state, ring_state = np.empty(8), np.empty(8)
    split = np.empty((rollers, 3))
    spare_load, spare_deflection = np.empty(rollers), np.empty(rollers)
    for p in range(load.size):
        gaps = crown[p] * gap_shape
        scale, fc, hc = constant[p] / slices, centrifugal[p], half_clearance[p]
        # The outer approach of a roller held by its centrifugal force alone.
        plain = (fc / constant[p]) ** (1.0 / N)
        free, free_ok = 0.0, math.isfinite(plain)
        if fc > 0.0:
            upper = gaps.max() + plain
            a = start_solve(state, 0.0, upper, 0.5 * upper, XTOL * upper)
            free_ok = False
            for _ in range(MAX_ITER):
                q, k = sliced_contact(a, gaps, counts, scale, work, roots)
                a, done, free_ok = newton_step(state, a, q - fc, k)
                if done:
                    break
            free = a
        # The ring's radial balance, bracketed as the model brackets it.
        play = hc
        lower = max(play, 0.0)
        reach = hc + 2.0 * gaps.max() + 2.0 * ((load[p] / cos_max + fc) / constant[p]) ** (
            1.0 / N)
        upper = max(1.001 * reach / cos_max, lower) + 1e-12
        split[:] = np.nan
        if play < 0.0:
            for _ in range(64):
                pushed = bearing_loads(upper, cos, hc, free, gaps, counts, scale, fc, split,
                                       spare_load, spare_deflection, work, roots, state)[0]
                if pushed >= load[p]:
                    break
                lower, upper = upper, 2.0 * upper
        resting = load[p] == 0.0 and play >= 0.0
        if resting:
            lower = upper = (play + free) / cos_max
        d = start_solve(ring_state, lower, upper, upper, XTOL * upper)
        rollers_ok, converged = True, False
        radial = radial_stiffness = np.nan
        for _ in range(MAX_ITER):
            radial, radial_stiffness, ok = bearing_loads(
                d, cos, hc, free, gaps, counts, scale, fc, split, roller_load[p],
                deflection[p], work, roots, state)
            rollers_ok = rollers_ok and ok
            d, done, converged = newton_step(ring_state, d, radial - load[p], radial_stiffness)
            if done:
                break
        if resting:
            roller_load[p, :] = 0.0
            radial = radial_stiffness = 0.0
            rollers_ok = True
        perturbed, perturbed_stiffness, _ = bearing_loads(
            d + perturbation[p], cos, hc, free, gaps, counts, scale, fc, split.copy(),
            spare_load, spare_deflection, work, roots, state)
        balanced = abs(radial - load[p]) <= 1e-9 * load[p] + 1e-6
        displacement[p], stiffness[p] = d, radial_stiffness
        perturbation_stiffness[p] = (perturbed - radial) / perturbation[p]
        ok = converged and rollers_ok and balanced and free_ok and math.isfinite(d) \
            and math.isfinite(radial_stiffness) and math.isfinite(perturbation_stiffness[p])
        count = 0
        # The forward difference's estimated error, half the stiffness change over its step.
        beyond = abs(perturbed_stiffness / radial_stiffness - 1.0) / 2.0 > PERTURBATION_ERROR
        for j in range(rollers):
            ok = ok and math.isfinite(roller_load[p, j]) and math.isfinite(deflection[p, j])
            count += roller_load[p, j] > 1e-9 * load[p]
            total = d * cos[j] - hc
            inner = inner_approach[j] = max(deflection[p, j], 0.0)
            outer = outer_approach[j] = total - deflection[p, j] if total - free > 0.0 else free
            line_inner = constant[p] / contact_length[p] * max(inner - gaps[0], 0.0) ** N
            line_outer = constant[p] / contact_length[p] * max(outer - gaps[0], 0.0) ** N
            pressure[p, j] = max(math.sqrt(line_inner * MODULUS * inner_curvature[p] / np.pi),
                                 math.sqrt(line_outer * MODULUS * outer_curvature[p] / np.pi))
            beyond = beyond or pressure[p, j] > PRESSURE_LIMIT or \
                inner + outer > APPROACH_LIMIT * diameter[p]
        if crown[p] > 0.0 and ok and not beyond:  # slices too few for the crown
            beyond = slicing_error(inner_approach, outer_approach, cos, gaps, counts,
                                   crown[p] * fine_shape, fine_counts, work, roots, sums,
                                   inner_stiffness) > SLICING_ERROR
        loaded_rollers[p] = count
        status[p] = (4 if beyond else 0) if ok else 1
        if not ok:
            displacement[p] = stiffness[p] = perturbation_stiffness[p] = np.nan
            roller_load[p, :] = deflection[p, :] = pressure[p, :] = np.nan


def kernel(load, clearance, roller_count, pitch_diameter, roller_diameter, effective_length):
    """The kernel's outputs (SI) for the points ``load``, ``clearance`` of one bearing."""
    size = load.size
    gap_shape, counts = distinct_slices(SLICES, "logarithmic")
    fine_shape, fine_counts = distinct_slices(max(4 * SLICES, REFERENCE_SLICES), "logarithmic")
    cos = np.cos(2.0 * np.pi * np.arange(roller_count) / roller_count)
    full = np.ones(size)
    out = dict(displacement=np.empty(size), stiffness=np.empty(size),
               perturbation_stiffness=np.empty(size),
               loaded_rollers=np.empty(size, np.int64),
               roller_load=np.empty((size, roller_count)),
               deflection=np.empty((size, roller_count)),
               pressure=np.empty((size, roller_count)), status=np.empty(size, np.int8))
    crb_points(load, 0.5 * clearance, CROWN * full,
               palmgren_constant(effective_length) * full,
               centrifugal_force(roller_diameter, effective_length, pitch_diameter, SPEED,
                                 DENSITY) * full,
               1e-6 * full, cos, gap_shape, counts, fine_shape, fine_counts,
               effective_length * full,
               roller_diameter * full,
               (2.0 / roller_diameter + 2.0 / (pitch_diameter - roller_diameter)) * full,
               (2.0 / roller_diameter - 2.0 / (pitch_diameter + roller_diameter)) * full,
               *out.values())
    return out


def definition(points: int) -> str:
    """The throughput benchmark's bearing and grid, with enough loads for ``points``, as TOML."""
    loads = math.ceil(points / CLEARANCES)
    geometry = "\n".join(f'{name} = "{value / MM:g} mm"' for name, value in GEOMETRY.items()
                         if name != "roller_count")
    return (f'[sweep]\nmodel = "crb_radial"\n[fixed]\n'
            f'roller_count = {GEOMETRY["roller_count"]}\n{geometry}\n'
            f'crown = "{CROWN / MM * 1e3:g} um"\nspeed = "5000 rpm"\nslices = {SLICES}\n'
            'perturbation = "0.001 mm"\n'
            f'[axes]\nradial_load = {{ start = "1 kN", stop = "12 kN", num = {loads} }}\n'
            f'clearance = {{ start = "0 mm", stop = "0.04 mm", num = {CLEARANCES} }}\n')


def model_grid(points: int) -> Grid:
    """:func:`definition`'s grid."""
    return Grid.from_sweep(spec.parse(definition(points), "crb_radial_kernel"))


class InProcessRuns:
    """``bearing-sweep run DEFINITION -o OUTPUT --workers 0 --quiet`` in this process, as the
    command runs it (the definition parsed, the inputs built, the outputs converted, the
    netCDF file written and completed), each run into a fresh file of a temporary folder."""

    def __init__(self, folder: str, points: int):
        self.folder, self.runs = folder, 0
        self.definition = os.path.join(folder, f"crb_{points}.toml")
        with open(self.definition, "w") as file:
            file.write(definition(points))

    def __call__(self):
        self.runs += 1
        output = os.path.join(self.folder, f"run{self.runs}.nc")
        with contextlib.redirect_stdout(io.StringIO()) as said:  # its closing summary
            if cli.program(["run", self.definition, "-o", output, "--workers", "0", "--quiet"]):
                raise SystemExit(f"the in-process run failed: {said.getvalue()}")
        os.remove(output)


def largest_difference(model, ours) -> float:
    """Largest difference of the outputs, relative to each point's largest value of that
    output (an unloaded roller's zero load is compared against the point's loaded ones)."""
    pairs = (("radial_displacement", "displacement", 1e3),
             ("radial_stiffness", "stiffness", 1e-3),
             ("perturbation_stiffness", "perturbation_stiffness", 1e-3),
             ("roller_load", "roller_load", 1.0),
             ("inner_contact_deflection", "deflection", 1e3),
             ("max_contact_pressure", "pressure", 1e-6))
    worst = 0.0
    for name, own, factor in pairs:
        theirs, mine = model["outputs"][name], ours[own] * factor
        theirs, mine = theirs.reshape(theirs.shape[0], -1), mine.reshape(mine.shape[0], -1)
        scale = np.abs(theirs).max(axis=-1, keepdims=True)
        worst = max(worst, float(np.max(np.abs(mine - theirs) / scale)))
    assert np.array_equal(model["outputs"]["loaded_rollers"], ours["loaded_rollers"]), \
        "loaded rollers differ"
    assert np.array_equal(model["status"], ours["status"]), "statuses differ"
    return worst


def main():
    probe = model_grid(2 * CLEARANCES)  # a range needs two loads
    block = probe.model.points_per_call
    grid = model_grid(block)
    varying, _ = grid.inputs(0, grid.size)
    load, clearance = varying["radial_load"], varying["clearance"]
    points = (load, clearance, *GEOMETRY.values())

    model = evaluate_chunk(grid, 0, grid.size)  # the first calls import and compile, untimed
    ours = kernel(*points)
    worst = largest_difference(model, ours)
    if not worst <= AGREEMENT:
        raise SystemExit(f"the kernel and the model differ by {worst:.1e} (> {AGREEMENT:g})")

    timing = interleaved(lambda: evaluate_chunk(grid, 0, grid.size), lambda: kernel(*points),
                         PAIRS, time.process_time)
    # The scipy baseline takes milliseconds a point: a few of the grid's points, in pairs.
    sample = np.linspace(0, grid.size - 1, 8).astype(int)

    def scipy_sample():
        for i in sample:
            per_point(load[i], clearance[i], CROWN, SPEED, SLICES, **GEOMETRY)

    scipy_timing = interleaved(scipy_sample, lambda: evaluate_chunk(grid, 0, grid.size), 3,
                               time.process_time)

    print(f"crb_radial against a compiled per-point kernel, {grid.size} points in one block of "
          f"{block} (bearing D, k = {SLICES}, crown, speed, clearance)")
    print(f"  numba kernel baseline: {timing[4] / grid.size * 1e6:7.2f} us/point "
          f"(CPU, one core); model through evaluate_chunk: "
          f"{timing[3] / grid.size * 1e6:7.2f} us/point")
    print(f"  answers: largest relative difference {worst:.1e} (tolerance {AGREEMENT:g}); "
          f"{os.cpu_count()} cores, shared")
    print(ratio_line(timing, "within 1.2x"))
    print("crb_radial against per-point scipy, the same block")
    print(f"  per-point scipy baseline: {scipy_timing[3] / sample.size * 1e3:.2f} ms/point "
          f"({sample.size} of the points)")
    per_point_scale = grid.size / sample.size  # calls hold different numbers of points
    print(ratio_line(tuple(r * per_point_scale for r in scipy_timing[:3]) + scipy_timing[3:],
                     "at least 50x"))

    end_to_end(points_in_process=END_TO_END_POINTS)


def end_to_end(points_in_process: int):
    """The command's whole path in this process against the kernel on the same points."""
    grid = model_grid(points_in_process)
    varying, _ = grid.inputs(0, grid.size)
    points = (varying["radial_load"], varying["clearance"], *GEOMETRY.values())
    with tempfile.TemporaryDirectory() as folder:
        run, smallest = InProcessRuns(folder, grid.size), InProcessRuns(folder, 2 * CLEARANCES)
        run(), smallest()  # the first runs open what later runs reuse, untimed
        # A run's fixed cost, that of a run of a few points, is subtracted from each run.
        fixed = min(timed(smallest, clock=time.process_time) for _ in range(3))
        timing = interleaved(run, lambda: kernel(*points), END_TO_END_PAIRS, time.process_time,
                             fixed)
    print(f"crb_radial end to end in-process (bearing-sweep run --workers 0 into a netCDF "
          f"file), {grid.size} points, against the kernel on the same points")
    print(f"  numba kernel baseline: {timing[4] / grid.size * 1e6:7.2f} us/point (CPU); run: "
          f"{timing[3] / grid.size * 1e6:7.2f} us/point, fixed cost {fixed * 1e3:.0f} ms "
          "subtracted (a run of 8 points)")
    print(ratio_line(timing, "within 1.2x"))

if __name__ == "__main__":
    main()
