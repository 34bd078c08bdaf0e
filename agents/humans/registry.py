"""The registry of humans: ``make_human(name, **params)`` and ``available_humans()``.

Names may carry parameters, so a command line or a population list can say
``"lazy:p_idle=0.5"`` or ``"noisy:temperature=0.2"``. Unknown names and bad parameters
raise :class:`HumanError` listing what exists. It is a :class:`hg_marl.core.registry.Registry`
like the robots' and the criteria's: each human's parameters and defaults are read from
its constructor's signature; the entries below add only a line per human and parameter.
Targets are ``module:Class`` texts, so listing the humans imports none of them.
"""

from __future__ import annotations

from typing import Any

from hg_marl.agents.humans.base import HumanError
from hg_marl.core.errors import SpecError
from hg_marl.core.registry import Entry, Param, Registry
from hg_marl.core.spec import parse_spec
from hg_marl.policy import Actor

HumanSpec = Entry
"""A registered human (the registry's :class:`~hg_marl.core.registry.Entry`)."""

__all__ = ["HUMANS", "HumanSpec", "Param", "available_humans", "make_human", "parse_human", "resolve_human"]

_P = "hg_marl.agents.humans."
_IDLE = "probability of doing nothing (wait) at any turn"
_FO = _P + "family_out:"
_FO_P = {"p_idle": _IDLE}
HUMANS = Registry(
    "human",
    HumanError,
    (
        Entry(
            "cooperative",
            _P + "cooperative:CooperativeHuman",
            "executes the human stream of the planner's shared plan; takes what the robot offers",
            {"p_idle": _IDLE},
        ),
        Entry(
            "lazy",
            _P + "lazy:LazyHuman",
            "handles only objects in its own area, never takes, often idles",
            {"p_idle": "probability of doing nothing at any turn"},
        ),
        Entry(
            "no_handover",
            _P + "no_handover:NoHandoverHuman",
            "never gives nor takes; throws what it can, moves the rest within robot reach",
            {"p_idle": _IDLE},
        ),
        Entry(
            "adversarial",
            _P + "adversarial:AdversarialHuman",
            "hoards objects, hides them out of robot reach, refuses handovers, never throws",
            {"p_idle": _IDLE},
        ),
        Entry(
            "random",
            _P + "random_human:RandomHuman",
            "uniform over its feasible actions",
            {"feasible_only": "draw among feasible actions only (False: all actions)"},
        ),
        Entry(
            "noisy",
            _P + "noisy:NoisyHuman",
            "Boltzmann-rational cooperative: softmax over -(predicted time to finish) / temperature",
            {"temperature": "seconds; 0 = cooperative, large = uniform over feasible actions"},
        ),
        Entry(
            "preference",
            _P + "preference:PreferenceHuman",
            "weighs the task's events (hand over, share, do it oneself, keep) and acts on the best one-step score",
            {
                "handover": "worth of handing the held object to the robot",
                "shared": "worth of putting an object on a spot the robot reaches",
                "self_work": "worth of throwing an object into a bin oneself",
                "keep": "worth of putting an object where only the human reaches (hoarding)",
                "robot_side": "added to picking an object the robot could reach itself",
                "colour": "preferred colour of objects to pick ('' for none; no match, no bonus)",
                "colour_bonus": "added to picking an object of the preferred colour",
                "haste": "seconds cost: each action's score minus haste x its duration",
                "accept": "probability of taking what the robot offers",
                "p_idle": _IDLE,
                "temperature": "0: best score, lowest index on ties; > 0: softmax of the scores",
            },
        ),
        Entry(
            "switching",
            _P + "switching:SwitchingHuman",
            "a schedule of other humans, by simulated time or tasks solved",
            {
                "humans": "the phases' humans (names or name:k=v)",
                "at": "thresholds between phases, increasing",
                "by": "'time' (simulated seconds) or 'tasks' (tasks solved)",
            },
            stationary=False,
        ),
        Entry(
            "learned",
            _P + "learned:LearnedHuman",
            "a saved policy trained in the human seat (numpy or SB3), acting from facts and mask",
            {
                "path": "policy directory (policy.json header + payload)",
                "deterministic": "take the most probable action instead of sampling",
                "fallback": "table kind, unseen observation: 'wait' or 'random'",
            },
        ),
        # The family-out set (agents/humans/family_out.py): no recipe trains or tunes on these.
        Entry("fo_freeze_on_offer", _FO + "FreezeOnOffer", "family-out: freezes while offered, never takes", _FO_P),
        Entry("fo_mirror", _FO + "Mirror", "family-out: works only while the robot works, echoing its kind", _FO_P),
        Entry("fo_picky", _FO + "Picky", "family-out: throws, takes, gives only even-index objects", _FO_P),
        Entry("fo_shy", _FO + "Shy", "family-out: freezes while the robot is at a handover place", _FO_P),
        Entry("fo_after_waits", _FO + "AfterWaits", "family-out: takes only after two robot waits", _FO_P, False),
        Entry(
            "fo_bursts",
            _FO + "Bursts",
            "family-out: works, then rests, by the clock",
            {"work": "seconds of work", "rest": "seconds of rest", "p_idle": _IDLE},
            stationary=False,
        ),
        Entry(
            "fo_forgetful",
            _FO + "Forgetful",
            "family-out: forgets what it picked for a while",
            {"hold": "seconds an object stays forgotten", "p_idle": _IDLE},
            stationary=False,
        ),
        Entry(
            "fo_slow_start",
            _FO + "SlowStart",
            "family-out: watches first, then helps",
            {"warmup": "seconds of watching", "p_idle": _IDLE},
            stationary=False,
        ),
        Entry(
            "replay",
            _P + "replay:ReplayHuman",
            "plays back a recorded JSON-lines trace",
            {
                "path": "trace file",
                "on_mismatch": "live facts differ from the recording: error, warn, ignore",
                "on_end": "recorded steps run out: wait or error",
                "loop": "start again at the first episode after the last",
            },
            stationary=False,
        ),
    ),
    list_params=True,
)
"""Every human by name."""


def available_humans() -> dict[str, dict[str, Any]]:
    """Every registered human: ``{name: {"doc": ..., "stationary": ..., "params": {p: (default, doc)}}}``."""
    return {
        name: {"doc": s.doc, "stationary": s.stationary, "params": {k: (p.default, p.doc) for k, p in s.params.items()}}
        for name, s in HUMANS.items()
    }


def parse_human(text: str) -> tuple[str, dict[str, str]]:
    """Split ``"name:k=v,k2=v2"`` into the name and raw parameter texts (the one spec parser)."""
    try:
        spec = parse_spec(text, "human")
    except SpecError as exc:
        raise HumanError(str(exc)) from None
    return spec.name, dict(spec.raw)


def make_human(name: str, **params: Any) -> Actor:
    """Build a registered human.

    Args:
        name: a registry name, optionally with parameters: ``"lazy:p_idle=0.5"``.
        **params: parameters (override those in ``name``).

    Raises:
        HumanError: unknown name, unknown parameter, or a value the human rejects
            (model-file problems stay :class:`ModelFileError`).
    """
    human: Actor = HUMANS.make(name, **params)
    return human


def resolve_human(human: str | Actor) -> Actor:
    """An Actor from a registry name (with optional parameters) or an Actor instance."""
    if isinstance(human, str):
        return make_human(human)
    if not isinstance(human, Actor):
        raise HumanError(f"expected a human name or an Actor (reset + act), got {human!r}")
    return human
