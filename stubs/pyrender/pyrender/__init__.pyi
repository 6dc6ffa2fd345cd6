# pyrender/__init__.py (0.1.45): `from .camera import (Camera, PerspectiveCamera, OrthographicCamera, IntrinsicsCamera)`,
# `from .node import Node`, `from .scene import Scene`
from pyrender.camera import (
    IntrinsicsCamera as IntrinsicsCamera,
    OrthographicCamera as OrthographicCamera,
    PerspectiveCamera as PerspectiveCamera,
)
from pyrender.node import Node as Node
from pyrender.scene import Scene as Scene
