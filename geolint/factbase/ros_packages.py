"""ROS packages: does the package around a module target tf2?

A ROS package is the folder holding a `package.xml` (REP 140/149); it is what a ROS 1 (`rospy`)
module is built and shipped with. Whether its frame ids must be tf2 frame ids (no leading slash)
depends on whom the package was written for: ROS 1 `tf` (before Hydro) accepted `/map`, and Noetic's
`tf` still strips the slash before asking tf2, while tf2 lookups reject it. So a `rospy` module
counts as tf2 code only with evidence from its own package:

- its `package.xml` declares a tf2 package (`tf2`, `tf2_ros`, `tf2_geometry_msgs`, ...; not
  `tf2_msgs`, the message types old `tf` publishes too) and not `tf` itself: a package that
  declares both is half-way, and its consumers may be `tf` ones, which strip the slash (jsk_pcl_ros
  stamps contact sensors `/gazebo_world` for its `tf::MessageFilter`), or
- one of the package's Python modules imports `tf2_ros`, `tf2_py`, `tf2_geometry_msgs`,
  `tf2_sensor_msgs` or `tf2_kdl` (read through the per-file votes of `conventions`, which the
  findings cache remembers, so a warm run stats these files and reads none).

The findings cache must re-lint a module when this evidence changes (an edited `package.xml`, a
tf2 import added to a sibling module): `package_key` is folded into each file's digest.
"""

from __future__ import annotations

from typing import Final

import os
import re
import threading

from geolint.factbase import conventions
from geolint.factbase.project_files import PACKAGE_MANIFEST, package_of_folder

# a `<depend>`, `<build_depend>`, `<exec_depend>`, `<run_depend>`... on a tf2 package
_TF2_DEPENDENCY: Final = re.compile(
    r"<(?:\w+_)?depend>\s*tf2(?:_ros|_py|_geometry_msgs|_sensor_msgs|_kdl|_eigen|_bullet|_tools)?\s*</", re.IGNORECASE
)
_OLD_TF_DEPENDENCY: Final = re.compile(r"<(?:\w+_)?depend>\s*tf\s*</", re.IGNORECASE)
_XML_COMMENT: Final = re.compile(r"<!--.*?-->", re.DOTALL)
_SKIPPED_FOLDERS: Final = frozenset({"node_modules", "__pycache__", "build", "devel", "install", "log"})
_MAX_FILES: Final = 5000
_MAX_MANIFEST_BYTES: Final = 1_000_000

_lock = threading.Lock()
_package_evidence: dict[str, bool] = {}


def declares_tf2(manifest: str) -> bool:
    """Whether a `package.xml` text depends on a tf2 package and not on ROS 1 `tf` (commented-out
    dependencies do not count)."""
    text = _XML_COMMENT.sub("", manifest)
    return _TF2_DEPENDENCY.search(text) is not None and _OLD_TF_DEPENDENCY.search(text) is None


def package_folder(path: str) -> str | None:
    """The ROS package a file belongs to: the nearest folder above it holding a `package.xml`."""
    return package_of_folder(os.path.dirname(os.path.abspath(path)))


def package_targets_tf2(path: str) -> bool:
    """Whether the ROS package around `path` states that it uses tf2 (False outside a package)."""
    folder = package_folder(path)
    if folder is None:
        return False
    with _lock:
        known = _package_evidence.get(folder)
    if known is not None:
        return known
    found = _manifest_declares_tf2(folder) or _a_module_imports_tf2(folder)
    with _lock:
        _package_evidence[folder] = found
    return found


def package_key(path: str) -> str:
    """What the findings of `path` read from its ROS package, for the findings cache ('' outside one)."""
    folder = package_folder(path)
    return "" if folder is None else f"ros-tf2:{package_targets_tf2(path)}"


def forget_packages() -> None:
    """Let the next question about each package look at its files again (a long-lived process)."""
    with _lock:
        _package_evidence.clear()
    package_of_folder.cache_clear()


def _manifest_declares_tf2(folder: str) -> bool:
    try:
        with open(os.path.join(folder, PACKAGE_MANIFEST), "rb") as stream:
            text = stream.read(_MAX_MANIFEST_BYTES).decode("utf-8", errors="replace")
    except OSError:
        return False
    return declares_tf2(text)


def _a_module_imports_tf2(folder: str) -> bool:
    count = 0
    for parent, dirnames, filenames in os.walk(folder):
        dirnames[:] = [
            name
            for name in dirnames
            if not name.startswith(".")
            and name not in _SKIPPED_FOLDERS
            and not os.path.isfile(os.path.join(parent, name, PACKAGE_MANIFEST))  # a nested package speaks for itself
        ]
        for filename in filenames:
            if not filename.endswith(".py"):
                continue
            count += 1
            if count > _MAX_FILES:
                return False
            if conventions.file_votes(os.path.join(parent, filename)).tf2_modules:
                return True
    return False
