/* ilahrs_frame_build() and ilahrs_command_build(): every message type, reserved byte, payload size
 * and command, every capacity of the caller's buffer, which ends at the end of an array (a write
 * past it is an alarm). Capacities below the frame's size share a state with a buffer of no byte
 * (these builders write nothing before they have checked the capacity); those from the frame's size
 * up share one, with a buffer of exactly the frame's size. */
#include "input.h"

int main(void)
{
    ilahrs_error_t err;
    ilahrs_frame_t frame;
    size_t need;
    size_t cap;
    uint8_t *out;
    int command = Frama_C_interval(-1, ILAHRS_COMMAND_COUNT);
    Frama_C_make_unknown((char *)prove_bytes, PROVE_LONG);
    frame.message_type = Frama_C_unsigned_char_interval(0, 255);
    frame.reserved = Frama_C_unsigned_char_interval(0, 255);
    frame.payload = Frama_C_nondet(0, 1) ? prove_bytes : NULL;
    /* A payload too long: refused, whatever the buffer. */
    frame.payload_size = Frama_C_size_t_interval(ILAHRS_FRAME_MAX_PAYLOAD + 1u, SIZE_MAX);
    (void)ilahrs_frame_build(&frame, PROVE_OUT(0), Frama_C_size_t_interval(0, SIZE_MAX), &err);
    frame.payload_size = Frama_C_size_t_interval(0, ILAHRS_FRAME_MAX_PAYLOAD);
    //@ split frame.payload_size;
    need = frame.payload_size + ILAHRS_FRAME_OVERHEAD;
    /* Each capacity range calls the builder on its own buffer: joined, EVA would lose which buffer
     * goes with which capacity, and which copy direction move_bytes() takes. */
    if (Frama_C_nondet(0, 1)) {
        cap = Frama_C_size_t_interval(0, need - 1u);
        (void)ilahrs_frame_build(&frame, PROVE_OUT(0), cap, &err);
        (void)ilahrs_frame_build(&frame, NULL, cap, NULL);
    } else {
        cap = Frama_C_size_t_interval(need, SIZE_MAX);
        out = PROVE_OUT(need);
        (void)ilahrs_frame_build(&frame, out, cap, &err);
        (void)ilahrs_frame_build(&frame, NULL, cap, NULL);
        /* The payload already in place, inside the output buffer. */
        frame.payload = out + ILAHRS_FRAME_PAYLOAD_OFFSET;
        (void)ilahrs_frame_build(&frame, out, cap, NULL);
    }
    if (Frama_C_nondet(0, 1)) {
        (void)ilahrs_command_build((ilahrs_command_t)command, PROVE_OUT(0),
                                   Frama_C_size_t_interval(0, ILAHRS_FRAME_MIN_SIZE - 1u), &err);
    } else {
        (void)ilahrs_command_build((ilahrs_command_t)command, PROVE_OUT(ILAHRS_FRAME_MIN_SIZE),
                                   Frama_C_size_t_interval(ILAHRS_FRAME_MIN_SIZE, SIZE_MAX), &err);
    }
    return 0;
}
