/* ilahrs_payload_build() and ilahrs_payload_build_frame(): every payload table (and an unknown one),
 * every value of every field (the struct's bytes unknown), every capacity of the caller's buffer
 * (as in frame_build.c: capacities below the frame's size each a state, those from there up one). */
#include "input.h"

static uint8_t prove_struct[256];

int main(void)
{
    ilahrs_error_t err;
    int payload = Frama_C_interval(ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_COUNT);
    size_t need;
    size_t cap;
    uint8_t *out;
    const void *in;
    //@ split payload;
    Frama_C_make_unknown((char *)prove_struct, sizeof prove_struct);
    in = prove_struct + sizeof prove_struct - ilahrs_payload_struct_size((ilahrs_payload_t)payload);
    need = ilahrs_payload_size((ilahrs_payload_t)payload) + ILAHRS_FRAME_OVERHEAD;
    if (Frama_C_nondet(0, 1)) {
        cap = Frama_C_size_t_interval(0, need - 1u);
        //@ split cap;
        out = PROVE_OUT(cap);
    } else {
        cap = Frama_C_size_t_interval(need, SIZE_MAX);
        out = PROVE_OUT(need);
    }
    (void)ilahrs_payload_build((ilahrs_payload_t)payload, in, out, cap, &err);
    (void)ilahrs_payload_build_frame((ilahrs_payload_t)payload, in, out, cap, &err);
    (void)ilahrs_payload_build_frame((ilahrs_payload_t)payload, in, NULL, cap, NULL);
    return 0;
}
