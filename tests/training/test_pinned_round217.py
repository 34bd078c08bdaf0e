"""Values that round 217's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.member_models import MemberModels
from hg_marl.core import Agent, World
from hg_marl.core.errors import OutputError
from hg_marl.envs.batched import BatchedTable
from tests.agents.test_member_models import COOP
from tests.env.test_pinned_batched import GOTO_HUMAN, HUMAN_WAIT, Always


def test_member_models_refuse_an_unwritable_cache_naming_the_cache_parameter(tmp_path: Path) -> None:
    # "option: what named ``cache``, for a refusal's message": built without an option (as the belief
    # robot builds its never-taking members), a folder through a file is refused naming ``cache``,
    # with the system's reason (POSIX's ENOTDIR text), before anything is solved.
    (tmp_path / "file").write_text("x")
    folder = tmp_path / "file" / "sub"
    with pytest.raises(OutputError) as refused:
        MemberModels((COOP,), str(folder))
    assert str(refused.value) == f"cache {folder}: cannot write in it (Not a directory)"


def test_in_the_humans_seat_info_effort_is_the_humans_own() -> None:
    # The human's seat, one table of paper2015 (seed 0), the robot partner playing goto(human) (3 s,
    # feasible in the first layout) and the human waiting. A wait is never effort, so after the first
    # cycle the seat's own effort is 0.0 s, while the robot's (partner_effort) is its 3 s move.
    world = World("paper2015")
    env = BatchedTable(Always(GOTO_HUMAN), 1, world, seat=Agent.HUMAN)  # type: ignore[arg-type]
    env.reset(seed=0)
    _, _, _, _, info = env.step(np.array([HUMAN_WAIT]))
    assert info["effort"].tolist() == [0.0]
    assert info["partner_effort"].tolist() == [3.0]
