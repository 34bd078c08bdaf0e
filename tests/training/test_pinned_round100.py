"""Values that round 100's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
import torch

from hg_marl.agents.humans.lazy import LazyHuman
from hg_marl.agents.humans.switching import SwitchingHuman
from hg_marl.agents.memory_numpy import NumpyMemoryPolicy
from hg_marl.agents.memory_policy import MemoryNet, load_memory, save_memory
from hg_marl.agents.model_file import world_fields
from hg_marl.agents.model_sb3 import load_replay_buffer, save_replay_buffer
from hg_marl.agents.models.cache import entry_path
from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError
from hg_marl.envs.history import history_size
from hg_marl.training.baselines.bc import Dataset, fit_linear
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig


def test_a_switching_phase_given_as_an_instance_has_no_spec() -> None:
    # "Each phase's registry spec (None for an instance)": a batched env compiles a phase by its
    # spec, so an instance (here a lazy human idling 90% of the time, not the registry's default
    # lazy) must not be given its name as spec, or it would be compiled as the default lazy human.
    human = SwitchingHuman(humans=[LazyHuman(p_idle=0.9), "cooperative"], at=[600.0])
    assert human.specs == [None, "cooperative"]


@pytest.mark.parametrize("recurrent", [True, False])
def test_the_numpy_memory_player_adds_the_actors_bias(tmp_path: Path, recurrent: bool) -> None:
    # The actor's weights set to 0 and its bias to 1, 2, ..., A: whatever the encoder and the GRU
    # compute, logits = 0 @ x + bias = (1, 2, ..., A) on every row (a fresh net's bias is 0, so a
    # player that drops it agrees with torch until a file has been trained).
    world = World("paper2015")
    n_actions = world.n_actions(Agent.ROBOT)
    obs_size = world.n_facts + history_size(2)
    net = MemoryNet(obs_size, n_actions, 8, recurrent)
    with torch.no_grad():
        net.actor.weight.zero_()
        net.actor.bias.copy_(torch.arange(1, n_actions + 1, dtype=torch.float32))
    path = save_memory(net, tmp_path / "model.json", world_fields(world, Agent.ROBOT), history=2)
    _, mf = load_memory(path)
    player = NumpyMemoryPolicy(mf)
    obs = np.random.default_rng(0).random((3, obs_size))
    logits, _ = player.step(obs, player.initial(3))
    assert np.allclose(logits, np.tile(np.arange(1.0, n_actions + 1), (3, 1)))


def test_a_family_scenarios_cache_entry_is_named_after_its_family(tmp_path: Path) -> None:
    # "generated:objects=2,seed=4" is the family "generated" with parameters: its entry is
    # <family>-<the key's first 24 characters>.npz.
    world = World("generated:objects=2,seed=4")
    key = "0123456789abcdef" * 4
    assert entry_path(tmp_path, world, key) == tmp_path / "generated-0123456789abcdef01234567.npz"


def test_a_loaded_replay_buffer_is_full_when_the_saved_one_was(tmp_path: Path) -> None:
    # A buffer of 4 that has wrapped round (pos 0, full): once loaded, the fresh buffer must be full
    # too, or it samples from its first pos = 0 rows only.
    def buffer(full: bool) -> SimpleNamespace:
        return SimpleNamespace(
            observations=np.arange(8, dtype=np.float64).reshape(4, 2) * full,
            actions=np.zeros((4, 1), dtype=np.int64),
            buffer_size=4,
            pos=0,
            full=full,
        )

    entry = save_replay_buffer(buffer(True), tmp_path / "buffer.npz")
    target = buffer(False)
    load_replay_buffer(target, tmp_path / "model.json", entry)
    assert (target.pos, target.full) == (0, True)
    assert target.observations.tolist() == [[0, 1], [2, 3], [4, 5], [6, 7]]


def test_recurrent_ppo_accepts_a_hidden_width_up_to_the_memory_files_1024() -> None:
    # A memory model file may hold layers up to 1024 wide (memory_numpy's MAX_HIDDEN): --hidden 1024
    # is accepted, 1025 refused naming the option.
    assert RecurrentConfig(hidden=1024).check().hidden == 1024
    with pytest.raises(ConfigError, match="--hidden"):
        RecurrentConfig(hidden=1025).check()


def test_the_linear_fits_bias_steps_by_the_summed_gradient() -> None:
    # Four rows of all-zero facts, two actions, every row action 0, one step of rate 0.5. At w = b = 0
    # both actions have p = 0.5, so each row's gradient is (p - y) / n = (-0.5, 0.5) / 4; summed over
    # the rows (-0.5, 0.5), and b = -0.5 * (-0.5, 0.5) = (0.25, -0.25). The facts are 0, so w stays 0.
    data = Dataset(
        np.zeros((4, 3), dtype=np.int8),
        np.ones((4, 2), dtype=bool),
        np.zeros(4, dtype=np.int64),
        "paper2015",
        Agent.HUMAN,
    )
    w, b = fit_linear(data, 2, iterations=1, learning_rate=0.5)
    assert np.allclose(b, [0.25, -0.25])
    assert np.allclose(w, 0.0)
