from typing import Literal, overload

from geolint.knowledge.markers import STACKED
from geolint.typing import QuaternionWXYZ, QuaternionXYZW
from typing_extensions import Annotated

_WXYZ = Annotated[QuaternionWXYZ, STACKED]
_XYZW = Annotated[QuaternionXYZW, STACKED]

@overload
def convert_quat(quat: _WXYZ, to: Literal["xyzw"] = ...) -> _XYZW: ...
@overload
def convert_quat(quat: _XYZW, to: Literal["wxyz"]) -> _WXYZ:
    """Source: IsaacLab source/isaaclab/isaaclab/utils/math.py, convert_quat(quat, to="xyzw"): `to`
    names the order it returns and it reads the other, the same in every Isaac Lab version."""
