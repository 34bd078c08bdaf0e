"""The "Play and watch" page's examples (``docs/play.md``) run: the Python block, then its shell commands."""

from __future__ import annotations

import shlex
import subprocess
from pathlib import Path

import pytest

from hg_marl.training.cli import main
from tests import docs_sections


def blocks(kind: str) -> list[str]:
    return docs_sections.blocks(docs_sections.section("play.md"), kind)


def test_readme_play_examples_run(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    (python,) = blocks("python")
    exec(compile(python, "docs/play.md", "exec"), {})
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
