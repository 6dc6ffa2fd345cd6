"""GEO210 camera-center-from-translation: the translation of a world-to-camera pose taken as the camera centre."""

from __future__ import annotations

import ast

from geolint.factbase.extrinsics import TRANSLATION, W2C, ExtrinsicsEvidence
from geolint.factbase.rule_support import FactRule
from geolint.rules.base import Invalid, Valid
from geolint.rules.frames.geo209_extrinsics_direction_mismatch import TRIGGER

_CENTRE_WORDS = frozenset({"center", "centre", "centers", "centres", "position", "positions", "pos", "location", "loc", "origin", "origins"})
_CAMERA_WORDS = frozenset({"cam", "camera", "cams", "cameras", "c", "view", "viewpoint", "eye"})
_CENTRE_NAMES = frozenset({"center", "centre", "centers", "centres", "campos", "camloc", "eye", "rays_o", "ray_o", "ray_origin", "ray_origins", "rays_origin", "rays_origins"})
# A centre of something else: an object, a box, a target the camera looks at.
_OTHER_THINGS = frozenset(
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
    `center`) assigned the translation part of a world-to-camera pose: BOP's `"cam_t_w2c"`,
    COLMAP's `image.tvec`, pycolmap's `image.cam_from_world.translation`, `w2c[:3, 3]`, or
    `-R.T @ t` of a camera-to-world pose (which is the world-to-camera translation).

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
    Only assignments to a name or attribute that says "camera position" are checked; a
    translation passed straight to a viewer (`look_at(eye=t)`) is not. A `T_a_b` pose counts only
    where the project's naming order is known.
    """

    code = "GEO210"
    name = "camera-center-from-translation"
    triggers = TRIGGER

    VALID = [
        Valid("def f(image):\n    R = image.qvec2rotmat()\n    cam_center = -R.T @ image.tvec\n    return cam_center\n"),
        Valid("def f(image):\n    cam_center = image.projection_center()\n    return cam_center\n"),
        Valid("import numpy as np\ndef f(frame):\n    c2w = np.array(frame['transform_matrix'])\n    rays_o = c2w[:3, 3]\n    return rays_o\n"),
        Valid("import numpy as np\ndef f(gt):\n    obj_center = np.array(gt['cam_t_w2c'])\n    return obj_center\n"),
    ]
    INVALID = [
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
        for node in facts.index.nodes(ast.Assign, ast.AnnAssign):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]  # type: ignore[attr-defined]
            value = node.value  # type: ignore[attr-defined]
            if value is None:
                continue
            for target in targets:
                name = target.id if isinstance(target, ast.Name) else target.attr if isinstance(target, ast.Attribute) else None
                if name is None or not is_camera_centre_name(name):
                    continue
                found = evidence.of(value)
                if found is None or found.part != TRANSLATION or found.direction != W2C or not found.explicit:
                    continue
                self.report(
                    value,
                    f"`{self.code_of(target)}` is a camera position, but `{self.code_of(value)}` is the translation of a "
                    f"world-to-camera pose ({'; '.join(found.evidence)}), i.e. the world origin seen from the camera; "
                    + (
                        "a camera-to-world pose's translation is the centre itself"
                        if any("inverse translation" in e for e in found.evidence)
                        else "the camera centre is -R.T @ t"
                    ),
                    evidence=found.evidence,
                )
