"""The boat as a ROS 2 stack sees it: standard messages, an MCAP log, and a node.

============  ==========================================================================
``geodesy``   WGS84: a point of the world's local ENU plane as latitude, longitude and
              altitude about a stated origin, and back
``messages``  the fields of the standard messages (sensor_msgs/Imu, NavSatFix,
              geometry_msgs/TwistStamped, Vector3Stamped) from the boat's state and
              instruments, in REP-103 frames (world ENU, body FLU) and REP-145's IMU
              convention, as plain mappings keyed by the messages' field names
``contract``  the topics, their types and what each carries; a team's remap file
``record``    every run as an MCAP log of those messages (rosbags' writer)
``node``      the boat as a ROS 2 node, lock-step with ``/clock`` (rclpy; ``sailmujoco ros2``)
============  ==========================================================================

Only ``node`` imports ROS, and only when a bridge starts: rclpy's message classes and rosbags'
typestores are filled from the mappings field by field.
"""
