"""Round 53's missed planted bugs, pinned (see mutation/README.md, "Fresh planted bugs")."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.model_format import load_model_file, resolve_header, save_model_file, world_fields
from hg_marl.agents.models.budget import Budget, OverBudget
from hg_marl.agents.vector_envs import robot_vector_env
from hg_marl.core import Agent, Durations, World
from hg_marl.envs.batched import BatchState

SCENARIO = "paper2015"
WORLD = World(SCENARIO)


def test_a_count_of_exactly_the_states_budget_is_enumerated_and_one_more_is_refused() -> None:
    # agents/models/budget.py's refuse_count: "Refuse before a phase that would enumerate
    # ``count`` items, more than the states budget". A budget of 10 states allows a phase of
    # 10 layouts (10 is not more than 10) and refuses 11, naming the budget, the count and
    # the phase with "0 of 11 layouts" as its progress (nothing enumerated yet).
    budget = Budget(states=10, memory=None, subject="the oracle")
    budget.refuse_count("layouts", 10, "layouts")
    budget.refuse_count("layouts", 0, "layouts")
    with pytest.raises(OverBudget) as refused:
        budget.refuse_count("layouts", 11, "layouts")
    assert str(refused.value) == (
        "the oracle is over its budget of max_states=10 (11 layouts to enumerate) in phase 'layouts' "
        "(0 of 11 layouts); raise --max-states or raise the budget or use a smaller scenario"
    )
    # without a states budget nothing is refused, however many
    Budget(states=None, memory=None).refuse_count("layouts", 10**12, "layouts")


def _saved_model(folder: Path) -> Path:
    """A linear softmax robot of paper2015 saved as ``folder/policy.json`` + ``policy.npz``."""
    n_a, n_f = WORLD.n_actions(Agent.ROBOT), WORLD.n_facts
    header = {**world_fields(WORLD, Agent.ROBOT), "kind": "linear_softmax", "observation": "facts"}
    arrays = {"W": np.zeros((n_a, n_f)), "b": np.arange(n_a, dtype=float)}
    return save_model_file(folder / "policy.json", header, arrays)


def test_a_model_given_by_its_weights_file_resolves_to_its_header(tmp_path: Path) -> None:
    # agents/model_format.py's resolve_header: "The header of a model given as its ``.json``,
    # its ``.npz``, its stem, or its folder". All four names of one saved model resolve to
    # the same header (policy.json, the name written by save_model_file), and loading it by
    # its .npz gives the header and the weights that were saved.
    header = _saved_model(tmp_path)
    assert header == tmp_path / "policy.json"
    for given in (tmp_path / "policy.json", tmp_path / "policy.npz", tmp_path / "policy", tmp_path):
        assert resolve_header(given) == header, given
    mf = load_model_file(tmp_path / "policy.npz", seat="robot")
    assert mf.path == header
    assert mf.header["kind"] == "linear_softmax"
    np.testing.assert_array_equal(mf.arrays["b"], np.arange(WORLD.n_actions(Agent.ROBOT), dtype=float))


class _WaitingHuman:
    """An array partner that waits at every table (the human's ``wait``, found by its name)."""

    name = "waiting"

    def __init__(self, world: World) -> None:
        self.wait = world.action_names[Agent.HUMAN].index("wait")

    def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        return np.full(len(batch), self.wait, dtype=np.int64)


def test_the_robot_seat_plays_the_durations_it_is_given() -> None:
    # agents/vector_envs.py's robot_vector_env takes ``durations`` (hg_marl.core.Durations:
    # "How long each action type takes"). With wait lasting 2.5 s, not the default 1 s, a
    # cycle where both agents wait lasts max(2.5, 2.5) = 2.5 simulated seconds (a cycle lasts
    # as long as the longer of its two actions), so after three such cycles every table's
    # clock reads 7.5 (with the default durations: 3.0).
    durations = Durations(wait=2.5)
    env = robot_vector_env(num_envs=3, scenario=SCENARIO, durations=durations, partner=_WaitingHuman(WORLD))
    assert env.world.durations == durations
    _, info = env.reset(seed=0)
    np.testing.assert_array_equal(info["clock"], [0.0, 0.0, 0.0])
    wait = WORLD.action_names[Agent.ROBOT].index("wait")
    for _ in range(3):
        _, _, terminated, truncated, info = env.step(np.full(3, wait))
        assert not terminated.any() and not truncated.any()
    np.testing.assert_allclose(info["clock"], [7.5, 7.5, 7.5])
