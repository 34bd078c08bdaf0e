"""The compiled planner robot of the human's batched seat: its plans, the AEC replay, the stall rule, pickling."""

from __future__ import annotations

import pickle
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from hg_marl.agents.compiled import CompileError
from hg_marl.agents.compiled_robot import CompiledRobot, compile_robot
from hg_marl.agents.planner import Planner
from hg_marl.agents.views import LiveRobots, human_vector_env
from hg_marl.core import Agent, State, World
from hg_marl.envs.batched import BatchedRules, BatchState
from hg_marl.envs.table_cleaning import raw_env

K = 12
"""The stall rule's K as the docstring states it (the progress guard's K, agents/progress.py)."""

SCENARIOS = ["paper2015", "generated:objects=2,seed=4,human_only=0.8"]
_WORLDS: dict[str, World] = {}


def world_of(name: str) -> World:
    if name not in _WORLDS:
        _WORLDS[name] = World(name)
    return _WORLDS[name]


@pytest.fixture(scope="module")
def cache(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """One folder for the module: each scenario's robot is compiled once, then loaded."""
    return tmp_path_factory.mktemp("robots")


def fresh_proposal(world: World, state: State) -> int:
    """A new planner's proposal: the plan's first robot action, ``wait`` when no plan is found."""
    result = Planner(world).plan(state, to_move=Agent.ROBOT)
    return int(result.robot_action) if result.success else world.n_actions(Agent.ROBOT) - 1


def stall_option(world: World, state: State, taken: int) -> int:
    """The rule's stall move: the (taken mod n)-th feasible non-wait action, wait if there is none."""
    wait = world.n_actions(Agent.ROBOT) - 1
    options = [int(a) for a in np.flatnonzero(world.mask(state, Agent.ROBOT)) if a != wait]
    return options[taken % len(options)] if options else wait


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_the_compiled_action_is_a_fresh_planners_proposal_on_sampled_states(scenario: str, cache: Path) -> None:
    """300 robot-turn states from random walks (any action of either agent): table == new planner."""
    world = world_of(scenario)
    robot = compile_robot(world, cache=cache)
    rules = BatchedRules(world)
    rng = np.random.default_rng(7)
    walk = rules.initial(rng, 30)
    states: list[State] = []
    for t in range(20):
        for agent in (Agent.ROBOT, Agent.HUMAN):
            if agent is Agent.ROBOT:
                states.extend(walk.state(i) for i in range(30))
            masks = rules.masks(walk, agent)
            acts = (rng.random(masks.shape) * masks).argmax(1)
            rules.step(walk, agent, acts)
        if t % 5 == 4:
            walk = rules.initial(rng, 30)
    states = states[::2]
    got, found = robot.plan(BatchState.of(states))
    assert found.all() and robot.fallbacks == 0
    for i, s in enumerate(states):
        assert got[i] == fresh_proposal(world, s), s
    reloaded = compile_robot(world, cache=cache)  # loaded from the folder: same arrays
    assert (reloaded.keys == robot.keys).all() and (reloaded.actions == robot.actions).all()
    assert len(list(cache.glob(f"{scenario.split(':')[0]}-robot-*.npz"))) == 1


def test_a_state_outside_the_table_is_planned_live_and_counted() -> None:
    world = world_of("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    robot = CompiledRobot(world, {"keys": np.zeros(0, np.int64), "actions": np.zeros(0, np.int64)})
    got, found = robot.plan(BatchState.of([state]))
    assert not found[0] and robot.fallbacks == 1 and got[0] == fresh_proposal(world, state)


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    scenario=st.sampled_from(SCENARIOS),
    seed=st.integers(0, 2**31),
    max_cycles=st.integers(2, 30),
    p_wait=st.sampled_from([0.0, 0.7]),
)
def test_human_seat_with_the_compiled_planner_equals_the_aec_env(
    scenario: str, seed: int, max_cycles: int, p_wait: float, cache: Path
) -> None:
    """The AEC env replays the recorded robot moves; each is a fresh planner's unless the stall rule fired.

    The stall rule is tracked here from the AEC env's own states: after K robot turns in a
    row with the state unchanged, the move is the rule's option.
    """
    n = 4
    world = world_of(scenario)
    env = human_vector_env(num_envs=n, scenario=world.scenario, max_cycles=max_cycles, cache=cache)
    rng = np.random.default_rng(seed)
    starts = [world.initial_state(rng) for _ in range(n)]
    obs, info = env.reset(seed=seed, options={"states": starts})
    aecs, prev, unchanged, stalls = [], list(starts), [0] * n, [0] * n
    for i in range(n):
        assert info["robot_action"][i] == fresh_proposal(world, starts[i])
        aec = raw_env(scenario=world.scenario, max_cycles=max_cycles)
        aec.reset(options={"state": starts[i]})
        aec.step(int(info["robot_action"][i]))
        aecs.append(aec)
    ended = np.zeros(n, dtype=bool)
    fired = 0
    for _ in range(40):
        masks = env.action_masks()
        actions = (rng.random(masks.shape) * masks).argmax(1)
        actions = np.where(rng.random(n) < p_wait, world.n_actions(Agent.HUMAN) - 1, actions)
        obs, reward, term, trunc, info = env.step(actions)
        for i, aec in enumerate(aecs):
            if ended[i]:
                continue
            aec.step(int(actions[i]))
            done, cut = aec.terminations["human"], aec.truncations["human"]
            task = 0.0
            if not (done or cut):
                state = aec.world_state
                unchanged[i] = unchanged[i] + 1 if state == prev[i] else 0
                prev[i] = state
                if unchanged[i] >= K:
                    expected = stall_option(world, state, stalls[i])
                    stalls[i] += expected != world.n_actions(Agent.ROBOT) - 1
                    fired += 1
                else:
                    expected = fresh_proposal(world, state)
                assert info["robot_action"][i] == expected
                aec.step(int(info["robot_action"][i]))
                task = aec.rewards["human"]
                done = task > 0
            assert reward[i] == task and (term[i], trunc[i]) == (done, cut)
            assert info["clock"][i] == aec.clock and info["tasks_solved"][i] == aec.tasks_solved
            if not (done or cut):
                assert (obs[i] == aec.observe("human")["observation"]).all()
            ended[i] = done or cut
        if ended.all():
            break
    assert env.partner.fallbacks == 0


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_a_human_who_only_waits_never_leaves_the_robot_waiting_forever(scenario: str, cache: Path) -> None:
    """K unchanged turns in a row end in the rule's (non-wait) move: never K+1 waits on an unchanged table.

    Each robot-turn state is rebuilt here with the rules from the start and both seats' moves.
    """
    n = 16
    world = world_of(scenario)
    wait_r, wait_h = world.n_actions(Agent.ROBOT) - 1, world.n_actions(Agent.HUMAN) - 1
    env = human_vector_env(num_envs=n, scenario=world.scenario, max_cycles=None, cache=cache)
    rules = BatchedRules(world)
    rng = np.random.default_rng(3)
    starts = [world.initial_state(rng) for _ in range(n)]
    _, info = env.reset(seed=3, options={"states": starts})
    walk = BatchState.of(starts)
    rules.step(walk, Agent.ROBOT, info["robot_action"])
    last: list[State] = list(starts)
    unchanged, stalls, waits = [0] * n, [0] * n, [0] * n
    alive = np.ones(n, dtype=bool)
    fired = 0
    for _ in range(6 * (K + 1)):
        rules.step(walk, Agent.HUMAN, np.full(n, wait_h))
        _, _, term, trunc, info = env.step(np.full(n, wait_h))
        assert not trunc.any()
        alive &= ~term  # a robot that solves the table alone ends its episode: nothing left to check
        acts = info["robot_action"]
        for i in np.flatnonzero(alive):
            state = walk.state(i)
            unchanged[i] = unchanged[i] + 1 if state == last[i] else 0
            last[i] = state
            if unchanged[i] >= K:
                assert acts[i] == stall_option(world, state, stalls[i])
                stalls[i] += acts[i] != wait_r
                fired += 1
            waits[i] = waits[i] + 1 if (acts[i] == wait_r and unchanged[i] > 0) else 0
            assert waits[i] < K + 1 or not any(np.flatnonzero(world.mask(state, Agent.ROBOT)) != wait_r), (
                f"table {i} waited {waits[i]} unchanged cycles in a row"
            )
        rules.step(walk, Agent.ROBOT, acts)
        assert (walk.where[alive] == env.state.where[alive]).all()
        assert (walk.robot_at[alive] == env.state.robot_at[alive]).all()
    assert fired > 0, "no stall: the test saw no waiting robot"


def test_the_human_seat_pickles_mid_episode_with_the_compiled_planner(cache: Path) -> None:
    env = human_vector_env(num_envs=4, cache=cache)
    assert isinstance(env.partner, CompiledRobot)
    env.reset(seed=0)
    wait = np.full(4, env.world.n_actions(Agent.HUMAN) - 1)
    for _ in range(3):
        env.step(wait)
    copy = pickle.loads(pickle.dumps(env))
    for _ in range(6):
        a, b = env.step(wait), copy.step(wait)
        assert (a[0] == b[0]).all() and (a[1] == b[1]).all() and (a[4]["robot_action"] == b[4]["robot_action"]).all()
    assert (env.partner.unchanged == copy.partner.unchanged).all()


def test_compiled_false_and_other_robots_stay_live(cache: Path) -> None:
    assert isinstance(human_vector_env(num_envs=2, compiled=False).partner, LiveRobots)
    assert isinstance(human_vector_env(num_envs=2, robot="random", cache=cache).partner, LiveRobots)
    with pytest.raises(CompileError, match="robot"):
        compile_robot(world_of("paper2015"), "random", cache=None)
    with pytest.raises(CompileError, match="max_states"):
        compile_robot(world_of("paper2015"), cache=None, max_states=10)


def test_a_state_that_never_changes_gets_the_planner_k_times_then_each_option_in_turn(cache: Path) -> None:
    """The rule on one frozen table: turns 1..K the planner's move, then options 0, 1, 2, ... of the mask."""
    world = world_of("paper2015")
    robot = compile_robot(world, cache=cache)
    state = world.initial_state(np.random.default_rng(11))
    wait = world.n_actions(Agent.ROBOT) - 1
    options = [int(a) for a in np.flatnonzero(world.mask(state, Agent.ROBOT)) if a != wait]
    assert len(options) >= 2
    robot.reset_rows(np.array([0]), np.random.default_rng(0))
    got = [int(robot.act(BatchState.of([state]), np.array([-1]), np.random.default_rng(0))[0]) for _ in range(K + 5)]
    planned = fresh_proposal(world, state)
    assert got[:K] == [planned] * K
    assert got[K:] == [options[j % len(options)] for j in range(5)]
    robot.reset_rows(np.array([0]), np.random.default_rng(0))  # a reset forgets the count and the rotation
    assert int(robot.act(BatchState.of([state]), np.array([-1]), np.random.default_rng(0))[0]) == planned


def test_a_scenario_over_the_budget_keeps_live_robots_with_a_warning(
    caplog: pytest.LogCaptureFixture, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A budget of 10 cold plans (paper2015: 328 states up to relabelling): refused, live robots."""
    from hg_marl.agents import compiled_robot

    monkeypatch.setitem(compiled_robot.compile_robot.__kwdefaults__, "max_states", 10)
    with caplog.at_level("WARNING"):
        env = human_vector_env(num_envs=2, scenario="paper2015", cache=None)
    assert isinstance(env.partner, LiveRobots)
    assert "328 up to relabelling" in caplog.text and "(max_states)" in caplog.text
