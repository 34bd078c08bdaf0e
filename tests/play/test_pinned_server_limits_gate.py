"""The play server's body reader and replayer, driven directly (no socket, no server).

Each answer is the HTTP rule stated by hand: a body that does not arrive in time is 408,
one over the size limit 413, a client gone before the end 400, and a body in chunks is
their concatenation. The timeout is 0.05 s of a receive that never answers (an asyncio
sleep of an hour), so the test waits 0.05 s whatever the machine's speed.
"""

from __future__ import annotations

import asyncio
from typing import Any

from hg_marl.training.play.server_limits import read_body, replay_body


def _receiver(messages: list[dict[str, Any]]) -> Any:
    queue = list(messages)

    async def receive() -> dict[str, Any]:
        if not queue:
            await asyncio.sleep(3600)  # the client never sends the rest
        return queue.pop(0)

    return receive


def _read(messages: list[dict[str, Any]], max_bytes: int = 10, timeout: float = 0.05) -> Any:
    return asyncio.run(read_body(_receiver(messages), max_bytes, timeout))


def test_a_body_in_chunks_is_their_concatenation() -> None:
    chunks = [
        {"type": "http.request", "body": b"abc", "more_body": True},
        {"type": "http.request", "body": b"", "more_body": True},
        {"type": "http.request", "body": b"defg"},
    ]
    assert _read(chunks) == (b"abcdefg", None)


def test_a_body_exactly_at_the_limit_passes_and_one_byte_more_is_413() -> None:
    assert _read([{"type": "http.request", "body": b"x" * 10}]) == (b"x" * 10, None)
    over = [{"type": "http.request", "body": b"x" * 6, "more_body": True}, {"type": "http.request", "body": b"y" * 5}]
    assert _read(over) == (b"", (413, "body larger than 10 bytes"))


def test_a_body_that_stops_arriving_is_408_after_the_timeout() -> None:
    started = [{"type": "http.request", "body": b"abc", "more_body": True}]
    assert _read(started) == (b"", (408, "request body not received within 0.05 s"))
    assert _read([]) == (b"", (408, "request body not received within 0.05 s"))


def test_a_client_gone_before_the_end_is_400() -> None:
    gone = [{"type": "http.request", "body": b"abc", "more_body": True}, {"type": "http.disconnect"}]
    assert _read(gone) == (b"", (400, "the client went away"))


def test_the_replayed_body_comes_once_then_the_real_receive() -> None:
    async def run() -> list[Any]:
        receive = replay_body(b"read before", _receiver([{"type": "http.disconnect"}]))
        return [await receive(), await receive()]

    first, second = asyncio.run(run())
    assert first == {"type": "http.request", "body": b"read before", "more_body": False}
    assert second == {"type": "http.disconnect"}


class _Timer:
    def __init__(self, delay: float, callback: Any, args: tuple[Any, ...]) -> None:
        self.delay, self.callback, self.args, self.cancelled = delay, callback, args, False

    def cancel(self) -> None:
        self.cancelled = True


class _Loop:
    """The protocol's event loop, reduced to a list of the deadlines it was asked to keep."""

    def __init__(self) -> None:
        self.timers: list[_Timer] = []

    def call_later(self, delay: float, callback: Any, *args: Any) -> _Timer:
        self.timers.append(_Timer(delay, callback, args))
        return self.timers[-1]

    def live(self) -> list[tuple[float, tuple[Any, ...]]]:
        return [(t.delay, t.args) for t in self.timers if not t.cancelled]


class _Transport:
    def __init__(self) -> None:
        self.closed = False

    def get_extra_info(self, name: str, default: Any = None) -> Any:
        return default

    def is_closing(self) -> bool:
        return self.closed

    def close(self) -> None:
        self.closed = True


def _connected(limits: Any) -> tuple[Any, _Loop, _Transport]:
    """A :func:`timed_protocol` connection on a fake loop and transport, just opened."""
    from uvicorn.config import Config
    from uvicorn.server import ServerState

    from hg_marl.training.play.server_limits import timed_protocol

    async def app(scope: Any, receive: Any, send: Any) -> None:  # never reached: no request completes
        raise AssertionError("no request should reach the app")

    loop, transport = _Loop(), _Transport()
    protocol = timed_protocol(limits)(Config(app=app), ServerState(), {}, _loop=loop)
    protocol.connection_made(transport)
    return protocol, loop, transport


def test_a_request_line_begun_arms_the_header_deadline_which_closes_the_connection() -> None:
    from hg_marl.training.play.server_limits import ServerLimits

    protocol, loop, transport = _connected(ServerLimits(idle_timeout=1.0, header_timeout=2.0, body_timeout=3.0))
    assert loop.live() == [(1.0, ())]  # just opened: uvicorn's idle timer, armed by our protocol
    protocol.data_received(b"GET / HTTP/1.1\r\nHost: x\r\nX-Slow: a")  # headers begun, never ended
    assert loop.live() == [(2.0, ("header",))]  # the idle timer gave way to the header deadline
    (timer,) = [t for t in loop.timers if not t.cancelled]
    timer.callback(*timer.args)
    assert transport.closed


def test_a_deadline_of_a_phase_already_left_closes_nothing() -> None:
    from hg_marl.training.play.server_limits import ServerLimits

    protocol, _, transport = _connected(ServerLimits(idle_timeout=1.0, header_timeout=2.0, body_timeout=3.0))
    protocol.data_received(b"GET / HTTP/1.1\r\n")
    protocol._expire("body")  # a stale body deadline: the client is in its headers
    assert not transport.closed
    protocol._expire("header")
    assert transport.closed
