"""Unit tests of the shared semantic model: names, kinds, frames, flow, homogeneous forms."""

from __future__ import annotations

import ast

import pytest

from geolint.algebra import Kind as Algebra
from geolint.factbase.index import ModuleIndex
from geolint.factbase.model import DST_FIRST, SRC_FIRST, FactBase
from geolint.lint_types import Config, NamingConventions
from geolint.semantic.names import Kind, NameFrames, frames_of_name, kind_of_name, same_frame


@pytest.mark.parametrize(
    ("name", "kind"),
    [
        ("normal", Kind.DIRECTION),
        ("normals", Kind.DIRECTION),
        ("surface_normal", Kind.DIRECTION),
        ("ray_dir", Kind.DIRECTION),
        ("vertex_normals", Kind.DIRECTION),
        ("VERTICES_AXIS", None),  # the vertices of a drawn axis, or an axis: a plural word is no modifier
        ("points_normal", None),
        ("v_cam", None),  # a vector, a velocity or a mesh's vertices: the frame is stated, the kind is not
        ("points", Kind.POINT),
        ("p_world", Kind.POINT),
        ("p_BQ", Kind.POINT),
        ("grasp_point_cam", Kind.POINT),
        ("T_world_cam", Kind.TRANSFORM),
        ("R_world_cam", Kind.ROTATION),
        ("n", None),  # a count
        ("n_points", None),
        ("normal_idx", None),
        ("p", None),  # a probability or a polynomial as often as a point
        ("p_value", None),
        ("pointer", None),
        ("origin_projected_on_screw_axis", None),  # two kinds in one long name: cannot tell
    ],
)
def test_kind_of_name(name: str, kind: Kind | None) -> None:
    assert kind_of_name(name, DRAKE) == kind


# Drake's monogram names are read where the project imports pydrake (or the config says so)
DRAKE = Config(naming=NamingConventions(monogram=True))


def test_monogram_names_are_frames_only_in_drake_code() -> None:
    assert frames_of_name("X_WB") is None and kind_of_name("p_BQ") is None  # `X_EQ` is a state vector elsewhere
    assert frames_of_name("X_WB", DRAKE) == NameFrames(dst="w", src="b", operator="transform")


def test_extra_names_from_config() -> None:
    config = Config(extra_direction_names=("spin",), extra_point_names=("waypoint",))
    assert kind_of_name("spin", config) == Kind.DIRECTION
    assert kind_of_name("waypoint", config) == Kind.POINT
    assert kind_of_name("spin") is None


@pytest.mark.parametrize(
    ("name", "frames"),
    [
        ("T_world_cam", NameFrames(dst="world", src="cam", operator="transform")),
        ("R_world_cam", NameFrames(dst="world", src="cam", operator="rotation")),
        ("world_T_cam", NameFrames(dst="world", src="cam", operator="transform")),
        ("X_WB", NameFrames(dst="w", src="b", operator="transform")),
        ("world_from_cam", NameFrames(dst="world", src="cam", operator="unknown")),
        ("cam_to_world", NameFrames(dst="world", src="cam", operator="unknown")),
        ("cam2world", NameFrames(dst="world", src="cam", operator="unknown")),
        ("A2B", NameFrames(dst="b", src="a", operator="unknown")),
        ("I2C", None),  # a bus, not frames I and C
        ("A2C", None),  # a learning algorithm
        ("image_to_base64", None),  # an encoding
        ("p_world", NameFrames(frame="world")),
        ("p_BQ", NameFrames(frame="b")),
        ("point_in_cam", NameFrames(frame="cam")),
        ("v_cam", NameFrames(frame="cam")),
        # conversions and qualifiers are not frames
        ("deg2rad", None),
        ("herm2poly", None),
        ("coef2d", None),
        ("module_from_spec", None),
        ("pos_des", None),
        ("p_h", None),
        ("T_world_base_link", None),  # ambiguous split
    ],
)
def test_frames_of_name(name: str, frames: NameFrames | None) -> None:
    assert frames_of_name(name, DRAKE) == frames


def test_naming_switches_and_aliases() -> None:
    no_monogram = Config(naming=NamingConventions(monogram=False))
    assert frames_of_name("X_WB", no_monogram) is None
    assert frames_of_name("T_world_cam", no_monogram) is not None
    no_suffix = Config(naming=NamingConventions(suffix=False))
    assert frames_of_name("p_world", no_suffix) is None
    aliased = Config(frame_aliases={"cam": "camera"})
    assert frames_of_name("T_world_cam", aliased) == NameFrames(dst="world", src="camera", operator="transform")
    assert frames_of_name("p_camera", aliased) == NameFrames(frame="camera")


def test_same_frame_never_compares_a_letter_with_a_word() -> None:
    assert same_frame("world", "world") is True
    assert same_frame("world", "cam") is False
    assert same_frame("w", "world") is None
    assert same_frame(None, "cam") is None


def test_same_frame_does_not_compare_a_word_with_its_abbreviation() -> None:
    assert same_frame("cam", "camera") is None
    assert same_frame("base_link", "base") is None
    assert same_frame("camera", "base") is False


def model_of(source: str, orders: tuple[str, ...] = (DST_FIRST,)) -> tuple[FactBase, ast.Module]:
    tree = ast.parse(source)
    return FactBase(ModuleIndex(tree, source), Config(), "<string>", orders), tree


def last_value(module: ast.Module) -> ast.expr:
    return module.body[-1].value  # type: ignore[attr-defined,no-any-return]


@pytest.mark.parametrize(
    ("source", "kind"),
    [
        ("import numpy as np\nx = np.cross(a, b)\nx\n", Algebra.DIRECTION),
        ("import numpy as np\nd = offset / np.linalg.norm(offset)\nd\n", Algebra.DIRECTION),
        ("delta = tip_position - base_position\ndelta\n", Algebra.VECTOR),  # the algebra: p - q is a vector
        ("for item in normals:\n    pass\nitem\n", Algebra.DIRECTION),
        ("for i, item in enumerate(points):\n    pass\nitem\n", Algebra.POINT),
        ("alias = mesh.vertices\nalias\n", Algebra.POINT),
        ("row = normals[3]\nrow\n", Algebra.DIRECTION),
        ("def helper():\n    return mesh.face_normals\nhelper()\n", Algebra.DIRECTION),
        ("import torch\nn = torch.cross(a, b, dim=-1)\nm = n.detach().cpu()\nm\n", Algebra.DIRECTION),
        ("class C:\n    def __init__(self, mesh):\n        self.vn = mesh.vertex_normals\nC().vn\n", None),
        ("a, b = mesh.vertices, mesh.face_normals\nb\n", Algebra.DIRECTION),
        ('direction = "left"\ndirection\n', None),
        ("velocity = distance / dt\nvelocity\n", None),
        ("import numpy as np\nnormal = np.random.normal(size=3)\nnormal\n", None),
        # the origin next to points along the axes: points (a drawn frame), whatever the name says
        ("import numpy as np\ntips = np.array([[0, 0, 0], [l, 0, 0], [0, l, 0], [0, 0, l]])\ntips\n", Algebra.POINT),
        ("import numpy as np\nsensor_axis = np.array([[0, 0, 0], [l, 0, 0], [0, 0, l]], dtype=float)\nsensor_axis\n", None),
        ("sensor_axis = [[0.0, 0.0, 0.0], [0.0, 0.0, l]]\nsensor_axis\n", None),
        ("import numpy as np\nsensor_axis = np.array([[l, 0, 0], [0, l, 0], [0, 0, l]])\nsensor_axis\n", Algebra.DIRECTION),
        ("import numpy as np\nseg = np.array([[0, a], [0, b], [0, 0]])\nseg\n", None),  # points in columns: no reading
        ("import numpy as np\nm = np.array([[0, 0, 0], [l, l, 0]])\nm\n", None),  # not along one axis
    ],
)
def test_kind_flow(source: str, kind: Algebra | None) -> None:
    model, module = model_of(source)
    assert model.kind_of(last_value(module)) == kind


ODOMETRY_CALLBACK = (
    "from nav_msgs.msg import Odometry\n"
    "from geometry_msgs.msg import Transform, Vector3Stamped\n"
    "def on_odometry(msg):\n    pass\n"
    "node.create_subscription(Odometry, 'odom', on_odometry, 10)\n"
)


@pytest.mark.parametrize(
    ("expression", "kind"),
    [
        ("msg.twist.twist.linear", Algebra.VECTOR),  # the subscription says msg is an Odometry
        ("msg.twist.twist.angular", Algebra.VECTOR),
        ("msg.pose.pose.position", Algebra.POINT),
        ("[msg.twist.twist.linear.x, msg.twist.twist.linear.y, msg.twist.twist.linear.z]", Algebra.VECTOR),
        ("Vector3Stamped().vector", Algebra.VECTOR),
        ("Transform().translation", Algebra.TRANSLATION),
        ("msg.pose.pose.orientation", None),
        ("msg.twist.linear", None),  # an Odometry has no such field: no guess
        ("other.twist.twist.linear", None),  # an untyped value: the field's name is no evidence
        ("[v.x, v.y, v.z]", None),
        ("[a.x, b.y, c.z]", None),
    ],
)
def test_message_field_kinds(expression: str, kind: Algebra | None) -> None:
    model, module = model_of(ODOMETRY_CALLBACK.replace("    pass", f"    return {expression}"))
    function = module.body[2]
    returned = function.body[0].value  # type: ignore[attr-defined]
    assert model.kind_of(returned) == kind


def test_components_carry_the_kind_of_their_value() -> None:
    model, module = model_of("import numpy as np\nv = np.array([normal.x, normal.y, normal.z])\nv\n")
    assert model.kind_of(last_value(module)) == Algebra.DIRECTION
    model, module = model_of("import numpy as np\nh = np.array([normal.x, normal.y, normal.z, 1.0])\n")
    found = model.homogeneous(module.body[-1].value)  # type: ignore[attr-defined]
    assert found is not None and found.w == 1 and ast.unparse(found.inner) == "normal"


def test_self_attribute_flow() -> None:
    source = "class Cloud:\n    def load(self, mesh):\n        self.vn = mesh.vertex_normals\n    def use(self):\n        return self.vn\n"
    model, module = model_of(source)
    returned = module.body[0].body[1].body[0].value  # type: ignore[attr-defined]
    assert model.kind_of(returned) == Algebra.DIRECTION


def test_parameter_default_says_not_geometry() -> None:
    model, module = model_of("def f(axis=0):\n    return axis\n")
    assert model.kind_of(module.body[0].body[0].value) is None  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    ("expression", "frames"),
    [
        ("np.linalg.inv(T_world_cam)", NameFrames(dst="cam", src="world", operator="transform")),
        ("R_world_cam.T", NameFrames(dst="cam", src="world", operator="rotation")),
        ("T_world_cam[:3, :3]", NameFrames(dst="world", src="cam", operator="rotation")),
        ("T_world_cam[:3, 3]", NameFrames(frame="world")),
        ("T_world_base @ T_base_cam", NameFrames(dst="world", src="cam", operator="transform")),
        ("T_world_cam @ p_cam", NameFrames(frame="world")),
        ("pts_cam @ R_world_cam.T", NameFrames(frame="world")),
        ("T_world_base @ T_cam_tool", None),  # mismatched: no frame, never a guess
    ],
)
def test_frames_of_expressions(expression: str, frames: NameFrames | None) -> None:
    model, module = model_of(f"import numpy as np\nresult = {expression}\n")
    assert model.frames_of(module.body[-1].value) == frames  # type: ignore[attr-defined]


def test_src_first_reading_flips_only_letter_names() -> None:
    model, module = model_of("T_obj_world @ world_from_cam\n", orders=(SRC_FIRST,))
    product = last_value(module)
    assert model.frames_of(product.left, SRC_FIRST) == NameFrames(dst="world", src="obj", operator="transform")  # type: ignore[attr-defined]
    assert model.frames_of(product.right, SRC_FIRST) == NameFrames(dst="world", src="cam", operator="unknown")  # type: ignore[attr-defined]


def test_explicit_declaration_beats_the_name() -> None:
    source = 'T_obj_world = RigidTransform(R, t, from_frame="obj", to_frame="world")\nT_obj_world\n'
    model, module = model_of(source)
    fact = model.frame_fact(last_value(module))
    assert fact is not None and fact.declared
    assert fact.frames == NameFrames(dst="world", src="obj", operator="transform")
    assert "from_frame='obj'" in fact.evidence[0]


def test_a_name_rebound_to_its_own_inverse_has_no_frames() -> None:
    model, module = model_of("import numpy as np\nworld2cam = np.linalg.inv(world2cam)\nworld2cam\n")
    assert model.frames_of(last_value(module)) is None


@pytest.mark.parametrize(
    ("construction", "w"),
    [
        ("np.append(x, 1)", 1),
        ("np.append(x, [0])", 0),
        ("np.r_[x, 1.0]", 1),
        ("np.hstack([x, np.ones((len(x), 1))])", 1),
        ("np.column_stack((x, np.zeros(len(x))))", 0),
        ("np.concatenate([x, [1]], axis=-1)", 1),
        ("np.array([x[0], x[1], x[2], 1])", 1),
        ("torch.cat([x, torch.zeros(*shape).type_as(x)], dim=-1)", 0),
        ("torch.cat([x, torch.ones_like(x[..., :1])], dim=-1)", 1),
        ("F.pad(x, (0, 1), value=1.0)", 1),
        ("F.pad(x, [0, 1, 0, 0], 'constant', 1)", 1),
        ("torch.nn.functional.pad(x, (0, 1))", 0),  # the default constant is 0
        ("np.pad(x, ((0, 0), (0, 1)), constant_values=1)", 1),
        ("np.pad(x, [(0, 0), (0, 0), (0, 1)])", 0),
    ],
)
def test_homogeneous_forms(construction: str, w: int) -> None:
    model, module = model_of(f"import numpy as np\nimport torch\nimport torch.nn.functional as F\nh = {construction}\n")
    found = model.homogeneous(module.body[-1].value)  # type: ignore[attr-defined]
    assert found is not None and found.w == w
    assert ast.unparse(found.inner).startswith("x")


@pytest.mark.parametrize(
    "construction",
    [
        "np.pad(x, (0, 1), constant_values=1)",  # a bare pair pads every axis
        "F.pad(x, (1, 0), value=1.0)",  # prepended
        "F.pad(x, (0, 1, 0, 1), value=1.0)",  # another axis padded too
        "F.pad(x, (0, 1), mode='replicate')",
        "F.pad(x, [0, 0, 0, 1], value=1)",  # a row appended: the bottom of [R t; 0 1]
        "other.pad(x, (0, 1), value=1)",
    ],
)
def test_pads_that_append_no_w(construction: str) -> None:
    model, module = model_of(f"import numpy as np\nimport torch.nn.functional as F\nh = {construction}\n")
    assert model.homogeneous(module.body[-1].value) is None  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    ("product", "acting"),
    [
        ('np.einsum("ij,jk->ik", A, B)', ("A", "B")),
        ('np.einsum("ij,nj->ni", R, points)', ("R", "points")),  # R acting on rows
        ('np.einsum("nj,ij->ni", points, R)', ("R", "points")),
        ('np.einsum("nj,ji->ni", points, R)', ("points", "R")),  # `points @ R`: R's transpose acts
        ('torch.einsum("bij,bkj->bki", R, x)', ("R", "x")),
        ('torch.einsum("...ij, ...j -> ...i", R, x)', ("R", "x")),
        ('np.einsum("bi,bi->b", a, b)', None),  # a dot product
        ('np.einsum("bij,bjk->bki", A, B)', None),  # the product's transpose
        ('np.einsum("ii->", A)', None),
        ("np.einsum(spec, R, x)", None),
    ],
)
def test_einsum_as_a_matrix_product(product: str, acting: tuple[str, str] | None) -> None:
    model, module = model_of(f"import numpy as np\nimport torch\n{product}\n")
    found = model.matmul(last_value(module))
    assert (None if found is None else (ast.unparse(found.left), ast.unparse(found.right))) == acting


@pytest.mark.parametrize(
    ("product", "operands"),
    [
        ("torch.mm(R, x)", ("R", "x")), ("torch.linalg.matmul(R, x)", ("R", "x")), ("np.linalg.matmul(R, x)", ("R", "x")),
        ("tf.linalg.matmul(R, x)", ("R", "x")), ("torch.bmm(R, x)", ("R", "x")), ("R.mm(x)", ("R", "x")), ("R.bmm(x)", ("R", "x")),
        ("mm(R, x)", None),  # a project's function of that name: not an array namespace's
        ("np.mm(R, x)", None),  # numpy has no `mm`
        ("torch.add(R, x)", None),
    ],
)
def test_a_product_in_any_spelling_the_stubs_state(product: str, operands: tuple[str, str] | None) -> None:
    model, module = model_of(f"import numpy as np\nimport torch\nimport tensorflow as tf\n{product}\n")
    found = model.matmul(last_value(module))
    assert (None if found is None else (ast.unparse(found.left), ast.unparse(found.right))) == operands


@pytest.mark.parametrize(
    ("expression", "matrix"),
    [("T[:3, 3]", "T"), ("T[:, :3, 3]", "T"), ("T[..., :3, 3:]", "T"), ("T[:3, 3:4]", "T"), ("T[:3, -1:]", "T"), ("T[:3, 2:]", None), ("T[:3, :3]", None)],
)
def test_the_translation_column_of_a_transform(expression: str, matrix: str | None) -> None:
    model, module = model_of(f"{expression}\n")
    found = model.translation_of(last_value(module))
    assert (None if found is None else ast.unparse(found)) == matrix


@pytest.mark.parametrize(
    ("expression", "matrix"),
    [
        ("T.T", "T"), ("T.mT", "T"), ("T.t()", "T"), ("T.transpose()", "T"), ("T.transpose(-2, -1)", "T"),
        ("T.transpose(0, 1)", "T"), ("T.swapaxes(-1, -2)", "T"), ("T.permute(1, 0)", "T"), ("T.permute(0, 2, 1)", "T"),
        ("np.transpose(T)", "T"), ("np.swapaxes(T, -1, -2)", "T"), ("np.matrix_transpose(T)", "T"),
        ("torch.transpose(T, -1, -2)", "T"), ("torch.swapaxes(T, -2, -1)", "T"), ("tf.linalg.matrix_transpose(T)", "T"),
        ("image.transpose(2, 0, 1)", None),  # channels first: not a matrix transpose
        ("x.permute(2, 0, 1)", None),
        ("np.transpose(x, (2, 0, 1))", None),
        ("torch.transpose(x, 0, 2)", None),
        ("np.linalg.inv(T)", None),  # an inverse, not a transpose
        ("T.inverse()", None),
    ],
)
def test_a_transpose_in_any_spelling(expression: str, matrix: str | None) -> None:
    model, module = model_of(f"import numpy as np\nimport torch\nimport tensorflow as tf\n{expression}\n")
    found = model.transposed(last_value(module))
    assert (None if found is None else ast.unparse(found)) == matrix


def test_concatenation_along_the_first_axis_is_not_homogeneous() -> None:
    model, module = model_of("import numpy as np\nh = np.concatenate([x, np.ones((1, 3))], axis=0)\n")
    assert model.homogeneous(module.body[-1].value) is None  # type: ignore[attr-defined]


def test_ones_buffer_filled_with_xyz() -> None:
    model, module = model_of("import numpy as np\nh = np.ones(4)\nh[:3] = x\nh\n")
    found = model.homogeneous(last_value(module))
    assert found is not None and found.w == 1 and found.fixed == "np.zeros(4)"


@pytest.mark.parametrize(
    ("name", "frames"),
    [
        ("odom_tform_body", NameFrames(dst="odom", src="body", operator="transform")),
        ("_vision_tform_hand", NameFrames(dst="vision", src="hand", operator="transform")),
        ("flat_body_tform_body", NameFrames(dst="flat_body", src="body", operator="transform")),
        ("last_odom_tform_body", None),  # a qualifier, not part of the frame
        ("body_tform_goal", None),  # a waypoint word
        ("se3_a_tform_b", None),
        ("tform_body", None),
    ],
)
def test_boston_dynamics_tform_names(name: str, frames: NameFrames | None) -> None:
    """Boston Dynamics' `a_tform_b` maps b into a, whatever the project's `T_a_b` order."""
    assert frames_of_name(name) == frames
    assert frames_of_name(name, Config(naming=NamingConventions(prefix_t=False))) is None
