"""Models of the human the planner plans against (HATP's "human model").

A model answers one question: when the human is to act in ``state``, which of its
candidate actions may it take, and with what probability? The answer is a short
distribution over *choice sets*: ``((p1, set1), (p2, set2), ...)``. Within a set the
human is cooperative (the planner picks the human's action that minimises the team's
cost, as HATP does for a cooperative human); across sets the planner takes the
expectation. So:

- cooperative: ``((1.0, all),)``; the planner chooses everything;
- a deterministic restriction (``no_handover``, ``lazy``): ``((1.0, allowed),)``; the
  planner optimises over what this human will do;
- a stochastic model, e.g. "does nothing with probability p, else cooperative":
  ``((p, (wait,)), (1 - p, all))``; the planner computes expectimax (expectation over
  the human, minimum over the robot).

``allowed_kinds`` is the static part of a restriction: the planner's lower bound drops
the disposal methods that need a forbidden kind, which is how it proves early that an
object cannot be disposed of with this human (e.g. no handover and no shared spot).

The humans package reuses these models as policies' specifications: a cooperative
human executes the human stream of the shared plan, a ``no_handover`` human never gives
or takes, a ``lazy`` one never takes what the robot offers and may idle.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

from hg_marl.core import Action, Agent, Kind, State, World

HUMAN_KINDS: frozenset[Kind] = frozenset(k for k in Kind if k is not Kind.GOTO)
"""Every action kind the human has."""

Choices = tuple[tuple[float, tuple[int, ...]], ...]
"""A distribution over choice sets of human action indices (see the module docstring)."""


@runtime_checkable
class HumanModel(Protocol):
    """What the planner assumes about the human."""

    @property
    def name(self) -> str:
        """Registry name, e.g. ``"cooperative"``."""

    @property
    def stochastic(self) -> bool:
        """True when :meth:`choices` may return more than one set (expectimax needed)."""

    @property
    def allowed_kinds(self) -> frozenset[Kind]:
        """Action kinds this human ever performs (``WAIT`` always included)."""

    def choices(self, world: World, state: State, candidates: Sequence[int]) -> Choices:
        """Distribution over subsets of ``candidates`` (human action indices, ``wait`` among them).

        Every returned set is non-empty and the probabilities sum to 1.
        """


@dataclass(frozen=True)
class RestrictedHuman:
    """A human that only performs ``allowed_kinds`` and idles with probability ``p_idle``.

    With ``p_idle == 0`` this is a deterministic restriction (the planner optimises the
    human's actions within it); otherwise "does nothing with probability ``p_idle``, else
    acts as the restricted cooperative human".
    """

    name: str = "cooperative"
    """Registry name."""
    allowed_kinds: frozenset[Kind] = HUMAN_KINDS
    """Kinds this human performs; ``WAIT`` is added if missing."""
    p_idle: float = 0.0
    """Probability of doing nothing (``wait``) at any turn."""
    blocked: frozenset[Action] = field(default_factory=frozenset)
    """Ground actions ruled out (the monitor's blocking facts, e.g. a take that did not happen)."""

    def __post_init__(self) -> None:
        if not 0.0 <= self.p_idle < 1.0:
            raise ValueError(f"{self.name}: p_idle must be in [0, 1), got {self.p_idle}")
        object.__setattr__(self, "allowed_kinds", frozenset(self.allowed_kinds) | {Kind.WAIT})

    @property
    def stochastic(self) -> bool:
        """Whether the model idles at random."""
        return self.p_idle > 0.0

    def allows(self, world: World, index: int) -> bool:
        """Whether this human ever performs human action ``index``."""
        action = world.actions(Agent.HUMAN)[index]
        return action.kind in self.allowed_kinds and action not in self.blocked

    def choices(self, world: World, state: State, candidates: Sequence[int]) -> Choices:
        """See :meth:`HumanModel.choices`."""
        if self.blocked or self.allowed_kinds != HUMAN_KINDS:
            allowed = tuple(i for i in candidates if self.allows(world, i))
        else:
            allowed = tuple(candidates)
        wait = world.n_actions(Agent.HUMAN) - 1
        if not allowed:
            allowed = (wait,)
        if self.p_idle == 0.0:
            return ((1.0, allowed),)
        return ((self.p_idle, (wait,)), (1.0 - self.p_idle, allowed))

    def with_blocked(self, actions: frozenset[Action]) -> RestrictedHuman:
        """The same model with extra ground actions ruled out (HATP's blocking facts)."""
        return RestrictedHuman(self.name, self.allowed_kinds, self.p_idle, self.blocked | actions)


def cooperative(p_idle: float = 0.0) -> RestrictedHuman:
    """The default: the human does whatever the shared plan needs (idles with ``p_idle``)."""
    return RestrictedHuman("cooperative", HUMAN_KINDS, p_idle)


def no_handover(p_idle: float = 0.0) -> RestrictedHuman:
    """A human "afraid of the robot": never gives nor takes; may place within robot reach."""
    return RestrictedHuman("no_handover", HUMAN_KINDS - {Kind.GIVE, Kind.TAKE}, p_idle)


def lazy(p_idle: float = 0.0) -> RestrictedHuman:
    """A human that only handles objects on spots it reaches (picks, throws, gives,
    places) and never takes what the robot offers; idles with ``p_idle``."""
    return RestrictedHuman("lazy", HUMAN_KINDS - {Kind.TAKE}, p_idle)


_MODELS = {"cooperative": cooperative, "no_handover": no_handover, "lazy": lazy}


def make_human_model(name: str, **params: float) -> RestrictedHuman:
    """Build a human model by name: ``cooperative``, ``no_handover`` or ``lazy``.

    Args:
        name: the model's registry name.
        **params: the model's parameters (all take ``p_idle``).

    Raises:
        ValueError: unknown name or parameter.
    """
    try:
        factory = _MODELS[name]
    except KeyError:
        raise ValueError(f"unknown human model {name!r} (known: {', '.join(_MODELS)})") from None
    try:
        return factory(**params)
    except TypeError as exc:
        raise ValueError(f"human model {name!r}: {exc}") from exc
