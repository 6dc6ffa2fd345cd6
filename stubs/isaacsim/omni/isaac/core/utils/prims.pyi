from geolint.typing import QuaternionWXYZ

def create_prim(prim_path: str, prim_type: str = ..., *args: object, orientation: QuaternionWXYZ = ..., **options: object) -> object:
    """Source: omni/isaac/core/utils/prims.py (Isaac Sim 4.1), create_prim: "orientation (Optional[Sequence[float]], optional): prim orientation (applied before translation)", handed to
    XFormPrim(prim_path, orientation=orientation), whose quaternion is scalar-first (w, x, y, z)."""
