"""GEO107 free-vectors-left-behind: what counts as the same object, as moved, and as left behind.

Each case is a small realistic function run through the real engine with every kind rule enabled,
so an overlap with GEO104 (normals-left-behind) would show as two findings.
"""

from __future__ import annotations

import textwrap

import pytest

from geolint.engine import lint_source
from geolint.rules import rule_by_code

KIND_RULES = [rule_by_code(code) for code in ("GEO101", "GEO102", "GEO103", "GEO104", "GEO107")]


def codes(source: str) -> list[tuple[int, str]]:
    found = lint_source(textwrap.dedent(source), "augment.py", rules=KIND_RULES)
    return [(finding.line, finding.code) for finding in found]


LAYOUT = '"""boxes: (N, 9) [x, y, z, l, w, h, yaw, vx, vy]"""'


def test_rotation_helper_on_box_centres_without_velocities() -> None:
    source = f"""
    def rotate_scene(boxes, points, angle):
        {LAYOUT}
        points[:, :3] = rotate_points_along_z(points[None, :, :3], angle)[0]
        boxes[:, :3] = rotate_points_along_z(boxes[None, :, :3], angle)[0]
        boxes[:, 6] += angle
        return boxes, points
    """
    assert codes(source) == [(5, "GEO107")]


def test_heading_left_behind_is_reported_with_the_velocities_moved() -> None:
    source = f"""
    def rotate_scene(boxes, rot_mat, angle):
        {LAYOUT}
        boxes[:, :3] = boxes[:, :3] @ rot_mat.T
        boxes[:, 7:9] = boxes[:, 7:9] @ rot_mat[:2, :2].T
        return boxes
    """
    found = lint_source(textwrap.dedent(source), "augment.py", rules=KIND_RULES)
    assert [(f.line, f.code) for f in found] == [(4, "GEO107")]
    assert "heading column 6" in found[0].message and "velocity" not in found[0].message


@pytest.mark.parametrize(
    "body",
    [
        "boxes[:, :3] += shift",  # a translation: vectors rightly stay
        "boxes[:, :3] *= scale",  # a scaling is not a rotation
        "boxes[:, :3] = boxes[:, :3] @ rot_mat.T\n    boxes = rotate_velocities(boxes, rot_mat)",  # passed on whole
        "boxes[:, :3] = boxes[:, :3] @ rot_mat.T\n    boxes[:, 6:9] = turn(boxes[:, 6:9], rot_mat)",  # written
        "boxes[:, :3] = boxes[:, :3] @ intrinsics.T",  # a projection, not a frame change
    ],
)
def test_silent_when_nothing_is_left_behind(body: str) -> None:
    source = f"def augment(boxes, rot_mat, shift, scale, intrinsics):\n    {LAYOUT}\n    {body}\n    return boxes\n"
    assert codes(source) == []


def test_velocity_columns_from_a_named_slice_elsewhere_in_the_module() -> None:
    source = """
    def speeds(boxes):
        vel = boxes[:, 7:9]
        return (vel ** 2).sum(-1) ** 0.5

    def rotate(boxes, R):
        boxes[:, :3] = boxes[:, :3] @ R.T
        return boxes
    """
    assert codes(source) == [(7, "GEO107")]


def test_no_layout_no_finding() -> None:
    """The commonest real form (an augmentation written for 7-column boxes) has no evidence in the module."""
    source = """
    def rotate(boxes, R):
        '''boxes: (N, 7) [x, y, z, dx, dy, dz, heading]'''
        boxes[:, :3] = boxes[:, :3] @ R.T
        boxes[:, 6] += angle_of(R)
        return boxes
    """
    assert codes(source) == []


def test_attribute_family_and_class_evidence() -> None:
    source = """
    class Box:
        def __init__(self, center, velocity):
            self.center = center
            self.velocity = velocity

        def rotate(self, quaternion):
            self.center = quaternion.rotation_matrix @ self.center

        def rotate_all(self, quaternion):
            self.center = quaternion.rotation_matrix @ self.center
            self.velocity = quaternion.rotation_matrix @ self.velocity

        def rotate_by_helper(self, quaternion):
            self.center = quaternion.rotation_matrix @ self.center
            self._rotate_vectors(quaternion)
    """
    assert codes(source) == [(8, "GEO107")]


def test_local_object_that_never_leaves_is_not_reported() -> None:
    source = """
    def centre_distance(track, R):
        moved = dict(track)
        moved["pos"] = moved["pos"] @ R.T
        print(moved["vel"])
        return float(moved["pos"][0, 0])
    """
    assert codes(source) == []


def test_returned_together_and_normals_left_to_geo104() -> None:
    moved_local = """
    def to_base(cloud, T_base_cam):
        pts = cloud[:, :3]
        normals = cloud[:, 3:6]
        pts_h = np.hstack([pts, np.ones((len(pts), 1))])
        pts_base = (T_base_cam @ pts_h.T).T[:, :3]
        return pts_base, normals
    """
    assert codes(moved_local) == [(6, "GEO107")]
    # the points and normals are both arguments: GEO104's case, reported once, by GEO104
    parameters = """
    def to_base(points, normals, T_base_cam):
        points_base = points @ T_base_cam[:3, :3].T + T_base_cam[:3, 3]
        return points_base, normals
    """
    assert codes(parameters) == [(3, "GEO104")]


@pytest.mark.parametrize(
    "vector_line",
    [
        "normals = cloud[:, 3:6] @ T_base_cam[:3, :3].T",  # rotated
        "normals = estimate_normals(pts_base)",  # computed from the moved points
        "normals_cam = cloud[:, 3:6]",  # states its frame
    ],
)
def test_returned_together_silent_cases(vector_line: str) -> None:
    name = vector_line.split(" =")[0]
    source = f"""
    def to_base(cloud, T_base_cam):
        pts_base = cloud[:, :3] @ T_base_cam[:3, :3].T + T_base_cam[:3, 3]
        {vector_line}
        return pts_base, {name}
    """
    assert codes(source) == []


def test_open3d_whole_object_move_is_silent() -> None:
    source = """
    import open3d as o3d

    def spin(pcd, R, track):
        pcd.points = o3d.utility.Vector3dVector(np.asarray(pcd.points) @ R.T)
        pcd.rotate(R, center=(0, 0, 0))
        track.position = R @ track.position
        track.apply_transform(R)
        return pcd, pcd.normals, track.velocity
    """
    assert codes(source) == []


def test_a_property_write_counts_for_its_private_backing_attribute() -> None:
    source = """
    class Mesh:
        def __init__(self, vertices, normals):
            self.vertices_ = vertices
            self.normals_ = normals

        def align(self, R_pc_obj):
            self.vertices = (R_pc_obj.T.dot(self.vertices.T)).T
            if self.normals_ is not None:
                self.normals = (R_pc_obj.T.dot(self.normals.T)).T
    """
    assert codes(source) == []


def test_stored_together_into_one_object() -> None:
    source = """
    import open3d as o3d

    def cloud_in_base(xyz_cam, normals, T_base_cam):
        xyz_base = xyz_cam @ T_base_cam[:3, :3].T + T_base_cam[:3, 3]
        cloud = o3d.geometry.PointCloud()
        cloud.points = o3d.utility.Vector3dVector(xyz_base)
        cloud.normals = o3d.utility.Vector3dVector(normals)
        return cloud

    def cloud_in_base_fixed(xyz_cam, normals, T_base_cam):
        xyz_base = xyz_cam @ T_base_cam[:3, :3].T + T_base_cam[:3, 3]
        normals_base = normals @ T_base_cam[:3, :3].T
        cloud = o3d.geometry.PointCloud()
        cloud.points = o3d.utility.Vector3dVector(xyz_base)
        cloud.normals = o3d.utility.Vector3dVector(normals_base)
        return cloud
    """
    assert codes(source) == [(5, "GEO107")]


def test_a_vector_the_class_recomputes_from_the_position_follows_it() -> None:
    source = """
    class OrbitCamera:
        def __init__(self, position, target):
            self.position = position
            self.target = target
            self.direction = None

        def look(self):
            self.direction = normalize(self.target - self.position)

        def orbit(self, R):
            self.position = R @ (self.position - self.target) + self.target
            self.look()

        def orbit_quietly(self, R):
            self.position = R @ (self.position - self.target) + self.target
    """
    assert codes(source) == []


ROTATING_BOX = """
import numpy as np

class Box:
    def __init__(self, center, orientation, velocity, angular_velocity, futures):
        self.center = np.array(center)
        self.orientation = orientation
        self.velocity = np.array(velocity)
        self.angular_velocity = {angular}
        self.future_orientations = futures

    def rotate(self, q):
        R = q.rotation_matrix
        self.orientation = q * self.orientation
        self.center = np.dot(R, self.center)
        self.velocity = np.dot(R, self.velocity)
{futures}
"""
FUTURES_ROTATED = """\
        if self.future_orientations is not None:
            for i in range(self.n):
                for j in range(self.m):
                    self.future_orientations[i][j] = q * self.future_orientations[i][j]
"""


def _box_messages(angular: str, futures: str) -> list[str]:
    source = ROTATING_BOX.format(angular=angular, futures=futures)
    return [f.message for f in lint_source(source, "box.py", rules=KIND_RULES) if f.code == "GEO107"]


def test_a_sibling_written_element_by_element_in_a_guarded_loop_is_handled() -> None:
    # blind round 7 (nuplan-devkit's Box3D.rotate shape): the loop assigns every element of the sibling
    assert _box_messages("float(angular_velocity) if angular_velocity is not None else 0.0", FUTURES_ROTATED) == []
    (message,) = _box_messages("float(angular_velocity)", "")
    assert "`self.future_orientations` (orientation)" in message and "angular_velocity" not in message


@pytest.mark.parametrize("angular", ["float(angular_velocity)", "int(angular_velocity)", "float(angular_velocity) if angular_velocity else 0.0"])
def test_an_attribute_stored_as_a_number_is_no_free_vector(angular: str) -> None:
    assert _box_messages(angular, FUTURES_ROTATED) == []


def test_an_attribute_stored_as_a_vector_or_a_float_parameter() -> None:
    (message,) = _box_messages("np.array(angular_velocity)", FUTURES_ROTATED)
    assert "`self.angular_velocity` (free vector)" in message
    annotated = ROTATING_BOX.format(angular="angular_velocity", futures=FUTURES_ROTATED).replace(
        "angular_velocity, futures)", "angular_velocity: float, futures)"
    )
    assert [f for f in lint_source(annotated, "box.py", rules=KIND_RULES) if f.code == "GEO107"] == []


def test_a_class_annotation_float_is_no_free_vector() -> None:
    source = """
    import numpy as np

    class Agent:
        angular_velocity: float

        def __init__(self, center, velocity, spin):
            self.center = np.asarray(center)
            self.velocity = np.asarray(velocity)
            self.angular_velocity = spin

        def rotate(self, R):
            self.center = R @ self.center
            self.velocity = R @ self.velocity
    """
    assert codes(source) == []
    assert codes(source.replace("angular_velocity: float", "angular_velocity: np.ndarray")) == [(13, "GEO107")]


def test_a_scalar_heading_is_still_an_orientation() -> None:
    source = """
    import numpy as np

    class Track:
        def __init__(self, center, yaw):
            self.center = np.asarray(center)
            self.yaw = float(yaw)

        def to_map(self, R):
            self.center = R @ self.center
    """
    assert codes(source) == [(10, "GEO107")]
