"""Shared pytest setup. Each test folder (runtime/, rules/, cli/, typing/, integrations/) owns its own conftest."""

# Appended to a sample module whose frame findings rest on names alone (`T_world_base @ p_cam`): a
# declaration bound to a `T_a_b` name states the module's naming order (dst-first), and only where the
# order is stated are names frame evidence on their own. Appended, so no line above it moves.
DECLARES_DST_FIRST = '\n\nT_world_base = RigidTransform(R, t, from_frame="base", to_frame="world")\n'
