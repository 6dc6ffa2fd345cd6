from geolint.typing import PointArray, RotationMatrix, TransformMatrix, Translation

class SE3:
    """Source: argoverse/utils/se3.py (argoverse-api 1.1.0, commit f886ac5), SE3(rotation, translation): "rotation: Array of
    shape (3, 3)", "translation: Array of shape (3,)", `self.transform_matrix` the 4x4 [R | t]; transform_point_cloud: "If
    the transform represents dst_SE3_src, then point_cloud should consist of points in frame `src`", `point_cloud @
    self.rotation.T + self.translation`; inverse_transform_point_cloud: "Undo the translation and then the rotation",
    `(point_cloud.copy() - self.translation) @ self.rotation`; inverse: "if the current object represents
    target_SE3_src, we will return instead src_SE3_target"; compose and right_multiply_with_se3: "chained_se3 = T *
    right_se3". Checked numerically, where argoverse imports (tests/knowledge/test_image_and_scene_facts.py)."""

    rotation: RotationMatrix
    translation: Translation
    transform_matrix: TransformMatrix
    def __init__(self, rotation: RotationMatrix, translation: Translation) -> None: ...
    def transform_point_cloud(self: TransformMatrix, point_cloud: PointArray) -> PointArray: ...
    def inverse_transform_point_cloud(self: TransformMatrix, point_cloud: PointArray) -> PointArray: ...
    def inverse(self) -> SE3: ...
    def compose(self, right_se3: SE3) -> SE3: ...
    def right_multiply_with_se3(self, right_se3: SE3) -> SE3: ...
