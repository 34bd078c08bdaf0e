"""Round 59's missed planted bugs, pinned (see mutation/README.md, "Fresh planted bugs")."""

from __future__ import annotations

import numpy as np

import hg_marl
from hg_marl.agents.adapters import scripted_v0
from hg_marl.core import Agent, World
from hg_marl.policy import Turn

# --- agents/adapters.py ---


class _Counting:
    """An actor whose k-th decision (k = 0, 1, ...) is action k, whatever the state."""

    def __init__(self) -> None:
        self.calls = 0

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.calls = 0

    def act(self, turn: Turn) -> int:
        self.calls += 1
        return self.calls - 1


def test_a_scripted_seat_decides_anew_on_each_of_its_turns_and_once_per_turn() -> None:
    # adapters.py's spec sheet: "one actor.act per turn, on the state when the seat is
    # observed", and the scripted seat's mask is one-hot on the actor's chosen action. With
    # an actor whose k-th decision is action k, the human seat's masks over its first five
    # turns are therefore one-hot on 0, 1, 2, 3, 4 (worked from the rule, not the code),
    # and observing a seat twice in one turn asks the actor once.
    human = _Counting()
    env = scripted_v0(hg_marl.env(), human=human)
    env.reset(seed=0)
    shown: list[int] = []
    while len(shown) < 5:
        agent = env.agent_selection
        assert not (env.terminations[agent] or env.truncations[agent])
        mask = np.asarray(env.observe(agent)["action_mask"])
        if agent == "human":
            again = np.asarray(env.observe(agent)["action_mask"])
            assert np.array_equal(mask, again)
            assert mask.sum() == 1
            shown.append(int(mask.argmax()))
        env.step(int(mask.argmax()))
    assert shown == [0, 1, 2, 3, 4]
    assert human.calls == 5
