"""Runtime values: indexing a batch keeps its kind and frame; comparing across frames is a type error;
a negated direction is a direction (as at runtime, see test_runtime_agrees_with_plugin)."""

from geolint import Direction, Frame, Point, Transform, Vector


class World(Frame):
    pass


class Cam(Frame):
    pass


def batches(T_wc: Transform[World, Cam], batch_w: Point[World], batch_c: Point[Cam], normals: Direction[Cam]) -> None:
    reveal_type(batch_w[0])  # N: geolint.runtime.primitives.Point[runtime_values_kept.World]
    reveal_type(batch_c[1:3])  # N: geolint.runtime.primitives.Point[runtime_values_kept.Cam]
    reveal_type(T_wc @ batch_c[0])  # N: geolint.runtime.primitives.Point[runtime_values_kept.World]
    T_wc @ batch_w[0]  # E: geo-frame: Transform[World <- Cam] applied to Point[World]: expected a Point[Cam]
    reveal_type(normals[0])  # N: geolint.runtime.primitives.Direction[runtime_values_kept.Cam]


def comparisons(p_w: Point[World], p_c: Point[Cam], q_w: Point[World], v_w: Vector[World], T: Transform[World, Cam]) -> None:
    reveal_type(p_w.is_close(q_w))  # N: bool
    p_w.is_close(p_c)  # E: geo-frame: Point[World].is_close(Point[Cam]): always False, the values live in different frames
    p_w.is_close(v_w)  # E: geo-kind: Point[World].is_close(Vector[World]): always False, a point is never a vector
    T.is_close(T.inverse())  # E: arg-type


def negation(d: Direction[World], v: Vector[World]) -> None:
    reveal_type(-d)  # N: geolint.runtime.primitives.Direction[runtime_values_kept.World]
    reveal_type(-v)  # N: geolint.runtime.primitives.Vector[runtime_values_kept.World]
    reveal_type(2.0 * d)  # N: geolint.runtime.primitives.Vector[runtime_values_kept.World]
