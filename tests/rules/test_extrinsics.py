"""Camera extrinsics conventions stated by data (geolint.factbase.extrinsics) and the rules on them
(GEO209, GEO210, GEO216): which way a pose maps, and which way its camera axes point, is read from keys,
library attributes, blocks, inverses and names, and a `T_a_b` name counts only in the order the project
settles."""

from __future__ import annotations

import ast
import textwrap
from pathlib import Path

import pytest

from geolint import api
from geolint.factbase import dataflow, facts_for_module
from geolint.factbase.extrinsics import (
    C2W,
    DATA,
    NAME,
    OPENCV,
    OPENGL,
    POSE,
    ROTATION,
    TRANSLATION,
    W2C,
    ExtrinsicsEvidence,
    camera_pose_attributes,
    frames_direction,
    name_extrinsic,
)
from geolint.knowledge import knowledge_base
from geolint.lint_types import Config, NamingConventions


def returned(code: str) -> tuple[str, str, str] | None:
    """(direction, part, strength) of the value the last `return` of `code` returns."""
    source = textwrap.dedent(code)
    tree = ast.parse(source)
    facts = facts_for_module(tree, source, "<test>", Config())
    evidence = ExtrinsicsEvidence(facts)
    value = [node for node in ast.walk(tree) if isinstance(node, ast.Return)][-1].value
    found = evidence.of(value)
    return None if found is None else (found.direction, found.part, found.strength)


@pytest.mark.parametrize(
    ("code", "expected"),
    [
        # BOP keys, through np.array / reshape / unit scaling
        ("def f(info):\n    R = np.array(info['cam_R_w2c']).reshape(3, 3)\n    return R\n", (W2C, ROTATION, DATA)),
        ("def f(info):\n    t = np.array(info['cam_t_w2c']) * 0.001\n    return t\n", (W2C, TRANSLATION, DATA)),
        # the hand-written inverse: R.T and -R.T @ t are the camera-to-world parts
        ("def f(info):\n    R = np.array(info['cam_R_w2c']).reshape(3, 3)\n    return R.T\n", (C2W, ROTATION, DATA)),
        (
            "def f(info):\n    R = np.array(info['cam_R_w2c']).reshape(3, 3)\n    t = np.array(info['cam_t_w2c'])\n"
            "    return -R.T @ t\n",
            (C2W, TRANSLATION, DATA),
        ),
        (
            "def f(info):\n    R = np.array(info['cam_R_w2c']).reshape(3, 3)\n    t = np.array(info['cam_t_w2c'])\n"
            "    return -t @ R\n",
            (C2W, TRANSLATION, DATA),
        ),
        # a 4x4 assembled from blocks, then inverted
        (
            "def f(info):\n    T = np.eye(4)\n    T[:3, :3] = np.array(info['cam_R_w2c']).reshape(3, 3)\n"
            "    T[:3, 3] = np.array(info['cam_t_w2c'])\n    return np.linalg.inv(T)\n",
            (C2W, POSE, DATA),
        ),
        # flow-sensitive: a name rebound to its own inverse holds the inverse from there on
        (
            "def f(info, pcd):\n    world2cam = np.eye(4)\n    world2cam[:3, :3] = np.array(info['cam_R_w2c']).reshape(3, 3)\n"
            "    world2cam = np.linalg.inv(world2cam)\n    return world2cam\n",
            (C2W, POSE, DATA),
        ),
        # COLMAP: [R | t] from qvec2rotmat() and tvec, with the bottom row
        (
            "def f(image):\n    bottom = np.array([[0, 0, 0, 1.0]])\n    R = image.qvec2rotmat()\n    t = image.tvec.reshape([3, 1])\n"
            "    m = np.concatenate([np.concatenate([R, t], 1), bottom], 0)\n    return m\n",
            (W2C, POSE, DATA),
        ),
        ("def f(image):\n    return qvec2rotmat(image.qvec)\n", (W2C, ROTATION, DATA)),
        # pycolmap
        ("def f(image):\n    return image.cam_from_world.matrix()\n", (W2C, POSE, DATA)),
        ("def f(image):\n    return image.cam_from_world.inverse().matrix()\n", (C2W, POSE, DATA)),
        ("def f(image):\n    return image.cam_from_world().rotation.matrix()\n", (W2C, ROTATION, DATA)),
        ("def f(image):\n    return image.projection_center()\n", (C2W, TRANSLATION, DATA)),
        # NeRF transforms.json, sliced and with axes permuted
        ("def f(frame):\n    c2w = np.array(frame['transform_matrix'])[:3, :4]\n    return c2w[[1, 0, 2]]\n", (C2W, POSE, DATA)),
        ("def f(frame):\n    return np.array(frame['transform_matrix'])[:3, 3]\n", (C2W, TRANSLATION, DATA)),
        # names that say their direction: the weakest evidence, used only when the data says nothing
        ("def f(pose_c2w):\n    return pose_c2w\n", (C2W, POSE, NAME)),
        ("def f(Tcw):\n    return Tcw\n", (W2C, POSE, NAME)),
        ("def f(R_w2c):\n    return R_w2c.T\n", (C2W, ROTATION, NAME)),
        ("def f(world_to_camera):\n    return world_to_camera\n", (W2C, POSE, NAME)),
    ],
)
def test_direction_from_evidence(code: str, expected: tuple[str, str, str]) -> None:
    assert returned(code) == expected


@pytest.mark.parametrize(
    "code",
    [
        "def f(pose):\n    return pose\n",  # no evidence
        "def f(info):\n    return np.array(info['cam_t_w2c']).T\n",  # a translation has no transpose direction
        "def f(image):\n    return image.cam_from_world.matrix().T\n",  # a pose's transpose is not its inverse
        # blocks that disagree (a half inverse, GEO205's business): no direction
        "def f(info):\n    T = np.eye(4)\n    T[:3, :3] = np.array(info['cam_R_w2c']).reshape(3, 3).T\n"
        "    T[:3, 3] = np.array(info['cam_t_w2c'])\n    return T\n",
        # the relative pose of two cameras is not an extrinsic (FP7: frames belong to their owners)
        "def f(image0, image1):\n    return image1.cam_from_world * image0.cam_from_world.inverse()\n",
        # `R.T @ t` without the minus is no camera centre
        "def f(info):\n    R = np.array(info['cam_R_w2c']).reshape(3, 3)\n    t = np.array(info['cam_t_w2c'])\n    return R.T @ t\n",
    ],
)
def test_no_direction_without_evidence(code: str) -> None:
    assert returned(code) is None


def test_t_a_b_names_count_only_in_a_settled_order() -> None:
    def facts_of(source: str):  # type: ignore[no-untyped-def]
        tree = ast.parse(source)
        return facts_for_module(tree, source, "<test>", Config())

    unsettled = facts_of("x = 1\n")
    assert name_extrinsic(unsettled, "H_cam_world") is None
    assert name_extrinsic(unsettled, "c2w").direction == C2W  # the word says it in any order
    dst_first = facts_of("T_cam_obj = T_cam_world @ T_world_obj\n")
    assert name_extrinsic(dst_first, "H_camZ_V").direction == W2C  # maps V into camera Z
    src_first = facts_of("T_obj_world = RigidTransform(R, t, from_frame='obj', to_frame='world')\n")
    assert name_extrinsic(src_first, "T_cam_world").direction == C2W  # autolab_core: cam -> world


def test_a_t_a_b_name_is_explicit_only_where_the_project_states_its_order() -> None:
    source = "x = 1\n"
    tree = ast.parse(source)
    stated = facts_for_module(tree, source, "<test>", Config(naming=NamingConventions(order="dst-first")))
    found = name_extrinsic(stated, "T_world_cam")
    assert found is not None and (found.direction, found.explicit) == (C2W, True)
    assert found.inverted("inverse").explicit  # carried through what follows the value
    # settled by the module's own products, not stated: a reading, never evidence against a stub
    chained = "T_cam_obj = T_cam_world @ T_world_obj\n"
    learned = facts_for_module(ast.parse(chained), chained, "<test>", Config())
    found = name_extrinsic(learned, "T_world_cam")
    assert found is not None and found.direction == C2W and not found.explicit


@pytest.mark.parametrize(
    ("frames", "expected"),
    [
        (("camera", "world"), W2C),
        (("world", "camera"), C2W),
        (("camera", "egovehicle"), W2C),  # av2's extrinsics: ego to camera
        (("vehicle", "camera"), C2W),  # Waymo's calibration: camera to vehicle
        (("world", "object"), None),  # Blender's Object.matrix_world: no camera
        (("camera", "camera"), None),
        (("camera",), None),
    ],
)
def test_the_direction_of_stub_frames(frames: tuple[str, ...], expected: str | None) -> None:
    assert frames_direction(frames) == expected


def returned_extrinsic(code: str) -> tuple[str, str, str | None] | None:
    """(direction, part, camera axes) of the value the last `return` of `code` returns."""
    source = textwrap.dedent(code)
    tree = ast.parse(source)
    found = ExtrinsicsEvidence(facts_for_module(tree, source, "<test>", Config())).of(
        [node for node in ast.walk(tree) if isinstance(node, ast.Return)][-1].value
    )
    return None if found is None else (found.direction, found.part, found.axes.convention if found.axes else None)


@pytest.mark.parametrize(
    ("code", "expected"),
    [
        # Blender: the scene's camera object is camera-to-world in OpenGL axes (stubs/bpy)
        ("import bpy\ndef f():\n    return bpy.context.scene.camera.matrix_world\n", (C2W, POSE, OPENGL)),
        ("import bpy\nimport numpy as np\ndef f():\n    cam = bpy.context.scene.camera\n    return np.linalg.inv(np.array(cam.matrix_world))\n", (W2C, POSE, OPENGL)),
        # av2: a camera's extrinsics map the ego vehicle into the camera, in OpenCV axes (stubs/av2)
        (
            "from av2.geometry.camera.pinhole_camera import PinholeCamera\ndef f(ego_SE3_cam, K):\n"
            "    camera = PinholeCamera(ego_SE3_cam, K, 'ring_front_center')\n    return camera.extrinsics[:3, :3]\n",
            (W2C, ROTATION, OPENCV),
        ),
        # Waymo: a camera's calibration extrinsic maps the camera into the vehicle; no camera axes stated
        (
            "import numpy as np\nfrom waymo_open_dataset import dataset_pb2\ndef f(calibration: dataset_pb2.CameraCalibration):\n"
            "    return np.array(calibration.extrinsic.transform).reshape(4, 4)\n",
            (C2W, POSE, None),
        ),
    ],
)
def test_library_attributes_state_what_their_stubs_say(code: str, expected: tuple[str, str, str | None]) -> None:
    assert returned_extrinsic(code) == expected


def test_a_stub_attribute_without_a_camera_states_nothing() -> None:
    # Blender's Object.matrix_world maps any object into the world: no camera in its frames
    assert returned_extrinsic("import bpy\ndef f(name):\n    return bpy.data.objects[name].matrix_world\n") is None
    names = camera_pose_attributes(knowledge_base())
    assert {"matrix_world", "extrinsics", "transform"} <= names


BOP_PROJECT = '''
import json
import numpy as np


def load_scene_camera(path):
    with open(path) as stream:
        return json.load(stream)


def camera_from_world(cam_info):
    cam_rot = np.array(cam_info["cam_R_w2c"]).reshape(3, 3)
    cam_trans = np.array(cam_info["cam_t_w2c"])
    T_cam_world = np.eye(4)
    T_cam_world[:3, :3] = cam_rot.T
    T_cam_world[:3, 3] = -cam_rot.T @ cam_trans
    return T_cam_world


def object_in_camera(cam_info, T_world_obj):
    return camera_from_world(cam_info) @ T_world_obj
'''


def _lint_project(tmp_path: Path, body: str, extra: str = "") -> set[tuple[int, str]]:
    (tmp_path / "pyproject.toml").write_text("[project]\nname = 'bop_tools'\n")
    module = tmp_path / "bop_tools.py"
    module.write_text(body + extra)
    findings = [f for result in api.lint_paths([tmp_path], config=Config(select=("GEO209", "GEO210"))) for f in result.findings]
    return {(f.line, f.code) for f in findings}


def test_inverted_w2c_in_a_dst_first_project_is_flagged(tmp_path: Path) -> None:
    extra = "\n\ndef chain(T_cam_world, T_world_obj):\n    T_cam_obj = T_cam_world @ T_world_obj\n    return T_cam_obj\n"
    assert _lint_project(tmp_path, BOP_PROJECT, extra) == {(15, "GEO209")}


def test_the_same_code_in_a_src_first_project_is_silent(tmp_path: Path) -> None:
    # autolab_core style: T_cam_world maps the camera into the world, which is what the blocks build
    extra = "\n\nT_obj_world = RigidTransform(R, t, from_frame='obj', to_frame='world')\n"
    assert _lint_project(tmp_path, BOP_PROJECT, extra) == set()


def test_unsettled_order_is_silent(tmp_path: Path) -> None:
    assert _lint_project(tmp_path, BOP_PROJECT) == set()


def test_project_order_counts_h_and_x_names(tmp_path: Path) -> None:
    from geolint.factbase.conventions import project_votes

    (tmp_path / "setup.py").write_text("")
    (tmp_path / "annotate.py").write_text("def chain(H_camZ_V, H_V_obj):\n    return H_camZ_V @ H_V_obj\n")
    assert project_votes(tmp_path).orders() == ("dst-first",)


def _codes(source: str) -> set[tuple[int, str]]:
    findings = api.lint_text(textwrap.dedent(source), "fusion.py", Config(select=("GEO209", "GEO210")))
    return {(f.line, f.code) for f in findings}


def test_open3d_extrinsics_are_world_to_camera() -> None:
    source = """
    import numpy as np
    import open3d as o3d

    def fuse(rgbd, depth, intrinsic, frame, volume_args):
        volume = o3d.pipelines.integration.UniformTSDFVolume(**volume_args)
        c2w = np.array(frame["transform_matrix"])
        volume.integrate(rgbd, intrinsic, c2w)
        volume.integrate(rgbd, intrinsic, np.linalg.inv(c2w))
        cloud = o3d.geometry.PointCloud.create_from_depth_image(depth, intrinsic, extrinsic=c2w)
        cloud_ok = o3d.geometry.PointCloud.create_from_depth_image(depth, intrinsic, np.linalg.inv(c2w))
        other = SomeVolume()
        other.integrate(rgbd, intrinsic, c2w)  # not Open3D's: no claim
        return cloud, cloud_ok
    """
    assert _codes(source) == {(8, "GEO209"), (10, "GEO209")}


def test_a_cloud_moved_before_is_no_longer_known_to_be_in_the_camera_frame() -> None:
    source = """
    import numpy as np
    import open3d as o3d

    def fuse(rgbd, intrinsic, image, flip):
        pcd = o3d.geometry.PointCloud.create_from_rgbd_image(rgbd, intrinsic)
        w2c = image.cam_from_world.matrix()
        pcd.transform(w2c)
        other = o3d.geometry.PointCloud.create_from_rgbd_image(rgbd, intrinsic)
        other.transform(flip)
        other.transform(w2c)
        return pcd, other
    """
    assert _codes(source) == {(8, "GEO209")}


def test_a_method_parameter_states_what_it_expects() -> None:
    source = """
    import numpy as np

    class NerfDataset:
        def __init__(self, meta, H, W, focal):
            self.rays = []
            for frame in meta["frames"]:
                pose = np.array(frame["transform_matrix"], dtype=np.float32)
                w2c = np.linalg.inv(pose)
                self.rays.append(self.get_rays(H, W, focal, w2c))
                self.rays.append(self.get_rays(H, W, focal, pose))

        def get_rays(self, H, W, focal, c2w):
            return H, W, focal, c2w
    """
    assert _codes(source) == {(10, "GEO209")}


def test_a_helper_of_another_project_module_states_what_it_expects(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text("[project]\nname = 'tiny_nerf'\n")
    package = tmp_path / "tiny_nerf"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "rays.py").write_text(
        "import torch\n\n\ndef get_rays(H, W, focal, c2w):\n"
        "    i, j = torch.meshgrid(torch.arange(W), torch.arange(H), indexing='xy')\n"
        "    dirs = torch.stack([(i - W * 0.5) / focal, -(j - H * 0.5) / focal, -torch.ones_like(i)], -1)\n"
        "    return c2w[:3, 3].expand(dirs.shape), dirs @ c2w[:3, :3].T\n"
    )
    (package / "data.py").write_text(
        "import numpy as np\nimport torch\n\nfrom tiny_nerf import rays\nfrom tiny_nerf.rays import get_rays\n\n\n"
        "def load(meta, H, W, focal):\n    out = []\n    for frame in meta['frames']:\n"
        "        pose = torch.from_numpy(np.array(frame['transform_matrix'], dtype=np.float32))\n"
        "        out.append(get_rays(H, W, focal, pose))\n"
        "        out.append(get_rays(H, W, focal, torch.linalg.inv(pose)))\n"
        "        out.append(rays.get_rays(H, W, focal, torch.linalg.inv(pose)))\n"
        "    return out\n"
    )
    findings = [f for result in api.lint_paths([tmp_path], config=Config(select=("GEO209",)), use_cache=False) for f in result.findings]
    assert {(Path(f.path).name, f.line) for f in findings} == {("data.py", 13), ("data.py", 14)}


def test_a_pyrender_camera_pose_is_camera_to_world() -> None:
    source = """
    import numpy as np
    import pyrender

    def render(scene_camera, mesh, K, H, W):
        scene = pyrender.Scene()
        camera = pyrender.IntrinsicsCamera(fx=K[0, 0], fy=K[1, 1], cx=K[0, 2], cy=K[1, 2])
        w2c = np.eye(4)
        w2c[:3, :3] = np.array(scene_camera["cam_R_w2c"]).reshape(3, 3)
        w2c[:3, 3] = np.array(scene_camera["cam_t_w2c"])
        scene.add(camera, pose=w2c)
        scene.add(camera, pose=np.linalg.inv(w2c))
        scene.add(pyrender.Mesh.from_trimesh(mesh), pose=w2c)  # a mesh given in world coordinates: fine
        return pyrender.OffscreenRenderer(W, H).render(scene)
    """
    assert _codes(source) == {(11, "GEO209")}


def returned_axes(code: str) -> tuple[str, str] | None:
    """(camera axes, direction) of the value the last `return` of `code` returns."""
    source = textwrap.dedent(code)
    tree = ast.parse(source)
    evidence = ExtrinsicsEvidence(facts_for_module(tree, source, "<test>", Config()))
    found = evidence.of([node for node in ast.walk(tree) if isinstance(node, ast.Return)][-1].value)
    return None if found is None or found.axes is None else (found.axes.convention, found.direction)


@pytest.mark.parametrize(
    ("code", "expected"),
    [
        # COLMAP data is in OpenCV axes; an inverse is the same camera, so the same axes
        ("def f(image):\n    return image.cam_from_world.matrix()\n", (OPENCV, W2C)),
        ("def f(image):\n    return np.linalg.inv(image.cam_from_world.matrix())\n", (OPENCV, C2W)),
        (
            "def f(image):\n    w2c = np.eye(4)\n    w2c[:3, :3] = image.qvec2rotmat()\n    w2c[:3, 3] = image.tvec\n"
            "    return np.linalg.inv(w2c)\n",
            (OPENCV, C2W),
        ),
        # transforms.json poses are in OpenGL axes; BOP's in OpenCV axes
        ("def f(frame):\n    c2w = np.array(frame['transform_matrix'])\n    return c2w[:3, :3]\n", (OPENGL, C2W)),
        ("def f(info):\n    return np.array(info['cam_R_w2c']).reshape(3, 3).T\n", (OPENCV, C2W)),
        # a name that states its direction may state its axes
        ("def f(c2w_opengl):\n    return c2w_opengl\n", (OPENGL, C2W)),
        ("def f(w2c_cv):\n    return w2c_cv\n", (OPENCV, W2C)),
    ],
)
def test_camera_axes_from_evidence(code: str, expected: tuple[str, str]) -> None:
    assert returned_axes(code) == expected


@pytest.mark.parametrize(
    "code",
    [
        # converted in place, before or after the read (a stored array is a reference)
        "def f(frame):\n    c2w = np.array(frame['transform_matrix'])\n    c2w[:3, 1:3] *= -1\n    return c2w\n",
        "def f(frame):\n    c2w = np.array(frame['transform_matrix'])\n    c2w[:3, 1] = -c2w[:3, 1]\n    return c2w\n",
        "def f(frame, out):\n    c2w = np.array(frame['transform_matrix'])\n    out.append(c2w)\n    c2w[:3, 1:3] *= -1\n    return c2w\n",
        # columns permuted, or multiplied by any matrix
        "def f(frame):\n    c2w = np.array(frame['transform_matrix'])\n    return c2w[:, [1, 0, 2, 3]]\n",
        "def f(frame, flip):\n    return np.array(frame['transform_matrix']) @ flip\n",
        # blocks of different or unknown axes
        "def f(image, frame):\n    T = np.eye(4)\n    T[:3, :3] = image.qvec2rotmat()\n    T[:3, 3] = np.array(frame['transform_matrix'])[:3, 3]\n    return T\n",
        "def f(image, R):\n    T = np.eye(4)\n    T[:3, :3] = R\n    T[:3, 3] = image.tvec\n    return T\n",
        # a direction but no axes in the name
        "def f(c2w):\n    return c2w\n",
    ],
)
def test_no_camera_axes_without_evidence(code: str) -> None:
    assert returned_axes(code) is None


def test_an_item_update_is_an_in_place_write() -> None:
    source = "def f(c2w, T):\n    c2w[:3, 1:3] *= -1\n    T[:3, 3] = 0\n"
    tree = ast.parse(source)
    facts = facts_for_module(tree, source, "<test>", Config())
    scope = facts.index.scope_of([node for node in ast.walk(tree) if isinstance(node, ast.AugAssign)][0])
    assert scope.item_augmented == {"c2w"}
    assert "c2w" not in scope.subscript_stores  # no block is stored: GEO209's blocks stay what they were
    assert dataflow.writes_into(facts.index, scope, "c2w") and dataflow.updates_in_place(facts.index, scope, "c2w")
    assert dataflow.writes_into(facts.index, scope, "T") and not dataflow.updates_in_place(facts.index, scope, "T")
