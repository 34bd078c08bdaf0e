"""Values that round 99's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import asyncio
import dataclasses
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.content import registry_targets
from hg_marl.agents.meta.registry import CRITERIA
from hg_marl.core import Agent, Kind, World
from hg_marl.core.errors import ScenarioError
from hg_marl.core.scenario_file import parse_scenario
from hg_marl.core.scenario_model import Bin, Reach, solvability_problems
from hg_marl.training.baselines.evaluation import runner_rate
from hg_marl.training.play.server_limits import ServerLimits, timed_protocol
from tests.play.test_pinned_server_limits_gate import _Loop, _Transport
from tests.training.test_pinned_round54 import _coloured

# --- hg_marl/core/registry.py ---


def test_a_class_entrys_module_is_the_module_that_defines_the_class() -> None:
    # Entry.module: "The module defining the target (read without importing it)". The criteria
    # are registered as classes; the entropy criterion's class is written in
    # agents/meta/entropy.py, installed as hg_marl.agents.meta.entropy (pyproject's package-dir),
    # and registry_targets (the modules a store's code key reads) names that module.
    assert CRITERIA["entropy"].module == "hg_marl.agents.meta.entropy"
    assert registry_targets(CRITERIA, names=["entropy"]) == ("hg_marl.agents.meta.entropy",)


# --- hg_marl/core/scenario_file.py ---


def test_a_name_of_64_characters_loads_and_one_of_65_is_refused() -> None:
    # NAME_PATTERN's docstring: an object, bin or spot name is "a letter then letters, digits,
    # ``_`` or ``-``, at most 64 characters". A 64-character name (c then 63 u's) loads under
    # each kind; 65 characters is refused naming the field.
    name = "c" + "u" * 63
    assert len(name) == 64
    data = _coloured([""])
    data["objects"][0]["name"] = name
    data["bins"][0]["name"] = "b" + name[1:]
    data["spots"][0]["name"] = "m" + name[1:]
    data["layout"][0]["spots"] = ["m" + name[1:]]
    scenario = parse_scenario(data, "long.toml", strict=True)
    assert scenario.objects == (name,)
    assert scenario.bins[0].name == "b" + "u" * 63 and scenario.spots[0].name == "m" + "u" * 63
    data["objects"][0]["name"] = name + "u"
    with pytest.raises(ScenarioError, match=r"field 'objects\[0\]\.name': name '.*' must be .*at most 64 characters"):
        parse_scenario(data, "longer.toml", strict=True)


# --- hg_marl/core/scenario_model.py ---


def test_a_colourless_bin_makes_a_coloured_object_cleanable() -> None:
    # solvability_problems: "An object can be cleaned when someone reaches its spot and someone
    # reaches a bin that accepts its colour", and a colourless bin "accepts objects of any colour"
    # (Bin.colour). paper2015's one bin is colourless and the robot reaches it: the three tapes
    # coloured red, green and blue are all cleanable. Made blue, the bin leaves tape1 (red) and
    # tape2 (green) with no bin, and tape3 (blue) with one.
    paper = World("paper2015").scenario
    coloured = dataclasses.replace(paper, object_colours=("red", "green", "blue"))
    assert coloured.bins[0].colour == "" and coloured.bins[0].reach.robot_from
    assert solvability_problems(coloured) == []
    blue = dataclasses.replace(coloured, bins=(Bin("trashbin", Reach(frozenset({0}), False), "blue"),))
    assert solvability_problems(blue) == [
        "no agent reaches a bin for object 'tape1'",
        "no agent reaches a bin for object 'tape2'",
    ]


# --- training/play/server_limits.py ---


class _TaskLoop(_Loop):
    """The fake loop of the gate tests, also keeping the request's task (run by the test)."""

    def __init__(self) -> None:
        super().__init__()
        self.tasks: list[Any] = []

    def create_task(self, coro: Any) -> Any:
        self.tasks.append(coro)
        return _Task()


class _Task:
    def add_done_callback(self, callback: Any) -> None:
        pass


class _WritableTransport(_Transport):
    def __init__(self) -> None:
        super().__init__()
        self.sent = b""

    def write(self, data: bytes) -> None:
        self.sent += data

    def pause_reading(self) -> None:
        pass

    def resume_reading(self) -> None:
        pass


def test_a_kept_alive_connection_waits_the_idle_timeout_after_a_response() -> None:
    # The module docstring: "a connection with no request under way (just opened, or after a
    # response) is closed after ServerLimits.idle_timeout seconds without a byte". With idle 1 s,
    # headers 2 s and body 3 s, a complete GET answered 200 leaves one deadline, of 1 s (not the
    # header's 2 s), and when it fires the connection is closed.
    from uvicorn.config import Config
    from uvicorn.server import ServerState

    async def app(scope: Any, receive: Any, send: Any) -> None:
        await send({"type": "http.response.start", "status": 200, "headers": [(b"content-length", b"2")]})
        await send({"type": "http.response.body", "body": b"ok"})

    limits = ServerLimits(idle_timeout=1.0, header_timeout=2.0, body_timeout=3.0)
    loop, transport = _TaskLoop(), _WritableTransport()
    protocol = timed_protocol(limits)(Config(app=app), ServerState(), {}, _loop=loop)
    protocol.connection_made(transport)
    protocol.data_received(b"GET / HTTP/1.1\r\nHost: x\r\n\r\n")
    (task,) = loop.tasks
    asyncio.run(task)
    assert transport.sent.startswith(b"HTTP/1.1 200") and transport.sent.endswith(b"ok")
    assert loop.live() == [(1.0, ())]
    (timer,) = [t for t in loop.timers if not t.cancelled]
    timer.callback(*timer.args)
    assert transport.closed


# --- training/baselines/evaluation.py ---


class _SeenModel:
    """A stand-in model with SB3's ``predict`` signature that keeps what it was shown and waits."""

    policy = object()

    def __init__(self, wait: int) -> None:
        self.wait = wait
        self.seen: list[Any] = []

    def predict(self, obs: Any, deterministic: bool = True, action_masks: Any = None) -> tuple[int, None]:
        self.seen.append(obs)
        return self.wait, None


def test_runner_rate_shows_the_model_its_own_observation_mode() -> None:
    # runner_rate's ``observation`` is the model's observation mode: with "flat" the model sees
    # the facts then the action mask (paper2015: n_facts + the robot's action count entries),
    # with "dict" a mapping of the two. A robot that always waits solves nothing (rate 0): only the
    # robot reaches paper2015's bin.
    world = World("paper2015")
    n_facts, n_actions = world.n_facts, world.n_actions(Agent.ROBOT)
    wait = next(i for i, action in enumerate(world.actions(Agent.ROBOT)) if action.kind is Kind.WAIT)
    flat = _SeenModel(wait)
    assert runner_rate(flat, "flat", "cooperative", "paper2015", duration=60.0) == 0.0
    assert flat.seen and all(np.shape(obs) == (n_facts + n_actions,) for obs in flat.seen)
    as_dict = _SeenModel(wait)
    runner_rate(as_dict, "dict", "cooperative", "paper2015", duration=60.0)
    assert as_dict.seen and all(set(obs) == {"observation", "action_mask"} for obs in as_dict.seen)
