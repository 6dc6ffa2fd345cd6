# bpy (5.3.0): `bpy.context` is the bpy.types.Context of the running session and `bpy.data` the bpy.types.BlendData of the
# open file (`type(bpy.context)` is `_bpy_types.Context`, `type(bpy.data)` is `bpy.types.BlendData`)
from bpy import types as types
from bpy.types import BlendData, Context

context: Context
"""Source: Blender 5.3.0 (bpy on PyPI): `type(bpy.context)` is `_bpy_types.Context`, the bpy.types.Context of the session."""
data: BlendData
"""Source: Blender 5.3.0 (bpy on PyPI): `type(bpy.data)` is `bpy.types.BlendData`, the data of the open file."""
