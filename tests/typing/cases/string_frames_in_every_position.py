"""String-frame constructors wherever an expression can stand: yield, defaults, comprehensions, match, lambdas,
decorators, class bodies, f-strings; a frame named like a builtin ("map") stays a string frame."""

from typing import Callable, Iterator

from geolint import Point, Transform, Vector
from geolint import Vector as V


def generator() -> Iterator[Point["odom"]]:
    yield Point["odom"]([1.0, 2.0, 3.0])
    yield from [Point["odom"]([1.0, 2.0, 3.0])]


def default(p: Point["odom"] = Point["odom"]([0.0, 0.0, 0.0]), *, v: V["map"] = V["map"]([0.0, 0.0, 1.0])) -> None:
    reveal_type(p)  # N: geolint.runtime.primitives.Point[Literal['odom']]
    reveal_type(v)  # N: geolint.runtime.primitives.Vector[Literal['map']]


def comprehensions(T: Transform["map", "odom"]) -> None:
    by_key = {k: Point["odom"]([1.0, 2.0, float(k)]) for k in range(3)}
    reveal_type(by_key)  # N: dict[int, geolint.runtime.primitives.Point[Literal['odom']]]
    unique = {T @ Point["odom"]([1.0, 2.0, 3.0]) for _ in range(3)}
    reveal_type(unique)  # N: set[geolint.runtime.primitives.Point[Literal['map']]]
    listed = [T @ Point["odom"]([1.0, 2.0, float(k)]) for k in range(3) if Point["odom"]([1.0, 2.0, 3.0]).is_batch]
    reveal_type(listed)  # N: list[geolint.runtime.primitives.Point[Literal['map']]]
    lazy = (T @ Point["odom"]([1.0, 2.0, 3.0]) for _ in range(3))
    reveal_type(lazy)  # N: typing.Generator[geolint.runtime.primitives.Point[Literal['map']], None, None]
    [T @ Point["base"]([1.0, 2.0, 3.0]) for _ in range(3)]  # E: geo-frame: applied to Point["base"]


def matching(command: str, T: Transform["map", "odom"]) -> None:
    match command:
        case "stop":
            reveal_type(Point["odom"]([1.0, 2.0, 3.0]))  # N: geolint.runtime.primitives.Point[Literal['odom']]
        case _ if Point["odom"]([1.0, 2.0, 3.0]).is_batch:
            T @ Point["base"]([1.0, 2.0, 3.0])  # E: geo-frame: applied to Point["base"]


def lambdas(T: Transform["map", "odom"]) -> None:
    make = lambda: Point["odom"]([1.0, 2.0, 3.0])
    reveal_type(make())  # N: geolint.runtime.primitives.Point[Literal['odom']]
    shift: Callable[[Point["map"]], Point["map"]] = lambda p: p + Vector["map"]([0.0, 0.0, 1.0])
    reveal_type(shift)  # N: def (geolint.runtime.primitives.Point[Literal['map']]) -> geolint.runtime.primitives.Point[Literal['map']]
    offset = lambda d=Vector["map"]([0.0, 0.0, 1.0]): d  # (mypy types an unannotated lambda parameter as Any)
    moved = lambda q=T @ Point["base"]([1.0, 2.0, 3.0]): q  # E: geo-frame: applied to Point["base"]


def builtin_names() -> None:
    reveal_type(Point["map"]([1.0, 2.0, 3.0]))  # N: geolint.runtime.primitives.Point[Literal['map']]
    reveal_type(Point["filter"]([1.0, 2.0, 3.0]))  # N: geolint.runtime.primitives.Point[Literal['filter']]
    reveal_type([Point["range"]([1.0, 2.0, 3.0]) for _ in range(2)])  # N: list[geolint.runtime.primitives.Point[Literal['range']]]


def elsewhere(T: Transform["map", "odom"]) -> str:
    try:
        origin = Point["odom"]([0.0, 0.0, 0.0])
    except ValueError:
        raise RuntimeError(str(Point["odom"]([0.0, 0.0, 0.0])))
    finally:
        del T
    with open("log") as log:
        log.write(f"{Point['odom']([1.0, 2.0, 3.0])}")
    assert Point["odom"]([1.0, 2.0, 3.0]).frame, Point["odom"]([1.0, 2.0, 3.0])
    return f"{origin} {Point['odom']([1.0, 2.0, 3.0])!r}"


class Robot:
    home = Point["map"]([0.0, 0.0, 0.0])
    reveal_type(home)  # N: geolint.runtime.primitives.Point[Literal['map']]

    @staticmethod
    def reach(p: Point["map"] = Point["map"]([1.0, 0.0, 0.0])) -> Point["map"]:
        return p
