"""A pygls protocol that answers malformed requests instead of dropping them.

pygls turns the JSON of each message into typed objects as it parses it; when a request's
parameters have the wrong shape, that fails before any handler runs and pygls sends no response,
so the client waits forever. Here such a request gets the JSON-RPC error it deserves
(-32602 invalid params) and the message is then ignored; malformed notifications are just logged.

pygls also keeps the future of every handler it runs in `_request_futures` (the table
`$/cancelRequest` looks requests up in) and removes only those of requests: each notification,
so each keystroke, left one behind for good. Here every future leaves the table when it is done.
"""

from __future__ import annotations

import asyncio
import logging
from typing import Any

from pygls.exceptions import JsonRpcInvalidParams
from pygls.protocol import LanguageServerProtocol

logger = logging.getLogger(__name__)


class _Rejected:
    """Stands in for a message that could not be read; `handle_message` drops it."""

    jsonrpc = "rejected"


class TolerantLanguageServerProtocol(LanguageServerProtocol):
    def structure_message(self, data: dict[str, Any]) -> Any:
        try:
            return super().structure_message(data)
        except Exception as error:
            if not isinstance(data, dict) or "method" not in data:
                raise
            if "id" in data and isinstance(data["id"], (int, str)):
                problem = JsonRpcInvalidParams(message=f"invalid params for {data['method']!r}: {error.__cause__ or error}")
                self._send_response(data["id"], error=problem.to_response_error())
            else:
                logger.warning("ignored a malformed %r notification: %s", data.get("method"), error.__cause__ or error)
            return _Rejected()

    def _execute_handler(self, msg_id: Any, handler: Any, callback: Any, args: Any = None, kwargs: Any = None) -> None:
        super()._execute_handler(msg_id, handler, callback, args, kwargs)
        future = self._request_futures.get(msg_id)
        if future is not None:
            loop = asyncio.get_running_loop()
            future.add_done_callback(lambda done: self._later(loop, msg_id, done))

    def _later(self, loop: asyncio.AbstractEventLoop, msg_id: Any, future: Any) -> None:
        try:
            loop.call_soon_threadsafe(self._forget_future, msg_id, future)
        except RuntimeError:  # the loop is closed: the server is exiting
            pass

    def _forget_future(self, msg_id: Any, future: Any) -> None:
        # Later, on the loop: pygls may be iterating the table when it cancels a future (shutdown).
        if self._request_futures.get(msg_id) is future:
            del self._request_futures[msg_id]

    def handle_message(self, message: Any) -> None:
        if isinstance(message, _Rejected):
            return
        super().handle_message(message)
