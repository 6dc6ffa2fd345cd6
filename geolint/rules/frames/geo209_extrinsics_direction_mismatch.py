"""GEO209 extrinsics-direction-mismatch: world-to-camera data used as camera-to-world, or the reverse."""

from __future__ import annotations

from typing import Final

import ast
from ast import AnnAssign, Assign, AsyncFunctionDef, Attribute, Call, FunctionDef, Load, Name, Return, Starred, Subscript

from geolint.factbase import library_calls
from geolint.factbase.extrinsics import (
    DATA,
    CameraPoseText,
    POSE,
    Extrinsic,
    ExtrinsicsEvidence,
    W2C,
    camera_frame_cloud,
    frames_direction,
    key_extrinsic,
    mentions,
    name_extrinsic,
    DIRECTION_WORDS,
    is_blank_matrix,
)
from geolint.factbase.model import FactBase, string, walk_within
from geolint.rules.fact_rule import STATED, FactRule
from geolint.factbase import vocabulary as vocab
from geolint.factbase.vocabulary import is_word_character
from geolint.rules.base import Invalid, Valid
from geolint.rules.triggers import AllOf, AnyOf


# What a shape-only helper reads of an array, and the joins that pad it
_SHAPE_ATTRIBUTES: Final = frozenset({"shape", "ndim", "dtype", "device", "size"})
_JOINS: Final = (*vocab.STACKING_FUNCTIONS, "stack", "vstack")


class _OrbSlamPoseName:
    """ORB-SLAM's `Tcw`, `R_wc`, `twc`: `\b[TRt]_?(?:cw|wc)\b`, found from its rare `cw` / `wc` (the
    regex engine has no literal to scan for in the regex, and tries it at every `t`)."""

    pattern = r"\b[TRt]_?(?:cw|wc)\b"

    def search(self, source: str, /) -> bool:
        for pair in ("cw", "wc"):
            at = source.find(pair)
            while at >= 0:
                lead = at - 2 if at >= 2 and source[at - 1] == "_" else at - 1
                if (
                    lead >= 0
                    and source[lead] in "TRt"
                    and (lead == 0 or not is_word_character(source[lead - 1]))
                    and (at + 2 == len(source) or not is_word_character(source[at + 2]))
                ):
                    return True
                at = source.find(pair, at + 1)
        return False


TRIGGER: Final = AllOf(
    AnyOf(
        r"w2c|c2w|2world|world2|_to_world|world_to_|cam_from_world|qvec|tvec|transform_matrix|projection_center|"
        r"create_from_(?:rgbd|depth)_image|_from_world|world_from_cam",
        _OrbSlamPoseName(),
        CameraPoseText(),
    )
)


class ExtrinsicsDirectionMismatch(FactRule):
    """World-to-camera extrinsics are used where camera-to-world ones are expected, or the reverse.

    ## What it does
    Follows camera poses whose direction the data states and flags where one meets a place that
    states the other direction. Directions come from, strongest first:

    - dataset and file-format keys: BOP `"cam_R_w2c"` / `"cam_t_w2c"` (world to camera), NeRF
      transforms.json `"transform_matrix"` (camera to world), `meta["c2w"]`, `meta["w2c"]`;
    - library attributes: pycolmap `image.cam_from_world` and COLMAP `image.qvec` / `image.tvec` /
      `image.qvec2rotmat()` (world to camera), pycolmap `image.projection_center()` (the camera
      centre, i.e. the camera-to-world translation), and every library attribute whose stub types it
      a pose between a camera and another frame (Blender's `scene.camera.matrix_world`, camera to
      world; av2's `PinholeCamera.extrinsics`, ego to camera; Waymo's calibration `extrinsic`);
    - names that say their direction in the word: `c2w`, `pose_w2c`, `R_c2w`, `world_to_camera`,
      `cam_from_world`, ORB-SLAM's `Tcw` / `Twc`; a `T_a_b` name with one camera frame only where
      the project's naming order is known, and as evidence against a library parameter or another
      name only where the project states it (`naming = "dst-first"`, or its declarations in one
      order).

    Values are followed through local data flow (a name rebound to its own inverse holds the
    inverse from there on), `np.linalg.inv` / `.inverse()`, rotation transposes, `[R | t]`
    concatenations, 4x4 blocks (`T = np.eye(4); T[:3, :3] = R; T[:3, 3] = t`) and the
    hand-written inverse translation `-R.T @ t`.

    Flagged: a 4x4 assembled from blocks whose direction contradicts the matrix's name (the usual
    shape: world-to-camera data inverted by hand into a camera-from-world target); a value stored
    under a name, attribute or key (`frame["transform_matrix"] = ...`, `{"cam_R_w2c": ...}`) of the
    other direction; an argument passed to a parameter or keyword of the other direction
    (`render(c2w=w2c)`); an argument of a library parameter whose stub types it a pose between a
    camera and another frame, in either direction: a camera-to-world pose given as an Open3D
    extrinsic, which is world to camera (TSDF `volume.integrate(rgbd, intrinsic, extrinsic)`,
    `create_from_rgbd_image` / `create_from_depth_image`'s `extrinsic`, `create_camera_visualization`),
    a world-to-camera one given to nerfstudio's `auto_orient_and_center_poses(poses)`; and an Open3D cloud in
    the camera frame (made by those two without an extrinsic) moved by a world-to-camera matrix,
    which only a camera-to-world one can take to the world. pyrender's camera nodes are such library
    parameters: `scene.add(camera, pose=...)` where `camera` is made by a pyrender camera class, and
    `Node(camera=..., matrix=...)`, whose pose maps the camera into the scene (stubs/pyrender).

    ## Why is this bad?
    A world-to-camera pose and its camera-to-world inverse are both 4x4 rigid transforms with
    plausible numbers; nothing fails when one is used for the other. The points come out
    mirrored about the camera, renders look at the wrong place, and merged clouds smear, usually
    in a way that is only obvious for cameras far from the world origin.

    ## Example
    ```python
    import numpy as np

    def camera_from_world(cam_info):
        R = np.array(cam_info["cam_R_w2c"]).reshape(3, 3)
        t = np.array(cam_info["cam_t_w2c"])
        T_cam_world = np.eye(4)
        T_cam_world[:3, :3] = R.T
        T_cam_world[:3, 3] = -R.T @ t
        return T_cam_world
    ```

    ## Use instead
    ```python
    import numpy as np

    def camera_from_world(cam_info):
        T_cam_world = np.eye(4)
        T_cam_world[:3, :3] = np.array(cam_info["cam_R_w2c"]).reshape(3, 3)
        T_cam_world[:3, 3] = np.array(cam_info["cam_t_w2c"])
        return T_cam_world
    ```

    ## Fix safety
    No fix is offered: either the value or the name that receives it is wrong, and only the
    author knows which.

    ## Known problems
    Parameters are read for functions of the project (this module, or a project module it imports)
    and for `self.method(...)` when the module defines one method of that name; a parameter the
    function only pads, measures or returns (`affine_padding(c2w)`) states nothing. A method that
    swaps two poses on purpose (`invert_pose`) is still reported.
    Only conventions stated in the code are used: a pose loaded from a file without a telling key
    (`np.loadtxt(pose_path)`) has no direction. A `T_a_b` target is read in the project's naming
    order and is skipped where the project does not settle it; a `T_a_b` value (`T_world_cam` given
    as an Open3D extrinsic) counts only where the order is stated, so a project that only follows
    one order without saying so is not checked there. A library attribute counts only where its
    owner's class is known (made by the library's constructor, annotated, or held by another known
    attribute): a pycolmap `Image` looked up in `reconstruction.images` is read by the attribute
    names of COLMAP and pycolmap instead (`cam_from_world`, `qvec`, `tvec`), on any object.
    A pyrender camera added to a scene counts only where its class is known (`camera =
    pyrender.IntrinsicsCamera(...)` in the same function): a camera passed in says nothing. Plain name-to-name assignments
    (`c2w = w2c`) are GEO203's; this rule takes what GEO203 cannot see (blocks, keys, arguments,
    library data, Open3D clouds). A "world" that is another camera (a stereo pair's left camera)
    still reads as a world here.
    """

    code = "GEO209"
    name = "extrinsics-direction-mismatch"
    triggers = TRIGGER

    VALID = [
        Valid(
            "import numpy as np\ndef f(info):\n    T_cam_world = np.eye(4)\n"
            "    T_cam_world[:3, :3] = np.array(info['cam_R_w2c']).reshape(3, 3)\n"
            "    T_cam_world[:3, 3] = np.array(info['cam_t_w2c'])\n    return T_cam_world @ T_cam_world\n"
        ),
        Valid("import numpy as np\ndef f(frame):\n    c2w = np.array(frame['transform_matrix'])\n    return c2w\n"),
        Valid("import numpy as np\ndef f(image):\n    w2c = image.cam_from_world.matrix()\n    return w2c\n"),
        Valid(
            "import numpy as np\nimport open3d as o3d\ndef f(rgbd, K, info):\n"
            "    pcd = o3d.geometry.PointCloud.create_from_rgbd_image(rgbd, K)\n"
            "    world2cam = np.eye(4)\n    world2cam[:3, :3] = np.array(info['cam_R_w2c']).reshape(3, 3)\n"
            "    world2cam[:3, 3] = np.array(info['cam_t_w2c'])\n    world2cam = np.linalg.inv(world2cam)\n"
            "    return pcd.transform(world2cam)\n"
        ),
        Valid("def f(image, render):\n    return render(c2w=image.cam_from_world.inverse().matrix())\n"),
        # a helper that only pads its argument to 4x4: the parameter's name is no contract (FP30)
        Valid(
            "import torch\ndef affine_padding(c2w):\n    if c2w.shape[-2] == 4:\n        return c2w\n"
            "    pad = c2w.new_zeros(c2w.shape[:-2] + (1, 4))\n    pad[..., -1] = 1.0\n"
            "    return torch.cat([c2w, pad], dim=-2)\ndef f(output):\n    return affine_padding(output.w2c)\n"
        ),
        # a `T_a_b` target in a project whose naming order nothing settles: no claim
        Valid(
            "import numpy as np\ndef f(info):\n    R = np.array(info['cam_R_w2c']).reshape(3, 3)\n"
            "    H_cam_world = np.eye(4)\n    H_cam_world[:3, :3] = R.T\n    return H_cam_world\n"
        ),
        # a camera-to-world parameter of a stub given a camera-to-world pose
        Valid(
            "from nerfstudio.cameras.camera_utils import auto_orient_and_center_poses\ndef f(image):\n"
            "    return auto_orient_and_center_poses(image.cam_from_world.inverse().matrix())\n"
        ),
        # Blender's camera matrix_world inverted before it is an Open3D extrinsic
        Valid(
            "import bpy\nimport numpy as np\nimport open3d as o3d\ndef f(depth, K):\n"
            "    w2c = np.linalg.inv(np.array(bpy.context.scene.camera.matrix_world))\n"
            "    return o3d.geometry.PointCloud.create_from_depth_image(depth, K, w2c)\n"
        ),
        # a `T_a_b` name in a project that states its naming order, read in it
        Valid(
            "import open3d as o3d\ndef f(depth, K, T_cam_world):\n"
            "    return o3d.geometry.PointCloud.create_from_depth_image(depth, K, T_cam_world)\n",
            options=STATED,
        ),
        # ... and where nothing states the order, no claim
        Valid(
            "import open3d as o3d\ndef f(depth, K, T_world_cam):\n"
            "    return o3d.geometry.PointCloud.create_from_depth_image(depth, K, T_world_cam)\n"
        ),
        # a pyrender camera node given the inverse of a world-to-camera pose; a mesh's pose states no camera
        Valid(
            "import numpy as np\nimport pyrender\ndef f(scene, image, mesh, K):\n"
            "    camera = pyrender.IntrinsicsCamera(fx=K[0, 0], fy=K[1, 1], cx=K[0, 2], cy=K[1, 2])\n"
            "    scene.add(camera, pose=np.linalg.inv(image.cam_from_world.matrix()))\n"
            "    scene.add(pyrender.Mesh.from_trimesh(mesh), pose=image.cam_from_world.matrix())\n"
        ),
    ]
    INVALID = [
        Invalid(
            "import numpy as np\ndef f(info):\n    R = np.array(info['cam_R_w2c']).reshape(3, 3)\n"
            "    t = np.array(info['cam_t_w2c'])\n    w2c = np.eye(4)\n    w2c[:3, :3] = R.T\n"
            "    w2c[:3, 3] = -R.T @ t\n    return w2c\n",
            message="`w2c` is a world-to-camera pose by its name `w2c`, but its blocks are set from a camera-to-world pose (key 'cam_R_w2c' (BOP scene_camera.json: world-to-camera); inverted by `.T`; key 'cam_t_w2c' (BOP scene_camera.json: world-to-camera); inverse translation -R.T @ t): an inverse too many or one missing",
            range=(6, 19, 6, 22),
        ),
        Invalid("import numpy as np\ndef f(frame):\n    frame['pose'].c2w = np.linalg.inv(np.array(frame['transform_matrix']))\n"),
        Invalid("def f(image, frames):\n    frames.append({'transform_matrix': image.cam_from_world.matrix().tolist()})\n"),
        Invalid("def f(image, render):\n    return render(c2w=image.cam_from_world.matrix())\n"),
        Invalid(
            "def camera_center(c2w):\n    return c2w[:3, 3]\ndef f(output):\n    return camera_center(output.w2c)\n",
            message="parameter `c2w` of `camera_center` expects a camera-to-world pose (name `c2w`), but `output.w2c` is a world-to-camera pose (name `w2c`): an inverse is missing or one too many",
            range=(4, 26, 4, 36),
        ),
        Invalid(
            "import open3d as o3d\ndef f(depth, K, image):\n"
            "    pcd = o3d.geometry.PointCloud.create_from_depth_image(depth, K)\n"
            "    return pcd.transform(image.cam_from_world.matrix())\n"
        ),
        # the composition settles dst-first naming: H_cam_world maps world into the camera
        Invalid(
            "import numpy as np\ndef f(info, H_world_obj):\n    R = np.array(info['cam_R_w2c']).reshape(3, 3)\n"
            "    t = np.array(info['cam_t_w2c'])\n    H_cam_world = np.eye(4)\n    H_cam_world[:3, :3] = R.T\n"
            "    H_cam_world[:3, 3] = -R.T @ t\n    return H_cam_world @ H_world_obj\n"
        ),
        # a stub parameter typed camera-to-world (nerfstudio's poses) given a world-to-camera pose
        Invalid(
            "from nerfstudio.cameras.camera_utils import auto_orient_and_center_poses\ndef f(image):\n"
            "    return auto_orient_and_center_poses(image.cam_from_world.matrix())\n",
            message="the `poses` of `camera_utils.auto_orient_and_center_poses` expects a camera-to-world pose (`poses` of "
            "`camera_utils.auto_orient_and_center_poses` maps camera into world (its stub)), but "
            "`image.cam_from_world.matrix()` is a world-to-camera pose (`.cam_from_world` (pycolmap Image.cam_from_world: "
            "world-to-camera)): an inverse is missing or one too many",
            range=(3, 41, 3, 70),
        ),
        # a library attribute its stub types camera-to-world (Blender's camera) given as an Open3D extrinsic
        Invalid(
            "import bpy\nimport numpy as np\nimport open3d as o3d\ndef f(depth, K):\n"
            "    c2w = np.array(bpy.context.scene.camera.matrix_world)\n"
            "    return o3d.geometry.PointCloud.create_from_depth_image(depth, K, c2w)\n",
            message="the `extrinsic` of `PointCloud.create_from_depth_image` expects a world-to-camera pose (`extrinsic` of "
            "`PointCloud.create_from_depth_image` maps world into camera (its stub)), but `c2w` is a camera-to-world pose "
            "(`.matrix_world` (bpy stub: camera-to-world)): an inverse is missing or one too many",
            range=(6, 70, 6, 73),
        ),
        # a `T_a_b` name read in the naming order the project states (`naming = "dst-first"`)
        Invalid(
            "import open3d as o3d\ndef f(depth, K, T_world_cam):\n"
            "    return o3d.geometry.PointCloud.create_from_depth_image(depth, K, T_world_cam)\n",
            options=STATED,
            message="the `extrinsic` of `PointCloud.create_from_depth_image` expects a world-to-camera pose (`extrinsic` of "
            "`PointCloud.create_from_depth_image` maps world into camera (its stub)), but `T_world_cam` is a camera-to-world "
            "pose (name `T_world_cam` (dst-first)): an inverse is missing or one too many",
            range=(3, 70, 3, 81),
        ),
        # a pyrender camera's pose maps the camera into the scene (stubs/pyrender)
        Invalid(
            "import pyrender\ndef f(scene, image, K):\n"
            "    camera = pyrender.IntrinsicsCamera(fx=K[0, 0], fy=K[1, 1], cx=K[0, 2], cy=K[1, 2])\n"
            "    scene.add(camera, pose=image.cam_from_world.matrix())\n",
            message="the `pose` of `Scene.add` expects a camera-to-world pose (`pose` of `Scene.add` maps camera into world "
            "(its stub)), but `image.cam_from_world.matrix()` is a world-to-camera pose (`.cam_from_world` (pycolmap "
            "Image.cam_from_world: world-to-camera)): an inverse is missing or one too many",
            range=(4, 28, 4, 57),
        ),
    ]

    def run(self) -> None:
        facts = self.facts
        self.evidence = ExtrinsicsEvidence(facts)
        for node in facts.index.nodes(Assign, AnnAssign, Call, ast.Dict):
            if isinstance(node, Assign):
                for target in node.targets:
                    self._stored(node, target, node.value)
            elif isinstance(node, AnnAssign):
                if node.value is not None:
                    self._stored(node, node.target, node.value)
            elif isinstance(node, ast.Dict):
                for key, value in zip(node.keys, node.values):
                    stated = key_extrinsic(string(key) or "") if key is not None else None
                    if stated is not None:
                        self._compare(value, stated, f"key {string(key)!r}")
            else:
                self._call(node)  # type: ignore[arg-type]

    # -- sinks -------------------------------------------------------------------------------------
    def _stored(self, statement: Assign | AnnAssign, target: ast.expr, value: ast.expr) -> None:
        if isinstance(target, Subscript):
            key = string(target.slice)
            stated = key_extrinsic(key) if key is not None else None
            if stated is not None and not mentions(value, target):
                self._compare(value, stated, f"key {key!r}")
            return
        name = target.id if isinstance(target, Name) else target.attr if isinstance(target, Attribute) else None
        if name is None:
            return
        stated = name_extrinsic(self.facts, name)
        if stated is None or mentions(value, target):
            return  # `c2w = np.linalg.inv(c2w)`: a name updated from itself holds both directions
        if isinstance(target, Name) and is_blank_matrix(value):
            self._blocks(statement, target, stated)
            return
        if isinstance(target, Name):
            if self.evidence.block_stores(target, binding=id(statement)):
                return  # a start value edited in place: the name describes the value after the edits
            if any(self.facts.frame_fact(value, order) is not None for order in self.facts.readings()):
                return  # frames GEO203 sees and compares
        self._compare(value, stated, f"`{self.code_of(target)}`")

    def _blocks(self, statement: ast.stmt, target: Name, stated: Extrinsic) -> None:
        """`T = np.eye(4); T[:3, :3] = R; T[:3, 3] = t`: the blocks' direction against T's name."""
        parts = self.evidence.block_parts(self.evidence.block_stores(target, binding=id(statement)))
        if not parts or len({part.direction for _, part in parts}) != 1:
            return
        if not all(part.explicit for _, part in parts) or not any(part.strength == DATA for _, part in parts):
            return
        value, part = parts[0]
        if part.direction == stated.direction or stated.part != POSE:
            return
        evidence = tuple(e for _, found in parts for e in found.evidence)
        self.report(
            value,
            f"`{target.id}` is a {stated.description} by its {stated.evidence[0]}, but its blocks are set from a "
            f"{DIRECTION_WORDS[part.direction]} pose ({'; '.join(dict.fromkeys(evidence))}): "
            "an inverse too many or one missing",
            evidence=(*stated.evidence, *evidence),
        )

    def _call(self, call: Call) -> None:
        for keyword in call.keywords:
            if keyword.arg is not None:
                stated = name_extrinsic(self.facts, keyword.arg)
                if stated is not None:
                    self._compare(keyword.value, stated, f"`{keyword.arg}=`", names_both_sides=True)
        defining, function, parameters = self._callee(call)
        if function is not None:
            for argument, parameter in zip(call.args, parameters):
                if isinstance(argument, Starred):
                    break
                stated = name_extrinsic(self.facts, parameter.arg)
                if stated is not None and not _only_reshaped(defining, function, parameter.arg):
                    self._compare(argument, stated, f"parameter `{parameter.arg}` of `{function.name}`", names_both_sides=True)
        for argument, read_as, frames in library_calls.stated_poses(self.facts, call):  # the knowledge base (stubs/)
            direction = frames_direction(frames)
            if direction is not None:
                called = library_calls.called_api(self.facts, call)
                owner = ".".join(called.qualified_name.split(".")[-2:]) if called is not None else read_as
                maps = "world into camera" if direction == W2C else "camera into world"
                stated = Extrinsic(direction, POSE, (f"`{read_as}` of `{owner}` maps {maps} (its stub)",))
                self._compare(argument, stated, f"the `{read_as}` of `{owner}`", names_both_sides=True)
        func = call.func
        if isinstance(func, Attribute) and func.attr == "transform" and len(call.args) == 1 and not call.keywords:
            why = camera_frame_cloud(self.evidence, func.value, call)
            if why is None:
                return
            moved = self.evidence.of(call.args[0])
            if moved is not None and moved.part == POSE and moved.direction == W2C and moved.explicit:
                self.report(
                    call.args[0],
                    f"{why}, but `{self.code_of(call.args[0])}` is a world-to-camera pose "
                    f"({'; '.join(moved.evidence)}): only its inverse (camera-to-world) takes the cloud into the world",
                    evidence=(why, *moved.evidence),
                )

    def _callee(self, call: Call) -> tuple[FactBase, FunctionDef | AsyncFunctionDef | None, list[ast.arg]]:
        """The project function a call runs (`render(...)` of this module or of a project module it
        imports, or `self.render(...)` when one method of the module has that name) and the
        parameters its positional arguments fill, with the fact base of the module that defines it."""
        index = self.facts.index
        func = call.func
        found = self.facts.called_function(call) if isinstance(func, (Name, Attribute)) else None
        if found is not None:
            defining, function = found
            return defining, function, [*function.args.posonlyargs, *function.args.args]
        if isinstance(func, Attribute) and isinstance(func.value, Name) and func.value.id == "self":
            methods = index.methods.get(func.attr, [])
            if len(methods) == 1:
                function = methods[0]
                return self.facts, function, [*function.args.posonlyargs, *function.args.args][1:]
        return self.facts, None, []

    def _compare(self, value: ast.expr, stated: Extrinsic, where: str, names_both_sides: bool = False) -> None:
        actual = self.evidence.of(value)
        if actual is None or not actual.explicit or actual.part != stated.part or actual.direction == stated.direction:
            return
        if actual.strength != DATA and not (names_both_sides and stated.explicit):
            return  # a name against a name is GEO203's, except at a call, which GEO203 does not see
        self.report(
            value,
            f"{where} expects a {stated.description} ({stated.evidence[0]}), but `{self.code_of(value)}` is a "
            f"{actual.description} ({'; '.join(actual.evidence)}): an inverse is missing or one too many",
            evidence=(*stated.evidence, *actual.evidence),
        )


def _only_reshaped(facts: FactBase, function: FunctionDef | AsyncFunctionDef, parameter: str) -> bool:
    """Whether the function does nothing with the parameter that depends on its direction: it only
    reads its shape, dtype or device, joins it with padding, or returns it (`affine_padding(c2w)`,
    which pads any 3x4 to 4x4). Its name is then no contract (FP30). `facts`: its module's."""
    uses = [node for node in walk_within(function) if isinstance(node, Name) and node.id == parameter and isinstance(node.ctx, Load)]
    return bool(uses) and all(_reshaping_use(facts, node) for node in uses)


def _reshaping_use(facts: FactBase, node: Name) -> bool:
    parent = facts.parent(node)
    if isinstance(parent, Attribute):
        return parent.attr in _SHAPE_ATTRIBUTES or (parent.attr.startswith("new_") and isinstance(facts.parent(parent), Call))
    if isinstance(parent, Return):
        return True
    if isinstance(parent, (ast.List, ast.Tuple)):
        joined = facts.parent(parent)
        return isinstance(joined, Call) and facts.is_array_call(joined.func, *_JOINS)
    return isinstance(parent, Call) and isinstance(parent.func, Name) and parent.func.id == "len"
