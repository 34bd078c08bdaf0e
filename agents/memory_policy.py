"""The network of a learned robot with memory, and its model file (kind ``memory``).

:class:`MemoryNet` is what ``ppo_recurrent`` trains: an MLP encoder of the observation
(the facts, plus the interaction history when ``history > 0``, ``hg_marl/envs/history.py``),
then either a GRU cell (``recurrent=True``: the hidden state carries what the robot has
seen of its partner this episode) or nothing (a memoryless MLP on the history
observation), then a masked categorical actor and a value head.

The model file is the project's (:mod:`hg_marl.agents.model_file`): a JSON header of kind
``memory`` naming the architecture in plain numbers (``obs_size``, ``hidden``,
``recurrent``, ``history``, ``history_cap``) and a ``.npz`` of the state dict. Loading
rebuilds the network from those numbers (bounded) and requires the arrays to have
exactly its names and shapes (:func:`~hg_marl.agents.memory_numpy.check_memory_file`);
nothing is unpickled. The robot plays the file in numpy (``agents/memory_numpy.py``).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import torch
from torch import nn

from hg_marl.agents.memory_numpy import check_memory_file
from hg_marl.agents.model_file import ModelFile, load_model_file, save_model_file
from hg_marl.envs.history import DEFAULT_CAP


class MemoryNet(nn.Module):
    """Encoder, optional GRU cell, actor and critic heads (see the module docstring)."""

    def __init__(self, obs_size: int, n_actions: int, hidden: int = 64, recurrent: bool = True) -> None:
        super().__init__()
        self.obs_size, self.n_actions, self.hidden, self.recurrent = obs_size, n_actions, hidden, recurrent
        self.encoder = nn.Sequential(nn.Linear(obs_size, hidden), nn.Tanh(), nn.Linear(hidden, hidden), nn.Tanh())
        self.gru = nn.GRUCell(hidden, hidden) if recurrent else None
        self.actor = nn.Linear(hidden, n_actions)
        self.critic = nn.Linear(hidden, 1)
        nn.init.orthogonal_(self.actor.weight, 0.01)
        nn.init.zeros_(self.actor.bias)

    def initial(self, n: int) -> torch.Tensor:
        """The hidden state of ``n`` tables at the start of an episode (zeros; width 0 without a GRU)."""
        return torch.zeros((n, self.hidden if self.recurrent else 0))

    def step(
        self, obs: torch.Tensor, h: torch.Tensor, start: torch.Tensor | None = None
    ) -> tuple[torch.Tensor, torch.Tensor, torch.Tensor]:
        """(logits, value, next hidden) of one step; ``start`` marks tables whose episode begins here (h reset)."""
        x = self.encoder(obs)
        if self.gru is not None:
            if start is not None:
                h = h * (~start).unsqueeze(1).to(h.dtype)
            h = self.gru(x, h)
            x = h
        return self.actor(x), self.critic(x).squeeze(1), h

    @staticmethod
    def masked(logits: torch.Tensor, mask: torch.Tensor) -> torch.distributions.Categorical:
        """The policy over feasible actions only (infeasible logits at a large negative value)."""
        return torch.distributions.Categorical(logits=logits.masked_fill(~mask, -1e8))


def save_memory(net: MemoryNet, path: Path, fields: dict[str, Any], history: int, cap: int = DEFAULT_CAP) -> Path:
    """Write ``net`` as a ``memory`` model file (``fields``: the world's and the run's header fields)."""
    arrays = {k: v.detach().cpu().numpy() for k, v in net.state_dict().items()}
    header = {
        **fields,
        "kind": "memory",
        "observation": "facts",
        "obs_size": net.obs_size,
        "hidden": net.hidden,
        "recurrent": net.recurrent,
        "history": history,
        "history_cap": cap,
    }
    return save_model_file(path, header, arrays)


def net_from_file(mf: ModelFile) -> MemoryNet:
    """Rebuild the network of a ``memory`` model file and load its weights (names and shapes checked)."""
    shape = check_memory_file(mf)
    net = MemoryNet(shape.obs_size, shape.n_actions, shape.hidden, shape.recurrent)
    net.load_state_dict({k: torch.as_tensor(np.asarray(v, dtype=np.float32)) for k, v in mf.arrays.items()})
    net.eval()
    return net


def load_memory(path: str | Path, what: str = "--model") -> tuple[MemoryNet, ModelFile]:
    """A ``memory`` model file's network and header (robot seat)."""
    mf = load_model_file(path, what=what, seat="robot")
    return net_from_file(mf), mf
