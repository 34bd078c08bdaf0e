"""Documented promises of the runner, two robots, family-out partners, batched table, world and adaptation, pinned.

Each test pins one rule a module's docstrings or comments state and no other test checked:
the runner's seed split, its decision numbering, its config's refusals and its summary's
missing mean; the hybrid robot's defaults, its charged decision time, its progress guard
(counted from zero at each reset) and a given learner kept with ``partner_features``; the
memory robot's model requirement, its seat and ``unstall`` refusals and the observation it
rebuilds; the family-out partners' idle mix, ``fo_mirror``'s echo, ``fo_shy``'s freeze and
the history cleared at reset; the batched table's memory bound, its reset counters, its
given states and its refusals; the world's memo-table size, bounded memo tables, read-only
masks and transition events; the adaptation protocol's defaults, its custom switches, its
rate curve and its printed table. Every expected value is worked by hand from the rule on
``paper2015`` (spots 0-5, the trashbin 6, the robot's hand 7, the human's hand 8; robot
locations bin_side 0 ... human_side 3, the only handover place; robot wait 17, human wait
30), restated from the docstring, or computed by a simpler reference in the test; each
test's comments say how its numbers follow.
"""

from __future__ import annotations

from types import SimpleNamespace
from typing import Any

import numpy as np
import pandas as pd
import pytest

from hg_marl.agents.habit import QLearner
from hg_marl.agents.humans.base import tidy_action
from hg_marl.agents.humans.family_out import AfterWaits, FreezeOnOffer, Mirror, Shy
from hg_marl.agents.meta.entropy_cost import EntropyAndCostCriterion
from hg_marl.agents.robots.hybrid import HybridRobot
from hg_marl.agents.robots.memory import MemoryRobot
from hg_marl.core import Agent, Event, State, World
from hg_marl.core.errors import ConfigError, RobotError
from hg_marl.core.world import CACHE_BYTES, cache_entries
from hg_marl.envs.batched import BatchedTable, BatchState, check_batch
from hg_marl.policy import Turn
from hg_marl.training.adaptation import (
    ROBOTS,
    SWITCHES,
    AdaptationConfig,
    Switch,
    adaptation_table,
    rate_curve,
)
from hg_marl.training.runner import COLUMNS, RunConfig, run, summarise

PAPER = World("paper2015")
FIRST = State((0, 4, 2), 0)
"""The first layout of seed 0: tape1 on mat_left, tape2 on human_mat_1, tape3 on mat_right; robot at bin_side."""
ROBOT_WAIT, HUMAN_WAIT = 17, 30
GOTO_TAPE1, GOTO_HUMAN = 12, 16
PICK_TAPE2_H = 1
"""The human's pick(tape2) (the human's first actions are named as the robot's)."""


def _robot_turn(world: World, state: State, observation: np.ndarray | None = None) -> Turn:
    facts = world.facts(state) if observation is None else observation
    obs = {"observation": facts, "action_mask": world.mask(state, Agent.ROBOT)}
    return Turn(world, state, Agent.ROBOT, obs)


# ---- training/runner.py ----------------------------------------------------------------------


class _Drawing:
    """Always ``wait``; records the first draw of the generator ``reset`` hands it."""

    def __init__(self) -> None:
        self.draw = -1.0

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.n = world.n_actions(agent)
        self.draw = float(rng.random())

    def act(self, turn: Turn) -> int:
        return self.n - 1


def test_runner_hands_each_actor_its_own_child_of_the_seed_sequence() -> None:
    # module docstring: one SeedSequence(seed) split into the environment's seed and the two
    # actors' generators, in that order: the robot's is the second child, the human's the third
    robot, human = _Drawing(), _Drawing()
    run(robot, human, RunConfig(duration=10.0, seed=5, max_decisions=1))
    _, robot_seq, human_seq = np.random.SeedSequence(5).spawn(3)
    assert robot.draw == np.random.default_rng(robot_seq).random()
    assert human.draw == np.random.default_rng(human_seq).random()


def test_runner_numbers_decisions_from_zero_one_row_each() -> None:
    # "Every robot decision becomes one row": 4 decisions (max_decisions) are rows 0, 1, 2, 3,
    # each naming the human's answer (a waiting human: its wait, index 30)
    log = run(_Drawing(), _Drawing(), RunConfig(duration=100.0, seed=0, max_decisions=4)).log
    assert log["decision"].tolist() == [0, 1, 2, 3]
    assert log["human_action"].tolist() == [HUMAN_WAIT] * 4
    assert log["human_action_name"].tolist() == ["wait"] * 4


@pytest.mark.parametrize(
    ("params", "field"),
    [({"duration": 0.0}, "duration"), ({"seed": -1}, "seed"), ({"max_decisions": 0}, "max_decisions")],
)
def test_run_config_refuses_a_non_positive_duration_a_negative_seed_and_zero_decisions(
    params: dict[str, Any], field: str
) -> None:
    # duration positive, seed minimum 0, max_decisions minimum 1 (None is the only way to say "no cap")
    with pytest.raises(ConfigError, match=field):
        RunConfig(**params)


def test_summary_human_as_expected_is_none_when_no_row_was_predicted() -> None:
    # _mean_or_none: the mean of the non-missing values, None when there are none (JSON has no
    # NaN) - also for a non-empty log whose decisions predicted nothing
    log = pd.DataFrame(
        {c: [None, None] for c in COLUMNS}
        | {
            "reward": [0.0, 1.0],
            "failed": [False, False],
            "time": [1.0, 2.0],
            "expert": ["habit", "habit"],
            "weight_amplitude": [0.0, 0.0],
        }
    )
    summary = summarise(log, 2.0)
    assert summary["human_as_expected"] is None
    assert summary["tasks_solved"] == 1 and summary["planner_share"] == 0.0


# ---- agents/robots/hybrid.py -----------------------------------------------------------------


def test_hybrid_defaults_are_the_documented_best_settings() -> None:
    # class docstring: entropy_and_cost over a tabular habit learning on canonical states;
    # partner_aware and partner_features off
    robot = HybridRobot()
    assert type(robot.meta.criterion) is EntropyAndCostCriterion
    assert robot.q_config.features == "tabular"
    assert robot.share_objects is True
    assert robot.partner_aware is False and robot.partner_model is None


def test_hybrid_charges_the_habit_cost_plus_the_planners_when_consulted() -> None:
    # "The decision time charged is the habit's cost plus, when it was consulted, the planner's":
    # default CostModel: habit 1 ms, planner 0.05 s + 0.5 ms per node
    planner = HybridRobot(criterion="planner")
    planner.reset(PAPER, Agent.ROBOT, np.random.default_rng(0))
    planner.act(_robot_turn(PAPER, FIRST))
    rec = planner.last_decision
    assert rec is not None and rec.planner_consulted and rec.planner_nodes > 0
    assert rec.decision_time == pytest.approx(0.001 + 0.05 + 5e-4 * rec.planner_nodes, rel=1e-12)
    habit = HybridRobot(criterion="habit")
    habit.reset(PAPER, Agent.ROBOT, np.random.default_rng(0))
    habit.act(_robot_turn(PAPER, FIRST))
    rec = habit.last_decision
    assert rec is not None and not rec.planner_consulted and rec.decision_time == 0.001


def _experts(robot: HybridRobot, turns: int) -> list[tuple[str, int, str]]:
    out = []
    for _ in range(turns):
        action = robot.act(_robot_turn(PAPER, FIRST))
        rec = robot.last_decision
        assert rec is not None
        out.append((rec.expert, action, rec.reason))
    return out


def test_hybrid_guard_fires_after_k_unchanged_turns_counted_afresh_at_reset() -> None:
    # K = 12: at one unchanged state turns 1-12 (unchanged 0..11) are the habit's, turn 13 the
    # guard's: the first feasible non-wait move in index order at FIRST, goto(tape1) = 12,
    # logged "no_progress". A reset is a new run: 12 more turns before the guard again.
    robot = HybridRobot(criterion="habit")
    robot.reset(PAPER, Agent.ROBOT, np.random.default_rng(0))
    first = _experts(robot, 13)
    assert [e for e, _, _ in first[:12]] == ["habit"] * 12
    assert first[12] == ("guard", GOTO_TAPE1, "no_progress")
    robot.reset(PAPER, Agent.ROBOT, np.random.default_rng(0))
    again = _experts(robot, 13)
    assert [e for e, _, _ in again[:12]] == ["habit"] * 12 and again[12][0] == "guard"


def test_hybrid_keeps_a_given_learner_when_partner_features_grow_the_state() -> None:
    # _reset: the habit's state grows by the partner model's 2 verdicts only for a learner it
    # builds itself; a learner handed over is the caller's and is kept
    given = QLearner(PAPER.n_facts + 2, PAPER.n_actions(Agent.ROBOT))
    robot = HybridRobot(criterion="habit", learner=given, partner_features=True)
    robot.reset(PAPER, Agent.ROBOT, np.random.default_rng(0))
    assert robot.learner is given
    robot.act(_robot_turn(PAPER, FIRST))
    assert robot.learner is given
    built = HybridRobot(criterion="habit", partner_features=True)
    built.reset(PAPER, Agent.ROBOT, np.random.default_rng(0))
    assert built.learner is not None and built.learner.n_facts == PAPER.n_facts + 2


# ---- agents/robots/memory.py -----------------------------------------------------------------


class _RecordingNet:
    """Prefers wait; records every observation it is fed."""

    def __init__(self) -> None:
        self.seen: list[np.ndarray] = []

    def initial(self, n: int) -> np.ndarray:
        return np.zeros((n, 1))

    def step(self, obs: np.ndarray, h: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        self.seen.append(obs.copy())
        logits = np.zeros((1, PAPER.n_actions(Agent.ROBOT)))
        logits[0, ROBOT_WAIT] = 1.0
        return logits, h


@pytest.mark.parametrize("both", [False, True])
def test_memory_robot_needs_exactly_one_of_a_model_file_and_a_net(both: bool) -> None:
    # (path is None) == (net is None): neither, or both at once, is refused
    kwargs: dict[str, Any] = {"path": "model.json", "net": _RecordingNet()} if both else {}
    with pytest.raises(RobotError, match="needs a trained model"):
        MemoryRobot(**kwargs)


def test_memory_robot_refuses_a_negative_unstall_and_the_human_seat() -> None:
    # unstall: minimum 0 (0 plays the policy as trained); the robot seat only
    with pytest.raises(RobotError, match="unstall"):
        MemoryRobot(net=_RecordingNet(), unstall=-1)
    with pytest.raises(RobotError, match="robot seat only"):
        MemoryRobot(net=_RecordingNet()).reset(PAPER, Agent.HUMAN, np.random.default_rng(0))


def test_memory_robot_reads_the_facts_only_from_a_longer_observation() -> None:
    # "the facts, then the interaction history": the facts are the observation's first n_facts
    # entries (the env's history option appends more); with history 0 nothing follows them
    net = _RecordingNet()
    robot = MemoryRobot(net=net, history=0)
    robot.reset(PAPER, Agent.ROBOT, np.random.default_rng(0))
    facts = np.asarray(PAPER.facts(FIRST))
    longer = np.concatenate([facts, np.ones(7, dtype=facts.dtype)])
    assert robot.act(_robot_turn(PAPER, FIRST, longer)) == ROBOT_WAIT
    assert robot.last_obs is not None and robot.last_obs.tolist() == facts.tolist()
    assert net.seen[0].shape == (1, PAPER.n_facts) and net.seen[0][0].tolist() == facts.tolist()


# ---- agents/humans/family_out.py -------------------------------------------------------------

OFFERED = State((7, 4, 2), 3, int(Agent.ROBOT), 0)
"""The robot at human_side holding out tape1; tape2 on human_mat_1, tape3 on mat_right."""


def test_stationary_partner_mixes_its_rule_with_wait_at_p_idle() -> None:
    # _Stationary.distribution: the rule's action at 1 - p_idle, wait at p_idle; a rule that
    # says wait is certain. FreezeOnOffer at FIRST tidies: pick(tape2) (out of the robot's
    # reach from anywhere); while the robot offers it waits.
    human = FreezeOnOffer(p_idle=0.25)
    assert sorted(human.distribution(PAPER, FIRST)) == [(PICK_TAPE2_H, 0.75), (HUMAN_WAIT, 0.25)]
    assert human.distribution(PAPER, OFFERED) == [(HUMAN_WAIT, 1.0)]


def test_mirror_echoes_the_kind_of_the_robots_action() -> None:
    # no robot action yet: wait; the robot waits with other moves open: wait; the robot
    # offers tape1: take(tape1) = 9; the robot works (goto): its own tidying move, pick(tape2)
    mirror = Mirror()
    assert mirror.rule(PAPER, FIRST, -1) == HUMAN_WAIT
    assert mirror.rule(PAPER, FIRST, ROBOT_WAIT) == HUMAN_WAIT
    assert mirror.rule(PAPER, OFFERED, 6) == 9
    assert mirror.rule(PAPER, FIRST, GOTO_HUMAN) == PICK_TAPE2_H


def test_shy_freezes_at_the_handover_place_and_tidies_away_from_it() -> None:
    # robot at human_side (the handover place, with moves open): wait; robot at bin_side:
    # its tidying without handing over, pick(tape2)
    shy = Shy()
    near = FIRST._replace(robot_at=3)
    assert shy.rule(PAPER, near, -1) == HUMAN_WAIT
    assert shy.rule(PAPER, FIRST, -1) == tidy_action(PAPER, FIRST, give=False) == PICK_TAPE2_H


def _after_waits_turn(robot_move: int) -> Any:
    return SimpleNamespace(world=PAPER, state=OFFERED, last_actions=(robot_move, -1), agent=Agent.HUMAN)


def test_after_waits_forgets_the_robots_moves_at_reset() -> None:
    # "the history is cleared in reset": two robot waits, then a new run whose first robot move
    # is the offer: no two waits just before it in this run, so no take (it tidies: pick(tape2));
    # the same three moves within one run end in take(tape1) = 9
    human = AfterWaits()
    human.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    for _ in range(2):
        human.choose(_after_waits_turn(ROBOT_WAIT))
    assert human.choose(_after_waits_turn(6)) == 9
    human.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    for _ in range(2):
        human.choose(_after_waits_turn(ROBOT_WAIT))
    human.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    assert human.choose(_after_waits_turn(6)) == PICK_TAPE2_H


def test_historied_partner_idles_at_p_idle_one_and_logs_the_action_it_takes() -> None:
    # act: the rule's action replaced by wait with probability p_idle (1: always), and
    # last_decision names the partner and the action taken
    human = AfterWaits(p_idle=1.0)
    human.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    assert human.choose(_after_waits_turn(GOTO_HUMAN)) == PICK_TAPE2_H  # the rule alone
    assert human.act(_after_waits_turn(GOTO_HUMAN)) == HUMAN_WAIT
    assert human.last_decision == {"human": "fo_after_waits", "action": "wait"}


# ---- hg_marl/envs/batched.py -----------------------------------------------------------------


class _Always:
    """A partner that plays one action index on every table."""

    def __init__(self, action: int) -> None:
        self.action = action

    def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        return np.full(len(batch), self.action, dtype=np.int64)


def test_check_batch_accepts_a_batch_that_exactly_fits_the_memory_limit() -> None:
    # per table on paper2015, restated from check_batch: 8 (objects + 16) + 2 facts +
    # 2 (human actions + 1) + 128 = 8 * 19 + 2 * 24 + 2 * 32 + 128 = 392 bytes; two tables 784.
    # "fit memory_limit bytes": 784 fits, 783 does not
    assert check_batch(PAPER, 2, memory_limit=784) == 2
    with pytest.raises(ConfigError, match="num_envs"):
        check_batch(PAPER, 2, memory_limit=783)


def test_batched_reset_zeroes_every_counter_of_the_previous_episode() -> None:
    # a clean table (every tape in the trashbin, 6) solved by the robot's wait: one task; a
    # goto(human) of 3 s of work on the other table; then reset: every counter reads 0
    env = BatchedTable(_Always(HUMAN_WAIT), 2, PAPER, continuing=True, max_cycles=None)  # type: ignore[arg-type]
    clean = State((6, 6, 6), 0)
    env.reset(seed=0, options={"states": [clean, FIRST]})
    env.step(np.array([ROBOT_WAIT, GOTO_HUMAN]))
    assert env.tasks_solved.tolist() == [1, 0] and env.effort[1, 0] == 3.0 and env.cycles.tolist() == [1, 1]
    env.reset(seed=1)
    assert env.clock.tolist() == [0.0, 0.0] and env.cycles.tolist() == [0, 0]
    assert env.tasks_solved.tolist() == [0, 0]
    assert not env.effort.any() and not env.idle.any()


def test_batched_reset_starts_from_the_given_states_and_refuses_a_wrong_count() -> None:
    # options={"states": [...]}: one state per table, observed as the world's facts of each
    env = BatchedTable(_Always(HUMAN_WAIT), 2, PAPER)  # type: ignore[arg-type]
    with pytest.raises(ConfigError, match="expected 2 states, got 1"):
        env.reset(seed=0, options={"states": [FIRST]})
    other = State((1, 5, 0), 2)
    obs, _ = env.reset(seed=0, options={"states": [FIRST, other]})
    assert obs[0].tolist() == PAPER.facts(FIRST).tolist() and obs[1].tolist() == PAPER.facts(other).tolist()


@pytest.mark.parametrize(
    ("params", "field"),
    [
        ({"time_budget": 0.0}, "time_budget"),
        ({"effort_weight": -0.1}, "effort_weight"),
        ({"autoreset_mode": "final"}, "autoreset_mode"),
        ({"max_cycles": 0}, "max_cycles"),
    ],
)
def test_batched_table_refuses_out_of_range_settings(params: dict[str, Any], field: str) -> None:
    # a positive finite time budget, a non-negative effort weight, next_step or same_step, max_cycles >= 1
    with pytest.raises(ConfigError, match=field):
        BatchedTable(_Always(HUMAN_WAIT), 1, PAPER, **params)  # type: ignore[arg-type]


# ---- hg_marl/core/world.py -------------------------------------------------------------------


def test_memo_tables_hold_the_entries_cache_bytes_allows_for_the_larger_action_set() -> None:
    # paper2015: 3 objects, 24 facts, 18 robot and 31 human actions: an entry is at most
    # 256 + 24 + 31 + 16 * 3 = 359 bytes, so 2**26 // 359 = 186932 entries (186932 * 359 =
    # 67108588 <= 67108864 < 67108947); a huge entry still leaves the floor of 1000
    assert CACHE_BYTES == 2**26
    assert PAPER.cache_limit == 186932
    assert cache_entries(10**6, 0, 0) == 1000


def test_memo_tables_are_cleared_once_over_their_limit_and_answer_alike() -> None:
    # "Entries each memo table may hold before it is cleared": with a limit of 2 no table
    # grows past 3 entries over 6 distinct states, and every answer is still the rule's
    world = World("paper2015")
    world.cache_limit = 2
    states = [State(where, at) for where in ((0, 4, 2), (1, 5, 0)) for at in range(3)]
    for state in states:
        assert world.facts(state).tolist() == world.compute_facts(state).tolist()
        assert np.flatnonzero(world.mask(state, Agent.ROBOT)).tolist() == world.feasible_indices(state, Agent.ROBOT)
        world.step(state, Agent.ROBOT, ROBOT_WAIT)
        sizes = (len(world._facts_cache), len(world._mask_cache[0]), len(world._step_cache))
        assert max(sizes) <= 3, sizes
    assert len(world._facts_cache) < len(states)


def test_cached_masks_are_read_only() -> None:
    # mask: "Memoised, read-only int8 action mask": a caller cannot corrupt the cache
    mask = PAPER.mask(FIRST, Agent.HUMAN)
    assert mask.dtype == np.int8 and not mask.flags.writeable
    with pytest.raises(ValueError):
        mask[0] = 1


def test_transitions_tell_the_offer_the_take_the_move_and_the_completion() -> None:
    # _outcome's events by hand: the human (tape2 in hand, 8) offers it to the robot at
    # human_side; the robot takes it; from bin_side a goto(human) moves it to human_side;
    # a robot wait on a clean table completes the task with reward 1
    held = State((0, 8, 2), 3)
    give = PAPER.step(held, Agent.HUMAN, 7)
    assert give.events == (Event("offered", "human", "tape2"),)
    take = PAPER.step(give.state, Agent.ROBOT, 10)
    assert take.events == (Event("took", "robot", "tape2"),) and take.state.where == (0, 7, 2)
    goto = PAPER.step(FIRST, Agent.ROBOT, GOTO_HUMAN)
    assert goto.events == (Event("moved", "robot", "", "human_side"),) and goto.state.robot_at == 3
    done = PAPER.step(State((6, 6, 6), 0), Agent.ROBOT, ROBOT_WAIT)
    assert done.reward == 1.0 and done.events == (Event("completed", "robot", "", "task"),)


# ---- training/adaptation.py ------------------------------------------------------------------


def test_adaptation_protocol_defaults_are_the_module_constants() -> None:
    # 1500 s runs, the first change at 600 s, a 300 s window, 10 seeds, every switch and robot;
    # adversarial_and_back returns to the cooperative human 300 s after it left it
    c = AdaptationConfig()
    assert (c.scenario, c.seeds, c.duration, c.window) == ("paper2015", 10, 1500.0, 300.0)
    assert c.switches == ("lazy", "no_handover", "noisy", "adversarial_and_back") and c.robots == tuple(ROBOTS)
    assert SWITCHES["lazy"] == Switch(("cooperative", "lazy"), (600.0,))
    assert SWITCHES["adversarial_and_back"].at == (600.0, 900.0)


def test_a_custom_switch_takes_the_place_of_a_built_in_one_of_the_same_label() -> None:
    # switch(label): custom first, then SWITCHES
    short = Switch(("cooperative", "lazy"), (50.0,))
    config = AdaptationConfig(custom={"lazy": short})
    assert config.switch("lazy") is short
    assert config.switch("noisy") is SWITCHES["noisy"]


def test_rate_curve_counts_simultaneous_completions_and_holds_after_the_last() -> None:
    # two tasks completed at 100 s: the count rises linearly from 0 at t = 0 to 2 at 100 s and
    # stays 2. Window 300 s, tasks/h = count in (t - 300, t] * 12:
    # t = 50: 1 -> 12; t = 100: 2 -> 24; t = 350: 2 - 1 = 1 -> 12; t = 450: 2 - 2 = 0 -> 0
    log = pd.DataFrame({"time": [100.0, 100.0, 250.0], "reward": [1.0, 1.0, 0.0]})
    curve = rate_curve(log, np.array([50.0, 100.0, 350.0, 450.0]), window=300.0)
    assert curve.tolist() == pytest.approx([12.0, 24.0, 12.0, 0.0])


def test_adaptation_table_lists_every_oracle_and_prints_recovery_in_whole_seconds() -> None:
    # header: the oracles joined by ", " at one decimal; recovery: 0 decimals (95.4 -> 95,
    # 90.2 -> 90, 100.6 -> 101); recovered runs as k/n
    summary = {
        "seeds": 3,
        "duration": 1500.0,
        "oracle_rate_per_hour": {"cooperative": 72.0, "lazy": 18.5},
        "results": {
            "lazy": {
                "robots": {
                    "planner": {
                        "tasks_lost": {"mean": 2.0, "low": 1.5, "high": 2.5},
                        "time_to_recover": {"mean": 95.4, "low": 90.2, "high": 100.6},
                        "recovered_runs": 2,
                        "runs": 3,
                    }
                }
            }
        },
    }
    lines = adaptation_table(summary).splitlines()
    assert lines[0] == "adaptation: 3 seeds, 1500 s runs; oracle tasks/h: cooperative 72.0, lazy 18.5"
    assert lines[3].split() == ["lazy", "planner", "2.0", "[1.5,", "2.5]", "95", "[90,", "101]", "2/3"]
