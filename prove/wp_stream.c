/* WP: the stream decoder (size path) never reads or writes out of its held buffer or the caller's
 * input, for any input cut anywhere, strict or lenient, keeps the invariant of its state (held_ok
 * in ilahrs.h), and reads no byte of its state, of the held bytes or of the input before it was
 * written (held_written, written; every read checked by -rte-initialized), with every runtime error
 * ruled out (-wp-rte). The contracts are on prototypes of ilahrs.c's static functions, which this
 * file then includes; the loop invariants are in the runtime sources. frame_check() is proved
 * against its contract by prove/wp_frame.c; sentence_candidate() by EVA (prove/stream_sentence.c,
 * prove/pahr_body.c for the pahr_body() it calls). Run by `make prove` (prove/drivers). */
#include <stdint.h>
#include "ilahrs.h"
#include "contracts.h"

/*@ requires \valid(dst + (0 .. n - 1)) && \valid_read(src + (0 .. n - 1));
    requires ilahrs_written(src, n);
    requires \separated(dst + (0 .. n - 1), src + (0 .. n - 1))
          || (\base_addr(dst) == \base_addr(src) && dst <= src);
    assigns dst[0 .. n - 1];
    ensures \forall integer k; 0 <= k < n ==> dst[k] == \old(src[k]);
    ensures ilahrs_written(dst, n); */
static void copy_forward(uint8_t *dst, const uint8_t *src, size_t n);

/*@ assigns \nothing; */
static bool may_start(uint8_t byte);

/*@ assigns \nothing; */
static bool printable(uint8_t byte);

/*@ requires 0 < n && p[0] == ILAHRS_FRAME_HEADER_0;
    requires \valid_read(p + (0 .. n - 1)) && \valid_read(s) && \valid(msg);
    requires ilahrs_written(p, n) && \initialized(&s->strict);
    requires \separated(msg, s) && \separated(msg, p + (0 .. n - 1));
    assigns *msg;
    ensures -1 <= \result <= n;
    ensures \result == -1 ==> ilahrs_waiting(p, n); */
static int frame_candidate(const ilahrs_stream_t *s, const uint8_t *p, size_t n, ilahrs_message_t *msg);

/*@ requires 0 < n && p[0] == '$' && seen <= n && (seen == 0 || ilahrs_waiting(p, seen));
    requires \valid_read(p + (0 .. n - 1)) && \valid(msg) && ilahrs_written(p, n);
    requires \separated(msg, p + (0 .. n - 1));
    assigns *msg;
    ensures -1 <= \result <= n;
    ensures \result == -1 ==> ilahrs_waiting(p, n); */
static int sentence_candidate(const uint8_t *p, size_t n, size_t seen, ilahrs_message_t *msg);

/*@ requires 0 < n && seen <= n && (seen == 0 || ilahrs_waiting(p, seen));
    requires \valid_read(p + (0 .. n - 1)) && ilahrs_written(p, n);
    requires \valid_read(s) && \valid(msg) && \initialized(&s->strict);
    requires \separated(msg, s) && \separated(msg, p + (0 .. n - 1));
    assigns *msg;
    ensures -1 <= \result <= n;
    ensures \result == -1 ==> ilahrs_waiting(p, n); */
static int candidate(const ilahrs_stream_t *s, const uint8_t *p, size_t n, size_t seen, ilahrs_message_t *msg);

/*@ requires \valid(s) && \valid(data) && \valid(len) && \valid(msg);
    requires \valid_read(*data + (0 .. *len - 1)) && ilahrs_written(*data, *len);
    requires \initialized(data) && \initialized(len) && ilahrs_state_written(s);
    requires \separated(msg, s, data, len);
    requires \separated(msg, data, len, *data + (0 .. *len - 1));
    requires in_held(s, *data, *len) || \separated(s, *data + (0 .. *len - 1));
    requires s->start == 0 && seen <= *len && (seen == 0 || ilahrs_waiting(*data, seen));
    assigns *data, *len, *msg, s->discarded, s->count, s->held[0 .. ILAHRS_MAX_MESSAGE_SIZE - 1];
    ensures scan_end: *data + *len == \old(*data + *len);
    ensures scan_len: *len <= \old(*len);
    ensures \result ==> s->count == \old(s->count) && *len < \old(*len);
    ensures !\result ==> *len == 0 && s->count < ILAHRS_MAX_MESSAGE_SIZE && (s->count != 0 ==> ilahrs_waiting(&s->held[0], s->count));
    ensures ilahrs_state_written(s) && \initialized(data) && \initialized(len);
    ensures \result ==> ilahrs_written(*data, *len);
    ensures !\result ==> ilahrs_written(&s->held[0], s->count); */
static bool scan(ilahrs_stream_t *s, const uint8_t **data, size_t *len, size_t seen, ilahrs_message_t *msg);

/*@ requires \valid(s) && \valid(msg) && \separated(s, msg);
    requires s->start + s->count <= ILAHRS_MAX_MESSAGE_SIZE;
    requires ilahrs_held_written(s);
    requires seen == 0 || (s->start == 0 && seen <= s->count && ilahrs_waiting(&s->held[0], seen));
    assigns *msg, s->discarded, s->start, s->count, s->held[0 .. ILAHRS_MAX_MESSAGE_SIZE - 1];
    ensures ilahrs_held_ok(s) && (!\result ==> s->start == 0);
    ensures ilahrs_held_written(s); */
static bool scan_held(ilahrs_stream_t *s, ilahrs_message_t *msg, size_t seen);

/*@ requires \valid(s) && \valid(msg) && \separated(s, msg) && ilahrs_held_ok(s);
    requires ilahrs_held_written(s);
    assigns *msg, s->discarded, s->start, s->count, s->held[0 .. ILAHRS_MAX_MESSAGE_SIZE - 1];
    ensures ilahrs_held_ok(s) && (!\result ==> s->start == 0);
    ensures ilahrs_held_written(s); */
static bool push_decide(ilahrs_stream_t *s, uint8_t byte, ilahrs_message_t *msg);

/*@ requires \valid(stream);
    assigns *stream;
    ensures ilahrs_held_ok(stream) && stream->start == 0;
    ensures ilahrs_held_written(stream); */
void ilahrs_stream_init(ilahrs_stream_t *stream);

/*@ requires \valid(s) && \valid(msg) && \separated(s, msg) && ilahrs_held_ok(s);
    requires ilahrs_held_written(s);
    assigns *s, *msg;
    ensures ilahrs_held_ok(s) && (!\result ==> s->start == 0);
    ensures ilahrs_held_written(s); */
bool ilahrs_stream_push(ilahrs_stream_t *s, uint8_t byte, ilahrs_message_t *msg);

/*@ requires \valid(s) && \valid(data) && \valid(len) && \valid(msg) && ilahrs_held_ok(s);
    requires ilahrs_held_written(s);
    requires \valid_read(*data + (0 .. *len - 1)) && ilahrs_written(*data, *len);
    requires \initialized(data) && \initialized(len);
    requires \separated(s, msg, data, len);
    requires \separated(msg, data, len, *data + (0 .. *len - 1));
    requires \separated(s, *data + (0 .. *len - 1));
    assigns *s, *msg, *data, *len;
    ensures ilahrs_held_ok(s);
    ensures ilahrs_held_written(s);
    ensures *data + *len == \old(*data + *len);
    ensures *len <= \old(*len);
    ensures \initialized(data) && \initialized(len); */
bool ilahrs_stream_next(ilahrs_stream_t *s, const uint8_t **data, size_t *len, ilahrs_message_t *msg);

/*@ requires \valid(s) && \valid(msg) && \separated(s, msg) && ilahrs_held_ok(s);
    requires ilahrs_held_written(s);
    assigns *s, *msg;
    ensures ilahrs_held_ok(s);
    ensures ilahrs_held_written(s); */
bool ilahrs_stream_poll(ilahrs_stream_t *s, ilahrs_message_t *msg);

/*@ requires \valid(s) && \valid(msg) && \separated(s, msg) && ilahrs_held_ok(s);
    requires ilahrs_held_written(s);
    assigns *s, *msg;
    ensures ilahrs_held_ok(s);
    ensures ilahrs_held_written(s); */
bool ilahrs_stream_finish(ilahrs_stream_t *s, ilahrs_message_t *msg);

/*@ requires \valid(s) && \valid(msg) && \separated(s, msg) && ilahrs_held_ok(s);
    requires ilahrs_held_written(s);
    assigns *s, *msg;
    ensures ilahrs_held_ok(s);
    ensures ilahrs_held_written(s); */
bool ilahrs_stream_idle(ilahrs_stream_t *s, uint32_t quiet_us, ilahrs_message_t *msg);

#include "ilahrs.c"
