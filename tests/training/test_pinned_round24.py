"""The values round 24's missed planted bugs changed, pinned after the round.

Round 24 planted 14 bugs in the fourteen newest modules (as rounds 19, 20 and 23), written
blind; 12 were caught. Each value below is stated from the rule the module documents:

- a compiled partner with a ``closure`` (other humans whose answers also lead on) keeps
  its own answers: on the states it meets, its distribution is the live human's, not a
  closure human's (the lazy human never takes and idles; the cooperative one does not);
- the array progress guard's ``reset_rows`` starts a table afresh as the scalar guard's
  ``reset`` does: ``W`` back to 40 turns after a spell doubled it, every counter 0 and
  every flag off, and the other tables untouched.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.compiled import compile_human
from hg_marl.agents.humans import make_human
from hg_marl.agents.progress import ArrayProgressGuard, ProgressGuard
from hg_marl.core import Agent, World
from hg_marl.envs.batched import BatchedRules


def test_a_compiled_partner_with_a_closure_answers_as_itself() -> None:
    world = World("paper2015")
    compiled = compile_human(world, "lazy", cache=None, closure=["cooperative"])
    live = make_human("lazy")
    live.reset(world, Agent.HUMAN, np.random.default_rng(0))
    rules = BatchedRules(world)
    rng = np.random.default_rng(5)
    batch = rules.initial(rng, 16)
    seen = np.full(16, -1)
    checked = 0
    for t in range(24):
        agent = Agent(t % 2)
        masks = rules.masks(batch, agent)
        actions = (rng.random(masks.shape) * masks).argmax(1)  # a random robot leads the tables on
        if agent is Agent.HUMAN:
            actions = compiled.act(batch, seen, rng)
        ok, _, _ = rules.step(batch, agent, actions)
        if agent is Agent.ROBOT:
            seen = np.where(ok, actions, -1)
            for i in range(16):
                expected = sorted(
                    (a, p)
                    for a, p in live.distribution(world, batch.state(i), int(seen[i]) if live.uses_robot_action else -1)
                    if p > 0
                )
                got = compiled.distribution(batch, seen, i)
                assert [a for a, _ in got] == [a for a, _ in expected], (t, i)
                assert [p for _, p in got] == pytest.approx([p for _, p in expected], abs=1e-12)
                checked += 1
    assert checked == 12 * 16
    assert compiled.fallbacks == 0


def test_reset_rows_starts_a_table_afresh_as_the_scalar_reset_does() -> None:
    world = World("paper2015")
    guard = ArrayProgressGuard(world)
    guard.grow(3)
    # tables 0 and 2 mid-run: a spell under way after one that doubled W (40 -> 80, then 160)
    for name, value in [
        ("patience", 160),
        ("unchanged", 7),
        ("moves", 3),
        ("fired", True),
        ("quiet", 250),
        ("waiting", True),
        ("spells", 2),
        ("answered", True),
    ]:
        getattr(guard, name)[:] = value
    guard.reset_rows(np.array([0, 2]))
    scalar = ProgressGuard()
    assert scalar.patience == 40  # W, the documented first spell's length
    fresh = {
        "patience": 40,
        "unchanged": 0,
        "moves": 0,
        "fired": False,
        "quiet": 0,
        "waiting": False,
        "spells": 0,
        "answered": False,
    }
    for name, value in fresh.items():
        assert getattr(guard, name)[[0, 2]].tolist() == [value, value], name
    assert guard.patience[1] == 160 and guard.spells[1] == 2  # the table not reset keeps its run
