"""The values round 87's missed planted bugs changed, pinned after the round.

Round 87 planted 16 bugs in sixteen gated modules, written blind; 12 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- a ``memory`` model file is loaded under the option the caller names: ``load_memory``'s
  ``what`` is the user's option for messages (``load_model_file``'s contract), so a missing
  file is refused naming that option, not ``--model``;
- a ``MetaController`` built with no criterion arbitrates with ``random``, the default its
  constructor documents (the floor criterion, a coin), not with a filtered one;
- a play session counts a person's give or take by whether *the person's* move failed: a
  feasible move always succeeds (the mask is the preconditions), so every give the
  person makes is counted, even after the robot's own move failed;
- the library RecurrentPPO baseline's config refuses ``threads=0`` as it refuses every
  other count below 1 (torch cannot run on zero threads), naming the field.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.memory_policy import load_memory
from hg_marl.agents.meta.coin import RandomCriterion
from hg_marl.agents.meta.controller import MetaController
from hg_marl.core import Agent
from hg_marl.core.errors import ConfigError, ModelFileError
from hg_marl.training.baselines.recurrent_ppo_sb3 import RecurrentSb3Config
from hg_marl.training.play.session import PlaySession
from tests.play.reference import person_choice


def test_a_memory_file_refusal_names_the_option_the_caller_gave(tmp_path: Path) -> None:
    # load_memory(path, what) passes ``what``, the user's option, to every message: a file that
    # is not there is refused as "<what> <path>: ...", here under --partner-model.
    missing = tmp_path / "absent.json"
    with pytest.raises(ModelFileError) as info:
        load_memory(missing, what="--partner-model")
    message = str(info.value)
    assert message.startswith(f"--partner-model {missing}")
    assert "--model " not in message


def test_a_meta_controller_built_without_a_criterion_uses_the_random_one() -> None:
    # The constructor's documented default is criterion="random": the coin of agents/meta/coin.py.
    controller = MetaController()
    assert isinstance(controller.criterion, RandomCriterion)
    assert controller.criterion.name == "random"


class _FailsBeforeAGive:
    """The session's planner robot, except that it fails its move whenever the person could give.

    An infeasible move fails and changes nothing but the clock (a pending offer by the person
    lapses), so the person can still give after it: the give then follows a failed robot move.
    """

    name = "fails_before_a_give"

    def __init__(self, inner: Any) -> None:
        self.inner = inner
        self.failed_before_a_give = 0

    def reset(self, *args: Any, **kwargs: Any) -> None:
        """The inner robot was reset by the session."""

    def act(self, turn: Any) -> int:
        world, state = turn.world, turn.state
        names = world.action_names[Agent.HUMAN]
        human_mask = world.mask(state, Agent.HUMAN)
        if any(ok and names[i].startswith("give(") for i, ok in enumerate(human_mask)):
            self.failed_before_a_give += 1
            # the first action the robot's mask rules out: by the rules its preconditions fail
            return int((~np.asarray(turn.mask, dtype=bool)).nonzero()[0][0])
        return int(self.inner.act(turn))


def test_a_persons_give_after_a_failed_robot_move_is_counted() -> None:
    # The person plays feasible moves only (the session refuses the others) and a feasible move
    # succeeds, so each give or take the person plays is a handover of theirs, counted whatever
    # the robot's own move before it did. The robot fails its move every time the person could
    # give, so every give the person makes follows a failed robot move.
    session = PlaySession(player="p", seed=0)
    robot = _FailsBeforeAGive(session.robot)
    session.robot = robot
    gave = took = 0
    for _ in range(200):
        names = [c.name for c in session.choices()]
        move = next((n for n in names if n.startswith("give(")), None) or person_choice(names)
        session.play(move)
        gave += move.startswith("give(")
        took += move.startswith("take(")
        if gave >= 2:
            break
    assert gave >= 2 and robot.failed_before_a_give >= gave  # each give followed a failed robot move
    handovers = session.summary()["handovers"]
    assert (handovers["you_gave"], handovers["you_took"]) == (gave, took)


def test_the_recurrent_sb3_config_refuses_zero_threads() -> None:
    # Every count of the run (steps, tables, rollout, batch, epochs, threads) is at least 1.
    with pytest.raises(ConfigError, match=r"^threads: expected an integer >= 1, got 0$"):
        RecurrentSb3Config(threads=0).check()
    assert RecurrentSb3Config(threads=1).check().threads == 1
