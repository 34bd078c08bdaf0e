"""Oracle budget: wall time and peak memory of value iteration per (scenario, human).

Run: ``python benchmarks/oracle_budget.py [--scenarios "paper2015;roboergosum;..."]
[--humans cooperative,...] [--max-seconds 60]``. Each solve runs in a fresh process
(nothing cached, its own peak resident memory), with the oracle's default budget (60 s,
4 GB); a solve over its budget prints the oracle's one-line refusal instead of a rate.
The reference printed in the same run is the same solve without symmetry reduction
(``symmetry=False``) on ``paper2015``, where it is cheap. Target: every bundled scenario
and stationary registry human, and generated layouts of up to 8 objects, within 60 s and
4 GB each; over it, the refusal.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys

CHILD = """
import json, resource, sys, time
from hg_marl.agents.oracle import OracleTooLarge, oracle_rate
scenario, human, symmetry, seconds = sys.argv[1], sys.argv[2], json.loads(sys.argv[3]), float(sys.argv[4])
start, cpu = time.perf_counter(), time.process_time()
try:
    r = oracle_rate(scenario, human, symmetry=symmetry, max_seconds=seconds)
    out = {"rate": r.rate_per_hour, "states": r.n_states, "reduced": r.reduced}
except OracleTooLarge as exc:
    out = {"refused": str(exc)}
out["wall"] = time.perf_counter() - start
out["cpu"] = time.process_time() - cpu
out["peak_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
print(json.dumps(out))
"""


def stationary_humans() -> tuple[str, ...]:
    """Every stationary registry human that needs no file (``learned`` needs a saved policy)."""
    from hg_marl.agents.humans.registry import HUMANS

    return tuple(n for n, s in HUMANS.items() if s.stationary and all(p.default is not None for p in s.params.values()))


SCENARIOS = ("paper2015", "roboergosum", "generated:objects=8,bins=2", "generated:objects=8,bins=1")


def solve(scenario: str, human: str, symmetry: bool | None, seconds: float) -> dict[str, object]:
    """One oracle solve in a fresh interpreter."""
    args = [sys.executable, "-c", CHILD, scenario, human, json.dumps(symmetry), str(seconds)]
    try:  # the budget is CPU time; wall time on a loaded machine may be many times more
        done = subprocess.run(args, capture_output=True, text=True, timeout=seconds * 10 + 120)
    except subprocess.TimeoutExpired:
        return {"error": f"no answer within {seconds * 10 + 120:g} s of wall time"}
    if done.returncode != 0:
        return {"error": done.stderr.strip().splitlines()[-1] if done.stderr.strip() else f"exit {done.returncode}"}
    result: dict[str, object] = json.loads(done.stdout.strip().splitlines()[-1])
    return result


def row(scenario: str, human: str, what: str, r: dict[str, object]) -> str:
    head = f"{scenario:32s} {human:12s} {what:9s}"
    if "error" in r:
        return f"{head} error: {r['error']}"
    cost = f"{r['wall']:7.1f} s wall {r['cpu']:7.1f} s cpu {r['peak_mb']:7.0f} MB peak"
    if "refused" in r:
        return f"{head} {cost}  refused: {r['refused']}"
    return f"{head} {cost}  {r['rate']:8.2f} tasks/h  {r['states']:>8} states"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenarios", default=";".join(SCENARIOS), help="separated by ;")
    parser.add_argument("--humans", default=",".join(stationary_humans()))
    parser.add_argument("--max-seconds", type=float, default=60.0)
    args = parser.parse_args()
    humans = args.humans.split(",")
    print(f"{'scenario':32s} {'human':12s} {'model':9s} cost and result")
    for human in humans:  # the reference: no symmetry reduction, on the paper's table
        print(row("paper2015", human, "full", solve("paper2015", human, False, args.max_seconds)), flush=True)
    for scenario in args.scenarios.split(";"):
        for human in humans:
            print(row(scenario, human, "default", solve(scenario, human, None, args.max_seconds)), flush=True)


if __name__ == "__main__":
    main()
