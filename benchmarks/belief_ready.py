"""How soon the belief robot makes its first move: cold (nothing cached) and from the cache.

The first move is everything between building the robot and its first action: loading
the population, the members' exact models (solved, or read from the cache), the belief's
set-up and the first decision. Printed in CPU seconds (``time.process_time``, what the
machine's load does not inflate) and wall seconds; run it under ``/usr/bin/time -v`` for
the peak resident memory. ``--cache DIR`` names the folder the members' models are kept
in (the first call fills it, the next reads it); without it nothing is written::

    /usr/bin/time -v python benchmarks/belief_ready.py --scenario roboergosum \
        --population populations/roboergosum.toml --cache /tmp/belief-cache

The figures are in ``docs/adaptation.md``.
"""

from __future__ import annotations

import argparse
import json
import time
from typing import Any

from hg_marl.agents.humans import make_human
from hg_marl.agents.robots import make_robot
from hg_marl.training.runner import RunConfig, run


def first_move(scenario: str, population: str, human: str, cache: str, extra: str) -> dict[str, Any]:
    """Seconds (CPU, wall) from building the robot to its first action, and the members it solved."""
    cpu0, wall0 = time.process_time(), time.perf_counter()
    params: dict[str, Any] = {"population": population}
    if cache:
        params["cache"] = cache
    for item in filter(None, extra.split(",")):
        key, _, value = item.partition("=")
        params[key] = value
    robot: Any = make_robot("belief", **params)
    marks: dict[str, float] = {}
    inner = robot.act

    def act(turn: Any) -> int:
        action = inner(turn)
        if not marks:
            marks["cpu"], marks["wall"] = time.process_time() - cpu0, time.perf_counter() - wall0
        return action

    robot.act = act
    run(robot, make_human(human), RunConfig(scenario=scenario, duration=60.0, seed=0, max_decisions=1))
    solved = getattr(robot, "members_built", lambda: None)()
    return {"first_move_cpu_s": round(marks["cpu"], 2), "first_move_wall_s": round(marks["wall"], 2), "built": solved}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenario", default="roboergosum")
    parser.add_argument("--population", default="populations/roboergosum.toml")
    parser.add_argument("--human", default="cooperative")
    parser.add_argument("--cache", default="", help="folder for the members' models (default: none)")
    parser.add_argument("--params", default="", help="more belief parameters, k=v,k=v")
    args = parser.parse_args()
    print(json.dumps(first_move(args.scenario, args.population, args.human, args.cache, args.params)))


if __name__ == "__main__":
    main()
