"""Values that round 163's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from hg_marl.agents.models.cache import result_key
from hg_marl.agents.planner.costs import CostWeights
from hg_marl.agents.planner.domain import Domain, Work
from hg_marl.agents.planner.models import cooperative
from hg_marl.agents.planner.space import Space
from hg_marl.agents.planner.tables import next_kinds
from hg_marl.core import Agent, Kind, World
from hg_marl.policy import Turn
from tests.agents.test_pinned_promises_b import PAPER, ROBOT_WAIT, K, _off_model_robot
from tests.source_copy import copy_sources, edit_code
from tests.training.test_pinned_round37 import train_clocked

OPTIONS = {"failed_actions": True, "symmetry": None, "tolerance": 1e-9, "max_iterations": 200_000}


@pytest.mark.parametrize("rel", ["agents/oracle.py", "agents/models/solve.py"])
def test_an_edit_of_the_oracle_or_its_solver_changes_the_oracle_cache_key(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, rel: str
) -> None:
    # The oracle's results are computed by agents/oracle.py and solved by agents/models/solve.py;
    # no human imports either. An entry keyed without them would be read back after the solver
    # changed (an old answer from new code), so an edit of either must give a new key.
    sources = copy_sources(tmp_path / "src", monkeypatch)
    world = World("paper2015")
    before = result_key(world, "cooperative", OPTIONS)
    edit_code(sources / rel)
    assert result_key(world, "cooperative", OPTIONS) != before


def saved_dqn(path: Path, **policy_kwargs: Any) -> Path:
    """An untrained DQN on paper2015's robot seat with these ``policy_kwargs``, saved at ``path`` (SB3 needed)."""
    from stable_baselines3 import DQN

    from hg_marl.agents.model_file import save_sb3, world_fields
    from hg_marl.agents.views import RobotView

    env = RobotView("paper2015")
    model = DQN("MlpPolicy", env, buffer_size=16, learning_starts=0, seed=0, device="cpu", policy_kwargs=policy_kwargs)
    return save_sb3(model, path, world_fields(PAPER, Agent.ROBOT), observation="facts")


def test_a_rebuild_given_policy_kwargs_keeps_the_headers_network(tmp_path: Path) -> None:
    # A resume hands the run's hyperparameters to build_sb3; among them may be policy_kwargs.
    # The network is the one the header describes (one hidden layer of 8 units, as saved), so
    # the caller's policy_kwargs are dropped, not passed to SB3 a second time (a refusal).
    pytest.importorskip("stable_baselines3")
    from hg_marl.agents.model_format import load_model_file
    from hg_marl.agents.model_sb3 import build_sb3

    path = saved_dqn(tmp_path / "model.json", net_arch=[8])
    again = build_sb3(load_model_file(path), policy_kwargs={"net_arch": [64, 64]}, learning_rate=0.01)
    assert again.policy_kwargs["net_arch"] == [8]
    assert again.learning_rate == 0.01


def test_off_its_model_a_guard_move_logs_the_planners_own_move_as_the_planner_action() -> None:
    # The planner stand-in always proposes wait. At the 13th turn at the same state the guard
    # (K = 12) moves instead: its move is the first feasible robot action other than wait (no guard
    # move taken yet), which is what the robot does; the record's planner_action stays the
    # planner's proposal, wait, as at the 12 turns before.
    robot, state = _off_model_robot()
    for _ in range(K):
        robot.act(Turn(PAPER, state, Agent.ROBOT, {}))
    action = robot.act(Turn(PAPER, state, Agent.ROBOT, {}))
    first_move = min(a for a in PAPER.feasible_indices(state, Agent.ROBOT) if a != ROBOT_WAIT)
    decision = robot.last_decision
    assert decision is not None
    assert action == decision.action == first_move != ROBOT_WAIT
    assert decision.planner_action == ROBOT_WAIT


def test_a_declared_method_gives_its_next_step_only_where_the_robot_stands() -> None:
    # A method declared on the domain, applicable only with the robot at location 1, whose next
    # robot step is a give of an object lying on a spot. None of the five default methods gives
    # a give as the next step of an object on a spot (a pick comes first), so the give is a next
    # kind at location 1 and at no other location.
    world = World("paper2015")
    domain = Domain(world, cooperative())

    def give_from_one(d: Domain, o: int, status: int, at: int) -> Work | None:
        if at == 1 and status < d.n_spots:
            return Work(1.0, 0.0, frozenset({Kind.GIVE}), frozenset())
        return None

    domain.declare("give_from_one", give_from_one)
    kinds = next_kinds(Space(domain, CostWeights()))[Agent.ROBOT]
    at_spot = [kinds[at][0][0] for at in range(len(world.scenario.robot_locations))]  # object 0 on spot 0
    assert [Kind.GIVE in k for k in at_spot] == [at == 1 for at in range(len(at_spot))]


def test_a_recurrent_model_file_names_every_training_partner(tmp_path: Path) -> None:
    # Trained against two partners, the model file's header lists both, in the order given.
    result = train_clocked(tmp_path, humans=("cooperative", "lazy"))
    header = json.loads(result.path.read_text())
    assert header["partners"] == ["cooperative", "lazy"]
