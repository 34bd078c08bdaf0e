"""Bad input on the command line: one line naming the option, exit 2, never a traceback.

Each case states the option the message must name; the CLI runs in-process through
``main`` (the entry point of the ``hg-marl`` script).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.training.cli import app
from tests.cli_helpers import run_main

CASES = [
    (["run", "--duration", "nan"], "--duration"),
    (["run", "--duration", "0"], "--duration"),
    (["run", "--duration", "inf"], "--duration"),
    (["run", "--seed", "-1"], "--seed"),
    (["run", "--robot", "oracle"], "unknown robot 'oracle'"),
    (["run", "--robot", "sb3"], "--model"),
    (["run", "--robot", "hybrid", "--robot-param", "q_config={bad json}"], "q_config"),
    (["run", "--robot", "hybrid", "--robot-param", "learn=no"], "learn"),
    (["run", "--robot-param", "noequals"], "--robot-param"),
    (["run", "--human", "lazy:p_idle=nan"], "p_idle"),
    (["run", "--human", "lazy:p_idle=2"], "p_idle"),
    (["run", "--human", "learned"], "learned:path"),
    (["run", "--criterion", "vpi:tau=-1"], "tau"),
    (["run", "--scenario", "generated:objects=10000"], "HG_MARL_MAX_OBJECTS"),
    (["run", "--scenario", "generated:bins=1e6"], "HG_MARL_MAX_BINS"),
    (["run", "--out", "/nonexistent-folder/log.csv"], "--out"),
    (["plan", "--scenario", "kitchen"], "unknown scenario 'kitchen'"),
    (["plan", "--human", "adversarial"], "--human"),
    (["plan", "--png", "/nonexistent-folder/plan.png"], "--png"),
    (["plan", "--budget", "0"], "--budget"),
    (["oracle", "--human", "lazy", "--max-states", "0"], "--max-states"),
    (["reproduce", "--duration", "nan"], "--duration"),
    (["reproduce", "--duration", "0"], "--duration"),
    (["train", "--algo", "sac"], "unknown algorithm"),
    (["train", "--algo", "ppo_batched", "--hp", "num_envs=0"], "--num-envs"),
    (["train", "--algo", "ppo_batched", "--hp", "num_envs=-4"], "--num-envs"),
    (["train", "--algo", "ppo_batched", "--hp", "gamma=nan"], "--gamma"),
    (["train", "--algo", "ppo_batched", "--hp", "colour=red"], "--hp"),
    (["train", "--algo", "ppo_batched", "--hp", "num_envs=100000000000"], "num_envs"),
    (["train", "--algo", "ppo_batched", "--human", "switching"], "human: "),
    (["train", "--algo", "ppo_batched", "--human", "lazy", "--scenario", "generated:objects=14"], "cannot be compiled"),
    (["train", "--checkpoint-freq", "-5"], "--checkpoint-freq"),
    (["train", "--effort-weight", "nan"], "--effort-weight"),
    (["convert", "model.zip"], "--trust"),
    (["nosuchcommand"], "nosuchcommand"),
]


@pytest.mark.parametrize(("args", "named"), CASES, ids=[" ".join(a) for a, _ in CASES])
def test_bad_option_is_one_line_exit_2(args: list[str], named: str, tmp_path: Path) -> None:
    code, _, err = run_main([*args])
    lines = [line for line in err.splitlines() if line.strip()]
    assert code == 2, err
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    assert named in lines[0], lines[0]
    assert "Traceback" not in err


def test_run_help_lists_only_robots_make_robot_accepts() -> None:
    from typer.testing import CliRunner

    from hg_marl.agents.robots import available_robots

    text = CliRunner().invoke(app, ["run", "--help"], env={"COLUMNS": "200"}).output
    assert "oracle" not in text
    code, out, _ = run_main(["run", "--list"])
    assert code == 0 and f"robots:   {', '.join(available_robots())}" in out


def test_scenario_error_under_plan_names_file_and_line(tmp_path: Path) -> None:
    from importlib import resources

    text = resources.files("hg_marl.core.scenarios").joinpath("paper2015.toml").read_text()
    path = tmp_path / "s.toml"
    path.write_text(text.replace("[[bins]]\n", "[[bins]]\nsize = 3\n", 1))
    line = next(i + 1 for i, t in enumerate(path.read_text().splitlines()) if t == "size = 3")
    code, _, err = run_main(["plan", "--scenario", str(path)])
    assert code == 2 and f"{path}:{line}" in err and "bins[0].size" in err
