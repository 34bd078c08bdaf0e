"""Values that round 186's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import torch

from hg_marl.agents.memory_policy import MemoryNet
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig


def test_a_default_memory_net_is_64_wide_and_recurrent_like_the_trainers() -> None:
    # MemoryNet(obs_size, n_actions) with no width: 64 hidden units and a GRU cell, the width
    # and memory ppo_recurrent trains by default (RecurrentConfig: hidden 64, memory "gru").
    # Worked by hand for 3 inputs and 2 actions: the encoder's layers are 3 -> 64 -> 64, the
    # GRU cell's weights stack its 3 gates (3 x 64 = 192 rows of 64), the heads read 64 units,
    # and an episode starts from a zero hidden state of width 64 per table.
    assert RecurrentConfig().hidden == 64 and RecurrentConfig().memory == "gru"
    net = MemoryNet(3, 2)
    assert net.hidden == 64 and net.recurrent
    assert tuple(net.encoder[0].weight.shape) == (64, 3)
    assert tuple(net.encoder[2].weight.shape) == (64, 64)
    assert net.gru is not None and tuple(net.gru.weight_hh.shape) == (192, 64)
    assert tuple(net.actor.weight.shape) == (2, 64)
    assert tuple(net.critic.weight.shape) == (1, 64)
    h = net.initial(2)
    assert tuple(h.shape) == (2, 64) and not h.any()
    logits, value, h_next = net.step(torch.zeros((2, 3)), h)
    assert tuple(logits.shape) == (2, 2) and tuple(value.shape) == (2,) and tuple(h_next.shape) == (2, 64)
