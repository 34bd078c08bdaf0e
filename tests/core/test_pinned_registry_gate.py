"""A malformed spec is the registry's own error, naming the kind and what is wrong.

The spec parser raises ``SpecError``; a registry re-raises it as its area's error type
(``ConfigError`` here), so a command catches one type per area. Messages are the parser's
words, stated here by hand.
"""

from __future__ import annotations

import pytest

from hg_marl.core.errors import ConfigError, SpecError
from hg_marl.core.registry import Registry


class Toy:
    name = "toy"

    def __init__(self, speed: float = 1.5) -> None:
        self.speed = speed


TOYS = Registry("toy", ConfigError, [Toy])


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("toy:speed", "toy 'toy:speed': expected key=value, got 'speed'"),
        (":speed=1", "toy ':speed=1': missing the name before ':'"),
        ("toy:speed=1,speed=2", "toy 'toy:speed=1,speed=2': parameter 'speed' given twice"),
    ],
)
def test_a_malformed_spec_is_the_registrys_error(text: str, message: str) -> None:
    assert not issubclass(ConfigError, SpecError)
    with pytest.raises(ConfigError) as info:
        TOYS.make(text)
    assert str(info.value) == message
    assert TOYS.make("toy:speed=2").speed == 2.0


class Learner:
    """A Python object a spec cannot write."""


class Trained:
    name = "trained"

    def __init__(self, speed: float = 1.5, learner: Learner | None = None) -> None:
        self.speed, self.learner = speed, learner


def test_a_python_only_parameter_is_not_listed_among_those_a_spec_can_set() -> None:
    # ``learner`` takes a Python object (its default None, annotated with a project class):
    # a spec cannot set it, so the listing leaves it out; ``speed`` is listed with its default
    entry = Registry("toy", ConfigError, [Trained])["trained"]
    assert list(entry.params) == ["speed"]
    assert entry.params["speed"].default == 1.5


def test_a_constructors_own_error_passes_through_unwrapped() -> None:
    # the learned human's own HumanError and ModelFileError keep their type and their words:
    # the registry does not prefix them with the spec a second time
    from hg_marl.agents.humans import make_human
    from hg_marl.core.errors import HumanError, ModelFileError

    with pytest.raises(HumanError) as info:
        make_human("learned")
    assert str(info.value) == "human 'learned' needs a policy: learned:path=FOLDER"
    with pytest.raises(ModelFileError) as missing:
        make_human("learned:path=/nonexistent")
    assert str(missing.value) == "human 'learned': path /nonexistent: no such model header (nonexistent.json)"
