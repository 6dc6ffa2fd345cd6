from typing import Annotated, Literal, overload

from geolint.knowledge.markers import CameraAxes
from geolint.typing import QuaternionXYZW, TransformMatrix, Translation

class Node:
    """Source: pyrender/node.py (0.1.45), Node(name=None, camera=None, children=None, skin=None, matrix=None, mesh=None,
    rotation=None, scale=None, translation=None, weights=None, light=None): "matrix : (4,4) float, optional A
    floating-point 4x4 transformation matrix", "rotation : (4,) float, optional The node's unit quaternion in the order
    (x, y, z, w), where w is the scalar" (the default is `np.array([0.0, 0.0, 0.0, 1.0])`), "translation : (3,) float".
    The matrix maps the node into its parent: Scene.get_pose composes `np.dot(n.matrix, pose)` up to 'world', and the
    renderer takes `V = np.linalg.inv(pose)  # V maps from world to camera` (renderer.py, _get_camera_matrices), in
    pyrender's OpenGL camera axes (camera.py, Camera). A node given a camera (the first overload) is that camera's pose
    in the world (for a root node; under a parent it is relative to the parent); a node without one (a mesh, a light)
    has no camera axes. Checked numerically (tests/knowledge/test_image_and_scene_facts.py)."""

    @overload
    def __init__(
        self, name: str | None = ..., *, camera: object, children: object = ..., skin: object = ...,
        matrix: Annotated[TransformMatrix[Literal["world"], Literal["camera"]], CameraAxes.OPENGL] = ..., mesh: object = ...,
        rotation: QuaternionXYZW = ..., scale: object = ..., translation: Translation = ..., weights: object = ..., light: object = ...,
    ) -> None: ...
    @overload
    def __init__(
        self, name: str | None = ..., *, children: object = ..., skin: object = ..., matrix: TransformMatrix = ..., mesh: object = ...,
        rotation: QuaternionXYZW = ..., scale: object = ..., translation: Translation = ..., weights: object = ..., light: object = ...,
    ) -> None: ...
    @property
    def rotation(self) -> QuaternionXYZW: ...
    @property
    def matrix(self) -> TransformMatrix: ...
