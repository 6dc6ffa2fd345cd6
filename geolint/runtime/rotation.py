"""Rotation matrices and quaternions: validation, projection onto SO(3), conversions with an explicit order.

A rotation is valid when it is orthonormal within a tolerance (max |R^T R - I| <= tolerance, default
`DEFAULT_TOLERANCE` = 1e-6) and has determinant +1 (a determinant of -1 is a reflection). Every failure says
by how much it failed. Quaternion conversions take ``order`` ("xyzw", scipy/ROS; or "wxyz", pytransform3d/
Eigen's constructor) with no default, because mixing the two is a classic silent bug.

All functions accept one matrix (3, 3) / quaternion (4,) or a batch (N, 3, 3) / (N, 4).
"""

from __future__ import annotations

from typing import Literal

import numpy as np

from geolint.runtime.errors import GeometryValueError, InvalidRotationError

__all__ = [
    "DEFAULT_TOLERANCE",
    "ORTHONORMALIZE_LIMIT",
    "QuatOrder",
    "orthonormality_error",
    "validate_rotation",
    "orthonormalize",
    "quat_to_matrix",
    "matrix_to_quat",
    "slerp",
]

DEFAULT_TOLERANCE = 1e-6
# orthonormalize() repairs noise, not garbage: beyond this deviation the input was never a rotation.
ORTHONORMALIZE_LIMIT = 0.1

QuatOrder = Literal["xyzw", "wxyz"]
_ORDERS = ("xyzw", "wxyz")


def orthonormality_error(rotation: np.ndarray) -> np.ndarray:
    """max |R^T R - I| per matrix: a float array of shape () or (N,)."""
    gram = np.swapaxes(rotation, -1, -2) @ rotation
    return np.abs(gram - np.eye(3)).max(axis=(-2, -1))  # type: ignore[no-any-return]


def _where(index: int, batch: bool) -> str:
    return f" (matrix {index} of the batch)" if batch else ""


def validate_rotation(rotation: np.ndarray, tolerance: float = DEFAULT_TOLERANCE, owner: str = "rotation") -> None:
    """Raise `InvalidRotationError` unless every matrix is orthonormal within ``tolerance`` with det +1.

    Parameters
    ----------
    rotation : ndarray, shape (3, 3) or (N, 3, 3)
        Finite float matrices.
    tolerance : float
        Largest accepted max |R^T R - I|.
    """
    if rotation.size == 0:  # an empty batch has nothing to check
        return
    batch = rotation.ndim == 3
    errors = np.atleast_1d(orthonormality_error(rotation))
    worst = int(np.argmax(errors))
    if errors[worst] > tolerance:
        raise InvalidRotationError(
            f"{owner}: the rotation is not orthonormal{_where(worst, batch)}: max |R^T R - I| = "
            f"{errors[worst]:.3g}, above the tolerance {tolerance:g}; pass orthonormalize=True to project it "
            f"onto SO(3), or a larger tolerance= if the error is expected"
        )
    dets = np.atleast_1d(np.linalg.det(rotation))
    lowest = int(np.argmin(dets))
    if dets[lowest] < 0:
        raise InvalidRotationError(
            f"{owner}: the matrix is a reflection, not a rotation{_where(lowest, batch)}: determinant "
            f"{dets[lowest]:.6g}, a rotation has +1 (check for a flipped axis or a left-handed frame)"
        )


def orthonormalize(matrix: np.ndarray, owner: str = "rotation") -> np.ndarray:
    """The nearest rotation (Frobenius norm) to each slightly-off matrix, by SVD: R = U diag(1, 1, d) V^T.

    Raises `InvalidRotationError` for a reflection (det < 0) or a matrix further than `ORTHONORMALIZE_LIMIT`
    from orthonormal: projecting those would silently invent a rotation.
    """
    if matrix.size == 0:
        return matrix.copy()
    batch = matrix.ndim == 3
    errors = np.atleast_1d(orthonormality_error(matrix))
    worst = int(np.argmax(errors))
    if errors[worst] > ORTHONORMALIZE_LIMIT:
        raise InvalidRotationError(
            f"{owner}: too far from a rotation to orthonormalize{_where(worst, batch)}: max |R^T R - I| = "
            f"{errors[worst]:.3g} (limit {ORTHONORMALIZE_LIMIT:g}); is it scaled, sheared or transposed?"
        )
    dets = np.atleast_1d(np.linalg.det(matrix))
    lowest = int(np.argmin(dets))
    if dets[lowest] <= 0:
        raise InvalidRotationError(
            f"{owner}: the matrix is a reflection{_where(lowest, batch)} (determinant {dets[lowest]:.6g}); "
            f"orthonormalize does not turn reflections into rotations"
        )
    u, _, vt = np.linalg.svd(matrix)
    projected = u @ vt
    # det(U V^T) is +1 here (det(matrix) > 0 and close to orthonormal), so no sign fix is needed.
    return projected  # type: ignore[no-any-return]


def _check_order(order: object) -> QuatOrder:
    if order not in _ORDERS:
        raise GeometryValueError(
            f"quaternion order must be 'xyzw' (scipy, ROS) or 'wxyz' (pytransform3d, Eigen), got {order!r}"
        )
    return "xyzw" if order == "xyzw" else "wxyz"


def quat_to_matrix(
    quat: np.ndarray,
    order: QuatOrder,
    tolerance: float = DEFAULT_TOLERANCE,
    normalize: bool = False,
    owner: str = "quaternion",
) -> np.ndarray:
    """Rotation matrices from unit quaternions.

    Parameters
    ----------
    quat : ndarray, shape (4,) or (N, 4)
        Finite quaternions in the given ``order``.
    order : {"xyzw", "wxyz"}
        Where the scalar part is. Required.
    tolerance : float
        Largest accepted | |q| - 1 | unless ``normalize``.
    normalize : bool
        Scale the quaternions to unit length instead of rejecting non-unit ones (zero is still rejected).
    owner : str
        What the quaternion is for, at the start of error messages (e.g. ``"Transform[World <- Camera]"``).

    Returns
    -------
    ndarray, shape (3, 3) or (N, 3, 3)
    """
    order = _check_order(order)
    norms = np.linalg.norm(quat, axis=-1)
    if np.any(norms < 1e-12):
        raise InvalidRotationError(f"{owner}: a zero quaternion is not a rotation")
    off = np.atleast_1d(np.abs(norms - 1.0))
    if not normalize and off.size and off.max() > tolerance:
        worst = int(np.argmax(off))
        raise InvalidRotationError(
            f"{owner}: the quaternion is not unit length{_where(worst, quat.ndim == 2)}: | |q| - 1 | = {off[worst]:.3g}, "
            f"above the tolerance {tolerance:g}; pass normalize=True to scale it"
        )
    q = quat / norms[..., None]
    if order == "xyzw":
        x, y, z, w = np.moveaxis(q, -1, 0)
    else:
        w, x, y, z = np.moveaxis(q, -1, 0)
    matrix = np.empty(q.shape[:-1] + (3, 3))
    matrix[..., 0, 0] = 1 - 2 * (y * y + z * z)
    matrix[..., 0, 1] = 2 * (x * y - z * w)
    matrix[..., 0, 2] = 2 * (x * z + y * w)
    matrix[..., 1, 0] = 2 * (x * y + z * w)
    matrix[..., 1, 1] = 1 - 2 * (x * x + z * z)
    matrix[..., 1, 2] = 2 * (y * z - x * w)
    matrix[..., 2, 0] = 2 * (x * z - y * w)
    matrix[..., 2, 1] = 2 * (y * z + x * w)
    matrix[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return matrix


def matrix_to_quat(rotation: np.ndarray, order: QuatOrder) -> np.ndarray:
    """Unit quaternions (scalar part >= 0) from rotation matrices, shape (4,) or (N, 4), in the given order.

    Uses the largest of the four candidate denominators (Shepperd's method) for stability.
    """
    order = _check_order(order)
    m = rotation.reshape(-1, 3, 3)
    trace = np.trace(m, axis1=1, axis2=2)
    candidates = np.stack([m[:, 0, 0], m[:, 1, 1], m[:, 2, 2], trace], axis=1)
    pick = np.argmax(candidates, axis=1)
    xyzw = np.empty((m.shape[0], 4))
    for case in range(4):
        rows = pick == case
        if not rows.any():
            continue
        r = m[rows]
        if case == 3:
            s = np.sqrt(1.0 + trace[rows]) * 2
            xyzw[rows] = np.stack(
                [(r[:, 2, 1] - r[:, 1, 2]) / s, (r[:, 0, 2] - r[:, 2, 0]) / s, (r[:, 1, 0] - r[:, 0, 1]) / s, s / 4],
                axis=1,
            )
        else:
            i, j, k = case, (case + 1) % 3, (case + 2) % 3
            s = np.sqrt(1.0 + r[:, i, i] - r[:, j, j] - r[:, k, k]) * 2
            out = np.empty((r.shape[0], 4))
            out[:, i] = s / 4
            out[:, j] = (r[:, j, i] + r[:, i, j]) / s
            out[:, k] = (r[:, k, i] + r[:, i, k]) / s
            out[:, 3] = (r[:, k, j] - r[:, j, k]) / s
            xyzw[rows] = out
    xyzw /= np.linalg.norm(xyzw, axis=1, keepdims=True)
    xyzw[xyzw[:, 3] < 0] *= -1
    result = xyzw if order == "xyzw" else xyzw[:, [3, 0, 1, 2]]
    return result.reshape(rotation.shape[:-2] + (4,))


def slerp(q0: np.ndarray, q1: np.ndarray, fraction: float) -> np.ndarray:
    """Spherical linear interpolation between two unit quaternions (same order), taking the shorter arc."""
    dot = float(np.dot(q0, q1))
    if dot < 0:
        q1, dot = -q1, -dot
    if dot > 0.9995:  # nearly parallel: lerp is accurate and avoids dividing by sin(~0)
        q = q0 + fraction * (q1 - q0)
        return q / np.linalg.norm(q)  # type: ignore[no-any-return]
    theta = np.arccos(dot)
    sin_theta = np.sin(theta)
    return (np.sin((1 - fraction) * theta) * q0 + np.sin(fraction * theta) * q1) / sin_theta  # type: ignore[no-any-return]
