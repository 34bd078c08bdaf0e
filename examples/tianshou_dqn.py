"""Tianshou masked DQN: the robot learns, a scripted project human plays through a policy adapter.

``PettingZooEnv`` needs identical spaces for all agents: :func:`homogenize_v0` (float32
facts + agent id, one ``Discrete`` padded with masked-out actions). Tianshou reads the
mask from ``obs["action_mask"]`` and its DQN never picks a masked action, greedy or
exploring. The human is ``scripted_v0(..., human="cooperative")`` with
:func:`~hg_marl.agents.adapters.tianshou_fixed_algorithm`: the project's cooperative
human decides, Tianshou carries its action. ``audit_v0`` counts infeasible actions
against the real state (0 for the robot when the mask is honoured).

Run: ``python examples/tianshou_dqn.py --steps 2000``. Needs ``pip install "hg-marl[tianshou]"``.
"""

from __future__ import annotations

import argparse
import time
from typing import Any

import numpy as np
import torch
from tianshou.algorithm import DQN, MultiAgentOffPolicyAlgorithm
from tianshou.algorithm.modelfree.dqn import DiscreteQLearningPolicy
from tianshou.algorithm.optim import AdamOptimizerFactory
from tianshou.data import Collector, CollectStats, VectorReplayBuffer
from tianshou.env import DummyVectorEnv
from tianshou.env.pettingzoo_env import PettingZooEnv
from tianshou.trainer import OffPolicyTrainerParams
from tianshou.utils.net.common import Net

import hg_marl
from hg_marl.agents.adapters import scripted_v0, tianshou_fixed_algorithm
from hg_marl.wrappers import AUDITS, audit_totals, audit_v0, homogenize_v0


def make_env(human: str = "cooperative") -> PettingZooEnv:
    """The robot's seat learns; the human's seat is the named project human."""
    audited = audit_v0(hg_marl.env(max_cycles=100))
    return PettingZooEnv(homogenize_v0(scripted_v0(audited, human=human), dtype=np.float32))


def main(steps: int = 2000, seed: int = 0, human: str = "cooperative") -> dict[str, Any]:
    """Train the robot for about ``steps`` env steps (both seats' turns count)."""
    torch.manual_seed(seed)
    torch.set_num_threads(1)
    AUDITS.clear()
    train_envs = DummyVectorEnv([lambda: make_env(human)])
    test_envs = DummyVectorEnv([lambda: make_env(human)])
    train_envs.seed(seed)
    test_envs.seed(seed + 1)
    probe = make_env(human)
    obs_shape = probe.observation_space["observation"].shape
    net = Net(state_shape=obs_shape, action_shape=int(probe.action_space.n), hidden_sizes=[64, 64])
    robot = DQN(
        policy=DiscreteQLearningPolicy(model=net, action_space=probe.action_space, eps_training=0.2, eps_inference=0.0),
        optim=AdamOptimizerFactory(lr=1e-3),
        gamma=0.95,
        target_update_freq=100,
    )
    algorithm = MultiAgentOffPolicyAlgorithm(
        algorithms=[robot, tianshou_fixed_algorithm(probe.action_space)], env=probe
    )
    train = Collector[CollectStats](algorithm, train_envs, VectorReplayBuffer(5000, 1), exploration_noise=True)
    test = Collector[CollectStats](algorithm, test_envs, exploration_noise=False)
    train.reset()
    start = time.perf_counter()
    algorithm.run_training(
        OffPolicyTrainerParams(
            training_collector=train,
            test_collector=test,
            max_epochs=1,
            epoch_num_steps=steps,
            collection_step_num_env_steps=10,
            test_step_num_episodes=1,
            batch_size=32,
            update_step_num_gradient_steps_per_sample=0.1,
            test_in_training=False,
            show_progress=False,
            verbose=False,
            multi_agent_return_reduction=lambda rews: rews[:, 0],
        )
    )
    seconds = time.perf_counter() - start
    sent, infeasible = audit_totals()
    return {
        "library": "tianshou",
        "steps": sent["robot"] + sent["human"],
        "steps_per_s": (sent["robot"] + sent["human"]) / seconds,
        "sent": sent,
        "infeasible": infeasible,
    }


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=2000)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    print(main(args.steps, args.seed))
