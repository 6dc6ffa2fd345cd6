from argoverse.utils import se3 as se3, transform as transform
