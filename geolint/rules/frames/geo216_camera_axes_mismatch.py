"""GEO216 camera-axes-mismatch: a camera pose in one camera-axes convention used where another is expected."""

from __future__ import annotations

import ast
from ast import AnnAssign, Assign, Attribute, BinOp, Call, Name, Starred, Subscript
from typing import Final, NamedTuple

from geolint.algebra import Kind
from geolint.factbase import dataflow, library_calls
from geolint.factbase.camera_rays import CAMERA_RAYS, ray_axes, rotated_rays
from geolint.factbase.extrinsics import (
    C2W,
    DATA,
    OPENCV,
    OPENGL,
    POSE,
    PYTORCH3D,
    ROTATION,
    W2C,
    Axes,
    CameraPoseText,
    Extrinsic,
    ExtrinsicsEvidence,
    frames_direction,
    key_extrinsic,
    mentions,
    name_extrinsic,
)
from geolint.factbase.model import string
from geolint.knowledge import Geometry
from geolint.rules.base import Invalid, Valid
from geolint.rules.fact_rule import FactRule
from geolint.rules.triggers import AllOf, AnyOf

TRIGGER: Final = AllOf(
    AnyOf(
        r"transform_matrix|qvec|tvec|cam_from_world|cam_R_w2c|projection_center|"
        r"opencv|opengl|OpenCV|OpenGL|blender|colmap|pytorch3d|p3d|_gl|_cv|gl_|cv_",
        CameraPoseText(),
    )
)

# The camera axes (0 x, 1 y, 2 z) that point the other way between two conventions.
_FLIPPED: Final = {
    frozenset({OPENCV, OPENGL}): (1, 2),
    frozenset({OPENCV, PYTORCH3D}): (0, 1),
    frozenset({OPENGL, PYTORCH3D}): (0, 2),
}
_AXIS_NAMES: Final = "xyz"
_AXIS_SLICES: Final = {(1, 2): "1:3", (0, 1): ":2", (0, 2): "[0, 2]"}


class _Expected(NamedTuple):
    """What a sink takes: a pose (part) of a direction (None: either), in stated camera axes."""

    direction: str | None
    part: str
    axes: Axes
    verb: str = "expects"


class CameraAxesMismatch(FactRule):
    """A camera pose whose camera axes follow one convention is used where another convention is expected.

    ## What it does
    Follows camera poses whose camera axes the data states and flags where one meets a place that
    states other axes. OpenCV axes (x right, y down, z forward) are those of COLMAP (`image.qvec`,
    `image.tvec`, `image.qvec2rotmat()`, pycolmap's `image.cam_from_world`), BOP (`"cam_R_w2c"`), the
    extrinsics Open3D takes and av2's `PinholeCamera.extrinsics`; OpenGL axes (x right, y up, z back)
    those of NeRF transforms.json's `"transform_matrix"`, nerfstudio's camera poses, pyrender's camera
    nodes (`scene.add(camera, pose=...)`) and Blender's `scene.camera.matrix_world` (any library attribute or parameter whose stub states `CameraAxes`); a name that says its direction may say its
    axes too (`c2w_opengl`, `w2c_cv`, `pose_c2w_p3d`). Pixel ray directions state the axes they are
    built in by their signs: `[(u - cx) / fx, (v - cy) / fy, 1]` OpenCV, `[(u - cx) / fx, -(v - cy) / fy,
    -1]` OpenGL, `[-(u - cx) / fx, -(v - cy) / fy, 1]` PyTorch3D. Values are followed as GEO209 follows
    them (data flow, inverses, transposes, `[R | t]` joins, 4x4 blocks); an inverse keeps the camera's
    axes.

    Flagged: a pose stored under `"transform_matrix"` (a dict literal or a subscript store) or under a
    name, keyword or library parameter that states other axes than the pose has, when at least one
    side is data (not two names); a camera-to-world rotation that rotates ray directions built in
    other axes (`sum(dirs[..., None, :] * c2w[:3, :3], -1)`, `dirs @ R.T`, `R @ dirs`), also when the
    rays are built and rotated in a project function (`get_rays(H, W, K, c2w)`) and the pose is
    passed to it.

    ## Why is this bad?
    An OpenCV camera and an OpenGL camera at the same place differ by a half-turn about their x axis:
    the same 4x4 numbers put the camera looking backwards and upside down. Renders come out empty,
    NeRF and Gaussian-splatting training never converges, TSDF fusion carves nothing, and nothing
    fails: converting COLMAP output to transforms.json without negating two columns is the classic
    form.

    ## Example
    ```python
    import numpy as np

    def to_frame(image, R, name):
        w2c = np.concatenate([np.concatenate([image.qvec2rotmat(), image.tvec[:, None]], 1), [[0, 0, 0, 1]]], 0)
        c2w = np.linalg.inv(w2c)
        return {"file_path": name, "transform_matrix": c2w.tolist()}
    ```

    ## Use instead
    ```python
    import numpy as np

    def to_frame(image, R, name):
        w2c = np.concatenate([np.concatenate([image.qvec2rotmat(), image.tvec[:, None]], 1), [[0, 0, 0, 1]]], 0)
        c2w = np.linalg.inv(w2c)
        c2w[:3, 1:3] *= -1  # OpenCV camera axes to OpenGL's
        return {"file_path": name, "transform_matrix": c2w.tolist()}
    ```

    ## Fix safety
    No fix is offered: the conversion may belong before the pose is inverted, or the sink may be the
    wrong one.

    ## Known problems
    Any in-place write into the array (`c2w[:3, 1:3] *= -1`, `c2w[:, 1] = -c2w[:, 1]`), a product with
    any matrix (`c2w @ flip`), a column permutation or a call to a project function is taken as a
    conversion, right or wrong, so a conversion to the wrong convention passes. Ray directions are
    read where they are built; rays built by one helper (`get_ray_directions(H, W, focal)`) and
    rotated by another (`get_rays(directions, c2w)`) are not followed yet.
    A project that stores OpenCV poses under `"transform_matrix"` on purpose, read only by its own
    code, is reported; say so with `# noqa: GEO216` on the store. A library attribute states its axes
    only where its owner's class is known (made by its constructor, annotated, or held by another
    known attribute, as `bpy.context.scene.camera`).
    """

    code = "GEO216"
    name = "camera-axes-mismatch"
    triggers = TRIGGER

    VALID = [
        # the usual conversion: two camera axes negated in place
        Valid(
            "import numpy as np\ndef f(image):\n    w2c = np.eye(4)\n    w2c[:3, :3] = image.qvec2rotmat()\n"
            "    w2c[:3, 3] = image.tvec\n    c2w = np.linalg.inv(w2c)\n    c2w[0:3, 1:3] *= -1\n"
            "    return {'transform_matrix': c2w.tolist()}\n"
        ),
        # transforms.json read and written back: the same axes
        Valid("import numpy as np\ndef f(frame, out):\n    c2w = np.array(frame['transform_matrix'])\n    out['transform_matrix'] = c2w.tolist()\n"),
        # converted by a product with a flip matrix
        Valid(
            "import numpy as np\nFLIP = np.diag([1, -1, -1, 1])\ndef f(image):\n"
            "    c2w = np.linalg.inv(image.cam_from_world.matrix()) @ FLIP\n    return {'transform_matrix': c2w}\n"
        ),
        # a wrong direction is GEO209's, not also this rule's
        Valid("def f(image):\n    return {'transform_matrix': image.cam_from_world.matrix()}\n"),
        # two names: no data states either side
        Valid("def f(c2w_cv):\n    c2w_gl = c2w_cv\n    return c2w_gl\n"),
        # OpenGL rays rotated by a transforms.json pose: the same axes
        Valid(
            "import numpy as np\ndef f(frame, i, j, focal, W, H):\n    c2w = np.array(frame['transform_matrix'])\n"
            "    dirs = np.stack([(i - W * 0.5) / focal, -(j - H * 0.5) / focal, -np.ones_like(i)], -1)\n"
            "    return np.sum(dirs[..., None, :] * c2w[:3, :3], -1)\n"
        ),
        # a helper written for OpenGL rays, given a COLMAP pose converted first
        Valid(
            "import numpy as np\ndef get_rays(i, j, K, c2w):\n"
            "    dirs = np.stack([(i - K[0][2]) / K[0][0], -(j - K[1][2]) / K[1][1], -np.ones_like(i)], -1)\n"
            "    return np.sum(dirs[..., None, :] * c2w[:3, :3], -1)\n"
            "def f(image, i, j, K):\n    c2w = np.linalg.inv(image.cam_from_world.matrix())\n    c2w[:3, 1:3] *= -1\n"
            "    return get_rays(i, j, K, c2w)\n"
        ),
        # a library attribute in OpenCV axes (av2's camera extrinsics), converted before a stub that takes OpenGL axes
        Valid(
            "import numpy as np\nfrom av2.geometry.camera.pinhole_camera import PinholeCamera\n"
            "from nerfstudio.cameras.camera_utils import auto_orient_and_center_poses\n"
            "def f(ego_SE3_cam, intrinsics):\n    camera = PinholeCamera(ego_SE3_cam, intrinsics, 'ring_front_center')\n"
            "    c2w = np.linalg.inv(camera.extrinsics) @ np.diag([1, -1, -1, 1])\n    return auto_orient_and_center_poses(c2w)\n"
        ),
    ]
    INVALID = [
        Invalid(
            "import numpy as np\ndef f(image, name):\n    w2c = np.eye(4)\n    w2c[:3, :3] = image.qvec2rotmat()\n"
            "    w2c[:3, 3] = image.tvec\n    c2w = np.linalg.inv(w2c)\n"
            "    return {'file_path': name, 'transform_matrix': c2w.tolist()}\n",
            message="`c2w.tolist()` is a camera-to-world pose in OpenCV axes (x right, y down, z forward) (`.qvec2rotmat()` "
            "(COLMAP Image.qvec2rotmat())), but key 'transform_matrix' expects OpenGL axes (x right, y up, z back) "
            "(NeRF transforms.json): its y and z axes point the other way; negate them first (`c2w[:3, 1:3] *= -1`)",
            range=(7, 52, 7, 64),
        ),
        Invalid(
            "import numpy as np\nimport open3d as o3d\ndef f(rgbd, K, frame):\n"
            "    volume = o3d.pipelines.integration.ScalableTSDFVolume(voxel_length=0.01, sdf_trunc=0.04)\n"
            "    w2c = np.linalg.inv(np.array(frame['transform_matrix']))\n    volume.integrate(rgbd, K, w2c)\n",
            message="`w2c` is a world-to-camera pose in OpenGL axes (x right, y up, z back) (key 'transform_matrix' (NeRF "
            "transforms.json)), but the `extrinsic` of `ScalableTSDFVolume.integrate` expects OpenCV axes (x right, y down, "
            "z forward) (its stub): its y and z axes point the other way; negate them first (`w2c[1:3, :] *= -1`)"
        ),
        Invalid(
            "import numpy as np\ndef f(info, frames):\n    R = np.array(info['cam_R_w2c']).reshape(3, 3)\n"
            "    t = np.array(info['cam_t_w2c'])\n    c2w = np.eye(4)\n    c2w[:3, :3] = R.T\n    c2w[:3, 3] = -R.T @ t\n"
            "    frames.append({'transform_matrix': c2w.tolist()})\n"
        ),
        Invalid(
            "def f(image):\n    c2w_gl = image.cam_from_world.inverse().matrix()\n    return c2w_gl\n",
            message="`image.cam_from_world.inverse().matrix()` is a camera-to-world pose in OpenCV axes (x right, y down, "
            "z forward) (`.cam_from_world` (pycolmap Image.cam_from_world)), but `c2w_gl` expects OpenGL axes (x right, "
            "y up, z back) (name `c2w_gl`): its y and z axes point the other way; negate them first (`c2w[:3, 1:3] *= -1`)",
            range=(2, 14, 2, 53),
        ),
        Invalid(
            "import numpy as np\ndef f(frame, u, v, fx, fy, cx, cy):\n    c2w = np.array(frame['transform_matrix'])\n"
            "    dirs = np.stack([(u - cx) / fx, (v - cy) / fy, np.ones_like(u)], axis=-1)\n    return dirs @ c2w[:3, :3].T\n",
            message="`c2w[:3, :3]` is a camera-to-world rotation in OpenGL axes (x right, y up, z back) (key 'transform_matrix' "
            "(NeRF transforms.json)), but the ray directions it rotates are built in OpenCV axes (x right, y down, z forward) "
            "(ray directions `np.stack([(u - cx) / fx, (v - cy) / fy, np.ones_like(u)],...`): its y and z axes point the "
            "other way; negate them first (`c2w[:3, 1:3] *= -1`)",
            range=(5, 19, 5, 30),
        ),
        Invalid(
            "import numpy as np\ndef get_rays(i, j, K, c2w):\n"
            "    dirs = np.stack([(i - K[0][2]) / K[0][0], -(j - K[1][2]) / K[1][1], -np.ones_like(i)], -1)\n"
            "    return np.sum(dirs[..., None, :] * c2w[:3, :3], -1)\n"
            "def f(image, i, j, K):\n    c2w = np.linalg.inv(image.cam_from_world.matrix())\n"
            "    return get_rays(i, j, K, c2w)\n",
            range=(7, 30, 7, 33),
        ),
        # the same, unconverted: av2's extrinsics are in OpenCV axes by its stub, nerfstudio's poses in OpenGL's
        Invalid(
            "import numpy as np\nfrom av2.geometry.camera.pinhole_camera import PinholeCamera\n"
            "from nerfstudio.cameras.camera_utils import auto_orient_and_center_poses\n"
            "def f(ego_SE3_cam, intrinsics):\n    camera = PinholeCamera(ego_SE3_cam, intrinsics, 'ring_front_center')\n"
            "    c2w = np.linalg.inv(camera.extrinsics)\n    return auto_orient_and_center_poses(c2w)\n",
            message="`c2w` is a camera-to-world pose in OpenCV axes (x right, y down, z forward) (`.extrinsics` (av2 stub)), "
            "but the `poses` of `camera_utils.auto_orient_and_center_poses` expects OpenGL axes (x right, y up, z back) "
            "(its stub): its y and z axes point the other way; negate them first (`c2w[:3, 1:3] *= -1`)",
            range=(7, 41, 7, 44),
        ),
        # Blender's camera (OpenGL axes by its stub) inverted into an Open3D extrinsic (OpenCV axes)
        Invalid(
            "import bpy\nimport numpy as np\nimport open3d as o3d\ndef f(rgbd, K, volume):\n"
            "    w2c = np.linalg.inv(np.array(bpy.context.scene.camera.matrix_world))\n"
            "    fused = o3d.pipelines.integration.ScalableTSDFVolume(voxel_length=0.01, sdf_trunc=0.04)\n"
            "    fused.integrate(rgbd, K, w2c)\n"
        ),
    ]

    def run(self) -> None:
        facts = self.facts
        self.evidence = ExtrinsicsEvidence(facts)
        for node in facts.index.nodes(Assign, AnnAssign, Call, ast.Dict, BinOp):
            if isinstance(node, (Call, BinOp)):
                self._rays(node)
            if isinstance(node, BinOp):
                continue
            if isinstance(node, Assign):
                for target in node.targets:
                    self._stored(target, node.value)
            elif isinstance(node, AnnAssign):
                if node.value is not None:
                    self._stored(node.target, node.value)
            elif isinstance(node, ast.Dict):
                for key, value in zip(node.keys, node.values):
                    self._keyed(string(key) if key is not None else None, value)
            else:
                self._call(node)  # type: ignore[arg-type]

    # -- sinks -------------------------------------------------------------------------------------
    def _keyed(self, key: str | None, value: ast.expr) -> None:
        stated = key_extrinsic(key) if key is not None else None
        if stated is not None and stated.axes is not None:
            self._compare(value, _Expected(stated.direction, stated.part, stated.axes), f"key {key!r}")

    def _stored(self, target: ast.expr, value: ast.expr) -> None:
        if mentions(value, target):
            return  # `c2w = c2w @ flip`, `f["transform_matrix"] = convert(f["transform_matrix"])`
        if isinstance(target, Subscript):
            self._keyed(string(target.slice), value)
            return
        name = target.id if isinstance(target, Name) else target.attr if isinstance(target, Attribute) else None
        stated = name_extrinsic(self.facts, name) if name is not None else None
        if stated is None or stated.axes is None:
            return
        if isinstance(target, Name) and dataflow.writes_into(self.facts.index, self.facts.index.scope_of(target), target.id):
            return  # a start value edited in place: the name describes the value after the edits
        self._compare(value, _Expected(stated.direction, stated.part, stated.axes), f"`{self.code_of(target)}`")

    def _call(self, call: Call) -> None:
        self._project_call(call)
        for keyword in call.keywords:
            stated = name_extrinsic(self.facts, keyword.arg) if keyword.arg is not None else None
            if stated is not None and stated.axes is not None:
                self._compare(keyword.value, _Expected(stated.direction, stated.part, stated.axes), f"`{keyword.arg}=`")
        stated_by_stub = library_calls.stated_camera_axes(self.facts, call)
        called = library_calls.called_api(self.facts, call) if stated_by_stub else None
        for argument, parameter, geometry in stated_by_stub:
            owner = ".".join(called.qualified_name.split(".")[-2:]) if called is not None else parameter
            expected = _expected_by_stub(geometry, "its stub")
            if expected is not None:
                self._compare(argument, expected, f"the `{parameter}` of `{owner}`")

    def _rays(self, node: Call | BinOp) -> None:
        """Ray directions built in one convention, rotated by a camera-to-world rotation of another."""
        rotated = rotated_rays(self.facts, node)
        axes = ray_axes(self.facts, rotated[0]) if rotated is not None else None
        if rotated is not None and axes is not None:
            self._compare(rotated[1], _Expected(C2W, ROTATION, axes, "are built in"), "the ray directions it rotates")

    def _project_call(self, call: Call) -> None:
        """A project function that rotates rays by a parameter expects a camera-to-world pose in their axes there."""
        if not self.facts.may_have_summary(call):
            return
        summary = self.facts.summary_of(call, CAMERA_RAYS)
        if summary is None or not summary.rotates_rays:
            return
        for index, argument in enumerate(call.args):
            if isinstance(argument, Starred):
                break
            stated = summary.rotates_rays.get(index)
            if stated is not None:
                part, axes = stated
                where = f"parameter `{summary.parameters[index]}` of `{self.code_of(call.func)}`"
                self._compare(argument, _Expected(C2W, part, axes), where)
        for keyword in call.keywords:
            if keyword.arg in summary.parameters:
                stated = summary.rotates_rays.get(summary.parameters.index(keyword.arg))
                if stated is not None:
                    where = f"parameter `{keyword.arg}` of `{self.code_of(call.func)}`"
                    self._compare(keyword.value, _Expected(C2W, stated[0], stated[1]), where)

    def _compare(self, value: ast.expr, expected: _Expected, where: str) -> None:
        actual = self.evidence.of(value)
        if actual is None or actual.axes is None or actual.part != expected.part or expected.part not in (POSE, ROTATION):
            return  # a camera-to-world translation (the camera centre) has no camera axes
        if expected.direction is not None and actual.direction != expected.direction:
            return  # a direction mismatch is GEO209's
        have, want = actual.axes, expected.axes
        if have.convention == want.convention or DATA not in (have.strength, want.strength):
            return
        flipped = _FLIPPED[frozenset({have.convention, want.convention})]
        stated_source = want.source.removeprefix(f"{where} (").removesuffix(")") if want.source.startswith(f"{where} (") else want.source
        self.report(
            value,
            f"`{self.code_of(value)}` is a {_pose_words(actual)} in {have.description} ({have.source}), but {where} {expected.verb} "
            f"{want.description} ({stated_source}): its {' and '.join(_AXIS_NAMES[axis] for axis in flipped)} axes point "
            f"the other way; negate them first ({_negation(value, actual, flipped)})",
            evidence=tuple(dict.fromkeys((*actual.evidence, have.source, want.source))),
        )


def _expected_by_stub(geometry: Geometry, source: str) -> _Expected | None:
    """A stub's `Annotated[TransformMatrix["camera", "world"], CameraAxes.OPENCV]` as a sink."""
    part = POSE if geometry.kind is Kind.TRANSFORM else ROTATION if geometry.kind is Kind.ROTATION else None
    if part is None or geometry.camera_axes is None:
        return None
    return _Expected(frames_direction(geometry.frames), part, Axes(geometry.camera_axes, source))


def _pose_words(found: Extrinsic) -> str:
    return {C2W: "camera-to-world", W2C: "world-to-camera"}[found.direction] + (" pose" if found.part == POSE else " rotation")


def _negation(value: ast.expr, found: Extrinsic, flipped: tuple[int, int]) -> str:
    """The in-place edit that changes a pose's camera axes: its columns when it maps from the camera,
    its rows when it maps into it."""
    axes = _AXIS_SLICES[flipped]
    name = value.id if isinstance(value, Name) else found.direction if found.part == POSE else "R"
    if found.part == ROTATION and isinstance(value, Subscript) and isinstance(value.value, Name):
        name, found = value.value.id, found.as_part(POSE)  # `c2w[:3, :3]`: the pose it is the block of
    if found.direction == C2W:
        return f"`{name}[:3, {axes}] *= -1`" if found.part == POSE else f"`{name}[:, {axes}] *= -1`"
    return f"`{name}[{axes}, :] *= -1`"
