"""The array namespaces' stubs (numpy, jax.numpy, cupy, torch, tensorflow, scipy.linalg): which functions
transpose, invert and multiply matrices, read by name as a file writes it (`np.linalg.inv`, `torch.bmm`), and
checked numerically on numpy (the one of them installed for the tests)."""

from __future__ import annotations

import numpy as np
import pytest

from geolint.knowledge import knowledge_base
from geolint.knowledge.markers import ArrayOperation
from tests.knowledge.facts_helpers import QUARTER_TURN_Z

A_POSE = np.array([[0.0, -1.0, 0.0, 1.0], [1.0, 0.0, 0.0, 2.0], [0.0, 0.0, 1.0, 3.0], [0.0, 0.0, 0.0, 1.0]])
STACK = np.stack([QUARTER_TURN_Z, QUARTER_TURN_Z.T])


@pytest.mark.parametrize(
    ("written", "operation"),
    [
        ("np.linalg.inv", ArrayOperation.INVERSE), ("numpy.linalg.pinv", ArrayOperation.INVERSE), ("la.inv", ArrayOperation.INVERSE),
        ("torch.inverse", ArrayOperation.INVERSE), ("torch.linalg.inv", ArrayOperation.INVERSE), ("jnp.linalg.inv", ArrayOperation.INVERSE),
        ("cp.linalg.inv", ArrayOperation.INVERSE), ("scipy.linalg.inv", ArrayOperation.INVERSE), ("tf.linalg.inv", ArrayOperation.INVERSE),
        ("np.transpose", ArrayOperation.TRANSPOSE), ("torch.transpose", ArrayOperation.TRANSPOSE), ("np.swapaxes", ArrayOperation.TRANSPOSE),
        ("np.dot", ArrayOperation.MATMUL), ("torch.bmm", ArrayOperation.MATMUL), ("jnp.matmul", ArrayOperation.MATMUL), ("tf.matmul", ArrayOperation.MATMUL),
        ("np.einsum", ArrayOperation.EINSUM), ("torch.einsum", ArrayOperation.EINSUM),
        ("np.linalg.norm", None), ("torch.sum", None), ("rotation.inv", None),
    ],
)  # fmt: skip
def test_what_a_function_as_written_does_to_matrices(written: str, operation: str | None) -> None:
    assert knowledge_base().array_operation(written) == operation


def test_a_conventional_name_never_hides_a_package_of_that_name() -> None:
    """`tf` is TensorFlow by convention, and ROS's tf package by name: the package's own functions win."""
    api = knowledge_base().api_as_written("tf.transformations.rotation_matrix")
    assert api is not None and api.qualified_name == "tf.transformations.rotation_matrix"
    assert knowledge_base().is_array_namespace("np") and knowledge_base().is_array_namespace("torch")
    assert not knowledge_base().is_array_namespace("math") and not knowledge_base().is_array_namespace("rospy")


def test_numpy_functions_do_what_their_stubs_say() -> None:
    kb = knowledge_base()
    assert kb.array_operation("np.linalg.inv") == ArrayOperation.INVERSE
    assert np.allclose(np.linalg.inv(A_POSE) @ A_POSE, np.eye(4))
    assert np.allclose(np.linalg.inv(STACK) @ STACK, np.eye(3))  # stacks broadcast
    assert kb.array_operation("np.transpose") == ArrayOperation.TRANSPOSE
    assert np.allclose(np.transpose(QUARTER_TURN_Z), QUARTER_TURN_Z.T)
    assert np.allclose(np.transpose(STACK, (0, 2, 1))[1], QUARTER_TURN_Z)  # axes given: the last two swapped
    assert kb.array_operation("np.swapaxes") == ArrayOperation.TRANSPOSE
    assert np.allclose(np.swapaxes(STACK, -1, -2)[0], QUARTER_TURN_Z.T)
    assert kb.array_operation("np.matmul") == ArrayOperation.MATMUL == kb.array_operation("np.dot")
    assert np.allclose(np.matmul(STACK, STACK), STACK @ STACK) and np.allclose(np.dot(QUARTER_TURN_Z, A_POSE[:3, :3]), QUARTER_TURN_Z @ A_POSE[:3, :3])
    assert kb.array_operation("np.einsum") == ArrayOperation.EINSUM
    assert np.allclose(np.einsum("ij,nj->ni", QUARTER_TURN_Z, np.eye(3)), np.eye(3) @ QUARTER_TURN_Z.T)


@pytest.mark.parametrize(
    ("written", "operation"),
    [
        ("np.pad", ArrayOperation.PAD_PER_AXIS), ("jnp.pad", ArrayOperation.PAD_PER_AXIS), ("cp.pad", ArrayOperation.PAD_PER_AXIS),
        ("F.pad", ArrayOperation.PAD_LAST_AXIS_FIRST), ("torch.nn.functional.pad", ArrayOperation.PAD_LAST_AXIS_FIRST),
        ("F.grid_sample", ArrayOperation.FEATURES), ("torch.nn.functional.interpolate", ArrayOperation.FEATURES), ("F.normalize", None),
    ],
)  # fmt: skip
def test_pads_and_feature_maps_are_stub_facts(written: str, operation: str | None) -> None:
    assert knowledge_base().array_operation(written) == operation


def test_numpy_pads_each_axis_with_a_before_and_after_pair() -> None:
    padded = np.pad(np.zeros((2, 3)), ((0, 0), (0, 1)), constant_values=1.0)  # the stub's pad_width: per axis, the last axis last
    assert padded.shape == (2, 4) and np.all(padded[:, 3] == 1.0) and np.all(padded[:, :3] == 0.0)


def test_the_array_namespaces_and_what_belongs_to_them_come_from_the_stubs() -> None:
    base = knowledge_base()
    assert {module for module in ("numpy", "torch", "jax.numpy", "cupy", "tensorflow") if base.is_namespace_module(module)} == {"numpy", "torch", "jax.numpy", "cupy", "tensorflow"}
    assert not base.is_namespace_module("numpy.linalg") and not base.is_namespace_module("math")
    # a library that is only an array namespace owns every name under it; scipy owns only scipy.linalg
    assert base.in_array_library("jax.random.normal") and base.in_array_library("torch.nn.functional.pad") and base.in_array_library("scipy.linalg.inv")
    assert not base.in_array_library("scipy.spatial.transform.Rotation") and not base.in_array_library("trimesh.transformations")
    assert base.conventional_array_module("np") == "numpy" and base.conventional_array_module("F") == "torch.nn.functional"
    assert base.conventional_array_module("R") is None  # scipy's Rotation by convention, but no array module


def test_torch_makers_take_sizes_one_by_one() -> None:
    zeros = knowledge_base().api_as_written("torch.zeros")
    assert zeros is not None and zeros.signatures[0].parameters[0].variadic


def test_numpy_keeps_and_appends_values_as_its_stub_says() -> None:
    point = np.array([1.0, 2.0, 3.0])
    assert knowledge_base().array_operation("np.asarray") == ArrayOperation.AS_ARRAY
    assert np.asarray(point) is point
    assert knowledge_base().array_operation("np.append") == ArrayOperation.APPEND_FLAT
    assert np.append(point, 1.0).tolist() == [1.0, 2.0, 3.0, 1.0]
    assert np.append(np.ones((2, 3)), 1.0).shape == (7,)  # flattened first


@pytest.mark.parametrize(
    ("defined_as", "public"),
    [
        ("numpy._core.multiarray.dot", "numpy.dot"),
        ("numpy._core.umath.matmul", "numpy.matmul"),
        ("numpy.linalg._linalg.inv", "numpy.linalg.inv"),
        ("numpy.lib._function_base_impl.append", "numpy.append"),  # not numpy.lib.append
        ("numpy.linalg.inv", "numpy.linalg.inv"),
        ("numpy._core.multiarray.not_a_function", None),
        ("mypackage._impl.dot", None),  # not a stubbed package
    ],
)
def test_a_name_as_a_type_checker_spells_it_is_found_through_its_public_re_export(defined_as: str, public: str | None) -> None:
    """mypy names a function after the (private) module that defines it."""
    api = knowledge_base().api_defined_as(defined_as)
    assert (api.qualified_name if api is not None else None) == public


def test_the_plugin_dispatches_numpy_calls_on_their_stub_facts() -> None:
    from geolint.mypy import numpy_calls
    from geolint.mypy.plugin import ARRAY_OPERATION_HOOKS, _array_function_hook

    assert _array_function_hook("numpy._core.multiarray.dot") is ARRAY_OPERATION_HOOKS[ArrayOperation.MATMUL]
    assert _array_function_hook("numpy.lib._function_base_impl.append") is ARRAY_OPERATION_HOOKS[ArrayOperation.APPEND_FLAT]
    assert _array_function_hook("numpy.linalg._linalg.pinv") is ARRAY_OPERATION_HOOKS[ArrayOperation.INVERSE]
    assert _array_function_hook("numpy._core.fromnumeric.transpose") is None  # a transpose keeps its type
    assert numpy_calls.array_operation("torch.bmm") is None  # geolint.typing's arrays are not tensors
