from geolint.knowledge.markers import any_receiver
from geolint.typing import QuaternionWXYZ, Radians

@any_receiver(when_imported=("pymavlink",))
class MAVLink:
    """Source: pymavlink 2.4.50 (the PyPI wheel), pymavlink/dialects/v20/common.py, class MAVLink (line 16882),
    generated from mavlink's message_definitions/v1.0/common.xml; the v20 dialects that include common.xml
    (ardupilotmega, all) have the same methods, and the MAVLink 1 builds (dialects/v10) the same without the
    extension fields (repr_offset_q, covariance...), which have defaults here, and without odometry and the gimbal
    messages. Reached as `mavutil.mavlink_connection(...).mav`, so its methods are recognised by name in modules
    that import pymavlink. Each method's docstring states the units
    and orders used below ("Roll angle (-pi..+pi) [rad]", "Attitude quaternion (w, x, y, z order, zero-rotation is
    1, 0, 0, 0)", "yaw setpoint [rad]"); the line cited on each method is where it is defined. Checked numerically
    (tests/knowledge/test_stubs_pymavlink.py)."""

    def attitude_send(self, time_boot_ms: object, roll: Radians, pitch: Radians, yaw: Radians, rollspeed: object, pitchspeed: object, yawspeed: object, force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 17816: roll [rad], pitch [rad], yaw [rad]."""

    def attitude_encode(self, time_boot_ms: object, roll: Radians, pitch: Radians, yaw: Radians, rollspeed: object, pitchspeed: object, yawspeed: object) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 17800: roll [rad], pitch [rad], yaw [rad]."""

    def attitude_quaternion_send(self, time_boot_ms: object, q1: object, q2: object, q3: object, q4: object, rollspeed: object, pitchspeed: object, yawspeed: object, repr_offset_q: QuaternionWXYZ = ..., force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 17851: repr_offset_q w, x, y, z."""

    def attitude_quaternion_encode(self, time_boot_ms: object, q1: object, q2: object, q3: object, q4: object, rollspeed: object, pitchspeed: object, yawspeed: object, repr_offset_q: QuaternionWXYZ = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 17832: repr_offset_q w, x, y, z."""

    def set_attitude_target_send(self, time_boot_ms: object, target_system: object, target_component: object, type_mask: object, q: QuaternionWXYZ, body_roll_rate: object, body_pitch_rate: object, body_yaw_rate: object, thrust: object, force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19276: q w, x, y, z."""

    def set_attitude_target_encode(self, time_boot_ms: object, target_system: object, target_component: object, type_mask: object, q: QuaternionWXYZ, body_roll_rate: object, body_pitch_rate: object, body_yaw_rate: object, thrust: object) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19258: q w, x, y, z."""

    def attitude_target_send(self, time_boot_ms: object, type_mask: object, q: QuaternionWXYZ, body_roll_rate: object, body_pitch_rate: object, body_yaw_rate: object, thrust: object, force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19312: q w, x, y, z."""

    def attitude_target_encode(self, time_boot_ms: object, type_mask: object, q: QuaternionWXYZ, body_roll_rate: object, body_pitch_rate: object, body_yaw_rate: object, thrust: object) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19294: q w, x, y, z."""

    def set_position_target_local_ned_send(self, time_boot_ms: object, target_system: object, target_component: object, coordinate_frame: object, type_mask: object, x: object, y: object, z: object, vx: object, vy: object, vz: object, afx: object, afy: object, afz: object, yaw: Radians, yaw_rate: object, force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19356: yaw [rad]."""

    def set_position_target_local_ned_encode(self, time_boot_ms: object, target_system: object, target_component: object, coordinate_frame: object, type_mask: object, x: object, y: object, z: object, vx: object, vy: object, vz: object, afx: object, afy: object, afz: object, yaw: Radians, yaw_rate: object) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19330: yaw [rad]."""

    def position_target_local_ned_send(self, time_boot_ms: object, coordinate_frame: object, type_mask: object, x: object, y: object, z: object, vx: object, vy: object, vz: object, afx: object, afy: object, afz: object, yaw: Radians, yaw_rate: object, force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19407: yaw [rad]."""

    def position_target_local_ned_encode(self, time_boot_ms: object, coordinate_frame: object, type_mask: object, x: object, y: object, z: object, vx: object, vy: object, vz: object, afx: object, afy: object, afz: object, yaw: Radians, yaw_rate: object) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19382: yaw [rad]."""

    def set_position_target_global_int_send(self, time_boot_ms: object, target_system: object, target_component: object, coordinate_frame: object, type_mask: object, lat_int: object, lon_int: object, alt: object, vx: object, vy: object, vz: object, afx: object, afy: object, afz: object, yaw: Radians, yaw_rate: object, force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19459: yaw [rad]."""

    def set_position_target_global_int_encode(self, time_boot_ms: object, target_system: object, target_component: object, coordinate_frame: object, type_mask: object, lat_int: object, lon_int: object, alt: object, vx: object, vy: object, vz: object, afx: object, afy: object, afz: object, yaw: Radians, yaw_rate: object) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19432: yaw [rad]."""

    def position_target_global_int_send(self, time_boot_ms: object, coordinate_frame: object, type_mask: object, lat_int: object, lon_int: object, alt: object, vx: object, vy: object, vz: object, afx: object, afy: object, afz: object, yaw: Radians, yaw_rate: object, force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19511: yaw [rad]."""

    def position_target_global_int_encode(self, time_boot_ms: object, coordinate_frame: object, type_mask: object, lat_int: object, lon_int: object, alt: object, vx: object, vy: object, vz: object, afx: object, afy: object, afz: object, yaw: Radians, yaw_rate: object) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19486: yaw [rad]."""

    def vision_position_estimate_send(self, usec: object, x: object, y: object, z: object, roll: Radians, pitch: Radians, yaw: Radians, covariance: object = ..., reset_counter: object = ..., force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19827: roll [rad], pitch [rad], yaw [rad]."""

    def vision_position_estimate_encode(self, usec: object, x: object, y: object, z: object, roll: Radians, pitch: Radians, yaw: Radians, covariance: object = ..., reset_counter: object = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19810: roll [rad], pitch [rad], yaw [rad]."""

    def vicon_position_estimate_send(self, usec: object, x: object, y: object, z: object, roll: Radians, pitch: Radians, yaw: Radians, covariance: object = ..., force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19888: roll [rad], pitch [rad], yaw [rad]."""

    def vicon_position_estimate_encode(self, usec: object, x: object, y: object, z: object, roll: Radians, pitch: Radians, yaw: Radians, covariance: object = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 19872: roll [rad], pitch [rad], yaw [rad]."""

    def odometry_send(self, time_usec: object, frame_id: object, child_frame_id: object, x: object, y: object, z: object, q: QuaternionWXYZ, vx: object, vy: object, vz: object, rollspeed: object, pitchspeed: object, yawspeed: object, pose_covariance: object, velocity_covariance: object, reset_counter: object = ..., estimator_type: object = ..., quality: object = ..., force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 23932: q w, x, y, z."""

    def odometry_encode(self, time_usec: object, frame_id: object, child_frame_id: object, x: object, y: object, z: object, q: QuaternionWXYZ, vx: object, vy: object, vz: object, rollspeed: object, pitchspeed: object, yawspeed: object, pose_covariance: object, velocity_covariance: object, reset_counter: object = ..., estimator_type: object = ..., quality: object = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 23904: q w, x, y, z."""

    def att_pos_mocap_send(self, time_usec: object, q: QuaternionWXYZ, x: object, y: object, z: object, covariance: object = ..., force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 21088: q w, x, y, z."""

    def att_pos_mocap_encode(self, time_usec: object, q: QuaternionWXYZ, x: object, y: object, z: object, covariance: object = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 21074: q w, x, y, z."""

    def hil_state_quaternion_send(self, time_usec: object, attitude_quaternion: QuaternionWXYZ, rollspeed: object, pitchspeed: object, yawspeed: object, lat: object, lon: object, alt: object, vx: object, vy: object, vz: object, ind_airspeed: object, true_airspeed: object, xacc: object, yacc: object, zacc: object, force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 20358: attitude_quaternion w, x, y, z."""

    def hil_state_quaternion_encode(self, time_usec: object, attitude_quaternion: QuaternionWXYZ, rollspeed: object, pitchspeed: object, yawspeed: object, lat: object, lon: object, alt: object, vx: object, vy: object, vz: object, ind_airspeed: object, true_airspeed: object, xacc: object, yacc: object, zacc: object) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 20332: attitude_quaternion w, x, y, z."""

    def gimbal_device_set_attitude_send(self, target_system: object, target_component: object, flags: object, q: QuaternionWXYZ, angular_velocity_x: object, angular_velocity_y: object, angular_velocity_z: object, force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 23233: q w, x, y, z."""

    def gimbal_device_set_attitude_encode(self, target_system: object, target_component: object, flags: object, q: QuaternionWXYZ, angular_velocity_x: object, angular_velocity_y: object, angular_velocity_z: object) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 23198: q w, x, y, z."""

    def gimbal_device_attitude_status_send(self, target_system: object, target_component: object, time_boot_ms: object, flags: object, q: QuaternionWXYZ, angular_velocity_x: object, angular_velocity_y: object, angular_velocity_z: object, failure_flags: object, delta_yaw: Radians = ..., delta_yaw_velocity: object = ..., gimbal_device_id: object = ..., force_mavlink1: bool = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 23314: q w, x, y, z, delta_yaw [rad]."""

    def gimbal_device_attitude_status_encode(self, target_system: object, target_component: object, time_boot_ms: object, flags: object, q: QuaternionWXYZ, angular_velocity_x: object, angular_velocity_y: object, angular_velocity_z: object, failure_flags: object, delta_yaw: Radians = ..., delta_yaw_velocity: object = ..., gimbal_device_id: object = ...) -> object:
        """Source: pymavlink 2.4.50, pymavlink/dialects/v20/common.py line 23268: q w, x, y, z, delta_yaw [rad]."""
