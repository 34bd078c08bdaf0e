"""The memory policy's mask (an infeasible action gets no probability, however large its logit)
and its model file (the history cap it was trained with is the one written)."""

from __future__ import annotations

from pathlib import Path

import torch

from hg_marl.agents.memory_policy import MemoryNet, load_memory, save_memory
from hg_marl.agents.model_file import world_fields
from hg_marl.core import Agent, World
from hg_marl.envs.history import DEFAULT_CAP, history_size


def test_masked_actions_get_zero_probability_and_the_rest_keep_their_softmax() -> None:
    # Logits (5, 0, ln 3, 0) with actions 0 and 3 ruled out: the feasible pair (0, ln 3)
    # has softmax (1/4, 3/4) and the infeasible ones 0, even action 0's top logit.
    logits = torch.tensor([[5.0, 0.0, float(torch.log(torch.tensor(3.0))), 0.0]])
    mask = torch.tensor([[False, True, True, False]])
    probs = MemoryNet.masked(logits, mask).probs
    torch.testing.assert_close(probs, torch.tensor([[0.0, 0.25, 0.75, 0.0]]), atol=1e-6, rtol=0.0)


def test_a_model_file_records_the_history_cap_it_was_trained_with(tmp_path: Path) -> None:
    # a net whose input holds the facts and a history capped at 5 (not the default 8): the
    # file says 5, so the loader's check of the input size against the facts and history holds
    world = World("paper2015")
    assert DEFAULT_CAP != 5
    obs_size = world.n_facts + history_size(2, 5)
    net = MemoryNet(obs_size, world.n_actions(Agent.ROBOT), 12, True)
    path = save_memory(net, tmp_path / "model.json", world_fields(world, Agent.ROBOT), history=2, cap=5)
    loaded, mf = load_memory(path)
    assert mf.header["history_cap"] == 5 and loaded.obs_size == obs_size
