from geolint.typing import Degrees

def glRotatef(angle: Degrees, x: float, y: float, z: float) -> None:
    """Source: OpenGL 2.1 reference page glRotate: "angle: Specifies the angle of rotation, in degrees";
    PyOpenGL 3.1.10 binds the C function (OpenGL/raw/GL/VERSION/GL_1_0.py, glRotatef(angle, x, y, z))."""

def glRotated(angle: Degrees, x: float, y: float, z: float) -> None:
    """Source: OpenGL 2.1 reference page glRotate, as glRotatef (double precision)."""
