"""Values that round 102's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.lazy import LazyHuman
from hg_marl.core import Agent, State
from tests.agents.test_pinned_human_base_gate import PAPER, turn


def test_the_lazy_human_logs_its_decisions_under_its_registry_name() -> None:
    # paper2015, tape1 (action 0) on human_mat_1 (4) with mat_shared free and no idling: the lazy
    # human picks it for sure (test_pinned_human_lazy_gate.py works that state by hand). Its decision
    # record names the human as the registry does ("lazy", what a switching human and a trace
    # report), and the action by its name in the world.
    for human in (LazyHuman(p_idle=0.0), make_human("lazy", p_idle=0.0)):
        human.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
        assert human.act(turn(PAPER, State((4, 0, 1), 0))) == 0
        assert human.last_decision == {"human": "lazy", "action": "pick(tape1)"}
