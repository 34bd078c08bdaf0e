"""CleanRL-style single-file PPO with action masks on the parallel env (both seats, one shared policy).

The turn-based parallel env is homogenised (one action space, an agent-id feature) and
flattened (``{"observations": float32 facts, "action_mask": int8}``), so robot and human
are two rows of one batch for one parameter-shared actor-critic. Infeasible actions get
logit ``-1e8``; the loop checks every action it sends against the mask it was given
(``outside_mask``, 0 when honoured).

In the parallel view the human's mask is the one at the start of the cycle; a human
action that the robot's move made infeasible fails when executed
(``infeasible_when_executed["human"]``, from ``audit_v0``).

Run: ``python examples/cleanrl_ppo.py --steps 2048``. Needs torch (``hg-marl[sb3]``).
"""

from __future__ import annotations

import argparse
import time
from typing import Any

import numpy as np
import torch
from torch import nn
from torch.distributions import Categorical

import hg_marl
from hg_marl.wrappers import audit_v0, flatten_v0, homogenize_v0, to_parallel


class Agent(nn.Module):
    """Actor and critic MLPs over the homogenised facts (+ agent id)."""

    def __init__(self, n_obs: int, n_actions: int) -> None:
        super().__init__()
        self.critic = nn.Sequential(nn.Linear(n_obs, 64), nn.Tanh(), nn.Linear(64, 1))
        self.actor = nn.Sequential(nn.Linear(n_obs, 64), nn.Tanh(), nn.Linear(64, n_actions))

    def value(self, obs: torch.Tensor) -> torch.Tensor:
        return self.critic(obs).squeeze(-1)

    def act(
        self, obs: torch.Tensor, mask: torch.Tensor, action: torch.Tensor | None = None
    ) -> tuple[torch.Tensor, torch.Tensor, torch.Tensor]:
        logits = self.actor(obs).masked_fill(mask == 0, -1e8)
        dist = Categorical(logits=logits)
        if action is None:
            action = dist.sample()
        return action, dist.log_prob(action), dist.entropy()


def main(steps: int = 2048, seed: int = 0, rollout: int = 128, epochs: int = 2, gamma: float = 0.99) -> dict[str, Any]:
    """Train for ``steps`` agent-steps (two per cycle); return throughput and the mask checks."""
    torch.manual_seed(seed)
    torch.set_num_threads(1)
    audited = audit_v0(hg_marl.env(max_cycles=200))
    env = to_parallel(flatten_v0(homogenize_v0(audited)))
    agents = env.possible_agents
    space = env.observation_space(agents[0])
    n_obs, n_act = space["observations"].shape[0], int(env.action_space(agents[0]).n)
    model = Agent(n_obs, n_act)
    optim = torch.optim.Adam(model.parameters(), lr=2.5e-4)
    obs, _ = env.reset(seed=seed)
    done_steps, outside_mask, episodes, tasks = 0, 0, 0, 0.0
    start = time.perf_counter()
    while done_steps < steps:
        buf: dict[str, list[torch.Tensor]] = {k: [] for k in ("obs", "mask", "act", "logp", "rew", "done", "val")}
        for _ in range(rollout):
            o = torch.as_tensor(np.stack([obs[a]["observations"] for a in agents]))
            m = torch.as_tensor(np.stack([obs[a]["action_mask"] for a in agents]))
            with torch.no_grad():
                action, logp, _ = model.act(o, m)
                value = model.value(o)
            outside_mask += int((m[torch.arange(len(agents)), action] == 0).sum())
            obs, rewards, terms, truncs, _ = env.step({a: int(action[i]) for i, a in enumerate(agents)})
            done = all(terms.values()) or all(truncs.values())
            tasks += rewards[agents[0]]
            for key, val in (("obs", o), ("mask", m), ("act", action), ("logp", logp), ("val", value)):
                buf[key].append(val)
            buf["rew"].append(torch.tensor([rewards[a] for a in agents], dtype=torch.float32))
            buf["done"].append(torch.full((len(agents),), float(done)))
            if done:
                episodes += 1
                obs, _ = env.reset()
            done_steps += len(agents)
        # returns by backward discounting (bootstrapped from the last value), then PPO-clip updates
        with torch.no_grad():
            nxt = model.value(torch.as_tensor(np.stack([obs[a]["observations"] for a in agents])))
        returns = []
        for rew, done_flag in zip(reversed(buf["rew"]), reversed(buf["done"]), strict=True):
            nxt = rew + gamma * nxt * (1.0 - done_flag)
            returns.append(nxt)
        b = {k: torch.cat(v) for k, v in buf.items()}
        b_ret = torch.cat(list(reversed(returns)))
        adv = b_ret - b["val"]
        adv = (adv - adv.mean()) / (adv.std() + 1e-8)
        for _ in range(epochs):
            _, logp, entropy = model.act(b["obs"], b["mask"], b["act"])
            ratio = (logp - b["logp"]).exp()
            pg = -torch.min(ratio * adv, ratio.clamp(0.8, 1.2) * adv).mean()
            loss = pg + 0.5 * (model.value(b["obs"]) - b_ret).pow(2).mean() - 0.01 * entropy.mean()
            optim.zero_grad()
            loss.backward()
            nn.utils.clip_grad_norm_(model.parameters(), 0.5)
            optim.step()
    seconds = time.perf_counter() - start
    return {
        "library": "cleanrl-style",
        "steps": done_steps,
        "steps_per_s": done_steps / seconds,
        "episodes": episodes,
        "outside_mask": outside_mask,
        "sent": dict(audited.sent),
        "infeasible_when_executed": dict(audited.infeasible),
        "tasks_solved": tasks,
    }


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=2048)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    print(main(args.steps, args.seed))
