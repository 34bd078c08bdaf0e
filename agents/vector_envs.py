"""The batched seats, Gymnasium's vector entry points of the two single-seat ids.

``gymnasium.make_vec(id, num_envs=N, vectorization_mode="vector_entry_point", ...)``
reaches :func:`robot_vector_env` / :func:`human_vector_env`, ``N`` tables in one
``hg_marl.envs.batched.BatchedTable``: the robot's seat with the human(s) compiled, the
human's seat with the ``planner`` robot compiled (``compiled=False`` keeps it live) and
other robots live, one per table; :mod:`hg_marl.agents.array_partners` builds those
partners.
"""

from __future__ import annotations

import logging
from collections.abc import Sequence
from typing import Any

from hg_marl.agents.array_partners import LiveRobots, compiled_humans, compiled_robots
from hg_marl.core import Agent, Durations, Scenario, World
from hg_marl.policy import Actor

logger = logging.getLogger(__name__)


def seat_robot(partner: Any) -> str:
    """Which robot the human's batched seat plays, in words (the compiled planner or live robots)."""
    from hg_marl.agents.compiled_robot import CompiledRobot

    if isinstance(partner, CompiledRobot):
        return (
            f"the compiled {partner.name} robot (its plans and the progress guard only; "
            "runs and studies play the live robot: compiled=False to train against it)"
        )
    return f"live robots ({partner.name}), one per table, as runs and studies play them"


def robot_vector_env(
    num_envs: int = 1,
    scenario: str | Scenario = "paper2015",
    human: str | Actor | Sequence[str | Actor] = "cooperative",
    continuing: bool = False,
    max_cycles: int | None = 500,
    time_budget: float | None = None,
    durations: Durations | None = None,
    autoreset_mode: str = "next_step",
    device: Any = None,
    cache: Any = True,
    progress: bool = False,
    history: int = 0,
    partner: Any = None,
) -> Any:
    """The robot's seat batched, the human compiled (a learned SB3 human batched instead, see :func:`compiled_humans`).

    Gymnasium reaches it as ``gymnasium.make_vec(ROBOT_VIEW_ID, num_envs=N,
    vectorization_mode="vector_entry_point", human=...)``. ``history=k`` wraps it in
    ``hg_marl.envs.history.HistoryVectorEnv``; ``partner`` (an ``ArrayPartner``) replaces
    the compiled ``human``.
    """
    from hg_marl.envs.batched import BatchedTable, check_batch
    from hg_marl.envs.history import HistoryVectorEnv, check_history

    world = World(scenario, durations)
    check_batch(world, num_envs)
    k = check_history(history)
    if partner is None:
        partner = compiled_humans(world, human, cache, progress)
    env = BatchedTable(
        partner, num_envs, world, Agent.ROBOT, continuing, max_cycles, time_budget, 0.0, autoreset_mode, device=device
    )
    return HistoryVectorEnv(env, k) if k else env


def human_vector_env(
    num_envs: int = 1,
    scenario: str | Scenario = "paper2015",
    robot: str | Actor | Sequence[str | Actor] = "planner",
    effort_weight: float = 0.0,
    continuing: bool = False,
    max_cycles: int | None = 500,
    time_budget: float | None = None,
    durations: Durations | None = None,
    autoreset_mode: str = "next_step",
    device: Any = None,
    compiled: bool = True,
    cache: Any = True,
    progress: bool = False,
) -> Any:
    """The human's seat batched: the ``planner`` robot compiled, other robots live (:class:`LiveRobots`).

    ``compiled=True`` (default) compiles a ``"planner"`` spec (or a list of them) into
    arrays with an array stall rule (``agents/compiled_robot.py``), so no Python runs per
    table; ``compiled=False`` keeps one live robot per table. Any other robot, or a robot
    instance, is live either way. ``cache``/``progress`` as for :func:`robot_vector_env`.

    Which robot a human trained here meets: by default the *compiled* planner, not the
    live ``planner`` robot that ``hg-marl run``, studies and ``train sb3 --seat human``
    play. The two propose the same plans, but the compiled one has only the progress
    guard where the live one also monitors unmet expectations and blocks refused human
    actions (``agents/compiled_robot.py`` says where they differ), so a human trained
    against it may meet a slightly different robot when evaluated. ``compiled=False``
    trains against the live robot itself (slower: one planner per table). The env says
    which in one log line (``logging`` INFO, :func:`seat_robot`).
    """
    from hg_marl.envs.batched import BatchedTable, check_batch

    world = World(scenario, durations)
    n = check_batch(world, num_envs)
    partner = compiled_robots(world, robot, n, cache, progress) if compiled else LiveRobots(world, robot, n)
    logger.info("human seat: %d tables against %s", n, seat_robot(partner))
    return BatchedTable(
        partner,
        n,
        world,
        Agent.HUMAN,
        continuing,
        max_cycles,
        time_budget,
        effort_weight,
        autoreset_mode,
        device=device,
    )
