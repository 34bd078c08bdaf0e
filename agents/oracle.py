"""The oracle: the optimal robot policy and its reward rate against a known stationary human.

Model. A semi-MDP on the symbolic :class:`~hg_marl.core.State` at the robot's turn
(continuing mode, the paper's protocol). From state ``s`` the robot takes action ``a``;
then the human, whose policy is folded into the dynamics through its exact
``distribution(world, state)``, answers; the cycle lasts ``max(d_robot, d_human)``
simulated seconds (the environment's clock; no decision time). The robot's ``wait`` on a
clean table earns 1, and the table is re-drawn from the scenario's layout distribution
(enumerated exactly with its probabilities by :func:`layout_distribution`), the robot's
location included, before the human's move of that same cycle. Every action of the
action space is modelled: infeasible ones all have the same effect (0.2 s, nothing done,
a pending offer lapses), so one representative stands for them (``failed_actions``).

Build and solution (``agents/models``, ``docs/exact-references.md``). The model is
built breadth-first on arrays (:func:`~hg_marl.agents.models.build_model`: packed state
keys, the batched rules, the partner's answers in an
:class:`~hg_marl.agents.models.AnswerTable`) and solved on CSR
(:func:`~hg_marl.agents.models.solve`): each success is worth exactly 1 and is followed
by a re-drawn table, a regeneration point, so by the renewal-reward theorem the
average-reward problem is the stochastic shortest path to the next success, solved by
value iteration ``V(s) = min_a E[tau + V(s')]`` with ``V = 0`` after the completing
``wait``. States from which the robot cannot make success certain (e.g. an adversarial
human hid an object) get ``V = inf``; if the re-drawn table can lead there, the rate is
0. The Python enumeration it replaced (``PythonModel``) is kept as the tests' reference.

Symmetry. Objects accepted by the same bins are interchangeable. When the human is
``equivariant`` (relabelling them in the state relabels its answer: the planner-driven
``cooperative`` and ``noisy``, ``random``), the model keeps one canonical state per
relabelling class (:class:`~hg_marl.agents.planner.space.Relabel`) and draws the
canonical layouts directly (:func:`canonical_layouts`); the rate is the full model's
(tests), the policy is keyed by canonical states (:meth:`OracleResult.action_at` maps
an action back). Humans whose rule picks "the first object" by index (``lazy``,
``no_handover``, ``adversarial``) are not equivariant and get the full model.

Budget. One :class:`~hg_marl.agents.models.Budget` (``max_states``, ``max_memory``,
``max_seconds`` of wall time) is read in every phase: the layout count, the layout
enumeration, the partner's first answers, the exploration (per batch and between live
answers) and the solve; beyond it, one line (:class:`OracleTooLarge`) names the budget,
the phase and how far it got, so a study falls back to the best robot as reference.
Measured sizes and times: ``docs/exact-references.md`` and ``benchmarks/model_build.py``.
"""

from __future__ import annotations

import logging
import math
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.agents.models.answers import AnswerTable, stationary_human
from hg_marl.agents.models.budget import (
    DEFAULT_MEMORY,
    DEFAULT_SECONDS,
    DEFAULT_STATES,
    Budget,
    OverBudget,
    trim_heap,
)
from hg_marl.agents.models.builder import build_model
from hg_marl.agents.models.cache import cache_folder, entry_path, load_entry, result_key, save_entry
from hg_marl.agents.models.layouts import canonical_layout_count, canonical_layouts, layout_distribution
from hg_marl.agents.models.packing import PackedMap, StatePacker
from hg_marl.agents.models.solve import solve
from hg_marl.agents.planner.space import Relabel
from hg_marl.agents.progress import ProgressGuard
from hg_marl.core import Agent, Durations, Scenario, State, World
from hg_marl.core.scenario import layout_count
from hg_marl.core.spec import AgentSpec
from hg_marl.policy import Decision, Turn

logger = logging.getLogger(__name__)

HOUR = 3600.0


OracleTooLarge = OverBudget
"""The model exceeds its budget (states, memory or wall seconds): one line naming it."""


@dataclass(frozen=True)
class OracleResult:
    """The optimal rate, its policy, and the size of the model."""

    rate_per_hour: float
    """Optimal long-run tasks per simulated hour (0 if no policy can ever complete)."""
    seconds_per_task: float
    """Optimal expected simulated seconds between successes (inf if never)."""
    n_states: int
    """Robot-turn states in the model."""
    n_transitions: int
    """(state, robot action, human reply) transitions."""
    n_layouts: int
    """Distinct tables the re-draw can produce."""
    iterations: int
    """Value-iteration sweeps."""
    converged: bool
    """Whether the sweeps met the tolerance before ``max_iterations``."""
    policy: Mapping[State, int] = field(repr=False)
    """Optimal robot action index at every robot-turn state of the model."""
    values: Mapping[State, float] = field(repr=False)
    """Optimal expected seconds to the next success from each state (inf: not certain)."""
    scenario: str = ""
    """Scenario name."""
    human: str = ""
    """The human's name."""
    seconds: float = 0.0
    """Wall time of the build and solve."""
    reduced: bool = False
    """Whether the model holds canonical states only (interchangeable objects in canonical
    order, :class:`~hg_marl.agents.planner.space.Relabel`): then ``policy`` and ``values``
    are keyed by canonical states and the policy's actions are in canonical labelling;
    :meth:`action_at` and :meth:`value_at` answer for any state."""

    def action_at(self, world: World, state: State, relabel: Relabel | None = None) -> int | None:
        """The optimal robot action at ``state`` (any labelling), or None outside the model."""
        if not self.reduced:
            return self.policy.get(state)
        relabel = relabel or Relabel(world)
        key, orig = relabel.canonical(state)
        action = self.policy.get(key)
        return None if action is None else relabel.action_back(Agent.ROBOT, action, orig)

    def value_at(self, world: World, state: State, relabel: Relabel | None = None) -> float:
        """Optimal expected seconds to the next success from ``state`` (inf outside the model)."""
        if self.reduced:
            state = (relabel or Relabel(world)).canonical(state)[0]
        return self.values.get(state, math.inf)


def _from_entry(world: World, human: Any, stored: dict[str, np.ndarray], seconds: float) -> OracleResult:
    """An :class:`OracleResult` from a cache entry (see :func:`oracle_rate`)."""
    expected, n, n_transitions, n_layouts, iterations, converged, reduced = stored["scalars"].tolist()
    packer = StatePacker(world)
    return OracleResult(
        rate_per_hour=0.0 if math.isinf(expected) else HOUR / expected,
        seconds_per_task=expected,
        n_states=int(n),
        n_transitions=int(n_transitions),
        n_layouts=int(n_layouts),
        iterations=int(iterations),
        converged=bool(converged),
        policy=PackedMap(packer, stored["keys"], stored["policy"]),
        values=PackedMap(packer, stored["keys"], stored["values"]),
        scenario=world.scenario.name,
        human=str(getattr(human, "name", type(human).__name__)),
        seconds=seconds,
        reduced=bool(reduced),
    )


def oracle_rate(
    scenario: str | Scenario | World = "paper2015",
    human: Any = "cooperative",
    *,
    durations: Durations | None = None,
    failed_actions: bool = True,
    max_states: int = DEFAULT_STATES,
    tolerance: float = 1e-9,
    max_iterations: int = 200_000,
    progress: bool = False,
    symmetry: bool | None = None,
    max_seconds: float | None = DEFAULT_SECONDS,
    max_memory: int | None = DEFAULT_MEMORY,
    budget: Budget | None = None,
    cache: Path | str | bool | None = True,
    roots: Sequence[State] = (),
) -> OracleResult:
    """The optimal tasks per simulated hour against ``human``, and the policy achieving it.

    Args:
        scenario: scenario name / TOML path / Scenario, or a World (then ``durations`` is ignored).
        human: a stationary human: registry name (``"lazy:p_idle=0.5"``), a parsed
            :class:`~hg_marl.core.spec.AgentSpec`, or an instance with ``distribution(world, state)``.
        durations: override the scenario's durations.
        failed_actions: also consider deliberately infeasible actions (a 0.2 s no-op);
            True is the exact model of the environment's action space.
        max_states: stop with :class:`OracleTooLarge` beyond this many states (or layouts to enumerate).
        tolerance: value-iteration stopping threshold (seconds).
        max_iterations: cap on sweeps (``converged`` says whether it was hit).
        progress: show a progress bar on stderr with the states explored and known.
        symmetry: keep states up to interchangeable objects (canonical order). None: when
            the human says it is ``equivariant`` (its answer at a relabelled state is its
            answer relabelled), the only case where this is exact.
        max_seconds: wall-time budget of the whole computation in seconds (None: unlimited).
        max_memory: resident-memory budget in bytes (None: unlimited).
        budget: a :class:`~hg_marl.agents.models.budget.Budget` to use instead of the three above.
        cache: a folder to keep results in by content (``agents/models/cache.py``); True:
            ``$HG_MARL_CACHE/oracle`` when set, else none; None/False: none. Only a human
            given by its spec is cached.
        roots: the tables to solve from instead of every initial layout (empty: every
            layout). The model then holds the states reachable from them until a task is
            solved, and a solved task re-draws one of them: each state's value (the expected
            seconds to the next success) is the same as in the whole model, and
            ``rate_per_hour`` is the rate of a table re-drawn as ``roots``. Not cached, not
            reduced by symmetry.

    Raises:
        HumanError: the human is not stationary.
        OracleTooLarge: over the budget, in any phase (one line naming the budget, phase and progress).
    """
    start = time.perf_counter()
    if budget is None:
        budget = Budget(max_seconds, max_memory, max_states)
    with budget.deadline():
        world = scenario if isinstance(scenario, World) else World(scenario, durations)
        budget.subject = f"the oracle for {world.scenario.name!r}"
        budget.hint = "use the best robot as reference"
        policy_human = stationary_human(human, world)
        options = {
            "failed_actions": failed_actions,
            "symmetry": symmetry,
            "tolerance": tolerance,
            "max_iterations": max_iterations,
        }
        folder = cache_folder(cache) if isinstance(human, str | AgentSpec) and not roots else None
        entry: tuple[Path, str] | None = None  # where the result is kept, and its key
        if folder is not None:
            key = result_key(world, str(human), options)
            path = entry_path(folder, world, key)
            entry = (path, key)
            stored = load_entry(path, key)
            if stored is not None:
                return _from_entry(world, policy_human, stored, time.perf_counter() - start)
        relabel: Relabel | None = Relabel(world)
        if symmetry is None:
            symmetry = bool(getattr(policy_human, "equivariant", False))
        if roots or not (symmetry and relabel is not None and relabel.active):
            relabel = None
        if roots:
            layouts = [(state, 1.0 / len(roots)) for state in roots]
        else:
            deals = layout_count(world.scenario) if relabel is None else canonical_layout_count(world)
            budget.refuse_count("layouts", deals, "initial layouts")  # before enumerating them
            layouts = layout_distribution(world, budget) if relabel is None else canonical_layouts(world, budget)
        answers = AnswerTable(world, policy_human, StatePacker(world), budget)
        model = build_model(
            world,
            answers,
            layouts,
            failed_actions=failed_actions,
            canonical=relabel is not None,
            budget=budget,
            progress=progress,
            label=f"oracle {world.scenario.name}",
        )
        del answers  # the model holds its own copies of the answers: the solver's arrays need the room
        trim_heap(model.t_prob.nbytes)  # (its pages given back where the build was large: see trim_heap)
        solution = solve(model, tolerance=tolerance, max_iterations=max_iterations, budget=budget)
    expected = solution.seconds_per_task
    rate = 0.0 if math.isinf(expected) else HOUR / expected
    if entry is not None:
        save_entry(
            *entry,
            {
                "keys": model.keys,
                "policy": model.pair_action[solution.best_pair],
                "values": solution.values,
                "scalars": np.array(
                    [
                        expected,
                        model.n,
                        len(model.t_next),
                        len(layouts),
                        solution.iterations,
                        solution.converged,
                        relabel is not None,
                    ],
                    dtype=np.float64,
                ),
            },
        )
    result = OracleResult(
        rate_per_hour=rate,
        seconds_per_task=expected,
        n_states=model.n,
        n_transitions=len(model.t_next),
        n_layouts=len(layouts),
        iterations=solution.iterations,
        converged=solution.converged,
        policy=PackedMap(model.packer, model.keys, model.pair_action[solution.best_pair]),
        values=PackedMap(model.packer, model.keys, solution.values),
        scenario=world.scenario.name,
        human=str(getattr(policy_human, "name", type(policy_human).__name__)),
        seconds=time.perf_counter() - start,
        reduced=relabel is not None,
    )
    logger.info(
        "oracle %s vs %s: %.2f tasks/h, %d states, %d iterations, %.1f s",
        result.scenario,
        result.human,
        rate,
        model.n,
        solution.iterations,
        result.seconds,
    )
    return result


class OracleRobot:
    """A robot that plays the oracle's optimal policy (greedy in its values).

    Off its model (a state the model never reaches: the partner is not the human the
    policy was solved against) it does not wait for a known state to come back: it asks
    the planner (cooperative model) for the robot's next move, under the progress guard
    every robot obeys (:mod:`hg_marl.agents.progress`): when the state has not changed
    for ``K`` of its turns, it takes the guard's feasible move instead, so it never
    repeats a move that changes nothing (a wait, a refused offer) forever. ``off_model``
    counts the off-model decisions in the current run. On its model the policy is played
    as solved (it is optimal there; a wait against a partner who idles is part of it).

    Args:
        result: a computed :class:`OracleResult`; or None to compute one at the first reset
            from ``human`` and the world it is reset in.
        human: the human the policy is optimal against (when ``result`` is None).
    """

    name = "oracle"

    def __init__(self, result: OracleResult | None = None, human: Any = "cooperative") -> None:
        self.result = result
        self.human = human
        self.last_decision: Decision | None = None
        self.off_model = 0
        """Decisions taken at states outside the model in the current run (0 when the
        partner is the human the policy was solved against)."""
        self._planner: Any = None
        self._relabel: Relabel | None = None
        self.progress = ProgressGuard()
        self._solved: tuple[OracleResult | None, Any] = (None, None)
        """The result this robot last took up and the (scenario, durations) it belongs to."""

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        """Compute the policy if needed (``rng`` unused: the policy is deterministic).

        A policy belongs to the table it was solved on, durations included (doubling every
        duration doubles the seconds per task): a reset on another scenario or other
        durations solves again. A result handed over from outside (at construction, or by
        setting :attr:`result`) is taken as the policy of the table it names at its first reset.
        """
        if agent is not Agent.ROBOT:
            raise ValueError("OracleRobot plays the robot seat only")
        table = (world.scenario, world.durations)
        if (
            self.result is not None
            and self.result is not self._solved[0]
            and self.result.scenario == world.scenario.name
        ):
            self._solved = (self.result, table)
        if self.result is None or self.result.scenario != world.scenario.name or self._solved[1] != table:
            self.result = oracle_rate(world, self.human)
            self._solved = (self.result, table)
        self._wait = world.n_actions(Agent.ROBOT) - 1
        self.off_model = 0
        self.progress.reset()
        self._planner = None
        self._relabel = Relabel(world)

    def act(self, turn: Turn) -> int:
        """The optimal action at the turn's state (the planner's move outside the model)."""
        assert self.result is not None
        self.progress.observe(turn.state)
        action = self.result.action_at(turn.world, turn.state, self._relabel)
        if action is not None:
            seconds = self.result.value_at(turn.world, turn.state, self._relabel)
            self.last_decision = Decision("oracle", int(action), stats=(("expected_seconds", float(seconds)),))
            return int(action)
        self.off_model += 1
        if self.off_model == 1:
            logger.warning("oracle policy has no entry for state %s; falling back to the planner", turn.state)
        return self._fallback(turn)

    def _fallback(self, turn: Turn) -> int:
        """The planner's move; the progress guard's move once the state has not changed for ``K`` turns."""
        world, state = turn.world, turn.state
        if self._planner is None or self._planner.world is not world:
            from hg_marl.agents.planner import Planner

            self._planner = Planner(world)
        start = time.perf_counter()
        intent = self._planner.intent(state, Agent.ROBOT)
        action = intent.robot_action if intent.success else self._wait
        reason = "off model: the planner's move"
        if self.progress.stalled:
            action = self.progress.move(world, state)
            reason = (
                "off model: nothing moved for P turns; waiting patiently"
                if self.progress.waiting
                else "off model: nothing changed for K turns; the progress guard's move"
            )
        self.last_decision = Decision(
            "planner",
            int(action),
            planner_action=int(intent.robot_action) if intent.success else -1,
            planning_time=time.perf_counter() - start,
            planner_success=intent.success,
            planner_consulted=True,
            expected_human_action=int(intent.human_action) if intent.success else -1,
            reason=reason,
        )
        return int(action)
