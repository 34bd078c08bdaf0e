"""The batched SB3 learned partner's checks, name and edge cases, pinned for the mutation gate.

Expected values from the module's documented rules: only a ``learned`` human of kind
``sb3`` is a batched learned partner (a numpy ``learned`` policy or a scripted human is
not, and is refused with a ``HumanError``); the partner is named after the human unless
given a name; it never falls back; an empty batch is answered by no action at all (an
empty int64 array) without calling the policy; its observations are the int8 facts and
human masks that ``World.facts`` / ``World.mask`` give the live human.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.batched_learned import BatchedLearned, is_sb3_learned
from hg_marl.agents.humans.learned import LearnedHuman, save_learned_policy, save_sb3_policy
from hg_marl.agents.humans.registry import make_human
from hg_marl.agents.views import HumanView
from hg_marl.core import Agent, World
from hg_marl.core.errors import HumanError
from hg_marl.envs.batched import BatchedRules

pytest.importorskip("stable_baselines3")
torch = pytest.importorskip("torch")

SCENARIO = "paper2015"


@pytest.fixture(scope="module")
def sb3_folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """An untrained PPO on the human seat's facts (its answers do not matter here)."""
    from stable_baselines3 import PPO

    torch.set_num_threads(1)
    model = PPO("MlpPolicy", HumanView(SCENARIO, robot="random"), n_steps=16, batch_size=16, seed=0, device="cpu")
    return save_sb3_policy(tmp_path_factory.mktemp("sb3") / "policy", model, SCENARIO)


def test_only_an_sb3_learned_human_is_a_batched_learned_partner(sb3_folder: Path, tmp_path: Path) -> None:
    world = World(SCENARIO)
    numpy_folder = save_learned_policy(
        tmp_path / "np", world, weights=np.zeros((world.n_actions(Agent.HUMAN), world.n_facts))
    )
    assert is_sb3_learned(LearnedHuman(sb3_folder))
    assert not is_sb3_learned(LearnedHuman(numpy_folder))
    table_folder = save_learned_policy(tmp_path / "table", world, table={})
    assert not is_sb3_learned(LearnedHuman(table_folder))  # "table" sorts after "sb3": a kind test, not an order
    assert not is_sb3_learned(make_human("lazy"))
    with pytest.raises(HumanError, match=r"^human: 'learned' is not a learned SB3 policy$"):
        BatchedLearned(world, LearnedHuman(numpy_folder))
    with pytest.raises(HumanError, match=r"^human: 'lazy' is not a learned SB3 policy$"):
        BatchedLearned(world, make_human("lazy"))


def test_the_partner_is_named_after_its_human_unless_named_and_never_falls_back(sb3_folder: Path) -> None:
    world = World(SCENARIO)
    assert BatchedLearned(world, LearnedHuman(sb3_folder)).name == "learned"
    assert BatchedLearned(world, LearnedHuman(sb3_folder), name="mine").name == "mine"
    assert BatchedLearned.fallbacks == 0


def test_an_empty_batch_gets_no_actions_and_no_policy_call(sb3_folder: Path) -> None:
    world = World(SCENARIO)
    partner = BatchedLearned(world, LearnedHuman(sb3_folder))
    calls: list[int] = []
    partner.human.model.predict = lambda *a, **k: calls.append(1)  # would fail if called
    batch = BatchedRules(world).initial(np.random.default_rng(0), 0)
    actions = partner.act(batch, np.zeros(0, dtype=np.int64), np.random.default_rng(0))
    assert actions.shape == (0,) and actions.dtype == np.int64
    assert calls == []


def test_the_observations_are_the_live_humans_int8_facts_and_masks(sb3_folder: Path) -> None:
    world = World(SCENARIO)
    partner = BatchedLearned(world, LearnedHuman(sb3_folder))
    batch = BatchedRules(world).initial(np.random.default_rng(5), 3)
    facts, masks = partner.observations(batch)
    assert facts.dtype == np.int8 and masks.dtype == np.int8
    for i in range(3):
        state = batch.state(i)
        np.testing.assert_array_equal(facts[i], world.facts(state))
        np.testing.assert_array_equal(masks[i], world.mask(state, Agent.HUMAN))
    actions = partner.act(batch, np.zeros(3, dtype=np.int64), np.random.default_rng(0))
    assert actions.shape == (3,) and actions.dtype == np.int64
