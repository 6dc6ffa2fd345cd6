"""GEO210 camera-center-from-translation: the translation of a world-to-camera pose taken as the camera centre."""

from __future__ import annotations

import ast
from ast import (
    AST,
    AnnAssign,
    Assign,
    AsyncFunctionDef,
    Attribute,
    AugAssign,
    BinOp,
    Call,
    ClassDef,
    Compare,
    Constant,
    FunctionDef,
    Lambda,
    Name,
    Return,
    Starred,
    Store,
    Subscript,
)
from typing import Final, TYPE_CHECKING

from geolint.factbase.extrinsics import (
    DATA,
    EXTRINSIC_ATTRIBUTES,
    TRANSLATION,
    W2C,
    Extrinsic,
    ExtrinsicsEvidence,
)
from geolint.factbase.pose_parts import call_name, int_value
from geolint.factbase.reaching import value_of

if TYPE_CHECKING:
    from geolint.factbase.model import FactBase
from geolint.rules.fact_rule import FactRule
from geolint.rules.base import Invalid, Valid
from geolint.rules.frames.geo209_extrinsics_direction_mismatch import TRIGGER

_CENTRE_WORDS: Final = frozenset({"center", "centre", "centers", "centres", "position", "positions", "pos", "location", "loc", "origin", "origins"})
_CAMERA_WORDS: Final = frozenset({"cam", "camera", "cams", "cameras", "c", "view", "viewpoint", "eye"})
_CENTRE_NAMES: Final = frozenset({"center", "centre", "centers", "centres", "campos", "camloc", "eye", "rays_o", "ray_o", "ray_origin", "ray_origins", "rays_origin", "rays_origins"})
# A centre of something else: an object, a box, a target the camera looks at.
_OTHER_THINGS: Final = frozenset(
    {"obj", "object", "objects", "model", "mesh", "bbox", "box", "target", "goal", "light", "lookat", "look", "scene",
     "principal", "pp", "image", "img", "pixel", "grid", "voxel", "bound", "bounds", "aabb", "rotation", "world"}
)  # fmt: skip


def is_camera_centre_name(name: str) -> bool:
    """`cam_center`, `camera_position`, `campos`, `rays_o`, `center`: where the camera is."""
    lowered = name.strip("_").lower()
    if lowered in _CENTRE_NAMES:
        return True
    tokens = [token.rstrip("0123456789") for token in lowered.split("_")]
    if not tokens or any(token in _OTHER_THINGS for token in tokens):
        return False
    return any(token in _CENTRE_WORDS for token in tokens) and any(token in _CAMERA_WORDS for token in tokens)


class CameraCenterFromTranslation(FactRule):
    """The translation of a world-to-camera pose is stored as the camera's position.

    ## What it does
    Flags a camera centre or position (`cam_center`, `camera_position`, `campos`, `rays_o`,
    `center`, a `"camera_position"` key, an `eye=` keyword) assigned the translation part of a
    world-to-camera pose: BOP's `"cam_t_w2c"`, COLMAP's `image.tvec`, pycolmap's
    `image.cam_from_world.translation`, `w2c[:3, 3]`, or `-R.T @ t` of a camera-to-world pose
    (which is the world-to-camera translation). A plain `"location"` / `"position"` key or keyword
    counts too when the translation is known from data (a dataset key such as BOP's, not a name
    alone). The value is followed through `list()`, local names, and a project helper that only
    reorders or negates the axes of its argument (`[p[0], -p[2], p[1]]`, a static method too).

    ## Why is this bad?
    A world-to-camera pose maps a world point p to R p + t. The camera centre C is the point that
    maps to the origin, so t = -R C and C = -Rᵀ t: t is the world origin seen from the camera,
    not where the camera is. The two agree only for a camera that does not rotate and sits at
    the origin, so rays, distances and viewer placements come out plausible and wrong.

    ## Example
    ```python
    R = image.qvec2rotmat()
    cam_center = image.tvec
    ```

    ## Use instead
    ```python
    R = image.qvec2rotmat()
    cam_center = -R.T @ image.tvec          # or pycolmap's image.projection_center()
    ```

    ## Fix safety
    No fix is offered: the rotation that `-R.T @ t` needs is not always at hand.

    ## Known problems
    Only assignments to a name or attribute that says "camera position", and keys or keywords
    named as above, are checked; a translation passed positionally to a viewer (`look_at(t, ...)`)
    is not. A `T_a_b` pose counts only where the project's naming order is known. A helper that
    does more than relabel axes (scales, adds, applies a matrix) ends the chain.
    """

    code = "GEO210"
    name = "camera-center-from-translation"
    triggers = TRIGGER

    VALID = [
        Valid("def f(image):\n    R = image.qvec2rotmat()\n    cam_center = -R.T @ image.tvec\n    return cam_center\n"),
        Valid("def f(image):\n    cam_center = image.projection_center()\n    return cam_center\n"),
        Valid("import numpy as np\ndef f(frame):\n    c2w = np.array(frame['transform_matrix'])\n    rays_o = c2w[:3, 3]\n    return rays_o\n"),
        Valid("import numpy as np\ndef f(gt):\n    obj_center = np.array(gt['cam_t_w2c'])\n    return obj_center\n"),
        Valid(
            "import numpy as np\ndef to_json(R, t):\n    Rt = np.eye(4)\n    Rt[:3, :3] = R.T\n    Rt[:3, 3] = t\n"
            "    W2C = np.linalg.inv(Rt)\n    return {'position': W2C[:3, 3].tolist()}\n"
        ),  # a plain key, and only a name says w2c (here the inverse of a w2c: the name is wrong)
        Valid("def f(marker):\n    return {'position': marker.tvec}\n"),  # OpenCV's tvec: the marker in the camera
        Valid(
            "import numpy as np\ndef scaled(p):\n    return [p[0] * 0.01, p[1] * 0.01, p[2] * 0.01]\n"
            "def f(sc):\n    t = np.array(sc['cam_t_w2c'])\n    return {'location': scaled(t)}\n"
        ),  # arithmetic on the components: not a relabelling, the chain ends
    ]
    INVALID = [
        Invalid(
            "import numpy as np\ndef to_blender(p):\n    return [p[0], -p[2], p[1]]\n"
            "def f(sc, cameras):\n    cam_H_w2c = np.eye(4)\n    cam_H_w2c[:3, :3] = np.array(sc['cam_R_w2c']).reshape(3, 3)\n"
            "    cam_H_w2c[:3, 3] = np.array(sc['cam_t_w2c'])\n    pos = to_blender(list(cam_H_w2c[:3, 3]))\n"
            "    cameras.append({'location': pos, 'rotation': cam_H_w2c[:3, :3]})\n",
            message="the key 'location' is a camera position, but `pos` is the translation of a world-to-camera pose (key 'cam_R_w2c' (BOP scene_camera.json: world-to-camera); key 'cam_t_w2c' (BOP scene_camera.json: world-to-camera); axes relabelled by `to_blender`), i.e. the world origin seen from the camera; the camera centre is -R.T @ t",
            range=(9, 33, 9, 36),
        ),
        Invalid("def f(image, viewer):\n    viewer.look_at(eye=image.tvec, target=(0, 0, 0))\n"),
        Invalid("def f(image):\n    cam_center = image.tvec\n    return cam_center\n"),
        Invalid("import numpy as np\ndef f(info):\n    camera_position = np.array(info['cam_t_w2c']).reshape(3)\n    return camera_position\n"),
        Invalid("def f(image, viewer):\n    viewer.camera_position = image.cam_from_world.translation\n"),
        Invalid(
            "import numpy as np\ndef f(frame):\n    c2w = np.array(frame['transform_matrix'])\n"
            "    R, t = c2w[:3, :3], c2w[:3, 3]\n    center = -R.T @ t\n    return center\n"
        ),
    ]

    def run(self) -> None:
        facts = self.facts
        evidence = ExtrinsicsEvidence(facts)
        for node in facts.index.nodes(Assign, AnnAssign, ast.Dict, Call):
            if isinstance(node, ast.Dict):
                for key, item in zip(node.keys, node.values):
                    if isinstance(key, Constant) and isinstance(key.value, str) and _is_position_key(key.value):
                        self._check(evidence, key, item, is_camera_centre_name(key.value))
                continue
            if isinstance(node, Call):
                for keyword in node.keywords:
                    if keyword.arg is not None and _is_position_key(keyword.arg):
                        self._check(evidence, keyword, keyword.value, is_camera_centre_name(keyword.arg))
                continue
            targets = node.targets if isinstance(node, Assign) else [node.target]  # type: ignore[attr-defined]
            value = node.value  # type: ignore[attr-defined]
            if value is None:
                continue
            for target in targets:
                name = target.id if isinstance(target, Name) else target.attr if isinstance(target, Attribute) else None
                if name is None or not is_camera_centre_name(name):
                    continue
                self._check(evidence, target, value, True)

    def _check(self, evidence: ExtrinsicsEvidence, destination: AST, value: ast.expr, says_camera: bool) -> None:
        """`says_camera`: the destination names a camera position (`cam_center`); a plain `location` /
        `position` key or keyword does not, so then only data evidence counts (BOP keys, COLMAP's
        `tvec`), never a name alone (`W2C = np.linalg.inv(Rt)` in code whose names are not to be trusted)."""
        found = self._translation(evidence, value, 4)
        if found is None or found.part != TRANSLATION or found.direction != W2C or not found.explicit:
            return
        if not says_camera and (found.strength != DATA or any(_AMBIGUOUS_SOURCE in e for e in found.evidence)):
            return  # `{"position": marker.tvec}`: OpenCV's tvec is an object's position in the camera
        if isinstance(destination, Constant):
            where = f"the key {destination.value!r}"
        elif isinstance(destination, ast.keyword):
            where = f"`{destination.arg}=`"
        else:
            where = f"`{self.code_of(destination)}`"
        self.report(
            value,
            f"{where} is a camera position, but `{self.code_of(value)}` is the translation of a "
            f"world-to-camera pose ({'; '.join(found.evidence)}), i.e. the world origin seen from the camera; "
            + (
                "a camera-to-world pose's translation is the centre itself"
                if any("inverse translation" in e for e in found.evidence)
                else "the camera centre is -R.T @ t"
            ),
            evidence=found.evidence,
        )

    def _translation(self, evidence: ExtrinsicsEvidence, value: ast.expr, depth: int) -> Extrinsic | None:
        """What `value` is, also through `list()` / `tuple()`, a local name, and a project helper that
        only relabels the axes of its first argument (`to_blender_axes(t)`: `[p[0], -p[2], p[1]]`)."""
        found = evidence.of(value)
        if found is not None or depth <= 0:
            return found
        if isinstance(value, Name):
            held = value_of(self.facts.index, value)
            return self._translation(evidence, held, depth - 1) if isinstance(held, ast.expr) else None
        if not isinstance(value, Call) or not value.args or isinstance(value.args[0], Starred):
            return None
        if call_name(value) in ("list", "tuple", "Vector") and len(value.args) == 1:
            return self._translation(evidence, value.args[0], depth - 1)
        callee = self.facts.called_function(value) or self._static_method(value)
        if callee is None or not relabels_axes(callee[0].index.parents, callee[1]):
            return None
        inner = self._translation(evidence, value.args[0], depth - 1)
        if inner is None:
            return None
        return Extrinsic(inner.direction, inner.part, (*inner.evidence, f"axes relabelled by `{call_name(value)}`"), inner.strength)

    def _static_method(self, call: Call) -> tuple[FactBase, FunctionDef | AsyncFunctionDef] | None:
        """`Utility.to_blender_axes(p)` with `Utility` a class of this module or imported from a project
        module: its static method (`called_function` resolves module functions only)."""
        func = call.func
        if not (isinstance(func, Attribute) and isinstance(func.value, Name)):
            return None
        qualified = self.facts.index.imports.get(func.value.id)
        found = self.facts.defining_module(qualified, self.facts.path) if qualified else (self.facts, func.value.id)
        if found is None:
            return None
        other, class_name = found
        for statement in other.index.tree.body:
            if isinstance(statement, ClassDef) and statement.name == class_name:
                for method in statement.body:
                    if (
                        isinstance(method, (FunctionDef, AsyncFunctionDef))
                        and method.name == func.attr
                        and any(isinstance(d, Name) and d.id == "staticmethod" for d in method.decorator_list)
                    ):
                        return other, method
        return None


# `.tvec` read as COLMAP's is evidence enough under a camera name, not under a plain `position` key.
_AMBIGUOUS_SOURCE: Final = EXTRINSIC_ATTRIBUTES["tvec"][2]
# Keys and keywords of a position in the world (`{"location": ...}`, `look_at(eye=...)`).
_POSITION_KEYS: Final = frozenset({"location", "position", "eye"})


def _is_position_key(key: str) -> bool:
    return key in _POSITION_KEYS or is_camera_centre_name(key)


def relabels_axes(parents: dict[AST, AST], function: FunctionDef | AsyncFunctionDef) -> bool:
    """The function returns its first argument with axes reordered or negated, nothing else: it reads
    the argument only as `p[0]`, `p[1]`, `p[2]`, `p[i]` (or passes it to `isinstance` / `len`), never in
    arithmetic other than a negation, and returns something that is not a constant."""
    params = [*function.args.posonlyargs, *function.args.args]
    if params and params[0].arg in ("self", "cls"):
        params = params[1:]
    if not params:
        return False
    name = params[0].arg
    indexed = False
    returns = False
    for node in ast.walk(function):
        if isinstance(node, Return):
            if node.value is None or isinstance(node.value, Constant):
                return False
            returns = True
        if isinstance(node, (FunctionDef, AsyncFunctionDef, Lambda)) and node is not function:
            return False
        if not (isinstance(node, Name) and node.id == name):
            continue
        if isinstance(node.ctx, Store):
            return False  # rebound
        parent = parents.get(node)
        if isinstance(parent, Subscript) and parent.value is node and (int_value(parent.slice) in (0, 1, 2) or isinstance(parent.slice, Name)):
            indexed = True
            grand = parents.get(parent)
            if isinstance(grand, (BinOp, AugAssign, Compare)):
                return False  # arithmetic on a component: more than a relabelling
            continue
        if isinstance(parent, Call) and call_name(parent) in ("isinstance", "len", "type") and node in parent.args:
            continue
        if isinstance(parent, ast.arg):
            continue
        return False
    return indexed and returns
