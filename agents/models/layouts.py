"""The tables a scenario's re-draw can produce, with their exact probabilities.

:func:`layout_distribution` enumerates every deal (``World.initial_state``'s draw);
:func:`canonical_layouts` the same up to interchangeable objects, without enumerating
every deal. Both check a :class:`~hg_marl.agents.models.budget.Budget` every
:data:`CHECK_EVERY` deals when given one (phase ``"layouts"``), so a scenario with
millions of layouts is refused at its budget during the enumeration, not after it.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator

from hg_marl.agents.models.budget import Budget
from hg_marl.core import State, World
from hg_marl.core.scenario import layout_count

CHECK_EVERY = 1024
"""Deals enumerated between two budget checks (each costs microseconds)."""


def layout_distribution(world: World, budget: Budget | None = None) -> list[tuple[State, float]]:
    """Every table ``World.initial_state`` can draw, with its exact probability.

    ``initial_state`` shuffles the objects, deals them to the layout groups in order, and
    each group draws an ordered sample of distinct spots; so each group receives a
    uniformly random subset of the remaining objects, mapped injectively and uniformly
    onto its spots, and the robot starts at a uniform ``robot_start`` location.
    """
    sc = world.scenario
    out: dict[State, float] = {}

    def deal(k: int, left: tuple[int, ...], where: dict[int, int], p: float) -> Iterator[tuple[dict[int, int], float]]:
        if k == len(sc.layout):
            yield where, p
            return
        group = sc.layout[k]
        subsets = list(itertools.combinations(left, group.count))
        spots = list(itertools.permutations(group.spots, group.count))
        q = p / (len(subsets) * len(spots))
        for subset in subsets:
            rest = tuple(o for o in left if o not in subset)
            for chosen in spots:
                yield from deal(k + 1, rest, {**where, **dict(zip(subset, chosen, strict=True))}, q)

    total = layout_count(sc)
    for i, (where, p) in enumerate(deal(0, tuple(range(world.n_objects)), {}, 1.0)):
        if budget is not None and i % CHECK_EVERY == 0:
            budget.check("layouts", i * len(sc.robot_start), total, "layouts", memory=i % (16 * CHECK_EVERY) == 0)
        for start in sc.robot_start:
            state = State(tuple(where[o] for o in range(world.n_objects)), start)
            out[state] = out.get(state, 0.0) + p / len(sc.robot_start)
    return sorted(out.items())


def canonical_layouts(world: World, budget: Budget | None = None) -> list[tuple[State, float]]:
    """:func:`layout_distribution` up to interchangeable objects, without enumerating every deal.

    Each state is :meth:`Relabel.canonical` of the tables it stands for, with their total
    probability. Per layout group: the class make-up of the dealt subset is
    multivariate-hypergeometric, and given it every assignment of the classes to disjoint
    spot sets is equally likely (``prod n_c! (m - c)! / m!`` each, ``m`` spots, ``c``
    objects). On ``generated:objects=8,bins=2`` that is 3,150 states instead of 1.8M deals.
    """
    sc = world.scenario
    members: dict[tuple[int, ...], list[int]] = {}
    for o, bins in enumerate(world.bins_of):
        members.setdefault(bins, []).append(o)
    classes = list(members.values())
    out: dict[State, float] = {}

    def assignments(spots: tuple[int, ...], sizes: tuple[int, ...]) -> Iterator[tuple[tuple[int, ...], ...]]:
        if not sizes:
            yield ()
            return
        for chosen in itertools.combinations(spots, sizes[0]):
            rest = tuple(x for x in spots if x not in chosen)
            for tail in assignments(rest, sizes[1:]):
                yield (chosen, *tail)

    def compositions(c: int, left: tuple[int, ...]) -> Iterator[tuple[int, ...]]:
        if not left:
            if c == 0:
                yield ()
            return
        for n in range(min(c, left[0]) + 1):
            for tail in compositions(c - n, left[1:]):
                yield (n, *tail)

    def deal(
        k: int, left: tuple[int, ...], places: tuple[tuple[int, ...], ...], p: float
    ) -> Iterator[tuple[tuple[tuple[int, ...], ...], float]]:
        if k == len(sc.layout):
            yield places, p
            return
        group = sc.layout[k]
        c, m = group.count, len(group.spots)
        for comp in compositions(c, left):
            q = math.prod(math.comb(n_left, n) for n_left, n in zip(left, comp, strict=True)) / math.comb(sum(left), c)
            q *= math.prod(math.factorial(n) for n in comp) * math.factorial(m - c) / math.factorial(m)
            rest = tuple(n_left - n for n_left, n in zip(left, comp, strict=True))
            for assign in assignments(group.spots, comp):
                yield from deal(k + 1, rest, tuple(a + b for a, b in zip(places, assign, strict=True)), p * q)

    total = canonical_layout_count(world)
    for i, (places, p) in enumerate(deal(0, tuple(len(m) for m in classes), tuple(() for _ in classes), 1.0)):
        if budget is not None and i % CHECK_EVERY == 0:
            budget.check("layouts", i * len(sc.robot_start), total, "layouts", memory=i % (16 * CHECK_EVERY) == 0)
        where = [0] * world.n_objects
        for objs, spots in zip(classes, places, strict=True):
            for o, spot in zip(objs, sorted(spots), strict=True):
                where[o] = spot
        for start in sc.robot_start:
            state = State(tuple(where), start)
            out[state] = out.get(state, 0.0) + p / len(sc.robot_start)
    return sorted(out.items())


def canonical_layout_count(world: World) -> int:
    """How many (class make-up, spot assignment) deals :func:`canonical_layouts` enumerates, times starts.

    Computed without allocating, so a caller can refuse before enumerating.
    """
    sizes: dict[tuple[int, ...], int] = {}
    for bins in world.bins_of:
        sizes[bins] = sizes.get(bins, 0) + 1
    sc = world.scenario

    def count(k: int, left: tuple[int, ...]) -> int:
        if k == len(sc.layout):
            return 1
        group = sc.layout[k]
        c, m = group.count, len(group.spots)
        total = 0

        def comps(i: int, c_left: int, comp: tuple[int, ...]) -> None:
            nonlocal total
            if i == len(left):
                if c_left == 0:
                    ways = math.perm(m, c) // math.prod(math.factorial(n) for n in comp)
                    total += ways * count(k + 1, tuple(a - b for a, b in zip(left, comp, strict=True)))
                return
            for n in range(min(c_left, left[i]) + 1):
                comps(i + 1, c_left - n, (*comp, n))

        comps(0, c, ())
        return total

    return len(sc.robot_start) * count(0, tuple(sizes.values()))
