"""The values round 84's missed planted bugs changed, pinned after the round.

Round 84 planted 16 bugs in sixteen gated modules, written blind; 12 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- the cooperative human "never depends on what it was asked before": its answer in a world
  is a fresh human's answer there, whatever world it answered in first (a property);
- the ``no_handover`` human is registered as ``no_handover`` and records that name in its
  decisions (the registry name a user typed);
- ``observe_move`` counts the partner's answer in "the robot's previous state after the
  robot's own action": a robot that drives to the handover place makes the partner answer
  in the context "robot at a handover place" (worked by hand on ``paper2015``);
- ``report.md``'s header counts the humans of the study's frame (worked by hand: one robot
  and three humans).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.cooperative import CooperativeHuman
from hg_marl.agents.partner_model import LearnedPartner, observe_move
from hg_marl.core import Agent, Kind, State, World
from hg_marl.policy import Turn
from hg_marl.training.report import markdown
from hg_marl.training.study import Actor, Study

PAPER = World("paper2015")
"""Places: spots 0-5 (the human reaches 3-5), the bin 6, the robot's hand 7, the human's hand 8;
robot locations 0-3, location 3 (``human_side``) the only handover place."""
HELD = State((8, 5, 0), 3, -1, -1)
"""Tape 0 in the human's hand, the robot at the handover place."""

# paper2015 with the trashbin within the human's reach too (same places, same state codes).
HUMAN_BIN = (
    (Path(__file__).resolve().parents[2] / "hg_marl" / "core" / "scenarios" / "paper2015.toml")
    .read_text()
    .replace('name = "paper2015"', 'name = "paper2015_human_bin"')
    .replace('robot_reach = ["bin_side"]\nhuman_reach = false', 'robot_reach = ["bin_side"]\nhuman_reach = true')
)


def test_a_cooperative_human_moved_to_another_world_answers_as_a_fresh_one_there(tmp_path: Path) -> None:
    """Property (the module docstring: "a warm instance answers exactly as a fresh one"): after
    answering at ``HELD`` in paper2015, its answer at the same state in a world where the
    human reaches the bin is a fresh human's answer there. The two worlds' fresh answers
    differ (so the memo of the first world cannot stand in for the second)."""
    assert "human_reach = true" in HUMAN_BIN.split("[[spots]]")[0]  # the variant was made
    path = tmp_path / "human_bin.toml"
    path.write_text(HUMAN_BIN)
    other = World(str(path))
    assert other.n_spots == PAPER.n_spots and other.n_bins == PAPER.n_bins  # HELD means the same there
    fresh_paper = CooperativeHuman().planned_action(PAPER, HELD)
    fresh_other = CooperativeHuman().planned_action(other, HELD)
    assert PAPER.actions(Agent.HUMAN)[fresh_paper] != other.actions(Agent.HUMAN)[fresh_other]
    warm = CooperativeHuman()
    assert warm.planned_action(PAPER, HELD) == fresh_paper
    assert warm.planned_action(other, HELD) == fresh_other
    assert warm.planned_action(PAPER, HELD) == fresh_paper  # and back again


def test_the_no_handover_human_records_its_registry_name_in_its_decisions() -> None:
    """Built by its registry name ``no_handover``, it reports that name as the deciding human."""
    human = make_human("no_handover")
    assert human.name == "no_handover"
    human.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    state = PAPER.initial_state(np.random.default_rng(0))
    human.act(Turn(PAPER, state, Agent.HUMAN, {}))
    assert human.last_decision["human"] == "no_handover"


def test_observe_move_counts_the_answer_in_the_state_after_the_robots_move() -> None:
    """By hand on paper2015: the robot starts at ``bin_side`` (location 0, no handover place)
    and drives to ``human_side`` (location 3, the handover place); the partner, empty-handed
    and offered nothing, then picks a tape. The answer is counted in the context (not holding,
    not offered, robot at a handover place, robot's kind goto): one pick."""
    first = PAPER.initial_state(np.random.default_rng(0))
    assert first.robot_at == 0 and first.offer_by < 0 and PAPER.holding(first, Agent.HUMAN) < 0
    goto = list(PAPER.action_names[Agent.ROBOT]).index("goto(human)")  # to the human: human_side
    moved = PAPER.step(first, Agent.ROBOT, goto)
    assert moved.ok and moved.state.robot_at == 3
    human = PAPER.actions(Agent.HUMAN)
    pick = next(
        i for i in PAPER.feasible_indices(moved.state, Agent.HUMAN) if human[i].kind is Kind.PICK
    )  # the tape on the human's side
    after = PAPER.step(moved.state, Agent.HUMAN, pick).state
    model = LearnedPartner()
    observe_move(model, PAPER, (first, goto), Turn(PAPER, after, Agent.ROBOT, {}, last_actions=(goto, pick)))
    assert model.counts == {(False, False, True, int(Kind.GOTO)): {int(Kind.PICK): 1.0}}


def test_the_report_header_counts_the_humans_of_the_frame() -> None:
    """By hand: robot A met humans h, k and m once each: "3 runs: 1 robots x 3 humans"."""
    study = Study(
        name="hand",
        path=Path("hand.toml"),
        robots=(Actor("A", label="A"),),
        humans=(Actor("h", label="h"), Actor("k", label="k"), Actor("m", label="m")),
        scenarios=("paper2015",),
        seeds=(0,),
        duration=60.0,
    )
    frame = pd.DataFrame(
        [
            {
                "robot": "A",
                "human": h,
                "scenario": "paper2015",
                "seed": 0,
                "score": 0.5,
                "oracle_rate": 100.0,
                "reference": "oracle",
            }
            for h in ("h", "k", "m")
        ]
    )
    agg = {
        "robots": {"A": {"iqm": 0.5, "iqm_ci": None, "mean": 0.5, "mean_ci": None, "runs": 3}},
        "improvement": {},
        "bootstrap": {"reps": 10, "poi_reps": 20, "seed": 0, "ci": 0.95, "seeds_per_task": 1, "flag": ""},
        "br_prox": [],
    }
    text = markdown(study, frame, agg, {"ran": 3, "reused": 0})
    assert "3 runs: 1 robots x 3 humans x 1 scenario(s) x 1 seeds, 60 simulated s each" in text
