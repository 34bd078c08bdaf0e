"""Values that round 157's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np

from hg_marl.agents.meta.coin import RandomCriterion
from hg_marl.agents.planner import Planner
from hg_marl.agents.planner.halfstep import astar
from hg_marl.agents.planner.models import RestrictedHuman, lazy
from hg_marl.agents.robots.partnering import Partnering
from hg_marl.agents.views import RobotView
from hg_marl.core import Agent, Kind, State, World
from hg_marl.training.backends import check_address
from tests.agents.test_pinned_meta_coin_gate import VIEW
from tests.agents.test_pinned_partnering_gate import _Posterior, _turn
from tests.training.test_pinned_round76 import _Scripted, _wait


def test_a_coin_criterion_never_reset_has_its_default_generator_and_no_stats() -> None:
    # Every criterion starts with a generator of its own (default_rng(0), until a run's
    # reset hands it the robot's) and empty stats. A coin with p = 1 plans on any draw
    # u < 1, one with p = 0 on none (u >= 0): both answer before any reset.
    sure, never = RandomCriterion(1.0), RandomCriterion(0.0)
    assert sure.stats == {} and never.stats == {}
    assert sure.wants_plan(VIEW) is True
    assert never.wants_plan(VIEW) is False


class _LazyPosterior(_Posterior):
    """The partnering gate's spy posterior, whose most probable type is the lazy human."""

    def model(self) -> RestrictedHuman:
        return lazy()


def test_a_partner_aware_robots_blocks_restrict_the_posteriors_type_not_the_base_model() -> None:
    # paper2015, partner aware: the base model is the cooperative human, the posterior's most
    # probable type the lazy one (never takes). With a give blocked by the monitor, the planner's
    # model is "the lazy human with the give ruled out": named lazy, still without takes.
    world = World("paper2015")
    partnering = Partnering(world, None, None, partner_aware=True)
    partnering.posterior = _LazyPosterior()
    give = next(a for a in world.actions(Agent.HUMAN) if a.kind is Kind.GIVE)
    partnering.monitor.blocked = frozenset({give})
    assert partnering.observe(_turn(world, (0, 2, 4), (-1, -1)), None) is True
    model = partnering.model
    assert model.name == "lazy"
    assert Kind.TAKE not in model.allowed_kinds and Kind.GIVE in model.allowed_kinds
    assert model.blocked == frozenset({give})


def test_the_half_step_search_says_unreachable_when_the_bound_proves_an_object_out_of_reach() -> None:
    # paper2015, tapes on mat_left, mat_right and human_mat_1, a human who only waits: the robot
    # reaches no human mat, so no method of dispose(tape3) applies, the bound is infinite at the
    # root and the search expands nothing: "unreachable" (not "no plan": nothing was explored).
    world = World("paper2015")
    idle = RestrictedHuman("idle", frozenset({Kind.WAIT}))
    state = State(where=(0, 2, 4), robot_at=1, offer_by=-1, offer_obj=-1)
    out = astar(Planner(world, human_model=idle).space, state, Agent.ROBOT, (0.0, -1), 1000)
    assert out.cycles is None
    assert (out.reason, out.nodes) == ("unreachable", 0)


def test_the_robot_views_info_action_is_the_robots_own_action() -> None:
    # The robot takes its first feasible action that is not its wait; the scripted human waits.
    # info["action"] is the robot's action by its name in the world's table, and the human's is
    # reported apart, under human_action and human_action_name.
    view = RobotView("paper2015", human=_Scripted(False))
    view.reset(seed=0)
    wait_r, wait_h = _wait(view.world, Agent.ROBOT), _wait(view.world, Agent.HUMAN)
    action = int(next(i for i in np.flatnonzero(view.action_masks()) if i != wait_r))
    info = view.step(action)[4]
    robot_names, human_names = view.world.action_names
    assert robot_names[action] != human_names[wait_h]
    assert info["action"] == robot_names[action]
    assert (info["human_action"], info["human_action_name"]) == (wait_h, human_names[wait_h])


def test_a_bracketed_ipv6_host_may_hold_an_embedded_ipv4_address() -> None:
    # HOST may be a bracketed IPv6 address, and an IPv4-mapped one ends in dotted IPv4
    # (::ffff:10.0.0.2): accepted and returned unchanged, as plain [::1] is.
    for address in ("[::ffff:10.0.0.2]:6379", "ray://[::ffff:127.0.0.1]:10001", "[::1]:6379"):
        assert check_address(address) == address
