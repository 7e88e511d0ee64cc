/* The stream decoder's sentence recognition, sentence_candidate() (the part of candidate() that
 * prove/wp_stream.c takes from its contract there): a candidate starting with "$" of any length n
 * and any count `seen` of bytes examined before (0, or up to the longest undecided sentence), its
 * bytes unknown. EVA shows no runtime error in it, and that each call of pahr_body() meets that
 * function's contract (prove/contracts.h; the body is taken from it, -eva-use-spec pahr_body, and
 * prove/pahr_body.c analyses it for every call that does), and the assertions check
 * sentence_candidate()'s own contract: the answer is NEED_MORE, INVALID or a size within n, and
 * NEED_MORE only for a sentence shorter than the longest. This driver includes ilahrs.c (the
 * helper is static). */
#include "input.h"
#include "contracts.h"
#include "ilahrs.c"

#ifndef MAX
#define MAX (ILAHRS_PAHR_MAX_LENGTH + 8)
#endif

int main(void)
{
    ilahrs_message_t msg;
    size_t n = prove_length(MAX);
    size_t seen;
    const uint8_t *p;
    int r;
    if (n == 0) {
        return 0;
    }
    //@ split n;
    seen = Frama_C_nondet(0, 1) ? 0 : Frama_C_size_t_interval(1, n < ILAHRS_PAHR_MAX_LENGTH ? n : ILAHRS_PAHR_MAX_LENGTH - 1);
    p = PROVE_DATA(n);
    prove_bytes[PROVE_LONG - n] = PAHR_START;
    r = sentence_candidate(p, n, seen, &msg);
    //@ check -1 <= r <= (int)n;
    //@ check r == -1 ==> n < ILAHRS_PAHR_MAX_LENGTH;
    return r;
}
