"""The answer table asks the live human once per key (work counted, not timed), and the
canonical layouts are the full deal summed over interchangeable objects.

The first reference is a count: ``live_calls`` after asking for keys already answered
does not grow, and a mix of known and new keys asks only the new ones. The second is a
plain enumeration: every deal ``World.initial_state`` can make (``layout_distribution``)
mapped through ``Relabel.canonical`` and summed, on scenarios whose layout groups draw
fewer objects than they have spots (where ``(m - c)!`` is not 1).

The live answers read the budget on a schedule stated here, not taken from the code: one
reading before every fourth answer (answers 0, 4, 8, ...), and the resident memory only on
every 4096th answer (0, 4096, ...), a system call too dear to make on each reading.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.models.answers import AnswerTable, stationary_human
from hg_marl.agents.models.budget import Budget
from hg_marl.agents.models.layouts import canonical_layout_count, canonical_layouts, layout_distribution
from hg_marl.agents.models.packing import StatePacker
from hg_marl.agents.planner.space import Relabel
from hg_marl.core import Agent, World
from hg_marl.core.spec import AgentSpec
from hg_marl.envs.batched import BatchState


def test_known_keys_are_not_asked_again() -> None:
    world = World("paper2015")
    human = make_human("cooperative")
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    packer = StatePacker(world)
    table = AnswerTable(world, human, packer, arrays=False)
    states = [s for s, _ in layout_distribution(world)][:12]
    keys = np.unique(packer.pack(BatchState.of(states), np.full(len(states), -1)))
    table.ensure(keys[:8])
    assert table.live_calls == 8 and len(table.keys) == 8
    table.ensure(keys[:8])
    assert table.live_calls == 8 and len(table.keys) == 8
    table.ensure(keys)  # 8 known, 4 new
    assert table.live_calls == 12 and table.keys.tolist() == keys.tolist()


class RecordingBudget(Budget):
    """A budget that never refuses and records each reading's (phase, done, total, unit, memory).

    ``states`` keeps each reading's model states alongside (None where the phase gave none).
    """

    def __init__(self) -> None:
        super().__init__(None, None, None)
        self.readings: list[tuple[str, int, int | None, str, bool]] = []
        self.states: list[int | None] = []

    def check(
        self,
        phase: str,
        done: int,
        total: int | None = None,
        unit: str = "states",
        *,
        states: int | None = None,
        memory: bool = True,
    ) -> None:
        self.readings.append((phase, done, total, unit, memory))
        self.states.append(states)


def _answered(human_name: str, layouts: int, arrays: bool) -> tuple[AnswerTable, RecordingBudget, int]:
    """A table for ``human_name`` on roboergosum's first ``layouts`` layouts, before and after
    answering them under a recording budget: (table, budget, distinct keys)."""
    world = World("roboergosum")
    human = make_human(human_name)
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    packer = StatePacker(world)
    states = [s for s, _ in layout_distribution(world)][:layouts]
    keys = np.unique(packer.pack(BatchState.of(states), np.full(len(states), -1)))
    budget = RecordingBudget()
    table = AnswerTable(world, human, packer, budget=budget, arrays=arrays)
    table.ensure(keys)
    return table, budget, len(keys)


def test_live_answers_read_the_budget_every_fourth_answer_and_the_memory_every_4096th() -> None:
    # 4097 live answers (the lazy human, asked live with arrays=False): readings before
    # answers 0, 4, ..., 4096 (1025 of them), the memory read at 0 and 4096 alone
    table, budget, n_keys = _answered("lazy", 4097, arrays=False)
    assert n_keys == 4097
    assert table.live_calls == 4097
    unit = "partner answers of this step"
    expected = [("answers", i, 4097, unit, i in (0, 4096)) for i in range(0, 4097, 4)]
    assert len(budget.readings) == len(expected) == 1025
    # the first few differences only: pytest's diff of two long lists would take minutes
    wrong = [(got, want) for got, want in zip(budget.readings, expected, strict=True) if got != want]
    assert wrong[:3] == []
    assert [done for _, done, _, _, memory in budget.readings if memory] == [0, 4096]


@pytest.mark.parametrize(
    "scenario", ["generated:objects=3,spots=5,bins=1,seed=2", "generated:objects=4,spots=6,bins=2,seed=1"]
)
def test_canonical_layouts_are_the_full_deal_summed_by_symmetry(scenario: str) -> None:
    world = World(scenario)
    relabel = Relabel(world)
    assert relabel.active
    expected: dict[object, float] = {}
    for state, p in layout_distribution(world):
        key = relabel.canonical(state)[0]
        expected[key] = expected.get(key, 0.0) + p
    got = dict(canonical_layouts(world))
    assert got.keys() == expected.keys()
    for state, p in expected.items():
        assert got[state] == pytest.approx(p, rel=1e-12)
    assert sum(got.values()) == pytest.approx(1.0, rel=1e-12)


@pytest.mark.parametrize(
    ("scenario", "deals"),
    [
        # one class of 3 objects, one group drawing 3 of 5 spots: C(5, 3) = 10 spot sets
        ("generated:objects=3,spots=5,bins=1,seed=2", 10),
        # paper2015: one class of 3 tapes; 2 onto 3 spots (C(3, 2) = 3), then 1 onto 2 spots (2): 6
        ("paper2015", 6),
    ],
)
def test_the_canonical_deal_count_by_hand(scenario: str, deals: int) -> None:
    world = World(scenario)
    assert canonical_layout_count(world) == deals
    assert len(canonical_layouts(world)) == deals  # one class: each deal is its own table


def test_canonical_answers_read_the_budget_every_fourth_answer_and_the_memory_first() -> None:
    # The cooperative human is asked once per canonical key (a planner search each): a
    # reading before its answers 0, 4, 8, ... of the step, the memory read at answer 0 only
    # (every 4096th: this step has fewer).
    table, budget, n_keys = _answered("cooperative", 60, arrays=True)
    assert table.canonical is not None  # the path under test
    asked = table.live_calls
    assert 9 <= asked < n_keys  # some keys share a canonical one; enough for three readings
    unit = "partner answers of this step"
    assert budget.readings == [("answers", i, asked, unit, i == 0) for i in range(0, asked, 4)]


def test_a_partner_given_as_an_agent_spec_answers_with_its_parameters() -> None:
    # lazy with p_idle 0.5 as a spec (what a study's partner list holds), as text and as the
    # default: the spec's and the text's answers are one, and the default idles less
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    wait = world.n_actions(Agent.HUMAN) - 1

    def idle(human: object) -> float:
        return dict(stationary_human(human, world).distribution(world, state)).get(wait, 0.0)

    from_spec = idle(AgentSpec("lazy", {"p_idle": 0.5}))
    assert from_spec == idle("lazy:p_idle=0.5")
    assert from_spec >= 0.5 and idle("lazy") < from_spec


def test_answers_on_arrays_read_the_budget_once_before_the_batch() -> None:
    # a preference member has an array form: one reading, at 0 of the batch's keys, memory included
    table, budget, n_keys = _answered("preference:handover=1.0", 40, arrays=True)
    assert table.batch is not None and table.live_calls == 0
    assert budget.readings == [("answers", 0, n_keys, "partner answers on arrays", True)]


def test_an_equivariant_partner_counts_each_live_call_once_across_batches() -> None:
    """The cooperative human answers once per canonical key (relabelled states share its
    answers): over three batches the table's count is the canonical asker's own count,
    never its running total added again, and known keys add nothing."""
    world = World("paper2015")
    human = make_human("cooperative")
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    packer = StatePacker(world)
    table = AnswerTable(world, human, packer, arrays=True)
    assert table.canonical is not None
    states = [s for s, _ in layout_distribution(world)][:60]
    keys = np.unique(packer.pack(BatchState.of(states), np.full(len(states), -1)))
    counts = []
    for batch in (keys[:20], keys[:40], keys):
        table.ensure(batch)
        counts.append(table.live_calls)
        assert table.live_calls == table.canonical.live_calls
    assert 0 < counts[0] <= counts[1] <= counts[2] < len(keys)  # relabelled deals share keys
    table.ensure(keys)
    assert table.live_calls == counts[2]
