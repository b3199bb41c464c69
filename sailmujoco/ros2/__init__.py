"""The boat as ROS 2 sees it, computed without ROS.

``geodesy``   WGS84: a point of the world's local ENU plane as latitude, longitude and altitude
              about a stated origin, and back
``contract``  the bridge's topics, their types and what each carries; the remap file
``messages``  the fields of the standard messages (sensor_msgs/Imu, sensor_msgs/NavSatFix,
              geometry_msgs/TwistStamped and Vector3Stamped) from the boat's state and its
              instruments, in REP-103 frames (world ENU, body FLU) and REP-145's IMU convention,
              as plain mappings keyed by the messages' field names

Nothing here imports ROS: rclpy's message classes and rosbags' typestores are filled from the
mappings field by field.
"""
