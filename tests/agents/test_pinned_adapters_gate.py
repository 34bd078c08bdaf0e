"""The scripted seats' seats and seeds, and the fixed library policies, pinned for the mutation gate.

Expected values from ``agents/adapters.py``'s spec sheet: each scripted actor is reset for
its own seat (``robot`` as the robot, ``human`` as the human); ``reset(seed=s)`` reseeds
the actors from ``s``: a generator ``default_rng(s)`` gives each actor, in the order the
seats were given (robot, then human), a seed drawn over the non-negative int64 range
``[0, 2**63 - 1)`` (the reference below is that rule, written out; it is what makes a
recorded seed replay the same play). The fixed Tianshou policy takes the first allowed
action of each row of the batch; the fixed RLlib module gives allowed actions logit 0,
ruled-out ones a very negative logit (a stand-in for -inf), and values 0, one per row.

Neither Tianshou nor RLlib is installed in the test environment, so the few names the
adapters import from them are stood in for by minimal modules (only the base classes and
constants the adapters use); what is tested is the adapters' own code.
"""

from __future__ import annotations

import sys
import types
from typing import Any

import numpy as np
import pytest
import torch

import hg_marl
from hg_marl.agents.adapters import rllib_fixed_module_class, scripted_v0, tianshou_fixed_algorithm
from hg_marl.core import Agent, World
from hg_marl.policy import Turn


class _Recording:
    """An actor that records the seat and the generator each reset gives it, and waits."""

    def __init__(self) -> None:
        self.seats: list[Agent] = []
        self.first_draws: list[float] = []

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.seats.append(agent)
        self.first_draws.append(float(rng.random()))
        self.wait = world.n_actions(agent) - 1

    def act(self, turn: Turn) -> int:
        return self.wait


def _reference_first_draws(seed: int, seats: int) -> list[float]:
    """The rule of the spec sheet: one seed per seat from ``default_rng(seed)`` over ``[0, 2**63 - 1)``."""
    parent = np.random.default_rng(seed)
    return [float(np.random.default_rng(int(parent.integers(0, 2**63 - 1))).random()) for _ in range(seats)]


def test_each_scripted_actor_is_reset_for_its_own_seat() -> None:
    robot, human = _Recording(), _Recording()
    env = scripted_v0(hg_marl.env(), robot=robot, human=human)
    env.reset(seed=0)
    assert robot.seats == [Agent.ROBOT] and human.seats == [Agent.HUMAN]


@pytest.mark.parametrize("seed", [0, 1, 7])
def test_a_reset_seed_seeds_the_actors_as_the_spec_sheet_says(seed: int) -> None:
    robot, human = _Recording(), _Recording()
    env = scripted_v0(hg_marl.env(), robot=robot, human=human)
    env.reset(seed=seed)
    assert robot.first_draws + human.first_draws == _reference_first_draws(seed, 2)


def test_different_reset_seeds_give_the_actor_different_generators() -> None:
    human = _Recording()
    env = scripted_v0(hg_marl.env(), human=human)
    for seed in range(4):
        env.reset(seed=seed)
    assert len(set(human.first_draws)) == 4


def _install(monkeypatch: pytest.MonkeyPatch, names: dict[str, dict[str, Any]]) -> None:
    """Stand-in modules: each dotted name (and its parents) in ``sys.modules`` with the given attributes."""
    for name, attrs in names.items():
        parts = name.split(".")
        for i in range(1, len(parts) + 1):
            dotted = ".".join(parts[:i])
            if dotted not in sys.modules:
                monkeypatch.setitem(sys.modules, dotted, types.ModuleType(dotted))
        for key, value in attrs.items():
            monkeypatch.setattr(sys.modules[name], key, value, raising=False)


def test_the_fixed_tianshou_policy_takes_each_rows_first_allowed_action(monkeypatch: pytest.MonkeyPatch) -> None:
    class Algorithm:
        class Policy:
            def __init__(self, action_space: Any) -> None:
                self.action_space = action_space

        def __init__(self, action_space: Any) -> None:
            self.policy: Any = None

    class Batch(dict):  # tianshou's Batch: attributes from keywords
        def __getattr__(self, key: str) -> Any:
            return self[key]

    _install(
        monkeypatch,
        {
            "tianshou.algorithm.random": {"MARLRandomDiscreteMaskedOffPolicyAlgorithm": Algorithm},
            "tianshou.data": {"Batch": Batch},
        },
    )
    algorithm = tianshou_fixed_algorithm("space")
    masks = np.array([[0, 1, 1, 0], [1, 0, 0, 1], [0, 0, 0, 1]], np.int8)
    out = algorithm.policy.forward(Batch(obs=Batch(mask=masks)))
    assert out.act.tolist() == [1, 0, 3]  # by hand: the first 1 of each row


def test_the_fixed_rllib_module_allows_only_masked_in_actions_and_values_zero(monkeypatch: pytest.MonkeyPatch) -> None:
    class TorchRLModule(torch.nn.Module):
        def setup(self) -> None:
            pass

    class Columns:
        OBS = "obs"
        ACTION_DIST_INPUTS = "action_dist_inputs"

    _install(
        monkeypatch,
        {
            "ray.rllib.core.columns": {"Columns": Columns},
            "ray.rllib.core.rl_module.apis.value_function_api": {"ValueFunctionAPI": object},
            "ray.rllib.core.rl_module.torch": {"TorchRLModule": TorchRLModule},
        },
    )
    module = rllib_fixed_module_class()()
    module.setup()
    assert [p.requires_grad for p in module.parameters()] == [False]  # nothing to train
    mask = torch.tensor([[0, 1, 1], [1, 0, 0]], dtype=torch.int8)
    logits = module._forward({"obs": {"action_mask": mask}})["action_dist_inputs"]
    allowed = mask.bool()
    assert torch.all(logits[allowed] == 0)
    assert torch.all(logits[~allowed] <= -1e9)
    probabilities = torch.softmax(logits, dim=-1)
    assert probabilities.tolist() == [[0.0, 0.5, 0.5], [1.0, 0.0, 0.0]]
    values = module.compute_values({"obs": {"action_mask": mask}})
    assert values.tolist() == [0.0, 0.0]
