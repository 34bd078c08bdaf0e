"""Studies: files validated with path:line, scores against the oracle, resumable after a kill."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pandas as pd
import pytest
from typer.testing import CliRunner

from hg_marl.core.errors import StudyError
from hg_marl.training.cli import app
from hg_marl.training.evaluate import SCORE_COLUMNS, evaluate
from hg_marl.training.study import load_study

TINY = Path(__file__).parent / "data" / "tiny.toml"


def _study(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "study.toml"
    path.write_text(text)
    return path


GOOD = """name = "t"
seeds = 2
duration = 60.0
robots = ["planner"]
humans = ["cooperative"]
"""


@pytest.mark.parametrize(
    ("text", "line", "field"),
    [
        (GOOD.replace("duration = 60.0", "duration = nan"), 3, "duration"),
        (GOOD.replace("seeds = 2", "seeds = 1.5"), 2, "seeds"),
        (GOOD.replace('robots = ["planner"]', 'robots = ["planner", "hybrid:criterion=nope"]'), 4, "robots[1]"),
        (GOOD.replace('humans = ["cooperative"]', 'humans = [\n"cooperative",\n"lazy:p_idel=0.5",\n]'), 7, "humans[1]"),
        (GOOD + "colour = 3\n", 6, "colour"),
        (GOOD + 'scenarios = ["missing.toml"]\n', 6, "scenarios[0]"),
        (GOOD + '[[train]]\nname = "lazy"\nparams = { p_idle = 2.0 }\n', 6, "train[0]"),
    ],
)
def test_bad_study_field_names_path_line_and_field(tmp_path: Path, text: str, line: int, field: str) -> None:
    path = _study(tmp_path, text)
    with pytest.raises(StudyError) as err:
        load_study(path)
    message = str(err.value)
    assert message.startswith(f"{path}:{line}: "), message
    assert field in message and "\n" not in message


def test_cli_bad_study_exits_2_with_one_line(tmp_path: Path) -> None:
    path = _study(tmp_path, GOOD.replace("duration = 60.0", "duration = -1.0"))
    result = subprocess.run(
        [sys.executable, "-m", "hg_marl.training.cli", "evaluate", str(path), "--out", str(tmp_path / "o")],
        capture_output=True,
        text=True,
    )
    assert result.returncode == 2
    assert result.stderr.strip().count("\n") == 0 and f"{path}:3" in result.stderr


def test_narrowing_picks_seeds_robots_humans() -> None:
    study = load_study(TINY).narrowed(seeds=2, robots=["random"], humans=["lazy"])
    assert study.seeds == (0, 1)
    assert [r.label for r in study.robots] == ["random"]
    assert [h.label for h in study.humans] == ["lazy:p_idle=0.5"]
    with pytest.raises(StudyError, match="--robots"):
        load_study(TINY).narrowed(robots=["nobody"])


def test_narrowing_picks_scenarios_by_name_or_file_stem(tmp_path: Path) -> None:
    layout = tmp_path / "my_layout.toml"
    layout.write_text((Path(__file__).parents[2] / "hg_marl/core/scenarios/forced_coordination.toml").read_text())
    study = load_study(_study(tmp_path, GOOD + 'scenarios = ["paper2015", "my_layout.toml"]\n'))
    assert study.narrowed(scenarios=["paper2015"]).scenarios == ("paper2015",)
    assert study.narrowed(scenarios=["my_layout"]).scenarios == (str(layout.resolve()),)
    assert study.narrowed().scenarios == study.scenarios
    with pytest.raises(StudyError, match="--scenarios: roboergosum not in"):
        study.narrowed(scenarios=["roboergosum"])


def test_scores_are_rate_over_oracle_rate(tmp_path: Path) -> None:
    agg = evaluate(load_study(TINY).narrowed(seeds=2), tmp_path)
    frame = pd.read_csv(tmp_path / "scores.csv")
    assert tuple(frame.columns) == SCORE_COLUMNS
    assert len(frame) == 2 * 2 * 2
    # rate is tasks per simulated hour of the 90 s runs; score divides by the oracle's rate
    assert (frame["rate"] - frame["tasks"] * 3600 / 90.0).abs().max() < 1e-9
    assert (frame["score"] - frame["rate"] / frame["oracle_rate"]).abs().max() < 1e-9
    assert set(frame["reference"]) == {"oracle"}
    for key in frame["key"]:
        assert (tmp_path / "store" / "runs" / key[:2] / key / "result.json").is_file()
    assert set(agg["robots"]) == {"planner", "random"}
    on_disk = json.loads((tmp_path / "aggregate.json").read_text())
    assert on_disk["robots"]["planner"]["iqm"] == agg["robots"]["planner"]["iqm"]
    assert set(on_disk["improvement"]) == {"planner>random"}
    for name in ("crossplay.png", "profiles.png", "intervals.png"):
        assert (tmp_path / name).read_bytes()[:4] == b"\x89PNG"
    assert "| planner |" in (tmp_path / "report.md").read_text()


def test_non_stationary_human_falls_back_to_best_robot_and_says_so(tmp_path: Path) -> None:
    path = _study(
        tmp_path,
        GOOD.replace('robots = ["planner"]', 'robots = ["planner", "random"]').replace(
            'humans = ["cooperative"]', 'humans = ["switching:humans=cooperative|lazy,at=[30.0]"]'
        ),
    )
    evaluate(load_study(path), tmp_path / "out")
    frame = pd.read_csv(tmp_path / "out" / "scores.csv")
    planner = frame[frame["robot"] == "planner"]
    assert set(frame["reference"]) == {"best robot (planner)"}
    assert frame["oracle_rate"].iloc[0] == pytest.approx(planner["rate"].mean())
    assert "best robot (planner)" in (tmp_path / "out" / "report.md").read_text()


def _evaluate_cmd(out: Path, workers: int) -> list[str]:
    cli = [sys.executable, "-m", "hg_marl.training.cli", "evaluate", str(TINY)]
    return [*cli, "--out", str(out), "--workers", str(workers)]


@pytest.mark.slow
def test_killed_study_resumes_to_identical_scores(tmp_path: Path) -> None:
    whole, killed = tmp_path / "whole", tmp_path / "killed"
    subprocess.run(_evaluate_cmd(whole, 1), check=True, capture_output=True)
    proc = subprocess.Popen(
        _evaluate_cmd(killed, 2), start_new_session=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )
    deadline = time.monotonic() + 600
    while len(list((killed / "store" / "runs").glob("*/*/result.json"))) < 3:
        assert proc.poll() is None, "the study ended before it could be killed"
        assert time.monotonic() < deadline
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    assert not (killed / "scores.csv").exists()
    rerun = subprocess.run(_evaluate_cmd(killed, 2), check=True, capture_output=True, text=True)
    assert (killed / "scores.csv").read_text() == (whole / "scores.csv").read_text()
    assert "reused" in (killed / "report.md").read_text()
    assert rerun.returncode == 0


@pytest.mark.slow
def test_pool_workers_die_with_a_killed_driver(tmp_path: Path) -> None:
    proc = subprocess.Popen(
        _evaluate_cmd(tmp_path, 2), start_new_session=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )
    deadline = time.monotonic() + 600
    while not list((tmp_path / "store" / "runs").glob("*/*/result.json")):
        assert proc.poll() is None and time.monotonic() < deadline
        time.sleep(0.05)
    os.kill(proc.pid, signal.SIGKILL)  # the driver only, not its group
    proc.wait()
    deadline = time.monotonic() + 600
    while True:
        try:
            os.killpg(proc.pid, 0)  # anyone left in the study's process group?
        except ProcessLookupError:
            break
        assert time.monotonic() < deadline, "pool workers outlived the driver"
        time.sleep(0.1)


def test_cli_evaluate_runs_and_reports(tmp_path: Path) -> None:
    result = CliRunner().invoke(app, ["evaluate", str(TINY), "--out", str(tmp_path), "--seeds", "1", "--workers", "1"])
    assert result.exit_code == 0, result.output
    assert "planner" in result.output and (tmp_path / "report.md").is_file()


@pytest.mark.parametrize("name", ["crossplay", "heldout"])
def test_bundled_studies_are_valid(name: str) -> None:
    study = load_study(Path(__file__).parents[2] / "studies" / f"{name}.toml")
    assert study.robots and study.humans and len(study.seeds) >= 5
    if name == "heldout":
        assert study.train and study.test and not set(study.train) & set(study.test)


def test_readme_quick_look_command_runs(tmp_path: Path) -> None:
    # The quick look of docs/studies.md: the bundled cross-play study narrowed to one seed, robot and human.
    study = Path(__file__).parents[2] / "studies" / "crossplay.toml"
    args = ["evaluate", str(study), "--out", str(tmp_path), "--seeds", "1", "--robots", "planner,habit"]
    result = CliRunner().invoke(app, [*args, "--humans", "lazy", "--workers", "1"])
    assert result.exit_code == 0, result.output
    frame = pd.read_csv(tmp_path / "scores.csv")
    assert list(frame["robot"]) == ["planner", "habit"] and set(frame["human"]) == {"lazy"}


def test_one_seed_study_flags_its_intervals_and_says_what_it_ran(tmp_path: Path) -> None:
    from tests.cli_helpers import run_main

    args = ["evaluate", str(TINY), "--out", str(tmp_path), "--seeds", "1", "--workers", "1"]
    code, out, err = run_main(args)
    assert code == 0, err
    # 2 robots x 2 humans x 1 seed, all new; then all reused
    assert f"store {tmp_path / 'store'}: 4 runs made, 0 reused" in err
    assert "oracle paper2015: states" in err  # the oracle's solves show their bar (cached for the rerun)
    assert "caution: 1 seed per task: no confidence interval" in out
    assert "| planner | " in out and "| - |" in out  # the CI columns are empty, not zero-width
    report = (tmp_path / "report.md").read_text()
    assert "**Caution: 1 seed per task" in report and "no pair can be called clearly better" in report
    code, out, err = run_main(args)
    assert code == 0 and f"store {tmp_path / 'store'}: 0 runs made, 4 reused" in err
    assert "oracle paper2015: states" not in err
    assert "of which aggregation" in out


@pytest.mark.parametrize("progress", [True, False])
def test_the_headrooms_model_shows_its_progress_when_asked(
    progress: bool, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The headroom's joint model takes minutes on a large table: ``evaluate(progress=True)``
    (the CLI's) shows its bars on stderr, as it does each oracle's; without it, nothing."""
    evaluate(load_study(TINY).narrowed(seeds=1), tmp_path, progress=progress)
    assert ("headroom: policies" in capsys.readouterr().err) is progress


def test_the_headrooms_cache_key_covers_the_models_and_every_partners_code(monkeypatch: pytest.MonkeyPatch) -> None:
    """A changed model builder, solver or partner module must compute the headroom again: the
    key's code is the digest of every project module the headroom and the humans reach."""
    from hg_marl.agents import content
    from hg_marl.training.evaluate import headroom_of

    asked: list[dict] = []

    class Keys:
        def cached(self, kind: str, fields: dict, compute: object) -> float:
            asked.append(fields)
            return 0.5  # nothing is computed: only the key is looked at

    roots: list[tuple[str, ...]] = []
    real = content.code_digest

    def recording(given: tuple[str, ...]) -> str:
        roots.append(tuple(given))
        return real(given)

    monkeypatch.setattr(content, "code_digest", recording)
    assert headroom_of(Keys(), load_study(TINY), "paper2015") == 0.5  # type: ignore[arg-type]
    (used,) = roots
    assert asked[0]["code"] == real(used)
    reached = content.code_modules(used)[0]
    for module in (
        "hg_marl.agents.headroom",
        "hg_marl.agents.oracle",
        "hg_marl.agents.models.builder",
        "hg_marl.agents.models.chains",
        "hg_marl.agents.humans.cooperative",
        "hg_marl.agents.humans.lazy",
        "hg_marl.core.batch",
    ):
        assert module in reached, module
