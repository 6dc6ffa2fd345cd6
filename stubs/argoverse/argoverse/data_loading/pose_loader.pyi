from argoverse.utils.se3 import SE3

def get_city_SE3_egovehicle_at_sensor_t(sensor_timestamp: int, dataset_dir: str, log_id: str) -> SE3 | None:
    """Source: argoverse/data_loading/pose_loader.py (commit f886ac5), get_city_SE3_egovehicle_at_sensor_t: "SE(3) for
    transforming ego-vehicle coordinates to city coordinates if found, else None", made `SE3(rotation=quat2rotmat(rotation),
    translation=translation)` from the pose file's (w, x, y, z) quaternion."""
