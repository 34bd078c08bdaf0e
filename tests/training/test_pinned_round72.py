"""The values round 72's missed planted bugs changed, pinned after the round.

Round 72 planted 16 bugs in sixteen gated modules, written blind; 11 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- the ``memory`` robot refuses, at ``reset``, a model file saved for another scenario's
  facts or actions (``check_world``: "refuse a policy saved for other facts or actions");
- the AEC environment's ``charge_time`` adds decision time to *the current cycle*: the
  cycles after it last as long as their longer action, nothing more;
- a scenario name reserved by the action syntax (human, robot, wait) is refused in any
  case, since the action syntax reads names case-insensitively (``Wait`` too);
- an unknown action type in a durations table is refused with the list of the known
  types, the eight fields of ``Durations``, whatever else the table gave.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np
import pytest

from hg_marl.core import Agent, World
from hg_marl.core.durations import Durations
from hg_marl.core.errors import ConfigError, HgMarlError, ScenarioError
from hg_marl.core.scenario_file import parse_scenario
from tests.memory_arrays import memory_arrays

# --- agents/robots/memory.py ---


def test_a_memory_file_saved_for_another_scenario_is_refused_at_reset(tmp_path: Path) -> None:
    # A file written for paper2015's facts and actions (a zero net: its weights do not matter)
    # played on roboergosum, whose objects and spots differ: the module docstring says the
    # robot "rebuilds exactly that observation", which it cannot on other facts, and
    # model_format.check_world refuses "a policy saved for other facts or actions".
    from hg_marl.agents.model_file import save_model_file, world_fields
    from hg_marl.agents.robots.memory import MemoryRobot

    trained = World("paper2015")
    other = World("roboergosum")
    assert list(other.fact_names) != list(trained.fact_names)  # the premise: other facts
    obs_size = trained.n_facts  # history 0: the facts only
    header = {
        **world_fields(trained, Agent.ROBOT),
        "kind": "memory",
        "observation": "facts",
        "obs_size": obs_size,
        "hidden": 4,
        "recurrent": False,
        "history": 0,
        "history_cap": 8,
    }
    arrays = memory_arrays(4, obs_size, trained.n_actions(Agent.ROBOT), recurrent=False)
    path = save_model_file(tmp_path / "model.json", header, arrays)
    robot = MemoryRobot(path=path, unstall=0)
    robot.reset(trained, Agent.ROBOT, np.random.default_rng(0))  # its own world: accepted
    with pytest.raises(HgMarlError, match="saved for scenario 'paper2015'"):
        robot.reset(other, Agent.ROBOT, np.random.default_rng(0))


# --- hg_marl/envs/table_cleaning.py ---


def test_charged_decision_time_lengthens_its_own_cycle_only() -> None:
    # Every action a wait of 1 s (durations given here): a cycle lasts max(1, 1) = 1 s plus
    # what was charged to it. 0.5 s charged in the first cycle only: the clock reads
    # 1.5, then 2.5, then 3.5 (by hand), never 1.5 + 1.5 + ... as if the charge repeated.
    from hg_marl.envs.table_cleaning import raw_env

    env = raw_env(scenario="paper2015", durations=Durations(wait=1.0), max_cycles=None)
    env.reset(seed=0)
    wait_r, wait_h = env.world.table.wait[Agent.ROBOT], env.world.table.wait[Agent.HUMAN]
    clocks = []
    for cycle in range(3):
        env.step(wait_r)
        if cycle == 0:
            env.charge_time(0.5)
        env.step(wait_h)
        clocks.append(env.clock)
    assert clocks == pytest.approx([1.5, 2.5, 3.5])


# --- hg_marl/core/scenario_file.py ---


def _scenario_text(object_name: str) -> str:
    """A small valid scenario whose first object is called ``object_name``."""
    return "\n".join(
        [
            'name = "tiny"',
            'robot_locations = ["near"]',
            'handover_locations = ["near"]',
            f'objects = [{{ name = "{object_name}" }}, {{ name = "pen" }}]',
            'bins = [{ name = "bin", robot_reach = ["near"], human_reach = true }]',
            "spots = ["
            '{ name = "s0", robot_reach = ["near"], human_reach = true }, '
            '{ name = "s1", robot_reach = ["near"], human_reach = true }]',
            'layout = [{ count = 2, spots = ["s0", "s1"] }]',
            "",
        ]
    )


@pytest.mark.parametrize("name", ["Wait", "ROBOT", "Human"])
def test_a_reserved_name_in_another_case_is_refused(name: str) -> None:
    # human, robot and wait are reserved by the action syntax; a name differing only in
    # case would read as the same word, so it is refused like the lower-case one.
    text = _scenario_text(name)
    with pytest.raises(ScenarioError, match="reserved by the action syntax"):
        parse_scenario(tomllib.loads(text), "tiny.toml", text=text)


def test_the_same_scenario_with_an_ordinary_name_loads() -> None:
    # The control: the refusals above are the names', not the rest of the scenario's.
    text = _scenario_text("cup")
    assert parse_scenario(tomllib.loads(text), "tiny.toml", text=text, strict=True).objects == ("cup", "pen")


# --- hg_marl/core/durations.py ---


@pytest.mark.parametrize("data", [{"pick": 1.0, "jump": 2.0}, {"jump": 2.0}])
def test_an_unknown_action_type_lists_every_known_type(data: dict[str, float]) -> None:
    # The known types are the dataclass's eight fields (pick, throw, give, take, place,
    # goto, wait, failed), listed sorted by hand; the fields the table gave do not matter.
    with pytest.raises(ConfigError) as caught:
        Durations.from_mapping(data, "cfg")
    message = str(caught.value)
    assert "field 'durations.jump': unknown action type" in message, message
    assert message.endswith("(known: failed, give, goto, pick, place, take, throw, wait)"), message
