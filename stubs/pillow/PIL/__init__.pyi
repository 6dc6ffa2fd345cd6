# PIL/__init__.py (13.0.0) imports no submodule: `from PIL import Image, ImageDraw` imports them
from PIL import Image as Image, ImageDraw as ImageDraw
