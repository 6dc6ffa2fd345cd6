from geolint.typing import Degrees, RotationMatrix, RotationVector

def getRotationMatrix2D(center: object, angle: Degrees, scale: float) -> object:
    """Source: OpenCV imgproc reference, getRotationMatrix2D: "angle: Rotation angle in degrees. Positive
    values mean counter-clockwise rotation (the coordinate origin is assumed to be the top-left corner)"
    (docs.opencv.org, group__imgproc__transform); checked numerically (tests/knowledge/test_opencv_facts.py)."""

def Rodrigues(src: RotationVector, dst: object = ..., jacobian: object = ...) -> tuple[RotationMatrix, object]:
    """Source: OpenCV calib3d reference, Rodrigues: "src: Input rotation vector (3x1 or 1x3) or rotation
    matrix (3x3)"; the vector's norm is the angle in radians (theta <- norm(r)). Checked numerically."""
