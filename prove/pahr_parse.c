/* ilahrs_pahr_parse(): every input of every length. */
#include "input.h"

#define MAX (ILAHRS_PAHR_MAX_LENGTH + 2)

int main(void)
{
    ilahrs_pahr_t s;
    ilahrs_error_t err;
    size_t len = prove_length(MAX);
    //@ split len;
    (void)ilahrs_pahr_parse((const char *)PROVE_DATA(len), len, &s, &err);
    {
        const uint8_t *data = prove_long(MAX, &len);
        (void)ilahrs_pahr_parse((const char *)data, len, &s, &err);
    }
    return 0;
}
