"""The fact base asks the knowledge base about library calls: by imports, by the receiver's library
class, by convention; the answers come from stubs/ (here scipy's)."""

from __future__ import annotations

import ast
import textwrap

from geolint.algebra import FREE, Kind
from geolint.config import Config
from geolint.factbase import facts_for_module
from geolint.factbase.library_calls import (
    angle_arguments,
    angle_inputs,
    angle_output,
    library_type,
    moved_arguments,
    moving_as,
    quaternion_inputs,
    quaternion_output,
    returned_kind,
    returns_euler_angles,
    rotation_vector_arguments,
    stated_poses,
    unit_keyword,
)
from geolint.knowledge import SCALAR_FIRST, SCALAR_LAST


def _calls(source: str) -> tuple[object, dict[str, ast.Call]]:
    source = textwrap.dedent(source)
    tree = ast.parse(source)
    facts = facts_for_module(tree, source, "module.py", Config())
    calls = {ast.unparse(node): node for node in ast.walk(tree) if isinstance(node, ast.Call)}
    return facts, calls


def test_quaternion_order_of_scipy_calls_through_imports_and_receivers() -> None:
    facts, calls = _calls(
        """
        from scipy.spatial.transform import Rotation as R
        r = R.from_quat(q_xyzw)
        s = R.from_quat(q_wxyz, scalar_first=True)
        a = r.as_quat()
        b = s.as_quat(scalar_first=True)
        e = r.as_euler("xyz", degrees=True)
        f = R.from_euler("xyz", angles)
        """
    )
    (argument, order), = quaternion_inputs(facts, calls["R.from_quat(q_xyzw)"])  # type: ignore[arg-type]
    assert ast.unparse(argument) == "q_xyzw" and order == SCALAR_LAST
    assert [order for _, order in quaternion_inputs(facts, calls["R.from_quat(q_wxyz, scalar_first=True)"])] == [SCALAR_FIRST]  # type: ignore[arg-type]
    receiver = calls["r.as_quat()"].func.value  # type: ignore[attr-defined]
    assert library_type(facts, receiver) == "scipy.spatial.transform._rotation.Rotation"  # type: ignore[arg-type]
    assert quaternion_output(facts, calls["r.as_quat()"]) == SCALAR_LAST  # type: ignore[arg-type]
    assert quaternion_output(facts, calls["s.as_quat(scalar_first=True)"]) == SCALAR_FIRST  # type: ignore[arg-type]
    assert angle_output(facts, calls["r.as_euler('xyz', degrees=True)"]) == "degrees"  # type: ignore[arg-type]
    assert [unit for _, unit in angle_inputs(facts, calls["R.from_euler('xyz', angles)"])] == ["radians"]  # type: ignore[arg-type]


def test_products_inverses_and_returned_kinds_come_from_the_stub() -> None:
    facts, calls = _calls(
        """
        from scipy.spatial.transform import Rotation as R
        from pytransform3d.transformations import transform_from_pq
        r = R.from_quat(q1)
        s = R.from_euler("z", yaw)
        q = (r * s).inv().as_quat()
        e = (r * s).as_euler("xyz")
        m = r.as_matrix()
        t = transform_from_pq(pq)
        f = R.from_euler("xyz", angles)
        g = R.from_euler("xyz", angles, degrees=False)
        """
    )
    assert quaternion_output(facts, calls["(r * s).inv().as_quat()"]) == SCALAR_LAST  # type: ignore[arg-type]
    assert returns_euler_angles(facts, calls["(r * s).as_euler('xyz')"])  # type: ignore[arg-type]
    assert angle_output(facts, calls["(r * s).as_euler('xyz')"]) == "radians"  # type: ignore[arg-type]
    assert returned_kind(facts, calls["r.as_matrix()"]) is Kind.ROTATION  # type: ignore[arg-type]
    assert returned_kind(facts, calls["transform_from_pq(pq)"]) is Kind.TRANSFORM  # type: ignore[arg-type]
    # a quaternion is not answered as an array kind: its order is a question of its own
    assert returned_kind(facts, calls["(r * s).inv().as_quat()"]) is None  # type: ignore[arg-type]
    # the keyword that reads degrees, from the overloads; none when the call already chose
    assert unit_keyword(facts, calls["R.from_euler('xyz', angles)"], "degrees") == "degrees=True"  # type: ignore[arg-type]
    assert unit_keyword(facts, calls["R.from_euler('xyz', angles, degrees=False)"], "degrees") is None  # type: ignore[arg-type]


def test_a_project_class_of_the_same_name_is_not_the_library_s() -> None:
    facts, calls = _calls(
        """
        from mylib.rotations import Rotation
        r = Rotation.from_quat(q)
        """
    )
    assert quaternion_inputs(facts, calls["Rotation.from_quat(q)"]) == []  # type: ignore[arg-type]


def test_a_conventional_name_without_an_import_means_the_library_class() -> None:
    facts, calls = _calls("r = R.from_quat(q)\n")
    assert [order for _, order in quaternion_inputs(facts, calls["R.from_quat(q)"])] == [SCALAR_LAST]  # type: ignore[arg-type]


def test_a_keyword_decided_at_run_time_gives_no_answer() -> None:
    facts, calls = _calls(
        """
        from scipy.spatial.transform import Rotation
        r = Rotation.from_quat(q, scalar_first=flag)
        """
    )
    assert quaternion_inputs(facts, calls["Rotation.from_quat(q, scalar_first=flag)"]) == []  # type: ignore[arg-type]


def test_a_name_rebound_from_its_own_method_call_in_a_loop_has_no_library_type() -> None:
    """`pose = pose.detach()` in a loop: the receiver's value is the call itself. The question of its
    type is a cycle, answered "unknown" (it once recursed until Python gave up: the file was lost)."""
    facts, calls = _calls(
        """
        from scipy.spatial.transform import Rotation
        def refine(pose, steps):
            current = pose
            for _ in range(steps):
                current = current.detach()
                current = Rotation.from_quat(current.as_quat())
            return current
        """
    )
    from geolint.factbase.library_calls import called_api

    call = calls["current.detach()"]
    receiver = call.func.value  # type: ignore[attr-defined]
    assert library_type(facts, receiver) is None  # type: ignore[arg-type]
    assert called_api(facts, call) is None  # type: ignore[arg-type]
    as_quat = calls["current.as_quat()"]
    assert called_api(facts, as_quat) is None  # type: ignore[arg-type]  # `current` may be anything on the first pass


def test_a_module_of_the_project_beside_the_file_shadows_the_library(tmp_path) -> None:  # type: ignore[no-untyped-def]
    """`from transformations import quaternion_from_euler` in a ROS node folder that holds its own copy of
    tf's transformations.py (x, y, z, w) is that copy, not the PyPI transformations the stubs describe."""
    source = "from transformations import quaternion_from_euler, quaternion_matrix\nq = quaternion_from_euler(0, 0, 1)\nm = quaternion_matrix(q)\n"
    for shadowed in (False, True):
        folder = tmp_path / ("vendored" if shadowed else "plain")
        folder.mkdir()
        (folder / "setup.py").write_text("")  # a project: its imports resolve within it
        node = folder / "node.py"
        node.write_text(source)
        if shadowed:
            (folder / "transformations.py").write_text("# a vendored copy\n")
        tree = ast.parse(source)
        facts = facts_for_module(tree, source, str(node), Config())
        calls = {ast.unparse(call): call for call in ast.walk(tree) if isinstance(call, ast.Call)}
        produced = quaternion_output(facts, calls["quaternion_from_euler(0, 0, 1)"])  # type: ignore[arg-type]
        read = quaternion_inputs(facts, calls["quaternion_matrix(q)"])  # type: ignore[arg-type]
        assert (produced, [order for _, order in read]) == ((None, []) if shadowed else (SCALAR_FIRST, [SCALAR_FIRST]))


def test_angle_units_of_calls_come_from_the_stubs() -> None:
    facts, calls = _calls(
        """
        from transforms3d.taitbryan import euler2mat, mat2euler
        from transforms3d.quaternions import quat2axangle
        from tf.transformations import euler_from_quaternion
        from scipy.spatial.transform import Rotation
        M = euler2mat(yaw, pitch, roll)
        angles = mat2euler(M)
        axis, angle = quat2axangle(q)
        rpy = euler_from_quaternion(q)
        r = Rotation.from_euler("xyz", angles_deg, degrees=flag)
        """
    )
    read = angle_arguments(facts, calls["euler2mat(yaw, pitch, roll)"], "radians")  # type: ignore[arg-type]
    assert [ast.unparse(argument) for argument in read] == ["yaw", "pitch", "roll"]
    assert angle_arguments(facts, calls["euler2mat(yaw, pitch, roll)"], "degrees") == []  # type: ignore[arg-type]
    # `degrees=flag`: the overloads disagree, so nothing is said
    assert angle_arguments(facts, calls["Rotation.from_euler('xyz', angles_deg, degrees=flag)"], "radians") == []  # type: ignore[arg-type]
    assert angle_output(facts, calls["mat2euler(M)"]) == "radians"  # type: ignore[arg-type]
    assert returns_euler_angles(facts, calls["mat2euler(M)"]) and returns_euler_angles(facts, calls["euler_from_quaternion(q)"])  # type: ignore[arg-type]
    # an axis and an angle: not every part is an angle
    assert angle_output(facts, calls["quat2axangle(q)"]) is None and not returns_euler_angles(facts, calls["quat2axangle(q)"])  # type: ignore[arg-type]


def test_re_exported_modules_and_rotation_vectors_come_from_the_stubs() -> None:
    facts, calls = _calls(
        """
        import quaternion
        import tf_conversions
        from scipy.spatial.transform import Rotation
        rpy = tf_conversions.transformations.euler_from_quaternion(q)
        a = quaternion.from_rotation_vector(angle * axis)
        b = Rotation.from_rotvec(theta * axis)
        c = Rotation.from_euler("z", theta)
        """
    )
    assert angle_output(facts, calls["tf_conversions.transformations.euler_from_quaternion(q)"]) == "radians"  # type: ignore[arg-type]
    assert returns_euler_angles(facts, calls["tf_conversions.transformations.euler_from_quaternion(q)"])  # type: ignore[arg-type]
    for call in ("quaternion.from_rotation_vector(angle * axis)", "Rotation.from_rotvec(theta * axis)"):
        assert [ast.unparse(argument) for argument in rotation_vector_arguments(facts, calls[call])] == [call.partition("(")[2][:-1]]  # type: ignore[arg-type]
    assert rotation_vector_arguments(facts, calls["Rotation.from_euler('z', theta)"]) == []  # type: ignore[arg-type]  # angles, not a rotation vector


def test_moved_arguments_and_their_fixes_come_from_the_stubs() -> None:
    facts, calls = _calls(
        """
        import trimesh
        from pytransform3d.transformations import vector_to_point
        from pytorch3d.transforms import Transform3d
        a = trimesh.transform_points(x, T)
        b = trimesh.transform_points(x, T, translate=False)
        c = trimesh.transform_points(x, T, translate=flag)
        d = vector_to_point(x)
        e = Transform3d(matrix=M).transform_normals(x)
        """
    )
    moved = {source: [(ast.unparse(argument), kind) for argument, kind in moved_arguments(facts, call)] for source, call in calls.items()}  # type: ignore[arg-type]
    assert moved["trimesh.transform_points(x, T)"] == [("x", Kind.POINT)]
    assert moved["trimesh.transform_points(x, T, translate=False)"] == [("x", Kind.VECTOR)]
    assert moved["trimesh.transform_points(x, T, translate=flag)"] == []  # either overload
    assert moved["vector_to_point(x)"] == [("x", Kind.POINT)]
    assert moved["Transform3d(matrix=M).transform_normals(x)"] == [("x", Kind.DIRECTION)]
    call = calls["trimesh.transform_points(x, T)"]
    assert moving_as(facts, call, call.args[0], FREE) == ("keyword", "translate=False")  # type: ignore[arg-type, attr-defined]
    call = calls["vector_to_point(x)"]
    assert moving_as(facts, call, call.args[0], FREE) == ("name", "vector_to_direction")  # type: ignore[arg-type, attr-defined]


def test_an_annotated_parameter_has_its_library_type() -> None:
    facts, calls = _calls(
        """
        import airsim
        def turn(client: airsim.MultirotorClient, other: "airsim.MultirotorClient", third):
            client.rotateToYawAsync(a)
            other.rotateToYawAsync(b)
            third.rotateToYawAsync(c)
        """
    )
    assert [ast.unparse(argument) for argument in angle_arguments(facts, calls["client.rotateToYawAsync(a)"], "degrees")] == ["a"]  # type: ignore[arg-type]
    assert [ast.unparse(argument) for argument in angle_arguments(facts, calls["other.rotateToYawAsync(b)"], "degrees")] == ["b"]  # type: ignore[arg-type]
    assert angle_arguments(facts, calls["third.rotateToYawAsync(c)"], "degrees") == []  # type: ignore[arg-type]


def test_poses_between_named_frames_come_from_the_stubs() -> None:
    facts, calls = _calls(
        """
        import open3d as o3d
        class Fusion:
            def __init__(self):
                self.volume = o3d.pipelines.integration.ScalableTSDFVolume(voxel_length=0.01)
            def add(self, rgbd, K, w2c):
                self.volume.integrate(rgbd, K, w2c)
        a = o3d.geometry.LineSet.create_camera_visualization(640, 480, K, E1)
        b = o3d.geometry.LineSet.create_camera_visualization(intrinsic, E2, 0.1)
        """
    )
    def poses(source: str) -> list[tuple[str, str, tuple[str, str]]]:
        return [(ast.unparse(argument), name, frames) for argument, name, frames in stated_poses(facts, calls[source])]  # type: ignore[arg-type]

    assert poses("self.volume.integrate(rgbd, K, w2c)") == [("w2c", "extrinsic", ("camera", "world"))]
    assert poses("o3d.geometry.LineSet.create_camera_visualization(640, 480, K, E1)") == [("E1", "extrinsic", ("camera", "world"))]
    assert poses("o3d.geometry.LineSet.create_camera_visualization(intrinsic, E2, 0.1)") == [("E2", "extrinsic", ("camera", "world"))]


def test_the_class_of_an_argument_tells_overloads_apart() -> None:
    """pyrender's `Scene.add(obj, pose=...)`: a camera's pose where `obj` is known to be a pyrender camera, else none."""
    from geolint.factbase.library_calls import library_call, stated_camera_axes

    facts, calls = _calls(
        """
        import pyrender

        def f(scene, mesh, pose, K, obj):
            camera = pyrender.IntrinsicsCamera(fx=K[0, 0], fy=K[1, 1], cx=K[0, 2], cy=K[1, 2])
            scene.add(camera, pose=pose)
            scene.add(obj, pose=pose)
            scene.add(pyrender.Node(camera=camera, matrix=pose))
        """
    )
    known = calls["scene.add(camera, pose=pose)"]
    assert [bound.signature.parameters[0].geometry.type_name for bound in library_call(facts, known)] == [  # type: ignore[union-attr]
        "pyrender.camera.IntrinsicsCamera"
    ]
    assert [(name, frames) for _, name, frames in stated_poses(facts, known)] == [("pose", ("world", "camera"))]
    assert [(name, geometry.camera_axes) for _, name, geometry in stated_camera_axes(facts, known)] == [("pose", "opengl")]
    unknown = calls["scene.add(obj, pose=pose)"]
    assert len(library_call(facts, unknown)) == 4  # every overload open: they disagree on the pose
    assert stated_poses(facts, unknown) == []
    # an argument of another known class: the overloads that leave the parameter untyped
    node = calls["scene.add(pyrender.Node(camera=camera, matrix=pose))"]
    assert [bound.signature.parameters[0].geometry for bound in library_call(facts, node)] == [None]


def test_a_camera_added_under_a_parent_is_posed_relative_to_it() -> None:
    from geolint.factbase.library_calls import library_call

    facts, calls = _calls(
        """
        import pyrender

        def f(scene, pose, node):
            camera = pyrender.PerspectiveCamera(yfov=1.0)
            scene.add(camera, pose=pose, parent_node=node)
        """
    )
    call = calls["scene.add(camera, pose=pose, parent_node=node)"]
    assert len(library_call(facts, call)) == 1
    assert stated_poses(facts, call) == []
