"""What the robot believes about its partner, revised from what the partner does.

The planner replans from the true state at every decision, but with a fixed model of
the human; a partner who keeps not doing what the plan expects would get the same
expectation forever (the robot waits at the handover place, the table stays dirty).
Two layers revise the model:

- :class:`PartnerMonitor` (every planning robot): HATP's blocking facts. A ground human
  action the plan expected and the human did not do, ``block_after`` times since the
  last task, is ruled out of the planner's model, so the planner looks for another way
  (the robot does the work itself, or a shared spot). When the human still does not do
  what is expected ``stall_after`` times in a row, the robot is *stalled*: it acts by
  its fallback (its habit, or any feasible move) for one decision, which also changes
  the situation a state-dependent partner reacts to. Blocks are forgotten when a task
  is solved, so a partner who changes back is trusted again.
- :class:`PartnerPosterior` (the ``partner_aware`` robots, the paper's outlook): a
  Bayesian posterior over the human registry's stationary types, updated from every
  observed human action with the type's own action distribution, and forgetting old
  evidence (``decay``) so a partner who switches is followed. The planner plans against
  the most probable type's model.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from hg_marl.agents.planner.models import RestrictedHuman, make_human_model
from hg_marl.core import Action, Agent, Kind, State, World

PLANNER_MODEL_OF: dict[str, str] = {"cooperative": "cooperative", "noisy": "cooperative"}
"""Partner type -> the planner's human model (types not listed use their own name)."""


class PartnerMonitor:
    """Blocking facts and stall detection from the plan's expected human actions.

    Args:
        block_after: refusals of one ground action (since the last task) that rule it out.
        stall_after: consecutive unmet expectations after which the robot is stalled.
    """

    def __init__(self, block_after: int = 2, stall_after: int = 4) -> None:
        if block_after < 1 or stall_after < 1:
            raise ValueError("block_after and stall_after must be positive")
        self.block_after = block_after
        self.stall_after = stall_after
        self.reset()

    def reset(self) -> None:
        """Forget everything (a new run)."""
        self.refusals: dict[Action, int] = {}
        self.blocked: frozenset[Action] = frozenset()
        self.misses = 0
        self.fallbacks = 0

    def observe(self, world: World, expected: int, actual: int, solved: bool) -> None:
        """The plan expected human action ``expected`` (-1: none), the human did ``actual``.

        Only an expected *non-wait* action that did not happen counts as a refusal: a human
        who does more than the plan hoped is not contradicting it.
        """
        if solved:
            self.refusals, self.blocked, self.misses = {}, frozenset(), 0
            return
        if expected < 0 or actual < 0:
            return
        action = world.actions(Agent.HUMAN)[expected]
        if action.kind is Kind.WAIT:
            return
        if actual == expected:
            self.misses = 0
            return
        self.misses += 1
        count = self.refusals.get(action, 0) + 1
        self.refusals[action] = count
        if count >= self.block_after:
            self.blocked = self.blocked | {action}

    def planner_failed(self) -> None:
        """No plan with this model: the blocks were a wrong guess, or the partner leaves nothing to do.

        Blocks are forgotten (the planner gets the base model back); without blocks a
        failure counts as an unmet expectation, so a robot that cannot plan is stalled
        after ``stall_after`` failures and moves.
        """
        if self.blocked:
            self.refusals, self.blocked = {}, frozenset()
        else:
            self.misses += 1

    @property
    def stalled(self) -> bool:
        """Whether the partner has not done what was expected ``stall_after`` times in a row."""
        return self.misses >= self.stall_after

    def fell_back(self) -> None:
        """The robot took its fallback: give the planner (with its new blocks) another chance."""
        self.fallbacks += 1
        self.misses = self.stall_after // 2

    def model(self, base: RestrictedHuman) -> RestrictedHuman:
        """``base`` with the blocked actions ruled out."""
        return base.with_blocked(self.blocked) if self.blocked else base


class PartnerPosterior:
    """Posterior over partner types, from the types' own action distributions.

    Args:
        types: registry specs of the candidate types (``"lazy"``, ``"lazy:p_idle=0.5"``).
        prior: prior probability of each type (None: ``prior_cooperative`` on the first,
            the rest shared equally).
        decay: weight kept by past evidence per informative observation (1: never forget);
            an observation every type predicts equally (most waits) is no evidence and
            forgets nothing, so the memory spans the last ``1 / (1 - decay)`` telling actions.
        epsilon: probability that the human does any feasible action at random, whatever
            its type (keeps one surprising action from ruling a type out for good).
    """

    def __init__(
        self,
        types: Sequence[str] = ("cooperative", "lazy", "no_handover", "noisy"),
        prior: Sequence[float] | None = None,
        decay: float = 0.95,
        epsilon: float = 0.05,
        prior_cooperative: float = 0.7,
        idle_in_model: bool = False,
        learned: Any = None,
    ) -> None:
        from hg_marl.agents.humans import make_human

        self.types = tuple(types)
        self.learned = learned
        """A :class:`~hg_marl.agents.partner_model.LearnedPartner` scored as the last type
        (its name is in ``types``; its evidence is prequential: predict, then count), or None."""
        if not self.types:
            raise ValueError("partner types: give at least one")
        if prior is None:
            rest = (1.0 - prior_cooperative) / max(len(self.types) - 1, 1)
            prior = [prior_cooperative] + [rest] * (len(self.types) - 1) if len(self.types) > 1 else [1.0]
        if len(prior) != len(self.types) or any(not (p > 0 and math.isfinite(p)) for p in prior):
            raise ValueError("partner prior: one positive probability per type")
        if not 0.0 < decay <= 1.0 or not 0.0 < epsilon < 1.0:
            raise ValueError("partner decay must be in (0, 1] and epsilon in (0, 1)")
        self.log_prior = [math.log(p / sum(prior)) for p in prior]
        self.decay, self.epsilon, self.idle_in_model = decay, epsilon, idle_in_model
        self.humans: list[Any] = []
        for spec in self.types:
            if learned is not None and spec == learned.name:
                self.humans.append(learned)
                continue
            self.humans.append(make_human(spec))  # the registry's one spec parser types the values
        self.reset()

    def reset(self) -> None:
        """Back to the prior (a new run)."""
        self.evidence = [0.0] * len(self.types)
        self.observations = 0
        if self.learned is not None:
            self.learned.reset()

    def observe(self, world: World, state: State, robot_action: int, human_action: int) -> None:
        """The human did ``human_action`` in ``state`` while the robot did ``robot_action`` (-1: failed)."""
        n = len(world.feasible_indices(state, Agent.HUMAN))
        logs = []
        for human in self.humans:
            dist = dict(human.distribution(world, state, robot_action if human.uses_robot_action else -1))
            logs.append(math.log((1.0 - self.epsilon) * dist.get(human_action, 0.0) + self.epsilon / max(n, 1)))
        if self.learned is not None:
            self.learned.update(world, state, robot_action, human_action)  # after its prediction: prequential
        if max(logs) - min(logs) < 1e-9:
            return  # every type would have done this: no evidence, and nothing to forget
        self.evidence = [self.decay * e + x for e, x in zip(self.evidence, logs, strict=True)]
        self.observations += 1

    def posterior(self) -> dict[str, float]:
        """Probability of each type given the (decayed) evidence."""
        logs = [a + b for a, b in zip(self.log_prior, self.evidence, strict=True)]
        top = max(logs)
        weights = [math.exp(x - top) for x in logs]
        total = sum(weights)
        return {t: w / total for t, w in zip(self.types, weights, strict=True)}

    def most_probable(self) -> str:
        """The maximum a posteriori type."""
        post = self.posterior()
        return max(post, key=post.__getitem__)

    def model(self) -> RestrictedHuman:
        """The planner's human model for the most probable type, idling as that type does."""
        k = self.types.index(self.most_probable())
        name = self.types[k].partition(":")[0]
        p_idle = float(getattr(self.humans[k], "p_idle", 0.0)) if self.idle_in_model else 0.0
        return make_human_model(PLANNER_MODEL_OF.get(name, name), p_idle=min(p_idle, 0.9))
