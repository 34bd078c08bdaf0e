"""The web front end in a real headless Chromium (Debian's ``chromium``, driven by Playwright).

Run by ``make test-browser`` (its CI stage installs chromium and the extras). Elsewhere
the tests skip with the reason; with ``HG_MARL_BROWSER_REQUIRED=1`` (the CI stage) a
missing browser fails instead of skipping. Screenshots go to ``artifacts/``.
"""

from __future__ import annotations

import importlib.util
import os
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from hg_marl.training.play.replay import replay_run
from hg_marl.training.play.session import PlaySession
from tests.play.reference import expected_drawing, person_choice

pytestmark = pytest.mark.browser

CHROMIUM = "/usr/bin/chromium"
ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--no-first-run",
    "--disable-sync",
]
ARTIFACTS = Path(__file__).resolve().parents[2] / "artifacts"


def _unavailable(reason: str) -> None:
    if os.environ.get("HG_MARL_BROWSER_REQUIRED") == "1":
        pytest.fail(f"browser stage: {reason}")
    pytest.skip(f"{reason}; run `make test-browser` (installs chromium and the play/browser-test extras)")


@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    for module in ("playwright", "starlette", "uvicorn"):
        if importlib.util.find_spec(module) is None:
            _unavailable(f"the Python package {module} is not installed")
    if not os.access(CHROMIUM, os.X_OK):
        _unavailable(f"no browser at {CHROMIUM} (apt-get install -y chromium)")
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=ARGS, headless=True)
        yield b
        b.close()


@pytest.fixture
def game(tmp_path: Path) -> Iterator[Any]:
    """A factory: serve a session and return (session, page)."""
    from hg_marl.training.play.web import Server

    servers: list[Server] = []

    def start(
        browser: Any, robot: str = "planner", seed: int = 0, scenario: str = "paper2015"
    ) -> tuple[PlaySession, Any]:
        session = PlaySession(robot, scenario=scenario, seed=seed, record=tmp_path, player="browser-test")
        server = Server(session, 0)
        server.start_in_thread()
        servers.append(server)
        page = browser.new_page(viewport={"width": 1000, "height": 820})
        page.goto(server.url)
        return session, page

    yield start
    for server in servers:
        server.stop()


def drawn(page: Any) -> dict[str, object]:
    """What the page draws, read back from the SVG's data attributes."""
    objects = page.eval_on_selector_all("#table g.object", "els => els.map(e => [e.dataset.name, e.dataset.place])")
    offer = page.query_selector("#offer")
    return {
        "robot": page.get_attribute("#robot", "data-at"),
        "objects": dict(objects),
        "offer": None if offer is None else (offer.get_attribute("data-object"), offer.get_attribute("data-by")),
    }


def buttons(page: Any) -> dict[str, tuple[str, int]]:
    """Feasible actions on the page: name -> (shortcut, index)."""
    rows = page.eval_on_selector_all(
        "#actions button",
        "els => els.map(e => [e.textContent.slice(e.dataset.key.length), e.dataset.key, e.dataset.action])",
    )
    return {name: (key, int(index)) for name, key, index in rows}


def play_one_task(page: Any, session: PlaySession, by: str, shots: str | None = None) -> tuple[list[str], int]:
    """Play as a person until a task is solved, checking the drawing after every move."""
    moves: list[str] = []
    handover_shot = False
    for n in range(60):
        assert drawn(page) == expected_drawing(session.world, session.state)
        assert int(page.get_attribute("#status", "data-tasks")) == session.tasks_solved
        assert float(page.get_attribute("#status", "data-clock")) == pytest.approx(session.clock, abs=1e-3)
        feasible = buttons(page)
        assert set(feasible) == {c.name for c in session.choices()}
        if session.tasks_solved >= 1:
            return moves, n
        name = person_choice(list(feasible))
        if shots and name.startswith("give(") and not handover_shot:
            page.screenshot(path=str(ARTIFACTS / f"{shots}-before-handover.png"), full_page=True)
        key, index = feasible[name]
        if by == "click":
            page.click(f'#actions button[data-action="{index}"]')
        else:
            page.keyboard.press(key)
        page.wait_for_selector(f'#status[data-moves="{n + 1}"]')
        moves.append(name)
        why = page.text_content("#why")
        assert why.startswith(f"{session.last_robot.name}, proposed by the planner.")
        assert "weight amplitude" not in why, "a planner has no habit: no habit numbers"
        expects = session.last_robot.expects
        assert (f"Its plan expects you to {expects} next." in why) == bool(expects)
        pending = page.text_content("#pending")
        offer = session.state.offer_by == 0
        assert "Your turn." in pending and ("The robot is offering you" in pending) == offer
        handed = bool(moves) and moves[-1].startswith("give(") and session.last_robot.name == "take" + moves[-1][4:]
        assert pending.startswith("Handover done: you gave") == handed
        if shots and name.startswith("give(") and not handover_shot:
            page.screenshot(path=str(ARTIFACTS / f"{shots}-after-handover.png"), full_page=True)
            handover_shot = True
    raise AssertionError(f"no task solved in 60 moves: {moves}")


@pytest.mark.parametrize("by", ["click", "keyboard"])
def test_play_a_whole_task_and_replay_it(browser: Any, game: Any, by: str) -> None:
    ARTIFACTS.mkdir(exist_ok=True)
    session, page = game(browser)
    assert page.title() == "hg-marl: play the human"
    intro = page.text_content("#intro")
    assert "every object into the bin." in intro and "colour" not in intro  # paper2015: one bin, any object
    # the robot's locations stand under what they reach: bin_side under the trashbin
    loc = page.eval_on_selector_all(
        "#table g.location circle, #table g.bin rect",
        "els => els.map(e => [e.parentElement.dataset.name, e.getBBox().x + e.getBBox().width / 2])",
    )
    x = dict(loc)
    assert abs(x["bin_side"] - x["trashbin"]) < abs(x["table_left"] - x["trashbin"])
    page.screenshot(path=str(ARTIFACTS / f"play-{by}-start.png"), full_page=True)
    moves, n = play_one_task(page, session, by, shots=f"play-{by}")
    assert session.tasks_solved == 1 and len(moves) == n
    assert "give(tape3)" in moves, "paper2015's human tape only reaches the bin through the robot"
    assert page.text_content("#robot-expert") == "planner"
    assert page.text_content("#solved").startswith("Task solved! That makes 1 task at t = ")
    page.screenshot(path=str(ARTIFACTS / f"play-{by}-solved.png"), full_page=True)
    page.click("#quit")
    page.wait_for_selector("#done")
    summary = page.text_content("#summary")
    assert f"played {len(moves)} moves with the robot planner on paper2015 (seed 0): 1 task solved" in summary
    numbers = dict(page.eval_on_selector_all("#numbers tr", "rs => rs.map(r => [...r.cells].map(c => c.textContent))"))
    assert numbers["tasks solved"] == "1" and numbers["your moves"] == str(len(moves))
    assert numbers["handovers: you gave"] == str(moves.count("give(tape3)"))
    page.screenshot(path=str(ARTIFACTS / f"play-{by}-finish.png"), full_page=True)
    trace = session.trace_path
    assert trace is not None and trace.exists()
    replay = replay_run(trace)
    assert float(replay.log["reward"].sum()) == session.rewards == 1.0
    assert list(replay.log["human_action_name"][: len(moves)]) == moves


def test_infeasible_request_is_refused_and_hybrid_shows_its_weights(browser: Any, game: Any) -> None:
    # min_visits 0: the criterion weighs the experts from the first decision (by default an
    # unvisited state goes to the planner before any weights are computed: "habit_untrained").
    session, page = game(browser, robot='hybrid:criterion=entropy_and_cost,criterion_params={"min_visits":0}')
    assert page.text_content("#robot-expert") in ("planner", "habit")
    weights = page.eval_on_selector_all("#weights td:first-child", "els => els.map(e => e.textContent)")
    assert "h_habit" in weights and "h_planner" in weights
    r = session.last_robot
    assert r is not None
    why = page.text_content("#why")
    # the criterion's numbers in words: the uncertainties as percentages, the higher value wins
    assert f"habit {100 * r.weights['h_habit']:.0f}%, planner {100 * r.weights['h_planner']:.0f}%" in why
    winner = "planner" if r.weights["value_planner"] > r.weights["value_habit"] else "habit"
    assert f"higher wins: {winner}" in why and r.expert == winner
    page.screenshot(path=str(ARTIFACTS / "play-hybrid.png"), full_page=True)
    status = page.evaluate(
        """async () => (await fetch('/act', {method: 'POST', body: JSON.stringify({action: 0}), headers: {
             'content-type': 'application/json',
             'x-play-token': document.querySelector('meta[name="play-token"]').content}})).status"""
    )
    feasible = {c.index for c in session.choices()}
    assert (status == 409) == (0 not in feasible)
    assert len(session.response_times) == (0 if 0 not in feasible else 1)


def test_another_origin_cannot_play_or_quit(browser: Any, game: Any) -> None:
    """What a hostile page can make the browser send: simple (no-preflight) requests."""
    session, page = game(browser)
    url = page.url.split("?")[0]
    other = browser.new_page()
    other.goto("about:blank")
    for path, body in (("act", '{"action": 0}'), ("act", '{"action": 17}'), ("quit", "{}")):
        other.evaluate(
            "async ([u, b]) => { try { await fetch(u, {method: 'POST', mode: 'no-cors', body: b,"
            " headers: {'content-type': 'text/plain'}}); } catch (e) {} }",
            [url + path, body],
        )
    # a form post navigates a frame with the cookie-less, token-less request
    other.set_content(
        f'<form method="post" action="{url}act" enctype="text/plain"><input name=\'{{"action":0,"x":"\' value=\'"}}\'>'
        "</form><script>document.forms[0].submit()</script>"
    )
    other.wait_for_load_state()
    assert "403" in other.content() or "refused" in other.content()
    assert session.response_times == [] and not session.closed
    assert page.evaluate("async () => (await fetch('/board')).status") == 200  # the own page still works


def test_a_robot_offer_is_shown_and_taken_on_a_coloured_scenario(browser: Any, game: Any) -> None:
    ARTIFACTS.mkdir(exist_ok=True)
    session, page = game(browser, scenario="roboergosum")
    intro = page.text_content("#intro")
    # roboergosum.toml: two bins by colour, green_bin from ROBOT_LOC, blue_bin from SECOND_LOC and the human
    assert "every object into a bin of its colour" in intro
    assert "green_bin (takes green objects; reached by the robot from ROBOT_LOC)" in intro
    rims = page.eval_on_selector_all("#table g.bin", "gs => gs.map(g => [g.dataset.name, g.dataset.colour])")
    assert dict(rims) == {"green_bin": "green", "blue_bin": "blue"}
    for n in range(20):
        if session.state.offer_by == 0:
            break
        name = "wait"
        page.keyboard.press(buttons(page)[name][0])
        page.wait_for_selector(f'#status[data-moves="{n + 1}"]')
    assert session.state.offer_by == 0, "the planner hands a blue object over within 20 moves"
    obj = session.world.scenario.objects[session.state.offer_obj]
    assert drawn(page)["offer"] == (obj, "robot")
    offer_text = f"Your turn. The robot is offering you {obj}: take({obj}) now, or the offer lapses."
    assert page.text_content("#pending") == offer_text
    assert f"take({obj})" in buttons(page)
    page.screenshot(path=str(ARTIFACTS / "play-robot-offers.png"), full_page=True)
    moves = len(session.response_times)
    page.keyboard.press(buttons(page)[f"take({obj})"][0])
    page.wait_for_selector(f'#status[data-moves="{moves + 1}"]')
    assert page.get_attribute("#holding", "data-human") == obj  # taken: now in your hand
    page.click("#quit")
    page.wait_for_selector("#done")
    numbers = dict(page.eval_on_selector_all("#numbers tr", "rs => rs.map(r => [...r.cells].map(c => c.textContent))"))
    assert (numbers["handovers: robot gave"], numbers["handovers: you took"]) == ("1", "1")
