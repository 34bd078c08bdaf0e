"""The rule table reads place codes and agents by value, and indexes actions by their parts, pinned for the gate.

The size limits are raised by environment variables (``HG_MARL_MAX_SPOTS``), so a table
may have more than 256 places: its hand codes are then ints that CPython does not cache,
and a state decoded from arrays, a file or a wire holds equal ints that are other objects.
Likewise an agent may come as a plain int (``agent: int``), not an ``Agent`` member.
The expected answers come from the naive reference rules of ``reference_rules.py``
(written from ``docs/task.md``), which compare every place code with ``==``, and from
the task's one reward rule (the robot waiting on a clean table); an action's index from
its parts is its position in the agent's list of ground actions.
"""

from __future__ import annotations

import pytest

from hg_marl.core import Agent, State, World
from hg_marl.core.durations import Durations
from hg_marl.core.scenario import generate_scenario
from hg_marl.core.table import RuleTable
from tests.core import reference_rules as ref


def _fresh(code: int) -> int:
    """An int equal to ``code`` but a new object (as decoding a state from text makes it)."""
    return int(str(code))


def test_a_hand_code_above_the_small_int_cache_is_recognised_by_value(monkeypatch: pytest.MonkeyPatch) -> None:
    """300 spots and one bin: the robot's hand is place 301, the human's 302 (``M + B``, ``M + B + 1``).

    With one robot location, which reaches the only bin and is the handover location
    (``generate_scenario``'s location 0 is next to the human), a robot holding object 0
    can throw it and give it; a human holding it can throw, give and place it. Every
    action of both agents is checked against the reference, in states whose held object's
    place code is a fresh int.
    """
    monkeypatch.setenv("HG_MARL_MAX_SPOTS", "400")
    scenario = generate_scenario(objects=2, spots=300, locations=1, bins=1)
    table = RuleTable(scenario, Durations())
    robot_hand, human_hand = 300 + 1, 300 + 1 + 1
    assert table.hand == (robot_hand, human_hand)
    states = [
        State((_fresh(robot_hand), 0), 0),
        State((1, _fresh(human_hand)), 0),
        State((_fresh(robot_hand), _fresh(human_hand)), 0),
    ]
    feasible_held = 0
    for state in states:
        for agent in Agent:
            for i, action in enumerate(table.actions[agent]):
                expected = ref.feasible(scenario, state, agent, action)
                assert table.feasible(state, agent, i) == expected, (state, agent, action)
                nxt, ok, _ = table.successor(state, agent, i)
                assert (nxt, ok) == ref.successor(scenario, state, agent, action), (state, agent, action)
                feasible_held += expected and action.kind.name in ("THROW", "GIVE")
    # each state holds one or two objects, each throwable and givable by its holder
    assert feasible_held == 2 * (1 + 1 + 2)


def test_the_robots_wait_on_a_clean_table_solves_it_with_the_agent_given_as_a_plain_int() -> None:
    """``solves`` takes ``agent: int``: index 0 (the robot) given as an int, as arrays and wires carry it.

    paper2015 has one bin accepting every colour: all objects in it is a clean table
    (the reference's ``is_clean`` agrees); only the robot's wait completes it.
    """
    world = World("paper2015")
    sc, table = world.scenario, world.table
    m = len(sc.spots)
    clean = State(tuple(m + 0 for _ in sc.objects), 0)
    messy = State((0, *clean.where[1:]), 0)
    assert ref.is_clean(sc, clean) and not ref.is_clean(sc, messy)
    robot, human = _fresh(0), _fresh(1)
    assert type(robot) is int
    assert table.solves(clean, robot, table.wait[robot])
    assert not table.solves(clean, human, table.wait[human])  # the human's wait completes nothing
    assert not table.solves(messy, robot, table.wait[robot])
    assert not table.solves(clean, robot, table.wait[robot] - 1)  # another action of the robot


def test_feasible_indices_with_the_agent_as_a_plain_int_are_the_reference_rules() -> None:
    """Each agent holding an object or not, at each robot location of roboergosum: the feasible actions.

    With the agent given as an int (0 robot, 1 human), the list is still every action the
    reference finds feasible, in index order: the human's places and the robot's gotos included.
    """
    world = World("roboergosum")
    sc, table = world.scenario, world.table
    m, b = len(sc.spots), len(sc.bins)
    rest = tuple(range(1, len(sc.objects)))  # objects 1.. on spots 1..
    places = 0
    for at in range(len(sc.robot_locations)):
        for held_by in (None, 0, 1):
            first = 0 if held_by is None else m + b + held_by
            state = State((first, *rest), at)
            for agent in (_fresh(0), _fresh(1)):
                expected = [i for i, a in enumerate(table.actions[agent]) if ref.feasible(sc, state, Agent(agent), a)]
                assert table.feasible_indices(state, agent) == expected, (state, agent)
                places += sum(table.actions[agent][i].kind.name == "PLACE" for i in expected)
    assert places > 0  # the human, holding object 0, can place it somewhere


@pytest.mark.parametrize("name", ["paper2015", "roboergosum", "generated:objects=3,spots=5,bins=2,locations=3,seed=1"])
def test_an_action_index_from_its_parts_is_the_actions_position(name: str) -> None:
    """``action_index(agent, kind, obj, target)`` of each ground action is where it stands in the agent's list.

    The places are M spots, B bins and the two hands: ``M + B + 2`` codes, the last the human's hand.
    """
    world = World(name)
    sc, table = world.scenario, world.table
    m, b = len(sc.spots), len(sc.bins)
    assert table.n_places == m + b + 2 and table.hand[Agent.HUMAN] == table.n_places - 1
    for agent in Agent:
        actions = table.actions[agent]
        assert [table.action_index(agent, a.kind, a.obj, a.target) for a in actions] == list(range(len(actions)))


def test_a_goto_that_is_not_possible_has_the_documented_destination_minus_one() -> None:
    """roboergosum: a goto to a bin or spot the robot reaches already, or to an object held or thrown, is -1.

    Each expected answer from the rules (``goto(x)``: ``x`` out of reach now and reachable
    from some location) as the reference decides them; a feasible goto's destination is
    ``>= 0`` and the reference's first location reaching ``x``.
    """
    world = World("roboergosum")
    sc, table = world.scenario, world.table
    m, b, n = len(sc.spots), len(sc.bins), len(sc.objects)
    held_and_thrown = (m + b, m, *range(2, n))  # object 0 in the robot's hand, object 1 in bin 0
    impossible = 0
    for at in range(len(sc.robot_locations)):
        for where in (tuple(range(n)), held_and_thrown):
            state = State(where, at)
            for target in range(n + b + 1):
                reach = ref.goto_reach(sc, state, target)
                if reach and at not in reach:
                    assert table.goto_destination(state, target) == min(reach)
                else:
                    assert table.goto_destination(state, target) == -1, (state, target)
                    impossible += 1
    assert impossible > 0
