"""Plan costs and durations worked by hand for small fixed layouts.

Each layout is a scenario file written here with its durations, so every number below
follows from the file and the cost model's definition (module docstring of
``agents/planner/costs.py``), not from the planner's own cost functions:

    per cycle  dt = max(d_robot, d_human); e_r, e_h = active (non-wait) durations
    time += dt; human_effort += e_h; effort_balance += max(0, e_h - e_r);
    human_idle += dt - e_h; human_holding += dt if the human holds an object after it
    cost = 1.0 time + 0.2 effort + 0.1 balance + 0.05 idle + 0.1 holding   (default weights)
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.agents.planner import Planner
from hg_marl.agents.planner.costs import CostWeights, PlannerConfig
from hg_marl.agents.planner.space import Relabel
from hg_marl.core import Action, Agent, Kind, State, World

DURATIONS = """
[durations]
pick = 2.0
throw = 2.0
give = 1.0
take = 1.5
place = 2.0
goto = 3.0
wait = 1.0
failed = 0.2
"""

ONE_TAPE = """
name = "one_tape"
description = "one tape the robot fetches alone; the human reaches nothing"
robot_locations = ["bin_side", "table"]
handover_locations = ["table"]
robot_start = ["bin_side"]
[[objects]]
name = "tape"
[[bins]]
name = "bin"
robot_reach = ["bin_side"]
human_reach = false
[[spots]]
name = "mat"
robot_reach = ["table"]
[[layout]]
count = 1
spots = ["mat"]
"""

HANDOVER = """
name = "handover"
description = "one tape only the human reaches; the bin only the robot reaches"
robot_locations = ["bin_side", "human_side"]
handover_locations = ["human_side"]
robot_start = ["bin_side"]
[[objects]]
name = "tape"
[[bins]]
name = "bin"
robot_reach = ["bin_side"]
human_reach = false
[[spots]]
name = "human_mat"
human_reach = true
[[layout]]
count = 1
spots = ["human_mat"]
"""


def world(tmp_path: Path, text: str) -> World:
    path = tmp_path / "layout.toml"
    path.write_text(text + DURATIONS)
    return World(str(path))


def joint(w: World, plan_cycles: tuple[tuple[int, int], ...]) -> list[tuple[str, str]]:
    return [(w.action_names[Agent.ROBOT][r], w.action_names[Agent.HUMAN][h]) for r, h in plan_cycles]


def test_one_tape_robot_alone(tmp_path: Path) -> None:
    w = world(tmp_path, ONE_TAPE)
    result = Planner(w).plan(State((0,), 0))  # tape on the mat, robot at the bin
    assert result.success and result.plan is not None
    # The human can only wait (1 s), so each cycle lasts the robot's action:
    #   goto(tape) 3 | pick 2 | goto(bin) 3 | throw 2 | completing wait 1  -> time 11 s
    assert joint(w, result.plan.cycles) == [
        ("goto(tape)", "wait"),
        ("pick(tape)", "wait"),
        ("goto(bin)", "wait"),
        ("throw(tape)", "wait"),
        ("wait", "wait"),
    ]
    assert result.plan.duration == pytest.approx(11.0)
    # effort 0, balance 0, idle = 11 (the human waits throughout), holding 0
    # cost = 11 + 0.05 * 11 = 11.55
    assert result.breakdown == pytest.approx(
        {"time": 11.0, "human_effort": 0.0, "effort_balance": 0.0, "human_idle": 0.55, "human_holding": 0.0}
    )
    assert result.cost == pytest.approx(11.55)


def test_handover_from_the_human(tmp_path: Path) -> None:
    w = world(tmp_path, HANDOVER)
    result = Planner(w).plan(State((0,), 0))
    assert result.success and result.plan is not None
    # cycle  robot           human       dt   e_h  balance  idle  holding(after)
    #   1    goto(human) 3   pick 2      3    2    0        1     3  (holds the tape)
    #   2    wait 1          give 1      1    1    1        0     1  (still in hand, offered)
    #   3    take 1.5        wait 1      1.5  0    0        1.5   0
    #   4    goto(bin) 3     wait 1      3    0    0        3     0
    #   5    throw 2         wait 1      2    0    0        2     0
    #   6    wait 1          wait 1      1    0    0        1     0
    # totals: time 11.5, effort 3, balance 1, idle 8.5, holding 4
    # cost = 11.5 + 0.2*3 + 0.1*1 + 0.05*8.5 + 0.1*4 = 11.5 + 0.6 + 0.1 + 0.425 + 0.4 = 13.025
    assert joint(w, result.plan.cycles) == [
        ("goto(human)", "pick(tape)"),
        ("wait", "give(tape)"),
        ("take(tape)", "wait"),
        ("goto(bin)", "wait"),
        ("throw(tape)", "wait"),
        ("wait", "wait"),
    ]
    assert result.plan.duration == pytest.approx(11.5)
    assert result.breakdown == pytest.approx(
        {"time": 11.5, "human_effort": 0.6, "effort_balance": 0.1, "human_idle": 0.425, "human_holding": 0.4}
    )
    assert result.cost == pytest.approx(13.025)


def test_handover_time_only_weights(tmp_path: Path) -> None:
    w = world(tmp_path, HANDOVER)
    result = Planner(w, PlannerConfig(weights=CostWeights.time_only())).plan(State((0,), 0))
    # no social term: the cost is the 11.5 s of the fastest plan above
    assert result.cost == pytest.approx(11.5) and result.plan is not None
    assert result.plan.duration == pytest.approx(11.5)


def test_bound_is_admissible_and_not_trivial(tmp_path: Path) -> None:
    # a = w_time + w_idle = 1.05. Whatever the plan, the robot must at least get the tape into
    # its hand (take 1.5 s or pick 2 s), throw it (2 s) and finish with a wait (1 s):
    # bound >= 1.05 * 4.5 = 4.725; and it may not exceed the optimal costs worked above.
    for text, optimal in ((ONE_TAPE, 11.55), (HANDOVER, 13.025)):
        planner = Planner(world(tmp_path, text))
        bound = planner.space.bound(State((0,), 0))
        assert 4.725 <= bound <= optimal + 1e-9


@pytest.mark.parametrize(
    ("where", "at", "action", "to_go"),
    [
        # one_tape, robot alone, the human waits throughout (idle = the cycle, weight 0.05):
        # throw 2 s: 2 + 0.05*2 = 2.1, then the completing wait 1 + 0.05 = 1.05 -> 3.15
        (2, 0, "throw(tape)", 3.15),
        (2, 1, "goto(bin)", 3.15 + 3.15),  # goto 3 s: 3 + 0.05*3
        (0, 1, "pick(tape)", 6.3 + 2.1),  # pick 2 s
        (0, 0, "goto(tape)", 8.4 + 3.15),  # the plan's whole cost, 11.55 (worked above)
    ],
)
def test_bound_at_each_step_of_the_plan_is_its_exact_cost_to_go(
    tmp_path: Path, where: int, at: int, action: str, to_go: float
) -> None:
    # With nothing to wait for, the relaxation is exact: the bound through the plan's next
    # robot action equals the cost still to pay, cycle by cycle as worked above.
    planner = Planner(world(tmp_path, ONE_TAPE))
    names = planner.world.action_names[Agent.ROBOT]
    edges = {names[edge.action]: edge.h for edge in planner.space.robot_edges(State((where,), at))}
    assert edges[action] == pytest.approx(to_go)


def test_handover_when_idling_costs_more_than_working(tmp_path: Path) -> None:
    # idle weight 0.5 above the effort weight 0.1 (the bound's other branch, b < 0); the same
    # plan stays optimal: time 11.5, effort 3, idle 8.5 -> 11.5 + 0.1*3 + 0.5*8.5 = 16.05
    weights = CostWeights(time=1.0, human_effort=0.1, effort_balance=0.0, human_idle=0.5, human_holding=0.0)
    planner = Planner(world(tmp_path, HANDOVER), PlannerConfig(weights=weights))
    result = planner.plan(State((0,), 0))
    assert result.cost == pytest.approx(16.05)
    assert result.breakdown == pytest.approx(
        {"time": 11.5, "human_effort": 0.3, "effort_balance": 0.0, "human_idle": 4.25, "human_holding": 0.0}
    )
    assert planner.space.bound(State((0,), 0)) <= 16.05 + 1e-9


def test_relabel_groups_only_objects_that_share_their_bins(tmp_path: Path) -> None:
    # paper2015: the three tapes all go to the one trashbin, so they form one class;
    # one_tape: a lone object has no partner, so nothing is relabelled (states already canonical)
    paper = Relabel(World("paper2015"))
    assert paper.classes == ((0, 1, 2),) and paper.active
    lone = Relabel(world(tmp_path, ONE_TAPE))
    assert lone.classes == () and not lone.active


def test_relabel_maps_actions_back_to_the_original_objects() -> None:
    # paper2015 robot actions 0, 1, 2 are pick(tape1), pick(tape2), pick(tape3).
    # orig = (2, 0, 1): canonical object 0 stands for tape3, 1 for tape1, 2 for tape2.
    w = World("paper2015")
    relabel = Relabel(w)
    orig = (2, 0, 1)
    pick = [w.index(Agent.ROBOT, Action(Kind.PICK, o)) for o in range(3)]
    assert [relabel.action_back(Agent.ROBOT, pick[o], orig) for o in range(3)] == [pick[2], pick[0], pick[1]]
    assert relabel.action_back(Agent.ROBOT, -1, orig) == -1  # "no action" stays "no action"


@pytest.mark.parametrize("weight", ["time", "human_effort", "effort_balance", "human_idle", "human_holding"])
@pytest.mark.parametrize("value", [float("nan"), float("inf")])
def test_a_cost_weight_that_is_not_a_finite_number_is_refused(weight: str, value: float) -> None:
    # NaN is neither below nor at 0, so the sign checks alone let it through and every plan
    # would cost NaN (no plan better than another); infinity makes every plan cost the same.
    with pytest.raises(ValueError, match=rf"^CostWeights\.{weight} must be a finite number, got {value}$"):
        CostWeights(**{weight: value})


@pytest.mark.parametrize("weight", ["time", "human_effort", "effort_balance", "human_idle", "human_holding"])
def test_a_cost_weight_over_a_million_per_second_is_refused(weight: str) -> None:
    # 1e308 per second of time made every plan's cost overflow to infinity, the bound's mark
    # of a dead end: the planner answered "no plan" for every table; 1e6 itself is accepted
    assert getattr(CostWeights(**{weight: 1e6}), weight) == 1e6
    with pytest.raises(ValueError, match=rf"^CostWeights\.{weight} must be at most 1e\+06 per second, got 1e\+308$"):
        CostWeights(**{weight: 1e308})
