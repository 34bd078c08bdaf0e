"""One play session: a person in the human seat, any robot in the other, one trace.

The session owns the environment and the robot. The robot's turn runs here, on the
server side, with its decision time charged to the simulated clock exactly as
:func:`hg_marl.training.runner.run` charges it; the person only ever sees the table
when it is the human's turn. Seeding follows the runner (one ``SeedSequence(seed)``
split into the environment's, the robot's and the human's generators), so the trace a
session writes, played back by the ``replay`` human through the runner with the same
seed and duration, reproduces the game action for action and reward for reward.

Every session is recorded (when given a directory) in the replay JSONL format of
:mod:`hg_marl.agents.humans.trace`: the header's ``meta`` says who played, when, with
which front end and against which robot spec; each step carries the person's response
time (wall seconds from the moment the choice was shown to the moment it was made).
"""

from __future__ import annotations

import dataclasses
import getpass
import inspect
import time
from collections import Counter
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

import numpy as np

import hg_marl
from hg_marl.agents.humans.trace import TraceWriter
from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.registry import ROBOTS
from hg_marl.core import Agent, State, World
from hg_marl.core.errors import ConfigError, HumanError, RobotError
from hg_marl.core.spec import bind, parse_spec
from hg_marl.policy import Actor, Turn, decision_of

SHORTCUTS = "123456789abcdefghijklmnopqrstuvxyz"
"""Keyboard shortcuts of the feasible actions, in order (``w`` is kept for ``wait``)."""

WAIT_KEY = "w"


@dataclass(frozen=True)
class Choice:
    """One feasible action of the person."""

    index: int
    """The action index in the human's action space."""
    name: str
    """Its readable name (``take(tape1)``)."""
    key: str
    """The keyboard shortcut shown beside it."""


@dataclass(frozen=True)
class RobotMove:
    """What the robot did on its last turn and why (read from its decision record)."""

    action: int
    """The executed action index."""
    name: str
    """Its readable name."""
    expert: str
    """Who proposed it: ``planner``, ``habit`` or the robot's own name."""
    decision_time: float
    """Simulated seconds charged for deciding."""
    failed: bool
    """Whether its preconditions failed (no effect)."""
    weights: Mapping[str, float] = field(default_factory=dict)
    """The MetaController criterion's numbers behind the choice (hybrid robots; finite
    values only); empty for robots without one."""
    weight_amplitude: float | None = None
    """The habit's weight amplitude; None for a robot without a habit."""
    reason: str = ""
    """Why this expert (the record's reason code, see :data:`~hg_marl.training.play.explain.REASONS`)."""
    expects: str = ""
    """The person's move the robot's plan expects next (its name; "" when none)."""
    planner_consulted: bool = False
    """Whether the planner was asked."""
    planner_success: bool = False
    """Whether it found a plan."""
    planner_nodes: int = 0
    """Search nodes it expanded."""


def robot_move(robot: Actor, world: World, action: int, failed: bool) -> RobotMove:
    """The robot's last decision as a :class:`RobotMove`, read through the typed record.

    :func:`hg_marl.policy.decision_of` gives every actor a :class:`~hg_marl.policy.Decision`
    (one naming its class if it keeps none), so any robot can be shown; the MetaController's
    numbers are the record's ``stats``. The habit's weight amplitude is kept only when the
    robot has a habit (it proposed, or acted).
    """
    record = decision_of(robot)
    weights: dict[str, float] = {}
    for key, value in record.stats:
        if isinstance(value, int | float) and not isinstance(value, bool) and np.isfinite(value):
            weights[str(key)] = float(value)
    has_habit = record.habit_action >= 0 or record.expert == "habit"
    amplitude = float(record.weight_amplitude)
    expected = int(record.expected_human_action)
    names = world.action_names
    return RobotMove(
        action=action,
        name=names[Agent.ROBOT][action],
        expert=str(record.expert),
        decision_time=float(record.decision_time),
        failed=failed,
        weights=weights,
        weight_amplitude=amplitude if has_habit and np.isfinite(amplitude) else None,
        reason=str(record.reason),
        expects=names[Agent.HUMAN][expected] if 0 <= expected < len(names[Agent.HUMAN]) else "",
        planner_consulted=bool(record.planner_consulted),
        planner_success=bool(record.planner_success),
        planner_nodes=int(record.planner_nodes),
    )


def build_robot(spec: str) -> Actor:
    """A robot from a ``name:k=v,...`` spec (``hybrid:criterion=vpi``), via ``make_robot``.

    Raises:
        RobotError: an unknown robot or parameter, or a bad value (the message names it).
    """
    parsed = parse_spec(spec, "--robot")
    entry = ROBOTS.get(parsed.name)
    if entry is None:
        raise RobotError(f"--robot {spec!r}: unknown robot {parsed.name!r}; available: {', '.join(ROBOTS)}")
    defaults = {
        name: (None if p.default is inspect.Parameter.empty else p.default)
        for name, p in inspect.signature(entry.factory()).parameters.items()
    }
    params = bind(parsed, defaults, what=f"robot {parsed.name!r}", error=RobotError)
    try:
        return make_robot(parsed.name, **params)
    except (ValueError, TypeError, OSError) as exc:
        raise RobotError(f"--robot {spec!r}: {exc}") from None


class PlaySession:
    """A game between a person (the human seat) and a robot.

    Args:
        robot: the robot's spec (``planner``, ``hybrid:criterion=entropy_and_cost``, ...).
        scenario: scenario name, ``generated:...`` spec or TOML path.
        seed: seeds the layouts and the robot, as in the runner.
        record: directory for the trace (None: not recorded).
        player: who plays (written in the trace; default: the login name).
        frontend: ``browser`` or ``terminal`` (written in the trace).
        timer: wall clock for response times (tests pass a fake one).
    """

    def __init__(
        self,
        robot: str = "planner",
        scenario: str = "paper2015",
        seed: int = 0,
        record: str | Path | None = None,
        player: str | None = None,
        frontend: str = "browser",
        timer: Callable[[], float] = time.monotonic,
    ) -> None:
        if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
            raise ConfigError(f"--seed: expected a non-negative integer, got {seed!r}")
        if record is not None:
            check_record_dir(Path(record))
        self.robot_spec = robot
        self.robot = build_robot(robot)
        self.seed = seed
        self.player = player or _login()
        self.timer = timer
        self.env = hg_marl.env(scenario=scenario, continuing=True, max_cycles=None, time_budget=None)
        self.raw: Any = self.env.unwrapped
        self.world: World = self.raw.world
        env_seq, robot_seq, _human_seq = np.random.SeedSequence(seed).spawn(3)
        self.env.reset(seed=int(env_seq.generate_state(1)[0]))
        self.robot.reset(self.world, Agent.ROBOT, np.random.default_rng(robot_seq))
        self.started = datetime.now(UTC)
        self.trace_path: Path | None = None
        self._writer: TraceWriter | None = None
        if record is not None:
            stamp = self.started.strftime("%Y%m%dT%H%M%S%fZ")
            self.trace_path = Path(record) / f"play-{stamp}-{self.world.scenario.name}-seed{seed}.jsonl"
            self._writer = TraceWriter(self.trace_path)
            self._writer.header(
                self.world,
                Agent.HUMAN,
                seed=seed,
                actor="person",
                meta={
                    "player": self.player,
                    "started": self.started.isoformat(),
                    "robot": robot,
                    "frontend": frontend,
                    "duration_protocol": "runner: continuing, decision time charged",
                },
            )
        self.last_robot: RobotMove | None = None
        self.last_human = ""
        self.response_times: list[float] = []
        self.rewards = 0.0
        self.closed = False
        """Whether :meth:`close` ran (no more moves)."""
        self.solved_at: list[float] = []
        """Simulated clock at each solved task."""
        self.just_solved = 0
        """Tasks solved by the last move and the robot's answer (the page says so)."""
        self.experts: Counter[str] = Counter()
        """How often each expert chose the robot's move."""
        self.handovers: Counter[str] = Counter()
        """Gives and takes by each side: ``you_gave``, ``robot_took``, ``robot_gave``, ``you_took``."""
        self._robot_turn()

    # ---- what the front ends read -------------------------------------------------
    @property
    def state(self) -> State:
        """The full symbolic state (the table as the person sees it)."""
        return self.raw.world_state

    @property
    def clock(self) -> float:
        """Simulated seconds so far."""
        return float(self.raw.clock)

    @property
    def tasks_solved(self) -> int:
        """Tasks completed so far."""
        return int(self.raw.tasks_solved)

    @property
    def cycle(self) -> int:
        """Completed robot-human cycles."""
        return int(self.raw.cycles)

    def choices(self) -> tuple[Choice, ...]:
        """The person's feasible actions, each with its shortcut (``w`` for wait)."""
        mask = self.world.mask(self.state, Agent.HUMAN)
        names = self.world.action_names[Agent.HUMAN]
        out: list[Choice] = []
        keys = iter(SHORTCUTS)
        for index in np.flatnonzero(mask):
            name = names[int(index)]
            out.append(Choice(int(index), name, WAIT_KEY if name == "wait" else next(keys, "")))
        return tuple(out)

    # ---- playing ----------------------------------------------------------------------
    def play(self, action: int | str) -> None:
        """The person's move (an action index or name), then the robot's next turn.

        Raises:
            HumanError: an unknown or currently infeasible action (nothing happens).
        """
        if self.closed:
            raise HumanError("the game is over (the session was closed)")
        index = self._resolve(action)
        response = max(0.0, self.timer() - self._shown_at)
        turn = self.raw.turn("human")
        if self._writer is not None:
            self._writer.step(turn, index, extra={"response_time": round(response, 3)})
        self.response_times.append(response)
        before = self.tasks_solved
        self.env.step(index)
        self.last_human = self.world.action_names[Agent.HUMAN][index]
        if not self.raw.infos["human"]["failed"]:
            self._count_handover("you", self.last_human)
        self.rewards += float(self.raw.rewards["robot"])
        self._note_solved(before)
        self._robot_turn()
        self.just_solved = self.tasks_solved - before

    def _count_handover(self, who: str, name: str) -> None:
        for verb, past in (("give(", "gave"), ("take(", "took")):
            if name.startswith(verb):
                self.handovers[f"{who}_{past}"] += 1

    def _note_solved(self, before: int) -> None:
        self.solved_at.extend([self.clock] * (self.tasks_solved - before))

    def _resolve(self, action: int | str) -> int:
        names = self.world.action_names[Agent.HUMAN]
        if isinstance(action, str):
            if action not in names:
                raise HumanError(f"unknown action {action!r}; the human's actions: {', '.join(names)}")
            index = names.index(action)
        elif isinstance(action, bool) or not isinstance(action, int | np.integer) or not 0 <= action < len(names):
            raise HumanError(f"action {action!r} is not an index in [0, {len(names)})")
        else:
            index = int(action)
        if not self.world.mask(self.state, Agent.HUMAN)[index]:
            feasible = ", ".join(c.name for c in self.choices())
            raise HumanError(f"{names[index]} is not feasible now; feasible: {feasible}")
        return index

    def _robot_turn(self) -> None:
        turn: Turn = self.raw.turn("robot")
        action = int(self.robot.act(turn))
        move = robot_move(self.robot, self.world, action, False)
        if move.decision_time > 0:
            self.raw.charge_time(move.decision_time)
        before = self.tasks_solved
        self.env.step(action)
        self.rewards += float(self.raw.rewards["robot"])
        self._note_solved(before)
        self.last_robot = dataclasses.replace(move, failed=bool(self.raw.infos["robot"]["failed"]))
        self.experts[move.expert] += 1
        if not self.last_robot.failed:
            self._count_handover("robot", move.name)
        self._shown_at = self.timer()

    def close(self) -> Path | None:
        """Finish the trace; returns its path (None when not recording). Idempotent."""
        self.closed = True
        if self._writer is not None:
            self._writer.end(self.clock, self.tasks_solved, self.rewards)
            self._writer.close()
            self._writer = None
        return self.trace_path

    def summary(self) -> dict[str, Any]:
        """Clock, tasks, moves and mean response time of the session so far."""
        rt = self.response_times
        return {
            "player": self.player,
            "robot": self.robot_spec,
            "clock": self.clock,
            "tasks_solved": self.tasks_solved,
            "moves": len(rt),
            "mean_response_time": float(np.mean(rt)) if rt else None,
            "trace": str(self.trace_path) if self.trace_path else None,
            "experts": dict(self.experts),
            "handovers": {k: self.handovers[k] for k in ("you_gave", "robot_took", "robot_gave", "you_took")},
        }

    def summary_text(self) -> str:
        """The game in words and numbers (the finish page, the terminal's last lines)."""
        s = self.summary()
        n, clock = s["tasks_solved"], s["clock"]
        per_task = f" ({clock / n:.1f} s a task)" if n else ""
        h = s["handovers"]
        experts = ", ".join(f"{name} {count}" for name, count in sorted(self.experts.items()))
        rt = s["mean_response_time"]
        return (
            f"{self.player} played {s['moves']} {_plural(s['moves'], 'move')} with the robot {self.robot_spec} "
            f"on {self.world.scenario.name} (seed {self.seed}): {n} {_plural(n, 'task')} solved in "
            f"{clock:.1f} simulated seconds{per_task}. Handovers: you gave {h['you_gave']} and the robot "
            f"took {h['robot_took']}; the robot gave {h['robot_gave']} and you took {h['you_took']}. "
            f"The robot's {sum(self.experts.values())} moves were chosen by: {experts or 'nobody'}."
            + (f" Your mean response time: {rt:.1f} s." if rt is not None else "")
        )


def _plural(n: int, word: str) -> str:
    return word if n == 1 else word + "s"


def check_record_dir(record: Path) -> None:
    """Refuse a ``--record`` that names a file (or lies under one): traces need a directory.

    Raises:
        ConfigError: naming the option and the file in the way.
    """
    from hg_marl.training.outputs import check_output

    check_output(record, "--record", folder=True)


def _login() -> str:
    try:
        return getpass.getuser()
    except (KeyError, OSError):
        return "anonymous"
