"""Values that round 236's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.trace import TraceRecorder, read_trace
from hg_marl.core import Agent, World
from hg_marl.core.spec import Spec, parse_spec


def test_a_spec_with_only_blanks_after_its_colon_has_no_parameters() -> None:
    # "name:" followed by blanks sets no parameter (the parameter part is empty once stripped, as
    # the parser strips the name and each key and value): the name alone, an empty table, the same
    # spec as the bare name and as "name:" with nothing after the colon.
    for text in ("lazy: ", "lazy:   ", "lazy:\t"):
        assert parse_spec(text) == Spec("lazy", {})
        assert parse_spec(text) == parse_spec("lazy") == parse_spec("lazy:")


def test_a_trace_recorders_headers_note_the_seed_it_was_given(tmp_path: Path) -> None:
    # TraceRecorder(seed=s) notes s in each episode's header ("the environment seed to note in each
    # header"); two resets write two episodes, both headed seed 11, numbered 0 and 1.
    path = tmp_path / "t.jsonl"
    recorder = TraceRecorder(make_human("cooperative"), path, seed=11)
    world = World("paper2015")
    recorder.reset(world, Agent.HUMAN, np.random.default_rng(0))
    recorder.reset(world, Agent.HUMAN, np.random.default_rng(1))
    recorder.close()
    episodes = read_trace(path)
    assert [e.header["seed"] for e in episodes] == [11, 11]
    assert [e.header["episode"] for e in episodes] == [0, 1]
