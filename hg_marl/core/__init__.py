"""The pure task core: scenarios, state, rules, the cycle, specs and registries. Imports only the stdlib and numpy."""

from hg_marl.core.durations import Durations
from hg_marl.core.errors import (
    ConfigError,
    CriterionError,
    HgMarlError,
    HumanError,
    ModelFileError,
    RobotError,
    StudyError,
)
from hg_marl.core.scenario import Scenario, ScenarioError, available_scenarios, generate_scenario, load_scenario
from hg_marl.core.types import AGENT_NAMES, WAIT, Action, Agent, Event, Kind, Outcome, State
from hg_marl.core.world import World

__all__ = [
    "AGENT_NAMES",
    "WAIT",
    "Action",
    "Agent",
    "ConfigError",
    "CriterionError",
    "Durations",
    "Event",
    "HgMarlError",
    "HumanError",
    "Kind",
    "ModelFileError",
    "Outcome",
    "RobotError",
    "Scenario",
    "ScenarioError",
    "State",
    "StudyError",
    "World",
    "available_scenarios",
    "generate_scenario",
    "load_scenario",
]
