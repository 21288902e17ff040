"""Run every benchmark and print one table of their ratios against their baselines.

Each benchmark script prints a title line, an indented line naming its baseline, and an
indented ``ratio: Nx`` (or ``speed-up: ... Nx``) line with its goal in parentheses; a script
may print several such sections. A benchmark that fails is a row that says so. Each row
carries the machine's one-minute load average when its script started: others' work on the
same cores slows the measured and the baseline alike, but not always evenly.
"""
import os
import re
import subprocess
import sys
from pathlib import Path

SCRIPTS = ("crb_radial_throughput.py", "ball_5dof_throughput.py", "ball_5dof_kernel.py",
           "trb_load_kernel.py", "crb_runout_throughput.py", "crb_runout_kernel.py",
           "cage_slip_cost.py", "cage_dynamics_6dof_cost.py", "worker_scaling.py",
           "output_encoding.py", "declared_costs.py", "cluster_break_even.py",
           "crb_radial_kernel.py", "zarr_cluster.py", "zarr_structure.py", "startup.py",
           "operating_outputs.py", "shaft_system_cost.py")
RATIO = re.compile(r"^\s+(?:ratio|speed-up):\D*?([\d.]+)x(.*)$")
GOAL = re.compile(r"goal:?\s*([^)]*)")


def sections(text: str):
    """``(title, baseline, ratio, goal)`` for every section of a benchmark's output."""
    title = baseline = None
    for line in text.splitlines():
        if line and not line.startswith(" "):
            title, baseline = line.strip(), None
        elif "baseline" in line or "1 worker" in line:
            baseline = line.strip().split(":")[0]
        match = RATIO.match(line)
        if match:
            goal = GOAL.search(line)
            yield title, baseline or "", match.group(1), goal.group(1).strip() if goal else ""


def main():
    folder = Path(__file__).parent
    rows = []
    for script in SCRIPTS:
        load = os.getloadavg()[0]
        done = subprocess.run([sys.executable, str(folder / script)], capture_output=True,
                              text=True, cwd=folder.parent)
        print(done.stdout, end="", flush=True)
        found = list(sections(done.stdout)) if done.returncode == 0 else []
        if not found:
            rows.append((script, "failed: " + (done.stderr.strip().splitlines() or ["?"])[-1],
                         "-", "", load))
        rows.extend(row + (load,) for row in found)
    width = max(len(row[0]) for row in rows)
    print()
    print(f"{os.cpu_count()} cores; load: the one-minute load average as each script began")
    print(f"{'benchmark':<{width}} | {'baseline':<44} | {'ratio':>7} | load | goal")
    print(f"{'-' * width}-|-{'-' * 44}-|-{'-' * 7}-|------|-----")
    for title, baseline, ratio, goal, load in rows:
        print(f"{title:<{width}} | {baseline[:44]:<44} | {ratio + 'x':>7} | {load:4.1f} | {goal}")


if __name__ == "__main__":
    main()
