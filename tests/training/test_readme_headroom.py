"""The README's "Hard layouts, adaptation headroom and BR-Prox" section runs as written."""

from __future__ import annotations

import csv
import re
import shlex
from pathlib import Path

import pytest

from tests.cli_helpers import run_main

ROOT = Path(__file__).resolve().parents[2]
TEXT = (ROOT / "README.md").read_text()
SECTION = TEXT[TEXT.index("## Hard layouts, adaptation headroom and BR-Prox\n") :]
SECTION = SECTION[: SECTION.index("\n## ", 1)]
COMMANDS = [c for block in re.findall(r"```bash\n(.*?)```", SECTION, flags=re.S) for c in block.splitlines()]


def test_the_section_has_its_examples() -> None:
    assert [shlex.split(c)[1] for c in COMMANDS] == ["headroom", "headroom", "evaluate", "run", "switching"]


@pytest.mark.parametrize("command", [c for c in COMMANDS if " headroom " in c])
def test_headroom_example_runs(command: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(ROOT)
    args = shlex.split(command.replace("results/", f"{tmp_path}/"))[1:]
    code, out, err = run_main(args)
    assert code == 0, err
    assert "adaptation headroom" in out
    out_dir = Path(args[args.index("--out") + 1])
    assert {p.name for p in out_dir.iterdir()} == {"headroom.csv", "headroom.png", "headroom.json"}


@pytest.mark.slow
def test_adaptation_study_example_runs_narrowed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(ROOT)
    command = next(c for c in COMMANDS if " evaluate " in c)
    # one hard layout, one seed, two robots: the whole study is measured in the README, not here
    narrow = ["--seeds", "1", "--robots", "planner,oracle", "--scenarios", "forced_coordination"]
    args = [*shlex.split(command.replace("results/", f"{tmp_path}/"))[1:], *narrow]
    code, _, err = run_main([*args, "--workers", "1"])
    assert code == 0, err
    report = (tmp_path / "adaptation" / "report.md").read_text()
    assert "BR-Prox" in report and "roboergosum" not in report
    # the oracle plays each member's exact best response: only chance keeps its BR-Prox below 1
    with (tmp_path / "adaptation" / "scores.csv").open() as f:
        rows = list(csv.DictReader(f))
    oracle = [float(r["br_prox"]) for r in rows if r["robot"] == "oracle" and r["br_prox"]]
    assert len(oracle) >= 4 and min(oracle) >= 0.9, oracle


def test_switching_example_runs_narrowed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(ROOT)
    command = next(c for c in COMMANDS if " switching " in c)
    args = shlex.split(command.replace("results/", f"{tmp_path}/"))[1:]
    # the README's robots and pairs, one seed, two periods, a short run
    args[args.index("--periods") + 1] = "20,120"
    code, out, err = run_main([*args, "--seeds", "1", "--duration", "240"])
    assert code == 0, err
    assert "cells where a robot loses to planner" in out
    assert {p.name for p in (tmp_path / "switching-forced").iterdir()} >= {"switching.json", "switching.png"}
