/* ilahrs_command_decode() and ilahrs_ack_build(): every input of every length. */
#include "input.h"

#define MAX (ILAHRS_FRAME_MAX_SIZE + 2)

static void decode(const uint8_t *data, size_t len)
{
    ilahrs_command_match_t match;
    ilahrs_error_t err;
    uint8_t ack[ILAHRS_FRAME_MAX_SIZE];
    (void)ilahrs_command_decode(data, len, &match, &err);
    (void)ilahrs_ack_build(data, len, ack, sizeof ack, &err);
}

int main(void)
{
    size_t len = prove_length(MAX);
    //@ split len;
    decode(PROVE_DATA(len), len);
    {
        const uint8_t *data = prove_long(MAX, &len);
        decode(data, len);
    }
    return 0;
}
