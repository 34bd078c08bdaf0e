"""TableCleaning-v0: a robot and a human clean a table together (Renaudo et al. 2015).

Spec sheet
----------
============================  =================================================================
Import                        ``import hg_marl; env = hg_marl.env(scenario="paper2015")``
Registered ids                ``pettingzoo.make("aec", "hg_marl/TableCleaning-v0")`` (and
                              ``"parallel"``)
Agents                        ``["robot", "human"]``, AEC order robot, human, robot, ...
Action spaces                 ``Discrete``: robot ``pick/throw/give/take(o)``, ``goto(x)`` for x in
                              objects, bins and the human, ``wait`` (18 for ``paper2015``);
                              human ``pick/throw/give/take(o)``, ``place(o, spot)``, ``wait``.
                              Names: ``env.unwrapped.action_names(agent)``.
Observation space             ``Dict(observation=Box(0, 1, (F,), int8), action_mask=Box(0, 1,
                              (A,), int8))``: the paper's boolean facts (``fact_names``) and the
                              feasible actions of the agent.
Rewards                       1 to both agents when the robot waits on a clean table (every
                              object in its bin), else 0.
Termination                   episodic (default): at the end of the cycle in which the task was
                              completed. Continuing (``continuing=True``, the paper's
                              experiments): the table is re-drawn and play goes on.
Truncation                    after ``max_cycles`` cycles or when the clock reaches
                              ``time_budget`` simulated seconds.
History (opt-in)              ``history=k`` (default 0: off) appends the interaction history
                              of the last ``k`` cycles to ``observation`` (``Box(0, 1, (F + H,),
                              int8)``, ``H = hg_marl.envs.history.history_size(k)``): both
                              agents' action kinds and failures and the partner's cycles since
                              progress, relative to the observer (``hg_marl/envs/history.py``).
Render modes                  ``ansi`` (text), ``rgb_array`` (labelled numpy image); no window,
                              ever (``human`` is refused with a pointer to ``--video``).
============================  =================================================================

Rules. An action whose preconditions fail is legal input: it has no effect, costs the
precondition check (``durations.failed``) and is reported in ``infos[agent]["failed"]``;
learning robots must discover this, as in the paper. An action outside the action space
raises :class:`InvalidActionError`. A handover takes two turns: the giver's ``give(o)``,
then the partner's ``take(o)`` on its very next turn; any other reply lets the offer
lapse.

Time. A cycle is the robot's turn then the human's. The agents act in parallel, so the
simulated clock advances at the end of each cycle by the longer of the two actions'
durations, plus any decision time a runner charged with :meth:`raw_env.charge_time`.

Infos (per agent, after its turn) have a fixed structure, so replay buffers (Tianshou,
RLlib) can store them: always the same keys, each with one type and shape for the whole
run. ``clock`` (float), ``cycle`` (int), ``tasks_solved`` (int), ``action`` (str, the
name; ``""`` before the first move), ``failed`` (bool), ``events`` (str: the sentences of
its last action joined by ``"; "``, ``""`` when nothing happened), and cumulative
``effort`` (float, seconds spent on physical actions) and ``idle`` (float, seconds
waiting). ``events_tuple=True`` makes ``events`` a tuple of sentences instead (its
length varies, so only for readers that do not batch infos).

Version history: v0 - initial release.
"""

from __future__ import annotations

import operator
from collections.abc import Mapping
from typing import Any, ClassVar

import numpy as np
from gymnasium import spaces
from pettingzoo import AECEnv
from pettingzoo.utils import wrappers

from hg_marl.core import AGENT_NAMES, Agent, Durations, Event, Scenario, State, World
from hg_marl.core.cycle import Clock, Half, Halves
from hg_marl.core.errors import ConfigError, check_bool, check_finite, check_int
from hg_marl.envs.render import HUMAN_MESSAGE, caption_of, render_ansi, render_rgb
from hg_marl.policy import Turn

_NO_HALF = Half(State((), -1), True, 0.0, 0.0, (), 0.0, False)
"""Stands for the robot's half before the first cycle (each cycle overwrites it before closing)."""
_AGENT_OF = {name: Agent(i) for i, name in enumerate(AGENT_NAMES)}
EVENT_SEPARATOR = "; "
"""Joins the sentences of ``infos[agent]["events"]`` (split on it to get them back)."""


class InvalidActionError(ValueError):
    """An action outside the agent's action space (a programming error, not a failed action)."""


class raw_env(AECEnv):
    """The AEC environment without wrappers; see the module docstring for the spec."""

    metadata: ClassVar[dict[str, Any]] = {
        "name": "TableCleaning-v0",
        "render_modes": ["ansi", "rgb_array"],
        "is_parallelizable": True,
        "render_fps": 2,
    }

    def __init__(
        self,
        scenario: str | Scenario = "paper2015",
        continuing: bool = False,
        max_cycles: int | None = 500,
        time_budget: float | None = None,
        render_mode: str | None = None,
        durations: Durations | None = None,
        events_tuple: bool = False,
        history: int = 0,
    ) -> None:
        """Build the environment.

        Args:
            scenario: built-in name (``paper2015``, ``roboergosum``,
                ``generated:objects=N,...``), a TOML path or a :class:`Scenario`.
            continuing: re-draw the table after each success instead of terminating.
            max_cycles: truncate after this many cycles (None: no limit).
            time_budget: truncate once the simulated clock reaches this (None: no limit).
            render_mode: None, ``"ansi"`` or ``"rgb_array"``.
            durations: override the scenario's action durations.
            events_tuple: ``infos[agent]["events"]`` as a tuple of sentences instead of
                one ``"; "``-joined string (see the module docstring).
            history: cycles of interaction history appended to observations (0: none).
        """
        super().__init__()
        if render_mode == "human":
            raise ValueError(HUMAN_MESSAGE)
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(
                f"render_mode {render_mode!r} is not supported; use one of {self.metadata['render_modes']} or None"
            )
        check_bool(continuing, "continuing")
        if max_cycles is not None:
            max_cycles = check_int(max_cycles, "max_cycles", minimum=1)
        if time_budget is not None:
            time_budget = check_finite(time_budget, "time_budget (simulated seconds)", positive=True)
        if isinstance(durations, Mapping):
            durations = Durations.from_mapping(durations, "durations")
        elif durations is not None and not isinstance(durations, Durations):
            raise ConfigError(f"durations: expected a Durations or a mapping like {{'pick': 2.0}}, got {durations!r}")
        self.world = World(scenario, durations)
        self.continuing = continuing
        self.max_cycles = max_cycles
        self.time_budget = time_budget
        self.render_mode = render_mode
        self.possible_agents = list(AGENT_NAMES)
        self._n_actions = [self.world.n_actions(a) for a in Agent]
        self._action_spaces = {name: spaces.Discrete(n) for name, n in zip(AGENT_NAMES, self._n_actions, strict=True)}
        from hg_marl.envs.history import HistoryTracker

        self._history = HistoryTracker(self.world, history)
        self._ok = [True, True]
        f = self.world.n_facts + self._history.size
        self._observation_spaces = {
            name: spaces.Dict(
                {
                    "observation": spaces.Box(0, 1, (f,), np.int8),
                    "action_mask": spaces.Box(0, 1, (n,), np.int8),
                }
            )
            for name, n in zip(AGENT_NAMES, self._n_actions, strict=True)
        }
        self._half = Halves(self.world).play
        self.events_tuple = bool(events_tuple)
        self._event_text: dict[tuple[Event, ...], str | tuple[str, ...]] = {}
        self._rng = np.random.default_rng()
        self.world_state: State = self.world.initial_state(self._rng)
        """The full symbolic state (read it; the environment replaces it, never mutates it)."""

    # ---- spaces and names ----------------------------------------------------------
    def observation_space(self, agent: str) -> spaces.Space:
        return self._observation_spaces[agent]

    def action_space(self, agent: str) -> spaces.Space:
        return self._action_spaces[agent]

    def action_names(self, agent: str) -> tuple[str, ...]:
        """Readable name of every action index of ``agent``."""
        return self.world.action_names[self._agent_id(agent)]

    @property
    def fact_names(self) -> tuple[str, ...]:
        """Name of each entry of the observation's fact vector."""
        return self.world.fact_names

    def _agent_id(self, agent: str) -> Agent:
        try:
            return Agent(AGENT_NAMES.index(agent))
        except ValueError:
            raise KeyError(f"unknown agent {agent!r}; agents are {list(AGENT_NAMES)}") from None

    # ---- lifecycle -------------------------------------------------------------------
    def reset(self, seed: int | None = None, options: dict[str, Any] | None = None) -> None:
        """Start an episode; ``options={"state": State}`` starts from a given state."""
        if seed is not None:
            self._rng = np.random.default_rng(seed)
        options = options or {}
        self.world_state = options.get("state") or self.world.initial_state(self._rng)
        self.agents = list(self.possible_agents)
        self.rewards = dict.fromkeys(self.agents, 0.0)
        self._cumulative_rewards = dict.fromkeys(self.agents, 0.0)
        self.terminations = dict.fromkeys(self.agents, False)
        self.truncations = dict.fromkeys(self.agents, False)
        self.clock = 0.0
        self.cycles = 0
        self.tasks_solved = 0
        self._effort = [0.0, 0.0]
        self._clock = Clock(self.max_cycles, self.time_budget)
        self._redraw = self._rng if self.continuing else None  # the generator of a continuing run's redraws
        self._idle = self._clock.idle
        self._robot_half = _NO_HALF  # the robot's half of the cycle under way
        self._charged = 0.0
        self._done_this_cycle = False
        self._last_actions = [-1, -1]
        self._last_events: list[tuple[Event, ...]] = [(), ()]
        self._history.reset()
        self.infos = {a: self._info(Agent(i), "", False, ()) for i, a in enumerate(self.agents)}
        self.agent_selection = self.agents[0]

    def charge_time(self, seconds: float) -> None:
        """Add decision time (e.g. planning) to the current cycle's duration."""
        self._charged += check_finite(seconds, "charge_time(seconds)", minimum=0.0)

    def _check_action(self, agent: Agent, action: Any) -> int:
        n = self._n_actions[agent]
        try:
            index = operator.index(action.item() if isinstance(action, np.ndarray) and action.size == 1 else action)
        except TypeError:
            raise InvalidActionError(
                f"action {action!r} for agent {AGENT_NAMES[agent]!r} is not an integer; expected an index in [0, {n})"
            ) from None
        if not 0 <= index < n or isinstance(action, bool):
            raise InvalidActionError(
                f"action {action!r} is out of range for agent {AGENT_NAMES[agent]!r}: expected an integer in "
                f"[0, {n}) (see env.unwrapped.action_names({AGENT_NAMES[agent]!r}))"
            )
        return index

    def step(self, action: Any) -> None:
        """Execute the selected agent's action (a Discrete index)."""
        name = self.agent_selection
        if self.terminations[name] or self.truncations[name]:
            self._was_dead_step(action)
            return
        agent = _AGENT_OF[name]
        if type(action) is not int or not 0 <= action < self._n_actions[agent]:
            action = self._check_action(agent, action)
        out = self._half(self.world_state, agent, action, self._redraw)
        self.world_state = out.state
        self._last_actions[agent] = action
        self._effort[agent] += out.effort
        self._ok[agent] = out.ok
        events = out.events
        reward = out.reward
        if reward:
            self.tasks_solved += 1
            self.rewards = dict.fromkeys(self.agents, reward)
            if not self.continuing:
                self._done_this_cycle = True
        else:
            self.rewards = dict.fromkeys(self.agents, 0.0)
        self._last_events[agent] = events
        self.infos[name] = self._info(agent, self.world.action_names[agent][action], not out.ok, events)
        cumulative = self._cumulative_rewards
        cumulative[name] = 0.0
        if reward:
            for a in self.agents:
                cumulative[a] += reward
        if agent is Agent.HUMAN:
            self._end_cycle(out)
            self.agent_selection = "robot"
        else:
            self._robot_half = out
            self.agent_selection = "human"

    def _end_cycle(self, human: Half) -> None:
        time = self._clock
        truncate = time.tick(self._robot_half, human, self._charged)
        self.clock = clock = time.now
        self.cycles = cycles = time.cycles
        idle = time.idle
        self._charged = 0.0
        if self._history.k:
            last, ok = self._last_actions, self._ok
            self._history.record(np.array(last[:1]), np.array(ok[:1]), np.array(last[1:]), np.array(ok[1:]))
        done = self._done_this_cycle
        if done or truncate:
            for name in self.agents:
                self.terminations[name] = done
                self.truncations[name] = truncate and not done
        tasks, effort, infos = self.tasks_solved, self._effort, self.infos
        for i, name in enumerate(self.agents):
            info = infos[name]
            info["clock"], info["cycle"], info["tasks_solved"] = clock, cycles, tasks
            info["effort"], info["idle"] = effort[i], idle[i]

    def _info(self, agent: Agent, action: str, failed: bool, events: tuple[Event, ...]) -> dict[str, Any]:
        """A fresh info dict (fixed keys and types: floats are Python floats, counters ints)."""
        text = self._event_text.get(events)
        if text is None:
            sentences = tuple(str(e) for e in events)
            text = self._event_text[events] = sentences if self.events_tuple else EVENT_SEPARATOR.join(sentences)
        return {
            "clock": self.clock,
            "cycle": self.cycles,
            "tasks_solved": self.tasks_solved,
            "action": action,
            "failed": failed,
            "events": text,
            "effort": self._effort[agent],
            "idle": self._idle[agent],
        }

    # ---- observations ----------------------------------------------------------------
    def observe(self, agent: str) -> dict[str, np.ndarray]:
        """Facts and this agent's action mask (shared read-only arrays)."""
        who = _AGENT_OF.get(agent) if type(agent) is str else None
        if who is None:
            raise ConfigError(f"observe: unknown agent {agent!r}; the agents are {', '.join(AGENT_NAMES)}")
        state = self.world_state
        facts = self.world.facts(state)
        if self._history.k:
            facts = np.concatenate([facts, self._history.features(who)[0]])
        return {"observation": facts, "action_mask": self.world.mask(state, who)}

    def turn(self, agent: str | None = None) -> Turn:
        """A :class:`Turn` for ``agent`` (default: the selected one), for scripted actors.

        ``events`` holds what happened since this agent's previous turn: its own last
        action's events, then its partner's. Only the last action of each agent is kept,
        so plain AEC use, which never calls this, stores nothing that grows.
        """
        name = agent or self.agent_selection
        me = self._agent_id(name)
        events = self._last_events[me] + self._last_events[me.other]
        return Turn(
            world=self.world,
            state=self.world_state,
            agent=me,
            observation=self.observe(name),
            clock=self.clock,
            reward=self._cumulative_rewards[name],
            tasks_solved=self.tasks_solved,
            events=events,
            last_actions=(self._last_actions[0], self._last_actions[1]),
        )

    def state(self) -> np.ndarray:
        """The global state for centralised critics: the fact vector."""
        return np.array(self.world.facts(self.world_state))

    # ---- rendering -------------------------------------------------------------------
    def render(self) -> str | np.ndarray | None:
        if self.render_mode is None:
            return None
        if self.render_mode == "ansi":
            return render_ansi(self.world, self.world_state, self.clock, self.cycles, self.tasks_solved)
        last = (self._last_actions[0], self._last_actions[1])
        return render_rgb(self.world, self.world_state, caption_of(self.world, self.clock, self.tasks_solved, last))

    def close(self) -> None:
        """Nothing to release: no window is ever opened."""


def env(**kwargs: Any) -> AECEnv:
    """The AEC environment with PettingZoo's standard order-enforcing wrapper.

    Out-of-range actions are rejected by the environment itself, with a clearer message
    than ``AssertOutOfBoundsWrapper`` and also under ``python -O``; infeasible actions are
    legal (no ``TerminateIllegalWrapper``), as in the paper.
    """
    return wrappers.OrderEnforcingWrapper(raw_env(**kwargs))
