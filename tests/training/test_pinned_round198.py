"""Values that round 198's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import pytest

from hg_marl.agents.humans.registry import HUMANS
from hg_marl.agents.humans.switching import SwitchingHuman
from hg_marl.core.errors import ConfigError
from hg_marl.training.limits import check_runs
from hg_marl.training.play.server_limits import ServerLimits


def test_a_mismatched_schedules_message_counts_the_humans_given() -> None:
    # two humans need one threshold; none given: the message names the 2 humans listed and the
    # empty schedule (counted from the arguments, not worked back from the thresholds)
    with pytest.raises(ValueError, match=r"got 2 humans and at=\[\]"):
        SwitchingHuman(humans=["lazy", "cooperative"], at=[])
    # three humans, three thresholds: 3 humans listed
    with pytest.raises(ValueError, match=r"got 3 humans and at=\[1\.0, 2\.0, 3\.0\]"):
        SwitchingHuman(humans=["lazy", "cooperative", "lazy"], at=[1.0, 2.0, 3.0])


def test_too_many_runs_is_a_config_error_by_default() -> None:
    # docs/inputs.md: at most 200,000 runs per study; one more is refused, by default as the
    # configuration's error (what the command line reports as a bad option), naming the count
    with pytest.raises(ConfigError, match=r"^sweep: 200,001 runs, over the limit of 200,000 runs$"):
        check_runs(200_001, "sweep")
    assert check_runs(200_000, "sweep") == 200_000


def test_a_registry_is_a_mapping_an_unknown_name_is_simply_not_in() -> None:
    # the Mapping protocol: ``in`` and ``get`` answer False and None for a name not registered,
    # and indexing raises KeyError (``lookup`` is the call that raises the registry's own error)
    assert "lazy" in HUMANS
    assert "nobody" not in HUMANS
    assert HUMANS.get("nobody") is None
    with pytest.raises(KeyError):
        HUMANS["nobody"]


def test_server_timeouts_are_accepted_up_to_an_hour() -> None:
    # the ceiling of every timeout is 3600 s: ten minutes and the full hour are accepted,
    # half a second more is refused
    limits = ServerLimits(idle_timeout=600.0, header_timeout=3600.0, body_timeout=3600.0)
    assert (limits.idle_timeout, limits.header_timeout, limits.body_timeout) == (600.0, 3600.0, 3600.0)
    with pytest.raises(ConfigError):
        ServerLimits(body_timeout=3600.5)
