"""Round 46 of the fresh planted bugs: the values its missed bugs changed, pinned.

The expected values are stated independently of the code under test: the recurrent PPO's
discount is per simulated second, ``gamma ** seconds``, so ``gamma = 1`` (no discount)
is a valid choice, as its own refusal says (``(0, 1]``); a space written to a model
header and read back is the same space (a round trip, a property, with ``Discrete``'s
``start`` among what makes a space); and a ``memory`` header's fields accept their
documented ranges up to and including the top (``history`` in ``[0, MAX_HISTORY]``,
``hg_marl/envs/history.py``; ``history_cap`` in ``[1, 1000]``, the history tracker's
own bounds; ``hidden`` up to ``MAX_HIDDEN``, "the widest layer a file may ask for").
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from gymnasium import spaces

from hg_marl.agents.memory_numpy import MAX_HIDDEN, check_memory_file
from hg_marl.agents.memory_policy import MemoryNet, save_memory
from hg_marl.agents.model_file import load_model_file, world_fields
from hg_marl.agents.model_sb3 import space_from_json, space_to_json
from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError, ModelFileError
from hg_marl.envs.history import MAX_HISTORY, history_size
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig

# --- training/baselines/ppo_recurrent.py ---


@pytest.mark.parametrize(("gamma", "lam"), [(1.0, 0.95), (1, 1.0), (0.5, 0.0), (1e-9, 1)])
def test_recurrent_ppo_accepts_a_discount_and_lambda_up_to_one(gamma: float, lam: float) -> None:
    """``gamma`` in (0, 1] and ``gae_lambda`` in [0, 1]: 1 for either is no discount, a valid
    (if slow to learn) choice; the ends of both ranges pass the check unchanged."""
    config = RecurrentConfig(gamma=gamma, gae_lambda=lam).check()
    assert (config.gamma, config.gae_lambda) == (gamma, lam)


@pytest.mark.parametrize(("gamma", "lam"), [(0.0, 0.95), (1.0000001, 0.95), (0.99, 1.5), (2.0, 0.95)])
def test_recurrent_ppo_refuses_a_discount_or_lambda_outside_its_range(gamma: float, lam: float) -> None:
    with pytest.raises(ConfigError, match="gamma"):
        RecurrentConfig(gamma=gamma, gae_lambda=lam).check()


# --- agents/model_sb3.py ---


@pytest.mark.parametrize(
    "space",
    [
        spaces.Discrete(5),
        spaces.Discrete(5, start=1),
        spaces.Discrete(3, start=-2),
        spaces.Dict({"action": spaces.Discrete(4, start=7), "mask": spaces.MultiBinary(4)}),
    ],
)
def test_a_space_written_to_a_header_reads_back_as_the_same_space(space: spaces.Space) -> None:
    """A round trip through the header's JSON (as written to disk) gives the space back:
    the same ``n`` and the same first action (``start``), so an SB3 model whose action
    space starts elsewhere than 0 rebuilds with its own spaces."""
    back = space_from_json(json.loads(json.dumps(space_to_json(space))), "model.json")
    assert back == space
    if isinstance(space, spaces.Discrete):
        assert (int(back.n), int(back.start)) == (int(space.n), int(space.start))


# --- agents/memory_numpy.py ---


def _memory_file(tmp_path: Path, history: int, cap: int, hidden: int, recurrent: bool) -> Path:
    world = World("paper2015")
    # the observation: the facts, then the history features (2 k (kinds + 1) + cap + 1, or 0 when k = 0)
    obs_size = world.n_facts + history_size(history, cap)
    net = MemoryNet(obs_size, world.n_actions(Agent.ROBOT), hidden, recurrent=recurrent)
    return save_memory(net, tmp_path / "model.json", world_fields(world, Agent.ROBOT), history=history, cap=cap)


@pytest.mark.parametrize(
    ("history", "cap", "hidden", "recurrent"),
    [(MAX_HISTORY, 1000, 3, True), (MAX_HISTORY, 1, 2, False), (0, 8, MAX_HIDDEN, False), (1, 1000, 1, True)],
)
def test_a_memory_header_at_the_top_of_each_range_loads(
    tmp_path: Path, history: int, cap: int, hidden: int, recurrent: bool
) -> None:
    """``history = MAX_HISTORY`` (64), ``history_cap = 1000`` and ``hidden = MAX_HIDDEN`` (1024)
    are the largest values their ranges document: each loads, with the values it was saved with."""
    path = _memory_file(tmp_path, history, cap, hidden, recurrent)
    shape = check_memory_file(load_model_file(path, seat="robot"))
    assert (shape.history, shape.cap, shape.hidden, shape.recurrent) == (history, cap, hidden, recurrent)


@pytest.mark.parametrize(("key", "value"), [("history", MAX_HISTORY + 1), ("history_cap", 1001), ("hidden", 0)])
def test_a_memory_header_one_past_a_range_names_the_field(tmp_path: Path, key: str, value: int) -> None:
    path = _memory_file(tmp_path, 2, 8, 3, True)
    header = json.loads(path.read_text())
    header[key] = value
    path.write_text(json.dumps(header))
    with pytest.raises(ModelFileError, match=f"field '{key}'"):
        check_memory_file(load_model_file(path, seat="robot"))
