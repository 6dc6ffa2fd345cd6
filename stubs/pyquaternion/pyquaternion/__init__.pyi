from pyquaternion.quaternion import Quaternion as Quaternion
