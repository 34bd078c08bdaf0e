"""Pictures of the table: a text one (``ansi``) and an image (``rgb_array``).

Drawn with numpy only (no window, no font, no pygame), so rendering never opens a
window and costs little. In the image the human's side is at the top, the robot's
locations along the bottom; spot colours tell who reaches them (blue: the robot only,
red: the human only, purple: both, grey: nobody); bins are dark; the robot is the
large square standing at its location, the human the large disc; an object is a small
square in its colour (orange when uncoloured) on its spot, in its bin or beside the
hand that holds it; a pending offer is drawn between the two agents.
"""

from __future__ import annotations

import numpy as np

from hg_marl.core import Agent, State, World
from hg_marl.core.scenario import Bin, Spot

_CELL = 48
_PALETTE = {
    "": (240, 150, 30),
    "green": (40, 170, 60),
    "blue": (40, 90, 220),
    "red": (210, 40, 40),
    "yellow": (230, 210, 40),
}


def render_ansi(world: World, state: State, clock: float, cycle: int, tasks: int) -> str:
    """A text picture of the table."""
    sc = world.scenario
    lines = [f"TableCleaning-v0 [{sc.name}]  t={clock:.1f}s  cycle={cycle}  tasks={tasks}"]
    for agent in Agent:
        held = world.holding(state, agent)
        where = f" at {sc.robot_locations[state.robot_at]}" if agent is Agent.ROBOT else ""
        offer = " (offering)" if state.offer_by == agent else ""
        lines.append(f"  {agent.label}{where} holding {sc.objects[held] if held >= 0 else '-'}{offer}")
    on: dict[int, list[str]] = {}
    for o, p in enumerate(state.where):
        on.setdefault(p, []).append(sc.objects[o])
    places: list[tuple[str, Spot | Bin, int]] = [("spot", s, i) for i, s in enumerate(sc.spots)]
    places += [("bin", b, world.n_spots + i) for i, b in enumerate(sc.bins)]
    for kind, item, code in places:
        reach = [sc.robot_locations[k] for k in sorted(item.reach.robot_from)]
        if item.reach.human:
            reach.append("human")
        here = " ".join(on.get(code, [])) or "."
        lines.append(f"  {kind} {item.name:<14} reach={','.join(reach) or 'nobody':<32} {here}")
    return "\n".join(lines)


def _box(img: np.ndarray, x: int, y: int, w: int, h: int, colour: tuple[int, int, int]) -> None:
    img[max(y, 0) : y + h, max(x, 0) : x + w] = colour


def _disc(img: np.ndarray, cx: int, cy: int, r: int, colour: tuple[int, int, int]) -> None:
    yy, xx = np.ogrid[: img.shape[0], : img.shape[1]]
    img[(yy - cy) ** 2 + (xx - cx) ** 2 <= r * r] = colour


def render_rgb(world: World, state: State) -> np.ndarray:
    """An ``(H, W, 3)`` uint8 image of the table."""
    sc = world.scenario
    columns = max(world.n_spots + world.n_bins, len(sc.robot_locations)) + 1
    width, height = columns * _CELL, 5 * _CELL
    img = np.full((height, width, 3), 250, dtype=np.uint8)
    _box(img, _CELL // 4, _CELL, width - _CELL // 2, 2 * _CELL, (200, 170, 120))  # the table
    colour = [_PALETTE.get(c, (120, 120, 120)) for c in sc.object_colours]
    slots: list[tuple[int, int]] = []
    for i, spot in enumerate(sc.spots):
        robot, human = bool(spot.reach.robot_from), spot.reach.human
        tint = (
            (150, 100, 200)
            if robot and human
            else (120, 150, 230)
            if robot
            else (230, 130, 130)
            if human
            else (160, 160, 160)
        )
        x = _CELL // 2 + i * _CELL
        _box(img, x + 4, int(1.5 * _CELL), _CELL - 8, _CELL - 8, tint)
        slots.append((x + _CELL // 2, 2 * _CELL - 4))
    for b in range(world.n_bins):
        x = _CELL // 2 + (world.n_spots + b) * _CELL
        _box(img, x + 4, int(1.4 * _CELL), _CELL - 8, _CELL, (60, 60, 60))
        slots.append((x + _CELL // 2, 2 * _CELL))
    loc_x = [
        _CELL // 2 + i * (width - _CELL) // max(len(sc.robot_locations), 1) + _CELL // 2
        for i in range(len(sc.robot_locations))
    ]
    for x in loc_x:
        _disc(img, x, 4 * _CELL, 5, (90, 90, 90))
    robot_x, human_x = loc_x[state.robot_at], width // 2
    _box(img, robot_x - 16, int(3.6 * _CELL), 32, 32, (70, 110, 160))
    _disc(img, human_x, _CELL // 2, 18, (230, 180, 150))
    hands = {
        world.hand[Agent.ROBOT]: (robot_x + 22, int(3.6 * _CELL)),
        world.hand[Agent.HUMAN]: (human_x + 22, _CELL // 2 - 8),
    }
    for o, p in enumerate(state.where):
        cx, cy = hands.get(p, slots[p] if p < len(slots) else (0, 0))
        if world.is_in_bin(p):
            cx += (o % 3 - 1) * 10
        _box(img, cx - 7, cy - 7, 14, 14, colour[o])
    if state.offer_by >= 0:
        _box(img, (robot_x + human_x) // 2 - 5, int(2.6 * _CELL), 10, 10, colour[state.offer_obj])
    return img
