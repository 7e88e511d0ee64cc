/* ilahrs_pahr_build(): every value of every field, every capacity of the caller's buffer. */
#include "input.h"

#define MAX (ILAHRS_PAHR_MAX_LENGTH + 2)

int main(void)
{
    ilahrs_error_t err;
    ilahrs_pahr_t s;
    size_t cap = prove_length(MAX);
    //@ split cap;
    Frama_C_make_unknown((char *)&s, sizeof s);
    (void)ilahrs_pahr_build(&s, (char *)PROVE_OUT(cap), cap, &err);
    (void)ilahrs_pahr_build(&s, NULL, cap, NULL);
    return 0;
}
