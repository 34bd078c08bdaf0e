"""Documented promises of the belief robot, its partner models, the headroom and the compiled partners, pinned.

Each test pins one rule a module's docstrings or comments state and no other test checked:
the learned partner's reset, its never-refused ``wait``, its strict verdict bound, its
context features and its per-kind shares; the members' solve counter, memo order, cache
folder and oracle options; the belief robot's tie-breaking, its ``NEGLIGIBLE`` and
``PROBE_BELOW`` bounds, its open world's Bayes factor and its closed world; the headroom
policy's tie-breaking and state budget, its rows and its written report; the compiled
partners' key budget, lookups and stall rule. Every expected value is worked by hand from
the rule on a small table (``paper2015``, whose places 3-5 the human reaches, 8 is the
human's hand, location 3 the handover place), on a hand-made model, or with stand-ins
(fixed members, a counting oracle) whose answers are known exactly; each test's comments
say how its numbers follow.
"""

from __future__ import annotations

import inspect
import math
from collections.abc import Iterator
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest
from partners import Fixed
from test_headroom import CROSSING, C, G
from test_oracle import TINY
from test_partner_model import offered_state
from test_pinned_belief_gate import _members

from hg_marl.agents import member_models
from hg_marl.agents.compiled import CompileError, Packer, compile_human
from hg_marl.agents.compiled_robot import CompiledRobot, compile_robot, planner_action, robot_cache_key
from hg_marl.agents.headroom import JointModel, headroom
from hg_marl.agents.member_models import ORACLE_OPTIONS, MemberModels, clear_memo
from hg_marl.agents.models import Model, StatePacker
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.builder import Dynamics
from hg_marl.agents.oracle import OracleTooLarge, oracle_rate
from hg_marl.agents.partner_model import FAILED, LearnedPartner, observe_move, partner_features
from hg_marl.agents.robots.belief import NEGLIGIBLE, PROBE_BELOW, BeliefRobot
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.batch import BatchState
from hg_marl.core.errors import RobotError
from hg_marl.policy import Turn
from hg_marl.training.headroom import heatmap_png, write_headroom

PAPER = World("paper2015")
FIRST = PAPER.initial_state(np.random.default_rng(0))
"""``where=(0, 4, 2)``, robot at 0: the human may pick tape 1 or wait."""
TWO_PICKS = State((4, 5, 0), 0, -1, -1)
"""Tapes 0 and 1 on the human's mats: the human may pick either, or wait."""
HELD = State((8, 5, 0), 3, -1, -1)
"""Tape 0 in the human's hand, the robot at the handover place."""
ROBOT_WAIT = PAPER.n_actions(Agent.ROBOT) - 1
HUMAN_WAIT = PAPER.n_actions(Agent.HUMAN) - 1


def _human_index(kind: Kind, obj: int) -> int:
    return next(i for i, a in enumerate(PAPER.actions(Agent.HUMAN)) if a.kind is kind and a.obj == obj)


# ---- agents/partner_model.py ------------------------------------------------------------------


def test_learned_partner_reset_forgets_every_count() -> None:
    """``reset``: "Forget every count (a new run)". After it the model predicts as a fresh
    one: at the offered state, alpha / (k alpha) per kind, shared by the kind's actions."""
    mid, give = offered_state(PAPER)
    model = LearnedPartner(forget=1.0)
    for _ in range(3):
        model.update(PAPER, mid, give, HUMAN_WAIT)
    assert Kind.TAKE in model.refused_kinds()  # 3 chances, none taken: the counts say something
    model.reset()
    assert model.counts == {} and model.chances == {} and model.taken == {}
    assert model.refused_kinds() == frozenset()
    acts = PAPER.actions(Agent.HUMAN)
    feasible = PAPER.feasible_indices(mid, Agent.HUMAN)
    k = len({acts[i].kind for i in feasible})
    assert model.predict(PAPER, mid, give, HUMAN_WAIT) == pytest.approx(1.0 / k)  # one wait action


def test_wait_is_never_a_refused_kind_even_when_never_done() -> None:
    """A partner who always picks (forget 1): wait was feasible 5 times and done 0 times,
    a share of 0 < 1e-9, yet ``refused_kinds`` never names wait (its rule excludes it);
    pick was done at each of its 5 chances, so nothing is refused."""
    pick = _human_index(Kind.PICK, 0)
    model = LearnedPartner(forget=1.0)
    for _ in range(5):
        model.update(PAPER, TWO_PICKS, -1, pick)
    assert model.chances[int(Kind.WAIT)] == 5.0 and model.taken[int(Kind.WAIT)] == 0.0
    assert model.refused_kinds() == frozenset()


def test_a_share_exactly_at_below_is_not_refused() -> None:
    """One take and one refusal of an offer (forget 1): take had 2 chances and was done
    once, a share of exactly 0.5. Refused means a share *below* ``below``: not at 0.5, but
    at the next float above it."""
    mid, give = offered_state(PAPER)
    take = next(i for i in PAPER.feasible_indices(mid, Agent.HUMAN) if PAPER.actions(Agent.HUMAN)[i].kind is Kind.TAKE)
    model = LearnedPartner(forget=1.0)
    model.update(PAPER, mid, give, take)
    model.update(PAPER, mid, give, HUMAN_WAIT)
    assert model.chances[int(Kind.TAKE)] == 2.0 and model.taken[int(Kind.TAKE)] == 1.0
    assert Kind.TAKE not in model.refused_kinds(min_chances=2.0, below=0.5)
    assert Kind.TAKE in model.refused_kinds(min_chances=2.0, below=float(np.nextafter(0.5, 1.0)))


def test_the_context_reads_the_partners_hand_and_the_robots_handover_place() -> None:
    """Features (module docstring): partner holds an object, robot offers, robot at a
    handover place, robot's action kind (-1 when failed). Tape 0 in the human's hand
    (object index 0 counts as held) and the robot at location 3 (``human_side``)."""
    wait_kind = int(Kind.WAIT)
    assert LearnedPartner.context(PAPER, HELD, ROBOT_WAIT) == (True, False, True, wait_kind)
    assert LearnedPartner.context(PAPER, TWO_PICKS, ROBOT_WAIT) == (False, False, False, wait_kind)
    assert LearnedPartner.context(PAPER, HELD, -1) == (True, False, True, FAILED)


def test_the_actions_of_a_kind_share_its_probability_equally() -> None:
    """Two picks and a wait feasible: with no data p(pick) = p(wait) = 1/2, each pick 1/4.
    After one pick (forget 0.95, alpha 1): p(pick) = (1 + 1) / (1 + 1 + 0 + 1) = 2/3, each
    pick 1/3, wait 1/3. An infeasible action is predicted 0."""
    pick0, pick1 = _human_index(Kind.PICK, 0), _human_index(Kind.PICK, 1)
    model = LearnedPartner()
    got = dict(model.distribution(PAPER, TWO_PICKS, -1))
    assert got == pytest.approx({pick0: 0.25, pick1: 0.25, HUMAN_WAIT: 0.5})
    model.update(PAPER, TWO_PICKS, -1, pick0)
    got = dict(model.distribution(PAPER, TWO_PICKS, -1))
    assert got == pytest.approx({pick0: 1 / 3, pick1: 1 / 3, HUMAN_WAIT: 1 / 3})
    place = next(i for i, a in enumerate(PAPER.actions(Agent.HUMAN)) if a.kind is Kind.PLACE)
    assert model.predict(PAPER, TWO_PICKS, -1, place) == 0.0


def test_only_the_observed_contexts_counts_are_forgotten() -> None:
    """The module docstring: "each context's counts multiplied by ``forget`` at each of its
    observations". A pick counted in one context keeps its weight 1 while another context is
    observed twice (forget 0.5: its wait weighs 0.5 * 1 + 1 = 1.5)."""
    mid, give = offered_state(PAPER)
    pick = _human_index(Kind.PICK, 0)
    model = LearnedPartner(forget=0.5)
    model.update(PAPER, TWO_PICKS, -1, pick)
    model.update(PAPER, mid, give, HUMAN_WAIT)
    model.update(PAPER, mid, give, HUMAN_WAIT)
    assert model.counts[LearnedPartner.context(PAPER, TWO_PICKS, -1)] == {int(Kind.PICK): 1.0}
    assert model.counts[LearnedPartner.context(PAPER, mid, give)] == {int(Kind.WAIT): 1.5}  # 0.5 * 1 + 1


def test_observe_move_skips_what_it_cannot_reconstruct() -> None:
    """Not counted: no previous turn, no human action (-1), a solved task (reward > 0), a
    state that is not the previous state after both actions. Counted otherwise: one pick."""
    pick = _human_index(Kind.PICK, 1)
    after = PAPER.step(PAPER.step(FIRST, Agent.ROBOT, ROBOT_WAIT).state, Agent.HUMAN, pick).state
    elsewhere = PAPER.initial_state(np.random.default_rng(1))
    assert elsewhere != after
    skipped: list[tuple[tuple[State, int] | None, Turn]] = [
        (None, Turn(PAPER, after, Agent.ROBOT, {}, last_actions=(ROBOT_WAIT, pick))),
        ((FIRST, ROBOT_WAIT), Turn(PAPER, after, Agent.ROBOT, {}, last_actions=(ROBOT_WAIT, -1))),
        ((FIRST, ROBOT_WAIT), Turn(PAPER, after, Agent.ROBOT, {}, reward=1.0, last_actions=(ROBOT_WAIT, pick))),
        ((FIRST, ROBOT_WAIT), Turn(PAPER, elsewhere, Agent.ROBOT, {}, last_actions=(ROBOT_WAIT, pick))),
    ]
    for previous, turn in skipped:
        model = LearnedPartner()
        observe_move(model, PAPER, previous, turn)
        assert model.counts == {} and model.chances == {}
    model = LearnedPartner()
    observe_move(
        model, PAPER, (FIRST, ROBOT_WAIT), Turn(PAPER, after, Agent.ROBOT, {}, last_actions=(ROBOT_WAIT, pick))
    )
    assert model.counts == {(False, False, False, int(Kind.WAIT)): {int(Kind.PICK): 1.0}}


def test_the_second_partner_feature_is_the_give_verdict() -> None:
    """The features are "does it refuse to take, to give (0/1 each)": give was feasible 3
    times and never done (refused), take never feasible (no verdict): [0, 1]."""
    model = LearnedPartner()
    model.chances = {int(Kind.GIVE): 3.0}
    assert partner_features(model).tolist() == [0, 1]


# ---- agents/member_models.py ------------------------------------------------------------------


@pytest.fixture
def solves(monkeypatch: pytest.MonkeyPatch) -> Iterator[list[tuple[str, Any]]]:
    """A stand-in oracle recording (spec, cache) per solve; an empty process memo, no env cache."""
    clear_memo()
    monkeypatch.delenv("HG_MARL_CACHE", raising=False)
    calls: list[tuple[str, Any]] = []

    def oracle(world: World, spec: str, cache: Any = None, **options: Any) -> Any:
        calls.append((spec, cache))
        return SimpleNamespace(spec=spec, scenario=world.scenario.name)

    monkeypatch.setattr(member_models, "oracle_rate", oracle)
    yield calls
    clear_memo()


def test_members_are_solved_with_the_oracles_own_defaults() -> None:
    """``ORACLE_OPTIONS``: "The options oracle_rate solves members with (its defaults)"."""
    params = inspect.signature(oracle_rate).parameters
    assert {name: params[name].default for name in ORACLE_OPTIONS} == ORACLE_OPTIONS
    assert set(ORACLE_OPTIONS) == {"failed_actions", "symmetry", "tolerance", "max_iterations"}


def test_a_member_is_counted_once_per_world_and_a_memo_read_counts(solves: list[tuple[str, Any]]) -> None:
    """``solved``: members solved *or read from a cache*, each counted once per world."""
    first = MemberModels(("cooperative", "lazy"))
    first.reset(PAPER)
    first.result(0)
    first.result(0)
    assert first.solved == 1 and len(solves) == 1
    first.result(1)
    assert first.solved == 2 and len(solves) == 2
    second = MemberModels(("cooperative",))
    second.reset(PAPER)
    second.result(0)  # read from the process memo: no solve, but counted
    assert second.solved == 1 and len(solves) == 2


def test_the_memo_drops_the_result_read_longest_ago(
    solves: list[tuple[str, Any]], monkeypatch: pytest.MonkeyPatch
) -> None:
    """A memo of 2 results: cooperative and lazy solved, cooperative read again (it becomes
    the newest), no_handover solved: lazy, now the oldest, is dropped; cooperative is still
    served without a solve, lazy is solved again."""
    monkeypatch.setattr(member_models, "MEMO_ENTRIES", 2)

    def read(spec: str) -> None:
        models = MemberModels((spec,))
        models.reset(PAPER)
        models.result(0)

    for spec in ("cooperative", "lazy", "cooperative", "no_handover"):
        read(spec)
    assert [s for s, _ in solves] == ["cooperative", "lazy", "no_handover"]
    read("cooperative")
    assert len(solves) == 3
    read("lazy")
    assert [s for s, _ in solves][-1] == "lazy" and len(solves) == 4


def test_an_empty_cache_names_hg_marl_cache_oracle_and_the_solve_uses_it(
    solves: list[tuple[str, Any]], monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """Empty ``cache``: ``$HG_MARL_CACHE/oracle`` when set (else no disk cache); a named folder
    wins. The oracle is asked with that folder (False when there is none)."""
    monkeypatch.setenv("HG_MARL_CACHE", str(tmp_path / "root"))
    env = MemberModels(("cooperative",))
    assert env.cache == tmp_path / "root" / "oracle"
    env.reset(PAPER)
    env.result(0)
    named = MemberModels(("lazy",), str(tmp_path / "mine"))
    assert named.cache == tmp_path / "mine"
    named.reset(PAPER)
    named.result(0)
    monkeypatch.delenv("HG_MARL_CACHE")
    nowhere = MemberModels(("no_handover",))
    nowhere.reset(PAPER)
    nowhere.result(0)
    assert solves == [
        ("cooperative", tmp_path / "root" / "oracle"),
        ("lazy", tmp_path / "mine"),
        ("no_handover", False),
    ]


def test_a_members_one_step_model_is_built_once_per_world() -> None:
    """``model(m)`` is built on first use and kept; another scenario drops it ("results of
    another scenario are dropped")."""
    models = MemberModels(("lazy",))
    models.reset(PAPER)
    first = models.model(0)
    assert models.model(0) is first and first.world is PAPER
    models.reset(World("paper2015"))  # the same table: kept
    assert models.model(0) is first
    other = World(TINY)
    models.reset(other)
    assert models.model(0) is not first and models.model(0).world is other


# ---- agents/robots/belief.py ------------------------------------------------------------------


def _belief(tmp_path: Path, **params: Any) -> BeliefRobot:
    """A belief robot over two members (cooperative, lazy) reset on ``paper2015``."""
    robot = BeliefRobot(population=_members(tmp_path, a="cooperative", b="lazy"), splits="train", **params)
    robot.reset(PAPER, Agent.ROBOT, np.random.default_rng(0))
    return robot


def _decide(
    robot: BeliefRobot, monkeypatch: pytest.MonkeyPatch, post: dict[str, float], q: list[dict[int, float]]
) -> tuple[int, dict[str, float], str]:
    """The robot's action on the first table under the posterior ``post``, member m's values ``q[m]``."""
    monkeypatch.setattr(robot.posterior, "posterior", lambda: post)
    monkeypatch.setattr(robot, "q_values", lambda w, s, m: q[m])
    robot._prev = None
    action = robot.act(Turn(PAPER, FIRST, Agent.ROBOT, {}))
    assert robot.last_decision is not None
    return action, dict(robot.last_decision.stats), str(robot.last_decision.reason)


def test_equally_good_actions_go_to_the_lowest_index(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Actions 3 and 1 both 5 s, action 2 7 s: the lowest index of the best, 1."""
    robot = _belief(tmp_path, unknown=0.0, hedge="qmdp")
    q = {3: 5.0, 1: 5.0, 2: 7.0}
    action, stats, _ = _decide(robot, monkeypatch, {"cooperative": 0.5, "lazy": 0.5}, [q, q])
    assert action == 1 and stats["expected_seconds"] == pytest.approx(5.0)


def test_a_member_at_exactly_negligible_has_a_say_and_one_below_has_none(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """QMDP, member a: action 0 10 s, action 1 11 s; member b: 1e6 s and 0 s. With b at
    weight 1e-3 (= NEGLIGIBLE, not less) the mixture is 0.999 * 10 + 1e-3 * 1e6 = 1009.99
    for 0 and 0.999 * 11 = 10.989 for 1: action 1. Just below it b has no say: action 0, 10 s."""
    assert NEGLIGIBLE == 1e-3
    robot = _belief(tmp_path, unknown=0.0, hedge="qmdp")
    q = [{0: 10.0, 1: 11.0}, {0: 1e6, 1: 0.0}]
    action, stats, _ = _decide(robot, monkeypatch, {"cooperative": 0.999, "lazy": 1e-3}, q)
    assert action == 1 and stats["expected_seconds"] == pytest.approx(10.989)
    below = float(np.nextafter(1e-3, 0.0))
    action, stats, _ = _decide(robot, monkeypatch, {"cooperative": 0.999, "lazy": below}, q)
    assert action == 0 and stats["expected_seconds"] == pytest.approx(10.0)


def test_the_information_leaves_out_members_under_negligible(tmp_path: Path) -> None:
    """Two equally believed members sure of replies a and b, a third also sure of b at weight
    0.0009: the information is the first two members' alone. With n replies, eps 0.05: each gives
    its reply q = 0.95 + 0.05/n and r = 0.05/n elsewhere; I = H(mix) - H(member)."""
    robot = _belief(tmp_path, unknown=0.0, epsilon=0.05)
    mid = PAPER.step(FIRST, Agent.ROBOT, ROBOT_WAIT).state
    replies = PAPER.feasible_indices(mid, Agent.HUMAN)
    n = len(replies)
    assert n == 2
    q, r = 0.95 + 0.05 / n, 0.05 / n
    mix = [(q + r) / 2] * 2
    expected = -sum(p * math.log(p) for p in mix) + (q * math.log(q) + r * math.log(r))
    robot.posterior.humans = [Fixed(replies[0]), Fixed(replies[1]), Fixed(replies[1])]
    got = robot.information(PAPER, FIRST, ROBOT_WAIT, [0.5, 0.5, 0.0009])
    assert got == pytest.approx(expected, rel=1e-12)
    # at 1e-3 the third member counts: the mixture leans to reply b, the information changes
    assert robot.information(PAPER, FIRST, ROBOT_WAIT, [0.5, 0.5, 1e-3]) != pytest.approx(expected, rel=1e-9)


def test_the_uniform_partner_needs_no_bayes_factor_and_a_tie_is_not_off_the_population(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """``bayes_factor`` applies to the learned partner only: the uniform one drives once it is
    more probable than the best member (0.6 > 0.2, though not 5 times 0.2), and not when it
    is exactly as probable (0.4 = 0.4)."""
    robot = _belief(tmp_path, unknown=0.05, bayes_factor=5.0)
    q = [{ROBOT_WAIT: 10.0}, {ROBOT_WAIT: 10.0}]
    _, _, reason = _decide(robot, monkeypatch, {"cooperative": 0.2, "lazy": 0.2, "random": 0.6}, q)
    assert reason.startswith("no member explains the partner") and robot.last_decision is not None
    assert robot.last_decision.partner == "random"
    _, _, reason = _decide(robot, monkeypatch, {"cooperative": 0.4, "lazy": 0.2, "random": 0.4}, q)
    assert not reason.startswith("no member explains") and robot.last_decision.partner == "a"


def test_a_robot_probes_only_while_no_member_holds_ninety_percent(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Both members: action 0 10 s, action 1 14 s; action 1's reply tells 1 nat, action 0's
    none; budget 20 s. At a top weight of 0.9 no probe (action 0, no reason); just under it
    the probe, action 1, 4 s dearer."""
    assert PROBE_BELOW == 0.9
    robot = _belief(tmp_path, unknown=0.0, probe=20.0)
    monkeypatch.setattr(robot, "information", lambda w, s, a, weights: 1.0 if a == 1 else 0.0)
    q = [{0: 10.0, 1: 14.0}, {0: 10.0, 1: 14.0}]
    action, _, reason = _decide(robot, monkeypatch, {"cooperative": 0.9, "lazy": 0.1}, q)
    assert action == 0 and reason == ""
    top = float(np.nextafter(0.9, 0.0))
    action, _, reason = _decide(robot, monkeypatch, {"cooperative": top, "lazy": 1 - top}, q)
    assert action == 1 and reason == "probe: 1.00 nats about the partner for 4.0 s"


def test_a_probe_may_be_an_action_of_a_lower_index_than_the_best(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The same as above with the indices swapped: action 1 10 s, action 0 14 s and telling 1
    nat: the probe is action 0, below the best action's index (every action but the best is a
    candidate, whatever its index)."""
    robot = _belief(tmp_path, unknown=0.0, probe=20.0)
    monkeypatch.setattr(robot, "information", lambda w, s, a, weights: 1.0 if a == 0 else 0.0)
    q = [{0: 14.0, 1: 10.0}, {0: 14.0, 1: 10.0}]
    top = float(np.nextafter(0.9, 0.0))
    action, _, reason = _decide(robot, monkeypatch, {"cooperative": top, "lazy": 1 - top}, q)
    assert action == 0 and reason == "probe: 1.00 nats about the partner for 4.0 s"


def test_off_every_members_model_the_fallback_says_so(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every member's values infinite (hopeless) or absent: no member has a say, the oracle
    robot's fallback moves and the reason starts "off every member's model: "."""
    robot = _belief(tmp_path, unknown=0.0)
    action, _, reason = _decide(robot, monkeypatch, {"cooperative": 0.6, "lazy": 0.4}, [{0: math.inf}, {}])
    assert reason.startswith("off every member's model: ")
    assert robot.last_decision is not None and robot.last_decision.partner == "a"
    assert action in PAPER.feasible_indices(FIRST, Agent.ROBOT)


def test_a_closed_world_holds_the_members_only(tmp_path: Path) -> None:
    """``unknown = 0``: no "none of them" hypothesis (uniform or learned), each member 1/n."""
    population = _members(tmp_path, a="cooperative", b="lazy")
    for open_world in ("uniform", "learned"):
        robot = BeliefRobot(population=population, splits="train", unknown=0.0, open_world=open_world)
        assert robot.posterior.types == ("cooperative", "lazy") and robot.posterior.learned is None
        assert robot.posterior.posterior() == pytest.approx({"cooperative": 0.5, "lazy": 0.5})
    learned = BeliefRobot(population=population, splits="train", unknown=0.1, open_world="learned")
    assert learned.posterior.learned is not None
    assert learned.posterior.posterior() == pytest.approx({"cooperative": 0.45, "lazy": 0.45, "learned": 0.1})


def test_the_belief_robot_refuses_the_human_seat_and_a_random_member(tmp_path: Path) -> None:
    robot = BeliefRobot(population=_members(tmp_path, a="cooperative"), splits="train")
    with pytest.raises(RobotError, match="robot seat only"):
        robot.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    with pytest.raises(RobotError, match="none of them"):
        BeliefRobot(population=_members(tmp_path, a="cooperative", r="random"), splits="train")


# ---- agents/headroom.py -----------------------------------------------------------------------


def _joint(pairs: list[list[tuple[int, int, float]]], terminal: set[int]) -> JointModel:
    """A hand-made joint model: per state, its pairs as (action, next state, seconds), certain.

    Pairs are numbered in order; a ``terminal`` pair completes the task (no transition);
    the re-draw is state 0 after 1 s.
    """
    world = World(TINY)
    flat = [p for state in pairs for p in state]
    t_start = [0]
    for k in range(len(flat)):
        t_start.append(t_start[-1] + (k not in terminal))
    live = [p for k, p in enumerate(flat) if k not in terminal]
    dynamics = Dynamics(
        t_start=np.array(t_start, dtype=np.int64),
        t_next=np.array([nxt for _, nxt, _ in live], dtype=np.int64),
        t_prob=np.ones(len(live)),
        t_tau=np.array([tau for _, _, tau in live]),
        regen_next=np.array([0], dtype=np.int64),
        regen_prob=np.array([1.0]),
        regen_tau=np.array([1.0]),
    )
    model = Model(
        packer=StatePacker(world),
        keys=np.arange(len(pairs), dtype=np.int64),
        pair_start=np.cumsum([0, *(len(s) for s in pairs)]).astype(np.int64),
        pair_action=np.array([a for a, _, _ in flat], dtype=np.int64),
        pair_terminal=np.array([k in terminal for k in range(len(flat))]),
        dynamics=[dynamics],
        n_layouts=1,
    )
    return JointModel.from_model(world, model)


def test_headroom_policy_ties_go_to_the_lowest_action_within_tie() -> None:
    """State 0: pair 0 is action 5, pair 1 action 2, both reach state 1 (which completes) in
    1 s: tied, the lowest *action* wins, pair 1 (not the first pair). 1e-6 s (TIE) apart
    they still tie (half of it here); 2e-6 apart the quicker one, action 5, wins."""

    def choice(slower: float) -> list[int]:
        model = _joint([[(5, 1, 1.0), (2, 1, 1.0 + slower)], [(0, 0, 0.0)]], terminal={2})
        return model.optimal_policy(0).tolist()

    assert choice(0.0) == [1, 2]
    assert choice(0.5e-6) == [1, 2]
    assert choice(2e-6) == [0, 2]


def test_headroom_policy_where_nothing_completes_takes_the_lowest_action() -> None:
    """State 1 is a trap (actions 4 and 1 loop on it, nothing completes): every option is
    infinite, and the lowest action index among them is taken, action 1 (pair 3)."""
    model = _joint([[(0, 1, 1.0), (3, 0, 1.0)], [(4, 1, 1.0), (1, 1, 2.0)]], terminal={1})
    choice = model.optimal_policy(0).tolist()
    assert choice[1] == 3
    assert choice[0] == 1  # the completing pair (0 s) beats the trap


def test_the_joint_model_holds_exactly_max_states_and_refuses_one_more() -> None:
    """``max_states``: "refuse beyond this many states". A model of n states builds under
    ``max_states = n`` and is refused under n - 1."""
    world = World(CROSSING)
    humans = [stationary_human(G, world)]
    n = JointModel(world, humans).n
    assert JointModel(world, humans, max_states=n).n == n
    with pytest.raises(OracleTooLarge, match=f"max_states={n - 1}"):
        JointModel(world, humans, max_states=n - 1)


def test_the_joint_models_failed_action_is_the_lowest_infeasible_one_and_only_when_asked() -> None:
    """``failed_actions``: per state the feasible robot actions and one failing one, the
    first infeasible index ("all failing actions lead to the same mid-cycle state");
    without it, the feasible actions only."""
    world = World(CROSSING)
    humans = [stationary_human(C, world)]
    for failed in (True, False):
        model = JointModel(world, humans, failed_actions=failed)
        for k, state in enumerate(model.states):
            feasible = world.feasible_indices(state, Agent.ROBOT)
            infeasible = [a for a in range(world.n_actions(Agent.ROBOT)) if a not in feasible]
            expected = sorted(feasible) + (infeasible[:1] if failed else [])
            got = model.actions[model.pair_state == k].tolist()
            assert sorted(got) == sorted(expected), (failed, k)


def test_extra_assumed_rows_come_after_cooperative_and_before_the_true_partners() -> None:
    """Rows: cooperative first, then the extra assumed ones, then every true partner once.
    X plays C's spec, so its row is C's hand-worked row (test_headroom.py): 0 with G, 450/h
    with C."""
    result = headroom(CROSSING, [("G", G), ("C", C)], assumed=[("X", C), ("G", G)])
    assert result.assumed == ("cooperative", "X", "G", "C") and result.true == ("G", "C")
    np.testing.assert_allclose(result.rates[1], [0.0, 3600 / 8])
    np.testing.assert_allclose(result.optimum, [3600 / 17.5, 3600 / 8])


# ---- training/headroom.py ---------------------------------------------------------------------


def test_the_heatmap_reads_n_a_in_grey_cells_and_titles_the_headroom(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Cooperative row 1/2 and 4/4 of the optima, a column without an optimum: cells "0.50",
    "1.00", "n/a" (grey, masked); headroom over column a: 1 - 0.5, titled "0.50"."""
    import matplotlib.pyplot as plt

    from hg_marl.agents.headroom import HeadroomResult

    result = HeadroomResult(
        scenario="hand",
        assumed=("cooperative",),
        true=("a", "b", "c"),
        rates=np.array([[1.0, 4.0, 0.0]]),
        optimum=np.array([2.0, 4.0, 0.0]),
        held_out=("a",),
        n_states=1,
        seconds=0.0,
    )
    figures: list[Any] = []
    real_close = plt.close

    def close(fig: Any = None) -> None:
        figures.append(fig)
        real_close(fig)

    monkeypatch.setattr(plt, "close", close)
    heatmap_png(result, tmp_path / "h.png")
    (fig,) = figures
    ax = fig.axes[0]
    assert [t.get_text() for t in ax.texts] == ["0.50", "1.00", "n/a"]
    assert ax.get_title() == "hand: adaptation headroom 0.50"
    image = ax.images[0]
    assert bool(np.ma.getmaskarray(image.get_array())[0, 2]) and not np.ma.getmaskarray(image.get_array())[0, :2].any()
    from matplotlib.colors import to_rgba

    assert tuple(image.cmap.get_bad()) == to_rgba("lightgrey")


def test_write_headroom_passes_the_budget_and_writes_nothing_when_refused(
    tmp_path: Path, capfd: pytest.CaptureFixture[str]
) -> None:
    """``**budget`` reaches the model (2 states is too few for the crossing: refused) and the
    folder is made only after the matrix is computed; ``progress=False`` draws no bar."""
    out = tmp_path / "report"
    with pytest.raises(OracleTooLarge, match="max_states=2"):
        write_headroom(CROSSING, [("G", G)], ["G"], out, progress=False, max_states=2)
    assert not out.exists()
    write_headroom(CROSSING, [("G", G)], ["G"], out, progress=False)
    assert capfd.readouterr().err == ""
    assert sorted(p.name for p in out.iterdir()) == ["headroom.csv", "headroom.json", "headroom.png"]


# ---- agents/compiled.py -----------------------------------------------------------------------


def test_a_table_of_exactly_max_keys_compiles_and_one_fewer_is_refused() -> None:
    """``MAX_KEYS``: "beyond it, a clear error". A table of exactly the budget's keys is
    within it; one key fewer is refused."""
    n = len(compile_human(PAPER, "lazy", cache=None))
    assert len(compile_human(PAPER, "lazy", cache=None, max_keys=n)) == n
    with pytest.raises(CompileError, match=f"budget of {n - 1} states"):
        compile_human(PAPER, "lazy", cache=None, max_keys=n - 1)


def test_a_human_who_ignores_the_robot_finds_every_state_whatever_it_saw() -> None:
    """``lazy`` does not read the robot's action, so its table is keyed without it: a batch
    told any robot action is found (no live fallback) and answers as told -1."""
    compiled = compile_human(PAPER, "lazy", cache=None)
    assert compiled.uses_robot_action is False
    moves = PAPER.feasible_indices(FIRST, Agent.ROBOT)  # the human answers after each robot move
    batch = BatchState.of([PAPER.step(FIRST, Agent.ROBOT, a).state for a in moves])
    told = np.array(moves)
    _, found = compiled.lookup(batch, told)
    assert found.tolist() == [True] * len(moves)
    a = compiled.act(batch, told, np.random.default_rng(5))
    b = compiled.act(batch, np.full(len(moves), -1), np.random.default_rng(5))
    assert a.tolist() == b.tolist() and compiled.fallbacks == 0


def test_the_distribution_of_a_state_outside_the_table_is_a_key_error() -> None:
    """The human's own offer never reaches its turn (test_batched.py): not in the table."""
    compiled = compile_human(PAPER, "lazy", cache=None)
    outside = FIRST._replace(offer_by=int(Agent.HUMAN), offer_obj=0)
    with pytest.raises(KeyError, match="not in the compiled table"):
        compiled.distribution(BatchState.of([outside]), np.array([-1]), 0)
    inside = compiled.distribution(BatchState.of([FIRST]), np.array([-1]), 0)
    assert sum(p for _, p in inside) == pytest.approx(1.0)


def test_a_scenario_whose_keys_overflow_64_bits_is_refused() -> None:
    """One object: radices 2**31 places, L locations, 3 offer states, 2 offered objects (none
    or the one), 1 robot action seen. L = 2**30 makes 6 * 2**61 = 1.5 * 2**63 keys, more
    than an int64 holds: refused. L = 2**28 makes 6 * 2**59 = 0.75 * 2**62: packed, the key
    of a state being its mixed-radix number (place weighs 1, location 2**31)."""

    def world(locations: int) -> Any:
        table = SimpleNamespace(n_places=2**31, n_objects=1, n_locations=locations)
        return SimpleNamespace(table=table, n_actions=lambda agent: 0, scenario=SimpleNamespace(name="huge"))

    with pytest.raises(CompileError, match="too many states to pack into 64-bit keys"):
        Packer(world(2**30))
    packer = Packer(world(2**28))
    assert packer.pack_one(State((5,), 7, -1, -1), -1) == 5 + 7 * 2**31


# ---- agents/compiled_robot.py -----------------------------------------------------------------


def test_stall_after_must_be_a_positive_number_of_turns() -> None:
    """K = 0 is refused; K = 1 is the smallest rule: one planned turn, then a stall move."""
    arrays = {"keys": np.zeros(0, dtype=np.int64), "actions": np.zeros(0, dtype=np.int64)}
    world = World(TINY)
    with pytest.raises(CompileError, match="stall_after"):
        CompiledRobot(world, arrays, stall_after=0)
    robot = compile_robot(world, cache=None, stall_after=1)
    assert _frozen_turns(robot, world, 2, lambda r: bool(r.stalled[0])) == [False, True]


def _frozen_turns(robot: Any, world: World, turns: int, read: Any) -> list[Any]:
    """``read(robot)`` after each of ``turns`` robot turns at one table whose state never changes."""
    state = world.initial_state(np.random.default_rng(11))
    robot.reset_rows(np.array([0]), np.random.default_rng(0))
    out = []
    for _ in range(turns):
        robot.act(BatchState.of([state]), np.array([-1]), np.random.default_rng(0))
        out.append(read(robot))
    return out


def test_an_empty_table_plans_every_state_live_and_counts_it() -> None:
    world = World(TINY)
    states = [world.initial_state(np.random.default_rng(seed)) for seed in (0, 1)]
    empty = {"keys": np.zeros(0, dtype=np.int64), "actions": np.zeros(0, dtype=np.int64)}
    robot = CompiledRobot(world, empty)
    out, found = robot.plan(BatchState.of(states))
    assert found.tolist() == [False, False]
    assert out.tolist() == [planner_action(world, s) for s in states]
    assert robot.fallbacks == 2


def test_a_robot_tables_disk_entry_is_keyed_by_its_budget(tmp_path: Path) -> None:
    """The budget decides between cold and canonical plans, so it is part of the entry's
    name: two budgets, two files named by their own keys."""
    world = World(TINY)
    for budget in (1000, 2000):
        compile_robot(world, cache=tmp_path, max_states=budget, stall_after=3)
    names = sorted(p.name for p in tmp_path.iterdir())
    expected = sorted(
        f"{world.scenario.name}-robot-{robot_cache_key(world, 'planner', 3, b)[:24]}.npz" for b in (1000, 2000)
    )
    assert names == expected and len(set(names)) == 2


def test_a_frozen_tables_unchanged_count_reads_the_turns_since_its_first() -> None:
    """``unchanged``: consecutive robot turns at which the state equals the previous turn's:
    0 at the first turn, then 1, 2, 3 (K = 3: the 4th turn takes the stall move)."""
    world = World(TINY)
    robot = compile_robot(world, cache=None, stall_after=3)
    assert _frozen_turns(robot, world, 4, lambda r: int(r.unchanged[0])) == [0, 1, 2, 3]
    assert bool(robot.stalled[0]) and int(robot.stall_count[0]) == 1
