"""Probe every boundary with bad input: exit 2 and one line, nothing written, no hang, bounded memory.

Each case is a command line (with the files it names, built in ``tmp_path``) and the text
its one error line must contain (the option or file field to fix). The rule checked for
every case: exit code 2, exactly one ``error:`` line, no traceback, and no file created
anywhere under the working folder (bad input is refused before anything is written).
Most cases run in-process (fast); :data:`SUBPROCESS` runs the worst ones as real processes
under a 2 GiB address-space limit (the memory bound is what is tested; a 600 s timeout
only guards against a hang, so a loaded machine cannot fail the test). A larger hypothesis sweep over trace
lines and scenario names is marked slow.

Families (``docs/bad-input.md`` states these counts): names, durations, traces, model
headers and weights, hyperparameters, output paths, workers and name lists, full disk.
"""

from __future__ import annotations

import errno
import json
import os
import re
import resource
import subprocess
import sys
from collections.abc import Callable
from importlib import resources
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from hg_marl.core import Agent, World
from tests.cli_helpers import error_lines, run_main

PAPER = resources.files("hg_marl.core.scenarios").joinpath("paper2015.toml").read_text()
WORLD = World("paper2015")
STUDY = Path(__file__).parents[1] / "training" / "data" / "tiny.toml"


def scenario_with(old: str, new: str, count: int = 1) -> str:
    """paper2015.toml with one edit (the edit must apply)."""
    assert old in PAPER
    return PAPER.replace(old, new, count)


def with_durations(*lines: str) -> str:
    """paper2015.toml (which has no durations table) with a ``[durations]`` table."""
    assert "[durations]" not in PAPER
    return PAPER + "\n[durations]\n" + "".join(f"{line}\n" for line in lines)


# ---- a valid recorded game, the base every trace case mutates -------------------------------


@pytest.fixture(scope="module")
def game_lines(tmp_path_factory: pytest.TempPathFactory) -> list[dict]:
    """A real recording of the cooperative human against the planner, with its end line."""
    from hg_marl.agents.humans import make_human
    from hg_marl.agents.humans.trace import TraceRecorder
    from hg_marl.training.play.session import build_robot
    from hg_marl.training.runner import RunConfig, run

    path = tmp_path_factory.mktemp("game") / "game.jsonl"
    recorder = TraceRecorder(make_human("cooperative"), path, seed=0, meta={"robot": "planner", "player": "p"})
    result = run(build_robot("planner"), recorder, RunConfig(duration=30.0, seed=0))
    recorder.close()
    lines = [json.loads(x) for x in path.read_text().splitlines()]
    last = lines[-1]
    rewards = float(result.log["reward"].sum())
    lines.append(
        {"type": "end", "clock": last["clock"] + 2.0, "tasks_solved": last["tasks_solved"], "rewards": rewards}
    )
    return lines


def _trace(lines: list[dict], edit: Callable[[list[dict]], None]) -> str:
    copy = [dict(x, meta=dict(x["meta"])) if x["type"] == "header" else dict(x) for x in lines]
    edit(copy)
    return "".join(json.dumps(x) + "\n" for x in copy)


def _set(index: int, **fields: object) -> Callable[[list[dict]], None]:
    def edit(lines: list[dict]) -> None:
        lines[index].update(fields)

    return edit


def _meta(**fields: object) -> Callable[[list[dict]], None]:
    def edit(lines: list[dict]) -> None:
        lines[0]["meta"].update(fields)

    return edit


def _rename_actions(lines: list[dict]) -> None:
    """Consistent within the file (header and every step), but not the scenario's names."""
    lines[0]["action_names"] = [n.replace("tape", "cup") for n in lines[0]["action_names"]]
    for line in lines[1:]:
        if "action_name" in line:
            line["action_name"] = line["action_name"].replace("tape", "cup")


def _rename_facts(lines: list[dict]) -> None:
    lines[0]["fact_names"] = [n.replace("tape", "cup") for n in lines[0]["fact_names"]]


def _infinite(index: int, key: str) -> Callable[[list[dict]], None]:
    """``1e400`` in the file (JSON has no infinity, but Python reads 1e400 as one)."""
    return _set(index, **{key: "INF_PLACEHOLDER"})


TRACE_EDITS: dict[str, tuple[Callable[[list[dict]], None], str]] = {
    "end clock 5e6": (_set(-1, clock=5e6), "'clock'"),
    "end tasks -50": (_set(-1, tasks_solved=-50), "'tasks_solved'"),
    "end tasks 10**6": (_set(-1, tasks_solved=10**6), "'tasks_solved'"),
    "end rewards text": (_set(-1, rewards="lots"), "'rewards'"),
    "end clock text": (_set(-1, clock="late"), "'clock'"),
    "end clock infinite": (_infinite(-1, "clock"), "'clock'"),
    "end rewards infinite": (_infinite(-1, "rewards"), "'rewards'"),
    "response time infinite": (_infinite(2, "response_time"), "'response_time'"),
    "step clock back": (_set(3, clock=-0.5), "'clock'"),
    "step tasks jump": (_set(2, tasks_solved=7), "'tasks_solved'"),
    "step tasks float": (_set(2, tasks_solved=0.5), "'tasks_solved'"),
    "response time text": (_set(2, response_time="slow"), "'response_time'"),
    "response time negative": (_set(2, response_time=-1.0), "'response_time'"),
    "response time 1e9": (_set(2, response_time=1e9), "'response_time'"),
    "seat robot": (_set(0, seat="robot"), "'seat'"),
    "seed float": (_set(0, seed=1.7), "'seed'"),
    "seed text": (_set(0, seed="abc"), "'seed'"),
    "seed negative": (_set(0, seed=-3), "'seed'"),
    "scenario number": (_set(0, scenario=5), "'scenario'"),
    "scenario unknown": (_set(0, scenario="kitchen"), "'scenario'"),
    "meta list": (_set(0, meta=[1, 2]), "'meta'"),
    "meta robot number": (_meta(robot=3), "'meta.robot'"),
    "meta player list": (_meta(player=["x"]), "'meta.player'"),
    "actor number": (_set(0, actor=7), "'actor'"),
    "action names of another scenario": (_rename_actions, "'action_names'"),
    "fact names of another scenario": (_rename_facts, "'fact_names'"),
    "second end line": (lambda lines: lines.append(dict(lines[-1])), "second end line"),
}


# ---- in-process cases ------------------------------------------------------------------------


def _cases() -> list[tuple[str, str, Callable[[Path], list[str]], str]]:
    """(family, id, build args in a folder, text the error line must contain)."""
    cases: list[tuple[str, str, Callable[[Path], list[str]], str]] = []

    def file(name: str, text: str) -> Callable[[Path], Path]:
        def make(tmp: Path) -> Path:
            (tmp / name).write_text(text)
            return tmp / name

        return make

    def plan_scenario(text: str) -> Callable[[Path], list[str]]:
        return lambda tmp: ["plan", "--scenario", str(file("s.toml", text)(tmp))]

    names = {
        "scenario name ../": (scenario_with('name = "paper2015"', 'name = "../../escape"'), "'name'"),
        "scenario name slash": (scenario_with('name = "paper2015"', 'name = "a/b"'), "'name'"),
        "scenario name dot": (scenario_with('name = "paper2015"', 'name = ".hidden"'), "'name'"),
        "object named human": (scenario_with('name = "tape1"', 'name = "human"'), "objects[0].name"),
        "object named robot": (scenario_with('name = "tape1"', 'name = "robot"'), "objects[0].name"),
        "object named wait": (scenario_with('name = "tape1"', 'name = "wait"'), "objects[0].name"),
        "object named like the bin": (scenario_with('name = "tape1"', 'name = "trashbin"'), "bins[0].name"),
        "spot named like an object": (scenario_with('name = "mat_left"', 'name = "tape1"'), "spots[0].name"),
        "object name with comma": (scenario_with('name = "tape1"', 'name = "ta,pe"'), "objects[0].name"),
        "spot name with comma": (scenario_with('name = "mat_left"', 'name = "mat,left"'), "spots[0].name"),
        "object name with paren": (scenario_with('name = "tape1"', 'name = "t(1)"'), "objects[0].name"),
        "object name empty": (scenario_with('name = "tape1"', 'name = ""'), "objects[0].name"),
        "object name 65 chars": (scenario_with('name = "tape1"', f'name = "{"t" * 65}"'), "objects[0].name"),
        "location with space": (scenario_with('"bin_side"', '"bin side"', 99), "robot_locations[0]"),
    }
    for case, (text, named) in names.items():
        cases.append(("names", case, plan_scenario(text), named))

    durations = {
        "pick 1e-300": ("pick = 1e-300", "durations.pick"),
        "failed 0.001": ("failed = 0.001", "durations.failed"),
        "wait 0": ("wait = 0", "durations.wait"),
        "goto 1e6": ("goto = 1e6", "durations.goto"),
    }
    for case, (line, named) in durations.items():
        text = with_durations(line)
        cases.append(("durations", case, lambda tmp, t=text: ["run", "--duration", "5", "--scenario",
                                                             str(file("s.toml", t)(tmp))], named))  # fmt: skip
    fast = with_durations(
        *(f"{k} = 0.01" for k in ("pick", "throw", "give", "take", "place", "goto", "wait", "failed"))
    )
    cases.append(("durations", "1e7 s at the 0.01 s floor",
                  lambda tmp: ["run", "--duration", "1e7", "--scenario", str(file("s.toml", fast)(tmp))],
                  "cycles"))  # fmt: skip
    cases.append(("durations", "run --duration 1e300", lambda tmp: ["run", "--duration", "1e300"], "--duration"))

    hp = {
        "learning_rate=abc": "learning_rate",
        "learning_rate=-1": "learning_rate",
        "learning_rate=.nan": "learning_rate",
        "n_steps=0": "n_steps",
        "n_steps=1.5": "n_steps",
        "batch_size=-1": "batch_size",
        "batch_size=1": "batch_size",
        "gamma=2": "gamma",
        "n_epochs=true": "n_epochs",
        "n_envs=100000": "n_envs",
        "n_timesteps=-5": "n_timesteps",
        "policy=[1]": "policy",
        "policy_kwargs.net_arch=[200000,200000]": "net_arch",
        "policy_kwargs.net_arch=[-64,64]": "net_arch",
        "policy_kwargs.net_arch=[4096,4096,4096]": "net_arch",
        "policy_kwargs.net_arch={pi:[64],bogus:[1]}": "net_arch",
        "policy_kwargs.net_arch=abc": "net_arch",
        "policy_kwargs=3": "policy_kwargs",
        "normalize_advantage=maybe": "normalize_advantage",
    }
    dqn = {
        "buffer_size=10**12": "buffer_size",
        "buffer_size=1000000000000": "buffer_size",
        "exploration_fraction=1.5": "exploration_fraction",
        "train_freq=0": "train_freq",
    }
    for algo, items in (("ppo", hp), ("dqn", dqn)):
        for item, named in items.items():
            args = ["train", "--algo", algo, "--hp", item]
            cases.append(("hyperparameters", f"{algo} --hp {item}", lambda tmp, a=args: [*a, "--out", str(tmp / "o")],
                          named))  # fmt: skip
    yamls = {
        "malformed YAML": ("default: {n_steps: [1, 2\n", "hp.yml:2: not valid YAML"),
        "YAML not a mapping": ("- 1\n- 2\n", "expected a mapping"),
        "YAML entry bad value": ("default:\n  n_steps: -4\n", "n_steps"),
    }
    for case, (text, named) in yamls.items():
        cases.append(("hyperparameters", case, lambda tmp, t=text: ["train", "--algo", "ppo", "--hyperparams",
                      str(file("hp.yml", t)(tmp)), "--out", str(tmp / "o")], named))  # fmt: skip
    cases.append(("hyperparameters", "--hyperparams missing",
                  lambda tmp: ["train", "--algo", "ppo", "--hyperparams", str(tmp / "no.yml"), "--out", str(tmp / "o")],
                  "no such file"))  # fmt: skip
    cases.append(("hyperparameters", "--hyperparams a folder",
                  lambda tmp: ["train", "--algo", "ppo", "--hyperparams", str(tmp), "--out", str(tmp / "o")],
                  "folder"))  # fmt: skip

    def a_file(tmp: Path) -> str:
        (tmp / "taken").write_text("x")
        return str(tmp / "taken")

    outs = {
        "run --out a folder": (lambda tmp: ["run", "--duration", "5", "--out", str(tmp)], "--out"),
        "run --out under a file": (lambda tmp: ["run", "--duration", "5", "--out", a_file(tmp) + "/log.csv"], "--out"),
        "plan --png x.txt": (lambda tmp: ["plan", "--png", str(tmp / "x.txt")], "--png"),
        "plan --png a folder": (lambda tmp: ["plan", "--png", str(tmp)], "--png"),
        "evaluate --out a file": (lambda tmp: ["evaluate", str(STUDY), "--out", a_file(tmp)], "--out"),
        "evaluate --out under a file": (lambda tmp: ["evaluate", str(STUDY), "--out", a_file(tmp) + "/r"], "--out"),
        "reproduce --out a file": (lambda tmp: ["reproduce", "--out", a_file(tmp)], "--out"),
        "train --out a file": (lambda tmp: ["train", "--algo", "ppo", "--out", a_file(tmp)], "--out"),
        "compare --out a file": (lambda tmp: ["compare", "--out", a_file(tmp)], "--out"),
    }
    for case, (build, named) in outs.items():
        cases.append(("output paths", case, build, named))

    workers = {
        "evaluate --workers 100000": (["--workers", "100000"], "--workers"),
        "evaluate --workers -1": (["--workers", "-1"], "--workers"),
        "evaluate --workers 0": (["--workers", "0"], "--workers"),
        "evaluate --robots ''": (["--robots", ""], "--robots"),
        "evaluate --humans ' , '": (["--humans", " , "], "--humans"),
    }
    for case, (extra, named) in workers.items():
        cases.append(("workers and lists", case,
                      lambda tmp, e=extra: ["evaluate", str(STUDY), "--out", str(tmp / "r"), *e], named))  # fmt: skip
    cases.append(("workers and lists", "reproduce --workers 100000",
                  lambda tmp: ["reproduce", "--workers", "100000", "--out", str(tmp / "r")], "--workers"))  # fmt: skip
    cases.append(("workers and lists", "compare --algos ','",
                  lambda tmp: ["compare", "--algos", ",", "--out", str(tmp / "r")], "--algos"))  # fmt: skip
    return cases


CASES = _cases()


PROGRESS = re.compile(r"\d+/\d+ \[")
"""A tqdm bar's line (``tiny: 0%| | 0/4 [00:00<?, ?run/s]``)."""


def check_refused(code: int, err: str, named: str, *, progress: bool = False) -> None:
    """The bad-input rule: exit 2, one ``error:`` line naming what to fix, no traceback.

    ``progress``: the failure comes mid-run (a full disk), after a progress bar that
    stays on screen; the bar's lines are not error lines.
    """
    lines = [x for x in error_lines(err) if not (progress and PROGRESS.search(x))]
    assert code == 2, err[-2000:]
    assert len(lines) == 1 and lines[0].startswith("error: "), err[-2000:]
    assert named in lines[0], lines[0]
    assert "Traceback" not in err


def files_under(folder: Path) -> set[Path]:
    return {p for p in folder.rglob("*")}


@pytest.mark.parametrize(("family", "case", "build", "named"), CASES, ids=[f"{f}: {c}" for f, c, _, _ in CASES])
def test_bad_input_is_refused_before_anything_is_written(
    family: str,
    case: str,
    build: Callable[[Path], list[str]],
    named: str,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.chdir(tmp_path)
    args = build(tmp_path)
    before = files_under(tmp_path)
    code, _, err = run_main(args)
    check_refused(code, err, named)
    assert files_under(tmp_path) == before, sorted(map(str, files_under(tmp_path) - before))


@pytest.mark.parametrize("edit", list(TRACE_EDITS), ids=list(TRACE_EDITS))
@pytest.mark.parametrize("command", ["traces", "replay"])
def test_crafted_trace_is_refused_by_traces_and_replay(
    game_lines: list[dict], edit: str, command: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    change, named = TRACE_EDITS[edit]
    path = tmp_path / "t.jsonl"
    path.write_text(_trace(game_lines, change).replace('"INF_PLACEHOLDER"', "1e400"))
    monkeypatch.chdir(tmp_path)
    before = files_under(tmp_path)
    code, _, err = run_main([command, str(path), *(["--no-compare"] if command == "traces" else [])])
    check_refused(code, err, named)
    assert str(path) in err
    assert files_under(tmp_path) == before


@pytest.mark.parametrize("command", ["traces", "replay"])
def test_the_unedited_game_is_accepted(game_lines: list[dict], command: str, tmp_path: Path) -> None:
    """The base of the trace cases is valid: each refusal above is the edit's doing."""
    path = tmp_path / "t.jsonl"
    path.write_text(_trace(game_lines, lambda lines: None))
    code, out, err = run_main([command, str(path), *(["--no-compare"] if command == "traces" else [])])
    assert code == 0, err
    tasks = game_lines[-1]["tasks_solved"]
    if command == "traces":
        assert f"{len(game_lines) - 2} session" not in out and "1 session(s)" in out
        row = next(line for line in out.splitlines() if line.startswith("recorded"))
        assert row.split()[1:3] == [str(len(game_lines) - 2), str(tasks)]
    else:
        assert "same as the recording" in out


# ---- model files -------------------------------------------------------------------------


def _policy(tmp: Path, w: np.ndarray | None = None, **header: object) -> Path:
    from hg_marl.agents.model_file import save_model_file, world_fields

    n_a, n_f = WORLD.n_actions(Agent.HUMAN), WORLD.n_facts
    fields = {**world_fields(WORLD, Agent.HUMAN), "kind": "linear_softmax", "temperature": 1.0, **header}
    save_model_file(tmp / "policy.json", fields, {"W": np.zeros((n_a, n_f)) if w is None else w, "b": np.zeros(n_a)})
    return tmp / "policy.json"


def _edit_header(path: Path, **fields: object) -> Path:
    data = json.loads(path.read_text())
    for key, value in fields.items():
        if value is None:
            data.pop(key, None)
        else:
            data[key] = value
    path.write_text(json.dumps(data))
    return path


def _sb3_header(tmp: Path, net_arch: object) -> Path:
    """An SB3 header (arrays need not fit: the policy's size is refused before they are read)."""
    from gymnasium import spaces

    from hg_marl.agents.model_file import save_model_file, space_to_json, world_fields

    fields = {
        **world_fields(WORLD, Agent.ROBOT),
        "kind": "sb3",
        "algo": "PPO",
        "policy": "MlpPolicy",
        "observation": "facts",
        "observation_space": space_to_json(spaces.MultiBinary(WORLD.n_facts)),
        "action_space": space_to_json(spaces.Discrete(WORLD.n_actions(Agent.ROBOT))),
        "policy_kwargs": {"net_arch": net_arch},
        "state": {},
    }
    save_model_file(tmp / "model.json", fields, {"x": np.zeros(1)})
    return tmp / "model.json"


SHAPE = (WORLD.n_actions(Agent.HUMAN), WORLD.n_facts)

MODEL_CASES: dict[str, tuple[Callable[[Path], list[str]], str]] = {
    "NaN weight": (lambda t: _human(_policy(t, np.full(SHAPE, np.nan))), "finite"),
    "infinite weight": (lambda t: _human(_policy(t, np.full(SHAPE, np.inf))), "finite"),
    "weight 1e300": (lambda t: _human(_policy(t, np.full(SHAPE, 1e300))), "W and b"),
    "temperature 1e-300": (lambda t: _human(_policy(t, temperature=1e-300)), "'temperature'"),
    "temperature 1e300": (lambda t: _human(_policy(t, temperature=1e300)), "'temperature'"),
    "no sha256": (lambda t: _human(_edit_header(_policy(t), sha256=None)), "'sha256'"),
    "sha256 a number": (lambda t: _human(_edit_header(_policy(t), sha256=5)), "'sha256'"),
    "header of 2 MB": (lambda t: _human(_edit_header(_policy(t), padding="x" * (2 << 20))), "larger than"),
    "sb3 net_arch 200000 units": (lambda t: _sb3(_sb3_header(t, [200000, 200000])), "net_arch"),
    "sb3 net_arch of 4096 x 3": (lambda t: _sb3(_sb3_header(t, [4096, 4096, 4096])), "net_arch"),
    "sb3 net_arch negative": (lambda t: _sb3(_sb3_header(t, [-3])), "net_arch"),
}  # fmt: skip


def _human(path: Path) -> list[str]:
    return ["run", "--duration", "5", "--human", f"learned:path={path.parent}"]


def _sb3(path: Path) -> list[str]:
    return ["run", "--duration", "5", "--robot", "sb3", "--model", str(path)]


@pytest.mark.parametrize("case", list(MODEL_CASES), ids=list(MODEL_CASES))
def test_bad_model_file_is_refused_naming_it(case: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    if case.startswith("sb3"):
        pytest.importorskip("stable_baselines3")
    build, named = MODEL_CASES[case]
    args = build(tmp_path)
    monkeypatch.chdir(tmp_path)
    before = files_under(tmp_path)
    code, _, err = run_main(args)
    check_refused(code, err, named)
    assert str(tmp_path) in err
    assert files_under(tmp_path) == before


# ---- a full disk ------------------------------------------------------------------------


def _full_disk(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every ``os.replace`` (the last step of an atomic write) fails as on a full disk."""

    def replace(src: object, dst: object) -> None:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(dst))

    monkeypatch.setattr(os, "replace", replace)
    monkeypatch.setattr(Path, "replace", lambda self, target: replace(self, target))


def test_run_out_on_a_full_disk_is_one_line_and_leaves_nothing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _full_disk(monkeypatch)
    code, _, err = run_main(["run", "--duration", "5", "--out", str(tmp_path / "log.csv")])
    check_refused(code, err, "No space left on device")
    assert f"{tmp_path / 'log.csv'}" in err
    assert list(tmp_path.iterdir()) == []  # neither the log nor its temporary file


def test_behaviour_cloning_on_a_full_disk_is_one_line_and_leaves_nothing(
    game_lines: list[dict], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    trace = tmp_path / "t.jsonl"
    trace.write_text(_trace(game_lines, lambda lines: None))
    _full_disk(monkeypatch)
    code, _, err = run_main(["train", "--algo", "bc", "--traces", str(trace), "--out", str(tmp_path / "bc")])
    check_refused(code, err, "No space left on device")
    assert [p.name for p in tmp_path.rglob("*") if p.is_file()] == ["t.jsonl"]


def test_evaluate_on_a_full_disk_is_one_line(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _full_disk(monkeypatch)
    code, _, err = run_main(["evaluate", str(STUDY), "--out", str(tmp_path / "r"), "--workers", "1", "--seeds", "1"])
    check_refused(code, err, "No space left on device", progress=True)
    assert not [p for p in tmp_path.rglob("*.tmp")]


def test_a_forbidden_folder_is_one_line(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """EACCES (simulated: the tests may run as root, for whom chmod forbids nothing)."""
    import tempfile

    def mkstemp(*args: object, **kwargs: object) -> None:
        raise PermissionError(errno.EACCES, os.strerror(errno.EACCES), str(kwargs.get("dir")))

    monkeypatch.setattr(tempfile, "mkstemp", mkstemp)
    code, _, err = run_main(["run", "--duration", "5", "--out", str(tmp_path / "log.csv")])
    check_refused(code, err, "Permission denied")
    assert list(tmp_path.iterdir()) == []


# ---- real processes: a 2 GiB address space (600 s: a hang guard only) ----------------------

LIMIT_BYTES = 2 << 30


def _limit() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (LIMIT_BYTES, LIMIT_BYTES))


SUBPROCESS: dict[str, tuple[Callable[[Path, list[dict]], list[str]], str]] = {
    "durations 1e-300": (
        lambda t, g: ["run", "--scenario", str(_write(t / "s.toml", with_durations("pick = 1e-300")))],
        "durations.pick",
    ),
    "replay of an end clock 5e6": (
        lambda t, g: ["replay", str(_write(t / "t.jsonl", _trace(g, _set(-1, clock=5e6))))], "'clock'"
    ),
    "traces of an end clock 5e6": (
        lambda t, g: ["traces", str(_write(t / "t.jsonl", _trace(g, _set(-1, clock=5e6))))], "'clock'"
    ),
    "net_arch of 160 GB": (
        lambda t, g: ["train", "--algo", "ppo", "--hp", "policy_kwargs.net_arch=[200000,200000]",
                      "--out", str(t / "o")],
        "net_arch",
    ),
    "workers 100000": (
        lambda t, g: ["evaluate", str(STUDY), "--out", str(t / "r"), "--workers", "100000"], "--workers"
    ),
}  # fmt: skip


def _write(path: Path, text: str) -> Path:
    path.write_text(text)
    return path


@pytest.mark.parametrize("case", list(SUBPROCESS), ids=list(SUBPROCESS))
def test_worst_inputs_in_a_real_process_under_limits(game_lines: list[dict], case: str, tmp_path: Path) -> None:
    build, named = SUBPROCESS[case]
    args = build(tmp_path, game_lines)
    before = files_under(tmp_path)
    proc = subprocess.run(
        [sys.executable, "-c", "from hg_marl.training.cli import main; main()", *args],
        capture_output=True,
        text=True,
        timeout=600,  # a hang guard only: the refusal takes seconds, but a loaded machine may be slow
        preexec_fn=_limit,
        cwd=tmp_path,
        env={**os.environ, "OMP_NUM_THREADS": "1"},
    )
    check_refused(proc.returncode, proc.stderr, named)
    assert files_under(tmp_path) == before


# ---- the larger sweep (slow) ---------------------------------------------------------------

json_values = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-(10**20), 10**20),
    st.floats(allow_nan=False, allow_infinity=False),
    st.text(max_size=6),
    st.lists(st.integers(-2, 2), max_size=3),
    st.dictionaries(st.text(max_size=3), st.integers(), max_size=2),
)


@pytest.mark.slow
@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(line=st.integers(0, 5), key=st.sampled_from(["clock", "tasks_solved", "rewards", "seed", "seat", "scenario",
       "meta", "actor", "response_time", "step", "action", "facts", "mask", "type"]), value=json_values)  # fmt: skip
def test_sweep_any_field_any_value_is_accepted_or_one_line(
    game_lines: list[dict], tmp_path: Path, line: int, key: str, value: object
) -> None:
    index = line if line < 5 else -1
    path = tmp_path / "t.jsonl"
    path.write_text(_trace(game_lines, _set(index, **{key: value})))
    code, _, err = run_main(["traces", str(path), "--no-compare"])
    assert code in (0, 2), err[-2000:]
    if code == 2:
        lines = error_lines(err)
        assert len(lines) == 1 and lines[0].startswith("error: ") and "Traceback" not in err, err[-2000:]


@pytest.mark.slow
@settings(max_examples=300, deadline=None)
@given(name=st.text(min_size=0, max_size=70), where=st.sampled_from(['name = "tape1"', 'name = "mat_left"',
       'name = "trashbin"', 'name = "paper2015"']))  # fmt: skip
def test_sweep_any_name_loads_safely_or_is_refused(name: str, where: str) -> None:
    import tomllib

    from hg_marl.core.errors import HgMarlError
    from hg_marl.core.scenario import parse_scenario

    try:
        data = tomllib.loads(PAPER.replace(where, f"name = {json.dumps(name)}", 1))
    except tomllib.TOMLDecodeError:
        return
    try:
        scenario = parse_scenario(data, "s.toml")
    except HgMarlError as exc:
        assert "\n" not in str(exc)
        return
    world = World(scenario)
    for agent in Agent:
        assert len(set(world.action_names[agent])) == world.n_actions(agent)  # no two actions share a name
    assert "/" not in scenario.name and not scenario.name.startswith(".")


def test_case_counts_match_the_docs() -> None:
    """The "Bad input" page states how many probe cases each family has; keep it honest."""
    from tests.docs_sections import section

    readme = section("bad-input.md")
    counts: dict[str, int] = {}
    for family, *_ in CASES:
        counts[family] = counts.get(family, 0) + 1
    counts["traces"] = 2 * len(TRACE_EDITS)
    counts["model files"] = len(MODEL_CASES)
    counts["full disk"] = 4
    total = sum(counts.values()) + len(SUBPROCESS)
    assert f"{total} probe cases" in readme
    for family, n in counts.items():
        assert f"{family} ({n})" in readme, family
