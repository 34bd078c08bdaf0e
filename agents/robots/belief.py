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
  measured better on the bundled hard layouts (BR-Prox IQM on held-out members, 3
  seeds: 0.98 / 0.96 against QMDP's 0.90 / 0.95 on ``forced_coordination`` /
  ``asymmetric_advantages``): the belief settles within a few telling actions, and
  QMDP's mixture, which assumes the uncertainty resolves after one step, keeps paying
  for members the partner has already ruled out in the states where they disagree. ``Q_m`` is the
  oracle's one-step backup of ``V_m`` through member ``m``'s replies
  (``_Model.replies``, the oracle's own transition rule).
- **Off every member's model** (a state no member's dynamics reach), and when it would
  wait again at an unchanged unfinished table after a run of shared waits that the
  belief makes unlikely (< 5%: the partner waits where its members would act, so the
  belief cannot move), it plays the oracle robot's fallback:
  the planner's move, or a feasible non-wait move when the planner would wait as well;
  once stalled, the planner drives until the partner does something or a task is solved.

The members' oracles are solved at the first reset in a world and kept for the
robot's lifetime (a pure cache: the same inputs give the same values).
"""

from __future__ import annotations

import math
import time
from dataclasses import replace

import numpy as np

from hg_marl.agents.oracle import OracleResult, OracleRobot, _human_policy, _Model, oracle_rate
from hg_marl.agents.partner import PartnerPosterior
from hg_marl.agents.planner.space import Relabel
from hg_marl.agents.robots.base import Robot
from hg_marl.core import Agent, State, World
from hg_marl.core.errors import RobotError
from hg_marl.policy import Decision, Turn

HEDGES = ("qmdp", "map")
NEGLIGIBLE = 1e-3
"""Members with less posterior mass than this have no say in the mixture (nor its cost)."""
STALL_LIKELIHOOD = 0.05
"""A run of shared waits less likely than this under the belief means the partner is stalled."""


class BeliefRobot(Robot):
    """Posterior over population members, acting on their exact best responses.

    Args:
        population: a population file (``hg-marl population generate`` writes one).
        splits: the members the robot may believe in, comma-separated splits of the file.
        decay: weight kept by past evidence per telling action (1: never forget).
        epsilon: probability the partner does any feasible action whatever its member.
        hedge: ``"map"`` (most probable member) or ``"qmdp"`` (expected seconds under the mixture).
    """

    name = "belief"

    def __init__(
        self,
        population: str = "",
        splits: str = "train,validation",
        decay: float = 0.9,
        epsilon: float = 0.05,
        hedge: str = "map",
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
        try:
            self.posterior = PartnerPosterior(
                types=self.member_specs, prior=[1.0] * len(members), decay=decay, epsilon=epsilon
            )
        except ValueError as exc:
            raise RobotError(f"belief: {exc}") from None
        self._world: World | None = None
        self._results: list[OracleResult] = []
        self._models: list[_Model] = []
        self._fallback = OracleRobot(result=None)
        self._prev: tuple[State, int] | None = None

    def _reset(self, world: World) -> None:
        """Solve each member's oracle (once per world) and forget the previous run's evidence."""
        if self.agent is not Agent.ROBOT:
            raise RobotError("belief plays the robot seat only")
        if self._world is None or self._world.scenario != world.scenario:
            self._results = [oracle_rate(world, spec) for spec in self.member_specs]
            humans = [_human_policy(spec, world) for spec in self.member_specs]
            self._models = [_Model(world, h, True, 1) for h in humans]
            self._world = world
        self._relabel = Relabel(world)
        self._wait = world.n_actions(Agent.ROBOT) - 1
        self._planner_mode = False
        self._wait_run = 1.0
        self.posterior.reset()
        self._prev = None
        self._fallback.result = self._results[0]
        self._fallback.reset(world, self.agent, self.rng)

    def _observe(self, turn: Turn) -> None:
        """Update the posterior from the human's move since the previous turn."""
        human_action = turn.last_actions[1]
        if self._prev is None or human_action < 0 or turn.reward > 0:
            return  # a solved task re-draws the table: the human's state is not reconstructible
        state, robot_action = self._prev
        step = turn.world.step(state, Agent.ROBOT, robot_action)
        if turn.world.step(step.state, Agent.HUMAN, human_action).state == turn.state:
            self.posterior.observe(turn.world, step.state, robot_action if step.ok else -1, human_action)

    def q_values(self, world: World, state: State, member: int) -> dict[int, float]:
        """Member ``member``'s expected seconds to the next success after each feasible robot action."""
        result, model = self._results[member], self._models[member]
        table = world.table
        wait = table.wait[Agent.ROBOT]
        out: dict[int, float] = {}
        for a in world.feasible_indices(state, Agent.ROBOT):
            mid, ok, duration = table.successor(state, Agent.ROBOT, a)
            if ok and a == wait and table.is_clean(state.where):
                out[a] = 0.0  # the completing wait: the oracle's terminal pair
                continue
            q = 0.0
            for nxt, p, tau in model.replies(mid, duration, a if ok else -1):
                q += p * (tau + result.value_at(world, nxt, self._relabel))
            out[a] = q
        return out

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
        for w, human in zip(weights, self.posterior.humans, strict=True):
            dist = dict(human.distribution(world, mid, self._wait if human.uses_robot_action else -1))
            p += w * ((1.0 - eps) * dist.get(human_wait, 0.0) + eps / max(n, 1))
        self._wait_run *= p
        return self._wait_run < STALL_LIKELIHOOD

    def act(self, turn: Turn) -> int:
        """Update the belief, then the action with the least expected seconds under it."""
        start = time.perf_counter()
        self._observe(turn)
        world, state = turn.world, turn.state
        post = self.posterior.posterior()
        weights = [post[spec] for spec in self.member_specs]
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
            self.last_decision = Decision(
                "belief",
                int(action),
                planning_time=time.perf_counter() - start,
                partner=best,
                stats=(("expected_seconds", mixed[action] / total), ("belief_top", float(max(weights)))),
            )
        self._prev = (state, int(action))
        return int(action)
