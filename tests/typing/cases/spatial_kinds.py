"""Point clouds, twists, wrenches and covariances move with transforms like points do."""

from geolint import Covariance, PointCloud, Transform, Twist, Wrench


def run(
    T: Transform["world", "camera"],
    cloud: PointCloud["camera"],
    far_cloud: PointCloud["lidar"],
    twist: Twist["camera"],
    other_twist: Twist["base"],
    wrench: Wrench["camera"],
    cov: Covariance["camera"],
) -> None:
    reveal_type(T @ cloud)  # N: geolint.runtime.cloud.PointCloud[Literal['world']]
    T @ far_cloud  # E: geo-frame: Transform["world" <- "camera"] applied to PointCloud["lidar"]: expected a PointCloud["camera"]
    reveal_type(T @ twist)  # N: geolint.runtime.spatial.Twist[Literal['world']]
    reveal_type(T @ wrench)  # N: geolint.runtime.spatial.Wrench[Literal['world']]
    reveal_type(T @ cov)  # N: geolint.runtime.spatial.Covariance[Literal['world']]
    reveal_type(twist + twist)  # N: geolint.runtime.spatial.Twist[Literal['camera']]
    twist + other_twist  # E: geo-frame: Twist["camera"] + Twist["base"]: the operands live in different frames
