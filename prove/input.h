/* What every driver decodes: `len` unknown bytes ending exactly at the end of an array, so that a
 * read past the caller's length is a read out of the array, an alarm. Lengths 0..max are each a
 * state of their own (`//@ split len;` in the driver, after prove_length(); the pointer is computed
 * after the split), longer inputs up to PROVE_LONG one state together (prove_long()). */
#ifndef PROVE_INPUT_H
#define PROVE_INPUT_H
#include "__fc_builtin.h"
#include "ilahrs.h"

#define PROVE_LONG 4096u

static uint8_t prove_bytes[PROVE_LONG];

/* Any length 0..max, the bytes unknown. */
static size_t prove_length(size_t max)
{
    Frama_C_make_unknown((char *)prove_bytes, PROVE_LONG);
    return Frama_C_size_t_interval(0, max);
}

/* The last `len` bytes of the array. */
#define PROVE_DATA(len) (prove_bytes + PROVE_LONG - (len))

/* Any length from above `max` to PROVE_LONG, in one state: in *len, its bytes returned. EVA keeps
 * no relation between an unsplit length and a pointer, so these bytes start at the start of the
 * array: a read past PROVE_LONG is an alarm, one past `len` within the array is not (the lengths
 * up to `max`, split, are what shows that none happens). */
static const uint8_t *prove_long(size_t max, size_t *len)
{
    Frama_C_make_unknown((char *)prove_bytes, PROVE_LONG);
    *len = Frama_C_size_t_interval(max + 1u, PROVE_LONG);
    return prove_bytes;
}

/* An output buffer of `cap` bytes (any of 0..max, split by the driver) ending at the end of an array. */
static uint8_t prove_out[PROVE_LONG];
#define PROVE_OUT(cap) (prove_out + PROVE_LONG - (cap))
#endif
