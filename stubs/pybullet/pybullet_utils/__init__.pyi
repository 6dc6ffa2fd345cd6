from pybullet_utils import bullet_client as bullet_client
