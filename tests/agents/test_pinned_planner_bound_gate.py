"""The planner's bound with a short move (0.5 s), pinned for the mutation gate.

Worked by hand as in tests/agents/test_planner_hand.py (the one-tape scenario, robot
alone, the human waits: idle weight 0.05, so each cycle of d seconds costs 1.05 d), with
``goto = 0.5`` s: pick 2 s -> 2.1, goto(bin) 0.5 s -> 0.525, throw 2 s -> 2.1, the
completing wait 1 s -> 1.05. The handover is at the bin's side, so at the table only the
tape's own spot saves the empty-handed move. With nothing to wait for the relaxation is exact, also when
a saved empty-handed move is worth less than a second.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.planner import CostWeights, Planner, PlannerConfig
from hg_marl.core import Agent, State, World
from tests.agents.test_planner_hand import DURATIONS, ONE_TAPE


@pytest.mark.parametrize(
    ("where", "at", "action", "to_go"),
    [
        (2, 0, "throw(tape)", 2.1 + 1.05),
        (2, 1, "goto(bin)", 0.525 + 3.15),
        (0, 1, "pick(tape)", 2.1 + 3.675),
        (0, 0, "goto(tape)", 0.525 + 5.775),
    ],
)
def test_bound_is_the_exact_cost_to_go_with_a_half_second_move(
    tmp_path: Path, where: int, at: int, action: str, to_go: float
) -> None:
    path = tmp_path / "layout.toml"
    text = ONE_TAPE.replace('handover_locations = ["table"]', 'handover_locations = ["bin_side"]')
    path.write_text(text + DURATIONS.replace("goto = 3.0", "goto = 0.5"))
    planner = Planner(World(str(path)))
    assert planner.world.durations.goto == 0.5
    names = planner.world.action_names[Agent.ROBOT]
    edges = {names[edge.action]: edge.h for edge in planner.space.robot_edges(State((where,), at))}
    assert edges[action] == pytest.approx(to_go)


def test_the_humans_holding_weight_raises_the_bound_where_every_method_has_the_human_hold() -> None:
    # every term of the bound is a nonnegative weight times a nonnegative work, so the bound
    # cannot fall as the holding weight grows; it rises where some object can only be
    # disposed of by the human carrying it (paper2015: the objects out of the robot's reach)
    world = World("paper2015")
    light = Planner(world, PlannerConfig(weights=CostWeights(human_holding=0.0))).space
    heavy = Planner(world, PlannerConfig(weights=CostWeights(human_holding=1.0))).space
    rng = np.random.default_rng(0)
    rose = 0
    for _ in range(40):
        state = world.initial_state(rng)
        low, high = light.bound(state), heavy.bound(state)
        assert high >= low, state
        rose += high > low
    assert rose > 0


@pytest.mark.parametrize(
    ("memo", "fill"),
    [
        ("_sums", lambda space, s: space._new_sums(s, space.key(s))),
        ("_bound", lambda space, s: space.bound(s)),
        ("_robot_edges", lambda space, s: space.robot_edges(s)),
        ("_human_edges", lambda space, s: space.human_edges(s)),
        ("_allowed", lambda space, s: space.allowed(s)),
        ("_cand", lambda space, s: space.candidates(s, 0)),
    ],
)
def test_each_memo_of_the_space_is_emptied_once_it_holds_more_than_its_limit(
    memo: str, fill: object, monkeypatch: pytest.MonkeyPatch
) -> None:
    """With a limit of 3, a memo grows 1, 2, 3, 4 and the fifth entry finds it over the limit:
    emptied, it holds that entry alone (a cleared entry is computed again, to the same value)."""
    from hg_marl.agents.planner import space as module

    monkeypatch.setattr(module, "_CACHE_LIMIT", 3)
    world = World("paper2015")
    space = Planner(world).space
    where = world.initial_state(np.random.default_rng(0)).where
    states = [State(where, at) for at in range(len(world.scenario.robot_locations))]
    states += [State(where, 0, 0, 0)]  # the robot offering object 0
    assert len({space.key(s) for s in states}) == len(states) >= 5
    sizes = []
    for state in states[:5]:
        fill(space, state)  # type: ignore[operator]
        table = getattr(space, memo)
        sizes.append(len(table[0]) if memo == "_cand" else len(table))
    assert sizes == [1, 2, 3, 4, 1]


def test_an_offered_objects_status_names_who_offers_it() -> None:
    world = World("paper2015")
    space = Planner(world).space
    where = world.initial_state(np.random.default_rng(0)).where
    d = space.domain
    assert space.statuses(State(where, 0, 0, 1))[1] == d.robot_offer
    assert space.statuses(State(where, 0, 1, 1))[1] == d.human_offer
    assert space.statuses(State(where, 0)) == list(where)


@pytest.mark.parametrize("scenario", ["paper2015", "roboergosum", "generated:objects=8,bins=2"])
def test_candidates_keep_one_move_per_interchangeable_choice_and_a_goto_per_destination(scenario: str) -> None:
    """Stated from the symmetry's definition: two picks of objects of one bin class from
    places of one code are one choice, as are two placements of one object on spots of one
    class; every destination the rule table gives a goto (to an object's place, a bin or the
    human) is reached by exactly one candidate goto, the first of the gotos there by index."""
    world = World(scenario)
    space = Planner(world).space
    table = world.table
    rng = np.random.default_rng(5)
    checked = 0
    for seed in range(6):
        state = world.initial_state(np.random.default_rng(seed))
        for _ in range(25):
            for agent in (0, 1):
                cands = space.candidates(state, agent)
                feasible = [int(a) for a in world.feasible_indices(state, Agent(agent))]
                assert set(cands) <= set(feasible)
                picks: dict[object, list[int]] = {}
                for a in feasible:
                    kind, o, _, _ = table.specs[agent][a]
                    if kind.name == "PICK":
                        picks.setdefault((space.object_class[o], space.place_code[state.where[o]]), []).append(a)
                for same in picks.values():
                    chosen = [a for a in same if a in cands]
                    assert len(chosen) <= 1, (state, same, cands)
                if agent == 0:
                    gotos = [a for a in cands if table.specs[0][a][0].name == "GOTO"]
                    dests = [table.successor(state, Agent.ROBOT, a)[0].robot_at for a in gotos]
                    expected = {table.goto_obj[state.robot_at][p] for p in state.where} | set(
                        table.goto_static[state.robot_at]
                    )
                    expected.discard(-1)
                    assert sorted(dests) == sorted(expected), (state, dests, expected)
                    for a, dest in zip(gotos, dests, strict=True):  # the first goto there, by index
                        same = [
                            b
                            for b in feasible
                            if table.specs[0][b][0].name == "GOTO"
                            and table.successor(state, Agent.ROBOT, b)[0].robot_at == dest
                        ]
                        assert a == min(same), (state, a, same)
                checked += 1
            acts = world.feasible_indices(state, Agent.ROBOT)
            state = table.successor(state, Agent.ROBOT, int(rng.choice(acts)))[0]
            acts = world.feasible_indices(state, Agent.HUMAN)
            state = table.successor(state, Agent.HUMAN, int(rng.choice(acts)))[0]
    assert checked > 100


@pytest.mark.parametrize("scenario", ["paper2015", "roboergosum"])
def test_the_bound_gives_back_an_empty_move_only_where_the_robot_stands_by_a_spot_that_costs_one(
    scenario: str,
) -> None:
    """The module's rule: the robot's first acquisition may save one empty-handed trip, so a
    spot counts where reaching it costs one (``empty_move > 0``) and the robot stands where it
    can pick from it."""
    space = Planner(World(scenario)).space
    d = space.domain
    for at, (_, spots) in enumerate(space.saves_at):
        assert spots == tuple(d.empty_move[s] > 0.0 and at in locs for s, locs in enumerate(d.spot_locs))
    flags = [flag for _, spots in space.saves_at for flag in spots]
    if scenario == "paper2015":  # some spots count, others not (roboergosum: none costs a move)
        assert any(flags) and not all(flags)


def test_the_bound_stays_admissible_when_idling_costs_more_than_working() -> None:
    """With the idle weight above the effort weight (``b < 0`` in ``Space``), the bound at
    every state of seeded walks is at most the optimal cost the search finds from it (the
    bound's defining property, checked against the search rather than worked by hand)."""
    weights = CostWeights(time=1.0, human_effort=0.1, effort_balance=0.0, human_idle=0.5, human_holding=0.0)
    checked = 0
    for name in ("paper2015", "generated:objects=4,human_only=0.8,seed=1"):
        world = World(name)
        planner = Planner(world, PlannerConfig(weights=weights))
        rng = np.random.default_rng(0)
        for _ in range(2):
            state = world.initial_state(rng)
            for _ in range(10):
                result = planner.plan(state)
                if result.success:
                    assert planner.space.bound(state) <= result.cost + 1e-9, state
                    checked += 1
                for agent in Agent:
                    acts = world.feasible_indices(state, agent)
                    state = world.step(state, agent, int(rng.choice(acts))).state
    assert checked >= 20
