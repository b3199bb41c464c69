"""An independent DDS reader of the bridge's ``/gps/fix``: Cyclone DDS, no ROS.

It declares sensor_msgs/NavSatFix in IDL under the name ROS 2 gives it on the wire
(``sensor_msgs::msg::dds_::NavSatFix_`` on DDS topic ``rt/gps/fix``: the ROS 2 design article
"Topic and Service name mapping to DDS"), reads SECONDS of samples from the first one, and
prints them as one JSON line. Run by tests/test_ros2_bridge.py inside a loopback network namespace only::

    python tests/ros2_cyclone_reader.py SECONDS

Cyclone finds Fast DDS's participants on loopback by unicast to the well-known ports of
127.0.0.1 (the ``CYCLONEDDS_URI`` below): with ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST, Fast
DDS announces itself only there. Fast DDS writes XCDR1, which the reader accepts.
"""

import json
import os
import sys
import time
from dataclasses import dataclass, field

from cyclonedds.core import Policy, Qos
from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
from cyclonedds.idl.types import array, float64, int8, int32, uint8, uint16, uint32
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

LOOPBACK = ('<CycloneDDS><Domain Id="any"><General><Interfaces><NetworkInterface name="lo"/></Interfaces>'
            '<AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto'
            '</ParticipantIndex><Peers><Peer address="127.0.0.1"/></Peers></Discovery></Domain></CycloneDDS>')


@dataclass
@final
class Time_(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
    sec: int32 = 0
    nanosec: uint32 = 0


@dataclass
@final
class Header_(IdlStruct, typename="std_msgs::msg::dds_::Header_"):
    stamp: Time_ = field(default_factory=Time_)
    frame_id: str = ""


@dataclass
@final
class NavSatStatus_(IdlStruct, typename="sensor_msgs::msg::dds_::NavSatStatus_"):
    status: int8 = 0
    service: uint16 = 0


@dataclass
@final
class NavSatFix_(IdlStruct, typename="sensor_msgs::msg::dds_::NavSatFix_"):
    header: Header_ = field(default_factory=Header_)
    status: NavSatStatus_ = field(default_factory=NavSatStatus_)
    latitude: float64 = 0.0
    longitude: float64 = 0.0
    altitude: float64 = 0.0
    position_covariance: array[float64, 9] = field(default_factory=lambda: [0.0] * 9)
    position_covariance_type: uint8 = 0


FIRST_WITHIN = 120.0  # s: the longest the reader waits for the first sample


def main() -> int:
    seconds = float(sys.argv[1])
    participant = DomainParticipant(int(os.environ["ROS_DOMAIN_ID"]))
    qos = Qos(Policy.Reliability.Reliable(max_blocking_time=0), Policy.Durability.Volatile,
              Policy.History.KeepLast(1000),
              Policy.DataRepresentation(use_cdrv0_representation=True, use_xcdrv2_representation=True))
    reader = DataReader(participant, Topic(participant, "rt/gps/fix", NavSatFix_), qos=qos)
    # ``seconds`` of samples from the first one, however long the bridge takes to start (a loaded
    # machine: its imports, the kernels' warm-up and its 3 s look for another clock), 120 s at most
    samples, end = [], time.monotonic() + FIRST_WITHIN
    while time.monotonic() < end:
        for s in reader.take(N=100):
            if s.sample_info.valid_data:
                if not samples:
                    end = time.monotonic() + seconds
                samples.append({"stamp": s.header.stamp.sec * 10**9 + s.header.stamp.nanosec,
                                "frame_id": s.header.frame_id, "latitude": s.latitude,
                                "longitude": s.longitude, "altitude": s.altitude,
                                "status": [s.status.status, s.status.service],
                                "covariance_type": s.position_covariance_type})
        time.sleep(0.01)
    print(json.dumps(samples))
    return 0


if __name__ == "__main__":
    os.environ.setdefault("CYCLONEDDS_URI", LOOPBACK)
    sys.exit(main())
