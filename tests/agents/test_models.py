"""The array model builder and sparse solver against the Python enumeration they replaced.

Expected values come from ``reference_oracle`` (the oracle before the array builder: one
Python state at a time, value iteration with ``np.bincount``), a simpler implementation
of the same model: same states, same (state, action, next state, seconds, probability)
transitions, same regeneration, rates to 1e-9.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from hg_marl.agents.models import AnswerTable, Budget, StatePacker, build_model, solve
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.layouts import canonical_layouts, layout_distribution
from hg_marl.agents.oracle import oracle_rate
from hg_marl.agents.planner.space import Relabel
from hg_marl.core import State, World
from hg_marl.envs.batched import BatchState
from tests.agents.reference_oracle import Reference, reference_oracle

SMALL = ("paper2015", "asymmetric_advantages", "forced_coordination")
HUMANS = ("cooperative", "lazy", "random", "no_handover", "noisy", "adversarial", "lazy:p_idle=0.5")


def array_model(world: World, human: Any, symmetry: bool | None = None) -> tuple[Any, bool]:
    live = stationary_human(human, world)
    canonical = bool(getattr(live, "equivariant", False)) if symmetry is None else symmetry
    canonical = canonical and Relabel(world).active
    layouts = canonical_layouts(world) if canonical else layout_distribution(world)
    answers = AnswerTable(world, live, StatePacker(world))
    return build_model(world, answers, layouts, canonical=canonical), canonical


def grouped(
    keys: np.ndarray,
    pair_state: np.ndarray,
    pair_action: np.ndarray,
    t_pair: np.ndarray,
    t_next: np.ndarray,
    t_tau: np.ndarray,
    t_prob: np.ndarray,
) -> tuple[tuple[np.ndarray, ...], tuple[np.ndarray, ...], np.ndarray]:
    """A model as sorted arrays, whatever its state ids: the pairs (state key, action); the
    transitions' distinct (state key, action, next key, seconds); their summed probability."""
    s_key = keys[pair_state]
    order = np.lexsort((pair_action, s_key))
    pairs = (s_key[order], pair_action[order])
    cols = (s_key[t_pair], pair_action[t_pair], keys[t_next], t_tau)
    order = np.lexsort(cols[::-1])  # stable: equal rows keep their order, so sums add alike
    cols = tuple(c[order] for c in cols)
    prob = t_prob[order]
    if not len(prob):
        return pairs, cols, prob
    new = np.ones(len(prob), dtype=bool)
    new[1:] = np.logical_or.reduce([c[1:] != c[:-1] for c in cols])
    at = np.flatnonzero(new)
    return pairs, tuple(c[at] for c in cols), np.add.reduceat(prob, at)


def assert_same(model: Any, ref: Reference) -> None:
    """The same states, (state, action) pairs, (state, action, next state, seconds) transitions
    with probabilities equal to 1e-12, and the same re-draw, compared as sorted packed keys."""
    assert model.n == ref.n_states and len(model.t_next) == ref.n_transitions
    ref_keys = model.packer.pack(BatchState.of(ref.states))
    assert np.array_equal(np.sort(model.keys), np.sort(ref_keys))
    got = grouped(
        model.keys, model.pair_state(), model.pair_action, model.t_pair(), model.t_next, model.t_tau, model.t_prob
    )
    want = grouped(ref_keys, ref.pair_state, ref.pair_action, ref.t_pair, ref.t_next, ref.t_tau, ref.t_prob)
    for a, b in zip((*got[0], *got[1]), (*want[0], *want[1]), strict=True):
        assert np.array_equal(a, b)
    np.testing.assert_allclose(got[2], want[2], rtol=1e-12, atol=0.0)
    regen_keys = model.packer.pack(BatchState.of(list(ref.regen)))
    want_regen = dict(zip(regen_keys.tolist(), ref.regen.values(), strict=True))
    got_regen: dict[int, float] = {}
    for k, p in zip(model.keys[model.regen_next].tolist(), model.regen_prob.tolist(), strict=True):
        got_regen[k] = got_regen.get(k, 0.0) + p
    assert got_regen.keys() == want_regen.keys()
    for k, p in want_regen.items():
        assert got_regen[k] == pytest.approx(p, rel=1e-12)


@pytest.mark.parametrize("scenario", SMALL)
@pytest.mark.parametrize("human", HUMANS)
def test_the_array_model_is_the_python_enumeration(scenario: str, human: str) -> None:
    world = World(scenario)
    ref = reference_oracle(world, human)
    model, _ = array_model(world, human)
    assert_same(model, ref)
    result = oracle_rate(world, human)
    assert result.rate_per_hour == pytest.approx(ref.rate_per_hour, rel=1e-9, abs=1e-9)
    assert (result.n_states, result.n_transitions) == (ref.n_states, ref.n_transitions)
    for state, action in ref.policy.items():  # ties broken alike: the first best action in option order
        assert result.policy[state] == action
        assert result.values[state] == pytest.approx(ref.values[state], rel=1e-9, abs=1e-9)


@pytest.mark.parametrize(
    "human",
    [
        "random",
        pytest.param("no_handover", marks=pytest.mark.slow),
        pytest.param("adversarial", marks=pytest.mark.slow),
    ],
)
def test_roboergosum_matches_the_python_enumeration(human: str) -> None:
    world = World("roboergosum")
    ref = reference_oracle(world, human)
    model, _ = array_model(world, human)
    assert_same(model, ref)
    assert oracle_rate(world, human).rate_per_hour == pytest.approx(ref.rate_per_hour, rel=1e-9, abs=1e-9)


@pytest.mark.slow
@pytest.mark.parametrize("member", [0, 5, 11])  # the Python reference takes minutes per member
def test_roboergosum_members_match_the_python_enumeration(member: int) -> None:
    from hg_marl.agents.humans.population import load_population

    spec = load_population("populations/roboergosum.toml").members()[member].spec
    world = World("roboergosum")
    ref = reference_oracle(world, spec)
    assert_same(array_model(world, spec)[0], ref)
    assert oracle_rate(world, spec).rate_per_hour == pytest.approx(ref.rate_per_hour, rel=1e-9, abs=1e-9)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    objects=st.integers(1, 3),
    bins=st.integers(1, 2),
    seed=st.integers(0, 50),
    human=st.sampled_from(["random", "lazy", "no_handover", "noisy"]),
)
def test_generated_scenarios_match_the_python_enumeration(objects: int, bins: int, seed: int, human: str) -> None:
    world = World(f"generated:objects={objects},spots={objects + 1},bins={bins},seed={seed}")
    ref = reference_oracle(world, human)
    model, _ = array_model(world, human)
    assert_same(model, ref)
    solution = solve(model)
    rate = 0.0 if np.isinf(solution.seconds_per_task) else 3600.0 / solution.seconds_per_task
    assert rate == pytest.approx(ref.rate_per_hour, rel=1e-9, abs=1e-9)


def test_canonical_relabelling_on_arrays_is_relabel_canonical() -> None:
    world = World("roboergosum")
    relabel, packer = Relabel(world), StatePacker(world)
    rng = np.random.default_rng(0)
    states = []
    for _ in range(300):  # random states, offers included: the relabelling is a pure function of the state
        where = tuple(int(x) for x in rng.integers(0, world.table.n_places, world.n_objects))
        by = int(rng.integers(-1, 2))
        states.append(
            State(where, int(rng.integers(0, world.table.n_locations)), by, int(rng.integers(0, 6)) if by >= 0 else -1)
        )
    b = BatchState.of(states)
    packer.canonical(b)
    assert [b.state(i) for i in range(len(b))] == [relabel.canonical(s)[0] for s in states]


def test_a_packed_key_unpacks_to_its_state() -> None:
    world = World("paper2015")
    packer = StatePacker(world)
    states = [s for s, _ in layout_distribution(world)]
    b = BatchState.of(states)
    keys = packer.pack(b, np.arange(len(b)) % 5 - 1)
    back, seen = packer.unpack(keys)
    assert [back.state(i) for i in range(len(back))] == states
    assert seen.tolist() == (np.arange(len(b)) % 5 - 1).tolist()
    assert [packer.pack_one(s) for s in states] == packer.pack(b).tolist()


def test_the_solver_reads_its_budget_while_sweeping() -> None:
    world = World("paper2015")
    model, _ = array_model(world, "random")
    budget = Budget(None, None, None)
    solve(model, budget=budget)
    assert budget.phase == "solve" and budget.checks >= 2


@pytest.mark.parametrize("scenario", ["paper2015", "forced_coordination"])
def test_the_headroom_joint_model_on_arrays_is_the_python_joint_model(scenario: str) -> None:
    from hg_marl.agents.headroom import JointModel
    from hg_marl.agents.models.layouts import layout_distribution as layouts_of

    world = World(scenario)
    specs = ["cooperative", "lazy", "no_handover", "random", "preference:handover=-1,shared=1"]
    reference = JointModel(world, [stationary_human(h, world) for h in specs])
    packer = StatePacker(world)
    tables = [AnswerTable(world, stationary_human(h, world), packer) for h in specs]
    arrays = JointModel.from_model(world, build_model(world, tables, layouts_of(world)))
    assert arrays.n == reference.n and arrays.n_pairs == reference.n_pairs
    for i in range(len(specs)):
        assert len(arrays.arrays(i)[0]) == len(reference.arrays(i)[0])
        ref_choice, new_choice = reference.optimal_policy(i), arrays.optimal_policy(i)
        for j in range(len(specs)):  # every policy against every partner: the matrix's entries
            assert arrays.rate(new_choice, j) == pytest.approx(reference.rate(ref_choice, j), rel=1e-9, abs=1e-9)


def test_a_cached_result_is_the_computed_one_and_its_key_follows_the_content(tmp_path: Any) -> None:
    from hg_marl.agents.models.cache import result_key

    world = World("paper2015")
    first = oracle_rate(world, "lazy", cache=tmp_path)
    assert len(list(tmp_path.glob("paper2015-*.npz"))) == 1
    again = oracle_rate(world, "lazy", cache=tmp_path)
    assert again.iterations == first.iterations and again.rate_per_hour == first.rate_per_hour
    assert dict(again.policy) == dict(first.policy) and dict(again.values) == dict(first.values)
    options = {"failed_actions": True, "symmetry": None, "tolerance": 1e-9, "max_iterations": 200_000}
    key = result_key(world, "lazy", options)
    assert key == result_key(World("paper2015"), "lazy", dict(options))  # same content, same key
    assert key != result_key(world, "lazy:p_idle=0.5", options)  # another human
    assert key != result_key(world, "lazy", {**options, "failed_actions": False})  # another option
    assert key != result_key(World("forced_coordination"), "lazy", options)  # another scenario
    oracle_rate(world, "lazy", cache=tmp_path, failed_actions=False)  # another option: another entry
    assert len(list(tmp_path.glob("paper2015-*.npz"))) == 2


def test_a_corrupt_cache_entry_is_rebuilt(tmp_path: Any) -> None:
    world = World("paper2015")
    first = oracle_rate(world, "no_handover", cache=tmp_path)
    (entry,) = tmp_path.glob("*.npz")
    entry.write_bytes(b"not an npz")
    again = oracle_rate(world, "no_handover", cache=tmp_path)
    assert again.rate_per_hour == first.rate_per_hour and again.n_states == first.n_states
    assert entry.read_bytes()[:2] == b"PK"  # rewritten as a zip archive


def mid_states(world: World, count: int = 3000) -> list[State]:
    """Mid-cycle states the robot's actions reach on random walks (offers included)."""
    rng = np.random.default_rng(1)
    out: list[State] = []
    layouts = [s for s, _ in layout_distribution(world)]
    while len(out) < count:
        s = layouts[int(rng.integers(len(layouts)))]
        for _ in range(30):
            opts = world.feasible_indices(s, 0)
            s = world.table.successor(s, 0, opts[int(rng.integers(len(opts)))])[0]
            out.append(s)
            opts = world.feasible_indices(s, 1)
            s = world.table.successor(s, 1, opts[int(rng.integers(len(opts)))])[0]
    return out


PREFERENCES = [
    "random",
    "preference",
    "preference:accept=0.5,p_idle=0.3,haste=0.2,colour=blue,colour_bonus=0.4",
    "preference:handover=-1,shared=1,keep=0.3,robot_side=0.8,accept=0",
    "preference:self_work=2,p_idle=1",
]


@pytest.mark.parametrize("scenario", ["paper2015", "roboergosum", "forced_coordination"])
def test_array_answers_are_the_live_humans_answers(scenario: str) -> None:
    from hg_marl.agents.humans.population import load_population
    from hg_marl.agents.models.partners import batch_answers

    world = World(scenario)
    states = mid_states(world)
    b = BatchState.of(states)
    members = [m.spec for m in load_population("populations/roboergosum.toml").members()]
    for spec in [*PREFERENCES, *members]:
        live = stationary_human(spec, world)
        batch = batch_answers(world, live)
        assert batch is not None, spec
        sizes, actions, probs = batch(b)
        at = 0
        for i, s in enumerate(states):
            expected = [(h, p) for h, p in live.distribution(world, s, -1) if p > 0.0]
            got = list(zip(actions[at : at + sizes[i]].tolist(), probs[at : at + sizes[i]].tolist(), strict=True))
            assert got == expected, (spec, s)
            at += sizes[i]


def test_a_softmax_preference_is_answered_live() -> None:
    from hg_marl.agents.models.partners import batch_answers

    world = World("paper2015")
    assert batch_answers(world, stationary_human("preference:temperature=0.5", world)) is None
    assert batch_answers(world, stationary_human("random:feasible_only=false", world)) is None


EQUIVARIANT = ("cooperative", "cooperative:p_idle=0.2", "noisy", "noisy:temperature=0")


@pytest.mark.parametrize("scenario", ["paper2015", "roboergosum"])
def test_canonical_answers_are_the_live_humans_answers(scenario: str) -> None:
    """Asked once per canonical key and mapped back, the answers are the live human's at every state and seen."""
    from hg_marl.agents.models.equivariant import canonical_answers

    world = World(scenario)
    states = mid_states(world, 1500 if scenario == "roboergosum" else 3000)
    b = BatchState.of(states)
    rng = np.random.default_rng(2)
    seen = rng.integers(-1, world.n_actions(0), size=len(states))
    for spec in EQUIVARIANT:
        table = canonical_answers(world, stationary_human(spec, world), StatePacker(world))
        assert table is not None, spec
        sizes, actions, probs = table(b, seen, lambda i, n: None)
        assert table.live_calls < len(states)  # relabelled states and alike actions share one live answer
        fresh = stationary_human(spec, world)  # a separate instance: no answer shared through a memo
        at = 0
        for i, s in enumerate(states):
            expected = [(h, p) for h, p in fresh.distribution(world, s, int(seen[i])) if p > 0.0]
            got = list(zip(actions[at : at + sizes[i]].tolist(), probs[at : at + sizes[i]].tolist(), strict=True))
            assert got == expected, (spec, s, int(seen[i]))
            at += sizes[i]


def test_a_partner_that_is_not_equivariant_is_not_asked_by_canonical_key() -> None:
    from hg_marl.agents.models.equivariant import canonical_answers

    world = World("roboergosum")
    for spec in ("lazy", "no_handover", "adversarial"):
        assert canonical_answers(world, stationary_human(spec, world), StatePacker(world)) is None


def full_chain_rate(model: Any, choice: np.ndarray, i: int) -> float:
    """A policy's rate on the whole joint model (the evaluation before it was restricted to the states reached)."""
    import math

    from scipy import sparse
    from scipy.sparse.linalg import spsolve

    t_pair, t_next, t_prob, t_tau = model.arrays(i)
    n = model.n
    chosen = np.zeros(model.n_pairs, dtype=bool)
    chosen[choice] = True
    done = model.terminal[choice]
    keep = chosen[t_pair]
    rows, cols, probs, taus = model.pair_state[t_pair[keep]], t_next[keep], t_prob[keep], t_tau[keep]
    graph = sparse.csr_matrix((np.ones(len(rows)), (rows, cols)), shape=(n, n))

    def backward(seeds: np.ndarray) -> np.ndarray:
        found = seeds.copy()
        while True:  # grow by one step at a time until nothing changes
            grown = found | ((graph @ found.astype(float)) > 0)
            if (grown == found).all():
                return found
            found = grown

    certain = ~backward(~backward(done))
    idx = np.flatnonzero(certain)
    pos = np.full(n, -1)
    pos[idx] = np.arange(len(idx))
    values = np.full(n, math.inf)
    inner = certain[rows] & certain[cols] & ~done[rows]
    p = sparse.csr_matrix((probs[inner], (pos[rows[inner]], pos[cols[inner]])), shape=(len(idx), len(idx)))
    src = certain[rows] & ~done[rows]
    c = np.bincount(pos[rows[src]], weights=(probs * taus)[src], minlength=len(idx))
    values[idx] = spsolve((sparse.identity(len(idx), format="csr") - p).tocsc(), c)
    chain = model.chain(i)
    regen = zip(chain.regen_next, chain.regen_prob, chain.regen_tau, strict=True)
    expected = math.fsum(p * (t + values[s]) for s, p, t in regen)
    return 0.0 if math.isinf(expected) else 3600.0 / expected


@pytest.mark.parametrize("scenario", ["paper2015", "forced_coordination"])
def test_a_policy_rate_on_the_states_it_reaches_is_its_rate_on_the_whole_model(scenario: str) -> None:
    from hg_marl.agents.headroom import JointModel
    from hg_marl.agents.models.layouts import layout_distribution as layouts_of

    world = World(scenario)
    specs = ["cooperative", "lazy:p_idle=0.5", "adversarial", "random", "preference:handover=-1,shared=1"]
    packer = StatePacker(world)
    tables = [AnswerTable(world, stationary_human(h, world), packer) for h in specs]
    model = JointModel.from_model(world, build_model(world, tables, layouts_of(world)))
    rates = []
    for i in range(len(specs)):
        choice = model.optimal_policy(i)
        for j in range(len(specs)):
            rates.append(model.rate(choice, j))
            assert rates[-1] == pytest.approx(full_chain_rate(model, choice, j), rel=1e-9, abs=1e-9), (i, j)
    assert 0.0 in rates and min(r for r in rates if r > 0) < max(rates)  # the adversarial column: some never finish


@pytest.mark.parametrize("scenario", ["paper2015", "forced_coordination"])
def test_transitions_read_from_the_answer_tables_are_the_kept_ones(scenario: str) -> None:
    """``build_model(keep=False)`` gives every partner the same transitions as the kept model, pair by pair."""
    from hg_marl.agents.models.layouts import layout_distribution as layouts_of

    world = World(scenario)
    specs = ["cooperative", "lazy:p_idle=0.5", "random", "preference:handover=-1,shared=1"]
    models = []
    for keep in (True, False):
        packer = StatePacker(world)
        tables = [AnswerTable(world, stationary_human(h, world), packer) for h in specs]
        models.append(build_model(world, tables, layouts_of(world), keep=keep))
    kept, lazy = models
    assert np.array_equal(kept.keys, lazy.keys) and np.array_equal(kept.pair_action, lazy.pair_action)
    rng = np.random.default_rng(0)
    for i in range(len(specs)):
        a, b = kept.chain(i), lazy.chain(i)
        for field in ("t_start", "t_next", "t_prob", "t_tau", "regen_next", "regen_prob", "regen_tau"):
            assert np.array_equal(getattr(a, field), getattr(b, field)), (i, field)
        pairs = np.sort(rng.choice(kept.n_pairs, size=50, replace=False))
        for x, y in zip(kept.gather(i, pairs), lazy.gather(i, pairs), strict=True):
            assert np.array_equal(x, y)
    for i in (0, 3, 0):  # partners asked out of turn, pairs in no order and repeated
        pairs = rng.choice(kept.n_pairs, size=5000)
        for x, y in zip(kept.gather(i, pairs), lazy.gather(i, pairs), strict=True):
            assert np.array_equal(x, y)


def test_a_reduced_models_transitions_read_from_the_answer_tables_are_the_kept_ones() -> None:
    """With the symmetry reduction the next states are the entries' canonical keys, as the kept model's."""
    world = World("paper2015")
    models = []
    for keep in (True, False):
        table = AnswerTable(world, stationary_human("cooperative", world), StatePacker(world))
        models.append(build_model(world, table, canonical_layouts(world), canonical=True, keep=keep))
    kept, lazy = models
    assert np.array_equal(kept.keys, lazy.keys)
    a, b = kept.chain(0), lazy.chain(0)
    for field in ("t_start", "t_next", "t_prob", "t_tau", "regen_next", "regen_prob", "regen_tau"):
        assert np.array_equal(getattr(a, field), getattr(b, field)), field
