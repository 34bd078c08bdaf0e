"""Output paths: every command checks where it will write before any work, the same way.

The rule (training/outputs.py, docs/inputs.md): an output file's folder must exist (it is
never created), an output folder is created with its parents, and either way the place
is tried by creating and removing a temporary file before the work starts. A place the
OS refuses (``/proc``, which not even root can write in; a folder without permission,
simulated since tests may run as root) is one ``error:`` line naming the option, exit
2, and nothing is left behind.

Also here: a trace whose steps leave out the optional ``action_name`` is read the same
as one that states it, by every command that reads traces.
"""

from __future__ import annotations

import errno
import json
import os
import re
from collections.abc import Callable
from pathlib import Path

import pytest

from hg_marl.training.outputs import check_output
from tests.cli_helpers import run_main
from tests.fuzz.test_probe import STUDY, check_refused, files_under

UNWRITABLE = Path("/proc/hg-marl-no-such-folder")
"""A place no process can create files in (procfs); the folder itself does not exist."""

needs_proc = pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="needs Linux procfs")


def _trace(tmp: Path) -> str:
    """A short valid recorded game (the cooperative human against the planner)."""
    from hg_marl.agents.humans import make_human
    from hg_marl.agents.humans.trace import TraceRecorder
    from hg_marl.training.play.session import build_robot
    from hg_marl.training.runner import RunConfig, run

    path = tmp / "game.jsonl"
    recorder = TraceRecorder(make_human("cooperative"), path, seed=0, meta={"robot": "planner", "player": "p"})
    run(build_robot("planner"), recorder, RunConfig(duration=30.0, seed=0))
    recorder.close()
    return str(path)


# (command line with the output path P substituted, option named, is P a folder)
OUTPUTS: dict[str, tuple[Callable[[Path, str], list[str]], str, bool]] = {
    "run --out": (lambda t, p: ["run", "--duration", "5", "--out", p], "--out", False),
    "run --video": (lambda t, p: ["run", "--duration", "5", "--video", p], "--video", False),
    "plan --png": (lambda t, p: ["plan", "--png", p], "--png", False),
    "replay --video": (lambda t, p: ["replay", _trace(t), "--video", p], "--video", False),
    "population generate --out": (lambda t, p: ["population", "generate", "--out", p], "--out", False),
    "convert --out": (lambda t, p: ["convert", str(t / "m.zip"), "--trust", "--out", p], "--out", False),
    "evaluate --out": (lambda t, p: ["evaluate", str(STUDY), "--out", p], "--out", True),
    "reproduce --out": (lambda t, p: ["reproduce", "--out", p], "--out", True),
    "compare --out": (lambda t, p: ["compare", "--out", p], "--out", True),
    "train --out": (lambda t, p: ["train", "--algo", "ppo", "--out", p], "--out", True),
    "headroom --out": (lambda t, p: ["headroom", "--out", p], "--out", True),
    "switching --out": (
        lambda t, p: ["switching", "--population", str(t / "no.toml"), "--pairs", "a/b", "--out", p], "--out", True),
    "population generate --store": (
        lambda t, p: ["population", "generate", "--out", str(t / "p.toml"), "--store", p], "--store", True),
    "play --record": (lambda t, p: ["play", "--no-browser", "--record", p], "--record", True),
}  # fmt: skip

SUFFIX = {"--png": ".png", "--video": ".gif", "population generate --out": ".toml", "convert --out": ".json"}


def _file_name(case: str, option: str) -> str:
    return "x" + SUFFIX.get(case, SUFFIX.get(option, ".csv"))


def _refused(case: str, path: str, tmp: Path, monkeypatch: pytest.MonkeyPatch, named: str) -> None:
    build, option, _ = OUTPUTS[case]
    if "compare" in case or "train" in case:
        pytest.importorskip("stable_baselines3")
    args = build(tmp, path)
    monkeypatch.chdir(tmp)
    before = files_under(tmp)
    code, _, err = run_main(args)
    check_refused(code, err, named)
    assert f"{option} {path}" in err
    assert files_under(tmp) == before, sorted(map(str, files_under(tmp) - before))


@needs_proc
@pytest.mark.parametrize("case", list(OUTPUTS), ids=list(OUTPUTS))
def test_an_unwritable_place_is_refused_before_work(case: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _, option, folder = OUTPUTS[case]
    path = UNWRITABLE / "sub" if folder else Path("/proc") / _file_name(case, option)
    _refused(case, str(path), tmp_path, monkeypatch, "cannot write in /proc")
    assert not path.exists()


FILES = [case for case, (_, _, folder) in OUTPUTS.items() if not folder]


@pytest.mark.parametrize("case", FILES, ids=FILES)
def test_a_missing_folder_for_a_file_is_refused_not_created(
    case: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """``--video`` used to create the missing folders that ``--out`` and ``--png`` refuse."""
    option = OUTPUTS[case][1]
    missing = tmp_path / "no" / "such"
    _refused(case, str(missing / _file_name(case, option)), tmp_path, monkeypatch, "does not exist")
    assert not (tmp_path / "no").exists()


def test_a_forbidden_folder_is_refused_whoever_runs_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The OS's answer decides (simulated EACCES: root passes every permission test but not this one)."""
    import tempfile

    def mkstemp(*args: object, **kwargs: object) -> None:
        raise PermissionError(errno.EACCES, os.strerror(errno.EACCES), str(kwargs.get("dir")))

    monkeypatch.setattr(tempfile, "mkstemp", mkstemp)
    for case in ("run --out", "evaluate --out", "plan --png"):
        _, option, folder = OUTPUTS[case]
        path = tmp_path / ("r" if folder else _file_name(case, option))
        _refused(case, str(path), tmp_path, monkeypatch, "Permission denied")


def test_the_check_leaves_nothing_and_creates_no_folder(tmp_path: Path) -> None:
    assert check_output(tmp_path / "log.csv", "--out") == tmp_path / "log.csv"
    assert check_output(tmp_path / "a" / "b", "--out", folder=True) == tmp_path / "a" / "b"
    assert list(tmp_path.iterdir()) == []  # the probe file is gone; the folder is made by the writer, later


def test_an_existing_file_is_kept_as_it_was(tmp_path: Path) -> None:
    target = tmp_path / "log.csv"
    target.write_text("keep")
    check_output(target, "--out")
    assert target.read_text() == "keep" and [p.name for p in tmp_path.iterdir()] == ["log.csv"]


@pytest.mark.parametrize(
    ("make", "folder", "message"),
    [
        (lambda t: t / "x.txt", False, "expected a file name ending in .png"),
        (lambda t: t / "d.png", False, "is a folder; name a file"),
        (lambda t: t / "f" / "x.png", False, "f is a file, not a folder"),
        (lambda t: t / "f", True, "is a file; name a folder"),
        (lambda t: t / "f" / "sub", True, "f is a file, not a folder"),
        (lambda t: t / ("n" * 300) / "x.png", False, "not a usable path"),
        (lambda t: Path("/dev/null"), False, "not a regular file"),
    ],
)
def test_what_is_wrong_is_named(tmp_path: Path, make: Callable[[Path], Path], folder: bool, message: str) -> None:
    from hg_marl.core.errors import ConfigError

    (tmp_path / "f").write_text("a file")
    (tmp_path / "d.png").mkdir()
    with pytest.raises(ConfigError, match=re.escape(message)):
        path = make(tmp_path)
        check_output(path, "--png", folder=folder, suffixes=() if folder or path.parent == Path("/dev") else (".png",))


# ---- a trace without the optional action_name ------------------------------------------------


@pytest.fixture(scope="module")
def traces(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """The same recorded game twice: as written, and with every step's ``action_name`` left out."""
    folder = tmp_path_factory.mktemp("traces")
    full = Path(_trace(folder))
    lines = [json.loads(x) for x in full.read_text().splitlines()]
    steps = [line for line in lines if line["type"] == "step"]
    assert steps and all("action_name" in s for s in steps)
    bare = folder / "bare.jsonl"
    bare.write_text("".join(json.dumps({k: v for k, v in x.items() if k != "action_name"}) + "\n" for x in lines))
    return full, bare


@pytest.mark.parametrize("command", ["replay", "traces", "run"])
def test_a_trace_without_action_names_reads_as_with_them(command: str, traces: tuple[Path, Path]) -> None:
    outputs = []
    for path in traces:
        if command == "run":
            args = ["run", "--duration", "30", "--robot", "planner", "--human", f"replay:path={path}"]
        else:
            args = [command, str(path), *(["--no-compare"] if command == "traces" else [])]
        code, out, err = run_main(args)
        assert code == 0, err
        outputs.append(out.replace(str(path), "TRACE"))
    assert outputs[0] == outputs[1]


def test_evaluate_replays_a_trace_without_action_names(traces: tuple[Path, Path], tmp_path: Path) -> None:
    rates = []
    for i, path in enumerate(traces):
        study = tmp_path / f"s{i}.toml"
        study.write_text(f'seeds = 1\nduration = 30.0\nrobots = ["planner"]\nhumans = ["replay:path={path}"]\n')
        code, _, err = run_main(["evaluate", str(study), "--out", str(tmp_path / f"o{i}"), "--workers", "1"])
        assert code == 0, err
        rows = (tmp_path / f"o{i}" / "scores.csv").read_text().splitlines()
        header = rows[0].split(",")
        rates.append([{k: v for k, v in zip(header, row.split(","), strict=False) if k in ("tasks", "rate")}
                      for row in rows[1:]])  # fmt: skip
    assert len(rates[0]) == 1 and rates[0] == rates[1]
