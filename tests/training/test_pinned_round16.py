"""Values that round 16's planted bugs changed unseen, each stated by hand.

The modules are user-facing commands and helpers outside the mutation gate: the run
summary's robot label, the traces command's ranking, the population command's default
store, the CLI's exit code for an unwritable file, JSON's infinities, the hyperparameters
of a generated scenario, a replay's episode bound and the text picture's offer mark.
"""

from __future__ import annotations

import errno
import json
import re
from pathlib import Path

import numpy as np
import pytest
import typer
from typer.testing import CliRunner

from hg_marl.agents.robots import make_robot
from hg_marl.core import Agent, Kind, World
from hg_marl.core.errors import ConfigError
from hg_marl.envs.render import render_ansi
from hg_marl.training.baselines.hyperparams import load_hyperparams
from hg_marl.training.cli import app, one_line_errors
from hg_marl.training.commands.run import robot_label
from hg_marl.training.io import write_json
from hg_marl.training.play.replay import load_episode
from tests.cli_helpers import error_lines, run_main
from tests.play.test_traces import record_games


def test_a_hybrid_whose_spec_names_its_criterion_is_labelled_by_the_spec_alone() -> None:
    assert robot_label(make_robot("hybrid:criterion=vpi"), "hybrid:criterion=vpi") == "hybrid:criterion=vpi"
    assert robot_label(make_robot("hybrid"), "hybrid") == "hybrid(entropy_and_cost)"
    assert robot_label(make_robot("planner"), "planner") == "planner"


def test_the_run_summary_names_the_hybrid_once() -> None:
    code, out, err = run_main(["run", "--robot", "hybrid:criterion=vpi", "--duration", "30"])
    assert code == 0, err
    assert out.splitlines()[0].startswith("robot hybrid:criterion=vpi with human cooperative on paper2015")


def test_the_traces_command_ranks_the_scripted_humans_by_distance(tmp_path: Path) -> None:
    record_games(tmp_path, [0, 2])
    result = CliRunner().invoke(app, ["traces", str(tmp_path)])
    assert result.exit_code == 0, result.output
    last = result.output.splitlines()[-1]
    ranked = re.findall(r"([a-z_]+) (\d+\.\d+)", last.partition("(")[2])
    names = [name for name, _ in ranked]
    assert sorted(names) == ["adversarial", "cooperative", "lazy", "no_handover", "noisy", "random"]
    distances = [float(d) for _, d in ranked]
    assert distances == sorted(distances) and names[0] == "cooperative"


def test_population_generate_keeps_its_runs_beside_the_file_under_its_stem(tmp_path: Path) -> None:
    out = tmp_path / "pop.toml"
    args = ["population", "generate", "--out", str(out), "--candidates", "4", "--held-out", "1", "--train", "1"]
    args += ["--validation", "0", "--duration", "120", "--seeds", "1", "--workers", "1", "--robots", "planner"]
    code, stdout, err = run_main(args)
    assert code == 0, err
    assert (tmp_path / "pop.store").is_dir() and not (tmp_path / "pop.toml.store").exists()
    assert stdout.splitlines()[-1] == f"wrote {out}; measuring runs in {tmp_path / 'pop.store'}"


@pytest.mark.parametrize("code", [errno.ENOSPC, errno.EACCES])
def test_an_unwritable_file_is_one_line_and_exit_2(code: int) -> None:
    small = typer.Typer()

    @small.command()
    @one_line_errors
    def write() -> None:
        raise OSError(code, "cannot", "x.zip")

    @small.command()
    def other() -> None:  # a second command, so typer keeps the command name
        pass

    result = CliRunner().invoke(small, ["write"])
    assert result.exit_code == 2
    assert len(error_lines(result.output)) == 1 and "x.zip" in result.output


def test_infinities_are_written_as_null(tmp_path: Path) -> None:
    path = write_json(tmp_path / "x.json", {"x": float("inf"), "y": [float("-inf"), 1.5], "z": float("nan")})
    assert json.loads(path.read_text()) == {"x": None, "y": [None, 1.5], "z": None}


def test_a_generated_scenario_reads_the_generated_entry(tmp_path: Path) -> None:
    path = tmp_path / "hp.yml"
    path.write_text("default:\n  n_steps: 128\ngenerated:\n  n_steps: 64\n")
    assert load_hyperparams("ppo", "generated:objects=3", path=path).kwargs["n_steps"] == 64
    assert load_hyperparams("ppo", "paper2015", path=path).kwargs["n_steps"] == 128


def test_an_episode_past_the_last_is_refused_in_one_line(tmp_path: Path) -> None:
    record_games(tmp_path, [0])
    trace = next(tmp_path.glob("*.jsonl"))
    assert load_episode(trace, 0).steps
    with pytest.raises(ConfigError, match=r"--episode 1: .* holds episodes 0\.\.0"):
        load_episode(trace, 1)


def test_only_the_offering_agent_is_marked_offering() -> None:
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    acts = world.actions(Agent.ROBOT)
    rng = np.random.default_rng(0)
    held = state
    for _ in range(200):  # the robot's random moves until it can give something
        feasible = world.feasible_indices(held, Agent.ROBOT)
        give = next((i for i in feasible if acts[i].kind is Kind.GIVE), None)
        if give is not None:
            break
        held = world.step(held, Agent.ROBOT, int(rng.choice(feasible))).state
    assert give is not None
    offering = world.step(held, Agent.ROBOT, give).state
    assert offering.offer_by == int(Agent.ROBOT)
    marked = [line for line in render_ansi(world, offering, 0.0, 0, 0).splitlines() if "(offering)" in line]
    assert len(marked) == 1 and marked[0].startswith("  robot")
    assert not any("(offering)" in line for line in render_ansi(world, state, 0.0, 0, 0).splitlines())
