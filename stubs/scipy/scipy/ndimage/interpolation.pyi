from scipy.ndimage import rotate as rotate
