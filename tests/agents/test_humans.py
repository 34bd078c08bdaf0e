"""Humans: registry, behaviour on hand-built states, schedules, round trips, seeding."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.humans import (
    HumanError,
    TraceRecorder,
    available_humans,
    behaviour_table,
    make_human,
    read_trace,
    save_learned_policy,
)
from hg_marl.agents.humans.learned import LearnedHuman
from hg_marl.agents.humans.switching import SwitchingHuman
from hg_marl.agents.models.python_model import PythonModel
from hg_marl.agents.oracle import layout_distribution
from hg_marl.agents.robots import make_robot
from hg_marl.agents.views import RobotView
from hg_marl.core import Action, Agent, Kind, State, World
from hg_marl.core.errors import ModelFileError
from hg_marl.policy import Turn

PAPER = World("paper2015")
ROBO = World("roboergosum")


def turn_at(world: World, state: State, clock: float = 0.0, tasks: int = 0) -> Turn:
    obs = {"observation": world.facts(state), "action_mask": world.mask(state, Agent.HUMAN)}
    return Turn(world, state, Agent.HUMAN, obs, clock=clock, tasks_solved=tasks)


def kinds(world: World, dist: list[tuple[int, float]]) -> set[Kind]:
    return {world.actions(Agent.HUMAN)[i].kind for i, p in dist if p > 0}


def many_states(world: World) -> list[State]:
    """Every robot-turn and mid-cycle state a random robot and random human can reach."""
    model = PythonModel(world, make_human("random"), failed_actions=False, max_states=50_000)
    model.build([s for s, _ in layout_distribution(world)])
    mids = [
        world.apply(s, Agent.ROBOT, world.actions(Agent.ROBOT)[a]).state
        for s in model.states
        for a in world.feasible_indices(s, Agent.ROBOT)
    ]
    return model.states + mids


STATES = many_states(PAPER)


# ---- registry ----------------------------------------------------------------------
def test_registry_lists_every_human_with_documented_params() -> None:
    humans = available_humans()
    assert set(humans) == {
        "cooperative",
        "lazy",
        "no_handover",
        "adversarial",
        "random",
        "noisy",
        "preference",
        "switching",
        "learned",
        "replay",
        # the family-out partners (docs/adaptation.md): registered, kept out of recipes
        "fo_freeze_on_offer",
        "fo_after_waits",
        "fo_mirror",
        "fo_bursts",
        "fo_picky",
        "fo_forgetful",
        "fo_shy",
        "fo_slow_start",
    }
    for spec in humans.values():
        assert spec["doc"]
        for default_and_doc in spec["params"].values():
            assert isinstance(default_and_doc[1], str) and default_and_doc[1]


def test_unknown_name_and_bad_params_are_clear() -> None:
    with pytest.raises(HumanError, match="available: cooperative"):
        make_human("grumpy")
    with pytest.raises(HumanError, match=r"no parameter 'speed'.*p_idle"):
        make_human("lazy", speed=2)
    with pytest.raises(HumanError, match="probability"):
        make_human("lazy", p_idle=1.5)
    with pytest.raises(HumanError, match="p_idle': expected a finite number, got 'often'"):
        make_human("lazy:p_idle=often")
    with pytest.raises(HumanError, match="p_idle': expected a finite number"):
        make_human("lazy:p_idle=NaN")
    with pytest.raises(HumanError, match="feasible_only': expected true or false, got 'no'"):
        make_human("random:feasible_only=no")
    assert make_human("lazy:p_idle=0.25").p_idle == 0.25  # type: ignore[attr-defined]


# ---- behaviour on hand-built states ------------------------------------------------------
def test_lazy_never_reaches_outside_its_area_nor_takes() -> None:
    lazy = make_human("lazy", p_idle=0.0)
    area = {s for s, spot in enumerate(PAPER.scenario.spots) if spot.reach.human}
    for state in STATES:
        for index, _ in lazy.distribution(PAPER, state):  # type: ignore[attr-defined]
            action = PAPER.actions(Agent.HUMAN)[index]
            assert action.kind is not Kind.TAKE
            if action.kind is Kind.PICK:
                assert state.where[action.obj] in area
            if action.kind is Kind.PLACE:
                assert action.target in area


def test_lazy_idles_with_its_probability() -> None:
    tape_on_human_mat = State((0, 1, 4), 0)
    dist = dict(make_human("lazy", p_idle=0.3).distribution(PAPER, tape_on_human_mat))  # type: ignore[attr-defined]
    assert dist[PAPER.index(Agent.HUMAN, Action(Kind.WAIT))] == pytest.approx(0.3)
    assert dist[PAPER.index(Agent.HUMAN, Action(Kind.PICK, 2))] == pytest.approx(0.7)


@pytest.mark.parametrize("world", [PAPER, ROBO], ids=["paper2015", "roboergosum"])
def test_no_handover_never_gives_or_takes(world: World) -> None:
    human = make_human("no_handover")
    states = STATES if world is PAPER else [s for s, _ in layout_distribution(world)][:500]
    for state in states:
        assert not kinds(world, human.distribution(world, state)) & {Kind.GIVE, Kind.TAKE}  # type: ignore[attr-defined]
    offering = State((PAPER.hand[Agent.ROBOT], 1, 4), 3, int(Agent.ROBOT), 0)  # robot offers tape1
    assert kinds(PAPER, human.distribution(PAPER, offering)) & {Kind.TAKE} == set()  # type: ignore[attr-defined]


def test_no_handover_moves_a_tape_within_robot_reach() -> None:
    human = make_human("no_handover")
    holding = State((0, 1, PAPER.hand[Agent.HUMAN]), 0)
    ((index, _),) = human.distribution(PAPER, holding)  # type: ignore[attr-defined]
    assert PAPER.action_names[Agent.HUMAN][index] == "place(tape3,mat_shared)"


def test_adversarial_never_fills_a_bin_and_hides_objects() -> None:
    human = make_human("adversarial")
    for world, states in ((PAPER, STATES), (ROBO, [s for s, _ in layout_distribution(ROBO)][:500])):
        for state in states:
            assert not kinds(world, human.distribution(world, state)) & {Kind.THROW, Kind.TAKE, Kind.GIVE}  # type: ignore[attr-defined]
    on_shared = State((0, 1, 3), 3)  # tape3 on mat_shared, robot next to it
    ((index, _),) = human.distribution(PAPER, on_shared)  # type: ignore[attr-defined]
    assert PAPER.action_names[Agent.HUMAN][index] == "pick(tape3)"
    ((index, _),) = human.distribution(PAPER, State((0, 1, PAPER.hand[1]), 3))  # type: ignore[attr-defined]
    assert PAPER.action_names[Agent.HUMAN][index].startswith("place(tape3,human_mat")


def test_cooperative_takes_what_the_robot_offers() -> None:
    offering = State((PAPER.hand[Agent.ROBOT], 1, 4), 3, int(Agent.ROBOT), 0)
    ((index, p),) = make_human("cooperative").distribution(PAPER, offering)  # type: ignore[attr-defined]
    assert PAPER.action_names[Agent.HUMAN][index] == "take(tape1)" and p == 1.0


def test_random_is_uniform_over_feasible() -> None:
    state = State((0, 1, 4), 0)
    dist = make_human("random").distribution(PAPER, state)  # type: ignore[attr-defined]
    assert [i for i, _ in dist] == PAPER.feasible_indices(state, Agent.HUMAN)
    assert sum(p for _, p in dist) == pytest.approx(1.0)


def test_noisy_is_cooperative_at_zero_temperature_and_spreads_when_hot() -> None:
    state = State((0, 1, 4), 0)
    cold = make_human("noisy", temperature=0.0).distribution(PAPER, state)  # type: ignore[attr-defined]
    assert cold == make_human("cooperative").distribution(PAPER, state)  # type: ignore[attr-defined]
    hot = make_human("noisy", temperature=1000.0).distribution(PAPER, state)  # type: ignore[attr-defined]
    assert len(hot) == len(PAPER.feasible_indices(state, Agent.HUMAN))


def test_cooperative_and_planner_robot_clean_paper2015_in_predicted_time() -> None:
    from hg_marl.agents.planner import Planner

    for seed in range(3):
        view = RobotView("paper2015", human="cooperative")
        view.reset(seed=seed)
        predicted = Planner(view.world).plan(view.env.world_state).plan.duration  # type: ignore[union-attr]
        robot = make_robot("planner")
        robot.reset(view.world, Agent.ROBOT, np.random.default_rng(0))
        done = False
        while not done:
            _, _, done, truncated, info = view.step(robot.act(view.env.turn("robot")))
            assert not truncated
        assert info["tasks_solved"] == 1
        assert info["clock"] == pytest.approx(predicted)


# ---- switching ----------------------------------------------------------------------
@pytest.mark.parametrize(
    ("by", "at", "cases"),
    [("time", 30.0, [(0, 0), (29.9, 0), (30.0, 1), (100, 1)]), ("tasks", 2, [(0, 0), (1, 0), (2, 1), (5, 1)])],
)
def test_switching_switches_at_the_scheduled_point(by: str, at: float, cases: list[tuple[float, int]]) -> None:
    human = SwitchingHuman(["cooperative", "adversarial"], at=[at], by=by)
    human.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    state = State((0, 1, 3), 3)
    for value, phase in cases:
        turn = turn_at(PAPER, state, clock=value) if by == "time" else turn_at(PAPER, state, tasks=int(value))
        human.act(turn)
        assert human.phase == phase, (value, human.phase)
        assert human.last_decision["human"] == ("cooperative", "adversarial")[phase]


def test_switching_in_a_run_stops_cooperating_after_the_first_task() -> None:
    human = make_human("switching", humans=["cooperative", "adversarial"], at=[1], by="tasks")
    view = RobotView("paper2015", human=human, continuing=True, max_cycles=400)
    view.reset(seed=0)
    robot = make_robot("planner")
    robot.reset(view.world, Agent.ROBOT, np.random.default_rng(0))
    done = False
    while not done:
        _, _, term, trunc, info = view.step(robot.act(view.env.turn("robot")))
        done = term or trunc
    assert info["tasks_solved"] == 1 and human.phase == 1  # type: ignore[attr-defined]


def test_switching_rejects_bad_schedules() -> None:
    with pytest.raises(HumanError, match="one threshold fewer"):
        make_human("switching", humans=["lazy", "cooperative"], at=[])
    with pytest.raises(HumanError, match="'time' or 'tasks'"):
        make_human("switching", by="cycles")


# ---- learned and replay round trips -------------------------------------------------------
def play(human: object, seed: int, steps: int = 60) -> tuple[list[int], list[bytes]]:
    """Human actions and robot observations of a seeded run against the random robot."""
    view = RobotView("paper2015", human=human)  # type: ignore[arg-type]
    obs, _ = view.reset(seed=seed)
    robot_rng = np.random.default_rng(seed)
    actions, observations = [], [obs.tobytes()]
    for _ in range(steps):
        mask = view.action_masks()
        obs, _, done, truncated, info = view.step(int(robot_rng.choice(np.flatnonzero(mask))))
        actions.append(info["human_action"])
        observations.append(obs.tobytes())
        if done or truncated:
            obs, _ = view.reset()
    return actions, observations


def test_learned_linear_round_trip(tmp_path: Path) -> None:
    rng = np.random.default_rng(1)
    w = rng.normal(size=(PAPER.n_actions(Agent.HUMAN), PAPER.n_facts))
    save_learned_policy(tmp_path / "lin", PAPER, weights=w, temperature=0.5)
    human = make_human("learned", path=str(tmp_path / "lin"))
    human.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    for state in STATES[:200]:
        logits = np.where(PAPER.mask(state, Agent.HUMAN) > 0, w @ PAPER.facts(state) / 0.5, -np.inf)
        p = np.exp(logits - logits.max())
        dist = dict(human.distribution(PAPER, state))  # type: ignore[attr-defined]
        assert np.allclose([dist.get(i, 0.0) for i in range(len(p))], p / p.sum())
    assert play(make_human("learned", path=str(tmp_path / "lin")), 4) == play(
        make_human("learned", path=str(tmp_path / "lin")), 4
    )


def test_learned_table_round_trip(tmp_path: Path) -> None:
    table = {PAPER.facts(s).tobytes(): PAPER.feasible_indices(s, Agent.HUMAN)[0] for s in STATES[:300]}
    save_learned_policy(tmp_path / "tab", "paper2015", table=table)
    human = make_human("learned", path=str(tmp_path / "tab" / "policy.json"), deterministic=True)
    human.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    for state in STATES[:300]:
        assert human.act(turn_at(PAPER, state)) == table[PAPER.facts(state).tobytes()]


def test_learned_rejects_another_scenario(tmp_path: Path) -> None:
    save_learned_policy(tmp_path / "p", PAPER, weights=np.zeros((PAPER.n_actions(Agent.HUMAN), PAPER.n_facts)))
    with pytest.raises(ValueError, match="differ from 'roboergosum'"):
        make_human("learned", path=str(tmp_path / "p")).reset(ROBO, Agent.HUMAN, np.random.default_rng(0))
    with pytest.raises(ValueError, match=r"no model\.json or policy\.json"):
        make_human("learned", path=str(tmp_path))


def test_replay_round_trip_gives_identical_actions(tmp_path: Path) -> None:
    trace = tmp_path / "noisy.jsonl"
    recorder = TraceRecorder(make_human("random"), trace, seed=7)
    recorded = play(recorder, 7, steps=80)
    recorder.close()
    episodes = read_trace(trace)
    assert episodes[0].header["scenario"] == "paper2015" and episodes[0].header["seat"] == "human"
    step = episodes[0].steps[0]
    assert {"facts", "mask", "action", "action_name", "clock"} <= set(step)
    assert [a for e in episodes for a in e.actions] == recorded[0]
    assert play(make_human("replay", path=str(trace)), 7, steps=80) == recorded


def test_behaviour_cloned_table_reproduces_a_deterministic_human(tmp_path: Path) -> None:
    trace = tmp_path / "nh.jsonl"
    recorder = TraceRecorder(make_human("no_handover"), trace)
    recorded = play(recorder, 5, steps=60)
    recorder.close()
    save_learned_policy(tmp_path / "bc", PAPER, table=behaviour_table(read_trace(trace)))
    assert play(make_human("learned", path=str(tmp_path / "bc")), 5, steps=60) == recorded


def test_replay_detects_divergence(tmp_path: Path) -> None:
    trace = tmp_path / "t.jsonl"
    recorder = TraceRecorder(make_human("random"), trace)
    play(recorder, 1, steps=10)
    recorder.close()
    with pytest.raises(ValueError, match="diverged"):
        play(make_human("replay", path=str(trace)), 2, steps=10)


# ---- seeding -------------------------------------------------------------------------
@pytest.mark.parametrize("name", sorted(available_humans()))
def test_same_seed_same_trajectory(name: str, tmp_path: Path) -> None:
    def build() -> object:
        if name == "learned":
            path = tmp_path / "lin"
            if not path.exists():
                w = np.random.default_rng(0).normal(size=(PAPER.n_actions(Agent.HUMAN), PAPER.n_facts))
                save_learned_policy(path, PAPER, weights=w)
            return make_human("learned", path=str(path))
        if name == "replay":
            path = tmp_path / "t.jsonl"
            if not path.exists():
                recorder = TraceRecorder(make_human("random"), path)
                play(recorder, 3, steps=40)
                recorder.close()
            return make_human("replay", path=str(path))
        if name == "switching":
            return make_human("switching", humans=["random", "noisy"], at=[20.0])
        return make_human(name)

    assert play(build(), 3, steps=40) == play(build(), 3, steps=40)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"weights": "big"}, r"policy\.json: W and b must lie in \[-1e\+06, 1e\+06\]"),
        ({"weights": "nan"}, r"policy\.json: W and b must be finite"),
        ({"weights": "zero", "temperature": 1e4}, r"'temperature': expected a number <= 1000, got 10000\.0"),
        ({"weights": "zero", "temperature": 1e-4}, r"'temperature': expected a number >= 0\.001, got 0\.0001"),
        ({"table": {b"\x02" * 24: 0}}, r"policy\.json: table facts must be 0 or 1"),
        ({"table": {b"\x01" * 5: 0}}, r"table keys must be 24 fact bytes each"),
    ],
)
def test_a_policy_the_reader_would_refuse_is_not_written(
    tmp_path: Path, kwargs: dict[str, object], message: str
) -> None:
    # the reader (LearnedHuman) accepts weights within 1e6, temperatures in [1e-3, 1e3] and
    # facts of 0 and 1 (paper2015 has 24 facts, 31 human actions); a policy outside those used
    # to be written, then refused on load: now it is refused before its folder is made
    shape = (PAPER.n_actions(Agent.HUMAN), PAPER.n_facts)
    arrays = {"big": np.full(shape, 2e6), "nan": np.full(shape, np.nan), "zero": np.zeros(shape)}
    given = {k: arrays[v] if k == "weights" else v for k, v in kwargs.items()}  # type: ignore[index]
    with pytest.raises((ValueError, ModelFileError), match=message):
        save_learned_policy(tmp_path / "p", PAPER, **given)  # type: ignore[arg-type]
    assert not (tmp_path / "p").exists()
    save_learned_policy(tmp_path / "ok", PAPER, weights=np.full(shape, 1e6), temperature=1e3)
    assert LearnedHuman(tmp_path / "ok").name == "learned"  # the bounds themselves are read back
