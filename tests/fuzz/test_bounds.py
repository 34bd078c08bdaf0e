"""Counts, sizes and long numbers: bounded before anything is allocated, refused in one line.

Each case below once grew a process past gigabytes, ended in a traceback, or was
refused only after runs had started (leaving claim files in the output folder). The rule
checked is the project's bad-input rule (exit 2, one ``error:`` line naming the option or
``file:line``, nothing written); :func:`test_worst_counts_in_a_real_process_under_limits`
also runs the worst of them as real processes under a 2 GiB address space, so an
allocation in proportion to the count fails the test instead of swapping. Limits are
read from the code that enforces them (:mod:`hg_marl.training.limits`) and their values
checked against docs/inputs.md, where users read them.
"""

from __future__ import annotations

import io
import json
import os
import resource
import subprocess
import sys
import zipfile
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.humans.population import MAX_MEMBERS
from hg_marl.core.errors import MAX_DIGITS
from hg_marl.training.limits import MAX_RUNS, MAX_SEEDS
from hg_marl.training.runner import MAX_CYCLES
from tests.cli_helpers import HANG_GUARD, run_main
from tests.fuzz.test_probe import PAPER, check_refused, files_under, with_durations

DOCS = Path(__file__).parents[2] / "docs" / "inputs.md"
LONG = "7" * (MAX_DIGITS + 700)
"""A number Python refuses to convert (its digit limit), as typed into a file or an option."""


def study(tmp: Path, *lines: str, name: str = "s.toml") -> str:
    """A study file of one planner and one cooperative human, with ``lines`` added."""
    base = ['robots = ["planner"]', 'humans = ["cooperative"]', "duration = 20.0"]
    keys = {line.split("=")[0].strip() for line in lines}
    text = "\n".join([*lines, *(b for b in base if b.split("=")[0].strip() not in keys)]) + "\n"
    (tmp / name).write_text(text)
    return str(tmp / name)


def _write(tmp: Path, name: str, text: str) -> str:
    (tmp / name).write_text(text)
    return str(tmp / name)


FAST = with_durations(*(f"{k} = 0.01" for k in ("pick", "throw", "give", "take", "place", "goto", "wait", "failed")))
"""paper2015 with every action at the 0.01 s floor: 1e7 s is 1e9 cycles, over the limit."""


CASES: dict[str, tuple[Callable[[Path], list[str]], str]] = {
    # seeds, runs and durations of a study: file:line and the limit
    "study seeds = 1e9": (lambda t: ["evaluate", study(t, "seeds = 1000000000"), "--out", str(t / "o")],
                          f"s.toml:1: seeds: 1,000,000,000 is over the limit of {MAX_SEEDS:,}"),
    "study seeds = 2**63-1": (lambda t: ["evaluate", study(t, f"seeds = {2**63 - 1}"), "--out", str(t / "o")],
                              f"s.toml:1: seeds: {2**63 - 1:,} is over the limit of {MAX_SEEDS:,}"),
    "study seed value 2**64": (lambda t: ["evaluate", study(t, f"seeds = [1, {2**64}]"), "--out", str(t / "o")],
                               "s.toml:1: seeds"),
    "study runs over the limit": (
        lambda t: ["evaluate", study(t, f"seeds = {MAX_SEEDS}", 'humans = ' + json.dumps(
            ["cooperative", *(f"lazy:p_idle=0.{i}" for i in range(1, 10)), "noisy", "random",
             *(f"noisy:temperature={i}" for i in range(2, 12))])), "--out", str(t / "o")],
        f"over the limit of {MAX_RUNS:,} runs"),
    "study duration = 1e300": (lambda t: ["evaluate", study(t, "seeds = 1", "duration = 1e300"), "--out", str(t / "o")],
                               "s.toml:2: duration 1e+300: up to 5e+300 cycles"),
    "study seeds of 5000 digits": (lambda t: ["evaluate", study(t, f"seeds = {LONG}"), "--out", str(t / "o")],
                                   f"s.toml:1: a number of {len(LONG):,} digits"),
    # counts on the command line
    "reproduce --seeds 1e9": (lambda t: ["reproduce", "--seeds", "1000000000", "--out", str(t / "o")],
                              f"--seeds: 1,000,000,000 is over the limit of {MAX_SEEDS:,}"),
    "reproduce --duration over the cycle limit": (
        lambda t: ["reproduce", "--duration", "1e7", "--scenario", _write(t, "f.toml", FAST), "--out", str(t / "o")],
        f"--duration 1e+07: up to 1e+09 cycles at the shortest action duration (0.01 s), over the limit "
        f"{MAX_CYCLES:,}"),
    "switching --duration over the cycle limit": (
        lambda t: ["switching", "--population", "p.toml", "--pairs", "a/b", "--duration", "1e7", "--scenario",
                   _write(t, "f.toml", FAST), "--out", str(t / "o")], "--duration 1e+07"),
    "population --duration over the cycle limit": (
        lambda t: ["population", "generate", "--out", str(t / "p.toml"), "--duration", "1e7", "--scenario",
                   _write(t, "f.toml", FAST)], "--duration 1e+07"),
    "reproduce --adaptation-seeds 1e9": (
        lambda t: ["reproduce", "--adaptation-seeds", "1000000000", "--out", str(t / "o")], "--adaptation-seeds"),
    "compare --seeds 1e9": (lambda t: ["compare", "--seeds", "1000000000", "--out", str(t / "o")], "--seeds"),
    "compare --humans bogus": (lambda t: ["compare", "--humans", "bogus", "--out", str(t / "o")],
                               "--humans: unknown human 'bogus'"),
    "population --train 1e6": (lambda t: ["population", "generate", "--out", str(t / "p.toml"), "--train", "1000000"],
                               f"--train: 1,000,000 is over the limit of {MAX_MEMBERS:,}"),
    "population --held-out 1e6": (
        lambda t: ["population", "generate", "--out", str(t / "p.toml"), "--held-out", "1000000"], "--held-out"),
    # numbers of 5000 digits, in each kind of file and option
    "scenario file": (lambda t: ["run", "--scenario", _write(t, "x.toml", PAPER + f"\nseed = {LONG}\n")],
                      f"x.toml:{PAPER.count(chr(10)) + 2}: a number of"),
    "population file": (lambda t: ["population", "show", _write(t, "p.toml", f'name = "p"\n\n[[members]]\nx = {LONG}')],
                        "p.toml:4: a number of"),
    "spec parameter": (lambda t: ["run", "--human", f"lazy:p_idle={LONG}"], "parameter 'p_idle': a number of"),
    "--hp": (lambda t: ["train", "--algo", "ppo", "--hp", f"n_steps={LONG}", "--out", str(t / "o")],
             "override n_steps: a number of"),
    "hyperparameters file": (lambda t: ["train", "--algo", "ppo", "--hyperparams",
                                        _write(t, "hp.yml", f"default:\n  n_steps: {LONG}\n"), "--out", str(t / "o")],
                             "hp.yml:2: a number of"),
    # an option that would be ignored
    "run --robot planner --criterion vpi": (lambda t: ["run", "--robot", "planner", "--criterion", "vpi"],
                                            "--criterion vpi: only for --robot hybrid, not planner"),
    "--criterion and --robot-param criterion": (
        lambda t: ["run", "--criterion", "vpi", "--robot-param", "criterion=random"], "--criterion"),
}  # fmt: skip


@pytest.mark.parametrize("case", list(CASES), ids=list(CASES))
def test_counts_and_long_numbers_are_refused_before_anything_is_written(
    case: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    build, named = CASES[case]
    args = build(tmp_path)
    monkeypatch.chdir(tmp_path)
    before = files_under(tmp_path)
    code, _, err = run_main(args)
    check_refused(code, err, named)
    assert "Traceback" not in err and "sys.set_int_max_str_digits" not in err
    assert files_under(tmp_path) == before  # no store, no claim file, no output folder


def test_a_study_within_the_limits_loads(tmp_path: Path) -> None:
    """The boundary itself is accepted: the refusals above are the counts' doing."""
    from hg_marl.training.study import load_study

    loaded = load_study(study(tmp_path, f"seeds = {MAX_SEEDS}", f"duration = {MAX_CYCLES * 0.2}"))
    assert loaded.seeds == tuple(range(MAX_SEEDS)) and loaded.duration == MAX_CYCLES * 0.2


def test_a_duration_just_over_the_cycle_limit_is_refused_on_load(tmp_path: Path) -> None:
    from hg_marl.core.errors import StudyError
    from hg_marl.training.study import load_study

    # paper2015's shortest action lasts 0.2 s, so MAX_CYCLES cycles last MAX_CYCLES * 0.2 s
    with pytest.raises(StudyError, match=r"s\.toml:2: duration .* over the limit 50,000,000"):
        load_study(study(tmp_path, "seeds = 1", f"duration = {MAX_CYCLES * 0.2 * 1.01}"))


# ---- the label names the criterion the robot was built with -------------------------------


@pytest.mark.parametrize(
    ("args", "label"),
    [
        (["--robot", "hybrid", "--robot-param", "criterion=vpi"], "robot hybrid(vpi) "),
        (["--robot", "hybrid", "--criterion", "vpi"], "robot hybrid(vpi) "),
        (["--robot", "hybrid"], "robot hybrid(entropy_and_cost) "),
        (["--robot", "hybrid:criterion=random"], "robot hybrid:criterion=random "),
        (["--robot", "planner"], "robot planner "),
    ],
)
def test_run_names_the_criterion_it_ran(args: list[str], label: str) -> None:
    code, out, err = run_main(["run", "--duration", "5", *args])
    assert code == 0, err
    assert out.splitlines()[0].startswith(label), out


def test_criterion_given_either_way_runs_the_same() -> None:
    """``--criterion vpi`` and ``--robot-param criterion=vpi`` build the same robot: same run, same summary."""
    runs = [
        run_main(["run", "--duration", "60", *extra])[1]
        for extra in (["--criterion", "vpi"], ["--robot-param", "criterion=vpi"], ["--robot", "hybrid:criterion=vpi"])
    ]
    bodies = [out.split("\n", 1)[1] for out in runs]
    assert bodies[0] == bodies[1] == bodies[2]


# ---- model files: array shapes read from the npy headers ----------------------------------

BIG = (100_000, 1_000)
"""An array of 800 MB of float64, declared in a few bytes of npy header."""


def _bomb_npz(path: Path, name: str, shape: tuple[int, ...]) -> Path:
    """An ``.npz`` whose one member declares ``shape`` but holds 64 bytes (never read if refused)."""
    header = io.BytesIO()
    np.lib.format.write_array_header_1_0(header, {"descr": "<f8", "fortran_order": False, "shape": shape})
    with zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        archive.writestr(f"{name}.npy", header.getvalue() + b"\0" * 64)
    return path


def _human_policy_declaring(tmp: Path, shape: tuple[int, ...]) -> Path:
    from hg_marl.agents.model_file import sha256_of, world_fields, write_header
    from hg_marl.core import Agent, World

    folder = tmp / "policy"
    folder.mkdir()
    weights = _bomb_npz(folder / "policy.npz", "W", shape)
    world = World("paper2015")
    header = {**world_fields(world, Agent.HUMAN), "kind": "linear_softmax", "temperature": 1.0,
              "format": "hg_marl.model", "version": 2, "file": weights.name, "sha256": sha256_of(weights)}  # fmt: skip
    write_header(folder / "policy.json", header)
    return folder


def _sb3_model_declaring(tmp: Path, shape: tuple[int, ...]) -> Path:
    from gymnasium import spaces

    from hg_marl.agents.model_file import sha256_of, space_to_json, world_fields, write_header
    from hg_marl.core import Agent, World

    world = World("paper2015")
    weights = _bomb_npz(tmp / "model.npz", "a0", shape)
    header = {
        **world_fields(world, Agent.ROBOT),
        "kind": "sb3", "algo": "PPO", "policy": "MlpPolicy", "observation": "facts",
        "observation_space": space_to_json(spaces.MultiBinary(world.n_facts)),
        "action_space": space_to_json(spaces.Discrete(world.n_actions(Agent.ROBOT))),
        "policy_kwargs": {"net_arch": [64, 64]}, "state": {"policy": {"w": "a0"}},
        "format": "hg_marl.model", "version": 2, "file": weights.name, "sha256": sha256_of(weights),
    }  # fmt: skip
    write_header(tmp / "model.json", header)
    return tmp / "model.json"


def test_sb3_budget_covers_the_networks_it_describes() -> None:
    """The budget counts (inputs+1) x units per layer for three networks, x 2 (targets) x 3 (Adam) x 8 bytes."""
    from hg_marl.agents.model_limits import SB3_SLACK_BYTES, sb3_budget

    header = {"algo": "PPO", "observation_space": {"type": "MultiBinary", "n": 10},
              "action_space": {"type": "Discrete", "n": 4}, "policy_kwargs": {"net_arch": [8]}}  # fmt: skip
    per_network = (10 + 1) * 8 + (8 + 1) * 4  # worked by hand: 88 + 36 weights and biases
    assert sb3_budget(header) == 3 * per_network * 2 * 3 * 8 + SB3_SLACK_BYTES
    assert sb3_budget({**header, "algo": "RecurrentPPO"}) is None  # not described: the format's 1 GiB applies
    assert sb3_budget({**header, "policy_kwargs": {"lstm_hidden_size": 256}}) is None


def test_model_arrays_are_held_to_their_header_before_reading(tmp_path: Path) -> None:
    from hg_marl.agents.model_file import read_arrays

    path = _bomb_npz(tmp_path / "w.npz", "W", (3, 4))
    with pytest.raises(ValueError, match=r"'W' declares shape \(3, 4\), the header implies \(2, 4\)"):
        read_arrays(path, shapes={"W": (2, 4)})
    with pytest.raises(ValueError, match=r"'W' is not one of V"):
        read_arrays(path, shapes={"V": (3, 4)})
    with pytest.raises(ValueError, match="more than 95 bytes"):
        read_arrays(path, limit=95)  # 3 x 4 x 8 = 96 bytes declared
    rows = _bomb_npz(tmp_path / "t.npz", "facts", (2_000_000, 4))
    with pytest.raises(ValueError, match="2,000,000 rows, over the limit of 1,000,000"):
        read_arrays(rows, shapes={"facts": (None, 4)})


MODEL_BOMBS: dict[str, tuple[Callable[[Path], list[str]], str]] = {
    "human policy declaring 800 MB": (
        lambda t: ["run", "--duration", "5", "--human", f"learned:path={_human_policy_declaring(t, BIG)}"],
        "'W' declares shape (100000, 1000)",
    ),
    "sb3 model declaring 800 MB": (
        lambda t: ["run", "--duration", "5", "--robot", "sb3", "--model", str(_sb3_model_declaring(t, BIG))],
        "bytes of arrays declared, over the limit for its header",
    ),
}


# ---- real processes: a 2 GiB address space; the timeout only guards against a hang ----------

LIMIT_BYTES = 2 << 30


def _limit() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (LIMIT_BYTES, LIMIT_BYTES))


SUBPROCESS: dict[str, tuple[Callable[[Path], list[str]], str]] = {
    "study seeds = 1e9": CASES["study seeds = 1e9"],
    "study seeds = 2**63-1": CASES["study seeds = 2**63-1"],
    "study duration = 1e300": CASES["study duration = 1e300"],
    "reproduce --seeds 1e9": CASES["reproduce --seeds 1e9"],
    **MODEL_BOMBS,
}


@pytest.mark.parametrize("case", list(SUBPROCESS), ids=list(SUBPROCESS))
def test_worst_counts_in_a_real_process_under_limits(case: str, tmp_path: Path) -> None:
    if "sb3" in case:
        pytest.importorskip("stable_baselines3")
    build, named = SUBPROCESS[case]
    args = build(tmp_path)
    before = files_under(tmp_path)
    proc = subprocess.run(
        [sys.executable, "-c", "from hg_marl.training.cli import main; main()", *args],
        capture_output=True,
        text=True,
        timeout=HANG_GUARD,
        preexec_fn=_limit,
        cwd=tmp_path,
        env={**os.environ, "OMP_NUM_THREADS": "1"},
    )
    check_refused(proc.returncode, proc.stderr, named)
    assert files_under(tmp_path) == before


def test_docs_state_the_limits_the_code_enforces() -> None:
    from hg_marl.agents.model_file import MAX_ARRAY_BYTES
    from hg_marl.agents.model_limits import MAX_TABLE_ROWS

    text = DOCS.read_text()
    for value in (MAX_SEEDS, MAX_RUNS, MAX_MEMBERS, MAX_CYCLES, MAX_TABLE_ROWS, MAX_DIGITS):
        assert f"| {value:,} |" in text or f"{value:,} rows" in text, value
    assert f"| {MAX_ARRAY_BYTES >> 30} GiB |" in text


def test_docs_state_the_play_server_defaults() -> None:
    pytest.importorskip("uvicorn")
    from hg_marl.training.play.server_limits import ServerLimits

    text, limits = DOCS.read_text(), ServerLimits()
    for name in ("idle_timeout", "header_timeout", "body_timeout"):
        assert f"| `{name}` | {getattr(limits, name):g} s |" in text, name
    assert f"| `max_connections` | {limits.max_connections} |" in text
    assert f"| `max_header_bytes` | {limits.max_header_bytes:,} |" in text
