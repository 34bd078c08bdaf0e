"""The runner-protocol rates of SB3 models and robots, pinned for the mutation gate.

Expected values come from a plain reference: one :func:`run` per seed, its tasks counted
and scaled by hand to an hour (``tasks * 3600 / duration``), averaged over the seeds.
The "model" is a stand-in with SB3's ``predict`` signature that draws a feasible action
with its own seeded generator (named ``Maskable...`` so the robot hands it the mask), so
nothing is trained and the runs take well under a second. Nothing here is timed.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.sb3 import SB3Robot
from hg_marl.training.baselines.evaluation import HOUR, actor_rate, runner_rate, steps_to_reach
from hg_marl.training.runner import RunConfig, run


class _Policy:
    """Sampling would call this: a deterministic robot never does."""

    def get_distribution(self, *args: Any, **kwargs: Any) -> Any:
        raise AssertionError("the policy was sampled, not asked for its most probable action")

    def obs_to_tensor(self, obs: Any) -> Any:
        raise AssertionError("the policy was sampled, not asked for its most probable action")


class MaskableRandomFeasible:
    """A stand-in model: ``predict`` draws one of the mask's feasible actions (seeded)."""

    def __init__(self, seed: int = 5) -> None:
        self.rng = np.random.default_rng(seed)
        self.policy = _Policy()

    def predict(self, obs: Any, deterministic: bool = True, action_masks: Any = None) -> tuple[int, None]:
        assert deterministic
        return int(self.rng.choice(np.flatnonzero(action_masks))), None


def _tasks(robot: Any, human: str, scenario: str, duration: float, seed: int) -> int:
    return int(
        run(robot, make_human(human), RunConfig(scenario=scenario, duration=duration, seed=seed)).summary[
            "tasks_solved"
        ]
    )


def test_an_hour_is_3600_simulated_seconds() -> None:
    assert HOUR == 3600.0


def test_actor_rate_is_the_mean_tasks_per_hour_of_a_fresh_robot_per_seed() -> None:
    """Planner robots on seeds 0 and 1 for 700 s: each seed's tasks x 36 / 7 (3600 / 700), averaged.

    700 s does not divide an hour, so the rate is not a whole number: a floor division shows.
    """
    built: list[Any] = []

    def factory() -> Any:
        built.append(make_robot("planner"))
        return built[-1]

    rate = actor_rate(factory, "cooperative", "paper2015", 700.0, [0, 1])
    tasks = [_tasks(make_robot("planner"), "cooperative", "paper2015", 700.0, seed) for seed in (0, 1)]
    assert sum(tasks) % 7  # the check below would pass on 0 x anything, or on whole rates, otherwise
    assert rate == pytest.approx((tasks[0] * 36 / 7 + tasks[1] * 36 / 7) / 2)
    assert len(built) == 2 and built[0] is not built[1]


def test_actor_rate_of_no_seeds_is_nan() -> None:
    assert math.isnan(actor_rate(lambda: make_robot("planner"), "cooperative", "paper2015", 300.0, []))


def test_runner_rate_defaults_to_one_deterministic_run_of_1200_seconds_on_seed_0() -> None:
    """The defaults: 1200 s (so tasks x 3), seed 0, the most probable action (never sampled)."""
    rate = runner_rate(MaskableRandomFeasible(seed=7), "facts", "cooperative", "paper2015")
    tasks = [
        _tasks(
            SB3Robot(model=MaskableRandomFeasible(seed=7), observation="facts"), "cooperative", "paper2015", 1200.0, s
        )
        for s in (0, 1)
    ]
    assert tasks[0] > 0 and tasks[0] != tasks[1]  # this stand-in tells seed 0 from seed 1
    assert rate == pytest.approx(tasks[0] * 3)


def test_runner_rate_passes_its_duration_and_seeds_through() -> None:
    """600 s on seeds 3 and 4: each seed's tasks x 6, averaged (one model, drawn on across seeds)."""
    model = MaskableRandomFeasible(seed=11)
    rate = runner_rate(model, "facts", "cooperative", "paper2015", duration=600.0, seeds=(3, 4))
    twin = MaskableRandomFeasible(seed=11)
    tasks = [
        _tasks(SB3Robot(model=twin, observation="facts"), "cooperative", "paper2015", 600.0, seed) for seed in (3, 4)
    ]
    assert sum(tasks) > 0
    assert rate == pytest.approx((tasks[0] * 6 + tasks[1] * 6) / 2)


def test_steps_to_reach_gives_the_first_step_count_at_or_above_the_target() -> None:
    """Worked by hand: rates 1, 50, 50, 95 at steps 0, 100, 200, 300."""
    curve = [(0, 1.0), (100, 50.0), (200, 50.0), (300, 95.0)]
    assert steps_to_reach(curve, 50.0) == 100  # reached exactly counts, and the first one wins
    assert steps_to_reach(curve, 1.0) == 0
    assert steps_to_reach(curve, 95.0) == 300
    assert steps_to_reach(curve, 95.5) is None
    assert steps_to_reach([], 0.0) is None
    found = steps_to_reach([(np.int64(7), 3.0)], 2.0)
    assert found == 7 and type(found) is int
