"""GEO301 quaternion-order: quaternion components passed in the other convention."""

from __future__ import annotations

from typing import Final

import ast
from ast import (
    AST, Assign, AsyncFunctionDef, Attribute, BinOp, Call, FunctionDef, If, IfExp, Load, Match, Name,
    Starred, Subscript, UnaryOp, While,
)
import re
from dataclasses import dataclass

from geolint.rules.base import Invalid, Valid
from geolint.factbase.messages import field_label, field_order, quaternion_field_names, quaternion_record_modules
from geolint.factbase.model import FactBase, last_name, number, positional_args, replace_span, string, subscript_parts
from geolint.factbase.rotations import (
    IDENTITY_NAME,
    ImportBranches,
    branch_qualified_name,
    PYBULLET_ORIENTATION_CALLS,
    SCALAR_FIRST,
    SCALAR_LAST,
    accepts_stacks,
    api_label,
    pybullet_orientation_arguments,
    quaternion_argument,
    quaternion_order,
    spread_argument,
)
from geolint.factbase.reaching import Unpacked, value_of
from geolint.rules.fact_rule import FactRule, with_keyword
from geolint.factbase.vocabulary import GATE_TRIGGER
from geolint.factbase.quaternion_formulas import formula_reads
from geolint.factbase.quaternion_orders import (
    QUATERNIONS,
    ORDER_FLAGS,
    flag_ordered_producer,
    mentions_order_flag,
    STANDARD_ORDERS,
    QuaternionFlow,
    Reorder,
    convention,
    label,
    keyword_states_order,
    name_order,
    permutation_between,
    permuted,
)
from geolint.factbase.quaternion_components import (
    COMPONENTS,
    component_name,
    literal_components,
    named_order,
    order_dependent_part,
    same_base,
    spelled_components,
    unwrapped_scalar,
)



@dataclass(frozen=True)
class _Helper:
    """`yaw_from_quat(q)`: a project helper that hands its parameter to a quaternion API."""

    call: Call
    parameter: str
    where: str


@dataclass(frozen=True)
class _Keyword:
    """`PoseTrajectory3D(orientations_quat_wxyz=q)`: a keyword whose name states the order its callee reads."""

    call: Call
    name: str


@dataclass(frozen=True)
class _MessageField:
    """`msg.q_d = value`: a quaternion field of a message whose class fixes the order."""

    target: Attribute
    cls: str


class _GateOrOrderName:
    """The fact rules' gate, a name that states a component order (`q_wxyz`, `quats_xyzw`), an angle
    formula's function (`atan2`, `asin`: formulas written by index), or the module of a record with a
    quaternion field of known order (PX4's messages, whose `q` may go to a helper that reads by index)."""

    _ORDER_WORDS = ("wxyz", "xyzw", "atan2", "asin", "arcsin")  # in any case

    def search(self, source: str, /) -> bool:
        return bool(GATE_TRIGGER.search(source) or self._mentions_order(source))

    def search_with(self, source: str, config: object, /) -> bool:
        return GATE_TRIGGER.search_with(source, config) or self._mentions_order(source)

    def _mentions_order(self, source: str) -> bool:
        # one lowercase copy and a substring test per word: a case-insensitive alternation has no
        # literal for the regex engine to scan for, and this runs on every module the gate turns away
        lowered = source.lower()
        return any(word in lowered for word in self._ORDER_WORDS) or any(module in source for module in quaternion_record_modules())


_GATE_OR_ORDER_NAME: Final = _GateOrOrderName()
# the expressions `QuaternionFlow.order_of` / `reorder_of` can know something of; for any other (a
# constant, an f-string, a comparison...) both are None, found without following anything
_MAY_HAVE_ORDER: Final = frozenset({UnaryOp, BinOp, Call, Name, Attribute, Subscript, ast.List, ast.Tuple})
_LETTERS: Final = frozenset(COMPONENTS)


class QuaternionOrder(FactRule):
    """Quaternion components are listed, reordered or read in the order of the other convention.

    ## What it does
    Flags a quaternion spelled out component by component (`[q.w, q.x, q.y, q.z]`,
    `[qx, qy, qz, qw]`) and passed to an API that expects the other order: scipy
    `Rotation.from_quat` (x, y, z, w unless `scalar_first=True`), transforms3d `quat2*` and
    `qmult` / `qconjugate` / `qinverse`, pytransform3d `*_from_quaternion`, pyquaternion `Quaternion` and spatialmath
    `UnitQuaternion` (w, x, y, z), ROS `tf.transformations` and ROS 1 `geometry_msgs.msg.Quaternion`
    (x, y, z, w); also trimesh's
    `transformations`, pytorch3d `quaternion_*`, numpy-quaternion `from_float_array` and `np.quaternion` (a
    4-vector spread with `*` into a constructor that takes components counts too), Open3D
    `get_rotation_matrix_from_quaternion` (w, x, y, z), roma `unitquat_*` (x, y, z, w), pybullet
    (`get*FromQuaternion`, and the orientation arguments of `resetBasePositionAndOrientation`,
    `loadURDF`, `multiplyTransforms`, `invertTransform`, `calculateInverseKinematics`), Isaac Gym's
    `isaacgym.torch_utils` (`quat_mul`, `quat_rotate`, `quat_apply`, `get_euler_xyz`, `tf_*`: x, y, z, w,
    also through `from isaacgym.torch_utils import *`), Isaac Sim's core (the `orientation(s)=` of prims,
    objects and views, `set_world_pose(s)` / `set_local_pose(s)` / `set_default_state`,
    `omni.isaac.core.utils.rotations` and `utils.torch.rotations`: w, x, y, z), Isaac Lab 1.x
    `omni.isaac.lab.utils.math` (w, x, y, z) and `convert_quat(q, to=...)`, pinocchio's `pin.Quaternion`
    (four coefficients w, x, y, z, but one 4-vector x, y, z, w), GTSAM's `Rot3.Quaternion(w, x, y, z)`
    and MuJoCo's `mju_quat2Mat`,
    `mju_quat2Vel`, `mju_quatIntegrate` (w, x, y, z). Through data it also flags:

    - a reorder that goes the wrong way for the API, whatever the data: `from_quat(X[..., [3, 0, 1, 2]])`
      or `from_quat(np.roll(q, 1))` (scalar-last to scalar-first, then read as scalar-last), and
      `Quaternion(q[..., [1, 2, 3, 0]])` for a scalar-first API; directly or through a variable;
    - a value whose order is known, passed to an API of the other order: from a producer
      (`mat2quat`, `euler2quat`, numpy-quaternion `as_float_array`, pyquaternion `.elements`,
      mujoco `xquat`, pytorch3d `matrix_to_quaternion`, Isaac Sim `euler_angles_to_quat`, Isaac Lab 1.x
      `quat_from_euler_xyz`: scalar-first; scipy `as_quat()`, pybullet `getQuaternionFromEuler`, ROS
      `tf.transformations`, Isaac Gym `quat_from_euler_xyz`: scalar-last), a spelled-out
      `np.array([o.w, o.x, o.y, o.z])`, or a name that states it (`quat_wxyz`), followed through
      project helpers' returns (here or in another module; a tuple `return pos, quat` unpacked or
      indexed by the caller, when every `return` agrees on that position), project classes' methods and `@property` getters (`robot = Robot(...)`, `robot: Robot`, `self`), local variables, `self` attributes, and record fields filled by keyword in the same module
      (`Label(quaternion=q)` read back as `label.quaternion` from a parameter annotated `Label`);
    - `np.roll(quats, -1)` / `torch.roll(quats, 1)` without an axis on a stack of quaternions
      (a plural name: `quats`, `quaternions`, `orientations`; mujoco's per-body arrays), which rolls
      the flattened array so each quaternion takes a component from its neighbour;
    - a name that states an order (`quat_xyzw`, `q_wxyz`) bound to data in another one
      (`quat_xyzw = mat2quat(R)`, `q_xyzw = (q_wxyz[3], q_wxyz[0], q_wxyz[1], q_wxyz[2])`);
    - PX4 messages (`px4_msgs`: `VehicleOdometry.q`, `VehicleAttitude.q`, `VehicleAttitudeSetpoint.q_d`...),
      which are (w, x, y, z), read into a scalar-last API or written from a scalar-last value, when the
      message's class is known: built by its constructor, an annotated parameter, or the message
      parameter of a callback the module registers with `create_subscription(VehicleOdometry, ...)`
      (also through `self` attributes every store of which is such a message); the name `q` alone
      is no evidence;
    - a value whose order is known passed to a project helper (here or in another module) that
      hands the parameter, unchanged and unconditionally, to one of those APIs
      (`yaw_from_quat(msg.q)` where `def yaw_from_quat(q): return Rotation.from_quat(q)...`), or that
      fills one object's `x`, `y`, `z`, `w` from the parameter's four indices, unconditionally
      (`def to_ros(q): m = Quaternion(); m.x = q[0]; ...; m.w = q[3]` reads `q` as x, y, z, w);
    - four local names that say which component they hold (`ori_x`, `qw`, `quat_z`; a bare `x` is
      not enough), read by index from one quaternion of known order with w taken from another index
      than the order puts it at (`ori_x = ee_quat[0]` ... `ori_w = ee_quat[3]` of a (w, x, y, z) value);
    - a textbook formula written by index that takes w from another component than the value's
      known order puts it in: the yaw `atan2(2 * (q[3] * q[2] + q[0] * q[1]), 1 - 2 * (q[1] ** 2 + q[2] ** 2))`,
      the roll, the pitch `asin(2 * (wy - xz))` and the 3x3 rotation matrix (or its transpose), read
      through local names (`q_w = q[3]`, `x, y, z, w = q`); directly (`q = msg.q` of a PX4 message)
      or through a project helper that computes one on its parameter unconditionally
      (`quat_get_yaw(odometry.q)`). An index pattern that is two formulas at once (the yaw of
      x, y, z, w is the roll of w, x, y, z) counts only when the component names or the result's name
      (`yaw = ...`, `def get_yaw`) choose one;
    - in a function with an order flag (`w_last`, `scalar_first`), a component slice at fixed
      positions (`mul[:, 1:]`, `q[..., 0]`) of a quaternion operation's result that was handed the
      flag (`mul = quat_mul(a, b, w_last)`), outside any branch: right for one value of the flag only;
    - a literal `[0, 0, 0, 1]` that its name (`IDENTITY_QUAT`, `no_rotation`) or a comment on its line
      (`# identity`) calls the identity, handed to a (w, x, y, z) API (Isaac Sim's `create_prim` and
      prims), or `[1, 0, 0, 0]` to an (x, y, z, w) one: the API reads a half turn;
    - a value whose order is known passed by a keyword whose name states the other order (evo's
      `PoseTrajectory3D(orientations_quat_wxyz=...)`, "nx4 list of quaternions (w,x,y,z format)");
    - a dict, keyword call or message filled component by component with the scalar part in the
      wrong place: `{"x": q[0], ..., "w": q[3]}` for a scalar-first `q`, `msg.w = q[0]` for a
      scalar-last one, `{"x": q.w, ..., "w": q.z}` whatever the convention. x, y and z permuted
      among themselves with w in place is an axis change and stays silent.

    ## Why is this bad?
    Both orders give a valid unit quaternion, so nothing fails: the rotation is just wrong (the
    scalar part is read as an axis component). ROS messages and scipy put w last, most math
    libraries put it first; the bug appears at every boundary between the two.

    ## Example
    ```python
    rotation = Rotation.from_quat([msg.w, msg.x, msg.y, msg.z])
    yaws = Rotation.from_quat(quats_wxyz[:, [3, 0, 1, 2]]).as_euler("xyz")[:, 2]
    ```

    ## Use instead
    ```python
    rotation = Rotation.from_quat([msg.x, msg.y, msg.z, msg.w])
    yaws = Rotation.from_quat(quats_wxyz[:, [1, 2, 3, 0]]).as_euler("xyz")[:, 2]
    ```

    ## Fix safety
    Reordering spelled-out components to the API's convention is safe: the names say which
    component is which. Correcting a reorder or a component read is safe when the producer is
    in the same function, and unsafe otherwise (a wrong-way reorder of data whose order nobody
    states is fixed on the assumption that the data is in the other convention). A value passed
    whole gets no fix.

    ## Known problems
    A wrong-way reorder of data whose order nothing states is not flagged in a module that also
    stores data reordered the opposite way in a container (`batch["quat"] = torch.roll(q, 1, -1)`):
    two rolls that cancel are correct, and such data may travel in that non-standard order. Evidence is followed within one module only: a record field filled in another module, or a
    parameter, has no known order and stays silent. A message callback that is also called directly
    (`self.on_odometry(recorded)`), or registered through a lambda or `functools.partial`, gives its
    parameter no known class. When a name (`quat_xyzw`) and its value
    (`mat2quat(R)`) disagree, the binding is flagged once and the later uses of the name are not
    judged. A literal `[0, 0, 0, 1]` handed to a (w, x, y, z) API is not flagged unless its name or a
    comment says identity: a deliberate half turn about z is written the same way.
    Isaac Lab's newer `isaaclab.utils.math` is not read (its releases changed the order under the same
    names), nor are Isaac Sim 4.5+'s `isaacsim.core.utils.rotations` functions; `quat_mul` & co. imported
    by star from two of these modules, or redefined by the module, are not read either. A quaternion
    that reaches a prim through a project class's constructor (`Cabinet(path, orientation=q)` whose
    `__init__` stores it and passes it on) is not followed. A name imported in two arms of a
    module-level `if` (`from tf.transformations import quaternion_multiply` under `if ROS_VERSION == 1:`,
    transforms3d's `qmult as quaternion_multiply` under `elif ROS_VERSION == 2:`) is read as the import of
    the arm when the call sits in a function branch on the same test (`if ROS_VERSION == 1:` again), and
    as the last import elsewhere: a call outside any such branch runs under both, so a fixed order
    given to it is wrong under one of them, but the finding names only the last import's order. A helper in a sibling package of a ROS workspace is found only when both packages hold a
    `package.xml` side by side (`carla_common/src/carla_common` imported from `carla_ros_bridge/src/...`);
    packages nested in meta-package folders are not searched. Component names read by unpacking (`x, y, z, w = q`) are not judged.
    """

    code = "GEO301"
    name = "quaternion-order"
    triggers = _GATE_OR_ORDER_NAME  # type: ignore[assignment]  # the gate, widened

    VALID = [
        Valid("from scipy.spatial.transform import Rotation\nr = Rotation.from_quat([q.x, q.y, q.z, q.w])\n"),
        Valid(
            "from transforms3d.euler import euler2quat\ndef to_ros(msg, q):\n    msg.w = q[0]\n    msg.x = q[1]\n"
            "    msg.y = q[2]\n    msg.z = q[3]\n    return msg\ndef f(msg, r, p, y):\n    return to_ros(msg, euler2quat(r, p, y))\n"
        ),
        Valid(
            "from transforms3d.euler import euler2quat\ndef f(r, p, y):\n    q = euler2quat(r, p, y)\n"
            "    qw = q[0]\n    qx = q[1]\n    qy = q[2]\n    qz = q[3]\n    return qx, qy, qz, qw\n"
        ),
        Valid(
            "from scipy.spatial.transform import Rotation\n"
            "r = Rotation.from_quat([q.w, q.x, q.y, q.z], scalar_first=True)\n"
        ),
        Valid("from transforms3d.quaternions import quat2mat\nm = quat2mat([q.w, q.x, q.y, q.z])\n"),
        Valid("from pyquaternion import Quaternion\nq2 = Quaternion(q.w, q.x, q.y, q.z)\n"),
        Valid("from geometry_msgs.msg import Quaternion\nq2 = Quaternion(q.x, q.y, q.z, q.w)\n"),
        Valid("from pyquaternion import Quaternion as PQ\nq2 = PQ(q.w, q.x, q.y, q.z)\n"),
        Valid("from scipy.spatial.transform import Rotation\nr = Rotation.from_quat([a, b, c, d])\n"),
        Valid("from scipy.spatial.transform import Rotation\ndef f(q_wxyz):\n    return Rotation.from_quat(q_wxyz[..., [1, 2, 3, 0]])\n"),
        Valid("from transforms3d.quaternions import quat2mat\nimport numpy as np\ndef f(q):\n    return quat2mat(np.roll(q, 1))\n"),
        Valid("from scipy.spatial.transform import Rotation\ndef f(X):\n    return Rotation.from_quat(X[:, [3, 0, 1, 2]], scalar_first=True)\n"),
        Valid("def f(rec):\n    return {'x': rec.q[0], 'y': rec.q[1], 'z': rec.q[2], 'w': rec.q[3]}\n"),
        Valid("def f(q_wxyz):\n    q_xyzw = (q_wxyz[1], q_wxyz[2], q_wxyz[3], q_wxyz[0])\n    return q_xyzw\n"),
        Valid("import numpy as np\ndef to_xyzw(quats_wxyz):\n    return np.roll(quats_wxyz, -1, axis=1)\n"),
        Valid("import numpy as np\ndef to_xyzw(frames):\n    return np.roll(frames[:, 3:7], -1, axis=1)\n"),
        Valid("import numpy as np\ndef to_xyzw(frame):\n    return np.roll(frame[3:7], -1)\n"),  # one row: 1-D
        Valid(
            "from scipy.spatial.transform import Rotation as R\ndef to_wxyz(euler):\n"
            "    quats_wxyz = R.from_euler('xyz', euler).as_quat()\n"
            "    quats_wxyz = quats_wxyz[:, [3, 0, 1, 2]]\n    return quats_wxyz\n"
        ),  # named for its value after the reorder on the next line
        Valid(
            "import numpy as np\nfrom scipy.spatial.transform import Rotation as sRot\ndef smooth(rotvecs, smooth_rows):\n"
            "    q = sRot.from_rotvec(rotvecs).as_quat()[:, [1, 2, 3, 0]]\n    q = smooth_rows(q)\n"
            "    return sRot.from_quat(q[:, [3, 0, 1, 2]]).as_rotvec()\n"
        ),  # the function applied the inverse reorder first: the two cancel
        Valid("import numpy as np\ndef to_xyzw(quat_wxyz):\n    return np.roll(quat_wxyz, -1)\n"),  # one quaternion
        Valid(
            "import pybullet as p\ndef place(body, position, yaw):\n"
            "    orientation = p.getQuaternionFromEuler([0, 0, yaw])\n    p.resetBasePositionAndOrientation(body, position, orientation)\n"
        ),
        Valid("def enu_to_ned(q):\n    return {'x': q.y, 'y': q.x, 'z': -q.z, 'w': q.w}\n"),  # an axis change
        Valid(
            "from scipy.spatial.transform import Rotation\nfrom transforms3d.quaternions import mat2quat\n"
            "def yaw_of(q, wxyz=False):\n    if wxyz:\n        q = [q[1], q[2], q[3], q[0]]\n"
            "    return Rotation.from_quat(q).as_euler('xyz')[2]\ndef f(R):\n    return yaw_of(mat2quat(R), wxyz=True)\n"
        ),  # the helper reorders under a condition: what it reads is not known
        Valid("from scipy.spatial.transform import Rotation\ndef on_odometry(msg):\n    return Rotation.from_quat(msg.q)\n"),  # type unknown
        Valid(
            "from px4_msgs.msg import VehicleOdometry\nfrom scipy.spatial.transform import Rotation\nclass Node:\n"
            "    def __init__(self):\n        self.create_subscription(VehicleOdometry, 'odom', self.on_odometry, 10)\n"
            "    def on_odometry(self, msg):\n        return Rotation.from_quat(msg.q, scalar_first=True)\n"
        ),
        Valid(
            "from transforms3d.quaternions import mat2quat\ndef f(R):\n    q = mat2quat(R)\n"
            "    return {'x': q[2], 'y': q[1], 'z': q[3], 'w': q[0]}\n"
        ),  # w in place, x and y swapped: an axis change
        Valid(
            "import numpy as np\nimport torch\nimport trimesh.transformations as tra\n"
            "def load(data):\n    return {'quat': torch.roll(data[:, 3:7], 1, -1)}\n"
            "def show(orientation):\n    return tra.quaternion_matrix(np.roll(orientation, -1))\n"
        ),  # the module stores data rolled the other way: the second roll may undo the first
        Valid(
            "import numpy as np\nimport quaternion\nfrom scipy.spatial.transform import Rotation\n"
            "def f(M):\n    x, y, z, w = Rotation.from_matrix(M).as_quat()\n    return np.quaternion(w, x, y, z)\n"
        ),
        Valid(  # without `import quaternion`, `np.quaternion` is not numpy-quaternion's type
            "import numpy as np\nfrom scipy.spatial.transform import Rotation\n"
            "def f(M):\n    return np.quaternion(*Rotation.from_matrix(M).as_quat())\n"
        ),
        Valid(  # the unpacking names lie (w holds x ...), so [w, x, y, z] is scipy's x, y, z, w again
            "from scipy.spatial.transform import Rotation\ndef target(euler):\n"
            "    q = Rotation.from_euler('XYZ', euler).as_quat()\n    w, x, y, z = q\n"
            "    return Rotation.from_quat([w, x, y, z]).as_matrix()\n"
        ),
        Valid(
            "import math\nfrom px4_msgs.msg import VehicleOdometry\ndef yaw(msg: VehicleOdometry):\n    q = msg.q\n"
            "    return math.atan2(2 * (q[0] * q[3] + q[1] * q[2]), 1 - 2 * (q[2] ** 2 + q[3] ** 2))\n"
        ),
        Valid(  # yaw of (x, y, z, w) or roll of (w, x, y, z): the code does not say which
            "import math\nfrom px4_msgs.msg import VehicleOdometry\ndef angle(msg: VehicleOdometry):\n    q = msg.q\n"
            "    return math.atan2(2 * (q[3] * q[2] + q[0] * q[1]), 1 - 2 * (q[1] ** 2 + q[2] ** 2))\n"
        ),
        Valid(
            "import torch\nfrom .rotations import quat_conjugate, quat_mul\ndef quat_angle(a, b, w_last: bool):\n"
            "    mul = quat_mul(a, quat_conjugate(b, w_last), w_last)\n    vec = mul[:, :3] if w_last else mul[:, 1:]\n"
            "    return 2 * torch.asin(torch.norm(vec, dim=-1).clamp(max=1.0))\n"
        ),
        Valid(  # the flag is not passed: the order is fixed
            "import torch\nfrom .rotations import quat_mul\ndef quat_angle(a, b, w_last: bool):\n"
            "    mul = quat_mul(a, b, True)\n    return torch.norm(mul[:, :3], dim=-1)\n"
        ),
    ]
    INVALID = [
        Invalid(  # four arguments that are not four components: the quaternion among them is judged
            "import numpy as np\nfrom isaacgym import torch_utils\ndef f(qw, qx, qy, qz, t1, q2, t2):\n    q1 = np.array([qw, qx, qy, qz])\n"
            "    return torch_utils.tf_combine(q1, t1, q2, t2)\n", range=(5, 35, 5, 37),
        ),
        Invalid(
            "from transforms3d.euler import euler2quat\ndef to_ros(msg, q):\n    msg.x = q[0]\n    msg.y = q[1]\n"
            "    msg.z = q[2]\n    msg.w = q[3]\n    return msg\ndef f(msg, r, p, y):\n    return to_ros(msg, euler2quat(r, p, y))\n",
            message="`euler2quat(r, p, y)` is scalar-first (w, x, y, z) (from `euler2quat(r, p, y)`, line 9), but `to_ros` (which passes its parameter `q` to the fields of `msg` in x, y, z, w order (`msg.w = q[3]`)) expects scalar-last (x, y, z, w)",
            range=(9, 24, 9, 43),
        ),
        Invalid(
            "from transforms3d.euler import euler2quat\ndef f(r, p, y):\n    q = euler2quat(r, p, y)\n"
            "    qx = q[0]\n    qy = q[1]\n    qz = q[2]\n    qw = q[3]\n    return qx, qy, qz, qw\n",
            message="`qw = q[3]` reads component 3 as w, but `q` is scalar-first (w, x, y, z) (from `euler2quat(r, p, y)`, line 3): w is component 0",
            range=(7, 5, 7, 14),
        ),
        Invalid(
            "import numpy as np\nfrom scipy.spatial.transform import Rotation\ndef root_rotvec(frames):\n"
            "    return Rotation.from_quat(np.roll(frames[:, 3:7], -1)).as_rotvec()\n",
            expected_fix="import numpy as np\nfrom scipy.spatial.transform import Rotation\ndef root_rotvec(frames):\n"
            "    return Rotation.from_quat(np.roll(frames[:, 3:7], -1, axis=-1)).as_rotvec()\n",
        ),  # stacked (x, y, z, qw, qx, qy, qz) rows: four columns of a table, rolled flat
        Invalid(
            "from scipy.spatial.transform import Rotation\nr = Rotation.from_quat([q.w, q.x, q.y, q.z])\n",
            expected_fix="from scipy.spatial.transform import Rotation\nr = Rotation.from_quat([q.x, q.y, q.z, q.w])\n",
        ),
        Invalid(
            "from transforms3d.quaternions import quat2mat\nm = quat2mat([q.x, q.y, q.z, q.w])\n",
            expected_fix="from transforms3d.quaternions import quat2mat\nm = quat2mat([q.w, q.x, q.y, q.z])\n",
        ),
        Invalid(
            "from pyquaternion import Quaternion\nq2 = Quaternion(q.x, q.y, q.z, q.w)\n",
            expected_fix="from pyquaternion import Quaternion\nq2 = Quaternion(q.w, q.x, q.y, q.z)\n",
        ),
        Invalid(
            "from scipy.spatial.transform import Rotation as R\nr = R.from_quat((qw, qx, qy, qz))\n",
            expected_fix="from scipy.spatial.transform import Rotation as R\nr = R.from_quat((qx, qy, qz, qw))\n",
        ),
        Invalid(
            "import pytransform3d.rotations as pr\nm = pr.matrix_from_quaternion([ori.x, ori.y, ori.z, ori.w])\n",
            expected_fix="import pytransform3d.rotations as pr\nm = pr.matrix_from_quaternion([ori.w, ori.x, ori.y, ori.z])\n",
        ),
        Invalid(
            "from scipy.spatial.transform import Rotation as R\nimport numpy as np\ndef yaws(X):\n"
            "    return R.from_quat(np.vstack(X)[:, [3, 0, 1, 2]]).as_euler('xyz')[:, 2]\n",
            expected_fix="from scipy.spatial.transform import Rotation as R\nimport numpy as np\ndef yaws(X):\n"
            "    return R.from_quat(np.vstack(X)[:, [1, 2, 3, 0]]).as_euler('xyz')[:, 2]\n",
        ),
        Invalid("from scipy.spatial.transform import Rotation\ndef f(X):\n    q = X[:, [3, 0, 1, 2]]\n    return Rotation.from_quat(q)\n"),
        Invalid("from pyquaternion import Quaternion\nimport numpy as np\ndef f(q):\n    return Quaternion(np.roll(q, -1))\n"),
        Invalid(
            "from scipy.spatial.transform import Rotation\nfrom transforms3d.quaternions import mat2quat\n"
            "def f(R):\n    q = mat2quat(R)\n    return Rotation.from_quat(q[[1, 2, 3, 0]][[3, 0, 1, 2]])\n",
        ),
        Invalid(
            "import numpy as np\nfrom scipy.spatial.transform import Rotation\ndef f(o):\n"
            "    quat = np.array([o.w, o.x, o.y, o.z])\n    return Rotation.from_quat(quat)\n"
        ),
        Invalid(
            "import quaternion\nfrom typing import List\nclass Label:\n    pass\n"
            "def make(q):\n    return Label(quaternion=quaternion.as_float_array(q))\n"
            "def save(labels: List[Label]):\n"
            "    return [{'x': l.quaternion[0], 'y': l.quaternion[1], 'z': l.quaternion[2], 'w': l.quaternion[3]} for l in labels]\n",
            expected_fix="import quaternion\nfrom typing import List\nclass Label:\n    pass\n"
            "def make(q):\n    return Label(quaternion=quaternion.as_float_array(q))\n"
            "def save(labels: List[Label]):\n"
            "    return [{'x': l.quaternion[1], 'y': l.quaternion[2], 'z': l.quaternion[3], 'w': l.quaternion[0]} for l in labels]\n",
            message='`"w": l.quaternion[3]` reads component 3 as w, but `l.quaternion` is scalar-first (w, x, y, z) (`Label.quaternion` is set from `quaternion.as_float_array(q)`, line 6): w is component 0',
            range=(8, 13, 8, 101),
        ),
        Invalid(
            "from scipy.spatial.transform import Rotation\ndef f(msg, yaw):\n    q = Rotation.from_euler('z', yaw).as_quat()\n"
            "    msg.w = q[0]\n    msg.x = q[1]\n    msg.y = q[2]\n    msg.z = q[3]\n",
            message="`msg.w = q[0]` reads component 0 as w, but `q` is scalar-last (x, y, z, w) (from `Rotation.from_euler('z', yaw).as_quat()`, line 3): w is component 3",
            range=(4, 5, 4, 17),
        ),
        Invalid(
            "from scipy.spatial.transform import Rotation\nfrom transforms3d.quaternions import mat2quat\n"
            "def f(R):\n    quat_xyzw = mat2quat(R)\n    return Rotation.from_quat(quat_xyzw)\n"
        ),  # once, at the binding: the name and the producer disagree, so the call itself is not judged
        Invalid("def f(q_wxyz):\n    q_xyzw = (q_wxyz[3], q_wxyz[0], q_wxyz[1], q_wxyz[2])\n    return q_xyzw\n"),
        Invalid(
            "import numpy as np\ndef to_xyzw(orientations_quat_wxyz):\n    return np.roll(orientations_quat_wxyz, -1)\n",
            expected_fix="import numpy as np\ndef to_xyzw(orientations_quat_wxyz):\n    return np.roll(orientations_quat_wxyz, -1, axis=-1)\n",
        ),
        Invalid(
            "import pybullet as p\nfrom transforms3d.euler import euler2quat\ndef place(body, position, yaw):\n"
            "    orientation = euler2quat(0, 0, yaw)\n    p.resetBasePositionAndOrientation(body, position, orientation)\n"
        ),
        Invalid(
            "import open3d as o3d\nimport roma\ndef f(R):\n    quat = roma.rotmat_to_unitquat(R)\n"
            "    return o3d.geometry.get_rotation_matrix_from_quaternion(quat)\n"
        ),
        Invalid("def to_json(quat):\n    return {'x': quat.w, 'y': quat.x, 'z': quat.y, 'w': quat.z}\n"),
        Invalid(
            "from scipy.spatial.transform import Rotation\nfrom transforms3d.quaternions import mat2quat\n"
            "def yaw_of(q):\n    return Rotation.from_quat(q).as_euler('xyz')[2]\ndef f(R):\n    return yaw_of(mat2quat(R))\n"
        ),
        Invalid(  # px4_msgs quaternions are (w, x, y, z); the subscription says what `msg` is
            "from px4_msgs.msg import VehicleOdometry\nfrom scipy.spatial.transform import Rotation\nclass Node:\n"
            "    def __init__(self):\n        self.create_subscription(VehicleOdometry, 'odom', self.on_odometry, 10)\n"
            "    def on_odometry(self, msg):\n        return Rotation.from_quat(msg.q)\n"
        ),
        Invalid(
            "from px4_msgs.msg import VehicleAttitudeSetpoint\nfrom scipy.spatial.transform import Rotation\n"
            "def setpoint(yaw):\n    msg = VehicleAttitudeSetpoint()\n    msg.q_d = Rotation.from_euler('z', yaw).as_quat()\n    return msg\n"
        ),
        Invalid(  # numpy-quaternion's constructor takes w first; scipy's as_quat() spreads x, y, z, w into it
            "import numpy as np\nimport quaternion\nfrom scipy.spatial.transform import Rotation\n"
            "def f(M):\n    return np.quaternion(*Rotation.from_matrix(M).as_quat())\n"
        ),
        Invalid(  # the textbook yaw by index takes w from q[3]: x, y, z, w, but PX4's q is w, x, y, z
            "import math\nfrom px4_msgs.msg import VehicleOdometry\ndef yaw(msg: VehicleOdometry):\n    q = msg.q\n"
            "    return math.atan2(2 * (q[3] * q[2] + q[0] * q[1]), 1 - 2 * (q[1] ** 2 + q[2] ** 2))\n"
        ),
        Invalid(  # a helper's formula names its components: it reads x, y, z, w
            "import math\nfrom transforms3d.euler import euler2quat\ndef heading(q):\n"
            "    qw, qx, qy, qz = q[3], q[0], q[1], q[2]\n"
            "    return math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))\n"
            "def f(r, p, y):\n    return heading(euler2quat(r, p, y))\n"
        ),
        Invalid(
            "import torch\nfrom .rotations import quat_conjugate, quat_mul\ndef quat_angle(a, b, w_last: bool):\n"
            "    mul = quat_mul(a, quat_conjugate(b, w_last), w_last)\n"
            "    return 2 * torch.asin(torch.norm(mul[:, 1:], dim=-1).clamp(max=1.0))\n"
        ),
        Invalid(
            "from geometry_msgs.msg import Quaternion\nq2 = Quaternion(o.w, o.x, o.y, o.z)\n",
            expected_fix="from geometry_msgs.msg import Quaternion\nq2 = Quaternion(o.x, o.y, o.z, o.w)\n",
        ),
    ]

    def run(self) -> None:
        facts = self.facts
        flow = facts.shared(QuaternionFlow)
        for node in facts.index.nodes(Call):
            self._check(node, flow)  # type: ignore[arg-type]
        self._check_component_writes(flow)
        self._check_formula_reads(flow)
        if mentions_order_flag(facts.index.source):
            self._check_order_flag_slices()
        named_reads: dict[tuple[int, str, str], dict[str, tuple[Name, Subscript]]] = {}
        for node in facts.index.nodes(Assign):
            self._check_named_target(node, flow)  # type: ignore[arg-type]
            self._check_message_field(node, flow)  # type: ignore[arg-type]
            _collect_named_read(facts, node, named_reads)  # type: ignore[arg-type]
        for group in named_reads.values():
            if len(group) == 4:
                self._check_named_reads(group, flow)
        if "roll" in facts.index.source:  # no `roll` in the text, no roll call (an alias is imported by name)
            for node in facts.index.nodes(Call):
                self._check_flat_roll(node, flow)  # type: ignore[arg-type]

    def _check_order_flag_slices(self) -> None:
        """`def quat_diff(a, b, w_last)`: `mul = quat_mul(a, b, w_last)` is in the order the flag picks,
        so a fixed component slice of it (`mul[:, 1:]`) outside any branch on the flag is right for
        one value of the flag only."""
        facts = self.facts
        for function in facts.index.nodes(FunctionDef, AsyncFunctionDef):
            flags = {arg.arg for arg in (*function.args.posonlyargs, *function.args.args, *function.args.kwonlyargs)} & ORDER_FLAGS  # type: ignore[attr-defined]
            if len(flags) != 1:
                continue
            (flag,) = flags
            for node in ast.walk(function):
                if not isinstance(node, Subscript) or not isinstance(node.ctx, Load):
                    continue
                if facts.index.scope_of(node).node is not function:
                    continue
                where = order_dependent_part(node)
                if where is None:
                    continue
                producer = flag_ordered_producer(facts, node.value, flag)
                if producer is None or _under_branch_on(facts, node, function):  # type: ignore[arg-type]
                    continue
                other = {"vector": "the scalar", "scalar": "a vector component"}[where]
                self.report(
                    node,
                    f"`{self.code_of(node)}` takes the {where} part at fixed positions, but `{self.code_of(node.value)}` "
                    f"comes from `{self.code_of(producer)}`, whose component order the flag `{flag}` chooses: for the "
                    f"other value of `{flag}` these positions hold {other}",
                )

    def _check_formula_reads(self, flow: QuaternionFlow) -> None:
        """`q = msg.q` (w, x, y, z) then `atan2(2 * (q[3] * q[2] + q[0] * q[1]), ...)`: a textbook formula
        that takes w from another index than the value's known order puts it in."""
        for read in formula_reads(self.facts):
            order = flow.order_of(read.base)
            if order is None or order.order not in STANDARD_ORDERS or order.order == read.order:
                continue
            if order.batch and not read.sliced:
                continue  # `quats[3]` is a row of the stack, not a component
            if isinstance(read.base, Name) and self._name_contradicted(read.base, flow):
                continue  # reported once, where the name is bound
            self.report(
                read.node,
                f"`{self.code_of(read.base)}` is {convention(order.order)} ({order.evidence}), but {read.evidence(self.facts)}, "
                f"reads it as {convention(read.order)}",
                evidence=(order.evidence,),
            )

    def _check_flat_roll(self, node: Call, flow: QuaternionFlow) -> None:
        """`np.roll(quats, -1)` without an axis on a stack of quaternions rolls the flattened array."""
        reorder = flow.reorder_of(node, through_names=False)
        if reorder is None or reorder.spelling != "roll" or len(node.args) > 2 or any(
            given.arg in ("axis", "dims") for given in node.keywords
        ):
            return
        if not flow.is_quaternion_stack(reorder.base):
            return
        self.report(
            node,
            f"`{self.code_of(node)}` has no axis: on a stack of quaternions (`{self.code_of(reorder.base)}`) it rolls the "
            "flattened array, so each quaternion takes a component from its neighbour; roll the last axis",
            replacement=with_keyword(self.facts.index.segment(node), "axis=-1"),
            applicability="unsafe",  # the stack is known from a name
            fix_description="pass axis=-1",
        )

    def _check_named_target(self, node: Assign, flow: QuaternionFlow) -> None:
        """`quat_xyzw = mat2quat(R)`: a name that states an order, bound to data in the other one."""
        if len(node.targets) != 1 or not isinstance(node.targets[0], (Name, Attribute)):
            return
        target = node.targets[0]
        stated = name_order(target.id if isinstance(target, Name) else target.attr)
        if stated is None:
            return
        order = flow.order_of(node.value)
        if order is None or order.order.index("w") == stated.index("w"):
            return
        if isinstance(target, Name) and _rebound_from_itself(self.facts, target):
            return  # `q_wxyz = r.as_quat()` then `q_wxyz = q_wxyz[:, [3, 0, 1, 2]]`: named for its final value
        self.report(
            node.value,
            f"`{self.code_of(target)}` says {convention(stated)}, but the value is in {convention(order.order)} order "
            f"({order.evidence})",
            evidence=(order.evidence,),
        )

    def _check_message_field(self, node: Assign, flow: QuaternionFlow) -> None:
        """`setpoint.q_d = Rotation.from_euler(...).as_quat()`: a quaternion written into a message field
        whose order the message class fixes (px4_msgs: w, x, y, z)."""
        if len(node.targets) != 1 or not isinstance(node.targets[0], Attribute) or node.targets[0].attr not in quaternion_field_names():
            return
        target = node.targets[0]
        cls = flow.messages.class_of(target.value)
        expected = field_order(cls, target.attr)
        if cls is None or expected is None:
            return
        field = _MessageField(target, cls)
        elements = spelled_components(self.facts, node.value)
        if elements is not None:
            order = named_order(elements)
            if order is not None:
                if order != expected and _is_other_convention(order, expected):
                    self._report(node.value, field, elements, order, expected)
                return
        self._check_value(field, node.value, expected, flow)

    def _name_contradicted(self, name: Name, flow: QuaternionFlow) -> bool:
        stated = name_order(name.id)
        if stated is None:
            return False
        for binding in self.facts.bindings(name) or []:
            if isinstance(binding, ast.expr):
                order = flow.order_of(binding)
                if order is not None and order.order.index("w") != stated.index("w"):
                    return True
        return False

    def _check(self, node: Call, flow: QuaternionFlow) -> None:
        self._check_helper(node, flow)
        self._check_stated_parameters(node, flow)
        expected = quaternion_order(self.facts, node)
        if expected is not None and not keyword_states_order(self.facts, node, expected):  # else checked above
            self._check_arguments(node, expected, flow)

    def _check_stated_parameters(self, node: Call, flow: QuaternionFlow) -> None:
        """Arguments whose order the simulator's API or the parameter's own name states."""
        if last_name(node.func) in PYBULLET_ORIENTATION_CALLS:
            for orientation in pybullet_orientation_arguments(node):
                self._check_value(node, orientation, SCALAR_LAST, flow)
        for given in node.keywords:  # `PoseTrajectory3D(orientations_quat_wxyz=q)`: the parameter states its order
            stated = name_order(given.arg) if given.arg is not None else None
            if given.arg is not None and stated in STANDARD_ORDERS:
                self._check_value(_Keyword(node, given.arg), given.value, stated, flow)  # type: ignore[arg-type]

    def _check_arguments(self, node: Call, expected: str, flow: QuaternionFlow) -> None:
        """The quaternion handed to an API that expects `expected`: four components, a spelled list, or a value."""
        facts = self.facts
        positional = positional_args(node)
        if len(positional) == 4 and len(node.args) == 4 and not node.keywords:
            order = named_order(positional)
            if order is not None and _names_mislabel_unpacked(facts, flow, positional):
                return  # `w, x, y, z = as_quat()`: the names lie about the components, the positions decide
            if order is not None:
                if order != expected and _is_other_convention(order, expected):
                    self._report(node, node, positional, order, expected)
                return
            spelled = same_base(facts, positional)  # `Quaternion(q[1], q[2], q[3], q[0])`
            if spelled is not None and sorted(spelled[1]) == [0, 1, 2, 3] and spelled[1] != [0, 1, 2, 3]:
                self._check_reorder(node, node, Reorder(node, spelled[0], tuple(spelled[1]), "arguments"), expected, flow)
                return
            # four arguments that are not four components (`tf_combine(q1, t1, q2, t2)`): the quaternion argument
        if positional and isinstance(positional[0], (ast.List, ast.Tuple)):
            elements = list(positional[0].elts)
            if len(elements) == 4 and not any(isinstance(element, Starred) for element in elements):
                order = named_order(elements)
                if order is not None:
                    if _names_mislabel_unpacked(facts, flow, elements):
                        return  # `w, x, y, z = as_quat()`: the names lie about the components, the positions decide
                    if order != expected and _is_other_convention(order, expected):
                        self._report(positional[0], node, elements, order, expected)
                    return
        argument = quaternion_argument(facts, node) or spread_argument(facts, node)
        if argument is not None:
            self._check_value(node, argument, expected, flow)

    def _report(self, reported: ast.expr, call: Call | _MessageField | _Helper, items: list[ast.expr], order: str, expected: str) -> None:
        by_component = {component: item for component, item in zip(order, items)}
        edits = [(item, self.facts.index.segment(by_component[component])) for item, component in zip(items, expected)]
        self.report(
            reported,
            f"quaternion components are in ({', '.join(order)}) order, but "
            f"{self._consumer(call)} expects {api_label(expected)}",
            replacement=replace_span(self.facts.index, reported, edits),  # type: ignore[arg-type]
            fix_description=f"reorder to {', '.join(expected)}",
        )

    # -- through data: reorders and producers ----------------------------------------------
    def _consumer(self, consumer: Call | _MessageField | _Helper | _Keyword) -> str:
        if isinstance(consumer, _Keyword):
            return f"`{consumer.name}=` of `{self.code_of(consumer.call.func)}`"
        if isinstance(consumer, _MessageField):
            return f"`{self.code_of(consumer.target)}` ({field_label(consumer.cls, consumer.target.attr)})"
        if isinstance(consumer, _Helper):
            return f"`{self.code_of(consumer.call.func)}` (which passes its parameter `{consumer.parameter}` to {consumer.where})"
        func = consumer.func
        if isinstance(func, Name) and func.id in self.facts.shared(ImportBranches).alternatives:
            # `quaternion_multiply` imported from tf under ROS 1 and as transforms3d's qmult under ROS 2
            return f"`{func.id}` (here `{branch_qualified_name(self.facts, func)}`, one of its imports in the arms of an `if`)"
        return f"`{self.code_of(func)}`"

    def _check_helper(self, node: Call, flow: QuaternionFlow) -> None:
        """A quaternion whose order is known passed to a project helper that hands the parameter,
        unchanged and unconditionally, to an API reading the other order (`yaw_from_quat(msg.q)`)."""
        facts = self.facts
        if not node.args or any(isinstance(arg, Starred) for arg in node.args) or not facts.may_have_summary(node):
            return
        if not any(type(arg) in _MAY_HAVE_ORDER and (flow.reorder_of(arg) is not None or flow.order_of(arg) is not None) for arg in node.args):
            return  # nothing with a known order or a reorder: the helper's summary cannot matter
        summary = facts.summary_of(node, QUATERNIONS)
        if summary is None:
            return
        for index, (order, where) in sorted(summary.reads_quaternion.items()):
            if order and index < len(node.args):
                self._check_value(_Helper(node, summary.parameters[index], where), node.args[index], order, flow)

    def _check_value(self, call: Call | _MessageField | _Helper | _Keyword, argument: ast.expr, expected: str, flow: QuaternionFlow) -> None:
        if isinstance(argument, Name) and self._name_contradicted(argument, flow):
            return  # reported once, where the name is bound
        reorder = flow.reorder_of(argument)
        if reorder is not None:
            self._check_reorder(call, argument, reorder, expected, flow)
            return
        order = flow.order_of(argument)
        if order is None:
            self._check_named_identity(call, argument, expected)
            return
        if order.batch and not _takes_stacks(self.facts, call) or order.order not in STANDARD_ORDERS or order.order == expected:
            return
        self.report(
            argument,
            f"`{self.code_of(argument)}` is {convention(order.order)} ({order.evidence}), but "
            f"{self._consumer(call)} expects {api_label(expected)}",
            evidence=(order.evidence,),
        )

    def _check_named_identity(self, call: Call | _MessageField | _Helper | _Keyword, argument: ast.expr, expected: str) -> None:
        """`IDENTITY_QUAT = [0, 0, 0, 1]` or `orientation=[0, 0, 0, 1],  # identity` handed to a (w, x, y, z)
        API: the name or the comment says the value is the identity, which it is only in the other order
        (read as w, x, y, z it is a half turn about z). A literal alone says nothing: a deliberate half
        turn about z is written the same way."""
        if isinstance(argument, Name):
            bound = self.facts.bindings(argument) or []
            if IDENTITY_NAME.search(argument.id) is None or len(bound) != 1 or not isinstance(bound[0], ast.expr):
                return
            literal, shown = bound[0], f"`{argument.id}` is named an identity and is"
        elif _identity_comment(self.facts.index.source, argument):
            literal, shown = argument, f"`{self.code_of(argument)}` is commented as the identity and is"
        else:
            return
        values = literal_components(self.facts, literal)
        if not (values == [0, 0, 0, 1] and expected == SCALAR_FIRST or values == [1, 0, 0, 0] and expected == SCALAR_LAST):
            return
        written = SCALAR_LAST if values[3] == 1 else SCALAR_FIRST
        self.report(
            argument,
            f"{shown} {list(values)}, the identity in {convention(written)} order, "
            f"but {self._consumer(call)} expects {api_label(expected)}: it reads a half turn about "
            f"{'z' if written == SCALAR_LAST else 'x'}",
        )

    def _check_reorder(self, call: Call | _MessageField | _Helper | _Keyword, reported: ast.expr, reorder: Reorder, expected: str, flow: QuaternionFlow) -> None:
        facts = self.facts
        other = SCALAR_FIRST if expected == SCALAR_LAST else SCALAR_LAST
        base = flow.order_of(reorder.base)
        if base is not None and (base.order not in STANDARD_ORDERS or base.batch and reorder.spelling in ("spelled", "arguments")):
            return  # rows of a stack picked one by one, or an unusual order: not a component reorder we can judge
        shown, func = facts.code_of(reorder.node), self._consumer(call)
        if base is not None:
            result = permuted(base.order, reorder.permutation)
            if result.index("w") == expected.index("w"):
                return  # right, or x, y, z permuted among themselves: an axis change, not a convention slip
            message = (
                f"`{facts.code_of(reorder.base)}` is {convention(base.order)} ({base.evidence}); `{shown}` makes it "
                f"{label(result)}, but {func} expects {api_label(expected)}"
            )
            right = permutation_between(base.order, expected)
            applicability = "safe" if base.local else "unsafe"
            evidence: tuple[str, ...] = (base.evidence,)
        else:
            if permuted(expected, reorder.permutation) != other:
                return  # the reorder turns the other convention into this one: what the API wants
            inverse = permutation_between(permuted("wxyz", reorder.permutation), "wxyz")
            if flow.module_applies(inverse) or flow.scope_applies(reorder.node, inverse):
                # the module also applies the inverse reorder somewhere: the data may carry a
                # non-standard order that this reorder undoes (two rolls that cancel)
                return
            message = (
                f"`{shown}` turns {label(expected)} into {label(other)}, but {func} expects {api_label(expected)}: "
                f"the reorder goes the wrong way (in either convention the result is not {label(expected)})"
            )
            right = permutation_between(other, expected)
            applicability = "unsafe"  # right only if the data really is in the other convention
            evidence = ()
        direct = flow.reorder_of(reported, through_names=False)
        replacement = self._reorder_fix(reorder, right) if direct is not None and direct.node is reorder.node else None
        self.report(
            reported,
            message,
            replacement=None if replacement is None else replace_span(facts.index, reported, [(reorder.node, replacement)]),
            applicability=applicability,  # type: ignore[arg-type]
            fix_description="drop the reorder" if right == (0, 1, 2, 3) else f"reorder with {list(right)}",
            evidence=evidence,
        )

    def _reorder_fix(self, reorder: Reorder, right: tuple[int, ...]) -> str | None:
        """The reorder node's text with the right permutation (or just its base when none is needed)."""
        index = self.facts.index
        base_text = index.segment(reorder.base)
        if not base_text:
            return None
        if right == (0, 1, 2, 3):
            return base_text if reorder.spelling in ("index", "roll") else None
        if reorder.spelling == "index":
            text = index.segment(reorder.node)
            old = index.segment(_last_index(reorder.node))  # type: ignore[arg-type]
            position = text.rfind(old)
            return text[:position] + repr(list(right)) + text[position + len(old) :] if old and position > 0 else None
        if reorder.spelling == "roll" and right in ((3, 0, 1, 2), (1, 2, 3, 0)):
            call = reorder.node
            shift = call.args[1] if isinstance(call, Call) and len(call.args) > 1 else None
            if shift is None:
                return None
            text = index.segment(call)
            start = _offset_in(call, shift, index)
            if start is None:
                return None
            old = index.segment(shift)
            return text[:start] + ("1" if right == (3, 0, 1, 2) else "-1") + text[start + len(old) :]
        if reorder.spelling == "spelled":
            elements = spelled_components(self.facts, reorder.node)
            if elements is None:
                return None
            by_index = {component: element for component, element in zip(reorder.permutation, elements)}
            edits = [(element, index.segment(by_index[component])) for element, component in zip(elements, right)]
            return replace_span(index, reorder.node, edits)  # type: ignore[arg-type]
        return None

    def _check_named_reads(self, group: dict[str, tuple[Name, Subscript]], flow: QuaternionFlow) -> None:
        """`ori_x = q[0]` ... `ori_w = q[3]`: four local names that say which component they hold, read by
        index from one quaternion of known order with w taken from another index than the order puts it at."""
        values: dict[str, ast.expr] = {letter: value for letter, (_, value) in group.items()}
        names = {letter: target.id for letter, (target, _) in group.items()}
        shape = "`" + names["w"].replace("{", "{{").replace("}", "}}")[:-1] + "{letter} = {value}`"
        # reported where the message quotes: the statement that reads w (`qw = q[3]`)
        read = group["w"][0]
        self._check_components(self.facts.parent(read) or read, values, flow, shape, fixable=False)

    # -- components written one by one: dicts, keyword arguments, message fields ----------------
    def _check_component_writes(self, flow: QuaternionFlow) -> None:
        facts = self.facts
        for node in facts.index.nodes(ast.Dict):
            if len(node.keys) < 4:  # type: ignore[attr-defined]
                continue  # four components need four keys
            mapping = {string(key): value for key, value in zip(node.keys, node.values) if string(key) in _LETTERS}  # type: ignore[attr-defined]
            if len(mapping) == 4:
                self._check_components(node, mapping, flow, '`"{letter}": {value}`')  # type: ignore[arg-type]
        for node in facts.index.nodes(Call):
            if len(node.keywords) < 4:  # type: ignore[attr-defined]
                continue
            mapping = {given.arg: given.value for given in node.keywords if given.arg in _LETTERS}  # type: ignore[attr-defined]
            if len(mapping) == 4:
                self._check_components(node, mapping, flow, "`{letter}={value}`")  # type: ignore[arg-type]
        for scope in facts.index.scopes.values():
            groups: dict[str, dict[str, tuple[Attribute, ast.expr]]] = {}
            for target, value in scope.attribute_stores:
                if target.attr in _LETTERS and isinstance(facts.parent(target), Assign):
                    groups.setdefault(ast.dump(target.value), {})[target.attr] = (target, value)
            for group in groups.values():
                if len(group) == 4:
                    written = group["w"][0]  # reported where the message quotes: the store into w
                    owner = facts.code_of(written.value)
                    values = {letter: value for letter, (_, value) in group.items()}
                    self._check_components(facts.parent(written) or written, values, flow, f"`{owner}.{{letter}} = {{value}}`", fixable=False)

    def _check_components(
        self, reported: AST, mapping: dict[str, ast.expr], flow: QuaternionFlow, shape: str, fixable: bool = True
    ) -> None:
        facts = self.facts
        named = {letter: component_name(value) for letter, value in mapping.items()}
        if all(found is not None and found[1] for found in named.values()) and len({found[1] for found in named.values()}) == 1:  # type: ignore[index]
            source = named["w"][0]  # type: ignore[index]
            if sorted(found[0] for found in named.values()) == sorted(COMPONENTS) and source != "w":  # type: ignore[index]
                written = shape.format(letter="w", value=facts.code_of(mapping["w"]))
                self.report(
                    reported,
                    f"{written} writes the {source} component into w: a quaternion's scalar part never moves to an axis "
                    "slot (component names are the same in every convention)",
                )
            return
        spelled = same_base(facts, [mapping[letter] for letter in COMPONENTS])
        if spelled is None or sorted(spelled[1]) != [0, 1, 2, 3]:
            return
        base, indices = spelled
        order = flow.order_of(base)
        if order is None or order.order not in STANDARD_ORDERS:
            return
        if order.batch and any(not isinstance(mapping[letter].slice, ast.Tuple) for letter in COMPONENTS):  # type: ignore[attr-defined]
            return  # `xquat[3]` is a row of the stack, not a component
        if indices[0] == order.order.index("w"):
            return  # w is read where it is; x, y, z permuted among themselves is an axis change
        letter = "w"
        value = mapping[letter]
        written = shape.format(letter=letter, value=facts.code_of(value))
        right = order.order.index(letter)
        edits: list[tuple[AST, str]] = []
        for component in COMPONENTS:
            element = mapping[component]
            text = facts.index.segment(element)
            old = facts.index.segment(_last_index(element))  # type: ignore[arg-type]
            position = text.rfind(old)
            if not fixable or not old or position <= 0:
                edits = []
                break
            edits.append((element, text[:position] + str(order.order.index(component)) + text[position + len(old) :]))
        self.report(
            reported,
            f"{written} reads component {indices[COMPONENTS.index(letter)]} as {letter}, but `{facts.code_of(base)}` is "
            f"{convention(order.order)} ({order.evidence}): {letter} is component {right}",
            replacement=replace_span(facts.index, reported, edits) if edits else None,  # type: ignore[arg-type]
            applicability="safe" if order.local else "unsafe",
            fix_description=f"read the components in {convention(order.order)} order",
            evidence=(order.evidence,),
        )


def _under_branch_on(facts: FactBase, node: AST, function: AST) -> bool:
    """Whether a branch encloses `node` (one on the flag picks the positions; any other, to be safe)."""
    current = facts.parent(node)
    while current is not None and current is not function:
        if isinstance(current, (If, IfExp, While, Match)):
            return True
        current = facts.parent(current)
    return False


def _collect_named_read(facts: FactBase, node: Assign, groups: dict[tuple[int, str, str], dict[str, tuple[Name, Subscript]]]) -> None:
    """`ori_x = ee_quat[0]`: a name that says it holds one component (`_component`), bound to one index of
    a name; grouped by scope, indexed name and the names' common prefix."""
    if len(node.targets) != 1 or not isinstance(node.targets[0], Name) or not isinstance(node.value, Subscript):
        return
    target, value = node.targets[0], node.value
    if not isinstance(value.value, Name) or type(number(value.slice)) is not int:
        return
    component = component_name(target)
    if component is None or component[1] == "":
        return  # a bare `x = q[0]` may be anything; `qx`, `ori_x`, `quat_w` say a quaternion component
    key = (id(facts.index.scope_of(node).node), value.value.id, component[1])
    groups.setdefault(key, {})[component[0]] = (target, value)


def _is_other_convention(order: str, expected: str) -> bool:
    return {order, expected} == {SCALAR_FIRST, SCALAR_LAST}


def _names_mislabel_unpacked(facts: FactBase, flow: QuaternionFlow, values: list[ast.expr]) -> bool:
    """Whether a component name was bound by unpacking a quaternion of known order into a position
    that holds another component: after `w, x, y, z = Rotation.as_quat()` (x, y, z, w), `w` holds x,
    and `[w, x, y, z]` is scipy's order again. The names then say nothing about the components."""
    for value in values:
        if not isinstance(value, Name):
            continue
        bound = value_of(facts.index, value)
        if not isinstance(bound, Unpacked) or len(bound.names) != 4:
            continue
        source = flow.order_of(bound.value)
        component = component_name(value)
        if source is None or source.batch or component is None or len(source.order) != 4:
            continue
        if source.order[bound.index] != component[0]:
            return True
    return False


def _takes_stacks(facts: FactBase, call: Call | _MessageField | _Helper | _Keyword) -> bool:
    """APIs that accept an (N, 4) stack as well as one quaternion (`STACKED` in their stubs, and a few by name)."""
    if isinstance(call, _Keyword):
        return True  # the parameter's own name states the order, for one quaternion or a stack
    if isinstance(call, (_MessageField, _Helper)):
        return False  # a message field holds one; a helper may index its parameter as one
    name = last_name(call.func) or ""
    return name in ("from_quat", "from_float_array", "as_quat_array") or name.startswith("quaternion_") or accepts_stacks(facts, call)




def _identity_comment(source: str, node: ast.expr) -> bool:
    """Whether a comment on the line where `node` ends calls it the identity (`# identity quaternion`)."""
    lines = source.splitlines()
    end = getattr(node, "end_lineno", None)
    if end is None or end > len(lines):
        return False
    line = lines[end - 1]
    comment = line.find("#", getattr(node, "end_col_offset", 0) or 0)
    return comment >= 0 and _IDENTITY_COMMENT.search(line[comment:]) is not None


_IDENTITY_COMMENT: Final = re.compile(r"(?i)\b(?:identity|no rotation|unrotated)\b")


def _last_index(node: AST) -> ast.expr:
    parts = subscript_parts(unwrapped_scalar(node))  # type: ignore[arg-type]
    return parts[-1]


def _offset_in(outer: AST, inner: AST, index: object) -> int | None:
    """Where `inner` starts within the text of `outer` (both on one line only)."""
    if getattr(outer, "lineno", None) != getattr(inner, "end_lineno", None) or outer.lineno != inner.lineno:  # type: ignore[attr-defined]
        return None
    line = index.source.splitlines()[outer.lineno - 1].encode()  # type: ignore[attr-defined]
    return len(line[outer.col_offset : inner.col_offset].decode(errors="replace"))  # type: ignore[attr-defined]


def _rebound_from_itself(facts: FactBase, target: Name) -> bool:
    """Whether a later binding of the target's name is computed from the name itself."""
    later = facts.index.scope_of(target).bindings.get(target.id, [])
    return any(
        isinstance(value, ast.expr) and value.lineno > target.lineno
        and any(isinstance(node, Name) and node.id == target.id for node in ast.walk(value))
        for value in later
    )
