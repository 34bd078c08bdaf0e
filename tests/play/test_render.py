"""Pictures of the table: the page's SVG, the labelled rgb_array image, GIF/MP4 videos."""

from __future__ import annotations

import importlib.util
import xml.etree.ElementTree as ET
from pathlib import Path

import imageio.v3 as iio
import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

import hg_marl
from hg_marl.core import State
from hg_marl.envs.render import layout, render_rgb
from hg_marl.training.cli import app, main
from hg_marl.training.play.session import PlaySession
from hg_marl.training.play.svg import table_svg
from tests.play.reference import expected_drawing, person_choice

SVG = "{http://www.w3.org/2000/svg}"


def read_svg(svg: str) -> dict[str, object]:
    root = ET.fromstring(svg)
    groups = list(root.iter(f"{SVG}g"))
    robot = next(g for g in groups if g.get("id") == "robot")
    offer = [g for g in groups if g.get("id") == "offer"]
    return {
        "robot": robot.get("data-at"),
        "objects": {g.get("data-name"): g.get("data-place") for g in groups if g.get("class") == "object"},
        "offer": (offer[0].get("data-object"), offer[0].get("data-by")) if offer else None,
    }


@pytest.mark.parametrize(
    "state",
    [
        State((0, 1, 5), 1),  # the initial kind of table
        State((7, 6, 8), 3, offer_by=0, offer_obj=0),  # robot holds and offers tape1; tape2 binned
        State((8, 3, 6), 0, offer_by=1, offer_obj=0),  # the human offers tape1
    ],
)
def test_svg_draws_the_state(paper, state: State) -> None:
    assert read_svg(table_svg(paper, state)) == expected_drawing(paper, state)


def test_labelled_image_has_the_layout_size_and_a_caption(paper) -> None:
    state = State((0, 1, 5), 1)
    lay = layout(paper)
    plain, captioned = render_rgb(paper, state), render_rgb(paper, state, "t=1.0s robot: wait")
    assert plain.shape == captioned.shape == (lay.height, lay.width, 3) and plain.dtype == np.uint8
    band = slice(lay.caption_y, lay.height)
    assert (plain[band] == 250).all() and (captioned[band] != 250).any()
    # an object's label is drawn: the spot of tape1 differs from the same spot with tape1 elsewhere
    assert not np.array_equal(render_rgb(paper, State((1, 1, 5), 1)), plain)


def test_render_mode_human_points_at_video_and_play() -> None:
    with pytest.raises(ValueError, match=r"--video out\.gif.*hg-marl play"):
        hg_marl.env(render_mode="human")


def test_run_video_gif_has_one_frame_per_cycle(tmp_path: Path) -> None:
    gif, log = tmp_path / "run.gif", tmp_path / "log.csv"
    args = ["run", "--robot", "planner", "--duration", "20", "--video", str(gif), "--out", str(log)]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    frames = iio.imread(gif, index=None)
    decisions = len(pd.read_csv(log))
    lay = layout(hg_marl.env().unwrapped.world)
    assert frames.shape[0] == decisions > 5
    assert frames.shape[1:3] == (lay.height, lay.width)


def test_replay_video_and_rewards(tmp_path: Path) -> None:
    session = PlaySession("planner", seed=0, record=tmp_path)
    while session.tasks_solved < 1:
        session.play(person_choice([c.name for c in session.choices()]))
    trace = session.close()
    gif = tmp_path / "replay.gif"
    result = CliRunner().invoke(app, ["replay", str(trace), "--video", str(gif)])
    assert result.exit_code == 0, result.output
    assert "1 tasks, rewards 1" in result.output and "same as the recording" in result.output
    # one frame per robot turn: one per recorded move, plus the robot's turn after the last one
    assert iio.imread(gif, index=None).shape[0] == len(session.response_times) + 1


def main_exit(args: list[str], monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> tuple[int, str]:
    """Run the real entry point (which turns bad input into one line and exit 2)."""
    monkeypatch.setattr("sys.argv", ["hg-marl", *args])
    with pytest.raises(SystemExit) as stop:
        main()
    return int(stop.value.code or 0), capsys.readouterr().err


def test_bad_video_names_are_one_line_errors(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    code, err = main_exit(["run", "--duration", "5", "--video", str(tmp_path / "x.avi")], monkeypatch, capsys)
    assert code == 2 and "expected a .gif or .mp4" in err and len(err.strip().splitlines()) == 1
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda n, *a: None if n == "imageio_ffmpeg" else real(n, *a))
    code, err = main_exit(["run", "--duration", "5", "--video", str(tmp_path / "x.mp4")], monkeypatch, capsys)
    assert code == 2 and "hg-marl[video]" in err
    code, err = main_exit(["replay", str(tmp_path / "none.jsonl")], monkeypatch, capsys)
    assert code == 2 and "trace file not found" in err


@pytest.mark.skipif(importlib.util.find_spec("imageio_ffmpeg") is None, reason="needs the video extra")
def test_run_video_mp4(tmp_path: Path) -> None:
    mp4 = tmp_path / "run.mp4"
    result = CliRunner().invoke(app, ["run", "--robot", "planner", "--duration", "10", "--video", str(mp4)])
    assert result.exit_code == 0, result.output
    assert iio.improps(mp4, plugin="pyav" if importlib.util.find_spec("av") else "FFMPEG").shape[0] > 3


def test_robot_locations_stand_beside_what_they_reach() -> None:
    world = hg_marl.env(scenario="paper2015").unwrapped.world
    lay = layout(world)
    sc = world.scenario
    x = dict(zip(sc.robot_locations, (p[0] for p in lay.locations), strict=True))
    # paper2015: table_left reaches mat_left/mat_centre, table_right mat_centre/mat_right,
    # human_side mat_shared, bin_side the trashbin (drawn last): so this order, left to right
    assert sorted(x, key=x.__getitem__) == ["table_left", "table_right", "human_side", "bin_side"]
    items, boxes = (*sc.spots, *sc.bins), lay.spots + lay.bins
    for k, name in enumerate(sc.robot_locations):
        nearest = min(abs(b.centre[0] - x[name]) for b in boxes)
        closest = [i for i, b in zip(items, boxes, strict=True) if abs(b.centre[0] - x[name]) == nearest]
        assert all(k in item.reach.robot_from for item in closest), (name, [i.name for i in closest])
