from eigenpy import Quaternion as Quaternion
from pinocchio import rpy as rpy
