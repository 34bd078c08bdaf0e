"""The belief robot's members' exact models: solved when first needed, kept by content.

Why (issue "ready in seconds"): solving every member's oracle before the first move cost
minutes on ``roboergosum``, yet a decision needs only the members the belief gives a say:
with ``hedge="map"`` one member (the most probable), with ``hedge="qmdp"`` those above
:data:`~hg_marl.agents.robots.belief.NEGLIGIBLE`. So a member's model is solved the first
time the belief asks for its values, and never again for the same content:

- **Lazily, most probable first.** :meth:`MemberModels.result` solves member ``m`` on
  demand; before the first move only the members the first decision consults are
  solved (under a uniform prior and ``map``: one). A decision reads the same values
  whether a member was solved at the start or on demand (the oracle is a pure function
  of its inputs), so what the robot decides does not change; only when the wall-clock
  work happens does. The work is wall time, never simulated time (the belief's
  decisions are not charged the solve).
- **Kept by content, in this process.** Results are memoised under the oracle cache's
  content key (:func:`~hg_marl.agents.models.cache.result_key`: scenario and durations,
  the member's spec and any file it names, the oracle's options, and the source of every
  module that can change an answer), so every robot of a study's worker shares them and a
  changed member or scenario is solved afresh. The memo keeps :data:`MEMO_ENTRIES`
  results (the oldest is dropped first), which bounds its memory.
- **Kept by content, on disk**, in the folder ``cache`` names (or ``$HG_MARL_CACHE/oracle``
  when ``cache`` is empty and the variable is set; nothing is written otherwise): the
  oracle's own content cache (``agents/models/cache.py``), one entry per member, so a
  changed member rebuilds that member only.
"""

from __future__ import annotations

from collections import OrderedDict
from pathlib import Path
from typing import Any, Protocol

from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.cache import cache_folder, named_folder, result_key
from hg_marl.agents.models.python_model import PythonModel
from hg_marl.agents.oracle import OracleResult, oracle_rate
from hg_marl.agents.planner.space import Relabel
from hg_marl.core import Agent, State, World

MEMO_ENTRIES = 32
"""Member results kept in this process (a ``roboergosum`` member's packed keys, policy and
values take a few MB)."""

_MEMO: OrderedDict[str, OracleResult] = OrderedDict()

ORACLE_OPTIONS: dict[str, Any] = {
    "failed_actions": True,
    "symmetry": None,
    "tolerance": 1e-9,
    "max_iterations": 200_000,
}
"""The options :func:`~hg_marl.agents.oracle.oracle_rate` solves members with (its defaults), part of the key."""


def clear_memo() -> None:
    """Forget every result kept in this process (tests; a long-lived process that changes code)."""
    _MEMO.clear()


class MemberModels:
    """Each member's oracle result and one-step model, built on first use.

    Args:
        specs: the members' human specs, in the belief's order.
        cache: a folder for the on-disk content cache, created and tried at once (a folder
            that cannot be written is refused); empty: ``$HG_MARL_CACHE/oracle`` when set,
            else no disk cache.
        option: what named ``cache``, for a refusal's message.
    """

    def __init__(self, specs: tuple[str, ...], cache: str = "", option: str = "cache") -> None:
        self.specs = specs
        self.cache: Path | None = named_folder(cache, option) if cache else cache_folder(True)
        self.world: World | None = None
        self._results: list[OracleResult | None] = [None] * len(specs)
        self._models: list[PythonModel | None] = [None] * len(specs)
        self.solved = 0
        """Members this object solved or read from a cache (each counted once per world)."""

    def reset(self, world: World) -> None:
        """Play in ``world``: results of another scenario (or durations) are dropped."""
        if self.world is None or (self.world.scenario, self.world.durations) != (world.scenario, world.durations):
            self.world = world
            self._results = [None] * len(self.specs)
            self._models = [None] * len(self.specs)
            self.solved = 0

    def built(self) -> list[int]:
        """The members whose results are at hand."""
        return [m for m, r in enumerate(self._results) if r is not None]

    def result(self, m: int) -> OracleResult:
        """Member ``m``'s oracle result: from this object, the process memo, the disk cache, or solved now."""
        result = self._results[m]
        if result is None:
            assert self.world is not None, "reset() first"
            key = result_key(self.world, self.specs[m], ORACLE_OPTIONS)
            result = _MEMO.get(key)
            if result is None:
                result = oracle_rate(self.world, self.specs[m], cache=self.cache or False, **ORACLE_OPTIONS)
                _MEMO[key] = result
                while len(_MEMO) > MEMO_ENTRIES:
                    _MEMO.popitem(last=False)
            else:
                _MEMO.move_to_end(key)
            self._results[m] = result
            self.solved += 1
        return result

    def model(self, m: int) -> PythonModel:
        """Member ``m``'s one-step model (its replies; nothing is enumerated)."""
        model = self._models[m]
        if model is None:
            assert self.world is not None, "reset() first"
            human = stationary_human(self.specs[m], self.world)
            model = self._models[m] = PythonModel(self.world, human, True, 1)
        return model


Replies = list[tuple[State, float, float]]
"""(next robot-turn state, probability, cycle seconds) per answer of the partner."""


class Values(Protocol):
    """What a one-step backup reads: the expected seconds to the next success of a state."""

    def value_at(self, world: World, state: State, relabel: Relabel | None = None) -> float: ...


def expand(world: World, state: State, model: PythonModel) -> list[tuple[int, Replies | None]]:
    """Per feasible robot action at ``state``: the partner's replies through ``model``, or None
    for the completing wait (the oracle's terminal pair). The oracle's own transition rule,
    one step: :func:`backup` reads it, and the observed solver keeps it per state."""
    table = world.table
    out: list[tuple[int, Replies | None]] = []
    for a in world.feasible_indices(state, Agent.ROBOT):  # feasible: each succeeds, and the partner sees it
        mid, _, duration = table.successor(state, Agent.ROBOT, a)
        out.append((a, None if table.solves(state, Agent.ROBOT, a) else model.replies(mid, duration, a)))
    return out


def backup(world: World, state: State, result: Values, model: PythonModel, relabel: Relabel) -> dict[int, float]:
    """Per feasible robot action, the expected seconds to the next success: the one-step backup
    of ``result``'s values through ``model``'s replies (:func:`expand`)."""
    out: dict[int, float] = {}
    for a, replies in expand(world, state, model):
        values = (p * (tau + result.value_at(world, nxt, relabel)) for nxt, p, tau in replies or ())
        out[a] = 0.0 if replies is None else sum(values)
    return out
