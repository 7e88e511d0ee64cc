/* WP: the frame check the parsers and the stream decoder share never reads past the caller's
 * length nor a byte of it the caller has not written, and a frame it accepts is never longer than
 * the input (so the stream decoder's `*len = n - size` cannot wrap), with every runtime error ruled
 * out (-wp-rte). The contracts are on prototypes of ilahrs.c's static functions, which this file
 * then includes; the loop invariants are in the runtime sources. Run by `make prove-wp`. */
#include <stdint.h>
#include "ilahrs.h"

/*@ requires \valid_read(data + (0 .. len - 1)) && ilahrs_written(data, len);
    assigns \nothing; */
static uint32_t sum_bytes(const uint8_t *data, size_t len);

/*@ requires \valid_read(p + (0 .. ILAHRS_FRAME_PAYLOAD_OFFSET - 1));
    requires ilahrs_written(p, ILAHRS_FRAME_PAYLOAD_OFFSET);
    requires \valid(frame);
    requires \separated(frame, p + (0 .. ILAHRS_FRAME_PAYLOAD_OFFSET - 1));
    assigns frame->message_type, frame->reserved; */
static void frame_get_fields(ilahrs_frame_t *frame, const uint8_t *p);

/* frame_check()'s contract, which the stream decoder's proof (prove/wp_stream.c) uses. */
#include "contracts.h"

#include "ilahrs.c"
