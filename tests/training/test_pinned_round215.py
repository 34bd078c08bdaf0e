"""Values that round 215's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from hg_marl.core import Agent, State, World


def test_each_agent_holds_what_is_in_its_own_hand() -> None:
    # paper2015 by hand: 6 spots (codes 0-5), 1 bin (code 6), so the robot's hand is 6 + 1 = 7
    # and the human's 6 + 1 + 1 = 8 (State's documented codes). tape1 in the human's hand and
    # the robot's empty: the human holds object 0, the robot nothing; with tape1 in the robot's
    # hand and tape2 in the human's, each holds its own.
    world = World("paper2015")
    assert (len(world.scenario.spots), len(world.scenario.bins)) == (6, 1)
    human_holds = State((8, 0, 1), 0)
    assert world.holding(human_holds, Agent.HUMAN) == 0
    assert world.holding(human_holds, Agent.ROBOT) == -1
    both_hold = State((7, 8, 6), 0)
    assert world.holding(both_hold, Agent.ROBOT) == 0
    assert world.holding(both_hold, Agent.HUMAN) == 1
