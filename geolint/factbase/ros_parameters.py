"""The ROS parameters a project sets outside its nodes: in parameter files (YAML, ROS 1 and ROS 2), in
launch files (`<param name=...>`, `<rosparam>`, a Python launch action's `parameters=[{...}]`).

A node's declared default (`declare_parameter("odom_frame", "odom")`) is what runs only when none of
these sets the parameter, so the tf-tree rules read a default as a frame only then
(`tf_statements.settled`). Parameters are matched by the last part of their name
(`parameter_key`): a namespace, a node name or a YAML nesting may sit on either side,
and a wrong match only makes a default unknown.
"""

from __future__ import annotations

import ast
import re
from ast import Call, Constant, Dict
from typing import Final, Iterable

import yaml

PARAMETER_FILE_SUFFIXES: Final = (".yaml", ".yml")
_MAX_PARAMETER_FILE_BYTES: Final = 1_000_000
_MAX_KEYS: Final = 100_000
_LAUNCH_WORDS: Final = (b"LaunchDescription", b"launch_ros")
_LAUNCH_FILE: Final = re.compile(r"[._]launch\.py$")  # `bringup.launch.py`, `bringup_launch.py`

try:  # libyaml's parser when PyYAML was built with it (most wheels), else the pure-Python one
    _Loader: type = yaml.CSafeLoader
except AttributeError:  # pragma: no cover
    _Loader = yaml.SafeLoader


def parameter_key(name: str) -> str:
    """The last part of a ROS parameter's name (`~frame_id`, `/robot/frame_id`, `frames.odom`), which is
    how launch files, parameter files and nodes are matched."""
    return re.split(r"[/.~]", name.strip())[-1]


def yaml_keys(text: str) -> frozenset[str]:
    """Every mapping key of a YAML text (all its documents), as parameter keys; empty when it is not
    YAML or too large to be a parameter file."""
    if len(text) > _MAX_PARAMETER_FILE_BYTES:
        return frozenset()
    try:
        documents = list(yaml.load_all(text, Loader=_Loader))
    except (yaml.YAMLError, ValueError, RecursionError):
        return frozenset()
    return frozenset(_keys(documents))


def _keys(documents: Iterable[object]) -> Iterable[str]:
    pending = list(documents)
    seen = 0
    while pending and seen < _MAX_KEYS:
        value = pending.pop()
        seen += 1
        if isinstance(value, dict):
            for key, item in value.items():
                if isinstance(key, str):
                    yield parameter_key(key)
                pending.append(item)
        elif isinstance(value, list):
            pending.extend(value)


def may_launch(path: str, data: bytes) -> bool:
    """Whether a Python file can be a launch file that sets parameters (a cheap test before parsing)."""
    return b"parameters" in data and (_LAUNCH_FILE.search(path) is not None or any(word in data for word in _LAUNCH_WORDS))


def launch_parameter_keys(tree: ast.AST) -> frozenset[str]:
    """The keys of the dictionaries a Python launch file passes as a node's `parameters=`."""
    found: set[str] = set()
    for node in ast.walk(tree):
        if not isinstance(node, Call):
            continue
        for keyword in node.keywords:
            if keyword.arg != "parameters":
                continue
            for part in ast.walk(keyword.value):
                if isinstance(part, Dict):
                    found.update(parameter_key(key.value) for key in part.keys if isinstance(key, Constant) and isinstance(key.value, str))
    return frozenset(found)
