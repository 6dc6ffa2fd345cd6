from typing import Annotated, Literal, overload

from geolint.knowledge.markers import CameraAxes, any_receiver
from geolint.typing import TransformMatrix
from pyrender.camera import IntrinsicsCamera, OrthographicCamera, PerspectiveCamera
from pyrender.node import Node

_CameraPose = Annotated[TransformMatrix[Literal["world"], Literal["camera"]], CameraAxes.OPENGL]

@any_receiver(when_imported=("pyrender",))
class Scene:
    """Source: pyrender/scene.py (0.1.45), Scene.add(obj, name=None, pose=None, parent_node=None, parent_name=None): "pose :
    (4,4) float The local pose of this node relative to its parent node", made `Node(name=name, matrix=pose,
    camera=obj)` when `isinstance(obj, Camera)` (`mesh=obj` for a Mesh, `light=obj` for a Light); get_pose(node): "Get
    the world-frame pose of a node in the scene", composing `np.dot(n.matrix, pose)` up to 'world'; set_pose(node, pose):
    "Set the local-frame pose of a node in the scene". The renderer takes `V = np.linalg.inv(pose)  # V maps from world
    to camera` (renderer.py, _get_camera_matrices), and Camera's note (camera.py): "Camera poses are specified in the
    OpenGL format, where the z axis points away from the view direction and the x and y axes point to the right and up
    in the image plane": a camera added as a root node is given its camera-to-world pose in OpenGL camera axes. The
    overloads are told apart by the class of `obj` (one per camera class; any other object, a mesh or a light, states no
    frames), so a pose is read as a camera's only where `obj` is known to be a pyrender camera. A camera added under a
    parent (`parent_node=`, `parent_name=`) is posed relative to the parent: the camera overloads leave those parameters
    out, so such a call binds only the last overload, whose pose states no frames. Recognised by name on any
    object in a module that imports pyrender: a scene is often handed to the function that adds to it. Checked
    numerically (tests/knowledge/test_image_and_scene_facts.py)."""

    @overload
    def add(self, obj: PerspectiveCamera, name: str | None = ..., pose: _CameraPose = ...) -> Node: ...
    @overload
    def add(self, obj: IntrinsicsCamera, name: str | None = ..., pose: _CameraPose = ...) -> Node: ...
    @overload
    def add(self, obj: OrthographicCamera, name: str | None = ..., pose: _CameraPose = ...) -> Node: ...
    @overload
    def add(self, obj: object, name: str | None = ..., pose: TransformMatrix = ..., parent_node: Node | None = ..., parent_name: str | None = ...) -> Node: ...
    def add_node(self, node: Node, parent_node: Node | None = ...) -> None: ...
    def get_pose(self, node: Node) -> TransformMatrix: ...
    def set_pose(self, node: Node, pose: TransformMatrix) -> None: ...
