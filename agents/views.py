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

Batched seats: ``gymnasium.make_vec(id, num_envs=N, vectorization_mode="vector_entry_point",
...)`` reaches :func:`robot_vector_env` / :func:`human_vector_env`, ``N`` tables in one
``hg_marl.envs.batched.BatchedTable``: the robot's seat with the human(s) compiled
(``agents/compiled.py``; a list is a :class:`CompiledPopulation`; a learned SB3 human,
which cannot be compiled, answers every table with one forward pass of its policy,
``agents/batched_learned.py``), the human's seat with
the ``planner`` robot compiled (``agents/compiled_robot.py``: its plans per robot-turn
state, with an array stall rule in place of its history-dependent partner monitor;
``compiled=False`` keeps it live) and other robots live, one per table (:class:`LiveRobots`).

Humans: a registry name (``"lazy:p_idle=0.5"``), an Actor, or a list of them (a
population; one is drawn per episode with the view's generator). Robots likewise, with
names from ``hg_marl.agents.robots.make_robot`` (``planner``, ``habit``, ``hybrid``,
``random``). The partner's decision time is not charged to the clock.
"""

from __future__ import annotations

import logging
from collections.abc import Sequence
from typing import Any

import gymnasium
import numpy as np
from gymnasium import spaces

from hg_marl.agents.humans.registry import resolve_human
from hg_marl.core import Agent, Durations, Scenario, World
from hg_marl.envs.table_cleaning import EVENT_SEPARATOR, raw_env
from hg_marl.policy import Actor

logger = logging.getLogger(__name__)

OBSERVATIONS = ("facts", "flat", "dict")


def make_robot_actor(robot: str | Actor) -> Actor:
    """An Actor for the robot seat from a name or an instance (see the module docstring)."""
    if not isinstance(robot, str):
        if not isinstance(robot, Actor):
            raise ValueError(f"expected a robot name or an Actor (reset + act), got {robot!r}")
        return robot
    from hg_marl.agents.robots import make_robot

    return make_robot(robot)


def join_events(first: str, second: str) -> str:
    """Two ``infos["events"]`` strings as one, in order (either may be empty)."""
    return EVENT_SEPARATOR.join(e for e in (first, second) if e)


def as_list(partner: str | Actor | Sequence[str | Actor]) -> list[str | Actor]:
    """One partner or a population, as a list."""
    if isinstance(partner, str) or not isinstance(partner, Sequence):
        return [partner]
    return list(partner)


def resolve_partner(seat: Agent, partner: str | Actor) -> Actor:
    """The Actor playing opposite ``seat``: a human for the robot's view, a robot for the human's."""
    return resolve_human(partner) if seat is Agent.ROBOT else make_robot_actor(partner)


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
        if effort_weight < 0:
            raise ValueError(f"effort_weight must be non-negative, got {effort_weight}")
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
            done = task_reward > 0 and not self.env.continuing
        reward = task_reward - self.effort_weight * work
        info = self._info(robot_action, events, work=work, task_reward=task_reward)
        return self._obs(), reward, done, truncated, info


# ---- batched seats (Gymnasium's vector entry points) -----------------------------------
class LiveRobots:
    """Robot actors playing the human's batched seat, one per table (the ``ArrayPartner`` protocol).

    Each table has its own actor (a robot may keep state between turns); the turn it sees
    carries the state, the facts and mask, the clock and the tasks solved, but no events
    or reward: robots that learn from those (``habit``, ``hybrid``) do not fit a batched
    seat, deterministic ones (``planner``, ``random``) do.
    """

    def __init__(self, world: World, robot: str | Actor | Sequence[str | Actor], num_envs: int) -> None:
        self.world = world
        specs = as_list(robot)
        self.name = str(getattr(specs[0], "name", specs[0]))
        self.specs = specs
        # a name builds one actor per table; an instance is shared by the tables it plays
        self.actors = [make_robot_actor(specs[i % len(specs)]) for i in range(num_envs)]

    def reset_rows(self, rows: np.ndarray, rng: np.random.Generator) -> None:
        """Start the actors of tables ``rows`` with generators drawn from ``rng``."""
        for i in rows:
            self.actors[int(i)].reset(self.world, Agent.ROBOT, np.random.default_rng(int(rng.integers(2**63 - 1))))

    def act(self, batch: Any, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """Each table's robot acts on its own turn."""
        from hg_marl.policy import Turn

        out = np.empty(len(batch), dtype=np.int64)
        rows = getattr(batch, "rows", np.arange(len(batch)))
        for j in range(len(batch)):
            state = batch.state(j)
            obs = {"observation": self.world.facts(state), "action_mask": self.world.mask(state, Agent.ROBOT)}
            out[j] = int(
                self.actors[int(rows[j])].act(Turn(world=self.world, state=state, agent=Agent.ROBOT, observation=obs))
            )
        return out


class CompiledPopulation:
    """Compiled humans as one partner: a member drawn per table at each of its resets (``ArrayPartner``)."""

    def __init__(self, members: Sequence[Any]) -> None:
        self.members = list(members)
        self.name = "+".join(m.name for m in self.members)
        self.member: np.ndarray = np.zeros(0, dtype=np.int64)
        if all(hasattr(m, "answer") for m in self.members):
            # the members' tables end to end: an entry of member k is offset by the entries before it
            sizes = [len(m.actions) for m in self.members]
            self.offset = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.int64)
            self.actions = np.concatenate([m.actions for m in self.members])
            self.outcome = {k: np.concatenate([m.outcome[k] for m in self.members]) for k in self.members[0].outcome}

    def answer(self, batch: Any, seen: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        """(entry in the joined tables, found) per table: each table's member answers."""
        who = self.member[batch.rows]
        pos = np.zeros(len(batch), dtype=np.int64)
        found = np.zeros(len(batch), dtype=bool)
        for k, member in enumerate(self.members):
            sel = np.flatnonzero(who == k)
            if len(sel):
                p, f = member.answer(self._part(batch, sel), seen[sel], rng)
                pos[sel], found[sel] = p + self.offset[k], f
        return pos, found

    def fall_back(
        self, batch: Any, seen: np.ndarray, rng: np.random.Generator, out: np.ndarray, found: np.ndarray
    ) -> np.ndarray:
        """The live members answer the tables not found (counted per member)."""
        who = self.member[batch.rows]
        for k, member in enumerate(self.members):
            sel = np.flatnonzero((who == k) & ~found)
            if len(sel):
                out[sel] = member.fall_back(self._part(batch, sel), seen[sel], rng, out[sel], found[sel])
        return out

    @staticmethod
    def _part(batch: Any, sel: np.ndarray) -> Any:
        from hg_marl.envs.batched import BatchState

        return BatchState(
            batch.where[sel], batch.robot_at[sel], batch.offer_by[sel], batch.offer_obj[sel], batch.rows[sel]
        )

    @property
    def fallbacks(self) -> int:
        """Live answers over all members."""
        return sum(m.fallbacks for m in self.members)

    def reset_rows(self, rows: np.ndarray, rng: np.random.Generator) -> None:
        """Draw tables ``rows``' members uniformly."""
        if len(self.member) <= int(rows.max(initial=-1)):
            self.member = np.concatenate(
                [self.member, np.zeros(int(rows.max()) + 1 - len(self.member), dtype=np.int64)]
            )
        self.member[rows] = rng.integers(len(self.members), size=len(rows))

    def act(self, batch: Any, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """Each table's member answers (one batched look-up per member)."""
        who = self.member[batch.rows]
        out = np.empty(len(batch), dtype=np.int64)
        for k, member in enumerate(self.members):
            sel = np.flatnonzero(who == k)
            if len(sel):
                out[sel] = member.act(self._part(batch, sel), seen[sel], rng)
        return out


class CompiledSchedule(CompiledPopulation):
    """A ``switching`` human over compiled members: each table's phase read from its own clock.

    The phase of a table is ``bisect_right(at, clock)`` (or of its tasks solved with
    ``by="tasks"``), exactly :meth:`SwitchingHuman.phase_at`'s rule, applied to the whole
    batch at once; a phase's member answers from its compiled table. A member that
    appears in several phases is compiled once (``phase_member`` maps phase -> member).
    """

    def __init__(self, members: Sequence[Any], phase_member: Sequence[int], at: Sequence[float], by: str) -> None:
        super().__init__(members)
        self.name = "switching(" + ",".join(members[k].name for k in phase_member) + ")"
        self.phase_member = np.asarray(phase_member, dtype=np.int64)
        self.at = np.asarray(at, dtype=float)
        self.by = by

    def follow(self, clock: np.ndarray, tasks_solved: np.ndarray) -> None:
        """Each table's member from its clock (or tasks solved), before the partner moves."""
        value = clock if self.by == "time" else tasks_solved.astype(float)
        self.member = self.phase_member[np.searchsorted(self.at, value, side="right")]

    def reset_rows(self, rows: np.ndarray, rng: np.random.Generator) -> None:
        """Nothing to draw: the phase follows the clock, which the reset set to 0."""


def _compiled_schedule(world: World, human: Any, cache: Any, progress: bool) -> CompiledSchedule:
    from hg_marl.agents.compiled import compile_human

    keys: dict[Any, int] = {}
    unique: list[Any] = []
    phase_member = []
    for spec, live in zip(human.specs, human.humans, strict=True):
        key = spec if spec is not None else id(live)
        if key not in keys:
            keys[key] = len(unique)
            unique.append(spec if spec is not None else live)
        phase_member.append(keys[key])
    # each member's table covers the states the other phases lead to (a switch mid-episode)
    members = [
        compile_human(world, h, cache=cache, progress=progress, closure=[o for o in unique if o is not h])
        for h in unique
    ]
    return CompiledSchedule(members, phase_member, human.at, human.by)


def compiled_humans(
    world: World, human: str | Actor | Sequence[str | Actor], cache: Any = True, progress: bool = False
) -> Any:
    """One compiled human, a :class:`CompiledPopulation` for a list, a :class:`CompiledSchedule` for a switching one.

    A learned SB3 human cannot be compiled (no exact distribution); it plays as a
    :class:`~hg_marl.agents.batched_learned.BatchedLearned` (one forward pass of its
    policy per step over all tables), alone or as a member of a population.
    """
    from hg_marl.agents.humans.switching import SwitchingHuman

    if isinstance(human, SwitchingHuman):
        return _compiled_schedule(world, human, cache, progress)
    members = [_batched_member(world, h, cache, progress) for h in as_list(human)]
    return members[0] if len(members) == 1 else CompiledPopulation(members)


def _batched_member(world: World, human: str | Actor, cache: Any, progress: bool) -> Any:
    """A human as an array partner: a learned SB3 policy batched, any other compiled (a spec keeps its cache key)."""
    from hg_marl.agents.batched_learned import BatchedLearned, is_sb3_learned
    from hg_marl.agents.compiled import compile_human
    from hg_marl.agents.humans.registry import parse_human

    live: Any = human
    if isinstance(human, str):
        live = resolve_human(human) if parse_human(human)[0] == "learned" else None
    if is_sb3_learned(live):
        return BatchedLearned(world, live, name=human if isinstance(human, str) else None)
    return compile_human(world, human, cache=cache, progress=progress)


def compiled_robots(
    world: World, robot: str | Actor | Sequence[str | Actor], num_envs: int, cache: Any = True, progress: bool = False
) -> Any:
    """A compiled robot when every spec is a compilable name (``"planner"``), else :class:`LiveRobots`.

    A scenario over the compiler's budget (``roboergosum``) keeps live robots, with a warning.
    """
    from hg_marl.agents.compiled import CompileError
    from hg_marl.agents.compiled_robot import COMPILABLE, compile_robot

    specs = as_list(robot)
    if all(isinstance(s, str) for s in specs) and len(set(specs)) == 1 and specs[0] in COMPILABLE:
        try:
            return compile_robot(world, str(specs[0]), cache=cache, progress=progress)
        except CompileError as exc:  # over the budget (a large scenario): live robots, said once
            logger.warning("%s; the human's seat uses live robots", exc)
    return LiveRobots(world, robot, num_envs)


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
    """
    from hg_marl.envs.batched import BatchedTable, check_batch

    world = World(scenario, durations)
    n = check_batch(world, num_envs)
    return BatchedTable(
        compiled_robots(world, robot, n, cache, progress) if compiled else LiveRobots(world, robot, n),
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
