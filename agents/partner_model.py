"""A partner model learned online: what *this* partner does, beside the posterior over members.

Why. A posterior over population members can only say which member the partner resembles
most. A partner no member explains (one who freezes while offered, who copies the robot)
is then "explained" by whichever member is least wrong, and every one of its refusals stays
plausible under a member who accepts offers 40% of the time. The learned model fits the
partner's own answers, so the evidence can say "none of them, but this".

The model (a Dirichlet-categorical, the textbook online partner model):

- **Context**: abstract features of the mid-cycle state the partner answers in and of the
  robot's action under way: whether the partner holds an object, whether the robot is
  offering one, whether the robot stands at a handover place, and the kind of the robot's
  action (pick, throw, give, take, goto, wait; ``failed`` when it failed). Small on purpose:
  a few dozen contexts are visited within minutes, so the counts mean something quickly.
- **Answer**: the *kind* of the partner's action; within a kind the ground actions feasible
  at the state share its probability equally.
- **Counts**: ``alpha`` pseudo-counts per feasible kind (the prior: no kind preferred) plus
  the observed answers, each context's counts multiplied by ``forget`` at each of its
  observations (a partner who changes is followed within about ``1 / (1 - forget)`` answers
  in that context).
- **Predictive**: ``p(kind) = (n_kind + alpha) / sum over feasible kinds (n_k + alpha)``.

:meth:`LearnedPartner.predict` is the prequential likelihood (predict, then :meth:`update`),
which is the model evidence :class:`~hg_marl.agents.partner.PartnerPosterior` weighs against
each member's: the posterior decides continuously how much the robot trusts the family or
the learned model (``tests/agents/test_partner_model.py`` works an estimate by hand and
watches the evidence switch on a partner no member explains).
"""

from __future__ import annotations

import math
from collections import Counter

import numpy as np

from hg_marl.agents.planner.models import HUMAN_KINDS, RestrictedHuman
from hg_marl.core import Agent, Kind, State, World
from hg_marl.policy import Turn

FAILED = -1
"""The robot action kind of a failed (or unknown) robot action."""

Context = tuple[bool, bool, bool, int]

NEVER = 1e-9
"""A kind is refused when its (forgetting) share of the answers at which it was feasible is
below this: not done once within the model's memory (one occurrence weighs ``forget ** n``
after n more chances, under 1e-9 after about 400 at 0.95). A share of 10% refused kinds a
partner does late rather than never (a partner who holds an object 30 s before placing it,
one who rests between bursts of work): planned without them, the robot planned as if they
would never come (``docs/adaptation.md``, section 7)."""


class LearnedPartner:
    """Dirichlet counts of the partner's action kind per abstract context.

    Args:
        alpha: prior pseudo-count of each feasible kind (> 0).
        forget: weight kept by a context's past counts at each of its observations, in (0, 1].
    """

    name = "learned"
    uses_robot_action = True

    def __init__(self, alpha: float = 1.0, forget: float = 0.95) -> None:
        if not (math.isfinite(alpha) and alpha > 0):
            raise ValueError(f"learned partner: alpha must be > 0, got {alpha!r}")
        if not (math.isfinite(forget) and 0 < forget <= 1):
            raise ValueError(f"learned partner: forget must be in (0, 1], got {forget!r}")
        self.alpha, self.forget = float(alpha), float(forget)
        self.reset()

    def reset(self) -> None:
        """Forget every count (a new run)."""
        self.counts: dict[Context, dict[int, float]] = {}
        self.chances: dict[int, float] = {}
        """Per kind, the (forgetting) number of answers at which it was feasible."""
        self.taken: dict[int, float] = {}
        """Per kind, the (forgetting) number of those answers that were of this kind."""

    @staticmethod
    def context(world: World, state: State, robot_action: int) -> Context:
        """The abstract features the model conditions on (module docstring)."""
        kind = FAILED if robot_action < 0 else int(world.actions(Agent.ROBOT)[robot_action].kind)
        return (
            world.holding(state, Agent.HUMAN) >= 0,
            state.offer_by == int(Agent.ROBOT),
            state.robot_at in world.scenario.handover_locations,
            kind,
        )

    def kind_distribution(self, world: World, state: State, robot_action: int) -> dict[int, float]:
        """``p(kind)`` over the kinds feasible for the partner at ``state``."""
        kinds = {int(world.actions(Agent.HUMAN)[i].kind) for i in world.feasible_indices(state, Agent.HUMAN)}
        counts = self.counts.get(self.context(world, state, robot_action), {})
        total = sum(counts.get(k, 0.0) + self.alpha for k in kinds)
        return {k: (counts.get(k, 0.0) + self.alpha) / total for k in kinds}

    def distribution(self, world: World, state: State, robot_action: int = -1) -> list[tuple[int, float]]:
        """The predicted answer over the partner's feasible ground actions (an answer distribution)."""
        feasible = world.feasible_indices(state, Agent.HUMAN)
        acts = world.actions(Agent.HUMAN)
        by_kind = Counter(int(acts[i].kind) for i in feasible)
        pk = self.kind_distribution(world, state, robot_action)
        return [(i, pk[int(acts[i].kind)] / by_kind[int(acts[i].kind)]) for i in feasible]

    def predict(self, world: World, state: State, robot_action: int, human_action: int) -> float:
        """Probability the model gives the partner's ``human_action`` at ``state`` (0 if infeasible)."""
        return dict(self.distribution(world, state, robot_action)).get(human_action, 0.0)

    def update(self, world: World, state: State, robot_action: int, human_action: int) -> None:
        """Count the answer ``human_action`` (after :meth:`predict`, for a prequential evidence)."""
        ctx = self.context(world, state, robot_action)
        counts = self.counts.setdefault(ctx, {})
        for k in counts:
            counts[k] *= self.forget
        kind = int(world.actions(Agent.HUMAN)[human_action].kind)
        counts[kind] = counts.get(kind, 0.0) + 1.0
        for k in {int(world.actions(Agent.HUMAN)[i].kind) for i in world.feasible_indices(state, Agent.HUMAN)}:
            self.chances[k] = self.forget * self.chances.get(k, 0.0) + 1.0
            self.taken[k] = self.forget * self.taken.get(k, 0.0) + float(k == kind)

    def refused_kinds(self, min_chances: float = 3.0, below: float = NEVER) -> frozenset[Kind]:
        """Kinds the partner never does when it can: feasible ``min_chances`` times, done < ``below`` of them."""
        return frozenset(
            Kind(k)
            for k, n in self.chances.items()
            if k != int(Kind.WAIT) and n >= min_chances and self.taken.get(k, 0.0) / n < below
        )

    def planner_model(self) -> RestrictedHuman:
        """The planner's human model of this partner: cooperative, without the kinds it refuses.

        The planner's human-aware search then plans as the partner behaves (a partner who
        never takes gets no handover in the plan); the answer distribution itself is the
        belief's evidence, not the planner's input, which keeps the planner's search small.
        """
        return RestrictedHuman("learned", HUMAN_KINDS - self.refused_kinds())


def observe_move(model: LearnedPartner, world: World, previous: tuple[State, int] | None, turn: Turn) -> None:
    """Count the partner's move since the robot's previous turn (``previous``: its state and action).

    The state the partner answered in is the robot's previous state after the robot's own
    action (the rules make it deterministic); a solved task re-draws the table, so that
    cycle is not counted, nor one whose reconstruction does not hold.
    """
    human_action = turn.last_actions[1]
    if previous is None or human_action < 0 or turn.reward > 0:
        return
    state, robot_action = previous
    step = world.step(state, Agent.ROBOT, robot_action)
    if world.step(step.state, Agent.HUMAN, human_action).state == turn.state:
        model.update(world, step.state, robot_action if step.ok else -1, human_action)


def partner_features(model: LearnedPartner) -> np.ndarray:
    """The partner model's verdicts a habit can read: does it refuse to take, to give (0/1 each)."""
    refused = model.refused_kinds()
    return np.array([Kind.TAKE in refused, Kind.GIVE in refused], dtype=np.int8)
