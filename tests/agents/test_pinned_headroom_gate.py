"""The headroom model's budget checks in the solve and its documented states budget, pinned for the gate.

Expected values by hand: the solve reads the budget every 64th sweep and the process's
memory every 4,096th (so a run of 4,096 sweeps reads it at 64, 128, ..., 4,096 and the
memory once, at 4,096); the states budget's default is the one the documentation gives.
"""

from __future__ import annotations

import inspect
import re
from pathlib import Path
from typing import Any

from hg_marl.agents.headroom import JointModel, headroom
from hg_marl.agents.humans import make_human
from hg_marl.agents.models.budget import Budget
from hg_marl.core import Agent, World
from tests.agents.test_oracle import TINY

ROOT = Path(__file__).resolve().parents[2]


class SpyBudget(Budget):
    """A budget without limits that records the solve's checks."""

    def __init__(self) -> None:
        super().__init__(None, None, None)
        self.solve_checks: list[tuple[int, bool]] = []

    def check(self, phase: str, done: int, total: int | None = None, unit: str = "states", **kw: Any) -> None:
        if phase == "solve":
            self.solve_checks.append((done, bool(kw.get("memory", False))))
        super().check(phase, done, total, unit, **kw)


def test_the_solve_reads_the_budget_every_64_sweeps_and_memory_every_4096() -> None:
    world = World(TINY)
    human = make_human("cooperative")
    human.reset(world, Agent.HUMAN, __import__("numpy").random.default_rng(0))
    budget = SpyBudget()
    model = JointModel(world, [human], failed_actions=False, budget=budget)
    model.optimal_policy(0, tolerance=-1.0, max_iterations=4096)  # a negative tolerance never stops early
    assert budget.solve_checks == [(k, k == 4096) for k in range(64, 4097, 64)]


def test_the_states_budget_default_is_the_documented_one() -> None:
    doc = (ROOT / "docs" / "exact-references.md").read_text()
    match = re.search(r"`--max-states`, default ([\d,]+)", doc)
    assert match is not None
    documented = int(match.group(1).replace(",", ""))
    assert documented == 1_500_000
    assert inspect.signature(headroom).parameters["max_states"].default == documented
    assert inspect.signature(JointModel).parameters["max_states"].default == documented
