"""Values that round 251's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

import hg_marl
from hg_marl.agents.humans import make_human
from hg_marl.agents.models.budget import OverBudget
from hg_marl.core.errors import ConfigError
from hg_marl.policy import Turn
from hg_marl.training.baselines.recipes import check_recipe
from hg_marl.training.runner import RunConfig, run
from tests.training.test_runner import _PlainRobot


def test_a_pickled_refusal_keeps_which_budget_stopped_it() -> None:
    # A forked worker's refusal reaches the parent pickled: the parent reads ``resource`` to word
    # a refusal its own way, so the copy must say "memory" (and the same one line) as the original.
    refusal = OverBudget("the oracle is over its budget of 4 GB of memory", "memory")
    copy = pickle.loads(pickle.dumps(refusal))
    assert isinstance(copy, OverBudget)
    assert copy.resource == "memory"
    assert str(copy) == "the oracle is over its budget of 4 GB of memory"


def test_an_unknown_recipe_is_refused_naming_every_recipe() -> None:
    # The six recipes of the module docstring, in their order, "members" (the plain pool) first.
    with pytest.raises(ConfigError) as caught:
        check_recipe("nope")
    assert str(caught.value) == "--recipe: expected one of members, fcp, fcp_init, hsp, e3t, coverage, got 'nope'"


class _FirstStateRobot(_PlainRobot):
    """The plain waiting robot, keeping the state of its first turn."""

    first: object = None

    def act(self, turn: Turn) -> int:
        if self.first is None:
            self.first = turn.state
        return super().act(turn)


def test_a_run_starts_from_the_table_its_seed_sequence_draws() -> None:
    # The runner's protocol (its module docstring): SeedSequence(seed) is split in three, the
    # first child seeds the environment; the environment, reset alone with the first word that
    # child generates, draws the table the run's first robot turn sees (a reference built from
    # the environment, not the runner). Seeds 0-4: a table drawn from another word differs on
    # at least one of them, so the comparison is over all five.
    for seed in range(5):
        robot = _FirstStateRobot()
        run(robot, make_human("cooperative"), RunConfig(duration=5.0, seed=seed, max_decisions=1))
        env = hg_marl.env(scenario="paper2015", continuing=True, max_cycles=None, time_budget=5.0)
        child = np.random.SeedSequence(seed).spawn(3)[0]
        env.reset(seed=int(child.generate_state(1)[0]))
        assert robot.first == env.unwrapped.world_state, seed
