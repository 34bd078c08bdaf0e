"""Single-agent Gymnasium views of TableCleaning-v0: one seat learns, a scripted partner plays the other.

``gymnasium.make("hg_marl/RobotTableCleaning-v0", scenario="paper2015", human="lazy")``
is :class:`RobotView`: the robot's seat, the human stepped inside ``step``.
``gymnasium.make("hg_marl/HumanTableCleaning-v0", robot="planner", effort_weight=0.05)``
is :class:`HumanView`, the mirror for learning humans against a fixed robot.

Observation (``observation=`` option; the choice is written down here because SB3 cares):

- ``"facts"`` (default): ``Box(0, 1, (F,), int8)``, the paper's boolean facts. Works
  with every SB3 algorithm's ``MlpPolicy`` (PPO, A2C, DQN, QR-DQN) and, with
  :meth:`action_masks`, with sb3-contrib's ``MaskablePPO``. This is what the paper's
  habit sees.
- ``"flat"``: ``Box(0, 1, (F + A,), int8)``, facts then the action mask, for plain
  algorithms that cannot be given the mask any other way.
- ``"dict"``: the AEC environment's ``Dict(observation=..., action_mask=...)`` (SB3:
  ``MultiInputPolicy``).

``history=k`` (robot seat, default 0) appends the last ``k`` cycles' interaction history
to the facts in every mode (``hg_marl/envs/history.py``), on the view and on
:func:`robot_vector_env` alike.

Rewards: the robot's view returns the team reward (1 per task completed, the paper's).
The human's view returns the same minus ``effort_weight`` times the seconds of physical
work the human did in the step, so humans that prefer to work less can be learned.

A step of :class:`RobotView` is one cycle: the robot's action, then the human's. A step
of :class:`HumanView` is the human's action, then the robot's action of the next cycle
(the one whose completing ``wait`` the human's action may have enabled); in episodic mode
the human's episode ends as soon as the robot completes the task. ``info`` carries the
partner's action (index and name), the cycle's events (one ``"; "``-joined string), the clock, tasks
solved, effort and idle time. Views charge no decision time. Seeding: ``reset(seed=s)``
seeds the table and the partner's own generator from ``s``.

Partners: a registry name (``"lazy:p_idle=0.5"``), an Actor, or a list of them (a
population; one is drawn per episode with the view's generator); see
:mod:`hg_marl.agents.partner_specs`. The batched seats (Gymnasium's vector entry
points) are :mod:`hg_marl.agents.vector_envs`, their partners over arrays
:mod:`hg_marl.agents.array_partners`; both are re-exported here, where they used to live.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import gymnasium
import numpy as np
from gymnasium import spaces

from hg_marl.agents.array_partners import (
    CompiledPopulation,
    CompiledSchedule,
    LiveRobots,
    compiled_humans,
    compiled_robots,
)
from hg_marl.agents.humans.registry import resolve_human
from hg_marl.agents.partner_specs import as_list, make_robot_actor, resolve_partner
from hg_marl.agents.vector_envs import human_vector_env, robot_vector_env
from hg_marl.core import Agent, Durations, Scenario, World
from hg_marl.core.cycle import check_effort_weight, ends_episode, seat_reward
from hg_marl.envs.table_cleaning import EVENT_SEPARATOR, raw_env
from hg_marl.policy import Actor

__all__ = [
    "OBSERVATIONS",
    "CompiledPopulation",
    "CompiledSchedule",
    "HumanView",
    "LiveRobots",
    "RobotView",
    "as_list",
    "compiled_humans",
    "compiled_robots",
    "human_vector_env",
    "join_events",
    "make_robot_actor",
    "resolve_partner",
    "robot_vector_env",
]

OBSERVATIONS = ("facts", "flat", "dict")


def join_events(first: str, second: str) -> str:
    """Two ``infos["events"]`` strings as one, in order (either may be empty)."""
    return EVENT_SEPARATOR.join(e for e in (first, second) if e)


class _View(gymnasium.Env):
    """Shared machinery: the wrapped AEC env, spaces, seeding, partner stepping."""

    metadata = {"render_modes": ["ansi", "rgb_array"], "render_fps": 2}  # noqa: RUF012 (as gymnasium.Env)
    seat = Agent.ROBOT

    def __init__(
        self,
        scenario: str | Scenario,
        partners: Sequence[str | Actor],
        continuing: bool,
        max_cycles: int | None,
        time_budget: float | None,
        observation: str,
        render_mode: str | None,
        durations: Durations | None,
        history: int = 0,
    ) -> None:
        if observation not in OBSERVATIONS:
            raise ValueError(f"observation must be one of {OBSERVATIONS}, got {observation!r}")
        self.env = raw_env(
            scenario=scenario,
            continuing=continuing,
            max_cycles=max_cycles,
            time_budget=time_budget,
            render_mode=render_mode,
            durations=durations,
            history=history,
        )
        self.world: World = self.env.world
        self.render_mode = render_mode
        self.observation_mode = observation
        self._partners = list(partners)
        if not self._partners:
            raise ValueError("need at least one partner")
        self.partner: Actor = resolve_partner(self.seat, self._partners[0])
        self._partners[0] = self.partner
        n_f, n_a = len(self.env.observe(self.seat.label)["observation"]), self.world.n_actions(self.seat)
        self.action_space = spaces.Discrete(n_a)
        if observation == "facts":
            self.observation_space = spaces.Box(0, 1, (n_f,), np.int8)
        elif observation == "flat":
            self.observation_space = spaces.Box(0, 1, (n_f + n_a,), np.int8)
        else:
            self.observation_space = self.env.observation_space(self.seat.label)

    @property
    def name(self) -> str:
        """The seat's agent name."""
        return self.seat.label

    def _obs(self) -> Any:
        raw = self.env.observe(self.seat.label)
        if self.observation_mode == "facts":
            return np.array(raw["observation"])
        if self.observation_mode == "flat":
            return np.concatenate([raw["observation"], raw["action_mask"]])
        return {k: np.array(v) for k, v in raw.items()}

    def action_masks(self) -> np.ndarray:
        """Feasible actions of the learning seat, as booleans (sb3-contrib's MaskablePPO hook)."""
        return self.world.mask(self.env.world_state, self.seat).astype(bool)

    def _reset_env(self, seed: int | None, options: dict[str, Any] | None) -> None:
        super().reset(seed=seed)
        env_seed, partner_seed = (int(x) for x in self.np_random.integers(2**63 - 1, size=2))
        index = int(self.np_random.integers(len(self._partners))) if len(self._partners) > 1 else 0
        self.env.reset(seed=env_seed, options=options)
        self.partner = resolve_partner(self.seat, self._partners[index])
        self._partners[index] = self.partner
        self.partner.reset(self.world, self.seat.other, np.random.default_rng(partner_seed))

    def _partner_step(self) -> tuple[int, str]:
        """Let the partner act; return its action index and the events of its action."""
        other = self.seat.other.label
        action = int(self.partner.act(self.env.turn(other)))
        self.env.step(action)
        return action, self.env.infos[other]["events"]

    def _info(self, partner_action: int, events: str, **extra: Any) -> dict[str, Any]:
        own = self.env.infos[self.seat.label]
        other = self.seat.other
        return {
            **extra,
            f"{other.label}_action": partner_action,
            f"{other.label}_action_name": self.world.action_names[other][partner_action] if partner_action >= 0 else "",
            "events": events,
            "clock": self.env.clock,
            "cycle": self.env.cycles,
            "tasks_solved": self.env.tasks_solved,
            "action": own["action"],
            "failed": own["failed"],
            "effort": own["effort"],
            "idle": own["idle"],
            "partner_effort": self.env.infos[other.label]["effort"],
        }

    def render(self) -> Any:
        """The wrapped environment's rendering (``ansi`` text or an ``rgb_array`` image)."""
        return self.env.render()


class RobotView(_View):
    """The robot's seat; the human acts inside :meth:`step` (see the module docstring).

    Args:
        scenario: scenario name, TOML path or Scenario.
        human: a human name, an Actor, or a list of them (a population resampled each episode).
        continuing: re-draw the table after each success instead of terminating.
        max_cycles: truncate after this many cycles (None: no limit).
        time_budget: truncate at this many simulated seconds (None: no limit).
        observation: ``"facts"``, ``"flat"`` or ``"dict"``.
        render_mode: None, ``"ansi"`` or ``"rgb_array"``.
        durations: override the scenario's action durations.
        history: cycles of interaction history appended to the facts (0: none).
    """

    seat = Agent.ROBOT

    def __init__(
        self,
        scenario: str | Scenario = "paper2015",
        human: str | Actor | Sequence[str | Actor] = "cooperative",
        continuing: bool = False,
        max_cycles: int | None = 500,
        time_budget: float | None = None,
        observation: str = "facts",
        render_mode: str | None = None,
        durations: Durations | None = None,
        history: int = 0,
    ) -> None:
        super().__init__(
            scenario,
            [resolve_human(h) for h in as_list(human)],
            continuing,
            max_cycles,
            time_budget,
            observation,
            render_mode,
            durations,
            history,
        )

    @property
    def human(self) -> Actor:
        """The human playing this episode."""
        return self.partner

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None) -> tuple[Any, dict[str, Any]]:
        """New table (``options={"state": State}`` to start from a given state); the robot acts first."""
        self._reset_env(seed, options)
        return self._obs(), {"clock": 0.0, "tasks_solved": 0, "human": getattr(self.partner, "name", "")}

    def step(self, action: Any) -> tuple[Any, float, bool, bool, dict[str, Any]]:
        """One cycle: the robot's ``action``, then the human's; returns the robot's reward."""
        self.env.step(action)
        reward = float(self.env.rewards["robot"])
        events = self.env.infos["robot"]["events"]
        human_action, human_events = self._partner_step()
        reward += float(self.env.rewards["robot"])
        info = self._info(
            human_action, join_events(events, human_events), human_failed=self.env.infos["human"]["failed"]
        )
        return self._obs(), reward, bool(self.env.terminations["robot"]), bool(self.env.truncations["robot"]), info


class HumanView(_View):
    """The human's seat against a fixed robot, with an effort-weighted reward.

    Args:
        scenario: scenario name, TOML path or Scenario.
        robot: a robot name (``make_robot``), an Actor, or a list of them.
        effort_weight: reward per task minus this times the human's seconds of work.
        continuing: re-draw the table after each success instead of terminating.
        max_cycles: truncate after this many cycles (None: no limit).
        time_budget: truncate at this many simulated seconds (None: no limit).
        observation: ``"facts"``, ``"flat"`` or ``"dict"``.
        render_mode: None, ``"ansi"`` or ``"rgb_array"``.
        durations: override the scenario's action durations.
    """

    seat = Agent.HUMAN

    def __init__(
        self,
        scenario: str | Scenario = "paper2015",
        robot: str | Actor | Sequence[str | Actor] = "planner",
        effort_weight: float = 0.0,
        continuing: bool = False,
        max_cycles: int | None = 500,
        time_budget: float | None = None,
        observation: str = "facts",
        render_mode: str | None = None,
        durations: Durations | None = None,
    ) -> None:
        effort_weight = check_effort_weight(effort_weight)
        super().__init__(
            scenario, as_list(robot), continuing, max_cycles, time_budget, observation, render_mode, durations
        )
        self.effort_weight = float(effort_weight)

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None) -> tuple[Any, dict[str, Any]]:
        """New table; the robot makes the first cycle's move, then it is the human's turn."""
        self._reset_env(seed, options)
        robot_action, events = self._partner_step()
        return self._obs(), {"robot_action": robot_action, "events": events, "clock": 0.0, "tasks_solved": 0}

    def step(self, action: Any) -> tuple[Any, float, bool, bool, dict[str, Any]]:
        """The human's ``action`` (ending the cycle), then the robot's next action."""
        effort_before = self.env.infos["human"]["effort"]
        self.env.step(action)
        events = self.env.infos["human"]["events"]
        work = self.env.infos["human"]["effort"] - effort_before
        done = bool(self.env.terminations["human"])
        truncated = bool(self.env.truncations["human"])
        robot_action, task_reward = -1, 0.0
        if not (done or truncated):
            robot_action, robot_events = self._partner_step()
            events = join_events(events, robot_events)
            task_reward = float(self.env.rewards["human"])
            # Episodic: the task is over once the robot completes it; the human's move left
            # in that cycle cannot matter, so the human's episode ends here.
            done = bool(ends_episode(task_reward, self.env.continuing))
        reward = seat_reward(task_reward, work, self.effort_weight)
        info = self._info(robot_action, events, work=work, task_reward=task_reward)
        return self._obs(), reward, done, truncated, info
