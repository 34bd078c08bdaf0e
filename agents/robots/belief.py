"""``belief``: a robot that infers which member of a partner population it plays with.

Why (the paper's outlook, Bayesian theory of mind): the partner-aware planner keeps a
posterior over four registry *names* and plans against the most probable one's planner
model, which cannot express a partner whose preferences are weights over events. This
robot keeps a posterior over the *members* of a population file (the parameter points
the population generator sampled; by default its ``train`` and ``validation`` members,
never the ``held_out`` ones it is scored on) and plans with each member's **exact best
response** (the oracle's values, :func:`~hg_marl.agents.oracle.oracle_rate`):

- **Belief.** After each human move the posterior is updated with that member's own
  action distribution at the state the human acted in (:class:`~hg_marl.agents.partner.PartnerPosterior`,
  with ``epsilon`` uniform slack so that no single surprise rules a member out) and old
  evidence decays by ``decay`` per telling action, so a partner who changes is followed
  within about ``1 / (1 - decay)`` telling actions (``tests/agents/test_belief.py``).
- **Plans.** ``hedge="map"`` (default) plays the most probable member's best response;
  ``hedge="qmdp"`` takes ``argmin_a sum_m b(m) Q_m(s, a)``, the expected seconds to the
  next success under the posterior mixture, assuming the partner's identity is revealed
  after this step (QMDP): a robot that is unsure hedges between the members' best
  responses, one that knows commits to its member's. MAP is the default because it
  did better on the bundled hard layouts (``docs/hard-layouts.md``): the belief settles
  within a few telling actions, and QMDP's mixture, which assumes the uncertainty
  resolves after one step, keeps paying for members the partner has already ruled out
  in the states where they disagree. ``Q_m`` is the
  oracle's one-step backup of ``V_m`` through member ``m``'s replies
  (``PythonModel.replies``, the oracle's own transition rule).
- **An open world.** Beside the members the posterior holds "none of them": the uniform
  partner (the registry's ``random`` human), prior ``unknown`` (5%). A partner the
  members explain worse than chance (one who keeps to its own side where every member
  would clear the middle) makes it the most probable hypothesis; the robot then hands
  the decisions to a plain ``planner`` robot of its own, which replans from what it
  sees and rules out the moves the partner refuses, until a member explains the partner
  again, so such a partner gets about what the plain planner gets rather than a closed
  world's wrong best response (``docs/hard-layouts.md``).
- **Observed answers** (``open_world="observed"``). The "none of them" hypothesis is
  the partner's own answers at each (state, robot move) it was seen at, the most probable
  member's answer elsewhere (:mod:`~hg_marl.agents.observed_partner`). When it is the
  most probable hypothesis the robot plays that model's exact best response, solved from
  the table in front of it and again only after the partner surprised it at the current
  state, over the expansions kept from earlier solves; a solve is charged to the clock as a
  planner call of one node per state it expands. A partner whose answers at a state
  contradict its earlier ones there (a clock, its own history), or a table whose members'
  models are too large (``roboergosum``), is planned for as the plain planner plans; so
  is a state where the partner was never seen answering, where the model is only a member
  worse than itself. A wait where the partner has acted is a pause, not counted.
- **Probing** (``probe=S``, default off). While no member holds 90% of the belief, the
  robot may take, instead of its best action, the action whose reply tells the members
  apart most (mutual information between member and reply, :meth:`information`) if it
  costs at most ``S`` expected seconds more and tells at least 0.05 nats more. It does
  not pay on the bundled layouts (``docs/hard-layouts.md``): the replies to the moves
  the robot makes anyway tell the members apart within a few actions, so a move bought
  for information is a move lost.
- **Off every member's model** (a state no member's dynamics reach), and when it would
  wait again at an unchanged unfinished table after a run of shared waits that the
  belief makes unlikely (< 5%: the partner waits where its members would act, so the
  belief cannot move), it plays the oracle robot's fallback:
  the planner's move, or a feasible non-wait move when the planner would wait as well;
  once stalled, the planner drives until the partner does something or a task is solved.
- **Refused offers** (``refusals=True``, default). A member who takes offers now and then
  explains each refusal, so the posterior cannot move and its best response keeps
  offering to a partner who never takes. Each refusal is scored under the belief; once a
  run of them is less likely than :data:`REFUSAL_LIKELIHOOD`, the robot plans against the
  same members as partners who never take (``accept=0``, solved exactly and kept by
  content like the members) until the partner takes or the verdict lapses
  (:meth:`refuses_offers`).
- **The progress guard** every robot obeys (:mod:`hg_marl.agents.progress`): when the
  state has not changed for ``K`` of its turns (a refused offer repeated while the belief
  keeps a member who accepts offers often enough to explain each refusal), it takes the
  guard's feasible move, whatever the belief says (``reason="no_progress"``).

Each member's oracle is solved the first time a decision consults it (under ``map`` and a
uniform prior the first move needs one member) and kept by content, in the process and
in the folder ``cache`` names (:mod:`hg_marl.agents.member_models`): the same inputs give
the same values, so the robot decides as if every member had been solved at the start.
"""

from __future__ import annotations

import functools
import math
import time
from dataclasses import replace
from typing import Any

import numpy as np

from hg_marl.agents.humans.preference import never_takes
from hg_marl.agents.member_models import MemberModels, backup
from hg_marl.agents.observed_partner import ObservedPartner, ObservedSolver
from hg_marl.agents.oracle import OracleResult, OracleRobot
from hg_marl.agents.partner import PartnerPosterior
from hg_marl.agents.partner_model import LearnedPartner
from hg_marl.agents.planner.space import Relabel
from hg_marl.agents.progress import ProgressGuard
from hg_marl.agents.robots.base import Robot, make_planner
from hg_marl.agents.robots.partnering import planner_in
from hg_marl.agents.robots.planner import PlannerRobot
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.errors import OutputError, RobotError, check_bool, check_finite
from hg_marl.policy import Decision, Turn

HEDGES = ("qmdp", "map")
OPEN_WORLDS = ("uniform", "learned", "observed")
NEGLIGIBLE = 1e-3
"""Members with less posterior mass than this have no say in the mixture (nor its cost)."""
UNKNOWN = "random"
"""The "none of the members" hypothesis: a partner no likelier to do one feasible move than another."""
PROBE_BELOW = 0.9
"""A robot probes only while no member holds this much of the belief."""
MIN_GAIN = 0.05
"""Nats a probe must tell beyond the best action's own reply."""
STALL_LIKELIHOOD = 0.05
"""A run of shared waits less likely than this under the belief means the partner is stalled."""
REFUSAL_LIKELIHOOD = 0.002
"""A run of refused offers less likely than this under the belief means the partner refuses offers.

A sequential likelihood-ratio test against "never takes": over a run's hundreds of offers a
partner who takes as its member does would reach 0.05 by chance now and then (a 0.9 taker
refusing twice); 1/500 needs three refusals in a row from it, thirteen from a 0.4 taker."""
REFUSALS_WITHIN = 30
"""Answers after the last offer for which "refuses offers" holds; then the robot may offer again."""
BAYES_FACTOR = 1.0
"""How many times more probable than the most probable member the learned partner must be
before the robot plans with it (``open_world="learned"``; the ``bayes_factor`` parameter).

Above 1 the robot keeps a member's exact best response against a partner that member only
roughly explains, where the learned model, fitted to the partner's last answers,
out-predicts it by small factors now and then (held-out members: factors of 1-10 against
hundreds and more for partners no member explains). That helps in the family and costs
outside it; 1 (the most probable hypothesis wins) is the default, measured both ways in
docs/adaptation.md, section 8."""


class BeliefRobot(Robot):
    """Posterior over population members, acting on their exact best responses.

    Args:
        population: a population file (``hg-marl population generate`` writes one).
        splits: the members the robot may believe in, comma-separated splits of the file.
        decay: weight kept by past evidence per telling action (1: never forget).
        epsilon: probability the partner does any feasible action whatever its member.
        hedge: ``"map"`` (most probable member) or ``"qmdp"`` (expected seconds under the mixture).
        unknown: prior probability that the partner is none of the members (0: a closed world).
        probe: expected seconds the robot may give up to learn who its partner is (0: never probes).
        open_world: the "none of them" hypothesis: ``"uniform"`` (the uniform partner),
            ``"learned"`` (a partner model learned online from this partner's answers,
            :class:`~hg_marl.agents.partner_model.LearnedPartner`; its prequential evidence
            competes with the members') or ``"observed"`` (the partner's own answers where it
            answered, the most probable member's elsewhere,
            :class:`~hg_marl.agents.observed_partner.ObservedPartner`; when it is the most
            probable hypothesis the robot plays its exact best response, solved from the
            table in front of it where the members' models are small enough).
        cache: a folder that keeps the members' solved models by content (empty:
            ``$HG_MARL_CACHE/oracle`` when set, else none), so a later robot reads them.
        refusals: plan against the members as partners who never take once the partner
            has refused more offers in a row than the belief explains (:meth:`refuses_offers`).
        bayes_factor: with ``open_world="learned"``, how many times more probable than the
            most probable member the learned partner must be before the robot plans with it
            (see :data:`BAYES_FACTOR`).
    """

    name = "belief"

    def __init__(
        self,
        population: str = "",
        splits: str = "train,validation",
        decay: float = 0.9,
        epsilon: float = 0.05,
        hedge: str = "map",
        unknown: float = 0.05,
        probe: float = 0.0,
        open_world: str = "uniform",
        cache: str = "",
        refusals: bool = True,
        bayes_factor: float = BAYES_FACTOR,
    ) -> None:
        from hg_marl.agents.humans.population import load_population

        super().__init__()
        if not population:
            raise RobotError("belief.population: name a population file (hg-marl population generate writes one)")
        if hedge not in HEDGES:
            raise RobotError(f"belief.hedge: expected one of {', '.join(HEDGES)}, got {hedge!r}")
        pop = load_population(population)
        members = [m for split in splits.split(",") if split.strip() for m in pop.members(split.strip())]
        if not members:
            raise RobotError(f"belief.splits: {splits!r} selects no member of {population}")
        self.population, self.splits, self.hedge = population, splits, hedge
        self.member_names = tuple(m.name for m in members)
        self.member_specs = tuple(m.spec for m in members)
        if not (math.isfinite(unknown) and 0.0 <= unknown < 1.0):
            raise RobotError(f"belief.unknown: expected a probability in [0, 1), got {unknown!r}")
        if UNKNOWN in self.member_specs:
            raise RobotError(f"belief.population: a member plays {UNKNOWN!r}, the robot's 'none of them' hypothesis")
        # The open world: "none of the members" is the uniform partner (the registry's
        # `random` human), so it wins only where the members explain the moves worse than chance.
        if open_world not in OPEN_WORLDS:
            raise RobotError(f"belief.open_world: expected one of {', '.join(OPEN_WORLDS)}, got {open_world!r}")
        self.open_world = open_world
        self.bayes_factor = check_finite(bayes_factor, "belief.bayes_factor", minimum=1.0, error=RobotError)
        learned: LearnedPartner | ObservedPartner | None = None
        if unknown > 0 and open_world != "uniform":
            learned = LearnedPartner() if open_world == "learned" else ObservedPartner()
        self._unknown_name = learned.name if learned is not None else UNKNOWN
        types = (*self.member_specs, self._unknown_name) if unknown > 0 else self.member_specs
        prior = [(1.0 - unknown) / len(members)] * len(members) + ([unknown] if unknown > 0 else [])
        self.unknown = unknown
        if not (math.isfinite(probe) and probe >= 0.0):
            raise RobotError(f"belief.probe: expected seconds >= 0, got {probe!r}")
        self.probe = probe
        try:
            self.posterior = PartnerPosterior(types=types, prior=prior, decay=decay, epsilon=epsilon, learned=learned)
        except ValueError as exc:
            raise RobotError(f"belief: {exc}") from None
        try:
            self.members = MemberModels(self.member_specs, cache, "belief.cache")
        except OutputError as exc:
            raise RobotError(str(exc)) from None
        self.refusals = check_bool(refusals, "belief.refusals", RobotError)
        self._never_takes = MemberModels(tuple(never_takes(spec) for spec in self.member_specs), cache)
        self._fallback = OracleRobot(result=None)
        self._planner = PlannerRobot()
        self._checkers: dict[Any, Any] = {}
        """A planner per learned model, asked whether that model leaves the table clearable."""
        self._prev: tuple[State, int] | None = None
        self.progress = ProgressGuard()
        self._observed = ObservedSolver()
        self._planned = False
        """Whether the planner decided this turn (otherwise it only follows: :meth:`PlannerRobot.follow`)."""

    def _reset(self, world: World) -> None:
        """Forget the previous run's evidence (members' models are solved when first consulted)."""
        if self.agent is not Agent.ROBOT:
            raise RobotError("belief plays the robot seat only")
        self.members.reset(world)
        self._never_takes.reset(world)
        self._refusal_run = 1.0
        self._since_offer = 0
        self._relabel = Relabel(world)
        self._wait = world.n_actions(Agent.ROBOT) - 1
        self._planner_mode = False
        self._wait_run = 1.0
        self.posterior.reset()
        self._prev = None
        # The fallback robot plays only its off-model move: an empty policy keeps it from solving one.
        self._fallback.result = OracleResult(0.0, math.inf, 0, 0, 0, 0, True, {}, {}, scenario=world.scenario.name)
        self._fallback.reset(world, self.agent, self.rng)
        self._planner.reset(world, self.agent, self.rng.spawn(1)[0])
        self._checkers = {}
        self._off_population = False
        self.progress.reset()
        self._observed.reset()

    def _observe(self, turn: Turn) -> None:
        """Update the posterior from the human's move since the previous turn."""
        human_action = turn.last_actions[1]
        if self._prev is None or human_action < 0 or turn.reward > 0:
            return  # a solved task re-draws the table: the human's state is not reconstructible
        state, robot_action = self._prev
        step = turn.world.step(state, Agent.ROBOT, robot_action)
        if turn.world.step(step.state, Agent.HUMAN, human_action).state == turn.state:
            seen = robot_action if step.ok else -1  # what the partner saw the robot do
            self._count_refusal(turn.world, step.state, seen, human_action)
            if isinstance(self.posterior.learned, ObservedPartner):
                # where the partner was never seen, it answers as the most probable member would
                post = self.posterior.posterior()
                best = max(range(len(self.member_specs)), key=lambda m: post[self.member_specs[m]])
                self.posterior.learned.base = self.posterior.humans[best]
            self.posterior.observe(turn.world, step.state, seen, human_action)

    def _count_refusal(self, world: World, mid: State, robot_action: int, human_action: int) -> None:
        """Score the partner's answer to an offer under the belief, before the belief moves.

        ``_refusal_run`` is the probability of the current run of refused offers under the
        posterior mixture (each member's chance of not taking at the state, with the
        posterior's ``epsilon`` slack); a take ends the run.
        """
        self._since_offer += 1
        if mid.offer_by != int(Agent.ROBOT):
            return
        acts = world.actions(Agent.HUMAN)
        feasible = world.feasible_indices(mid, Agent.HUMAN)
        # One object is offered at a time, so at most one take answers it.
        take = next((i for i in feasible if acts[i].kind is Kind.TAKE), -1)
        if take < 0:
            return  # the partner's hand is full: it could not take
        self._since_offer = 0
        if human_action == take:
            self._refusal_run = 1.0
            return
        post = self.posterior.posterior()
        eps, n = self.posterior.epsilon, len(feasible)
        refuse = 0.0
        for spec, human in zip(self.posterior.types, self.posterior.humans, strict=True):
            # A human who does not look at the robot's action ignores it.
            p_take = dict(human.distribution(world, mid, robot_action)).get(take, 0.0)
            refuse += post[spec] * (1.0 - ((1.0 - eps) * p_take + eps / n))
        self._refusal_run *= refuse

    def refuses_offers(self) -> bool:
        """Whether the members are planned against as partners who never take (``refusals``).

        True while the run of refused offers is less likely than :data:`REFUSAL_LIKELIHOOD`
        under the belief and the last offer is at most :data:`REFUSALS_WITHIN` answers old.
        Why: a member who accepts offers now and then explains each refusal, so the
        posterior cannot move and its best response keeps offering; a partner who refuses
        more offers in a row than any believed member would is planned against as the same
        members who never take (:func:`~hg_marl.agents.humans.preference.never_takes`),
        each solved exactly and kept by content like the members. Once the robot stops
        offering the partner has no chance to take, so the verdict lapses after
        :data:`REFUSALS_WITHIN` answers and the robot offers again: a partner who has
        changed is followed; one who has not refuses once more, and the verdict holds.
        """
        return self.refusals and self._refusal_run < REFUSAL_LIKELIHOOD and self._since_offer <= REFUSALS_WITHIN

    def q_values(self, world: World, state: State, member: int) -> dict[int, float]:
        """Member ``member``'s expected seconds to the next success after each feasible robot action."""
        members = self._never_takes if self.refuses_offers() else self.members
        return backup(world, state, members.result(member), members.model(member), self._relabel)

    def _clears(self, world: World, model: Any, state: State) -> bool:
        """Whether a planner with the human ``model`` finds a plan that clears the table from ``state``."""
        planner = planner_in(
            self._checkers, model, functools.partial(make_planner, world, self._planner.planner_config)
        )
        return bool(planner.intent(state).success)

    def _unexplained_waits(self, turn: Turn, weights: list[float]) -> bool:
        """Whether robot and partner have both been waiting at this unfinished table longer than the belief explains.

        The run of cycles in which both waited and nothing changed is scored by the
        mixture's probability that the partner waits each time (with the posterior's
        ``epsilon`` slack); below ``STALL_LIKELIHOOD`` the wait is unexplained: an idle
        member makes long waits likely, a busy one makes even two unlikely.
        """
        world, state = turn.world, turn.state
        if self._prev is None or self._prev != (state, self._wait) or world.is_clean(state):
            self._wait_run = 1.0
            return False
        mid = world.step(state, Agent.ROBOT, self._wait).state
        n = len(world.feasible_indices(mid, Agent.HUMAN))
        eps = self.posterior.epsilon
        human_wait = world.n_actions(Agent.HUMAN) - 1
        p = 0.0
        for w, human in zip(weights, self.posterior.humans[: len(weights)], strict=True):
            dist = dict(human.distribution(world, mid, self._wait if human.uses_robot_action else -1))
            p += w * ((1.0 - eps) * dist.get(human_wait, 0.0) + eps / max(n, 1))
        self._wait_run *= p
        return self._wait_run < STALL_LIKELIHOOD

    def act(self, turn: Turn) -> int:
        """Update the belief, then the action with the least expected seconds under it."""
        self._planned = False
        action = self._act(turn)
        if not self._planned:
            self._planner.follow(turn, action)
        return action

    def _act(self, turn: Turn) -> int:
        start = time.perf_counter()
        self._observe(turn)
        world, state = turn.world, turn.state
        post = self.posterior.posterior()
        weights = [post[spec] for spec in self.member_specs]
        if self.progress.observe(state):
            # Nothing changed for K turns (a refused offer repeated, waits answered by waits):
            # whatever the belief says, the move it keeps choosing does not work with this partner.
            action = self.progress.move(world, state)
            partner = self.member_names[int(np.argmax(weights))]
            self.last_decision = Decision("guard", action, reason=self.progress.reason, partner=partner)
            self._prev = (state, action)
            return action
        order = [int(np.argmax(weights))] if self.hedge == "map" else list(range(len(weights)))
        mixed: dict[int, float] = {}
        total = 0.0
        for m in order:
            if weights[m] < NEGLIGIBLE:
                continue  # no say: also keeps 0 * inf (a hopeless action under it) out of the sum
            q = self.q_values(world, state, m)
            if not q or all(math.isinf(v) for v in q.values()):
                continue  # off this member's model (or hopeless there): no say
            w = weights[m]
            total += w
            for a, v in q.items():
                mixed[a] = mixed.get(a, 0.0) + w * v
        best = self.member_names[int(np.argmax(weights))]
        action = min(mixed, key=lambda a: (mixed[a], a)) if mixed else -1
        # The partner explained by no member better than by chance is off the population:
        # a member's best response would be a guess, the planner replans from what it sees.
        # The learned partner must be ``bayes_factor`` times as probable as the best member
        # (the uniform one, fitted to nothing, only more probable).
        factor = self.bayes_factor if self.posterior.learned is not None else 1.0
        off_population = self.unknown > 0 and post[self._unknown_name] > factor * max(weights)
        if off_population:
            self._off_population = True
            unpaid = 0.0  # a solve that gave no move is charged with the planner's decision
            if isinstance(self.posterior.learned, ObservedPartner):
                observed, unpaid = self._observed_action(world, state, weights, start)
                if observed >= 0:
                    return observed
            if isinstance(self.posterior.learned, LearnedPartner):
                # Plan as the partner behaves: without the kinds of action it refuses, unless
                # without them the table cannot be cleared from here and with the fixed model it
                # can (the partner has not yet shown every kind it will do): then as the
                # fixed-model planner plans.
                partnering = self._planner.partnering
                learned, fixed = self.posterior.learned.planner_model(), partnering.fixed
                keep = self._clears(world, partnering.monitor.model(learned), state) or not self._clears(
                    world, partnering.monitor.model(fixed), state
                )
                partnering.base = learned if keep else fixed
            action = self._planner.act(turn)
            self._planned = True
            record = self._planner.last_decision
            assert record is not None
            reason = "no member explains the partner, the planner drives: " + record.reason
            self.last_decision = replace(
                record, reason=reason, partner=self._unknown_name, decision_time=record.decision_time + unpaid
            )
            self._prev = (state, int(action))
            return int(action)
        self._off_population = False
        off_model = total <= 0.0 or not mixed or math.isinf(mixed[action])
        # A wait on an unfinished table at the very state of the previous decision: the
        # partner waited too (no member predicted that, so it is no evidence and the
        # belief cannot move). Waiting again would wait forever: play the fallback.
        stalled = not off_model and action == self._wait and self._unexplained_waits(turn, weights)
        # Once stalled, the planner drives until the partner acts or a task is solved (new
        # evidence): alternating between two experts that disagree would loop.
        human_acted = turn.last_actions[1] >= 0 and turn.last_actions[1] != world.n_actions(Agent.HUMAN) - 1
        if human_acted or turn.reward > 0:
            self._planner_mode = False
        self._planner_mode = self._planner_mode or stalled
        if off_model or self._planner_mode:
            action = self._fallback._fallback(turn)
            record = self._fallback.last_decision
            assert record is not None
            why = "off every member's model: " if off_model else "partner stalled, the planner drives: "
            self.last_decision = replace(record, reason=why + record.reason, partner=best)
        else:
            reason = "the partner refuses offers: its members planned as never taking" if self.refuses_offers() else ""
            if self.probe > 0 and max(weights) < PROBE_BELOW:
                probe, gain = self._probe(world, state, weights, mixed, total)
                if probe != action:
                    cost = (mixed[probe] - mixed[action]) / total
                    reason = f"probe: {gain:.2f} nats about the partner for {cost:.1f} s"
                    action = probe
            self.last_decision = Decision(
                "belief",
                int(action),
                planning_time=time.perf_counter() - start,
                partner=best,
                reason=reason,
                stats=(("expected_seconds", mixed[action] / total), ("belief_top", float(max(weights)))),
            )
        self._prev = (state, int(action))
        return int(action)

    def _observed_action(self, world: World, state: State, weights: list[float], start: float) -> tuple[int, float]:
        """The exact best response to the observed partner at ``state`` (-1: none here), and the
        seconds its solve is charged (with the planner's decision when it gave no move).

        Its model is solved from the table in front of the robot, and again only after the
        partner surprised it at this state (:class:`~hg_marl.agents.observed_partner.ObservedSolver`);
        a solve is charged to the clock as a planner call of one node per state it expands.
        """
        partner = self.posterior.learned
        assert isinstance(partner, ObservedPartner)
        best = int(np.argmax(weights))
        if not partner.seen_at(world, state):
            return -1, 0.0  # the model is only its base here, a member worse than it: the planner drives
        q, expanded, solved = self._observed.q_values(
            world, state, partner, self.members.result(best).n_states, self._relabel
        )
        finite = {a: v for a, v in q.items() if not math.isinf(v)}
        charge = self.cost.planner_cost(expanded) if solved else 0.0
        if not finite:
            return -1, charge  # too large to solve, or no move leads to a success: the planner drives
        action = min(finite, key=lambda a: (finite[a], a))
        self.last_decision = Decision(
            "belief",
            action,
            planning_time=time.perf_counter() - start,
            decision_time=charge,
            partner=self._unknown_name,
            reason="no member explains the partner: the exact best response to its observed answers",
            stats=(("expected_seconds", finite[action]), ("solves", float(self._observed.solves))),
        )
        self._prev = (state, action)
        return action, 0.0

    def members_built(self) -> list[int]:
        """The members whose models have been solved (or read from a cache) so far."""
        return self.members.built()

    def information(self, world: World, state: State, action: int, weights: list[float]) -> float:
        """Mutual information (nats) between the member and the partner's reply to ``action``.

        ``I = H(sum_m b(m) p_m) - sum_m b(m) H(p_m)`` over the partner's feasible replies at
        the mid-cycle state the action leads to, each member's ``p_m`` with the posterior's
        ``epsilon`` slack (the likelihood the belief is updated with): how much, in
        expectation, the next reply will tell the members apart.
        """
        mid, ok, _ = world.table.successor(state, Agent.ROBOT, action)
        replies = world.feasible_indices(mid, Agent.HUMAN)
        n = max(len(replies), 1)
        eps = self.posterior.epsilon
        kept = [(w, h) for w, h in zip(weights, self.posterior.humans[: len(weights)], strict=True) if w >= NEGLIGIBLE]
        total = sum(w for w, _ in kept)
        mix = np.zeros(len(replies))
        inner = 0.0
        for w, human in kept:
            dist = dict(human.distribution(world, mid, action if ok else -1))  # ignored by who does not look
            p = np.array([(1.0 - eps) * dist.get(h, 0.0) + eps / n for h in replies])
            inner += w / total * float(-(p * np.log(p)).sum())
            mix += w / total * p
        outer = float(-(mix * np.log(mix)).sum())
        return max(outer - inner, 0.0)

    def _probe(
        self, world: World, state: State, weights: list[float], mixed: dict[int, float], total: float
    ) -> tuple[int, float]:
        """The most telling action within ``probe`` expected seconds of the best one (and its information).

        A probe must tell at least :data:`MIN_GAIN` nats more than the best action does, so
        a robot never pays for information it would get anyway.
        """
        best = min(mixed, key=lambda a: (mixed[a], a))
        limit = mixed[best] / total + self.probe
        base = self.information(world, state, best, weights)
        choice, gain = best, base
        for a in sorted(mixed):
            if a == best or mixed[a] / total > limit or math.isinf(mixed[a]):
                continue
            info = self.information(world, state, a, weights)
            if info > gain + 1e-12:
                choice, gain = a, info
        return (choice, gain) if gain >= base + MIN_GAIN else (best, base)
