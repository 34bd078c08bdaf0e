"""SB3 baselines: training, save/load/resume, the sb3 robot, learned humans, behaviour cloning, CLI."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

# The sb3 extra: conftest.py errors (instead of letting this module skip) when it is
# missing in CI or with HG_MARL_REQUIRE_EXTRAS=1, so these tests cannot vanish there.
pytest.importorskip("stable_baselines3", reason="needs the sb3 extra")
pytest.importorskip("sb3_contrib", reason="needs the sb3 extra")

import torch
import typer
from typer.testing import CliRunner

from hg_marl.agents.humans import TraceRecorder, make_human
from hg_marl.agents.humans.learned import LearnedHuman
from hg_marl.agents.model_file import load_model_file
from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.sb3 import SB3Robot
from hg_marl.agents.views import RobotView
from hg_marl.core.errors import ConfigError, ModelFileError
from hg_marl.training.baselines.bc import behaviour_clone, load_traces
from hg_marl.training.baselines.envs import EnvSpec, split_population
from hg_marl.training.baselines.evaluation import actor_rate, runner_rate, steps_to_reach
from hg_marl.training.baselines.hyperparams import ALGOS, HyperparamError, load_hyperparams
from hg_marl.training.baselines.train import TrainConfig, train
from hg_marl.training.runner import RunConfig, run

pytestmark = pytest.mark.sb3
torch.set_num_threads(1)

SCENARIO = "paper2015"
EVAL_SEEDS = (100, 101, 102)


@pytest.fixture(scope="module")
def trained(tmp_path_factory: pytest.TempPathFactory):
    """MaskablePPO, 4096 steps against the cooperative human (about 20 s on 2 cores)."""
    out = tmp_path_factory.mktemp("mppo")
    config = TrainConfig(
        algo="maskable_ppo",
        env=EnvSpec(scenario=SCENARIO),
        steps=4096,
        seed=0,
        out=out,
        eval_freq=2048,
        eval_episodes=3,
        checkpoint_freq=2048,
    )
    return config, train(config)


# ---- hyperparameters -----------------------------------------------------------------
@pytest.mark.parametrize("algo", list(ALGOS))
def test_every_yaml_parses(algo: str) -> None:
    hp = load_hyperparams(algo)
    assert hp.policy == ("MlpLstmPolicy" if algo == "recurrent_ppo" else "MlpPolicy")
    assert hp.n_envs >= 1 and hp.n_timesteps > 0
    assert "policy" not in hp.kwargs and "n_envs" not in hp.kwargs


def test_overrides_are_yaml_and_nested() -> None:
    hp = load_hyperparams("ppo", overrides=["learning_rate=0.01", "policy_kwargs.net_arch=[16, 16]", "n_envs=2"])
    assert hp.kwargs["learning_rate"] == 0.01
    assert hp.kwargs["policy_kwargs"]["net_arch"] == [16, 16]
    assert hp.n_envs == 2
    assert load_hyperparams("ppo").kwargs["policy_kwargs"]["net_arch"] == [64, 64]  # no mutation leaks


@pytest.mark.parametrize(
    ("algo", "overrides", "match"),
    [
        ("sac", [], "unknown algorithm 'sac'; available: ppo"),
        ("ppo", ["learning_rat=0.1"], "unknown hyperparameter.*learning_rat.*accepted"),
        ("dqn", ["n_epochs=5"], "unknown hyperparameter.*n_epochs"),
        ("a2c", ["no_equals_sign"], "expected key=value"),
        ("ppo", ["n_envs=zero"], "n_envs: expected an integer"),
    ],
)
def test_bad_hyperparams_are_clear(algo: str, overrides: list[str], match: str) -> None:
    with pytest.raises(HyperparamError, match=match):
        load_hyperparams(algo, overrides=overrides)


def test_population_specs_split_on_commas_keeping_parameters() -> None:
    assert split_population("cooperative,lazy,no_handover") == ("cooperative", "lazy", "no_handover")
    assert split_population("noisy:temperature=0.2,p=1,lazy") == ("noisy:temperature=0.2,p=1", "lazy")


def test_steps_to_reach() -> None:
    curve = [(0, 1.0), (100, 50.0), (200, 95.0)]
    assert steps_to_reach(curve, 50.0) == 100 and steps_to_reach(curve, 99.0) is None


# ---- training, save, load, resume ------------------------------------------------------
def test_short_training_beats_random_robot(trained) -> None:
    """Sampled from the policy (as compare evaluates): early greedy policies can loop forever."""
    _, result = trained
    assert result.num_timesteps >= 4096
    learned = runner_rate(result.model, "facts", "cooperative", SCENARIO, 600.0, EVAL_SEEDS, deterministic=False)
    random = actor_rate(lambda: make_robot("random"), "cooperative", SCENARIO, 600.0, EVAL_SEEDS)
    assert learned >= 2 * random and learned - random >= 30, (learned, random)


def test_outputs_written(trained) -> None:
    config, result = trained
    out = config.out
    side = load_model_file(result.path).header
    assert side["algo"] == "MaskablePPO" and side["observation"] == "facts" and side["scenario"] == SCENARIO
    assert side["counters"]["num_timesteps"] == result.num_timesteps
    assert (out / "checkpoints" / "ckpt_2048_steps.npz").is_file()
    assert (out / "checkpoints" / "ckpt_2048_steps.json").is_file()
    assert not list(out.rglob("*.zip")) and not list(out.rglob("*.pkl"))  # nothing pickled is written
    assert (out / "eval" / "evaluations.npz").is_file() and (out / "eval" / "best_model.json").is_file()
    assert any((out / "tb").rglob("events.out.tfevents*"))


def test_load_gives_identical_predictions(trained) -> None:
    _, result = trained
    robot = SB3Robot(path=result.path)
    view = RobotView(SCENARIO, human="cooperative")
    obs, _ = view.reset(seed=3)
    for _ in range(50):
        mask = view.action_masks()
        a_mem, _ = result.model.predict(obs, deterministic=True, action_masks=mask)
        a_disk, _ = robot.model.predict(obs, deterministic=True, action_masks=mask)
        assert int(a_mem) == int(a_disk)
        obs, _, term, trunc, _ = view.step(int(a_mem))
        if term or trunc:
            obs, _ = view.reset()


def test_sb3_robot_in_runner_is_seeded_and_charged(trained) -> None:
    _, result = trained
    a = run(SB3Robot(path=result.path), make_human("cooperative"), RunConfig(SCENARIO, duration=300.0, seed=4))
    b = run(SB3Robot(path=result.path.parent), make_human("cooperative"), RunConfig(SCENARIO, duration=300.0, seed=4))
    assert a.log["action"].tolist() == b.log["action"].tolist()
    assert (a.log["expert"] == "sb3").all() and (a.log["decision_time"] == 1e-3).all()
    c = run(SB3Robot(path=result.path, deterministic=False), make_human("cooperative"), RunConfig(SCENARIO, 300.0, 4))
    d = run(SB3Robot(path=result.path, deterministic=False), make_human("cooperative"), RunConfig(SCENARIO, 300.0, 4))
    assert c.log["action"].tolist() == d.log["action"].tolist()  # sampling uses the robot's own generator
    assert c.summary["tasks_solved"] > 0


def test_sb3_robot_respects_mask(trained) -> None:
    _, result = trained
    log = run(SB3Robot(path=result.path), make_human("lazy"), RunConfig(SCENARIO, duration=300.0, seed=1)).log
    assert not log["failed"].any()


def test_sb3_robot_rejects_other_world(trained) -> None:
    _, result = trained
    with pytest.raises(ModelFileError, match="differ from 'roboergosum'"):
        run(SB3Robot(path=result.path), make_human("cooperative"), RunConfig("roboergosum", duration=10.0))
    with pytest.raises(ModelFileError, match=r"nope\.zip: no such file"):
        SB3Robot(path=result.path.parent / "nope.zip")


def test_resume_continues_step_count(trained, tmp_path: Path) -> None:
    config, _ = trained
    ckpt = config.out / "checkpoints" / "ckpt_2048_steps.json"
    resumed = train(
        TrainConfig(
            algo="maskable_ppo",
            env=config.env,
            steps=3072,
            seed=0,
            out=tmp_path,
            resume=ckpt,
            eval_freq=0,
            checkpoint_freq=0,
            tensorboard=False,
        )
    )
    assert resumed.num_timesteps >= 3072 and 0 < resumed.session_steps <= 1024 + 512
    with pytest.raises(ConfigError, match="trained with --algo maskable_ppo"):
        train(TrainConfig(algo="ppo", env=config.env, steps=3072, out=tmp_path / "x", resume=ckpt, eval_freq=0))


def test_dqn_resume_keeps_replay_buffer(tmp_path: Path) -> None:
    hp = ("learning_starts=100", "buffer_size=2000")
    first = train(
        TrainConfig(
            algo="dqn",
            steps=400,
            seed=1,
            out=tmp_path / "a",
            hp_overrides=hp,
            eval_freq=0,
            checkpoint_freq=200,
            tensorboard=False,
        )
    )
    ckpt = first.checkpoints[0]
    assert ckpt.with_name(f"{ckpt.stem}_replay_buffer.npz").is_file()
    again = train(
        TrainConfig(
            algo="dqn",
            steps=400,
            seed=1,
            out=tmp_path / "b",
            resume=ckpt,
            eval_freq=0,
            checkpoint_freq=0,
            tensorboard=False,
        )
    )
    assert again.num_timesteps == 400 and again.session_steps == 200
    assert again.model.replay_buffer.size() > 300  # 200 loaded + 200 new (an empty buffer would hold 200)


@pytest.mark.parametrize("algo", ["ppo", "a2c"])
def test_plain_algorithms_train_and_play(algo: str, tmp_path: Path) -> None:
    result = train(
        TrainConfig(
            algo=algo,
            steps=256,
            seed=0,
            out=tmp_path,
            eval_freq=128,
            eval_episodes=1,
            checkpoint_freq=0,
            tensorboard=False,
            env=EnvSpec(partners=("cooperative", "lazy"), observation="flat"),
        )
    )
    log = run(SB3Robot(path=result.path), make_human("no_handover"), RunConfig(SCENARIO, duration=60.0)).log
    assert len(log) > 0


# ---- learned humans ---------------------------------------------------------------------
def test_learned_human_trained_in_human_seat_loads_by_name(tmp_path: Path) -> None:
    config = TrainConfig(
        algo="maskable_ppo",
        steps=512,
        seed=0,
        out=tmp_path,
        eval_freq=0,
        checkpoint_freq=0,
        tensorboard=False,
        env=EnvSpec(seat="human", partners=("random",), effort_weight=0.05),
    )
    train(config)
    human = make_human("learned", path=str(tmp_path))
    assert isinstance(human, LearnedHuman) and human.kind == "sb3"
    result = run(make_robot("planner"), human, RunConfig(SCENARIO, duration=120.0, seed=0))
    assert len(result.log) > 0 and result.log["human_action"].ge(0).all()
    with pytest.raises(ValueError, match="human seat"):
        SB3Robot(path=tmp_path)


def _record(human: str, path: Path, duration: float = 600.0) -> Path:
    recorder = TraceRecorder(make_human(human), path, seed=0)
    run(make_robot("planner"), recorder, RunConfig(SCENARIO, duration=duration, seed=0))
    recorder.close()
    return path


@pytest.mark.parametrize("kind", ["table", "linear_softmax"])
def test_behaviour_cloning_reproduces_recorded_actions(kind: str, tmp_path: Path) -> None:
    trace = _record("no_handover", tmp_path / "trace.jsonl")
    out, accuracy = behaviour_clone([trace], tmp_path / "policy", kind=kind)
    assert accuracy == 1.0
    human = make_human("learned", path=str(out), deterministic=True)
    data = load_traces([trace])
    view = RobotView(SCENARIO, human=human)
    view.reset(seed=0)  # resets the human in the human seat
    for facts, mask, action in zip(data.facts, data.masks, data.actions, strict=True):
        p = human.probabilities(facts, mask)  # type: ignore[attr-defined]
        assert int(np.argmax(p)) == action


def test_behaviour_cloning_errors(tmp_path: Path) -> None:
    trace = _record("cooperative", tmp_path / "t.jsonl", duration=30.0)
    with pytest.raises(ValueError, match="kind"):
        behaviour_clone([trace], tmp_path / "p", kind="mlp")
    with pytest.raises(ValueError, match="do not match"):
        behaviour_clone([trace], tmp_path / "p", scenario="roboergosum")


# ---- command line -------------------------------------------------------------------------
def _app() -> typer.Typer:
    from hg_marl.training.cli import register_all

    app = typer.Typer()

    @app.callback()
    def _root() -> None:
        """Test app."""

    register_all(app, ("train", "compare"))
    return app


def test_cli_train_bc_and_errors(tmp_path: Path) -> None:
    runner = CliRunner()
    res = runner.invoke(
        _app(),
        [
            "train",
            "--algo",
            "maskable_ppo",
            "--steps",
            "256",
            "--out",
            str(tmp_path / "m"),
            "--eval-freq",
            "0",
            "--no-tensorboard",
            "--no-progress",
            "--hp",
            "n_steps=64",
            "--human",
            "cooperative,lazy",
        ],
    )
    assert res.exit_code == 0, res.output
    assert load_model_file(tmp_path / "m").header["train"]["partners"] == ["cooperative", "lazy"]
    res = runner.invoke(_app(), ["train", "--algo", "sac", "--out", str(tmp_path / "x")])
    assert res.exit_code == 2 and "unknown algorithm" in res.output
    res = runner.invoke(_app(), ["train", "--hp", "bogus=1", "--out", str(tmp_path / "x")])
    assert res.exit_code == 2 and "bogus" in res.output
    trace = _record("no_handover", tmp_path / "t.jsonl", duration=120.0)
    res = runner.invoke(_app(), ["train", "--algo", "bc", "--traces", str(trace), "--out", str(tmp_path / "bc")])
    assert res.exit_code == 0 and "100.0%" in res.output, res.output


def test_cli_compare_is_resumable(tmp_path: Path) -> None:
    args = [
        "compare",
        "--algos",
        "maskable_ppo",
        "--humans",
        "no_handover",
        "--steps",
        "512",
        "--eval-every",
        "256",
        "--eval-seeds",
        "1",
        "--duration",
        "300",
        "--seeds",
        "2",
        "--out",
        str(tmp_path),
    ]
    res = CliRunner().invoke(_app(), args)
    assert res.exit_code == 0, res.output
    summary = json.loads((tmp_path / "summary.json").read_text())
    agents = {r["agent"] for r in summary["rows"]}
    assert agents == {"maskable_ppo", "planner", "hybrid"}
    row = next(r for r in summary["rows"] if r["agent"] == "maskable_ppo")
    assert row["oracle"] > 0 and row["fraction"] >= 0 and summary["cells"][0]["curve"][0][0] == 0
    assert row["seeds"] == 2 and row["fraction_ci"][0] <= row["fraction"] <= row["fraction_ci"][1]
    assert summary["aggregate"]["robots"]["maskable_ppo"]["runs"] == 2
    assert "95% CI" in res.output and "over humans" in res.output
    res = CliRunner().invoke(_app(), args)
    assert res.exit_code == 0 and "training" not in res.output  # every cell came from disk


def test_cli_compare_passes_deterministic_on(tmp_path: Path) -> None:
    args = ["compare", "--algos", "dqn", "--humans", "no_handover", "--steps", "256", "--eval-every", "256"]
    args += ["--eval-seeds", "1", "--duration", "120", "--seeds", "1", "--deterministic", "--out", str(tmp_path)]
    res = CliRunner().invoke(_app(), args)
    assert res.exit_code == 0, res.output
    assert json.loads((tmp_path / "summary.json").read_text())["config"]["deterministic"] is True


def test_importing_the_package_and_commands_does_not_import_torch() -> None:
    code = (
        "import sys, hg_marl, hg_marl.agents.robots, hg_marl.agents.robots.sb3, "
        "hg_marl.training.commands.train, hg_marl.training.commands.compare; "
        "assert 'torch' not in sys.modules and 'stable_baselines3' not in sys.modules"
    )
    subprocess.run([sys.executable, "-c", code], check=True)
