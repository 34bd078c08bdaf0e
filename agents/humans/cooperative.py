"""``cooperative``: executes the human stream of the planner's shared plan.

At its turn (after the robot's action in the same cycle) the human plans for both agents
with ``to_move=HUMAN`` and does the human action the plan expects next, as a partner who
shares the robot's plan would (the paper's assumption, HATP's cooperative human). When
the robot is offering an object it takes it. If the plan fails or expects nothing of the
human, it waits.

The plan depends on the state only, so the human is stationary; answers are memoised
per state (the planner is deterministic), which keeps the oracle's model build cheap.
Every cache behind an answer (this memo, the planner's intents, the shared search
space's bounds and expansions) holds a pure function of its key, so a warm instance
answers exactly as a fresh one: the human never depends on what it was asked before.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from hg_marl.agents.humans.base import (
    Distribution,
    StationaryHuman,
    check_p_idle,
    deterministic,
    index_of,
    wait_index,
    with_idle,
)
from hg_marl.core import Agent, Kind, State, World

_MEMO_LIMIT = 500_000


def seen_representatives(world: World) -> list[int]:
    """Per robot action, the first action the cooperative human answers alike (its class's representative).

    The planner only uses the robot action's duration and whether it is a wait or a give
    (an unanswered give is no robot activity): one representative per class multiplies
    memo and planner-cache hits without changing an answer, and the model builder asks
    once per class (``agents/models/answers.py``).
    """
    classes: dict[tuple[float, bool, bool], int] = {}
    return [
        classes.setdefault((world.durations.of(a.kind), a.kind is Kind.WAIT, a.kind is Kind.GIVE), i)
        for i, a in enumerate(world.actions(Agent.ROBOT))
    ]


class CooperativeHuman(StationaryHuman):
    """Follows the shared plan.

    Args:
        p_idle: probability of doing nothing at any turn (0: a perfect partner).
        planner_config: a ``PlannerConfig`` for the human's planner (default settings).
    """

    name = "cooperative"
    uses_robot_action = True
    equivariant = True  # the planner answers for the canonical state and maps the actions back

    def __init__(self, p_idle: float = 0.0, planner_config: Any = None) -> None:
        super().__init__()
        self.p_idle = check_p_idle(p_idle)
        self.planner_config = planner_config
        self._planner: Any = None
        self._planner_world: World | None = None
        self._memo: dict[tuple[State, int], int] = {}
        self._canonical: list[int] = []

    def planner(self, world: World) -> Any:
        """The planner for ``world`` (built on first use; the planner package is imported lazily)."""
        if self._planner is None or self._planner_world is not world:
            from hg_marl.agents.planner import Planner, PlannerConfig

            # cache_suffixes=False: a cached plan suffix is *an* optimal plan, a cold search may
            # break ties differently; caching exact repeats only keeps every answer equal to a
            # cold search's, a function of the state alone, so the oracle's model and the live
            # human agree exactly.
            config = replace(self.planner_config or PlannerConfig(), cache_suffixes=False)
            self._planner = Planner(world, config=config, human_model=None)
            self._planner_world = world
            self._memo = {}
            self._canonical = seen_representatives(world)
        return self._planner

    def planned_action(self, world: World, state: State, robot_action: int = -1) -> int:
        """The human action the shared plan expects at ``state`` (``wait`` if none).

        ``robot_action`` (the robot's successful action of this cycle, -1 if unknown)
        tells the planner how long the cycle already lasts, so the human does in parallel
        what fits in the robot's action instead of waiting.
        """
        planner = self.planner(world)
        robot_action = self._canonical[robot_action] if robot_action >= 0 else -1
        index = self._memo.get((state, robot_action))
        if index is None:
            if state.offer_by == Agent.ROBOT and world.holding(state, Agent.HUMAN) < 0:
                index = index_of(world, Kind.TAKE, state.offer_obj)
            else:
                intent = planner.intent(
                    state, to_move=Agent.HUMAN, robot_action=robot_action if robot_action >= 0 else None
                )
                index = intent.human_action if intent.success and intent.human_action >= 0 else wait_index(world)
            if len(self._memo) > _MEMO_LIMIT:
                self._memo.clear()
            self._memo[(state, robot_action)] = index
        return index

    def seen_representatives(self, world: World) -> list[int]:
        """Per robot action, the one it answers alike (:func:`seen_representatives`)."""
        return seen_representatives(world)

    def distribution(self, world: World, state: State, robot_action: int = -1) -> Distribution:
        """The planned action (mixed with ``wait`` by ``p_idle``)."""
        return with_idle(deterministic(self.planned_action(world, state, robot_action)), world, self.p_idle)
