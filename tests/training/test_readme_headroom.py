"""The "Hard layouts, adaptation headroom and BR-Prox" page (``docs/hard-layouts.md``) runs as written."""

from __future__ import annotations

import csv
import shlex
from pathlib import Path

import pytest

from tests.cli_helpers import run_main
from tests.docs_sections import ROOT, blocks, section

COMMANDS = [c for block in blocks(section("hard-layouts.md"), "bash") for c in block.splitlines()]


def test_the_section_has_its_examples() -> None:
    # the learned robot's example trains, then evaluates, once per hard layout
    learned = ["train", "evaluate"] * 2
    assert [shlex.split(c)[1] for c in COMMANDS] == ["headroom", "headroom", "evaluate", *learned, "run", "switching"]


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
    # one hard layout, one seed, two robots: the whole study is measured on the page, not here
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


LEARNED = [c for c in COMMANDS if "adaptation_learned" in c]
"""The learned robot's example: ``train`` then ``evaluate`` per hard layout."""


def test_learned_example_trains_where_its_study_reads_the_model() -> None:
    # the study names the model by a path read from the repository root; the page's
    # train command must write exactly there, or the evaluate command fails to load it
    import tomllib

    pairs = list(zip(LEARNED[::2], LEARNED[1::2], strict=True))
    assert [s for t, e in pairs for s in (shlex.split(t)[1], shlex.split(e)[1])] == ["train", "evaluate"] * 2
    layouts = []
    for train, evaluate in pairs:
        t, e = shlex.split(train), shlex.split(evaluate)
        scenario = t[t.index("--scenario") + 1]
        layouts.append(scenario)
        study = tomllib.loads((ROOT / e[2]).read_text())
        assert study["scenarios"] == [scenario] and study["splits"] == ["held_out"]
        assert f"sb3:path={t[t.index('--out') + 1]}/model.json" in study["robots"]
        assert {"planner", "oracle"} <= set(study["robots"])
        assert t[t.index("--population") + 1] == "populations/hard_layouts.toml"
    assert layouts == ["forced_coordination", "asymmetric_advantages"]


@pytest.mark.slow
def test_learned_example_runs_narrowed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    pytest.importorskip("sb3_contrib")
    # run from an empty folder so the model lands in tmp_path/runs, where the study
    # (read from the repository) looks for it relative to the working directory
    monkeypatch.chdir(tmp_path)
    train, evaluate = (
        shlex.split(c.replace(" populations/", f" {ROOT}/populations/").replace(" studies/", f" {ROOT}/studies/"))[1:]
        for c in LEARNED[:2]
    )
    assert train[train.index("--scenario") + 1] == "forced_coordination"
    # a tiny budget: the run must work end to end, not learn (the page measures that)
    narrow_train = ["--steps", "2048", "--hp", "num_envs=64", "--hp", "eval_envs=4", "--no-tensorboard"]
    code, _, err = run_main([*train, *narrow_train])
    assert code == 0, err
    assert (tmp_path / "runs" / "adaptation_learned" / "forced_coordination" / "model.json").is_file()
    # two held-out members, one seed: a 1800 s run of the sb3 robot is its forward passes (~10 s)
    members = ["h_giver_only", "h_soft_giver"]
    narrow = ["--seeds", "1", "--robots", "sb3", "--humans", ",".join(members), "--workers", "1"]
    code, _, err = run_main([*evaluate, *narrow])
    assert code == 0, err
    out = Path(evaluate[evaluate.index("--out") + 1])
    with (out / "scores.csv").open() as f:
        rows = list(csv.DictReader(f))
    assert {r["robot"] for r in rows} == {"sb3:path=runs/adaptation_learned/forced_coordination/model.json"}
    assert sorted(r["human"] for r in rows) == members
    # both are held-out members the oracle completes with: each run has a BR-Prox
    scored = {r["human"]: float(r["br_prox"]) for r in rows if r["br_prox"]}
    assert sorted(scored) == members, rows
    assert all(0.0 <= v <= 1.0 for v in scored.values()), scored
    # the report's BR-Prox table scores it on the held-out (test) split
    row = "| test | sb3:path=runs/adaptation_learned/forced_coordination/model.json |"
    assert row in (out / "report.md").read_text()


def test_switching_example_runs_narrowed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(ROOT)
    command = next(c for c in COMMANDS if " switching " in c)
    args = shlex.split(command.replace("results/", f"{tmp_path}/"))[1:]
    # the page's robots and pairs, one seed, two periods, a short run
    args[args.index("--periods") + 1] = "20,120"
    code, out, err = run_main([*args, "--seeds", "1", "--duration", "240"])
    assert code == 0, err
    assert "cells where a robot loses to planner" in out
    assert {p.name for p in (tmp_path / "switching-forced").iterdir()} >= {"switching.json", "switching.png"}
