/*
 * MAVLink's decoder as a C user calls it: mavlink_parse_char() on one channel, which keeps the
 * message being received and the parser status in its static channel buffers and copies a
 * complete message into the caller's mavlink_message_t. See theirs.h.
 */
#include "theirs.h"

#include <mavlink.h>

#include <string.h>

void theirs_init(void)
{
    memset(mavlink_get_channel_status(MAVLINK_COMM_0), 0, sizeof(mavlink_status_t));
    memset(mavlink_get_channel_buffer(MAVLINK_COMM_0), 0, sizeof(mavlink_message_t));
}

static void count(theirs_tally_t *tally, const mavlink_message_t *msg)
{
    tally->messages++;
    tally->bytes += (uint64_t)MAVLINK_NUM_NON_PAYLOAD_BYTES + msg->len +
                    ((msg->incompat_flags & MAVLINK_IFLAG_SIGNED) ? MAVLINK_SIGNATURE_BLOCK_LEN : 0);
}

void theirs_decode(const uint8_t *data, size_t len, theirs_tally_t *tally)
{
    mavlink_message_t msg;
    mavlink_status_t status;
    size_t i;
    for (i = 0; i < len; i++) {
        if (mavlink_parse_char(MAVLINK_COMM_0, data[i], &msg, &status)) {
            count(tally, &msg);
        }
    }
}

bool theirs_push(uint8_t byte, theirs_tally_t *tally)
{
    mavlink_message_t msg;
    mavlink_status_t status;
    if (mavlink_parse_char(MAVLINK_COMM_0, byte, &msg, &status)) {
        count(tally, &msg);
        return true;
    }
    return false;
}
