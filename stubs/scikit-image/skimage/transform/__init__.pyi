# skimage/transform/__init__.pyi (0.26.0): the names below are re-exported from these modules
from skimage.transform._geometric import (
    AffineTransform as AffineTransform,
    EssentialMatrixTransform as EssentialMatrixTransform,
    EuclideanTransform as EuclideanTransform,
    SimilarityTransform as SimilarityTransform,
)
from skimage.transform._warps import rotate as rotate, swirl as swirl
from skimage.transform.hough_transform import (
    hough_line as hough_line,
    hough_line_peaks as hough_line_peaks,
    probabilistic_hough_line as probabilistic_hough_line,
)
from skimage.transform.radon_transform import iradon as iradon, iradon_sart as iradon_sart, radon as radon
