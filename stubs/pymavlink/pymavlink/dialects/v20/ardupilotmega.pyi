# pymavlink/dialects/v20/ardupilotmega.py (2.4.50): generated from ardupilotmega.xml, which includes common.xml; its
# MAVLink class has the same methods as common's (a class of its own, stated once, in common)
from pymavlink.dialects.v20.common import MAVLink as MAVLink
