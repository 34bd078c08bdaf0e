"""Values that round 168's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.models import AnswerTable, StatePacker, build_model
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.core import Agent, World
from hg_marl.core.errors import RobotError
from hg_marl.envs.batched import BatchState


def test_a_models_first_ids_are_its_layouts_in_their_order() -> None:
    # Ids are given in order of discovery and the exploration starts from the layouts, so the layouts
    # (distinct tables) are states 0..L-1, in the order given; the states of the partner's first
    # answers on them come after. The reference is the layouts' own packed keys, in their order.
    # The random partner: its first answers move objects, so they reach states other than the
    # layouts (the cooperative partner's first answer leaves each layout as it is).
    world = World("paper2015")
    layouts = layout_distribution(world)
    packer = StatePacker(world)
    table = AnswerTable(world, stationary_human("random", world), packer)
    model = build_model(world, [table], layouts)
    want = packer.pack(BatchState.of([s for s, _ in layouts]))
    assert len(np.unique(want)) == len(layouts) < model.n
    assert model.keys[: len(layouts)].tolist() == want.tolist()
    assert model.states()[: len(layouts)] == [s for s, _ in layouts]
    assert (model.regen_next >= len(layouts)).any()


@pytest.mark.parametrize("history", [1, 2])
def test_the_sb3_robot_refuses_a_model_trained_with_any_history(history: int, tmp_path: Path) -> None:
    # The robot does not rebuild the history observation, so any history > 0 in the header is
    # refused (the docstring: "a model trained with the history observation ... is refused");
    # the same model saved with history 0 loads.
    from hg_marl.agents.model_file import save_sb3, world_fields
    from hg_marl.agents.robots.sb3 import SB3Robot
    from tests.agents.test_pinned_sb3_robot_gate import _model

    model = _model("maskable")
    world = World("paper2015")
    fields = world_fields(world, Agent.ROBOT)
    save_sb3(model, tmp_path / "plain" / "model.json", {**fields, "history": 0}, observation="facts")
    assert SB3Robot(path=tmp_path / "plain").file is not None
    save_sb3(model, tmp_path / "hist" / "model.json", {**fields, "history": history}, observation="facts")
    with pytest.raises(RobotError, match="history"):
        SB3Robot(path=tmp_path / "hist")
