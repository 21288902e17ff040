"""Timing in interleaved pairs, shared by the benchmarks that compare a model with a baseline.

Others share the machine's cores: each pair runs the two things compared one after the other,
so that a change of load slows both alike, and the median of the pairs' ratios is reported
with the load average at the start.
"""
import os
import statistics
import time

PAIRS = 9
SECONDS = 0.3  # of each side's runs in a pair


def timed(work, seconds=SECONDS, clock=time.perf_counter) -> float:
    """Seconds per call of ``work`` on ``clock``, called at least once and until ``seconds``
    have passed."""
    calls, start = 0, clock()
    while calls == 0 or clock() - start < seconds:
        work()
        calls += 1
    return (clock() - start) / calls


def interleaved(measured, baseline, pairs=PAIRS, clock=time.perf_counter, fixed=0.0):
    """``(median ratio, lowest, highest, measured s/call, baseline s/call, load average)``
    of ``measured`` over ``baseline`` (callables), timed in ``pairs`` pairs on ``clock``
    (``time.process_time``: this process's CPU time, which others' load disturbs less);
    ``fixed`` seconds are subtracted from each of ``measured``'s calls."""
    load = os.getloadavg()
    ours, theirs = [], []
    for _ in range(pairs):
        ours.append(timed(measured, clock=clock) - fixed)
        theirs.append(timed(baseline, clock=clock))
    ratios = [a / b for a, b in zip(ours, theirs)]
    return (statistics.median(ratios), min(ratios), max(ratios), statistics.median(ours),
            statistics.median(theirs), load)


def ratio_line(result, goal: str) -> str:
    """The ``ratio:`` line of :func:`interleaved`'s result for run_all.py's table."""
    ratio, lowest, highest, _, _, load = result
    return (f"  ratio: {ratio:.2f}x (goal: {goal}); pairs {lowest:.2f}-{highest:.2f}x, "
            f"load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
