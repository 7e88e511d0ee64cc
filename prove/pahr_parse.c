/* ilahrs_pahr_parse(): every input of every length. pahr_body(), which it calls once it has found
 * the sentence's end, is taken by its contract (prove/contracts.h; -eva-use-spec pahr_body in
 * prove/drivers), which EVA checks the call meets: prove/pahr_body.c shows that the body has no
 * runtime error for any call that does. This driver includes ilahrs.c (for the contract to name
 * the static function). */
#include "input.h"
#include "contracts.h"
#include "ilahrs.c"

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
