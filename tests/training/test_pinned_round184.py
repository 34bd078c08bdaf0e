"""Values that round 184's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from hg_marl.agents.views import join_events
from hg_marl.core import State
from hg_marl.envs.table_cleaning import EVENT_SEPARATOR, raw_env
from tests.env.test_pinned_aec_env_gate import _index


def test_joining_events_drops_the_empty_ones() -> None:
    # Either side may be empty (a turn with no events): the joined text is the other side as it is,
    # with no separator before or after it, and two empty sides join to "". Only two non-empty
    # sides get the separator, "a" + "; " + "b".
    assert join_events("robot picks", "") == "robot picks"
    assert join_events("", "human waits") == "human waits"
    assert join_events("", "") == ""
    assert join_events("a", "b") == "a" + EVENT_SEPARATOR + "b"


def test_a_continuing_env_counts_every_task_it_solved() -> None:
    # paper2015, continuing: every tape in the bin (spot 6), the robot at 0. The robot's wait on the
    # clean table solves a task (reward 1) and the table is re-drawn; the human waits. Put the
    # clean table back and do it again: two tasks solved, so tasks_solved is 2 (not 1), on the env
    # and in both agents' infos.
    env = raw_env(continuing=True)
    clean = State((6, 6, 6), 0)
    env.reset(seed=0, options={"state": clean})
    for solved in (1, 2):
        env.world_state = clean
        env.step(_index(env, "robot", "wait"))
        assert env.rewards["robot"] == 1.0
        env.step(_index(env, "human", "wait"))
        assert env.tasks_solved == solved
    assert env.infos["robot"]["tasks_solved"] == 2
    assert env.infos["human"]["tasks_solved"] == 2
