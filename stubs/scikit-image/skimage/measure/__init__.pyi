# skimage/measure/__init__.pyi (0.26.0): `from ._regionprops import regionprops, ...`; RegionProperties is the class of
# what regionprops returns (a list of them)
from skimage.measure._regionprops import RegionProperties as RegionProperties
