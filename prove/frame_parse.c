/* ilahrs_frame_parse() and ilahrs_frame_parse_strict(): every input of every length. */
#include "input.h"

#define MAX (ILAHRS_FRAME_MAX_SIZE + 2)

static void parse(const uint8_t *data, size_t len)
{
    ilahrs_frame_t frame;
    ilahrs_error_t err;
    (void)ilahrs_frame_parse(data, len, &frame, &err);
    (void)ilahrs_frame_parse_strict(data, len, &frame, &err);
    (void)ilahrs_frame_parse(data, len, &frame, NULL);
}

int main(void)
{
    size_t len = prove_length(MAX);
    //@ split len;
    parse(PROVE_DATA(len), len);
    {
        const uint8_t *data = prove_long(MAX, &len);
        parse(data, len);
    }
    parse(NULL, 0);
    return 0;
}
