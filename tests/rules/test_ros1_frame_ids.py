"""GEO207 in ROS 1 code: a `rospy` module counts as tf2 code only when its ROS package says so
(`package.xml`, or a sibling module's tf2 import), and the findings cache follows that evidence."""

from __future__ import annotations

import ast
import json
import subprocess
import sys
from pathlib import Path

from geolint.factbase import index_of, ros_packages
from geolint.factbase.conventions import votes_of_source
from geolint.factbase.frame_ids import frame_string

MANIFEST = '<?xml version="1.0"?>\n<package format="2">\n  <name>{name}</name>\n{depends}</package>\n'
NODE = (
    "import rospy\nfrom std_msgs.msg import Header\nfrom sensor_msgs.msg import PointCloud2\n\n\n"
    "def publish(pub, cloud):\n    cloud.header = Header()\n    cloud.header.frame_id = '/camera_link'\n    pub.publish(cloud)\n"
)


def _package(root: Path, name: str, depends: str = "") -> Path:
    folder = root / name
    (folder / "nodes").mkdir(parents=True)
    (folder / "package.xml").write_text(MANIFEST.format(name=name, depends=depends))
    (folder / "nodes" / "cloud_node.py").write_text(NODE)
    return folder


def _geo207(root: Path, *extra: str) -> list[tuple[str, int]]:
    completed = subprocess.run(
        [sys.executable, "-m", "geolint", "check", "--select", "GEO207", "--format", "json", *extra, "."],
        cwd=root, capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert completed.returncode in (0, 1), completed.stderr
    return sorted((Path(f["path"]).name, f["line"]) for f in json.loads(completed.stdout))


def test_manifest_dependencies_that_count() -> None:
    assert ros_packages.declares_tf2("<package><exec_depend>tf2_ros</exec_depend></package>")
    assert ros_packages.declares_tf2("<package><build_depend>tf2</build_depend></package>")
    assert ros_packages.declares_tf2("<package><depend> tf2_geometry_msgs </depend></package>")
    assert not ros_packages.declares_tf2("<package><depend>tf</depend><depend>tf2_msgs</depend></package>")
    assert not ros_packages.declares_tf2("<package><!-- <depend>tf2_ros</depend> --></package>")
    # half-way: tf consumers strip the slash themselves
    assert not ros_packages.declares_tf2("<package><depend>tf</depend><exec_depend>tf2_ros</exec_depend></package>")


def test_tf2_imports_are_counted_per_module() -> None:
    assert votes_of_source("import tf2_ros\n").tf2_modules == 1
    assert votes_of_source("def f():\n    from tf2_geometry_msgs import do_transform_point\n").tf2_modules == 1
    assert votes_of_source("import tf\nfrom tf2_msgs.msg import TFMessage\n# tf2_ros later\n").tf2_modules == 0


def test_built_frame_ids_are_folded_exactly() -> None:
    source = (
        "PREFIX = ''\nNAME = 'gps'\nBUILT = '%s/%s' % (PREFIX, NAME)\n"
        "def f(param):\n    local = '/' + NAME\n    return ('%s/%s' % (PREFIX, NAME), '/' + 'map', f'/{NAME}', '{}/{}'.format('', 'odom'),"
        " BUILT, local, '%s/%s' % (param, NAME), '/' + param, PREFIX % 3)\n"
    )
    tree = ast.parse(source)
    index = index_of(tree)
    returned = next(node for node in ast.walk(tree) if isinstance(node, ast.Return)).value
    assert isinstance(returned, ast.Tuple)
    values = [frame_string(element, index) for element in returned.elts]
    assert values == ["/gps", "/map", "/gps", "/odom", "/gps", "/gps", None, None, None]


def test_a_global_rebound_in_the_function_is_not_the_module_constant() -> None:
    local = "FRAME = '/map'\ndef f(flag):\n    if flag:\n        FRAME = 'odom'\n    else:\n        FRAME = flag\n    return FRAME\n"
    rebound = "FRAME = '/map'\ndef reset():\n    global FRAME\n    FRAME = 'odom'\ndef f():\n    return FRAME\n"
    for source in (local, rebound):
        tree = ast.parse(source)
        returned = next(node for node in ast.walk(tree) if isinstance(node, ast.Return)).value
        assert isinstance(returned, ast.Name)
        assert frame_string(returned, index_of(tree)) is None, source


def test_a_rospy_module_counts_as_tf2_code_only_with_package_evidence(tmp_path: Path) -> None:
    _package(tmp_path, "old_tf_pkg", "  <depend>tf</depend>\n")
    _package(tmp_path, "half_way_pkg", "  <depend>tf</depend>\n  <exec_depend>tf2_ros</exec_depend>\n")
    _package(tmp_path, "tf2_manifest_pkg", "  <depend>rospy</depend>\n  <exec_depend>tf2_ros</exec_depend>\n")
    sibling = _package(tmp_path, "tf2_sibling_pkg")
    (sibling / "nodes" / "lookup.py").write_text("import tf2_ros\nbuffer = tf2_ros.Buffer()\n")
    found = _geo207(tmp_path, "--no-cache")
    assert found == [("cloud_node.py", 8), ("cloud_node.py", 8)]
    by_package = subprocess.run(
        [sys.executable, "-m", "geolint", "check", "--select", "GEO207", "--format", "json", "--no-cache", "old_tf_pkg"],
        cwd=tmp_path, capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert json.loads(by_package.stdout) == []


def test_the_findings_cache_follows_the_package_evidence(tmp_path: Path) -> None:
    package = _package(tmp_path, "cloud_pkg", "  <depend>rospy</depend>\n")
    cache = ["--cache-dir", str(tmp_path / ".geolint-cache")]
    assert _geo207(tmp_path, *cache) == []
    # the manifest now declares tf2: the unchanged node is linted again, and reported
    (package / "package.xml").write_text(MANIFEST.format(name="cloud_pkg", depends="  <depend>tf2_ros</depend>\n"))
    assert _geo207(tmp_path, *cache) == [("cloud_node.py", 8)]
    # back to no evidence, then a sibling module starts using tf2_ros
    (package / "package.xml").write_text(MANIFEST.format(name="cloud_pkg", depends=""))
    assert _geo207(tmp_path, *cache) == []
    (package / "nodes" / "lookup.py").write_text("import rospy\nimport tf2_ros\n")
    assert _geo207(tmp_path, *cache) == [("cloud_node.py", 8)]


def test_a_module_using_ros1_tf_itself_is_left_alone_but_not_one_using_only_its_math(tmp_path: Path) -> None:
    """ROS 1 tf strips a leading slash before asking tf2 (stubs/tf/METADATA.toml `strips_leading_slash`), so a
    tf2 package's node that uses tf's listener or broadcaster may stamp '/camera_link'; one that imports only
    tf.transformations (frame-free helpers, however it is imported) is tf2 code like any other."""
    uses = {
        "math_from": "from tf.transformations import quaternion_from_euler\n",
        "math_module": "from tf import transformations\n",
        "math_attribute": "import tf\nQ = tf.transformations.quaternion_from_euler(0, 0, 1)\n",
        "listener_from": "from tf import TransformListener\n",
        "listener_attribute": "import tf\nLISTENER = tf.TransformListener()\n",
    }
    for name, header in uses.items():
        folder = _package(tmp_path, name, "  <depend>tf2_ros</depend>\n")
        (folder / "nodes" / "cloud_node.py").write_text(header + NODE)
    flagged = {Path(path).parent.parent.name for path, _ in _geo207_paths(tmp_path)}
    assert flagged == {"math_from", "math_module", "math_attribute"}


def _geo207_paths(root: Path) -> list[tuple[str, int]]:
    completed = subprocess.run(
        [sys.executable, "-m", "geolint", "check", "--select", "GEO207", "--format", "json", "--no-cache", "."],
        cwd=root, capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert completed.returncode in (0, 1), completed.stderr
    return sorted((f["path"], f["line"]) for f in json.loads(completed.stdout))
