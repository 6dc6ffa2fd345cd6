"""ROS message types of values, the kinds of their geometric fields, and the quaternion fields whose
component order a message type fixes.

A value's message class is known when every binding says it: a constructor call (`VehicleOdometry()`),
a parameter annotated with the class, the message parameter of a subscription callback registered
for the class in the same module (`create_subscription(VehicleOdometry, topic, self.on_odometry, qos)`),
or a `self` attribute every store of which is one of those (or None). Classes are qualified names
resolved through the module's imports, so `q` alone, or an unimported `VehicleOdometry`, is no evidence.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Final, TYPE_CHECKING

import ast
from ast import Attribute, Call, ClassDef, Constant, Name

from geolint.algebra import Kind
from geolint.factbase.index import FUNCTION_NODES, ParamBinding
from geolint.factbase.memo import NodeMemo
from geolint.factbase.syntax import keyword, last_name, positional_args
from geolint.knowledge import SCALAR_LAST, Geometry, knowledge_base

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase

_MAX_DEPTH: Final = 8


def _fields(cls: str | None) -> dict[str, Geometry]:
    return knowledge_base().record_fields(cls) if cls else {}


def quaternion_field_names() -> frozenset[str]:
    """The record fields that hold a quaternion of known order (px4_msgs `VehicleOdometry.q`): the one cheap
    test by attribute name before any type is looked for."""
    return knowledge_base().record_field_names("quaternion_order")


@lru_cache(maxsize=1)
def quaternion_record_modules() -> tuple[str, ...]:
    """The modules of the record classes that have such a field (`px4_msgs.msg`)."""
    base = knowledge_base()
    return tuple(sorted({cls.rpartition(".")[0] for cls in base.record_classes() if any(g.quaternion_order for g in base.record_fields(cls).values())}))


def vector_field_names() -> frozenset[str]:
    """The record fields that hold a 3-vector of known kind (`Twist.linear`): the cheap test before a
    message class is looked for."""
    return knowledge_base().record_field_names("kind")


def field_order(cls: str | None, field: str) -> str | None:
    """The component order of quaternion field `field` of message class `cls`, or None."""
    geometry = _fields(cls).get(field)
    return geometry.quaternion_order if geometry is not None else None


def short_name(cls: str) -> str:
    return cls.rsplit(".", 1)[-1]


def field_label(cls: str, field: str) -> str:
    """How a finding names a message field: "px4_msgs `VehicleOdometry.q`"."""
    return f"{cls.split('.', 1)[0]} `{short_name(cls)}.{field}`"


def holds_quaternion_components(cls: str | None) -> bool:
    """Whether `cls` is a record of a quaternion's four components, x, y, z and w, each a field of its own
    (geometry_msgs' Quaternion): what is built empty and filled in component by component."""
    api = knowledge_base().api(cls) if cls else None
    return api is not None and api.is_class and any(signature.components == SCALAR_LAST for signature in api.signatures)


class MessageTypes:
    """The message class of values in one module (memoised per node)."""

    def __init__(self, facts: FactBase) -> None:
        self.facts = facts
        self._classes: NodeMemo[str] = NodeMemo(_MAX_DEPTH)
        self._callbacks: dict[str, set[str | None]] | None = None

    def class_of(self, node: ast.expr) -> str | None:
        """The qualified message class of `node`'s value, when every binding agrees on a known one."""
        return self._classes.get(id(node), lambda: self._class(node))

    def field_kind(self, node: Attribute) -> Kind | None:
        """The kind of a message field's 3-vector (`msg.twist.twist.linear` of an Odometry: a free vector)."""
        geometry = _fields(self.class_of(node.value)).get(node.attr)
        return geometry.kind if geometry is not None else None

    def _class(self, node: ast.expr) -> str | None:
        facts = self.facts
        if isinstance(node, Call):
            qualified = facts.qualified_name(node.func)
            return qualified if _fields(qualified) and not node.args else None
        if isinstance(node, Name):
            bound = facts.bindings(node) or []
            return _agreed([self._class_of_binding(binding) for binding in bound])
        if isinstance(node, Attribute) and isinstance(node.value, Name) and node.value.id == "self":
            stores = facts.index.self_attribute_stores.get(node.attr, [])
            # `self.odometry = None` before the first message, or the subscription handle stored under
            # the same name: reading `.q` from either would fail, so where `.q` is read it is the message
            return _agreed([self.class_of(store) for store in stores if not _has_no_fields(store)])
        if isinstance(node, Attribute):  # `msg.twist.twist`: the field's own message class
            geometry = _fields(self.class_of(node.value)).get(node.attr)
            return geometry.type_name if geometry is not None else None
        return None

    def _class_of_binding(self, binding: object) -> str | None:
        if isinstance(binding, ast.expr):
            return self.class_of(binding)
        if not isinstance(binding, ParamBinding):
            return None
        annotation = binding.arg.annotation
        if annotation is not None:
            qualified = self.facts.qualified_name(annotation)
            return qualified if _fields(qualified) else None
        return self._callback_class(binding)

    def _callback_class(self, binding: ParamBinding) -> str | None:
        """The class a subscription delivers to this parameter: it is the message parameter of a
        function the module registers as a callback, and the function is never called directly."""
        function = binding.function
        if not isinstance(function, FUNCTION_NODES):
            return None
        parameters = [*function.args.posonlyargs, *function.args.args]
        is_method = isinstance(self.facts.parent(function), ClassDef)
        if len(parameters) != 1 + is_method or parameters[is_method] is not binding.arg:
            return None
        return _agreed(list(self._registrations().get(function.name, ())))

    def _registrations(self) -> dict[str, set[str | None]]:
        """Function name -> the message classes it is registered for (None: unknown class, or called
        directly somewhere, so its parameter may hold anything)."""
        if self._callbacks is not None:
            return self._callbacks
        facts = self.facts
        found: dict[str, set[str | None]] = {}
        called: set[str] = set()
        for call in facts.index.nodes(Call):
            func = call.func  # type: ignore[attr-defined]
            called.add(last_name(func) or "")
            registered = _subscription(call)  # type: ignore[arg-type]
            name = _function_name(registered[1]) if registered is not None else None
            if registered is not None and name is not None:
                qualified = facts.qualified_name(registered[0])
                found.setdefault(name, set()).add(qualified if _fields(qualified) else None)
        for name in found.keys() & called:
            found[name].add(None)  # also called directly: its parameter may hold anything
        self._callbacks = found
        return found


def _subscription(call: Call) -> tuple[ast.expr, ast.expr] | None:
    """`node.create_subscription(MsgType, topic, callback, qos)` (rclpy) or
    `rospy.Subscriber(topic, MsgType, callback)`: (message type, callback)."""
    func = call.func
    name = last_name(func)
    positional = positional_args(call)
    if name == "create_subscription":
        message_type, callback = _argument(call, positional, 0, "msg_type"), _argument(call, positional, 2, "callback")
    elif name == "Subscriber":
        message_type, callback = _argument(call, positional, 1, "data_class"), _argument(call, positional, 2, "callback")
    else:
        return None
    return (message_type, callback) if message_type is not None and callback is not None else None


def _argument(call: Call, positional: list[ast.expr], position: int, name: str) -> ast.expr | None:
    if len(positional) > position:
        return positional[position]
    given = keyword(call, name)
    return given.value if given is not None else None


def _function_name(callback: ast.expr) -> str | None:
    """`self.on_odometry` or `on_odometry` (a lambda or a partial is not followed)."""
    if isinstance(callback, Attribute) and isinstance(callback.value, Name) and callback.value.id == "self":
        return callback.attr
    return callback.id if isinstance(callback, Name) else None


def _agreed(classes: list[str | None]) -> str | None:
    found = set(classes)
    return found.pop() if len(found) == 1 and None not in found else None


def _has_no_fields(node: ast.expr) -> bool:
    """None, or an rclpy handle (`self.create_subscription(...)`): values with no message field."""
    if isinstance(node, Constant):
        return node.value is None
    return isinstance(node, Call) and isinstance(node.func, Attribute) and node.func.attr in _NODE_HANDLES


_NODE_HANDLES: Final = frozenset({"create_subscription", "create_publisher", "create_timer", "create_client", "create_service"})
