"""Values that round 221's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.agents.humans.learned import LearnedHuman
from hg_marl.core.errors import HumanError
from tests.agents.test_pinned_learned_human_gate import _linear


@pytest.mark.parametrize("fallback", ["greedy", "uniform", "none", "WAIT", "Random", ""])
def test_a_learned_human_refuses_every_fallback_but_wait_and_random(tmp_path: Path, fallback: str) -> None:
    # The module documents exactly two fallbacks for an unseen observation, "wait" and
    # "random" (case matters): any other name, however plausible, is refused at once with
    # the name given, rather than silently acting as one of the two.
    folder = _linear(tmp_path / "p")
    with pytest.raises(HumanError, match=f"fallback must be 'wait' or 'random', got '{fallback}'"):
        LearnedHuman(folder, fallback=fallback)
    assert LearnedHuman(folder, fallback="random").fallback == "random"
    assert LearnedHuman(folder, fallback="wait").fallback == "wait"
