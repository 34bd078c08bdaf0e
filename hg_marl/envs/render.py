"""Pictures of the table: text (``ansi``), an image (``rgb_array``) and the shared layout.

:func:`layout` places everything once (the human's side at the top, the table with its
spots and bins in the middle, the robot's locations along the bottom, a caption band),
so the image here and the web page's SVG (``hg_marl.training.play.svg``) draw the same
table. In the image, spot colours tell who reaches them (blue: the robot only, red: the
human only, purple: both, grey: nobody); bins are dark; the robot is the square at its
location, the human the disc; an object is a small square in its colour (orange when
uncoloured) on its spot, in its bin or beside the hand that holds it; a pending offer
is drawn between the two agents. Labels (object, spot, bin and location names, agent
roles, the last actions and the clock) are written with Pillow, imported only when an
image is drawn, so ``import hg_marl`` stays light. Rendering never opens a window.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from hg_marl.core import Agent, State, World
from hg_marl.core.scenario import Bin, Spot

CELL = 96
"""Width of one spot or bin column, in pixels."""

PALETTE = {
    "": (240, 150, 30),
    "green": (40, 170, 60),
    "blue": (40, 90, 220),
    "red": (210, 40, 40),
    "yellow": (230, 210, 40),
}
"""Object colours by the scenario's colour name (grey for unknown names)."""

HUMAN_MESSAGE = (
    "render_mode='human' would open a window, which TableCleaning-v0 never does; "
    "watch a run with `hg-marl run ... --video out.gif` or `hg-marl replay TRACE --video out.gif`, "
    "play the human with `hg-marl play`, or use render_mode='rgb_array'"
)
"""The one-line answer to ``render_mode="human"``."""


@dataclass(frozen=True)
class Box:
    """An axis-aligned rectangle in pixels."""

    x: int
    y: int
    w: int
    h: int

    @property
    def centre(self) -> tuple[int, int]:
        """Its centre point."""
        return self.x + self.w // 2, self.y + self.h // 2


@dataclass(frozen=True)
class Layout:
    """Where everything of a scenario is drawn (pixels, origin top-left)."""

    width: int
    height: int
    table: Box
    """The table top."""
    spots: tuple[Box, ...]
    """One box per spot, in scenario order."""
    bins: tuple[Box, ...]
    """One box per bin."""
    locations: tuple[tuple[int, int], ...]
    """The robot's locations (where its square stands)."""
    human: tuple[int, int]
    """The human's position (disc centre)."""
    caption_y: int
    """Top of the caption band."""

    def places(self) -> tuple[Box, ...]:
        """Spot boxes then bin boxes: indexed like ``State.where`` codes below the hands."""
        return self.spots + self.bins

    def objects(self, world: World, state: State) -> list[tuple[int, int]]:
        """The centre of each object's square (stacked when several share a place)."""
        robot = self.locations[state.robot_at]
        hands = {
            world.hand[Agent.ROBOT]: (robot[0] + 34, robot[1] - 24),
            world.hand[Agent.HUMAN]: (self.human[0] + 40, self.human[1]),
        }
        places = self.places()
        seen: dict[int, int] = {}
        out = []
        for p in state.where:
            k = seen.get(p, 0)
            seen[p] = k + 1
            if p in hands:
                x, y = hands[p]
                out.append((x + 18 * k, y))
            else:
                box = places[p] if p < len(places) else Box(0, 0, 0, 0)
                out.append((box.x + 16 + (k % 3) * 22, box.y + box.h - 16 - (k // 3) * 22))
        return out

    def offer(self, state: State) -> tuple[int, int]:
        """Where a pending offer is drawn: between the robot and the human."""
        robot = self.locations[state.robot_at]
        return (robot[0] + self.human[0]) // 2 + 40, self.table.y + self.table.h + 14


@lru_cache(maxsize=32)
def layout(world: World) -> Layout:
    """The layout of ``world``'s scenario (cached: it depends on the scenario only)."""
    sc = world.scenario
    columns = max(world.n_spots + world.n_bins, len(sc.robot_locations))
    width = columns * CELL + CELL
    table = Box(CELL // 4, 88, width - CELL // 2, 150)
    spots = tuple(Box(CELL // 2 + i * CELL + 4, 118, CELL - 8, 96) for i in range(world.n_spots))
    bins = tuple(Box(CELL // 2 + (world.n_spots + b) * CELL + 4, 110, CELL - 8, 112) for b in range(world.n_bins))
    locations = tuple((x, 280) for x in _location_xs(world, spots + bins, width))
    return Layout(width, 384, table, spots, bins, locations, (width // 2, 44), 340)


def _location_xs(world: World, places: tuple[Box, ...], width: int) -> list[int]:
    """Each robot location under what it reaches: the mean centre of the spots and bins
    reachable from it (a location reaching nothing goes to a free slot), then pushed
    apart so that neighbouring labels never overlap."""
    sc = world.scenario
    items: tuple[Spot | Bin, ...] = (*sc.spots, *sc.bins)
    n = len(sc.robot_locations)
    xs: list[float | None] = []
    for k in range(n):
        centres = [box.centre[0] for item, box in zip(items, places, strict=True) if k in item.reach.robot_from]
        xs.append(sum(centres) / len(centres) if centres else None)
    step = (width - CELL // 2) / max(n, 1)
    out = [x if x is not None else CELL // 4 + step * (i + 0.5) for i, x in enumerate(xs)]
    gap, low, high = 0.8 * CELL, CELL / 2, width - CELL / 2
    order = sorted(range(n), key=lambda i: (out[i], i))
    for left, right in itertools.pairwise(order):
        out[right] = max(out[right], out[left] + gap)
    if order:  # pushed off the table's end: push back from the right
        out[order[-1]] = min(out[order[-1]], high)
        for left, right in itertools.pairwise(reversed(order)):
            out[right] = min(out[right], out[left] - gap)
    return [round(min(max(x, low), high)) for x in out]


def reach_tint(item: Spot | Bin) -> tuple[int, int, int]:
    """A spot's colour by who reaches it (see the module docstring)."""
    robot, human = bool(item.reach.robot_from), item.reach.human
    if robot and human:
        return (150, 100, 200)
    if robot:
        return (120, 150, 230)
    return (230, 130, 130) if human else (160, 160, 160)


def object_colour(world: World, o: int) -> tuple[int, int, int]:
    """An object's drawing colour."""
    return PALETTE.get(world.scenario.object_colours[o], (120, 120, 120))


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


def render_rgb(world: World, state: State, caption: str = "") -> np.ndarray:
    """An ``(H, W, 3)`` uint8 labelled image of the table, with ``caption`` at the bottom."""
    from PIL import Image, ImageDraw

    sc = world.scenario
    lay = layout(world)
    img = Image.new("RGB", (lay.width, lay.height), (250, 250, 250))
    draw = ImageDraw.Draw(img)
    t = lay.table
    draw.rectangle((t.x, t.y, t.x + t.w, t.y + t.h), fill=(200, 170, 120))
    for spot, box in zip(sc.spots, lay.spots, strict=True):
        draw.rectangle((box.x, box.y, box.x + box.w, box.y + box.h), fill=reach_tint(spot))
        draw.text((box.x + 3, box.y + 3), spot.name, fill=(20, 20, 20))
    for b, box in zip(sc.bins, lay.bins, strict=True):
        draw.rectangle((box.x, box.y, box.x + box.w, box.y + box.h), fill=(60, 60, 60))
        draw.text((box.x + 3, box.y + 3), b.name, fill=(240, 240, 240))
    for name, (x, y) in zip(sc.robot_locations, lay.locations, strict=True):
        draw.ellipse((x - 5, y + 30, x + 5, y + 40), fill=(90, 90, 90))
        draw.text((x - 3 * len(name), y + 42), name, fill=(60, 60, 60))
    rx, ry = lay.locations[state.robot_at]
    draw.rectangle((rx - 22, ry - 22, rx + 22, ry + 22), fill=(70, 110, 160))
    draw.text((rx - 15, ry - 6), "robot", fill=(255, 255, 255))
    hx, hy = lay.human
    draw.ellipse((hx - 26, hy - 26, hx + 26, hy + 26), fill=(230, 180, 150))
    draw.text((hx - 15, hy - 6), "human", fill=(20, 20, 20))
    for o, (x, y) in enumerate(lay.objects(world, state)):
        draw.rectangle((x - 9, y - 9, x + 9, y + 9), fill=object_colour(world, o), outline=(0, 0, 0))
        draw.text((x - 9, y + 10), sc.objects[o], fill=(0, 0, 0), stroke_width=2, stroke_fill=(255, 255, 255))
    if state.offer_by >= 0:
        x, y = lay.offer(state)
        draw.rectangle((x - 7, y - 7, x + 7, y + 7), fill=object_colour(world, state.offer_obj), outline=(0, 0, 0))
        by = Agent(state.offer_by).label
        draw.text((x + 12, y - 6), f"{by} offers {sc.objects[state.offer_obj]}", fill=(0, 0, 0))
    if caption:
        draw.text((8, lay.caption_y + 8), caption, fill=(0, 0, 0))
    return np.asarray(img, dtype=np.uint8).copy()


def caption_of(world: World, clock: float, tasks: int, last_actions: tuple[int, int]) -> str:
    """The image caption: the clock, tasks solved and each agent's last action."""
    names = [world.action_names[a][i] if i >= 0 else "-" for a, i in zip(Agent, last_actions, strict=True)]
    return f"t={clock:.1f}s  tasks={tasks}   robot: {names[0]}   human: {names[1]}"
