// The bench's frame link between the plant and the guidance computer (docs/hil.md, "Link frames").
// The frames and their codec are flight code: they live in fsw_core's hal module
// (tolip/hal/link.hpp), which the Cortex-M7 image links too; this header names them in the bench's
// namespace.
#pragma once

#include "tolip/hal/link.hpp"

namespace tolip::sim {

using hal::ActuatorFrame;
using hal::decode_actuator_frame;
using hal::decode_sensor_frame;
using hal::encode_actuator_frame;
using hal::encode_sensor_frame;
using hal::kActuatorFrameSize;
using hal::kActuatorFrameType;
using hal::kFrameSync;
using hal::kSensorFrameSize;
using hal::kSensorFrameType;
using hal::SensorFrame;

}  // namespace tolip::sim
