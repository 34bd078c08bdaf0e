"""The batched table against the AEC environment: identical trajectories, masks, autoreset, partners."""

from __future__ import annotations

import pickle

import gymnasium
import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from hg_marl.agents.compiled import CompileError, compile_human
from hg_marl.agents.humans.registry import make_human
from hg_marl.agents.oracle import layout_distribution
from hg_marl.agents.views import CompiledPopulation, robot_vector_env
from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError
from hg_marl.envs.batched import BatchedRules, BatchedTable
from hg_marl.envs.table_cleaning import raw_env

RULE_SCENARIOS = [
    "paper2015",
    "roboergosum",
    "generated:objects=3,seed=2",
    "generated:objects=3,seed=1,bins=2,locations=3",
    "generated:objects=2,seed=4,human_only=0.8",
]
ENV_SCENARIOS = ["paper2015", "generated:objects=3,seed=2", "generated:objects=2,seed=4,human_only=0.8"]
HUMANS = ["cooperative", "lazy", "no_handover", "adversarial", "random", "noisy", "cooperative:p_idle=0.3"]
POPULATION = "cooperative|lazy|random"
"""A population of three compiled humans (a member per table)."""

_WORLDS: dict[str, World] = {}
_PARTNERS: dict[tuple[str, str], object] = {}


def world_of(name: str) -> World:
    if name not in _WORLDS:
        _WORLDS[name] = World(name)
    return _WORLDS[name]


def partner_of(scenario: str, human: str) -> object:
    key = (scenario, human)
    if key not in _PARTNERS:
        members = [compile_human(world_of(scenario), h, cache=None) for h in human.split("|")]
        _PARTNERS[key] = members[0] if len(members) == 1 else CompiledPopulation(members)
    return _PARTNERS[key]


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(scenario=st.sampled_from(RULE_SCENARIOS), seed=st.integers(0, 2**31), p_feasible=st.floats(0.0, 1.0))
def test_rules_step_every_table_as_world_step(scenario: str, seed: int, p_feasible: float) -> None:
    """Both agents' random actions (feasible with probability p, else any index).

    Same states, oks, durations, rewards, facts and masks as ``World.step``, whichever
    way the step is told what is feasible.
    """
    world = world_of(scenario)
    rules = BatchedRules(world)
    rng = np.random.default_rng(seed)
    batch = rules.initial(rng, 16)
    states = [batch.state(i) for i in range(16)]
    for t in range(40):
        agent = Agent(t % 2)
        masks = rules.masks(batch, agent)
        for i, s in enumerate(states):
            assert (masks[i] == world.mask(s, agent).astype(bool)).all()
        actions = rng.integers(world.n_actions(agent), size=16)
        for i in np.flatnonzero(rng.random(16) < p_feasible):
            actions[i] = rng.choice(np.flatnonzero(masks[i]))
        # each of the three forms: masks computed inside, passed, or the actions' feasibility passed
        given = [{}, {"mask": masks}, {"ok": masks[np.arange(16), actions]}][(t // 2) % 3]
        ok, duration, reward = rules.step(batch, agent, actions, **given)
        for i in range(16):
            out = world.step(states[i], agent, int(actions[i]))
            assert (out.state, out.ok, out.duration, out.reward) == (batch.state(i), ok[i], duration[i], reward[i])
            states[i] = out.state
        facts = rules.facts(batch)
        for i, s in enumerate(states):
            assert (facts[i] == world.compute_facts(s)).all()


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    scenario=st.sampled_from(ENV_SCENARIOS),
    human=st.sampled_from([*HUMANS, POPULATION]),
    seed=st.integers(0, 2**31),
    max_cycles=st.integers(3, 25),
)
@example(scenario="paper2015", human=POPULATION, seed=1, max_cycles=10)
def test_robot_seat_trajectories_equal_the_aec_env(scenario: str, human: str, seed: int, max_cycles: int) -> None:
    """Each table replayed in the AEC env with the same robot action and the human's recorded answer.

    Observations, rewards, terminations, truncations, clock, cycle, tasks, effort and idle
    must be identical, through autoresets (NEXT_STEP: the step after the last returns the
    new table's observation, reward 0), and each human answer must have positive
    probability under the live human's distribution at the AEC state.
    """
    n = 6
    world = world_of(scenario)
    env = BatchedTable(partner_of(scenario, human), n, world, max_cycles=max_cycles)
    lives = [make_human(h) for h in human.split("|")]
    for live in lives:
        live.reset(world, Agent.HUMAN, np.random.default_rng(0))
    obs, _ = env.reset(seed=seed)
    aecs = []
    for i in range(n):
        aec = raw_env(scenario=world.scenario, max_cycles=max_cycles)
        aec.world = world
        aec.reset(options={"state": env.state.state(i)})
        aecs.append(aec)
        assert (obs[i] == aec.observe("robot")["observation"]).all()
    rng = np.random.default_rng(seed)
    pending = np.zeros(n, dtype=bool)
    for _ in range(60):
        masks = env.action_masks()
        actions = np.where(
            rng.random(n) < 0.7, (rng.random(masks.shape) * masks).argmax(1), rng.integers(0, masks.shape[1], n)
        )
        obs, reward, term, trunc, info = env.step(actions)
        for i, aec in enumerate(aecs):
            if pending[i]:  # autoreset step: the new table, nothing else
                assert reward[i] == 0.0 and not term[i] and not trunc[i]
                aec.reset(options={"state": env.state.state(i)})
                assert (obs[i] == aec.observe("robot")["observation"]).all()
                continue
            assert (masks[i] == aec.observe("robot")["action_mask"].astype(bool)).all()
            aec.step(int(actions[i]))
            r = aec.rewards["robot"]
            h = int(info["human_action"][i])
            ok_robot = not aec.infos["robot"]["failed"]
            live = lives[int(env.partner.member[i])] if len(lives) > 1 else lives[0]  # type: ignore[attr-defined]
            seen = int(actions[i]) if ok_robot and live.uses_robot_action else -1
            assert dict(live.distribution(world, aec.world_state, seen)).get(h, 0.0) > 0.0
            aec.step(h)
            r += aec.rewards["robot"]
            assert reward[i] == r
            assert (obs[i] == aec.observe("robot")["observation"]).all()
            assert term[i] == aec.terminations["robot"] and trunc[i] == aec.truncations["robot"]
            ri = aec.infos["robot"]
            assert (info["clock"][i], info["cycle"][i], info["tasks_solved"][i]) == (
                aec.clock,
                aec.cycles,
                aec.tasks_solved,
            )
            assert info["effort"][i] == pytest.approx(ri["effort"], abs=1e-9)
            assert info["idle"][i] == pytest.approx(ri["idle"], abs=1e-9)
            assert info["partner_effort"][i] == pytest.approx(aec.infos["human"]["effort"], abs=1e-9)
            assert info["failed"][i] == ri["failed"] and info["human_failed"][i] == aec.infos["human"]["failed"]
        pending = term | trunc
    assert env.partner.fallbacks == 0  # type: ignore[attr-defined]


@pytest.mark.parametrize("human", HUMANS)
def test_compiled_distribution_equals_the_live_humans(human: str) -> None:
    """On sampled mid-cycle states: the compiled table's distribution is the live human's."""
    world = world_of("paper2015")
    compiled = partner_of("paper2015", human)
    live = make_human(human)
    live.reset(world, Agent.HUMAN, np.random.default_rng(0))
    rules = BatchedRules(world)
    rng = np.random.default_rng(3)
    batch = rules.initial(rng, 32)
    checked = 0
    seen = np.full(32, -1)
    for t in range(30):
        agent = Agent(t % 2)
        masks = rules.masks(batch, agent)
        actions = (rng.random(masks.shape) * masks).argmax(1)
        if agent is Agent.HUMAN:  # the human's own answers keep the tables where it can be
            actions = compiled.act(batch, seen, rng)  # type: ignore[attr-defined]
        ok, _, _ = rules.step(batch, agent, actions)
        if agent is Agent.ROBOT:
            seen = np.where(ok, actions, -1)
            for i in range(0, 32, 4):
                expected = sorted(
                    (a, p)
                    for a, p in live.distribution(world, batch.state(i), int(seen[i]) if live.uses_robot_action else -1)
                    if p > 0
                )
                got = compiled.distribution(batch, seen, i)  # type: ignore[attr-defined]
                assert [a for a, _ in got] == [a for a, _ in expected]
                assert [p for _, p in got] == pytest.approx([p for _, p in expected], abs=1e-12)
                checked += 1
    assert checked == 15 * 8


def test_a_state_outside_the_table_falls_back_to_the_live_human_and_is_counted() -> None:
    world = world_of("paper2015")
    compiled = partner_of("paper2015", "cooperative")
    rules = BatchedRules(world)
    batch = rules.initial(np.random.default_rng(0), 4)
    # an offer by the human to itself's partner never reaches the human's turn: not in the table
    batch.offer_by[:2], batch.offer_obj[:2] = 1, 0
    before = compiled.fallbacks  # type: ignore[attr-defined]
    compiled.act(batch, np.full(4, -1), np.random.default_rng(0))  # type: ignore[attr-defined]
    assert compiled.fallbacks - before == 2  # type: ignore[attr-defined]


def test_initial_states_draw_exactly_the_layout_distribution() -> None:
    world = world_of("paper2015")
    support = {s for s, _ in layout_distribution(world)}
    where, at = world.initial_states(np.random.default_rng(0), 20_000)
    drawn = {(tuple(int(x) for x in w), int(a)) for w, a in zip(where, at, strict=True)}
    assert drawn == {(s.where, s.robot_at) for s in support}


def test_make_vec_reaches_the_batched_env_and_masks_are_an_array() -> None:
    env = gymnasium.make_vec(
        "hg_marl:hg_marl/RobotTableCleaning-v0", num_envs=5, vectorization_mode="vector_entry_point", human="lazy"
    )
    obs, _ = env.reset(seed=0)
    world = World("paper2015")
    assert obs.shape == (5, world.n_facts)
    masks = env.unwrapped.action_masks()
    assert masks.shape == (5, world.n_actions(Agent.ROBOT)) and masks.dtype == bool
    # at a fresh table the robot holds nothing: no throw, give or take; wait always
    n = world.n_objects
    assert not masks[:, n : 4 * n].any() and masks[:, -1].all()


def test_same_step_autoreset_returns_the_new_table_and_keeps_the_final_observation() -> None:
    env = robot_vector_env(num_envs=3, human="cooperative", max_cycles=2, autoreset_mode="same_step", cache=None)
    env.reset(seed=0)
    wait = np.full(3, env.world.n_actions(Agent.ROBOT) - 1)
    env.step(wait)
    obs, _, _, trunc, info = env.step(wait)
    assert trunc.all() and info["_final_obs"].all()
    assert (info["final_info"]["cycle"] == 2).all()
    assert (env.cycles == 0).all()  # the new tables start at cycle 0
    assert (obs == env.rules.facts(env.state)).all()


def test_next_step_autoreset_ignores_the_action_and_restarts() -> None:
    env = robot_vector_env(num_envs=2, human="cooperative", max_cycles=1, cache=None)
    env.reset(seed=0)
    _, _, _, trunc, _ = env.step(np.zeros(2, dtype=int))
    assert trunc.all()
    _, reward, term, trunc, info = env.step(np.zeros(2, dtype=int))
    assert (reward == 0).all() and not term.any() and not trunc.any()
    assert (env.cycles == 0).all() and not info["_clock"].any()


def test_population_draws_a_member_per_table() -> None:
    env = robot_vector_env(num_envs=64, human=["cooperative", "adversarial"], cache=None)
    env.reset(seed=0)
    assert isinstance(env.partner, CompiledPopulation)
    members = set(env.partner.member.tolist())
    assert members == {0, 1}


def test_a_switching_partner_plays_each_tables_phase_from_its_clock() -> None:
    """cooperative until 20 s of an episode, adversarial until 60 s, then cooperative.

    Each table is replayed in the AEC env (autoresets included): at every cycle the member
    that answered must be the phase's, ``bisect_right(at, clock at the cycle's start)``
    (the switching human's own rule, stated here as thresholds), its answer must have
    positive probability under that phase's live human, and observations and clocks stay
    identical.
    """
    import bisect

    at = [20.0, 60.0]
    human = make_human("switching", humans=["cooperative", "adversarial", "cooperative"], at=at)
    n = 6
    env = robot_vector_env(num_envs=n, human=human, cache=None, max_cycles=None)
    world = env.world
    lives = {0: make_human("cooperative"), 1: make_human("adversarial")}
    for live in lives.values():
        live.reset(world, Agent.HUMAN, np.random.default_rng(0))
    obs, _ = env.reset(seed=3)
    aecs = []
    for i in range(n):
        aec = raw_env(scenario=world.scenario, max_cycles=None)
        aec.world = world
        aec.reset(options={"state": env.state.state(i)})
        aecs.append(aec)
    rng = np.random.default_rng(3)
    phases_seen = set()
    pending = np.zeros(n, dtype=bool)
    for _ in range(150):
        masks = env.action_masks()
        actions = (rng.random(masks.shape) * masks).argmax(1)
        start = [aec.clock for aec in aecs]
        obs, _, term, trunc, info = env.step(actions)
        for i, aec in enumerate(aecs):
            if pending[i]:  # autoreset step: the new table
                aec.reset(options={"state": env.state.state(i)})
                continue
            phase = bisect.bisect_right(at, start[i])
            phases_seen.add(phase)
            member = int(env.partner.member[i])  # type: ignore[attr-defined]
            assert member == (1 if phase == 1 else 0)
            aec.step(int(actions[i]))
            h = int(info["human_action"][i])
            live = lives[member]
            seen = int(actions[i]) if not aec.infos["robot"]["failed"] and live.uses_robot_action else -1
            assert dict(live.distribution(world, aec.world_state, seen)).get(h, 0.0) > 0.0
            aec.step(h)
            assert (obs[i] == aec.observe("robot")["observation"]).all()
            assert info["clock"][i] == aec.clock
        pending = term | trunc
    assert phases_seen == {0, 1, 2}
    assert env.partner.fallbacks == 0  # type: ignore[attr-defined]


def test_a_switching_partner_by_tasks_follows_each_tables_count() -> None:
    human = make_human("switching", humans=["cooperative", "adversarial"], at=[2.0], by="tasks")
    env = robot_vector_env(num_envs=8, human=human, cache=None, continuing=True, max_cycles=None)
    env.reset(seed=0)
    rng = np.random.default_rng(0)
    for _ in range(200):
        before = env.tasks_solved.copy()
        masks = env.action_masks()
        env.step((rng.random(masks.shape) * masks).argmax(1))
        member = env.partner.member  # type: ignore[attr-defined]
        # the phase is read at the partner's move, after the robot's move of the same cycle
        # (the AEC human's turn sees the robot's success too): adversarial from 2 tasks on
        assert (member[before >= 2] == 1).all() and (member[env.tasks_solved < 2] == 0).all()
    assert (env.tasks_solved >= 2).any() and (env.tasks_solved < 2).any()


@pytest.mark.parametrize("num_envs", [0, -3, 1.5, "4"])
def test_bad_num_envs_is_one_error_naming_it(num_envs: object) -> None:
    with pytest.raises(ConfigError, match="num_envs"):
        robot_vector_env(num_envs=num_envs, cache=None)  # type: ignore[arg-type]


def test_a_batch_over_the_memory_limit_is_refused_before_allocating() -> None:
    with pytest.raises(ConfigError, match=r"num_envs.*limit"):
        BatchedTable(partner_of("paper2015", "lazy"), 10**12, world_of("paper2015"))  # type: ignore[arg-type]


def test_a_partner_that_cannot_be_compiled_is_named() -> None:
    with pytest.raises(CompileError, match=r"human: .*switching"):
        compile_human(world_of("paper2015"), "switching", cache=None)


def test_a_scenario_over_the_compilers_budget_is_named() -> None:
    with pytest.raises(CompileError, match="budget"):
        compile_human(world_of("paper2015"), "random", cache=None, max_keys=100)


def test_disk_cache_is_reused_and_keyed_by_content(tmp_path) -> None:  # type: ignore[no-untyped-def]
    world = world_of("paper2015")
    first = compile_human(world, "lazy", cache=tmp_path)
    files = list(tmp_path.glob("*.npz"))
    assert len(files) == 1
    again = compile_human(world, "lazy", cache=tmp_path)
    assert (again.keys == first.keys).all() and (again.cum == first.cum).all()
    compile_human(world, "lazy:p_idle=0.5", cache=tmp_path)
    assert len(list(tmp_path.glob("*.npz"))) == 2


def test_the_batched_env_pickles_mid_episode() -> None:
    env = robot_vector_env(num_envs=4, human="lazy", cache=None)
    env.reset(seed=0)
    for _ in range(3):
        env.step(env.action_masks().argmax(1))
    copy = pickle.loads(pickle.dumps(env))
    actions = np.full(4, env.world.n_actions(Agent.ROBOT) - 1)
    a, b = env.step(actions), copy.step(actions)
    assert (a[0] == b[0]).all() and (a[1] == b[1]).all() and (env.clock == copy.clock).all()


FILE_FREE_ROBOTS = ["planner", "habit", "hybrid", "random"]
FILE_FREE_HUMANS = ["cooperative", "lazy", "no_handover", "adversarial", "random", "noisy", "switching"]


@pytest.mark.parametrize(
    ("view", "partner"), [("Human", r) for r in FILE_FREE_ROBOTS] + [("Robot", h) for h in FILE_FREE_HUMANS]
)
def test_every_registry_partner_view_pickles_mid_episode(view: str, partner: str) -> None:
    """A view pickled after a few steps continues exactly as the original (same seed, same actions)."""
    kw = {"robot": partner} if view == "Human" else {"human": partner}
    env = gymnasium.make(f"hg_marl/{view}TableCleaning-v0", **kw)
    env.reset(seed=5)
    for _ in range(3):
        env.step(int(env.unwrapped.action_masks().argmax()))
    copy = pickle.loads(pickle.dumps(env))
    for _ in range(4):
        action = int(env.unwrapped.action_masks().argmax())
        a, b = env.step(action), copy.step(action)
        assert (a[0] == b[0]).all() and a[1:4] == b[1:4] and a[4]["clock"] == b[4]["clock"]


def test_sb3_vec_env_adapter_answers_masks_seed_and_has_attr() -> None:
    pytest.importorskip("stable_baselines3")
    from hg_marl.wrappers.sb3 import BatchedVecEnv, batched_vec_env

    venv = batched_vec_env(4, human="cooperative", max_cycles=2, cache=None)
    assert venv.has_attr("action_masks")
    venv.seed(3)
    first = venv.reset()
    venv.seed(3)
    assert (venv.reset() == first).all()
    masks = np.stack(venv.env_method("action_masks"))
    assert masks.shape == (4, venv.action_space.n)  # type: ignore[attr-defined]
    wait = np.full(4, venv.action_space.n - 1)  # type: ignore[attr-defined]
    venv.step(wait)
    _, _, dones, infos = venv.step(wait)  # max_cycles=2: every table truncated, reset in the same step
    assert dones.all() and all(i["TimeLimit.truncated"] for i in infos)
    assert all(i["terminal_observation"].shape == first.shape[1:] for i in infos)
    with pytest.raises(ConfigError, match="autoreset_mode"):
        BatchedVecEnv(robot_vector_env(num_envs=2, cache=None))


def test_maskable_ppo_trains_on_the_batched_env_and_honours_masks() -> None:
    """A short MaskablePPO run: every action it sends is feasible (the masks reach it)."""
    pytest.importorskip("sb3_contrib")
    import torch
    from sb3_contrib import MaskablePPO

    from hg_marl.wrappers.sb3 import batched_vec_env, quiet_logger

    torch.set_num_threads(1)
    venv = batched_vec_env(16, human="cooperative", max_cycles=50, cache=None)
    sent: list[bool] = []
    step_async = venv.step_async

    def audited(actions: np.ndarray) -> None:
        masks = venv.action_masks()
        sent.extend(masks[np.arange(len(actions)), actions].tolist())
        step_async(actions)

    venv.step_async = audited  # type: ignore[method-assign]
    quiet_logger(MaskablePPO("MlpPolicy", venv, n_steps=16, batch_size=64, n_epochs=1, seed=0, device="cpu")).learn(512)
    assert len(sent) >= 512 and all(sent)


def test_compiled_sampling_draws_each_answer_with_its_probability() -> None:
    """20,000 draws at one state of the random human: frequencies within 0.02 of the live distribution."""
    world = world_of("paper2015")
    compiled = partner_of("paper2015", "random")
    live = make_human("random")
    live.reset(world, Agent.HUMAN, np.random.default_rng(0))
    rules = BatchedRules(world)
    walk = rules.initial(np.random.default_rng(1), 1)
    for t in range(40):  # walk until the human has three or more answers
        state = walk.state(0)
        expected = dict(live.distribution(world, state, -1))
        if t % 2 == 1 and len(expected) > 2:
            break
        agent = Agent(t % 2)
        rules.step(walk, agent, np.array([np.flatnonzero(rules.masks(walk, agent)[0])[0]]))
    assert len(expected) > 2
    from hg_marl.envs.batched import BatchState

    batch = BatchState.of([state] * 20_000)
    drawn = compiled.act(batch, np.full(20_000, -1), np.random.default_rng(0))  # type: ignore[attr-defined]
    counts = np.bincount(drawn, minlength=world.n_actions(Agent.HUMAN)) / 20_000
    for action in range(world.n_actions(Agent.HUMAN)):
        assert counts[action] == pytest.approx(expected.get(action, 0.0), abs=0.02)


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    scenario=st.sampled_from(ENV_SCENARIOS),
    robot=st.sampled_from(["random", "planner"]),
    seed=st.integers(0, 2**31),
    max_cycles=st.integers(2, 12),
    effort_weight=st.sampled_from([0.0, 0.05]),
)
def test_human_seat_trajectories_equal_the_aec_env(
    scenario: str, robot: str, seed: int, max_cycles: int, effort_weight: float
) -> None:
    """The human's batched seat replayed in the AEC env with the robots' recorded moves (HumanView's protocol)."""
    from hg_marl.agents.views import human_vector_env

    n = 4
    world = world_of(scenario)
    env = human_vector_env(
        num_envs=n,
        scenario=world.scenario,
        robot=robot,
        max_cycles=max_cycles,
        effort_weight=effort_weight,
        compiled=False,  # the live robots (the compiled planner: tests/env/test_compiled_robot.py)
    )
    rng = np.random.default_rng(seed)
    starts = [world.initial_state(rng) for _ in range(n)]
    obs, info = env.reset(seed=seed, options={"states": starts})
    aecs = []
    for i in range(n):
        aec = raw_env(scenario=world.scenario, max_cycles=max_cycles)
        aec.reset(options={"state": starts[i]})
        aec.step(int(info["robot_action"][i]))
        assert (obs[i] == aec.observe("human")["observation"]).all()
        aecs.append(aec)
    ended = np.zeros(n, dtype=bool)
    for _ in range(30):
        masks = env.action_masks()
        actions = (rng.random(masks.shape) * masks).argmax(1)
        obs, reward, term, trunc, info = env.step(actions)
        for i, aec in enumerate(aecs):
            if ended[i]:
                continue
            assert (masks[i] == aec.observe("human")["action_mask"].astype(bool)).all()
            before = aec.infos["human"]["effort"]
            aec.step(int(actions[i]))
            work = aec.infos["human"]["effort"] - before
            done, cut = aec.terminations["human"], aec.truncations["human"]
            task = 0.0
            if not (done or cut):
                aec.step(int(info["robot_action"][i]))
                task = aec.rewards["human"]
                done = task > 0
            assert reward[i] == pytest.approx(task - effort_weight * work, abs=1e-12)
            assert (term[i], trunc[i]) == (done, cut)
            assert info["clock"][i] == aec.clock and info["tasks_solved"][i] == aec.tasks_solved
            assert info["work"][i] == pytest.approx(work, abs=1e-12)
            if not (done or cut):
                assert (obs[i] == aec.observe("human")["observation"]).all()
            ended[i] = done or cut
        if ended.all():
            break


@pytest.mark.slow
@pytest.mark.parametrize("algo", ["PPO", "DQN"])
def test_plain_sb3_algorithms_train_on_the_batched_vec_env(algo: str) -> None:
    """PPO and DQN learn a few hundred steps on the adapter (no masks: failed actions are legal input)."""
    sb3 = pytest.importorskip("stable_baselines3")
    import torch

    from hg_marl.wrappers.sb3 import batched_vec_env, quiet_logger

    torch.set_num_threads(1)
    venv = batched_vec_env(8, human="lazy", max_cycles=20, cache=None)
    kwargs = {"n_steps": 16, "batch_size": 64} if algo == "PPO" else {"learning_starts": 64, "buffer_size": 1000}
    model = quiet_logger(getattr(sb3, algo)("MlpPolicy", venv, seed=0, device="cpu", **kwargs)).learn(256)
    assert model.num_timesteps >= 256
    assert int(venv.env.cycles.max()) <= 20  # the tables were reset by the adapter as they ended


def test_a_spec_naming_a_file_is_keyed_by_the_files_content(tmp_path) -> None:  # type: ignore[no-untyped-def]
    from hg_marl.agents.compiled import cache_key
    from hg_marl.agents.humans.learned import save_learned_policy

    world = world_of("paper2015")
    weights = np.zeros((world.n_actions(Agent.HUMAN), world.n_facts))
    policy = save_learned_policy(tmp_path / "policy", world, weights=weights)
    spec = f"learned:path={policy}"
    first = cache_key(world, spec)
    assert cache_key(world, spec) == first
    save_learned_policy(policy, world, weights=weights + 1.0)  # retrained into the same folder
    assert cache_key(world, spec) != first


def test_a_learned_numpy_human_compiles_to_its_live_distribution(tmp_path) -> None:  # type: ignore[no-untyped-def]
    """A learned (linear softmax) policy is stationary: compiled once, its answers are the live ones."""
    from hg_marl.agents.humans.learned import save_learned_policy

    world = world_of("paper2015")
    rng = np.random.default_rng(0)
    weights = rng.normal(size=(world.n_actions(Agent.HUMAN), world.n_facts))
    path = save_learned_policy(tmp_path / "policy", world, weights=weights)
    spec = f"learned:path={path}"
    compiled = compile_human(world, spec, cache=tmp_path / "cache")
    live = make_human(spec)
    live.reset(world, Agent.HUMAN, np.random.default_rng(0))
    rules = BatchedRules(world)
    batch = rules.initial(np.random.default_rng(2), 8)
    seen = np.full(8, -1)
    for i in range(8):
        expected = [(a, p) for a, p in live.distribution(world, batch.state(i), -1) if p > 0]
        got = compiled.distribution(batch, seen, i)
        assert [a for a, _ in got] == [a for a, _ in expected]
        assert [p for _, p in got] == pytest.approx([p for _, p in expected], abs=1e-12)
