"""FrameTree: lookups through the nearest common ancestor, stamped edges, errors, transform(), DOT."""

from __future__ import annotations

import numpy as np
import pytest

from geolint import (
    DisconnectedFramesError,
    ExtrapolationError,
    Frame,
    FrameCycleError,
    FrameTree,
    FrameTreeError,
    GeometryTypeError,
    GeometryValueError,
    MissingStampError,
    Point,
    SecondParentError,
    Transform,
    UnknownFrameError,
    Vector,
    Wrench,
)


class World(Frame):
    pass


class Base(Frame):
    pass


class Camera(Frame):
    pass


def pose(dst: str, src: str, seed: int) -> Transform:  # type: ignore[type-arg]
    rng = np.random.default_rng(seed)
    q = rng.normal(size=4)
    return Transform[dst, src].from_quat(q / np.linalg.norm(q), rng.normal(size=3), order="xyzw")  # type: ignore[misc]


@pytest.fixture
def robot() -> tuple[FrameTree, dict[str, Transform]]:  # type: ignore[type-arg]
    #        World
    #       /     \
    #    Base     table
    #    /   \        \
    # Camera  arm      mug
    edges = {
        ("World", "Base"): pose("World", "Base", 1),
        ("Base", "Camera"): pose("Base", "Camera", 2),
        ("Base", "arm"): pose("Base", "arm", 3),
        ("World", "table"): pose("World", "table", 4),
        ("table", "mug"): pose("table", "mug", 5),
    }
    tree = FrameTree()
    for T in edges.values():
        tree.add(T)
    return tree, {f"{d}<-{s}": T for (d, s), T in edges.items()}


def test_lookup_walks_through_the_nearest_common_ancestor(robot) -> None:  # type: ignore[no-untyped-def]
    tree, T = robot
    expected = (T["Base<-Camera"].inverse() @ T["Base<-arm"]).matrix  # common ancestor Base, not World
    found = tree.lookup("Camera", "arm")
    assert (found.dst, found.src) == ("Camera", "arm")
    np.testing.assert_allclose(found.matrix, expected, atol=1e-12)
    across = tree.lookup("mug", Camera)
    chain = T["table<-mug"].inverse() @ T["World<-table"].inverse() @ T["World<-Base"] @ T["Base<-Camera"]
    np.testing.assert_allclose(across.matrix, chain.matrix, atol=1e-12)
    np.testing.assert_allclose(tree.lookup(World, "mug").matrix, (T["World<-table"] @ T["table<-mug"]).matrix, atol=1e-12)
    np.testing.assert_allclose(tree.lookup("arm", "arm").matrix, np.eye(4))
    np.testing.assert_allclose((tree.lookup("mug", "arm") @ tree.lookup("arm", "mug")).matrix, np.eye(4), atol=1e-12)


def test_queries(robot) -> None:  # type: ignore[no-untyped-def]
    tree, _ = robot
    assert tree.frames == ("Base", "Camera", "World", "arm", "mug", "table")
    assert tree.parent(Camera) == "Base" and tree.parent("World") is None
    assert Camera in tree and "nowhere" not in tree


def test_transform_uses_the_values_own_frame(robot) -> None:  # type: ignore[no-untyped-def]
    tree, T = robot
    p_cam = Point[Camera]([0.1, 0.2, 0.3])
    p_world = tree.transform(p_cam, to=World)
    assert p_world.frame == "World"
    np.testing.assert_allclose(np.asarray(p_world), np.asarray(T["World<-Base"] @ (T["Base<-Camera"] @ p_cam)), atol=1e-12)
    v_mug = tree.transform(Vector[Camera]([1, 0, 0]), to="mug")
    assert v_mug.frame == "mug" and v_mug.norm() == pytest.approx(1.0)
    wrench = tree.transform(Wrench["arm"](force=[0, 0, -9.81], torque=[0, 0, 0]), to=World)
    assert wrench.frame == "World"
    with pytest.raises(GeometryTypeError, match="needs a framed value"):
        tree.transform(np.zeros(3), to=World)  # type: ignore[call-overload]


def test_unknown_frame_suggests_close_names(robot) -> None:  # type: ignore[no-untyped-def]
    tree, _ = robot
    with pytest.raises(UnknownFrameError, match=r"unknown frame 'camera' .*did you mean Camera") as caught:
        tree.lookup("World", "camera")
    assert isinstance(caught.value, LookupError) and isinstance(caught.value, FrameTreeError)


def test_disconnected_frames(robot) -> None:  # type: ignore[no-untyped-def]
    tree, _ = robot
    tree.add(pose("map", "odom", 9))
    with pytest.raises(DisconnectedFramesError, match=r"no path between map and Camera: .*rooted at map and World"):
        tree.lookup("map", Camera)


def test_second_parent_and_cycles_are_refused(robot) -> None:  # type: ignore[no-untyped-def]
    tree, _ = robot
    with pytest.raises(SecondParentError, match="Camera already has the parent Base; it cannot also be a child of table"):
        tree.add(pose("table", "Camera", 10))
    with pytest.raises(FrameCycleError, match=r"would close a cycle \(World -> Base -> Camera -> World\)"):
        tree.add(pose("Camera", "World", 11))
    with pytest.raises(FrameCycleError, match="its own parent"):
        tree.add(Transform.identity("lonely"))
    # The failed additions left the tree as it was.
    assert tree.parent("Camera") == "Base" and tree.parent("World") is None and "lonely" not in tree


def test_static_edge_is_replaced_by_a_new_static_pose(robot) -> None:  # type: ignore[no-untyped-def]
    tree, _ = robot
    new = Transform["Base", "Camera"](translation=[0, 0, 1])
    tree.add(new)
    np.testing.assert_array_equal(tree.lookup("Base", "Camera").matrix, new.matrix)


def rot_z(degrees: float) -> np.ndarray:
    a = np.radians(degrees)
    return np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])


def test_stamped_edges_interpolate_with_lerp_and_slerp() -> None:
    tree = FrameTree()
    tree.add(Transform["odom", "base"](rotation=rot_z(0), translation=[0, 0, 0]), stamp=10.0)
    tree.add(Transform["odom", "base"](rotation=rot_z(90), translation=[2, 4, 0]), stamp=12.0)
    tree.add(Transform["base", "laser"](translation=[0.5, 0, 0.2]))  # static child of a moving frame
    quarter = tree.lookup("odom", "base", at=10.5)
    np.testing.assert_allclose(quarter.translation, [0.5, 1.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(quarter.rotation, rot_z(22.5), atol=1e-12)  # slerp: a quarter of the angle
    middle = tree.lookup("odom", "laser", at=11.0)
    np.testing.assert_allclose(middle.translation, [1, 2, 0] + rot_z(45) @ [0.5, 0, 0.2], atol=1e-12)
    np.testing.assert_allclose(tree.lookup("odom", "base", at=12.0).translation, [2, 4, 0])
    # Samples may arrive out of order.
    tree.add(Transform["odom", "base"](rotation=rot_z(-90), translation=[0, 0, 0]), stamp=8.0)
    np.testing.assert_allclose(tree.lookup("odom", "base", at=9.0).rotation, rot_z(-45), atol=1e-12)


def test_stamped_edges_refuse_extrapolation_and_missing_stamps() -> None:
    tree = FrameTree()
    tree.add(Transform["odom", "base"](), stamp=10.0)
    tree.add(Transform["odom", "base"](translation=[1, 0, 0]), stamp=11.0)
    with pytest.raises(ExtrapolationError, match=r"lookup at 11.5 .* 0.5 after the last sample \(samples cover 10 .. 11\)"):
        tree.lookup("odom", "base", at=11.5)
    with pytest.raises(ExtrapolationError, match="before the first"):
        tree.lookup("base", "odom", at=9.0)
    with pytest.raises(MissingStampError, match="pass at=<time>"):
        tree.lookup("odom", "base")
    with pytest.raises(GeometryValueError, match="holds time-stamped samples"):
        tree.add(Transform["odom", "base"]())
    tree.add(Transform["map", "odom"]())
    with pytest.raises(GeometryValueError, match="is static"):
        tree.add(Transform["map", "odom"](), stamp=1.0)
    with pytest.raises(GeometryValueError, match="finite number"):
        tree.add(Transform["odom", "base"](), stamp=float("nan"))
    with pytest.raises(GeometryValueError, match="one pose"):
        tree.add(Transform["x", "y"](translation=np.zeros((2, 3))))


def test_to_dot_draws_parent_to_child_edges(robot) -> None:  # type: ignore[no-untyped-def]
    tree, _ = robot
    tree.add(Transform["World", "sun"](), stamp=1.0)
    dot = tree.to_dot()
    assert dot.startswith("digraph")
    assert '"World" -> "Base" [label="T_World_Base"];' in dot
    assert '"table" -> "mug" [label="T_table_mug"];' in dot
    assert "T_World_sun (1 stamped samples)" in dot
    assert dot.count("->") == 6
