/* ilahrs_payload_parse(): every payload table (and an unknown one), every input of every length,
 * the struct written at the end of an array of exactly its size. */
#include "input.h"

#define MAX (ILAHRS_FRAME_MAX_PAYLOAD + 2)

static uint8_t prove_struct[256];

int main(void)
{
    ilahrs_error_t err;
    int payload = Frama_C_interval(ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_COUNT);
    size_t size;
    size_t len;
    //@ split payload;
    size = ilahrs_payload_struct_size((ilahrs_payload_t)payload);
    len = prove_length(MAX);
    //@ split len;
    (void)ilahrs_payload_parse((ilahrs_payload_t)payload, PROVE_DATA(len), len, prove_struct + sizeof prove_struct - size,
                               &err);
    {
        const uint8_t *data = prove_long(MAX, &len);
        (void)ilahrs_payload_parse((ilahrs_payload_t)payload, data, len, prove_struct + sizeof prove_struct - size, &err);
    }
    return 0;
}
