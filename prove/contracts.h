/* ACSL shared by the proofs: the frame check's contract (proved by prove/wp_frame.c, used by
 * prove/wp_stream.c for the stream decoder's calls), pahr_body()'s (analysed by prove/pahr_body.c,
 * used by the lines of its callers), and where the stream decoder's bytes lie (its invariant,
 * ilahrs_held_ok(), is in ilahrs.h). */
#ifndef PROVE_CONTRACTS_H
#define PROVE_CONTRACTS_H
#include <stdint.h>
#include "ilahrs.h"

/*@ // p[0 .. n) lies within the decoder's held buffer.
    predicate in_held(ilahrs_stream_t *s, uint8_t *p, integer n) =
        \base_addr(p) == \base_addr(&s->held[0]) && &s->held[0] <= p
        && p + n <= &s->held[0] + ILAHRS_MAX_MESSAGE_SIZE;
*/

/*@ requires \valid_read(p + (0 .. n - 1)) && ilahrs_written(p, n);
    requires \valid(frame);
    requires \separated(frame, p + (0 .. n - 1));
    assigns *frame;
    ensures \result <= n;
    ensures \result > 0 ==> frame->payload == p + ILAHRS_FRAME_PAYLOAD_OFFSET
                         && ILAHRS_FRAME_PAYLOAD_OFFSET + frame->payload_size + ILAHRS_FRAME_CHECKSUM_SIZE == \result;
    ensures \result == -ILAHRS_ERR_TRUNCATED && n >= ILAHRS_FRAME_PAYLOAD_OFFSET
            ==> n < ilahrs_frame_size(p) <= ILAHRS_FRAME_MAX_SIZE; */
static int frame_check(const uint8_t *p, size_t n, ilahrs_frame_t *frame);

/* pahr_body(), as ilahrs_pahr_parse() and the stream decoder call it: a sentence of `end` bytes,
 * the prefix and at least an LF after it, at most the longest. prove/pahr_body.c analyses the body
 * for every such call, and checks its answer: ILAHRS_OK, or an error kind it reports with a place
 * (a field, or PAHR_AT_PREFIX, _STAR, _CHECKSUM: at most the field count + 2). The lines of its
 * callers take the body from this contract (-eva-use-spec pahr_body) and check that each call
 * meets it. */
/*@ requires \valid_read(p + (0 .. end - 1));
    requires 7 <= end <= ILAHRS_PAHR_MAX_LENGTH; // PAHR_PREFIX_LENGTH + 1: the prefix and an LF
    requires \valid(out);
    assigns *out \from p[0 .. end - 1];
    assigns \result \from p[0 .. end - 1];
    ensures \result == ILAHRS_OK
            || ((\result & 0xF) \in {ILAHRS_ERR_MALFORMED, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_ERR_BAD_CHECKSUM}
                && \result >> 4 <= ILAHRS_PAHR_FIELD_COUNT + 2); */
static uint32_t pahr_body(const uint8_t *p, size_t end, ilahrs_pahr_t *out);
#endif
