"""The values round 95's missed planted bugs changed, pinned after the round.

Round 95 planted 16 bugs in sixteen gated modules, written blind; 15 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- ``PartnerMonitor.planner_failed`` with blocks in force: "the blocks were a wrong
  guess", so they are forgotten and the planner gets the base model back; a ground action
  is then blocked only after ``block_after`` refusals *counted afresh*, as after a solved
  task. With ``block_after=2``, one refusal after the failure leaves the action unblocked
  and a second one blocks it again.
"""

from __future__ import annotations

from hg_marl.agents.partner import PartnerMonitor
from hg_marl.core import WAIT, Agent, Kind, World


def test_after_a_failed_plan_lifts_the_blocks_an_action_needs_block_after_fresh_refusals() -> None:
    """Worked by hand from the rule above: 2 refusals block, the failure forgets, 1 is not enough, 2 are."""
    world = World("paper2015")
    give = next(i for i, a in enumerate(world.actions(Agent.HUMAN)) if a.kind is Kind.GIVE)
    wait = world.index(Agent.HUMAN, WAIT)
    refused = world.actions(Agent.HUMAN)[give]
    monitor = PartnerMonitor(block_after=2, stall_after=10)
    monitor.observe(world, give, wait, solved=False)
    monitor.observe(world, give, wait, solved=False)
    assert monitor.blocked == {refused}
    monitor.planner_failed()
    assert not monitor.blocked
    monitor.observe(world, give, wait, solved=False)  # the first refusal counted afresh
    assert not monitor.blocked
    monitor.observe(world, give, wait, solved=False)  # the second one: block_after reached again
    assert monitor.blocked == {refused}
