/*
 * The AHRS side of the mix (mix.h), built with the library's public builders: the three binary
 * output formats the device streams (Tables 6.4-6.6, 34-byte payloads, random contents: the
 * stream decoder checks the framing, not the values), a command frame from the host, and the
 * acknowledgement the device sends for one.
 */
#include "ours.h"

#include "ilahrs.h"

size_t ours_message(mix_kind_t kind, uint64_t *rng, uint8_t *out, size_t cap)
{
    static const ilahrs_payload_t outputs[3] = { ILAHRS_PAYLOAD_FULL_OUTPUT, ILAHRS_PAYLOAD_QUATERNION,
                                                 ILAHRS_PAYLOAD_ORIENTATION_SENSORS };
    uint8_t payload[ILAHRS_FRAME_MAX_PAYLOAD];
    uint8_t command[ILAHRS_FRAME_MAX_SIZE];
    ilahrs_frame_t frame;
    size_t i;
    size_t c;
    switch (kind) {
    case MIX_OUTPUT_A:
    case MIX_OUTPUT_B:
    case MIX_OUTPUT_C:
        frame.message_type = ILAHRS_MESSAGE_TYPE_DATA;
        frame.reserved = 0;
        frame.payload = payload;
        frame.payload_size = ilahrs_payload_size(outputs[kind - MIX_OUTPUT_A]);
        for (i = 0; i < frame.payload_size; i++) {
            payload[i] = (uint8_t)mix_next(rng);
        }
        return ilahrs_frame_build(&frame, out, cap, NULL);
    case MIX_SMALL:
        return ilahrs_command_build((ilahrs_command_t)mix_below(rng, ILAHRS_COMMAND_COUNT), out, cap, NULL);
    case MIX_ACK:
        c = ilahrs_command_build((ilahrs_command_t)mix_below(rng, ILAHRS_COMMAND_COUNT), command, sizeof command, NULL);
        return ilahrs_ack_build(command, c, out, cap, NULL);
    }
    return 0;
}

/* AA 55, a message type, the reserved byte, a random message length (little-endian). */
size_t ours_false_header(uint64_t *rng, uint8_t *out)
{
    out[0] = ILAHRS_FRAME_HEADER_0;
    out[1] = ILAHRS_FRAME_HEADER_1;
    out[2] = (uint8_t)mix_below(rng, 2);
    out[3] = 0;
    out[4] = (uint8_t)mix_below(rng, 256);
    out[5] = 0;
    return 6;
}
