from geolint.typing import Degrees

def glRotatef(angle: Degrees, x: float, y: float, z: float) -> None:
    """Source: OpenGL 2.1 reference page glRotate: "angle: Specifies the angle of rotation, in degrees";
    pyglet/gl/gl_compat.py (commit 6d9527c3) binds the C function: `glRotatef = _link_function('glRotatef',
    None, [GLfloat, GLfloat, GLfloat, GLfloat], None)`."""

def glRotated(angle: Degrees, x: float, y: float, z: float) -> None:
    """Source: OpenGL 2.1 reference page glRotate, as glRotatef (pyglet/gl/gl_compat.py, commit 6d9527c3)."""
