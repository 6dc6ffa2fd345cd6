from geolint.typing import Radians

class PerspectiveCamera:
    """Source: pyrender/camera.py (0.1.45), PerspectiveCamera(yfov, znear=0.05, zfar=None, aspectRatio=None, name=None): "yfov
    : float The floating-point vertical field of view in radians"; get_projection_matrix uses `np.tan(self.yfov / 2.0)`.
    Camera (the base class): "Camera poses are specified in the OpenGL format, where the z axis points away from the view
    direction and the x and y axes point to the right and up in the image plane, respectively." Checked numerically
    (tests/knowledge/test_image_and_scene_facts.py)."""

    def __init__(self, yfov: Radians, znear: float = ..., zfar: float | None = ..., aspectRatio: float | None = ..., name: str | None = ...) -> None: ...

class IntrinsicsCamera:
    """Source: pyrender/camera.py (0.1.45), IntrinsicsCamera(fx, fy, cx, cy, znear=0.05, zfar=100.0, name=None): "fx : float
    X-axis focal length in pixels", "cx : float X-axis optical center in pixels"; its get_projection_matrix sets
    `P[3][2] = -1.0` (clip w = -z: what it sees lies along the camera's -z) and `P[1][2] = 2.0 * cy / height - 1.0`, so a
    pixel row v = cy + fy * y / z in the image's top-down rows for a point in OpenCV-style axes: the intrinsics are
    OpenCV's K, the pose (Camera's note) OpenGL's. The vocabulary states no intrinsics: nothing is stated but the
    class. Checked numerically (tests/knowledge/test_image_and_scene_facts.py)."""

    def __init__(self, fx: float, fy: float, cx: float, cy: float, znear: float = ..., zfar: float = ..., name: str | None = ...) -> None: ...

class OrthographicCamera:
    """Source: pyrender/camera.py (0.1.45), OrthographicCamera(xmag, ymag, znear=0.05, zfar=100.0, name=None), a Camera:
    its pose is in the OpenGL format of Camera's note (see PerspectiveCamera). The vocabulary states no magnification:
    nothing is stated but the class, which tells `Scene.add`'s overloads apart."""

    def __init__(self, xmag: float, ymag: float, znear: float = ..., zfar: float = ..., name: str | None = ...) -> None: ...
