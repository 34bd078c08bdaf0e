"""Round 36 of the fresh planted bugs: the values its missed bugs changed, pinned.

Each expected value is stated by hand, from the documented rule or from a simpler
reference (the ``run`` command's own parser, the module's documented limit), not computed
with the code under test.
"""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace
from typing import Any

import pytest
from typer.testing import CliRunner

from hg_marl.core import State, World
from hg_marl.core.errors import ConfigError


def test_the_use_it_line_after_training_against_a_population_names_one_human(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """``hg-marl run`` plays one robot with one human: after ``train sb3 --human lazy,cooperative``
    the printed command passes the population's first member, ``--human lazy``, which ``run``
    can build (the training itself replaced by one returning a finished result)."""
    import hg_marl.training.baselines.train as train_module
    from hg_marl.agents.humans import make_human
    from hg_marl.training.cli import app

    model = tmp_path / "out" / "model.zip"

    def finished(config: Any, callbacks: Any = ()) -> Any:
        return SimpleNamespace(
            interrupted=False,
            hyperparams=SimpleNamespace(class_name="PPO"),
            num_timesteps=128,
            session_steps=128,
            steps_per_second=100.0,
            path=model,
        )

    monkeypatch.setattr(train_module, "train", finished)
    args = ["train", "sb3", "--algo", "ppo", "--human", "lazy,cooperative", "--steps", "128"]
    result = CliRunner().invoke(app, [*args, "--out", str(tmp_path / "out"), "--no-progress"])
    assert result.exit_code == 0, result.output
    (line,) = [ln for ln in result.output.splitlines() if "use it" in ln]
    assert line.strip() == f"use it  hg-marl run --robot sb3 --model {model} --human lazy"
    make_human(line.split("--human ")[1])  # what `run --human` accepts


def test_the_batched_ppo_checkpoints_a_tenth_of_its_steps_by_default(tmp_path: Path) -> None:
    """``--checkpoint-freq`` left out: "a tenth of --steps" (the option's help), so 1000 steps
    checkpoint every 100; without ``--steps``, a tenth of the default 600,000: 60,000."""
    from hg_marl.training.baselines.ppo_batched import config_from_options

    options = ("paper2015",)
    given = config_from_options(("cooperative",), *options, 1000, 0, tmp_path / "out", None, False, False, ())
    assert given.steps == 1000
    assert given.checkpoint_freq == 100
    default = config_from_options(("cooperative",), *options, None, 0, tmp_path / "out", None, False, False, ())
    assert default.checkpoint_freq == 60_000
    explicit = config_from_options(("cooperative",), *options, 1000, 0, tmp_path / "out", 0, False, False, ())
    assert explicit.checkpoint_freq == 0


@pytest.mark.parametrize(
    ("robot_holds", "human_holds", "sentence"),
    [
        (0, None, "The robot holds tape1; you hold nothing."),
        (None, 1, "The robot holds nothing; you hold tape2."),
    ],
)
def test_the_play_page_says_who_holds_what(robot_holds: int | None, human_holds: int | None, sentence: str) -> None:
    """On paper2015 (spots 0-5, the bin 6, the robot's hand 7, the human's 8; place codes as
    ``State.where`` documents them): the page's sentence names the robot's object first, then
    the person's ("you")."""
    from hg_marl.training.play.session import PlaySession
    from hg_marl.training.play.web import board_html

    session = PlaySession(robot="random", player="tester")
    where = [0, 1, 2]  # tape1, tape2, tape3 on mat_left, mat_centre, mat_right
    if robot_holds is not None:
        where[robot_holds] = 7
    if human_holds is not None:
        where[human_holds] = 8
    session.raw.world_state = State(where=tuple(where), robot_at=0)
    assert sentence in board_html(session)


def test_a_net_arch_of_sixteen_hidden_layers_is_accepted_and_seventeen_refused() -> None:
    """The module's limit: "at most MAX_LAYERS hidden layers" (16), so 16 pass, 17 are refused."""
    from hg_marl.agents.sb3_limits import MAX_LAYERS, check_net_arch, check_policy_kwargs

    assert MAX_LAYERS == 16
    check_net_arch([8] * 16, "net_arch", ConfigError)
    check_net_arch({"pi": [8] * 16, "vf": [8] * 16}, "net_arch", ConfigError)
    check_policy_kwargs({"net_arch": [8] * 16}, "policy_kwargs", ConfigError)
    with pytest.raises(ConfigError, match="at most 16 layer sizes"):
        check_net_arch([8] * 17, "net_arch", ConfigError)


def test_a_key_error_becomes_a_cli_error_with_its_own_message() -> None:
    """``checked`` turns a KeyError (an unknown name) into a ConfigError: its message as
    written, not the KeyError's repr in quotes."""
    from hg_marl.training.commands.common import checked

    def unknown() -> None:
        raise KeyError("unknown human 'tidy'; the humans are lazy, cooperative")

    with pytest.raises(ConfigError) as caught:
        checked(unknown)
    assert str(caught.value) == "unknown human 'tidy'; the humans are lazy, cooperative"

    def bad_value() -> None:
        raise ValueError("p_idle: expected a value in [0, 1], got 2")

    with pytest.raises(ConfigError) as caught:
        checked(bad_value)
    assert str(caught.value) == "p_idle: expected a value in [0, 1], got 2"


def test_live_robots_listed_for_the_human_seat_each_play_their_share_of_tables() -> None:
    """Two robots for four tables, one actor per table: each robot plays two of them, not
    the first everywhere."""
    from hg_marl.agents.array_partners import LiveRobots

    live = LiveRobots(World("paper2015"), ["random", "planner"], 4)
    names = [actor.name for actor in live.actors]
    assert sorted(names) == ["planner", "planner", "random", "random"]
