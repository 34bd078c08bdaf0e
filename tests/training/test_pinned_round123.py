"""Values that round 123's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import torch

from hg_marl.agents.memory_policy import MemoryNet, load_memory, save_memory
from hg_marl.agents.model_file import world_fields
from hg_marl.core import Agent, World
from hg_marl.core.errors import HgMarlError
from hg_marl.training.baselines.recurrent_ppo_sb3 import RecurrentSb3Config
from hg_marl.training.play.session import PlaySession
from tests.play.reference import person_choice
from tests.play.test_pinned_play_session_gate import ticking


def test_a_memory_model_file_says_it_observes_the_facts(tmp_path: Path) -> None:
    # The memory net reads the fact vector (plus the history when history > 0), never the
    # mask: its input is n_facts wide with history 0. The header it writes must say so
    # ("facts"), on disk and as loaded back; "flat" would be the facts followed by the mask.
    world = World("paper2015")
    torch.manual_seed(0)
    net = MemoryNet(world.n_facts, world.n_actions(Agent.ROBOT), 8, True)
    path = save_memory(net, tmp_path / "model.json", world_fields(world, Agent.ROBOT), history=0)
    assert json.loads(path.read_text())["observation"] == "facts"
    _, mf = load_memory(path)
    assert mf.header["observation"] == "facts" and mf.header["obs_size"] == world.n_facts


def test_a_sessions_experts_count_the_planner_not_the_actions_it_chose() -> None:
    # The plain planner robot proposes every move itself (expert "planner"); on the first
    # turns of a fresh game it never stalls, so after the robot's opening move and two of the
    # scripted person's moves (each answered by the robot) the count is planner: 3, whatever
    # actions those were.
    session = PlaySession(player="p", seed=0, timer=ticking())
    assert dict(session.experts) == {"planner": 1}
    for _ in range(2):
        session.play(person_choice([c.name for c in session.choices()]))
    assert dict(session.experts) == {"planner": 3}
    assert session.summary()["experts"] == {"planner": 3}


def test_the_recurrent_sb3_config_accepts_an_lstm_as_wide_as_a_model_header_may_ask() -> None:
    # A model header's lstm_hidden_size may be up to 1024 units (agents/sb3_limits.py's
    # MAX_LSTM_UNITS, "4 x 1024 x 1024 weights per layer"); the run's config accepts the same
    # widths, 1 through 1024, and refuses 1025 naming the field.
    for width in (1, 513, 1024):
        assert RecurrentSb3Config(lstm_hidden=width).check().lstm_hidden == width
    with pytest.raises(HgMarlError, match="lstm_hidden"):
        RecurrentSb3Config(lstm_hidden=1025).check()
