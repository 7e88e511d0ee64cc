/*
 * The MAVLink side of the mix (mix.h), built with the pack functions mavgen generates for the
 * bench dialect (bench/mavlink/dialect.py), MAVLink 2 framing, unsigned: ATTITUDE,
 * ATTITUDE_QUATERNION and RAW_IMU for the three outputs, HEARTBEAT for the small message and
 * COMMAND_ACK for the acknowledgement. Values are random within each field's usual range.
 */
#include "theirs.h"

#include <mavlink.h>

#define SYSTEM_ID 1
#define COMPONENT_ID 1

static float uniform(uint64_t *rng, double low, double high)
{
    return (float)(low + (high - low) * (double)(mix_next(rng) >> 11) * (1.0 / 9007199254740992.0));
}

static int16_t raw16(uint64_t *rng)
{
    return (int16_t)(int)mix_below(rng, 8001) - 4000;
}

size_t theirs_message(mix_kind_t kind, uint64_t *rng, uint8_t *out, size_t cap)
{
    uint32_t time_ms = (uint32_t)mix_below(rng, 86400000);
    mavlink_message_t msg;
    switch (kind) {
    case MIX_OUTPUT_A:
        mavlink_msg_attitude_pack(SYSTEM_ID, COMPONENT_ID, &msg, time_ms, uniform(rng, -3.1416, 3.1416),
                                  uniform(rng, -1.5708, 1.5708), uniform(rng, -3.1416, 3.1416), uniform(rng, -5, 5),
                                  uniform(rng, -5, 5), uniform(rng, -5, 5));
        break;
    case MIX_OUTPUT_B: {
        float q[4] = { 0, 0, 0, 0 }; /* repr_offset_q: not supported, so trimmed from the wire */
        mavlink_msg_attitude_quaternion_pack(SYSTEM_ID, COMPONENT_ID, &msg, time_ms, uniform(rng, -1, 1),
                                             uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1),
                                             uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -5, 5), q);
        break;
    }
    case MIX_OUTPUT_C:
        mavlink_msg_raw_imu_pack(SYSTEM_ID, COMPONENT_ID, &msg, (uint64_t)time_ms * 1000u, raw16(rng), raw16(rng),
                                 raw16(rng), raw16(rng), raw16(rng), raw16(rng), raw16(rng), raw16(rng), raw16(rng),
                                 0, (int16_t)(2000 + mix_below(rng, 3000)));
        break;
    case MIX_SMALL:
        mavlink_msg_heartbeat_pack(SYSTEM_ID, COMPONENT_ID, &msg, MAV_TYPE_QUADROTOR, MAV_AUTOPILOT_GENERIC,
                                   (uint8_t)mix_below(rng, 256), (uint32_t)mix_below(rng, 20), MAV_STATE_ACTIVE);
        break;
    case MIX_ACK:
        mavlink_msg_command_ack_pack(SYSTEM_ID, COMPONENT_ID, &msg, (uint16_t)(16 + mix_below(rng, 500)),
                                     (uint8_t)mix_below(rng, 5), 0, 0, 0, 0);
        break;
    default:
        return 0;
    }
    if (cap < (size_t)MAVLINK_NUM_NON_PAYLOAD_BYTES + msg.len) {
        return 0;
    }
    return mavlink_msg_to_send_buffer(out, &msg);
}

/* The MAVLink 2 start byte, a random payload length, no incompatible or compatible flags, a
 * sequence number and this system's id. */
size_t theirs_false_header(uint64_t *rng, uint8_t *out)
{
    out[0] = MAVLINK_STX;
    out[1] = (uint8_t)mix_below(rng, 256);
    out[2] = 0;
    out[3] = 0;
    out[4] = (uint8_t)mix_below(rng, 256);
    out[5] = SYSTEM_ID;
    return 6;
}
