"""Cold commands: each run in a fresh process, as users meet them, against the cost of its elimination.

Each command of the grid runs ``--repeats`` times, each time in a new interpreter (the runs of
the commands and of the imports taken in turn, so that a load on the machine falls on all of
them alike). From each run's ``--json`` ``timings`` (seconds per stage) the table prints the
median total, the median elimination stage, total/eliminate, each stage's share of the total,
and the process's wall time (start to exit, as a shell sees it), with the spread (min-max) of
the total and of the wall. Beside them, in the same run, the wall time of ``python -c "import
flint, numpy"`` (the floor issue 34 measures against: a command should take at most twice
it), of ``import algkin`` and of ``import sympy``. Last, ``python -X importtime -m algkin derive
chebyshev-lambda --outputs B``: the ten imports with the largest cumulative time.

Each command runs as ``python -m algkin`` from this checkout; ``--against DIR`` runs it from
another checkout's sources too (``git archive <commit> | tar -x -C DIR``), in the same rounds, and
prints that table first: a change's before and after from one run.

Run: ``python benchmarks/bench_cold.py [--repeats N] [--quick] [--against DIR]`` (``--quick``
drops the six-bar derive).
"""

import argparse
import json
import statistics
import subprocess
import sys
import time

from checkouts import ROOT, add_against, describe, measured, run_python

COMMANDS = [
    "derive chebyshev-lambda --outputs B",
    "curve chebyshev-lambda --point P",
    "curve stephenson-iii --point P",
]
SIX_BAR_DERIVE = "derive stephenson-iii --outputs P"
IMPORTS = ["flint, numpy", "algkin", "sympy"]
FLOOR = IMPORTS[0]
IMPORTTIME_COMMAND = COMMANDS[0]


def run_command(command, root):
    """One fresh run of ``python -m algkin <command> --json`` from the sources in ``root``: its stage
    timings and its process wall time."""
    start = time.perf_counter()
    completed = run_python(root, ["-m", "algkin", *command.split(), "--json"])
    wall = time.perf_counter() - start
    return json.loads(completed.stdout)["timings"], wall


def run_import(modules):
    """The wall time of one fresh ``python -c "import <modules>"``."""
    start = time.perf_counter()
    subprocess.run([sys.executable, "-c", f"import {modules}"], check=True)
    return time.perf_counter() - start


def measure(commands, roots, repeats):
    """Per root, per command, the list of (timings, wall) of its runs; per import, its walls; taken in turn."""
    runs = {root: {command: [] for command in commands} for root in roots}
    imports = {modules: [] for modules in IMPORTS}
    for _ in range(repeats):
        for modules in IMPORTS:
            imports[modules].append(run_import(modules))
        for command in commands:
            for root in roots:
                runs[root][command].append(run_command(command, root))
    return runs, imports


def spread(values, scale=1e3):
    """``median (min-max)`` of ``values`` in milliseconds.

    >>> spread([0.1, 0.3, 0.2])
    '200 (100-300)'
    """
    return (f"{statistics.median(values) * scale:.0f} "
            f"({min(values) * scale:.0f}-{max(values) * scale:.0f})")


def stage_medians(timings):
    """The median seconds of each stage over the runs (the stages of the first run, in its order)."""
    return {stage: statistics.median(run[stage] for run in timings) for stage in timings[0]}


def print_commands(runs, floor):
    print(f"{'command':38} {'total ms':>15} {'elim ms':>8} {'tot/elim':>8} {'wall ms':>16} {'wall/floor':>10}")
    for command, results in runs.items():
        timings = [stages for stages, _ in results]
        walls = [wall for _, wall in results]
        medians = stage_medians(timings)
        ratio = medians["total"] / medians["eliminate"]
        print(f"{command:38} {spread([t['total'] for t in timings]):>15} {medians['eliminate'] * 1e3:8.2f} "
              f"{ratio:7.0f}x {spread(walls):>16} {statistics.median(walls) / floor:9.2f}x")
    print("\nshare of the total, per stage (medians):")
    for command, results in runs.items():
        medians = stage_medians([stages for stages, _ in results])
        shares = "  ".join(f"{stage} {medians[stage] / medians['total']:5.1%}"
                           for stage in medians if stage != "total")
        print(f"  {command:38} {shares}")


def print_imports(imports):
    print(f"\n{'python -c':38} {'wall ms':>16}")
    for modules, walls in imports.items():
        print(f"{'import ' + modules:38} {spread(walls):>16}")


def importtime_top(command, count=10):
    """The ``count`` imports with the largest cumulative time (us) under ``python -X importtime``."""
    completed = run_python(ROOT, ["-X", "importtime", "-m", "algkin", *command.split()])
    cumulative: dict[str, int] = {}  # a module may be listed twice (a package, then again under a child)
    for line in completed.stderr.splitlines():
        if not line.startswith("import time:") or "cumulative" in line:
            continue
        _, micros, name = (field.strip() for field in line[len("import time:"):].split("|"))
        cumulative[name] = max(cumulative.get(name, 0), int(micros))
    return sorted(((us, name) for name, us in cumulative.items()), reverse=True)[:count]


def print_importtime(command):
    print(f"\npython -X importtime -m algkin {command}: top 10 cumulative imports")
    for micros, name in importtime_top(command):
        print(f"  {micros / 1e3:8.1f} ms  {name}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="fresh runs of each command and import (default 5)")
    parser.add_argument("--quick", action="store_true", help=f"leave out `{SIX_BAR_DERIVE}`")
    add_against(parser)
    arguments = parser.parse_args()
    commands = COMMANDS if arguments.quick else [*COMMANDS, SIX_BAR_DERIVE]
    roots = measured(arguments.against)
    runs, imports = measure(commands, roots, arguments.repeats)
    floor = statistics.median(imports[FLOOR])
    print(f"{arguments.repeats} fresh processes each; ms as median (min-max); "
          f"floor = python -c \"import {FLOOR}\" = {floor * 1e3:.0f} ms")
    for root in roots:
        print(f"\nalgkin from {describe(root)}:")
        print_commands(runs[root], floor)
    print_imports(imports)
    print_importtime(IMPORTTIME_COMMAND)
    return 0


if __name__ == "__main__":
    sys.exit(main())
