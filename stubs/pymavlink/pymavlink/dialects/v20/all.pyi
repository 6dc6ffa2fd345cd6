# pymavlink/dialects/v20/all.py (2.4.50): generated from all.xml, which includes common.xml
from pymavlink.dialects.v20.common import MAVLink as MAVLink
