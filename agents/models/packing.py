"""States packed into one int64 each, and the canonical relabelling on arrays.

A robot-turn or mid-cycle state (and, for partners who see it, the robot's action of the
cycle) is a tuple of small integers; packed as mixed-radix digits (the compiled partners'
layout, ``agents/compiled.py``) a batch of them is one int64 array, deduplicated and
looked up with the helpers of :mod:`hg_marl.agents.models.keyed`.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from typing import TypeVar

import numpy as np

from hg_marl.agents.planner.space import Relabel
from hg_marl.core import Agent, State, World
from hg_marl.envs.batched import BatchState

KEY_LIMIT = 2**62


class StatePacker:
    """Mixed-radix packing of (where..., robot_at, offer_by + 1, offer_obj + 1, seen + 1)."""

    def __init__(self, world: World) -> None:
        t = world.table
        self.n_objects = n = t.n_objects
        self.radix = np.array(
            [t.n_places] * n + [t.n_locations, 3, n + 1, world.n_actions(Agent.ROBOT) + 1], dtype=np.int64
        )
        total = 1
        for r in self.radix.tolist():
            total *= int(r)
        if total >= KEY_LIMIT:
            raise ValueError(
                f"scenario: {world.scenario.name!r} has too many states to pack into 64-bit keys "
                f"({n} objects, {t.n_places} places); use a smaller scenario"
            )
        self.weights = np.concatenate([[1], np.cumprod(self.radix[:-1])]).astype(np.int64)
        self._weights = [int(w) for w in self.weights]
        self._radix = [int(r) for r in self.radix]
        relabel = Relabel(world)
        self.classes = [np.array(c, dtype=np.int64) for c in relabel.classes]

    def pack(self, b: BatchState, seen: np.ndarray | None = None) -> np.ndarray:
        """(N,) int64 keys; ``seen`` None packs -1 (a robot-turn state)."""
        w, n = self.weights, self.n_objects
        key = b.where @ w[:n]
        key += b.robot_at * w[n] + (b.offer_by + 1) * w[n + 1] + (b.offer_obj + 1) * w[n + 2]
        return key if seen is None else self.seen(key, seen)

    def seen(self, keys: np.ndarray, seen: np.ndarray) -> np.ndarray:
        """``keys`` (packed with no action seen) with the robot action ``seen`` added (-1: none)."""
        out: np.ndarray = keys + (seen + 1) * self.weights[self.n_objects + 3]
        return out

    def unpack(self, keys: np.ndarray) -> tuple[BatchState, np.ndarray]:
        """The batch and the robot action seen (-1: none) that :meth:`pack` made ``keys`` from."""
        digits, rest = [], keys
        for radix in self._radix:  # the lowest digit first: one division per digit
            rest, digit = np.divmod(rest, radix)
            digits.append(digit)
        n = self.n_objects
        at, by, obj, seen = digits[n:]
        return BatchState(np.stack(digits[:n], axis=1), at, by - 1, obj - 1), seen - 1

    def canonical(self, b: BatchState) -> np.ndarray:
        """Relabel ``b`` in place into :meth:`Relabel.canonical`'s state (each class sorted by place).

        Returns ``orig`` (N, objects): per row, the object of the original state that each
        object of the canonical one stands for (:meth:`Relabel.canonical`'s second value).
        """
        offer = b.offer_obj.copy()
        every = np.broadcast_to(np.arange(self.n_objects, dtype=np.int64), b.where.shape).copy()
        for cols in self.classes:
            block = b.where[:, cols]
            perm = np.argsort(block, axis=1, kind="stable")  # slot j holds the object cols[perm[:, j]]
            b.where[:, cols] = np.take_along_axis(block, perm, axis=1)
            orig = cols[perm]
            every[:, cols] = orig
            hit = orig == offer[:, None]
            inside = hit.any(axis=1)
            b.offer_obj[inside] = cols[hit[inside].argmax(axis=1)]
        return every

    def pack_one(self, state: State) -> int:
        """The key of one robot-turn state (as :meth:`pack` with no action seen)."""
        digits = (*state.where, state.robot_at, state.offer_by + 1, state.offer_obj + 1)
        w = self._weights
        return sum(d * w[i] for i, d in enumerate(digits))


V = TypeVar("V")


class PackedMap(Mapping[State, V]):
    """A read-only mapping from states to values, held as sorted packed keys and an array.

    A model of a million states keeps its policy and values in two arrays instead of a
    million-entry dict of tuples; a look-up packs the state and bisects.
    """

    def __init__(self, packer: StatePacker, keys: np.ndarray, values: np.ndarray) -> None:
        order = np.argsort(keys, kind="stable")
        self.packer = packer
        self._keys = keys[order]
        self._data = values[order]

    def __getitem__(self, state: State) -> V:
        if not isinstance(state, State) or len(state.where) != self.packer.n_objects:
            raise KeyError(state)
        key = self.packer.pack_one(state)
        i = int(np.searchsorted(self._keys, key))
        if i >= len(self._keys) or int(self._keys[i]) != key:
            raise KeyError(state)
        return self._data[i].item()

    def __iter__(self) -> Iterator[State]:
        b, _ = self.packer.unpack(self._keys)
        return (b.state(i) for i in range(len(b)))

    def __len__(self) -> int:
        return len(self._keys)
