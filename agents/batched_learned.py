"""An SB3 ``learned`` human as the batched env's partner: one forward pass per env step.

A Stable-Baselines3 policy has no exact action distribution here (``LearnedHuman``
acts greedily through ``predict``), so it cannot be compiled into a table
(``agents/compiled.py``). It is a function of its observation, though, and the policy
network takes a batch as readily as one row: :class:`BatchedLearned` builds the human
seat's observation of every table at once (``BatchedRules.facts`` and
``BatchedRules.masks`` of the mid-cycle states, the same arrays ``World.facts`` /
``World.mask`` give the live human through its turn) and calls the model's ``predict``
once with them, with the mask as ``action_masks`` for a maskable model. The input is
built by ``LearnedHuman.sb3_inputs``, the function the live human uses, so a table's
answer is the live human's. As for the live human, a greedy action the mask forbids (a
model that is not given the mask) is returned as it is, and the rules fail it.

The answer depends on the observation only: no generator is drawn, no state is kept
per table, so there is nothing to reset and ``seen`` (the robot's action) is unused.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hg_marl.agents.humans.learned import LearnedHuman
from hg_marl.core import Agent, World
from hg_marl.core.errors import HumanError
from hg_marl.envs.batched import BatchedRules, BatchState


def is_sb3_learned(human: Any) -> bool:
    """Whether ``human`` (an instance) is a ``learned`` human of kind ``sb3``."""
    return isinstance(human, LearnedHuman) and human.kind == "sb3"


class BatchedLearned:
    """An SB3 learned human answering every table with one ``predict`` call (``ArrayPartner``).

    Args:
        world: the batched env's world (the policy's file is checked against it and the human seat).
        human: a ``LearnedHuman`` of kind ``sb3``.
        name: the partner's name (default: the human's).
    """

    fallbacks = 0
    """Tables answered by anything but the policy (never: every state has an observation)."""

    def __init__(self, world: World, human: LearnedHuman, name: str | None = None) -> None:
        if not is_sb3_learned(human):
            raise HumanError(f"human: {getattr(human, 'name', human)!r} is not a learned SB3 policy")
        human.reset(world, Agent.HUMAN, np.random.default_rng(0))  # checks world and seat; draws nothing
        self.world, self.human = world, human
        self.rules = BatchedRules(world)
        self.name = name or str(human.name)

    def observations(self, batch: BatchState) -> tuple[np.ndarray, np.ndarray]:
        """(N, F) int8 facts and (N, A) int8 human masks of the batch: what each table's live human observes."""
        return self.rules.facts(batch), self.rules.masks(batch, Agent.HUMAN).astype(np.int8)

    def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """The policy's greedy action per table, from one forward pass over the batch."""
        if len(batch) == 0:
            return np.zeros(0, dtype=np.int64)
        obs, kwargs = self.human.sb3_inputs(*self.observations(batch))
        actions, _ = self.human.model.predict(obs, **kwargs)
        return np.asarray(actions, dtype=np.int64).reshape(len(batch))
