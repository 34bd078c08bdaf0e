"""PettingZoo's api tests with their random actions drawn from seeded spaces.

``api_test`` and ``parallel_api_test`` pick each action with ``action_space(agent).sample``,
which draws from the space's own generator, seeded from the operating system unless the
space is seeded. Whether an episode ends within the test's cycles then changed from one
run to the next, and so did what a test run caught (a planted bug in the flat wrapper's
end of episode was caught by one run and missed by the next). Seeded spaces make each
test one fixed trajectory, as the project asks of every random choice.
"""

from __future__ import annotations

from typing import TypeVar

from pettingzoo.test.seed_test import seed_action_spaces, seed_observation_spaces

E = TypeVar("E")


def seeded(env: E, seed: int = 0) -> E:
    """``env`` reset with ``seed`` and its agents' spaces seeded (PettingZoo's own helpers), for an api test."""
    env.reset(seed=seed)  # type: ignore[attr-defined]
    seed_action_spaces(env)
    seed_observation_spaces(env)
    return env
