"""The values round 67's missed planted bugs changed (``mutation/planted.py``, FRESH67), pinned.

Each expected value is stated from the module's documented behaviour, not read off the code.
"""

from __future__ import annotations

import numpy as np

from hg_marl.agents.views import RobotView


def test_the_flat_observation_is_the_facts_then_the_action_mask() -> None:
    # The views' docstring: '"flat": Box(0, 1, (F + A,), int8), facts then the action mask'. The
    # reference is built beside the view: the "facts" view's observation (the same seed deals the
    # same table and seeds the same partner) followed by the view's own action_masks(), checked
    # at the reset and after each of a few steps (the mask changes as objects move).
    flat = RobotView(human="random", observation="flat", max_cycles=20)
    facts = RobotView(human="random", observation="facts", max_cycles=20)
    obs_flat, _ = flat.reset(seed=5)
    obs_facts, _ = facts.reset(seed=5)
    n_facts = len(obs_facts)
    for _ in range(6):
        mask = flat.action_masks().astype(np.int8)
        assert mask.sum() < len(mask)  # some action is ruled out: the two halves differ in kind
        np.testing.assert_array_equal(obs_flat, np.concatenate([obs_facts, mask]))
        np.testing.assert_array_equal(obs_flat[:n_facts], obs_facts)
        np.testing.assert_array_equal(obs_flat[n_facts:], mask)
        action = int(np.flatnonzero(mask)[0])
        obs_flat, *_ = flat.step(action)
        obs_facts, *_ = facts.step(action)
