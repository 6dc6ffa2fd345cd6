"""The facts of the image and scene libraries in stubs/ (scikit-image, Pillow, mathutils, bpy, pyrender, Argoverse 2,
Argoverse 1, the Waymo Open Dataset): first what the linter now says of a small invented call of each and of its
correct twin, then each fact checked against the library where it installs (skipped where it does not: none of them
is a dependency of geolint's). The unit, order, frames and axes checked are read from the stubs."""

from __future__ import annotations

import math
import textwrap

import numpy as np
import pytest

from geolint.api import lint_text
from geolint.knowledge import RADIANS, SCALAR_FIRST, SCALAR_LAST, Geometry, knowledge_base
from tests.knowledge.facts_helpers import QUARTER_TURN_Z, _quarter_turn, _stated

DEGREES = "degrees"
_HALF = math.sqrt(0.5)

# (what it shows, a call that misuses a library as its stub states it, the finding, the same call done right)
PAIRS = [
    (
        "skimage rotate reads degrees",
        "import numpy as np\nfrom skimage.transform import rotate\ndef f(img, dy, dx):\n    return rotate(img, np.arctan2(dy, dx))\n",
        "GEO305",
        "import numpy as np\nfrom skimage.transform import rotate\ndef f(img, dy, dx):\n    return rotate(img, np.degrees(np.arctan2(dy, dx)))\n",
    ),
    (
        "skimage AffineTransform reads radians",
        "from skimage.transform import AffineTransform\ndef f():\n    return AffineTransform(rotation=90)\n",
        "GEO302",
        "import numpy as np\nfrom skimage.transform import AffineTransform\ndef f():\n    return AffineTransform(rotation=np.pi / 2)\n",
    ),
    (
        "skimage EuclideanTransform reads radians, through `import skimage as ski`",
        "import skimage as ski\ndef f(heading_deg):\n    return ski.transform.EuclideanTransform(rotation=heading_deg, translation=(1, 2))\n",
        "GEO302",
        "import numpy as np\nimport skimage as ski\ndef f(heading_deg):\n"
        "    return ski.transform.EuclideanTransform(rotation=np.deg2rad(heading_deg), translation=(1, 2))\n",
    ),
    (
        "skimage draw.ellipse reads radians",
        "from skimage.draw import ellipse\ndef f(angle_deg):\n    return ellipse(10, 10, 3, 5, rotation=angle_deg)\n",
        "GEO302",
        "import math\nfrom skimage.draw import ellipse\ndef f(angle_deg):\n    return ellipse(10, 10, 3, 5, rotation=math.radians(angle_deg))\n",
    ),
    (
        "PIL Image.rotate reads degrees, on an image from Image.open",
        "import math\nfrom PIL import Image\ndef f(path, dy, dx):\n    img = Image.open(path)\n    return img.rotate(math.atan2(dy, dx))\n",
        "GEO305",
        "import math\nfrom PIL import Image\ndef f(path, dy, dx):\n    img = Image.open(path)\n"
        "    return img.rotate(math.degrees(math.atan2(dy, dx)))\n",
    ),
    (
        "PIL ImageDraw.pieslice reads degrees",
        "import math\nfrom PIL import Image, ImageDraw\ndef f(img: Image.Image, dy, dx):\n    heading = math.atan2(dy, dx)\n"
        "    ImageDraw.Draw(img).pieslice((0, 0, 9, 9), start=heading - 0.3, end=heading + 0.3)\n",
        "GEO305",
        "import math\nfrom PIL import Image, ImageDraw\ndef f(img: Image.Image, dy, dx):\n    heading = math.degrees(math.atan2(dy, dx))\n"
        "    ImageDraw.Draw(img).pieslice((0, 0, 9, 9), start=heading - 15, end=heading + 15)\n",
    ),
    (
        "mathutils Quaternion reads (w, x, y, z)",
        "from mathutils import Quaternion\nfrom scipy.spatial.transform import Rotation\ndef f(R):\n"
        "    return Quaternion(Rotation.from_matrix(R).as_quat())\n",
        "GEO301",
        "from mathutils import Quaternion\nfrom scipy.spatial.transform import Rotation\ndef f(R):\n"
        "    return Quaternion(Rotation.from_matrix(R).as_quat(scalar_first=True))\n",
    ),
    (
        "mathutils Euler reads radians",
        "from mathutils import Euler\ndef f():\n    return Euler((0.0, 0.0, 90.0), 'XYZ')\n",
        "GEO302",
        "import math\nfrom mathutils import Euler\ndef f():\n    return Euler((0.0, 0.0, math.radians(90.0)), 'XYZ')\n",
    ),
    (
        "mathutils Matrix.Rotation reads radians",
        "import mathutils\ndef f(yaw_deg):\n    return mathutils.Matrix.Rotation(yaw_deg, 4, 'Z')\n",
        "GEO302",
        "import math\nimport mathutils\ndef f(yaw_deg):\n    return mathutils.Matrix.Rotation(math.radians(yaw_deg), 4, 'Z')\n",
    ),
    (
        "bpy rotation_quaternion holds (w, x, y, z), through bpy.context",
        "import bpy\nfrom scipy.spatial.transform import Rotation\ndef f():\n"
        "    return Rotation.from_quat(bpy.context.object.rotation_quaternion)\n",
        "GEO301",
        "import bpy\nfrom scipy.spatial.transform import Rotation\ndef f():\n"
        "    return Rotation.from_quat(bpy.context.object.rotation_quaternion, scalar_first=True)\n",
    ),
    (
        "pyrender camera node poses are in OpenGL camera axes",
        "import pyrender\ndef f(cam, c2w_opencv):\n    return pyrender.Node(camera=cam, matrix=c2w_opencv)\n",
        "GEO216",
        "import pyrender\ndef f(cam, c2w_opengl):\n    return pyrender.Node(camera=cam, matrix=c2w_opengl)\n",
    ),
    (
        "pyrender Node rotation is (x, y, z, w)",
        "import pyrender\nfrom scipy.spatial.transform import Rotation\ndef f(mesh, R):\n"
        "    return pyrender.Node(mesh=mesh, rotation=Rotation.from_matrix(R).as_quat(scalar_first=True))\n",
        "GEO301",
        "import pyrender\nfrom scipy.spatial.transform import Rotation\ndef f(mesh, R):\n"
        "    return pyrender.Node(mesh=mesh, rotation=Rotation.from_matrix(R).as_quat())\n",
    ),
    (
        "pyrender PerspectiveCamera yfov is radians",
        "import pyrender\ndef f():\n    return pyrender.PerspectiveCamera(yfov=60.0)\n",
        "GEO302",
        "import numpy as np\nimport pyrender\ndef f():\n    return pyrender.PerspectiveCamera(yfov=np.pi / 3.0)\n",
    ),
    (
        "av2 quat_to_mat reads (w, x, y, z)",
        "from av2.geometry.geometry import quat_to_mat\nfrom scipy.spatial.transform import Rotation\ndef f(R):\n"
        "    return quat_to_mat(Rotation.from_matrix(R).as_quat())\n",
        "GEO301",
        "from av2.geometry.geometry import quat_to_mat\nfrom scipy.spatial.transform import Rotation\ndef f(R):\n"
        "    return quat_to_mat(Rotation.from_matrix(R).as_quat(scalar_first=True))\n",
    ),
    (
        "av2 mat_to_quat returns (w, x, y, z)",
        "from av2.geometry.geometry import mat_to_quat\nfrom scipy.spatial.transform import Rotation\ndef f(R):\n"
        "    return Rotation.from_quat(mat_to_quat(R))\n",
        "GEO301",
        "from av2.geometry.geometry import mat_to_quat\nfrom scipy.spatial.transform import Rotation\ndef f(R):\n"
        "    return Rotation.from_quat(mat_to_quat(R), scalar_first=True)\n",
    ),
    (
        "av2 SE3.transform_point_cloud translates points",
        "from av2.geometry.se3 import SE3\ndef f(R, t, normals):\n    city_SE3_ego = SE3(rotation=R, translation=t)\n"
        "    return city_SE3_ego.transform_point_cloud(normals)\n",
        "GEO101",
        "from av2.geometry.se3 import SE3\ndef f(R, t, normals):\n    city_SE3_ego = SE3(rotation=R, translation=t)\n"
        "    return normals @ city_SE3_ego.rotation.T\n",
    ),
    (
        "Argoverse 1 quat2rotmat reads (w, x, y, z)",
        "from argoverse.utils.transform import quat2rotmat\ndef f(qx, qy, qz, qw):\n    return quat2rotmat([qx, qy, qz, qw])\n",
        "GEO301",
        "from argoverse.utils.transform import quat2rotmat\ndef f(qx, qy, qz, qw):\n    return quat2rotmat([qw, qx, qy, qz])\n",
    ),
    (
        "Argoverse 1 yaw_to_quaternion3d reads radians",
        "from argoverse.utils.transform import yaw_to_quaternion3d\ndef f():\n    return yaw_to_quaternion3d(90)\n",
        "GEO302",
        "import numpy as np\nfrom argoverse.utils.transform import yaw_to_quaternion3d\ndef f():\n    return yaw_to_quaternion3d(np.pi / 2)\n",
    ),
    (
        "Waymo Label.Box heading is radians",
        "from waymo_open_dataset import label_pb2\ndef f(x, y, yaw_deg):\n    return label_pb2.Label.Box(center_x=x, center_y=y, heading=yaw_deg)\n",
        "GEO302",
        "import math\nfrom waymo_open_dataset import label_pb2\ndef f(x, y, yaw_deg):\n"
        "    return label_pb2.Label.Box(center_x=x, center_y=y, heading=math.radians(yaw_deg))\n",
    ),
]


def _codes(source: str) -> list[str]:
    return [finding.code for finding in lint_text(textwrap.dedent(source), "example.py")]


@pytest.mark.parametrize(("what", "invalid", "code", "valid"), PAIRS, ids=[pair[0] for pair in PAIRS])
def test_the_linter_reads_the_stub(what: str, invalid: str, code: str, valid: str) -> None:
    assert _codes(invalid) == [code], what
    assert _codes(valid) == [], what


def _attribute(qualified: str) -> Geometry:
    """What a stub states that an attribute (or property) holds."""
    api = knowledge_base().api(qualified)
    assert api is not None and api.is_attribute, f"{qualified} is not an attribute in the knowledge base"
    (signature,) = api.signatures
    assert signature.returns is not None
    return signature.returns


def _lit(image: np.ndarray) -> list[tuple[int, int]]:
    return [(int(row), int(column)) for row, column in np.argwhere(np.asarray(image) > 0.5 * np.max(image))]


# -- scikit-image ------------------------------------------------------------------------------------------------------


def test_skimage_rotate_reads_degrees_counter_clockwise() -> None:
    transform = pytest.importorskip("skimage.transform")
    assert _stated("skimage.transform.rotate", "rotate(image, angle)", "angle", "angle_unit") == DEGREES
    image = np.zeros((5, 5))
    image[2, 4] = 1.0  # right of the centre
    assert _lit(transform.rotate(image, 90.0, order=0)) == [(0, 2)]  # a quarter turn counter-clockwise: above it
    assert _lit(transform.rotate(image, math.pi / 2, order=0)) == [(2, 4)]  # 1.57 degrees: where it was


@pytest.mark.parametrize("name", ["AffineTransform", "EuclideanTransform", "SimilarityTransform"])
def test_skimage_geometric_transforms_read_radians(name: str) -> None:
    transform = pytest.importorskip("skimage.transform")
    assert _stated(f"skimage.transform.{name}", f"{name}(rotation=r)", "rotation", "angle_unit") == RADIANS
    made = getattr(transform, name)(rotation=math.pi / 2)
    assert np.allclose(made.params[:2, :2], QUARTER_TURN_Z[:2, :2])


def test_skimage_affine_properties_and_3d_euclidean_rotation_are_radians() -> None:
    transform = pytest.importorskip("skimage.transform")
    assert _attribute("skimage.transform._geometric.AffineTransform.rotation").angle_unit == RADIANS
    assert math.isclose(transform.AffineTransform(rotation=0.3).rotation, 0.3)
    assert math.isclose(transform.AffineTransform(shear=0.2).shear, 0.2)
    # three Euler angles, radians, in 3D
    assert np.allclose(transform.EuclideanTransform(rotation=(0.0, 0.0, math.pi / 2)).params[:3, :3], QUARTER_TURN_Z)


def test_skimage_hough_lines_are_radians_and_radon_degrees() -> None:
    transform = pytest.importorskip("skimage.transform")
    (hough_angles,) = [part.angle_unit for part in _stated("skimage.transform.hough_line", "hough_line(image)", "return", "items") if part.angle_unit]  # type: ignore[attr-defined]
    assert hough_angles == RADIANS
    assert _stated("skimage.transform.radon", "radon(image, theta)", "theta", "angle_unit") == DEGREES
    edges = np.zeros((40, 40), dtype=bool)
    edges[20, 5:35] = True  # a horizontal line: its normal is vertical
    hspace, angles, distances = transform.hough_line(edges)
    _, peak_angles, _ = transform.hough_line_peaks(hspace, angles, distances, num_peaks=1)
    assert math.isclose(abs(float(peak_angles[0])), math.pi / 2, abs_tol=0.02)
    # radon's default angles are np.arange(180): one projection per degree
    assert transform.radon(np.ones((8, 8))).shape[1] == 180


def test_skimage_ellipse_rotation_is_radians() -> None:
    draw = pytest.importorskip("skimage.draw")
    assert _stated("skimage.draw.ellipse", "ellipse(r, c, a, b, rotation=x)", "rotation", "angle_unit") == RADIANS
    rows, columns = draw.ellipse(20, 20, 2, 8, rotation=0.0)
    assert np.ptp(columns) > np.ptp(rows)
    rows, columns = draw.ellipse(20, 20, 2, 8, rotation=math.pi / 2)  # a quarter turn: the long axis along the rows
    assert np.ptp(rows) > np.ptp(columns)


# -- Pillow ------------------------------------------------------------------------------------------------------------


def test_pillow_rotate_reads_degrees_counter_clockwise() -> None:
    image_module = pytest.importorskip("PIL.Image")
    assert _stated("PIL.Image.Image.rotate", "rotate(angle)", "angle", "angle_unit") == DEGREES
    pixels = np.zeros((5, 5), dtype=np.uint8)
    pixels[2, 4] = 255  # right of the centre
    image = image_module.fromarray(pixels)
    assert _lit(np.asarray(image.rotate(90))) == [(0, 2)]  # a quarter turn counter-clockwise: above it
    assert _lit(np.asarray(image.rotate(math.pi / 2))) == [(2, 4)]


def test_pillow_draw_angles_are_degrees() -> None:
    image_module = pytest.importorskip("PIL.Image")
    draw_module = pytest.importorskip("PIL.ImageDraw")
    for method in ("arc", "chord", "pieslice"):
        assert _stated(f"PIL.ImageDraw.ImageDraw.{method}", f"{method}(xy, start, end)", "start", "angle_unit") == DEGREES
    image = image_module.new("L", (21, 21))
    draw_module.Draw(image).pieslice((0, 0, 20, 20), start=0, end=90, fill=255)
    filled = np.asarray(image)
    # from 3 o'clock clockwise to 6 o'clock: the lower right quarter, rows counting down
    assert filled[15, 15] == 255 and filled[5, 15] == filled[15, 5] == filled[5, 5] == 0
    square = image_module.new("L", (21, 21))
    draw_module.Draw(square).regular_polygon((10, 10, 10), 4, rotation=45, fill=255)
    assert np.asarray(square)[1, 10] == 255  # turned 45 degrees: a corner at the top


# -- mathutils and bpy -------------------------------------------------------------------------------------------------


def test_mathutils_quaternion_is_w_first_and_angles_radians() -> None:
    mathutils = pytest.importorskip("mathutils")
    order = _stated("mathutils.Quaternion", "Quaternion(q)", "seq")
    assert order == SCALAR_FIRST
    as_array = lambda matrix: np.array([list(row) for row in matrix])  # noqa: E731
    assert np.allclose(as_array(mathutils.Quaternion(_quarter_turn(order)).to_matrix()), QUARTER_TURN_Z, atol=1e-6)
    assert _stated("mathutils.Quaternion", "Quaternion(axis, angle)", "angle", "angle_unit") == RADIANS
    assert np.allclose(as_array(mathutils.Quaternion((0.0, 0.0, 1.0), math.pi / 2).to_matrix()), QUARTER_TURN_Z, atol=1e-6)
    assert math.isclose(mathutils.Quaternion(_quarter_turn(order)).angle, math.pi / 2, rel_tol=1e-6)
    assert _stated("mathutils.Euler", "Euler(angles, order)", "angles", "angle_unit") == RADIANS
    # the default order, XYZ (mathutils 3.3.0 built for Python 3.11 rejects every order string: "invalid euler order")
    assert np.allclose(as_array(mathutils.Euler((0.0, 0.0, math.pi / 2)).to_matrix()), QUARTER_TURN_Z, atol=1e-6)
    assert _stated("mathutils.Matrix.Rotation", "Rotation(angle, size, axis)", "angle", "angle_unit") == RADIANS
    assert np.allclose(as_array(mathutils.Matrix.Rotation(math.pi / 2, 3, "Z")), QUARTER_TURN_Z, atol=1e-6)


def test_blender_camera_matrix_world_is_camera_to_world_in_opengl_axes() -> None:
    bpy = pytest.importorskip("bpy")
    mathutils = pytest.importorskip("mathutils")
    object_utils = pytest.importorskip("bpy_extras.object_utils")
    stated = _attribute("bpy.types._CameraObject.matrix_world")
    assert stated.camera_axes == "opengl" and stated.frames == ("world", "camera")
    assert _attribute("bpy.types.Object.rotation_quaternion").quaternion_order == SCALAR_FIRST
    assert _attribute("bpy.types.Object.rotation_euler").type_name == "mathutils.Euler"
    assert _attribute("mathutils.Euler.z").angle_unit == RADIANS
    assert _attribute("bpy.types.Camera.angle").angle_unit == RADIANS
    scene = bpy.context.scene
    camera_data = bpy.data.cameras.new("geolint_camera")
    camera = bpy.data.objects.new("geolint_camera", camera_data)
    scene.collection.objects.link(camera)
    scene.camera = camera
    camera.matrix_world = mathutils.Matrix.Translation((1.0, 2.0, 3.0))
    bpy.context.view_layer.update()
    # a point 5 in front of the camera along its -z, a little right (+x) and up (+y) of its axis
    x, y, depth = object_utils.world_to_camera_view(scene, camera, mathutils.Vector((1.1, 2.1, 3.0 - 5.0)))
    assert x > 0.5 and y > 0.5 and math.isclose(depth, 5.0, rel_tol=1e-6)  # right, up, in front
    assert object_utils.world_to_camera_view(scene, camera, mathutils.Vector((1.0, 2.0, 8.0)))[2] < 0  # +z: behind
    camera.location = (0.0, 0.0, 0.0)
    camera.rotation_mode = "XYZ"
    camera.rotation_euler = (0.0, 0.0, math.pi / 2)
    bpy.context.view_layer.update()
    as_array = lambda matrix: np.array([list(row) for row in matrix])  # noqa: E731
    assert np.allclose(as_array(camera.matrix_world.to_3x3()), QUARTER_TURN_Z, atol=1e-6)
    camera.rotation_mode = "QUATERNION"
    camera.rotation_quaternion = _quarter_turn(SCALAR_FIRST)
    bpy.context.view_layer.update()
    assert np.allclose(as_array(camera.matrix_world.to_3x3()), QUARTER_TURN_Z, atol=1e-6)
    camera_data.sensor_fit = "HORIZONTAL"
    camera_data.angle = math.pi / 2  # a quarter turn of field of view: the focal length is half the sensor width
    assert math.isclose(camera_data.lens, camera_data.sensor_width / 2, rel_tol=1e-5)


# -- pyrender ----------------------------------------------------------------------------------------------------------


def test_pyrender_node_rotation_is_xyzw_and_camera_poses_are_camera_to_world() -> None:
    pyrender = pytest.importorskip("pyrender")
    order = _stated("pyrender.Node", "Node(mesh=m, rotation=q)", "rotation")
    assert order == SCALAR_LAST
    assert np.allclose(pyrender.Node(rotation=np.array(_quarter_turn(order))).matrix[:3, :3], QUARTER_TURN_Z)
    assert _stated("pyrender.Node", "Node(camera=c, matrix=pose)", "matrix", "frames") == ("world", "camera")
    camera = pyrender.IntrinsicsCamera(fx=100.0, fy=100.0, cx=50.0, cy=40.0)
    pose = np.eye(4)
    pose[:3, :3] = QUARTER_TURN_Z
    pose[:3, 3] = [1.0, 2.0, 3.0]
    scene = pyrender.Scene()
    node = scene.add(camera, pose=pose)
    assert np.allclose(scene.get_pose(node), pose)
    # what the renderer does (renderer.py, _get_camera_matrices): V = inv(pose) takes the world into the camera
    world_to_camera = np.linalg.inv(scene.get_pose(node))
    centre_in_camera = world_to_camera @ np.array([1.0, 2.0, 3.0, 1.0])
    assert np.allclose(centre_in_camera[:3], 0.0)  # the pose's translation is the camera centre


def test_pyrender_cameras_look_down_minus_z_with_y_up_and_yfov_in_radians() -> None:
    pyrender = pytest.importorskip("pyrender")
    assert _stated("pyrender.Node", "Node(camera=c, matrix=pose)", "matrix", "camera_axes") == "opengl"
    width, height = 100, 80
    camera = pyrender.IntrinsicsCamera(fx=100.0, fy=100.0, cx=50.0, cy=40.0)
    projection = camera.get_projection_matrix(width, height)
    clip = projection @ np.array([0.1, 0.1, -2.0, 1.0])  # right of, above and in front of (-z) the camera
    assert clip[3] > 0 and clip[0] / clip[3] > 0 and clip[1] / clip[3] > 0
    assert (projection @ np.array([0.0, 0.0, 2.0, 1.0]))[3] < 0  # +z is behind it
    # the intrinsics are OpenCV's: the row of a point is cy + fy * y / z with y down, z forward
    y_down, z_forward = 0.2, 2.0
    clip = projection @ np.array([0.0, -y_down, -z_forward, 1.0])
    row_from_top = (1.0 - clip[1] / clip[3]) / 2.0 * height
    assert math.isclose(row_from_top, 40.0 + 100.0 * y_down / z_forward, rel_tol=1e-9)
    assert _stated("pyrender.PerspectiveCamera", "PerspectiveCamera(yfov=a)", "yfov", "angle_unit") == RADIANS
    assert math.isclose(pyrender.PerspectiveCamera(yfov=math.pi / 2).get_projection_matrix(100, 100)[1, 1], 1.0)


# -- Argoverse ---------------------------------------------------------------------------------------------------------


def test_av2_quaternions_are_w_first() -> None:
    geometry = pytest.importorskip("av2.geometry.geometry")
    order = _stated("av2.geometry.geometry.quat_to_mat", "quat_to_mat(q)", "quat_wxyz")
    assert order == SCALAR_FIRST
    assert np.allclose(geometry.quat_to_mat(np.array(_quarter_turn(order))), QUARTER_TURN_Z)
    returned = _stated("av2.geometry.geometry.mat_to_quat", "mat_to_quat(R)", "return")
    assert np.allclose(geometry.mat_to_quat(QUARTER_TURN_Z), _quarter_turn(str(returned)))
    assert _stated("av2.geometry.geometry.xyz_to_mat", "xyz_to_mat(a)", "xyz_rad", "angle_unit") == RADIANS
    assert np.allclose(geometry.xyz_to_mat(np.array([0.0, 0.0, math.pi / 2])), QUARTER_TURN_Z)


def test_av2_se3_moves_points_from_its_source_into_its_destination() -> None:
    se3 = pytest.importorskip("av2.geometry.se3")
    pinhole = pytest.importorskip("av2.geometry.camera.pinhole_camera")
    translation = np.array([1.0, 2.0, 3.0])
    city_SE3_ego = se3.SE3(rotation=QUARTER_TURN_Z, translation=translation)
    # R p + t: the point is rotated, then translated
    assert np.allclose(city_SE3_ego.transform_point_cloud(np.array([[1.0, 0.0, 0.0]])), [[1.0, 3.0, 3.0]])
    assert np.allclose(city_SE3_ego.transform_matrix[:3, 3], translation)
    assert np.allclose(city_SE3_ego.inverse().transform_point_cloud(np.array([[1.0, 3.0, 3.0]])), [[1.0, 0.0, 0.0]])
    chained = city_SE3_ego.compose(city_SE3_ego.inverse())
    assert np.allclose(chained.transform_matrix, np.eye(4))
    camera = pinhole.PinholeCamera(ego_SE3_cam=city_SE3_ego, intrinsics=None, cam_name="ring_front_center")
    assert np.allclose(camera.extrinsics, np.linalg.inv(city_SE3_ego.transform_matrix))  # ego-to-camera
    stated = _attribute("av2.geometry.camera.pinhole_camera.PinholeCamera.extrinsics")
    assert stated.frames == ("camera", "egovehicle") and stated.camera_axes == "opencv"


def test_argoverse1_quaternions_are_w_first() -> None:
    transform = pytest.importorskip("argoverse.utils.transform")
    se3 = pytest.importorskip("argoverse.utils.se3")
    order = _stated("argoverse.utils.transform.quat2rotmat", "quat2rotmat(q)", "q")
    assert order == SCALAR_FIRST
    assert np.allclose(transform.quat2rotmat(np.array(_quarter_turn(order))), QUARTER_TURN_Z)
    returned = _stated("argoverse.utils.transform.yaw_to_quaternion3d", "yaw_to_quaternion3d(a)", "return")
    assert np.allclose(transform.yaw_to_quaternion3d(math.pi / 2), _quarter_turn(str(returned)))
    city_SE3_egovehicle = se3.SE3(rotation=QUARTER_TURN_Z, translation=np.array([1.0, 2.0, 3.0]))
    assert np.allclose(city_SE3_egovehicle.transform_point_cloud(np.array([[1.0, 0.0, 0.0]])), [[1.0, 3.0, 3.0]])
    assert np.allclose(city_SE3_egovehicle.inverse_transform_point_cloud(np.array([[1.0, 3.0, 3.0]])), [[1.0, 0.0, 0.0]])


# -- Waymo Open Dataset ------------------------------------------------------------------------------------------------


def test_waymo_stub_fields_are_the_protos_fields() -> None:
    """The fields the stub states are the generated messages' fields, a pose 16 doubles; box headings and beam
    inclinations are radians (the protos' comments: there is nothing to compute them from without a data file)."""
    dataset_pb2 = pytest.importorskip("waymo_open_dataset.dataset_pb2")
    label_pb2 = pytest.importorskip("waymo_open_dataset.label_pb2")
    stated = {
        ("Frame", "pose"): ("world", "vehicle"),
        ("CameraImage", "pose"): ("world", "vehicle"),
        ("CameraCalibration", "extrinsic"): ("vehicle", "camera"),
        ("LaserCalibration", "extrinsic"): ("vehicle", "lidar"),
    }
    for (message, field), frames in stated.items():
        assert field in getattr(dataset_pb2, message).DESCRIPTOR.fields_by_name
        holder = _attribute(f"waymo_open_dataset.dataset_pb2.{message}.{field}").type_name
        assert _attribute(f"{holder}.transform").frames == frames
    frame = dataset_pb2.Frame()
    frame.pose.transform.extend([1.0, 0.0, 0.0, 5.0, 0.0, 1.0, 0.0, 6.0, 0.0, 0.0, 1.0, 7.0, 0.0, 0.0, 0.0, 1.0])
    assert np.allclose(np.reshape(np.array(frame.pose.transform), [4, 4])[:3, 3], [5.0, 6.0, 7.0])  # row-major
    for field in ("beam_inclinations", "beam_inclination_min", "beam_inclination_max"):
        assert field in dataset_pb2.LaserCalibration.DESCRIPTOR.fields_by_name
        assert _attribute(f"waymo_open_dataset.dataset_pb2.LaserCalibration.{field}").angle_unit == RADIANS
    assert "heading" in label_pb2.Label.Box.DESCRIPTOR.fields_by_name
    assert _stated("waymo_open_dataset.label_pb2.Label.Box", "Box(heading=h)", "heading", "angle_unit") == RADIANS
    assert label_pb2.Label.Box(center_x=1.0, heading=0.5).heading == 0.5
