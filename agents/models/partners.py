"""Stationary partners whose answers are computed on arrays, a batch of states at a time.

The model builder's cost, once the robot's side is on arrays, is the partner's answers:
one Python call per distinct mid-cycle state. For the partners whose rule is a few table
look-ups per action, :func:`batch_answers` returns the same distributions for a whole
batch with numpy; the builder's :class:`~hg_marl.agents.models.AnswerTable` uses it and
falls back to the live human for every other partner. Each function below restates its
human's rule (``agents/humans/random_human.py``, ``agents/humans/preference.py``) in the
same floating-point order, and a test compares them with the live humans state by state.

- ``random`` (``feasible_only``): uniform over the human's mask.
- ``preference`` with ``temperature=0``: each feasible action's score, the best one above 0
  in index order with the same tie rule (``_TIE``), the offer taken with ``accept``, mixed
  with ``wait`` by ``p_idle``. A softmax (``temperature > 0``) stays live.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Protocol

import numpy as np

from hg_marl.agents.models.keyed import nonzero_2d
from hg_marl.core import Agent, Kind, World
from hg_marl.envs.batched import BatchedRules, BatchState


class Shared(Protocol):
    """What the partners asked about one batch of states share (:class:`~hg_marl.agents.models.answers.KeyBatch`)."""

    @property
    def mask(self) -> np.ndarray:
        """The human's masks of the batch (:meth:`BatchedRules.masks`)."""
        ...

    def derived(self, name: str, make: Callable[[], Any]) -> Any:
        """``make()``, computed once per batch for every partner that asks for ``name``."""
        ...


class Answers(Protocol):
    """A batch of mid-cycle states -> (entries per state, actions, probabilities), entries in index order.

    ``shared``: what the batch's partners share where the caller has it (a joint model
    asks twenty partners the same states): the human's masks and what every partner of
    a kind derives from the states alone, computed once.
    """

    def __call__(self, b: BatchState, shared: Shared | None = None, /) -> tuple[np.ndarray, np.ndarray, np.ndarray]: ...


_TIE = 1e-9  # agents/humans/preference.py's tie rule


class Alone:
    """The :class:`Shared` of a batch asked of one partner: everything computed when read."""

    def __init__(self, rules: BatchedRules, b: BatchState) -> None:
        self.rules, self.b = rules, b

    @property
    def mask(self) -> np.ndarray:
        return self.rules.masks(self.b, Agent.HUMAN)

    def derived(self, name: str, make: Callable[[], Any]) -> Any:
        return make()


def feasible_rows(mask: np.ndarray) -> list[np.ndarray]:
    """Per action, the rows of ``mask`` (states x actions) where it is feasible, in row order.

    Why: a preference human's choice scans the actions that may win, each over the states
    where it is feasible (a few per state): shared by every partner of a batch, this is one
    pass over the masks instead of a dense score per partner.
    """
    by_action = np.ascontiguousarray(mask.T)
    return [np.flatnonzero(column) for column in by_action]


def batch_answers(world: World, human: Any) -> Answers | None:
    """An array version of ``human``'s distribution, or None when it has none (answered live)."""
    from hg_marl.agents.humans.preference import PreferenceHuman
    from hg_marl.agents.humans.random_human import RandomHuman

    if type(human) is RandomHuman and human.feasible_only:
        return _uniform(BatchedRules(world))
    if type(human) is PreferenceHuman and human.temperature == 0.0:
        return _preference(world, human)
    return None


def _uniform(rules: BatchedRules) -> Answers:
    def answers(b: BatchState, shared: Shared | None = None, /) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        mask = (shared or Alone(rules, b)).mask
        sizes = mask.sum(axis=1)
        rows, actions = nonzero_2d(mask)
        return sizes, actions, 1.0 / sizes[rows]

    return answers


def _preference(world: World, h: Any) -> Answers:
    rules = BatchedRules(world)
    t = world.table
    sc = world.scenario
    specs = t.specs[Agent.HUMAN]
    n_actions = len(specs)
    wait = rules.wait[Agent.HUMAN]
    robot_reaches = np.zeros(t.n_places, dtype=bool)
    robot_reaches[: t.n_spots] = [bool(s.reach.robot_from) for s in sc.spots]
    colour_match = [bool(h.colour) and c == h.colour for c in sc.object_colours]
    held = np.full(n_actions, -np.inf)  # the score of an action on the held object
    for i, (kind, _, target, duration) in enumerate(specs):
        if kind in (Kind.THROW, Kind.GIVE, Kind.PLACE):
            held[i] = h._held_score(kind, target, duration, tuple(robot_reaches[: t.n_spots].tolist()))
    first = rules.first[Agent.HUMAN]
    pick, throw, give, take = (first[k] for k in (Kind.PICK, Kind.THROW, Kind.GIVE, Kind.TAKE))
    place = first[Kind.PLACE]
    m, n = t.n_spots, t.n_objects
    hand = t.hand[Agent.HUMAN]
    spot_human = np.array(t.spot_human, dtype=bool)
    throw_to = rules.throw_to[Agent.HUMAN]
    pick_cost = [h.haste * specs[pick + o].duration for o in range(n)]
    bonus_colour = [h.colour_bonus if colour_match[o] else 0.0 for o in range(n)]

    human_spots = np.flatnonzero(spot_human[:m])
    # per object, the score of placing it on each spot the human can place on (-inf: never better)
    place_score = np.array([held[place + o * m + human_spots] for o in range(n)]).reshape(n, len(human_spots))

    def targets(b: BatchState) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """What a pick of each object may be followed by, from the states alone (the same for every
        preference human): (throw ok, give ok, place ok per spot, on the robot's side, offered)."""
        size = len(b)
        occupied = np.zeros((size, t.n_places), dtype=bool)
        occupied[np.arange(size)[:, None], b.where] = True
        side = robot_reaches[b.where]  # (size, objects): the object lies on the robot's side
        throw_ok = throw_to[b.robot_at] >= 0  # (size, objects)
        give_ok = rules.give_ok[b.robot_at]
        spots = human_spots[:, None]
        place_ok = (
            ~occupied.T[human_spots][None, :, :]
            & (b.where.T[:, None, :] != spots[None])
            & (robot_reaches[spots][None] != side.T[:, None, :])
        )  # (objects, spots, size): one object's spots are contiguous rows
        offered = (b.offer_by == Agent.ROBOT) & ~(b.where == hand).any(axis=1)
        return throw_ok, give_ok, place_ok, side, offered

    bar = _TIE + _TIE  # the first best score plus the tie: an action scoring no more never wins
    picks = set(range(pick, pick + n))
    contenders = [a for a in range(n_actions) if a in picks or (a != wait and held[a] > bar)]
    """The actions that may beat ``wait``, in index order (the others score -inf, 0 or too little)."""

    def pick_scores(o: int, rows: np.ndarray, targets: tuple[np.ndarray, ...]) -> np.ndarray:
        """The score of picking object ``o`` at ``rows`` (where it is feasible): its best target once held."""
        throw_ok, give_ok, place_ok, side_of, _ = targets
        best = np.full(len(rows), -np.inf)
        best = np.where(throw_ok[rows, o], np.maximum(best, held[throw + o]), best)
        best = np.where(give_ok[rows], np.maximum(best, held[give + o]), best)
        for j in np.flatnonzero(place_score[o] > -np.inf).tolist():  # other spots: never better
            best = np.where(place_ok[o, j, rows], np.maximum(best, place_score[o, j]), best)
        bonus = np.where(side_of[rows, o], h.robot_side, 0.0) + bonus_colour[o]
        value = (best + bonus) - pick_cost[o]
        return np.where(np.isfinite(best), value, -np.inf)

    def answers(b: BatchState, shared: Shared | None = None, /) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        size = len(b)
        shared = shared or Alone(rules, b)
        feasible = shared.derived("feasible rows", lambda: feasible_rows(shared.mask))
        found = shared.derived("preference targets", lambda: targets(b))
        choice = np.full(size, wait, dtype=np.int64)
        top = np.full(size, _TIE)
        for a in contenders:  # the live rule's scan in index order, over the rows where ``a`` is feasible
            rows = feasible[a]
            if not len(rows):
                continue
            value = pick_scores(a - pick, rows, found) if a in picks else held[a]
            better = value > top[rows] + _TIE
            won = rows[better]
            choice[won] = a
            top[won] = value[better] if a in picks else value
        offered_any = found[4]
        offered = offered_any & (h.accept > 0.0)
        # up to three entries per state: the offer's take, the choice, the idle wait
        act = np.stack([np.where(offered, take + b.offer_obj, -1), choice, np.full(size, wait)], axis=1)
        prob = np.stack([np.full(size, h.accept), np.where(offered, (1.0 - h.accept) * 1.0, 1.0), np.zeros(size)], 1)
        if h.p_idle > 0.0:
            prob[:, :2] = (1.0 - h.p_idle) * prob[:, :2]
            merged = choice == wait
            prob[:, 2] = np.where(merged, h.p_idle + prob[:, 1], h.p_idle)
            prob[merged, 1] = 0.0
        else:
            act[:, 2] = -1
        keep = (act >= 0) & (prob > 0.0)
        order = np.argsort(np.where(keep, act, n_actions + 1), axis=1, kind="stable")
        act, prob, keep = (np.take_along_axis(x, order, axis=1) for x in (act, prob, keep))
        return keep.sum(axis=1), act[keep], prob[keep]

    return answers
