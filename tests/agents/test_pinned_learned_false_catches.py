"""Two planted bugs in the learned human that only a test failing in every scratch copy had
"caught" (it runs a benchmark script the copies did not hold), pinned here.

Expected values worked by hand from ``LearnedHuman``'s documented rules: a ``table``
policy's unseen observation falls back to ``wait`` (the seat's last action), and a
``linear_softmax`` policy plays ``p(a) ∝ exp((W facts + b)_a / temperature)``.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from hg_marl.agents.humans.learned import LearnedHuman, save_learned_policy
from hg_marl.core import Agent, World


def test_a_table_policys_unseen_observation_waits(tmp_path: Path) -> None:
    world = World("paper2015")
    n_a, n_f = world.n_actions(Agent.HUMAN), world.n_facts
    seen = np.zeros(n_f, dtype=np.int8)
    path = save_learned_policy(tmp_path / "table", world, table={seen.tobytes(): 0})
    human = LearnedHuman(path)
    unseen = np.ones(n_f, dtype=np.int8)
    mask = np.ones(n_a, dtype=bool)
    expected = np.zeros(n_a)
    expected[n_a - 1] = 1.0  # wait is the seat's last action
    np.testing.assert_array_equal(human.probabilities(unseen, mask), expected)
    expected_seen = np.zeros(n_a)
    expected_seen[0] = 1.0
    np.testing.assert_array_equal(human.probabilities(seen, mask), expected_seen)


def test_a_linear_softmax_policy_divides_its_biases_by_the_temperature(tmp_path: Path) -> None:
    """Weights 0, biases 2 for action 0 and 0 elsewhere, temperature 2, two actions feasible:
    p(0) = e^(2/2) / (e^(2/2) + e^0) = e / (e + 1), about 0.731 (not e^2 / (e^2 + 1))."""
    world = World("paper2015")
    n_a, n_f = world.n_actions(Agent.HUMAN), world.n_facts
    bias = np.zeros(n_a)
    bias[0] = 2.0
    path = save_learned_policy(tmp_path / "linear", world, weights=np.zeros((n_a, n_f)), bias=bias, temperature=2.0)
    mask = np.zeros(n_a, dtype=bool)
    mask[[0, n_a - 1]] = True
    p = LearnedHuman(path).probabilities(np.ones(n_f), mask)
    assert math.isclose(p[0], math.e / (math.e + 1.0), rel_tol=1e-12)
    assert math.isclose(p[n_a - 1], 1.0 / (math.e + 1.0), rel_tol=1e-12)
    assert math.isclose(p.sum(), 1.0)
