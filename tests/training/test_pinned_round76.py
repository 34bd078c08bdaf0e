"""The values round 76's missed planted bugs changed, pinned after the round.

Round 76 planted 16 bugs in sixteen gated modules, written blind; 12 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- a planner's human model with ground actions blocked is "the same model with extra
  ground actions ruled out": an idling human (``p_idle``) still idles with the same
  probability, so its choices are still the two-set expectimax distribution;
- the robot's view reports in ``info["human_failed"]`` whether the *human's* action of
  the cycle failed (an infeasible action fails), whatever the robot's action did;
- behaviour cloning refuses trace files whose name lists differ ("files from different
  scenarios, seats or name lists"), the action names included;
- a callback of period ``freq`` fires when the step count reaches the next multiple of
  ``freq`` above the count at its previous firing, however many multiples one jump of the
  count crossed: no second firing before that multiple.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.planner.models import HUMAN_KINDS, RestrictedHuman
from hg_marl.agents.views import RobotView
from hg_marl.core import Agent, Kind, World
from hg_marl.policy import Turn
from hg_marl.training.baselines.bc import load_traces
from tests.training.test_pinned_baselines_callbacks_gate import _Fires, _Model, _start, _steps

WORLD = World("paper2015")


# -- the planner's human model: blocking keeps the idling probability ----------------------


def test_a_blocked_idling_human_still_idles_with_its_probability() -> None:
    # "does nothing with probability p_idle, else acts as the restricted cooperative human";
    # blocking one ground action rules that action out and changes nothing else
    take = next(a for a in WORLD.actions(Agent.HUMAN) if a.kind is Kind.TAKE)
    model = RestrictedHuman("cooperative", HUMAN_KINDS, 0.3).with_blocked(frozenset({take}))
    assert model.p_idle == 0.3 and model.stochastic
    assert model.blocked == frozenset({take})
    wait = WORLD.n_actions(Agent.HUMAN) - 1
    take_index = WORLD.index(Agent.HUMAN, take)
    choices = model.choices(WORLD, WORLD.initial_state(np.random.default_rng(0)), [take_index, 0, wait])
    # worked by hand: (0.3, wait alone), then (0.7, the candidates left once the take is ruled out)
    assert [p for p, _ in choices] == pytest.approx([0.3, 0.7])
    assert choices[0][1] == (wait,)
    assert take_index not in choices[1][1] and wait in choices[1][1]


# -- the robot's view: human_failed is the human's failure ----------------------------------


class _Scripted:
    """A partner that plays its seat's wait, or the first action its mask rules out (which fails)."""

    def __init__(self, fail: bool) -> None:
        self.fail = fail

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.world, self.agent = world, agent

    def act(self, turn: Turn) -> int:
        if self.fail:
            return int(np.flatnonzero(np.asarray(turn.mask) == 0)[0])
        return _wait(self.world, self.agent)


def _wait(world: World, agent: Agent) -> int:
    return next(i for i, a in enumerate(world.actions(agent)) if a.kind is Kind.WAIT)


@pytest.mark.parametrize(("robot_fails", "human_fails"), [(False, True), (True, False)])
def test_the_robot_views_human_failed_is_the_humans_failure(robot_fails: bool, human_fails: bool) -> None:
    # waiting is always feasible and an action the mask rules out fails: one seat fails, the other not
    view = RobotView("paper2015", human=_Scripted(human_fails))
    view.reset(seed=0)
    robot = int(np.flatnonzero(~view.action_masks())[0]) if robot_fails else _wait(view.world, Agent.ROBOT)
    _, _, _, _, info = view.step(robot)
    assert bool(info["failed"]) is robot_fails
    assert bool(info["human_failed"]) is human_fails


# -- behaviour cloning: traces with other action names are refused --------------------------


def _trace(path: Path, action_names: list[str]) -> Path:
    """A one-turn human trace of ``paper2015`` (the human waits) with ``action_names`` in its header."""
    n = WORLD.n_actions(Agent.HUMAN)
    head: dict[str, Any] = {
        "type": "header",
        "format": "hg_marl.trace",
        "version": 1,
        "episode": 0,
        "scenario": "paper2015",
        "seat": "human",
        "actor": "hand",
        "fact_names": list(WORLD.fact_names),
        "action_names": action_names,
        "meta": {},
    }
    step = {
        "type": "step",
        "step": 0,
        "clock": 0.0,
        "tasks_solved": 0,
        "facts": [0] * WORLD.n_facts,
        "mask": [0] * (n - 1) + [1],
        "action": n - 1,
    }
    path.write_text(json.dumps(head) + "\n" + json.dumps(step) + "\n", encoding="utf-8")
    return path


def test_traces_with_other_action_names_are_refused(tmp_path: Path) -> None:
    names = list(WORLD.action_names[Agent.HUMAN])
    first = _trace(tmp_path / "a.jsonl", names)
    same = _trace(tmp_path / "b.jsonl", names)
    assert load_traces([first, same]).actions.tolist() == [len(names) - 1] * 2  # the control: same names load
    renamed = _trace(tmp_path / "c.jsonl", [*names[:-1], "idle"])
    with pytest.raises(ValueError, match=r"c\.jsonl: episode 0 is from 'paper2015' \(human\), not 'paper2015'"):
        load_traces([first, renamed])


# -- the callbacks' schedule: one firing per reached multiple -------------------------------


def test_a_jump_over_several_multiples_fires_once_and_waits_for_the_next_multiple() -> None:
    # period 100 from 0: the jump to 250 crosses 100 and 200 and fires once; the next
    # multiple above 250 is 300, so 260 and 299 fire nothing and 300 fires
    model = _Model()
    callback = _Fires(100)
    _start(callback, model)
    assert _steps(callback, model, [250, 260, 299, 300, 310]) == [True] * 5
    assert callback.fired == [250, 300]
