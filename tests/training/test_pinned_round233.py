"""Values that round 233's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.models.budget import Budget, OverBudget
from hg_marl.core import Agent, World
from hg_marl.envs.batched import BatchedTable
from hg_marl.training.store import Store, seal
from tests.env.test_pinned_batched import GOTO_HUMAN, HUMAN_WAIT, ROBOT_WAIT, Always
from tests.training.test_pinned_store import JOB, _result, skipped_then_removed

ROOT = Path(__file__).resolve().parents[2]


def test_the_default_states_budget_is_the_documented_one_and_named_in_a_refusal() -> None:
    # docs/exact-references.md: "(`--max-states`, default 1,500,000)"; a phase reporting one state
    # more than that is refused, the refusal naming the budget with thousands separators.
    doc = (ROOT / "docs" / "exact-references.md").read_text()
    match = re.search(r"`--max-states`, default ([\d,]+)", doc)
    assert match is not None and match.group(1) == "1,500,000"
    budget = Budget()
    assert budget.states == 1_500_000
    budget.check("enumerate", 0, states=1_500_000, memory=False)  # exactly the budget: allowed
    with pytest.raises(OverBudget, match=r"max_states=1,500,000 states \(1,500,001 states\)"):
        budget.check("enumerate", 0, states=1_500_001, memory=False)


@pytest.mark.parametrize(("summary", "problem"), [(None, "incomplete (no summary)"), ([], "incomplete (no summary)")])
def test_a_sealed_entry_without_a_summary_dict_is_not_used(
    tmp_path: Path, summary: object, problem: str, caplog: pytest.LogCaptureFixture
) -> None:
    # The seal matches (sealed again as put seals), so only the summary check can refuse it:
    # a summary that is not a dict is "incomplete (no summary)", skipped, then removed with one warning.
    store = Store(tmp_path)
    store.put(JOB, _result())
    path = store.entry(JOB.key()) / "result.json"
    record = json.loads(path.read_text())
    record["summary"] = summary
    path.write_text(json.dumps(seal(record)))
    skipped_then_removed(store, problem, caplog)


def test_same_step_autoreset_keeps_the_final_observation_of_a_table_that_ended_alone() -> None:
    # Two tables on one layout, the human waiting (1 s), a budget of 2 s. Table 0's robot waits
    # (a 1 s cycle: clock 1, not ended); table 1's goes to the human (3 s: clock 3 >= 2, truncated).
    # Only table 1 ended: its final observation and info are kept, flagged by _final_obs [False, True].
    world = World("paper2015")
    assert world.action_name(Agent.ROBOT, GOTO_HUMAN) == "goto(human)"
    rng = np.random.default_rng(0)
    state = world.initial_state(rng)
    while not world.table.feasible(state, Agent.ROBOT, GOTO_HUMAN):
        state = world.initial_state(rng)
    env = BatchedTable(
        Always(HUMAN_WAIT),  # type: ignore[arg-type]
        2,
        world,
        max_cycles=None,
        time_budget=2.0,
        autoreset_mode="same_step",
    )
    env.reset(seed=0, options={"states": [state, state]})
    _, _, term, trunc, info = env.step(np.array([ROBOT_WAIT, GOTO_HUMAN]))
    assert term.tolist() == [False, False] and trunc.tolist() == [False, True]
    assert info["_final_obs"].tolist() == [False, True]
    assert info["final_info"]["clock"].tolist() == [1.0, 3.0]
    assert info["final_obs"].shape == (2, world.n_facts)
    assert env.clock.tolist() == [1.0, 0.0]  # table 1 restarted in the same step
