"""The README's "Play and watch" examples run: the Python block, then its shell commands."""

from __future__ import annotations

import re
import shlex
import subprocess
from pathlib import Path

import pytest

from hg_marl.training.cli import main

README = Path(__file__).resolve().parents[2] / "README.md"


def section() -> str:
    text = README.read_text()
    start = text.index("## Play and watch")
    return text[start : text.index("\n## ", start + 1)]


def blocks(kind: str) -> list[str]:
    return re.findall(rf"```{kind}\n(.*?)```", section(), flags=re.S)


def test_readme_play_examples_run(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    (python,) = blocks("python")
    exec(compile(python, "README.md", "exec"), {})
    assert len(list((tmp_path / "runs/play").glob("*.jsonl"))) == 1
    interactive, batch = blocks("bash")
    assert all(line.startswith("hg-marl play") for line in interactive.strip().splitlines())
    for line in batch.strip().splitlines():
        command = line.split("  #")[0].strip()
        command = subprocess.run(["bash", "-c", f"echo {command}"], capture_output=True, text=True).stdout
        monkeypatch.setattr("sys.argv", shlex.split(command))
        with pytest.raises(SystemExit) as stop:
            main()
        assert stop.value.code in (0, None), line
    assert (tmp_path / "runs/me.gif").exists() and (tmp_path / "runs/replay.gif").exists()
