from typing import Annotated, Literal

from geolint.knowledge.markers import CameraAxes, any_receiver
from geolint.typing import QuaternionWXYZ, Radians, TransformMatrix, Translation
from mathutils import Euler

class Object:
    """Source: Blender 5.3.0 (bpy on PyPI), bpy.types.Object.bl_rna.properties: matrix_world "Worldspace transformation
    matrix" (a 4x4 mathutils Matrix: the object's local coordinates into the world; bpy_extras/object_utils.py,
    world_to_camera_view, takes a world point into the object's frame by `obj.matrix_world.normalized().inverted() @
    coord`); rotation_euler "Rotation in Eulers" (subtype EULER, unit ROTATION: radians in Python); rotation_quaternion
    "Rotation in Quaternions" (a mathutils Quaternion, w first); location "Location of the object" (subtype
    TRANSLATION). Checked numerically (tests/knowledge/test_image_and_scene_facts.py)."""

    matrix_world: TransformMatrix[Literal["world"], Literal["object"]]
    rotation_euler: Euler  # a mathutils Euler: its x, y, z are radians (stubs/mathutils)
    rotation_quaternion: QuaternionWXYZ
    location: Translation

class _CameraObject:
    """Not a class of bpy: the Object that `Scene.camera` holds, whose data is a Camera.

    Source: Blender 5.3.0,
    bpy.types.Scene.bl_rna.properties["camera"]: "Active camera, used for rendering the scene"; a camera looks down its
    local -z axis with its y axis up (bpy_extras/object_utils.py, world_to_camera_view: `co_local =
    obj.matrix_world.normalized().inverted() @ coord`, `z = -co_local.z`, "A negative 'z' value means the point is behind
    the camera", and y maps to the frame's top, "(1, 1) is the top right of the camera frame"): its matrix_world is
    camera-to-world in OpenGL camera axes. Checked numerically (tests/knowledge/test_image_and_scene_facts.py)."""

    matrix_world: Annotated[TransformMatrix[Literal["world"], Literal["camera"]], CameraAxes.OPENGL]
    rotation_euler: Euler
    rotation_quaternion: QuaternionWXYZ
    location: Translation
    data: Camera

class Camera:
    """Source: Blender 5.3.0, bpy.types.Camera.bl_rna.properties: angle "Camera lens field of view", angle_x "Camera lens
    horizontal field of view", angle_y "Camera lens vertical field of view", each subtype ANGLE, unit ROTATION (radians
    in Python); lens "Perspective Camera focal length value in millimeters"."""

    angle: Radians
    angle_x: Radians
    angle_y: Radians

class Scene:
    """Source: Blender 5.3.0, bpy.types.Scene.bl_rna.properties["camera"]: "Active camera, used for rendering the scene"."""

    camera: _CameraObject

@any_receiver(when_imported=("bpy",))
class Context:
    """Source: Blender 5.3.0, bpy.types.Context: `scene`, `object` and `active_object` (the context members of the same
    names). Recognised by name on any object in a module that imports bpy: `bpy.context` is a module attribute, and an
    operator's `execute(self, context)` or a panel's `draw(self, context)` is handed the same Context."""

    scene: Scene
    object: Object
    active_object: Object

class BlendDataCameras:
    """Source: Blender 5.3.0, bpy.types.BlendDataCameras.bl_rna.functions["new"]: "Add a new camera to the main database",
    returning "New camera data-block" (a Camera)."""

    def new(self, name: str) -> Camera: ...

@any_receiver(when_imported=("bpy",))
class BlendData:
    """Source: Blender 5.3.0, bpy.types.BlendData: `cameras` (a BlendDataCameras collection). Recognised by name in a
    module that imports bpy, as `bpy.data` is a module attribute."""

    cameras: BlendDataCameras
