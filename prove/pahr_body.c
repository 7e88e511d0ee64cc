/* pahr_body(), the $PAHR check both ilahrs_pahr_parse() and the stream decoder call once they have
 * found the sentence's end: a sentence of any length `end` its contract allows (prove/contracts.h),
 * its bytes unknown (the prefix and the CR LF included, which the callers check before and it
 * checks again or does not read). Its callers' lines take it by that contract (-eva-use-spec
 * pahr_body), which EVA checks at each of their calls. This driver includes ilahrs.c (the function
 * is static). */
#include "input.h"
#include "contracts.h"
#include "ilahrs.c"

int main(void)
{
    ilahrs_pahr_t out;
    size_t end = prove_length(ILAHRS_PAHR_MAX_LENGTH);
    if (end < PAHR_PREFIX_LENGTH + 1u) {
        return 0;
    }
    //@ split end;
    return (int)pahr_body(PROVE_DATA(end), end, &out);
}
