"""The equilibrium of every point of :func:`models.cylindrical.crb_radial`, compiled.

The ring's radial balance is solved one point after the other (:func:`ring_balances`), so a
point's data stay at hand; at each radial displacement it tries, every roller's balance
``Qo(total - x) = Qt(x) + Fc`` is solved for its inner approach ``x``: the hot loop of the
model. It runs one roller at a time, each slice summed only while it touches (the roller's
gaps are sorted) and the slices' ``(delta - c)^(1/9)`` of a contact taken at once by a loop of
plain arithmetic that the compiler vectorises. ``error_model="numpy"`` keeps division checks out of
the loops. Imported only when a crb_radial point is solved (numba costs half a second to
import); ``cache=True`` keeps the compiled code, once per machine (:mod:`.compiled_cache`),
so workers load it.
"""
from __future__ import annotations

import math

import numpy as np

from .compiled_cache import njit
from .contact import LINE_CONTACT_EXPONENT

N = LINE_CONTACT_EXPONENT
#: Iterations of a roller's solve before it is given up, as ``solve_increasing``'s default.
MAX_ITER = 200
# x^(-1/9) from the bits of x: its exponent field divided by -9 around this constant, within
# 3 % for every normal x; four division-free Newton steps then take it to full precision and
# one Newton step on x^(1/9) itself brings it within two ulps of the exact root.
_ROOT_MAGIC = 5118851384464337920


@njit(cache=True, error_model="numpy")
def ninth_roots(values, roots, count):
    """``roots[:count] = values[:count] ** (1/9)`` for positive normal ``values``, in plain
    arithmetic (``pow`` is a call the compiler cannot vectorise)."""
    bits, guess = values.view(np.int64), roots.view(np.int64)
    for i in range(count):
        guess[i] = _ROOT_MAGIC - bits[i] // 9
    for i in range(count):
        x, r = values[i], roots[i]
        for _ in range(4):  # r -> x^(-1/9), quadratically
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
def sliced_contact(approach, gaps, counts, slices, constant, by_loaded, work, roots):
    """:func:`models.contact.sliced_line_contact` of one contact whose ``gaps`` are sorted:
    load and stiffness [N, N/m]. ``slices`` is ``counts.sum()``; ``by_loaded``: the paper's
    law (the constant shared by the loaded slices)."""
    touching, loaded = 0, 0.0
    while touching < gaps.size and gaps[touching] < approach:
        work[touching] = approach - gaps[touching]
        loaded += counts[touching]
        touching += 1
    ninth_roots(work, roots, touching)
    load_sum = slope_sum = 0.0
    for i in range(touching):
        term = roots[i] * counts[i]
        load_sum += work[i] * term
        slope_sum += term
    divisor = (loaded if loaded > 0.0 else 1.0) if by_loaded else slices
    scale = constant / divisor
    return scale * load_sum, scale * N * slope_sum


@njit(cache=True, error_model="numpy")
def start_solve(state, lower, upper, start, xtol):
    """Bracket, tolerance and first point of one entry of
    :func:`models.solvers.solve_increasing`, in ``state`` (8 numbers)."""
    state[0], state[1], state[2], state[3], state[4] = lower, upper, lower, upper, xtol
    state[5] = state[6] = 0.0  # lower end seen, upper end seen
    state[7] = 0.0 if upper - lower > xtol else 1.0  # pinned
    return min(max(start, lower), upper)


@njit(cache=True, error_model="numpy")
def newton_step(state, x, value, slope):
    """One iteration of :func:`models.solvers.solve_increasing` for one entry, with its rules
    (Newton inside the bracket, else bisection; an unevaluated end probed before ending on it;
    no root in the bracket, or a residual that is not finite, is not converged). Returns the
    next ``x`` (the root once done), whether the entry is done and whether it converged."""
    lower, upper, first_lower, first_upper, xtol = (state[0], state[1], state[2], state[3],
                                                    state[4])
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
def bearing_balance(displacement, cos, half_clearance, floor, free, gaps, counts, slices, k,
                    fc, by_loaded, crowned_outer, xtol, split, roller_load, deflection, work,
                    roots, state):
    """:func:`roller_balances` of one bearing at one displacement, its arrays its own rows
    (``cos``, ``split``, ``roller_load``, ``deflection`` ``(Z, ...)``; ``floor``, ``free``,
    ``gaps`` ``(1 or Z, ...)``); ``work``, ``roots`` ``(m,)`` and ``state`` ``(8,)`` scratch.
    Returns the radial load, its stiffness and whether every roller converged."""
    straight, one = np.zeros(1), np.ones(1)
    load_sum = stiffness_sum = 0.0
    converged = True
    for j in range(cos.size):
        c = cos[j]
        # In total_approach's order, so that both give the same bits.
        reach = displacement * c - half_clearance
        reach = reach - 2.0 * floor[j if floor.size > 1 else 0]
        spare = free[j if free.size > 1 else 0]
        room = reach - spare
        roller_load[j], deflection[j] = 0.0, room
        if not room > 0.0:
            continue
        own = gaps[j if gaps.shape[0] > 1 else 0]
        if own[-1] != own[-1]:  # a NaN gap (NaN sorts last): no balance
            roller_load[j] = deflection[j] = np.nan
            converged = False
            continue
        # A first-order prediction of the split from the last solution: what the total
        # gained, shared as the contacts' stiffnesses share it. The paper's law, whose
        # load drops each time a slice comes into contact, may balance a roller at
        # several splits: there the start stays the last split's fraction of the room,
        # which finds the balance the model has always found.
        last, last_total, share = split[j, 0], split[j, 1], split[j, 2]
        if not math.isfinite(last):
            start = 0.5 * room
        elif by_loaded:
            start = last / (last_total - spare) * room
        else:
            start = last + share * (reach - last_total)
        x = start_solve(state, 0.0, room, start, xtol * room)
        qi = ki = ko = kt = np.nan
        done = ok = False
        for _ in range(MAX_ITER):
            qi, ki = sliced_contact(x, own, counts, slices, k, by_loaded, work, roots)
            if crowned_outer:
                qo, ko = sliced_contact(reach - x, own, counts, slices, k, by_loaded, work,
                                        roots)
                qt, kt = qi, ki
            else:
                qo, ko = sliced_contact(reach - x, straight, one, 1.0, k, False, work, roots)
                qt, kt = sliced_contact(x, straight, one, 1.0, k, False, work, roots)
            x, done, ok = newton_step(state, x, qt + fc - qo, kt + ko)
            if done:
                break
        converged = converged and ok
        roller_load[j], deflection[j] = qi, x
        # Series contacts: dQi/d(total) = Qi' Qo' / (Qo' + Qt') (eq. 14, generalised).
        stiffness = ki * ko / (ko + kt)
        if stiffness != stiffness:  # 0/0 just at contact
            stiffness = 0.0
        split[j, 0], split[j, 1] = x, reach
        split[j, 2] = ko / (ko + kt) if ko + kt > 0.0 else 1.0
        load_sum += qi * c
        stiffness_sum += stiffness * (c * c)  # eq. 13-16
    return load_sum, stiffness_sum, converged


@njit(cache=True, error_model="numpy")
def roller_balances(displacement, points, cos, half_clearance, floor, free, gaps, counts,
                    constant, centrifugal, by_loaded, crowned_outer, xtol, split, roller_load,
                    deflection):
    """Solve the force balance of every roller of the bearings ``points`` at the radial
    displacements ``displacement`` (``(p,)`` both) and sum the rollers' loads on the ring.

    Parameters
    ----------
    cos, half_clearance, floor, free : numpy.ndarray
        Of every bearing: ``cos(phi_j)`` ``(P, Z)``; ``P_d/2`` ``(P,)``; each roller's
        smallest gap from its middle's (tilt; ``(P, 1)`` zeros without) and the outer
        approach of a free roller [m], ``(P, 1 or Z)``. A roller's total approach at its
        deepest slice is ``delta_r cos(phi_j) - P_d/2 - 2 floor`` (eq. 1); it is loaded where
        that exceeds ``free``.
    gaps : numpy.ndarray
        ``(P, 1 or Z, m)`` every roller's slice gaps in rising order [m].
    counts : numpy.ndarray
        ``(m,)`` slices per gap.
    constant, centrifugal : numpy.ndarray
        ``(P,)`` ``K`` [N/m^n] and ``Fc`` [N].
    by_loaded : bool
        The paper's slice law (eq. 9 as printed) rather than the uniform one.
    crowned_outer : bool
        Both contacts the same sliced crowned contact, the roller's balance
        ``Qo(total - x) = Qi(x) + Fc``; else eq. 6 of paper 000: the outer contact a straight
        roller, ``Qo = K delta_o^n``, balanced against ``Qt = K x^n`` rather than the crowned
        ``Qi`` of eq. 9.
    xtol : float
        Tolerance of a roller's inner approach relative to the approach it has to share [-].
    split : numpy.ndarray
        ``(P, Z, 3)`` start of each roller: its inner approach, total and ``dx/d(total)`` at its
        last solution (NaN: none yet, start halfway); updated with the solutions. A roller
        starts from that solution moved along the derivative (the paper's law: from its
        fraction of the room).
    roller_load, deflection : numpy.ndarray
        ``(P, Z)``, their rows ``points`` filled: ``Qi`` [N] and the inner approach [m]
        (negative, its gap, where the roller is not loaded).

    Returns
    -------
    radial_load, radial_stiffness : numpy.ndarray
        ``(p,)`` ``F_r = sum Qi_j cos(phi_j)`` (eq. 10) [N] and ``dF_r/d delta_r`` [N/m].
    converged : numpy.ndarray of bool
        ``(p,)`` every loaded roller's balance converged.
    """
    slices = counts.sum()
    work, roots = np.empty(gaps.shape[-1]), np.empty(gaps.shape[-1])
    state = np.empty(8)
    radial_load, radial_stiffness = np.empty(points.size), np.empty(points.size)
    converged = np.ones(points.size, dtype=np.bool_)
    for i in range(points.size):
        point = points[i]
        radial_load[i], radial_stiffness[i], converged[i] = bearing_balance(
            displacement[i], cos[point], half_clearance[point], floor[point], free[point],
            gaps[point], counts, slices, constant[point], centrifugal[point], by_loaded,
            crowned_outer, xtol, split[point], roller_load[point], deflection[point], work,
            roots, state)
    return radial_load, radial_stiffness, converged


@njit(cache=True, error_model="numpy")
def ring_balances(load, lower, upper, preloaded, perturbation, cos, half_clearance, floor,
                  free, gaps, counts, constant, centrifugal, by_loaded, crowned_outer, xtol,
                  split, displacement, radial_load, radial_stiffness, converged,
                  rollers_converged, roller_load, deflection, perturbed_load,
                  perturbed_stiffness, max_iter):
    """The ring's radial balance ``F_r(delta_r) = load`` of every bearing, point by point: the
    safeguarded Newton of :func:`models.solvers.solve_increasing` (one entry, started at
    ``upper``, to ``xtol`` relative to it, given up after ``max_iter`` iterations) around
    :func:`bearing_balance`, each point's data at hand while it is solved.

    ``load``, ``lower``, ``upper`` ``(P,)``: the load and the bracket; where ``preloaded``,
    the upper end is first doubled (up to 64 times, the lower end following) until the
    rollers carry the load there. ``perturbation`` ``(P,)``: where finite, the load and
    stiffness with the ring moved on by it from the solution (from each roller's solved
    split) go to ``perturbed_load``, ``perturbed_stiffness`` (left as they are elsewhere).
    The other arrays are :func:`roller_balances`'; filled: ``displacement``, ``radial_load``,
    ``radial_stiffness``, ``converged`` (the ring's solve) and ``rollers_converged`` (every
    roller's balance at every displacement tried) ``(P,)``, ``roller_load`` and
    ``deflection`` ``(P, Z)`` at the solution, ``split`` ``(P, Z, 3)`` (NaN on entry) at the
    solution.
    """
    slices = counts.sum()
    rollers = cos.shape[1]
    work, roots = np.empty(gaps.shape[-1]), np.empty(gaps.shape[-1])
    state, ring = np.empty(8), np.empty(8)
    spare_load, spare_deflection = np.empty(rollers), np.empty(rollers)
    moved = np.empty((rollers, 3))
    for p in range(load.size):
        args = (cos[p], half_clearance[p], floor[p], free[p], gaps[p], counts, slices,
                constant[p], centrifugal[p], by_loaded, crowned_outer, xtol)
        low, high = lower[p], upper[p]
        if preloaded[p]:  # rollers opposite the load push back: widen until it holds
            for _ in range(64):
                pushed = bearing_balance(high, *args, split[p], spare_load, spare_deflection,
                                         work, roots, state)[0]
                if not pushed < load[p]:
                    break
                low, high = high, 2.0 * high
        d = start_solve(ring, low, high, high, xtol * high)
        rollers_ok, ok = True, False
        for _ in range(max_iter):
            radial, stiffness, balanced = bearing_balance(d, *args, split[p], roller_load[p],
                                                          deflection[p], work, roots, state)
            radial_load[p], radial_stiffness[p] = radial, stiffness
            rollers_ok = rollers_ok and balanced
            d, done, ok = newton_step(ring, d, radial - load[p], stiffness)
            if done:
                break
        displacement[p], converged[p], rollers_converged[p] = d, ok, rollers_ok
        if math.isfinite(perturbation[p]):
            for j in range(rollers):  # element by element: a copy of arrays compiles slower
                for k in range(3):
                    moved[j, k] = split[p, j, k]
            perturbed_load[p], perturbed_stiffness[p], _ = bearing_balance(
                d + perturbation[p], *args, moved, spare_load, spare_deflection, work, roots,
                state)


@njit(cache=True, error_model="numpy")
def free_outer_approaches(gaps, counts, constant, centrifugal, by_loaded, upper, xtol,
                          approach, converged, max_iter):
    """Outer approach of a roller held by its centrifugal force alone, ``Qo(a) = Fc``.

    For every row of ``gaps`` (``(P, 1 or Z, m)``, sorted) whose bearing spins
    (``centrifugal > 0``), solved in ``[0, upper]`` (``(P,)``, where every slice already
    touches) to ``xtol`` relative to ``upper`` (given up after ``max_iter`` iterations):
    ``approach`` and ``converged`` (``(P, 1 or Z)``) are set there and left as they are
    elsewhere.
    """
    slices = counts.sum()
    work, roots = np.empty(gaps.shape[-1]), np.empty(gaps.shape[-1])
    state = np.empty(8)
    for p in range(gaps.shape[0]):
        fc, k, top = centrifugal[p], constant[p], upper[p]
        if not fc > 0.0:
            continue
        for r in range(gaps.shape[1]):
            if not math.isfinite(top):
                approach[p, r], converged[p, r] = np.nan, False
                continue
            a = start_solve(state, 0.0, top, 0.5 * top, xtol * top)
            ok = False
            for _ in range(max_iter):
                load, stiffness = sliced_contact(a, gaps[p, r], counts, slices, k, by_loaded,
                                                 work, roots)
                a, done, ok = newton_step(state, a, load - fc, stiffness)
                if done:
                    break
            approach[p, r], converged[p, r] = a, ok


@njit(cache=True, error_model="numpy")
def slice_sums(approach, crown, tilt, floor, shape, position, counts, by_loaded, rising,
               sums):
    """What a slicing gives each of ``n`` contacts, in units of its constant ``K``.

    Contact ``i`` has the approach ``approach[i]`` and slices of ``counts`` whose gaps are
    ``crown[i] shape - tilt[i] position - floor[i]`` (``(n,)`` each, ``(m,)`` each; with
    ``rising``, the distinct slices of aligned rollers, ``shape`` rises and the loop stops at
    the first slice that does not touch). Row ``i`` of ``sums`` ``(n, 6)`` takes its load
    ``Q/K``, stiffness ``(dQ/d delta)/K``, the deepest slice's penetration, the share of
    ``K/l`` a slice's line load takes per penetration to the ``n``, the laminae's life sum
    ``k^(7/2) divisor^(-9/2) sum pen^5`` (ISO/TS 16281's ``sum (q/q_c)^(9/2)`` up to a
    factor common to every slicing: the lamina ratings go as ``k^(-7/9)``) and its slope
    along the approach. ``by_loaded``: the paper's law, the constant shared by the loaded
    slices."""
    rows, size = approach.size, shape.size
    work, roots, weights = np.empty(size), np.empty(size), np.empty(size)
    slices = counts.sum()
    for i in range(rows):
        touching, loaded, deepest = 0, 0.0, 0.0
        for j in range(size):
            penetration = approach[i] - (crown[i] * shape[j] - tilt[i] * position[j]
                                         - floor[i])
            if penetration > 1e-300:  # normal numbers only: ninth_roots needs them
                work[touching], weights[touching] = penetration, counts[j]
                touching += 1
                loaded += counts[j]
                deepest = max(deepest, penetration)
            elif rising:
                break
        ninth_roots(work, roots, touching)
        load = stiffness = life = slope = 0.0
        for t in range(touching):
            fourth = work[t] * work[t]
            fourth = fourth * fourth * weights[t]
            load += work[t] * roots[t] * weights[t]
            stiffness += roots[t] * weights[t]
            life += fourth * work[t]
            slope += fourth
        divisor = (loaded if loaded > 0.0 else 1.0) if by_loaded else slices
        scale = slices**3.5 / divisor**4.5
        sums[i, 0], sums[i, 1] = load / divisor, N * stiffness / divisor
        sums[i, 2], sums[i, 3] = deepest, slices / divisor
        sums[i, 4], sums[i, 5] = scale * life, 5.0 * scale * slope


@njit(cache=True, error_model="numpy")
def tilted_contact_sums(inner, reach, crown, shape, tilt, floor, position, half_length,
                        constant, by_loaded, sums):
    """What both contacts of every tilted roller carry at its solution, for a shaft's
    tangent: ``inner`` and ``reach`` ``(n, Z)`` are each roller's inner and total approach
    at its deepest slice [m] (:meth:`models.cylindrical._RollerSet.loads`' and
    ``total_approach``'s), its slices' gaps ``crown shape - tilt position - floor``
    (``crown``, ``half_length`` ``(n,)``; ``tilt``, ``floor`` ``(n, Z)``; ``shape``,
    ``position`` ``(m,)``, the latter along the half length). ``sums`` ``(n, Z, 2, 6)``
    takes per contact (inner, outer) its load ``Q`` [N], ``dQ/d approach`` [N/m], ``dQ/dm``
    [N/rad] (each slice's penetration grows by ``x_k / 2`` per radian of the ring's tilt
    ``m`` across the roller), the moment ``M = sum q_k x_k`` [N m], ``dM/d approach`` [N] and
    ``dM/dm`` [N m/rad], with ``q_k = (K / k) p_k^(10/9)`` (``by_loaded``: ``k`` the loaded
    slices, the paper's law; else all of them). An unloaded roller's outer contact is left
    at zero: without an inner load it adds no terms."""
    size = shape.size
    work, roots, where = np.empty(size), np.empty(size), np.empty(size)
    for i in range(inner.shape[0]):
        for j in range(inner.shape[1]):
            for contact in range(2):
                if contact == 1 and sums[i, j, 0, 1] == 0.0:  # an unloaded roller: no terms
                    for term in range(6):
                        sums[i, j, 1, term] = 0.0
                    break
                approach = inner[i, j] if contact == 0 else reach[i, j] - inner[i, j]
                touching = 0
                for k in range(size):
                    penetration = approach - (crown[i] * shape[k] - tilt[i, j] * position[k]
                                              - floor[i, j])
                    if penetration > 1e-300:  # normal numbers only: ninth_roots needs them
                        work[touching] = penetration
                        where[touching] = position[k] * half_length[i]
                        touching += 1
                ninth_roots(work, roots, touching)
                load = slope = by_tilt = moment = moment_slope = moment_tilt = 0.0
                for t in range(touching):
                    x = where[t]
                    stiffness = N * roots[t]
                    slice_load = work[t] * roots[t]
                    load += slice_load
                    slope += stiffness
                    by_tilt += 0.5 * stiffness * x
                    moment += slice_load * x
                    moment_slope += stiffness * x
                    moment_tilt += 0.5 * stiffness * x * x
                divisor = (touching if touching > 0 else 1) if by_loaded else size
                scale = constant[i] / divisor
                sums[i, j, contact, 0] = scale * load
                sums[i, j, contact, 1] = scale * slope
                sums[i, j, contact, 2] = scale * by_tilt
                sums[i, j, contact, 3] = scale * moment
                sums[i, j, contact, 4] = scale * moment_slope
                sums[i, j, contact, 5] = scale * moment_tilt
