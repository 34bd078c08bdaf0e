"""Time and connection limits of the play server, so no client can hold it open for ever.

uvicorn closes a keep-alive connection left idle after a response, but a connection that
never sends a byte, or sends its request line and headers a byte at a time, stays open
as long as the client likes (the slowloris attack), and so does a request whose body
trickles in. Each such connection holds a file descriptor and, under a concurrency
limit, a slot that a real player then cannot get. The limits here, all in
:class:`ServerLimits`:

- **idle**: a connection with no request under way (just opened, or after a response)
  is closed after :attr:`ServerLimits.idle_timeout` seconds without a byte;
- **headers**: once the first byte of a request arrives, its request line and headers
  must be complete within :attr:`ServerLimits.header_timeout` seconds, however slowly
  they trickle;
- **body**: once the headers are in, the body must be complete within
  :attr:`ServerLimits.body_timeout` seconds: the connection is closed, and the app (which
  reads bodies with :func:`read_body`) answers 408 if it was still waiting;
- **connections**: at most :attr:`ServerLimits.max_connections` open at once (one more is
  closed as soon as it is accepted; uvicorn answers 503 to requests beyond the same count);
- **head size**: a request line and headers of at most :attr:`ServerLimits.max_header_bytes`.
  h11 holds an unfinished head to that size (uvicorn answers 400 beyond it), but a head
  that arrives whole in one read is parsed whatever its size, so the app refuses such a
  request too (431), measured by :func:`head_bytes`.

The timers live in :func:`timed_protocol`, a subclass of uvicorn's h11 protocol (the
one layer that sees bytes arrive). Tests pass short limits; docs/inputs.md states the
defaults.
"""

from __future__ import annotations

import asyncio
from dataclasses import dataclass
from typing import Any

import h11
from starlette.types import Message, Receive, Scope
from uvicorn.protocols.http.h11_impl import H11Protocol

from hg_marl.core.errors import ConfigError, check_finite, check_int


@dataclass(frozen=True)
class ServerLimits:
    """How long a client may take, and how many may be connected (module docstring)."""

    idle_timeout: float = 30.0
    """Seconds a connection may stay open without a request under way (a page's keep-alive)."""
    header_timeout: float = 10.0
    """Seconds from a request's first byte to the end of its headers."""
    body_timeout: float = 10.0
    """Seconds from the end of a request's headers to the end of its body."""
    max_connections: int = 32
    """Connections open at once (one player's browser opens a handful)."""
    max_header_bytes: int = 16_384
    """Largest request line plus headers, in bytes."""

    def __post_init__(self) -> None:
        for name in ("idle_timeout", "header_timeout", "body_timeout"):
            check_finite(getattr(self, name), name, positive=True, maximum=3600.0, error=ConfigError)
        check_int(self.max_connections, "max_connections", minimum=1, maximum=10_000)
        check_int(self.max_header_bytes, "max_header_bytes", minimum=1024, maximum=1 << 20)

    def uvicorn_options(self) -> dict[str, Any]:
        """The ``uvicorn.Config`` arguments that carry these limits."""
        return {
            "http": timed_protocol(self),
            # uvicorn counts the asking connection too: at the cap, each open one is still served
            "limit_concurrency": self.max_connections + 1,
            "h11_max_incomplete_event_size": self.max_header_bytes,
        }


def timed_protocol(limits: ServerLimits) -> type[H11Protocol]:
    """uvicorn's h11 protocol with the idle, header and body deadlines and the connection cap of ``limits``."""

    class TimedH11Protocol(H11Protocol):
        """Arms one deadline for whatever the client owes next (idle, headers or body)."""

        def __init__(self, *args: Any, **kwargs: Any) -> None:
            super().__init__(*args, **kwargs)
            self.timeout_keep_alive = limits.idle_timeout  # type: ignore[assignment]  # uvicorn's idle timer
            self._phase: str | None = None
            self._timer: asyncio.TimerHandle | None = None

        def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]
            super().connection_made(transport)
            if len(self.connections) > limits.max_connections:
                transport.close()
                return
            # uvicorn arms its idle timer only after a response: a silent new connection needs one too
            self.timeout_keep_alive_task = self.loop.call_later(limits.idle_timeout, self.timeout_keep_alive_handler)

        def connection_lost(self, exc: Exception | None) -> None:
            self._arm(None)
            super().connection_lost(exc)

        def data_received(self, data: bytes) -> None:
            super().data_received(data)
            self._rearm()

        def on_response_complete(self) -> None:
            super().on_response_complete()
            self._rearm()

        def _rearm(self) -> None:
            """Start the deadline of the phase the client is in, if it changed."""
            if self.transport.is_closing():
                self._arm(None)
                return
            state = self.conn.their_state
            if state is h11.IDLE and self.conn.trailing_data[0]:
                self._arm("header")  # part of a request line or headers, not the whole
            elif state is h11.SEND_BODY:
                self._arm("body")
            else:
                self._arm(None)  # idle (uvicorn's timer) or the app is answering

        def _arm(self, phase: str | None) -> None:
            if phase == self._phase:
                return
            if self._timer is not None:
                self._timer.cancel()
            self._phase, self._timer = phase, None
            if phase is not None:
                delay = limits.header_timeout if phase == "header" else limits.body_timeout
                self._timer = self.loop.call_later(delay, self._expire, phase)

        def _expire(self, phase: str) -> None:
            if self._phase == phase and not self.transport.is_closing():
                self.transport.close()

    return TimedH11Protocol


def head_bytes(scope: Scope) -> int:
    """Bytes of an HTTP/1.1 request's line and headers as sent (``GET /p?q HTTP/1.1``, CRLFs included)."""
    query = scope.get("query_string", b"")
    line = len(scope["method"]) + 1 + len(scope.get("raw_path") or scope["path"].encode()) + len(" HTTP/1.1\r\n")
    line += 1 + len(query) if query else 0
    return line + sum(len(name) + 2 + len(value) + 2 for name, value in scope["headers"]) + 2


async def read_body(receive: Receive, max_bytes: int, timeout: float) -> tuple[bytes, tuple[int, str] | None]:
    """A request's body: stops at ``max_bytes`` (413) or after ``timeout`` seconds (408)."""
    chunks: list[bytes] = []
    size = 0

    async def read() -> tuple[bytes, tuple[int, str] | None]:
        nonlocal size
        while True:
            message = await receive()
            if message["type"] != "http.request":
                return b"", (400, "the client went away")
            chunk = message.get("body", b"")
            size += len(chunk)
            if size > max_bytes:
                return b"", (413, f"body larger than {max_bytes} bytes")
            chunks.append(chunk)
            if not message.get("more_body", False):
                return b"".join(chunks), None

    try:
        return await asyncio.wait_for(read(), timeout)
    except TimeoutError:
        return b"", (408, f"request body not received within {timeout:g} s")


def replay_body(body: bytes, receive: Receive) -> Receive:
    """A ``receive`` that hands the already read body over once, then defers to ``receive``."""
    sent = False

    async def replayed() -> Message:
        nonlocal sent
        if sent:
            return await receive()
        sent = True
        return {"type": "http.request", "body": body, "more_body": False}

    return replayed
