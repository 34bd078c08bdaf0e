"""Per-decision wall time of each robot agent on ``paper2015`` (habit path, planner path).

Drives each robot for a few hundred cycles against a cooperative human (the planner's
human stream) with the task core directly, and prints the mean and 95th percentile of
the wall time of ``act`` split by the expert that decided. Run::

    python benchmarks/decision_latency.py [--cycles 1000] [--seed 0]
"""

from __future__ import annotations

import argparse
import time
from collections import defaultdict

import numpy as np

from hg_marl.agents.habit import QLearner
from hg_marl.agents.planner import Planner
from hg_marl.agents.robots import make_robot
from hg_marl.core import WAIT, Agent, World
from hg_marl.policy import Turn

AGENTS = [
    ("planner", {}),
    ("habit", {}),
    ("random", {}),
    ("hybrid", {"criterion": "random"}),
    ("hybrid", {"criterion": "entropy"}),
    ("hybrid", {"criterion": "entropy_and_cost"}),
    ("hybrid", {"criterion": "vpi"}),
    ("hybrid", {"criterion": "learning_state"}),
]


def measure(name: str, params: dict, cycles: int, seed: int) -> dict[str, list[float]]:
    """Wall seconds of each ``act`` call, keyed by the deciding expert."""
    world = World("paper2015")
    rng = np.random.default_rng(seed)
    robot = make_robot(name, **params)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(seed))
    human = Planner(world)
    human_wait = world.index(Agent.HUMAN, WAIT)
    state, reward = world.initial_state(rng), 0.0
    times: dict[str, list[float]] = defaultdict(list)
    for _ in range(cycles):
        obs = {"observation": world.facts(state), "action_mask": world.mask(state, Agent.ROBOT)}
        turn = Turn(world, state, Agent.ROBOT, obs, reward=reward)
        t0 = time.perf_counter()
        action = robot.act(turn)
        times[robot.last_decision.expert].append(time.perf_counter() - t0)
        out = world.step(state, Agent.ROBOT, action)
        state, reward = out.state, out.reward
        if reward > 0:
            state = world.initial_state(rng)
            continue
        plan = human.plan(state, to_move=Agent.HUMAN, robot_action=action)
        h = plan.human_action if plan.success and plan.human_action >= 0 else human_wait
        state = world.step(state, Agent.HUMAN, h).state
    return times


def main() -> None:
    """Print the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cycles", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    world = World("paper2015")
    facts = world.facts(world.initial_state(np.random.default_rng(0)))
    learner, rng = QLearner(world.n_facts, world.n_actions(Agent.ROBOT)), np.random.default_rng(0)
    n = 20_000
    t0 = time.perf_counter()
    for _ in range(n):
        learner.act(facts, rng)
    print(f"QLearner.act (matvec + softmax + draw): {(time.perf_counter() - t0) / n * 1e6:.1f} us")
    print(f"{'agent':<28}{'path':<9}{'n':>6}{'mean us':>10}{'p95 us':>10}")
    for name, params in AGENTS:
        label = name + (f"({params['criterion']})" if params else "")
        for expert, ts in sorted(measure(name, params, args.cycles, args.seed).items()):
            arr = np.array(ts) * 1e6
            print(f"{label:<28}{expert:<9}{len(arr):>6}{arr.mean():>10.1f}{np.percentile(arr, 95):>10.1f}")


if __name__ == "__main__":
    main()
