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
