"""Values that round 152's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import json
import logging
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.array_partners import LiveRobots
from hg_marl.agents.model_format import save_model_file
from hg_marl.agents.robots.uniform import RandomRobot
from hg_marl.agents.vector_envs import seat_robot
from hg_marl.core import Agent, Event, State, World
from hg_marl.core.batch import BatchState
from hg_marl.core.errors import ConfigError
from hg_marl.envs.table_cleaning import raw_env
from hg_marl.training.outputs import check_output
from hg_marl.training.store import Job, Store

# paper2015's place codes, read off its scenario: spots 0-5 (mat_left .. human_mat_2), the
# trashbin 6 (it accepts all three tapes), the robot's hand 7, the human's hand 8.
TRASHBIN, HUMAN_HAND = 6, 8


def test_a_saved_header_keeps_the_package_version_it_was_given(tmp_path: Path) -> None:
    # save_model_file fills in the package version only where the header has none ("setdefault"):
    # a converted model keeps the version that trained it, and the written header says so.
    header = {"kind": "table", "seat": "robot", "fact_names": [], "action_names": [], "package_version": "0.0.1"}
    arrays = {"facts": np.zeros((0, 0), dtype=np.int8), "actions": np.zeros(0, dtype=np.int64)}
    written = save_model_file(tmp_path / "m.json", header, arrays)
    assert json.loads(written.read_text())["package_version"] == "0.0.1"


def test_a_folder_path_through_a_file_names_the_file_in_the_way(tmp_path: Path) -> None:
    # --out notes/day1/log.csv where notes is a file: day1 does not exist, and what stops the user
    # is the file notes (the nearest thing that exists on the way), so the refusal names it.
    blocker = tmp_path / "notes"
    blocker.write_text("a file, not a folder\n")
    target = blocker / "day1" / "log.csv"
    with pytest.raises(ConfigError) as refused:
        check_output(target, "--out")
    assert str(refused.value) == f"--out {target}: {blocker} is a file, not a folder"


def test_the_hsp_partners_are_none_of_the_paper_populations_members() -> None:
    # The bundled populations were drawn by the generator from seed 0; the hsp recipe's eight
    # partners must come from another seed, or the held-out members would be trained with.
    from hg_marl.agents.humans.population import load_population
    from hg_marl.training.baselines.recipes import hsp_partners

    path = Path(__file__).parents[2] / "populations" / "paper2015.toml"
    members = {str(m.spec) for m in load_population(path).members()}
    drawn = set(hsp_partners(World("paper2015")))
    assert len(drawn) == 8
    assert not members & drawn


def test_the_warning_on_a_damaged_entry_names_the_jobs_label(tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    # An entry folder without result.json is "partial"; under the claim it is reported in one line
    # naming the job as people know it: its label ("condition A"), the robot only when unlabelled.
    store = Store(tmp_path)
    job = Job(robot="planner", seed=0, duration=60.0, label="condition A")
    store.entry(job.key()).mkdir(parents=True)
    with caplog.at_level(logging.WARNING, logger="hg_marl.training.store"):
        assert store.get(job, repair=True) is None
    messages = [r.getMessage() for r in caplog.records]
    assert len(messages) == 1
    assert "(condition A) is partial (no result.json)" in messages[0]


def test_the_human_seats_line_calls_live_robots_live() -> None:
    # LiveRobots are one live robot per table, not the compiled planner: the log line says so.
    live = LiveRobots(World("paper2015"), RandomRobot(), 2)
    assert seat_robot(live).startswith("live robots (")
    assert "compiled" not in seat_robot(live)


def test_a_place_event_names_the_spot_the_object_was_placed_on() -> None:
    # The human holds tape1 and places it on human_mat_1 (spot 4, one of its own mats): the event
    # reads "human placed tape1 ... human_mat_1", the spot in the action's own name.
    world = World("paper2015")
    state = State((HUMAN_HAND, 0, 1), 0)
    index = world.action_names[Agent.HUMAN].index("place(tape1,human_mat_1)")
    outcome = world.step(state, Agent.HUMAN, index)
    assert outcome.ok
    assert outcome.events == (Event("placed", "human", "tape1", "human_mat_1"),)


def test_the_robots_turn_reports_the_reward_of_its_last_wait() -> None:
    # All three tapes in the trashbin: the robot's wait completes the task (reward 1 to both);
    # the human then waits (no reward). At the robot's next turn, its reward since its previous
    # turn is the 1 of that wait, although the last step (the human's) paid nothing.
    env = raw_env(scenario="paper2015", continuing=True)
    env.reset(seed=0, options={"state": State((TRASHBIN, TRASHBIN, TRASHBIN), 0)})
    env.step(env.world.table.wait[Agent.ROBOT])
    env.step(env.world.table.wait[Agent.HUMAN])
    assert env.rewards["robot"] == 0.0
    assert env.turn("robot").reward == 1.0


def test_a_batch_of_states_keeps_who_offers_and_what() -> None:
    # The human (seat 1) offers tape3 (object 2): offer_by 1, offer_obj 2, as the state says.
    state = State((0, 1, HUMAN_HAND), 0, 1, 2)
    batch = BatchState.of([state, State((0, 1, 2), 0)])
    assert batch.offer_by.tolist() == [1, -1]
    assert batch.offer_obj.tolist() == [2, -1]
    assert batch.state(0) == state
