/* On its own (an editor, `make lint-c`), this file includes what precedes it in ilahrs.c:
 * the $PAHR field reader. ilahrs.c holds it without this include. */
#include "pahr.c"

/* ---- Stream decoder -------------------------------------------------------------------- */

/*
 * Sentences in the stream decoder (ilahrs.h, "Build switches"). Without them it finds exactly the
 * frames the full decoder finds, in the same order: a valid sentence is printable ASCII ending in
 * CR LF, so no frame starts inside one, and a frame's validity never depends on what precedes it.
 */
#ifndef ILAHRS_PAHR_FIELD_COUNT
#undef ILAHRS_STREAM_SENTENCES
#define ILAHRS_STREAM_SENTENCES 0
#elif !defined(ILAHRS_STREAM_SENTENCES)
#define ILAHRS_STREAM_SENTENCES 1
#endif

/* The stream decoder's counters fit its buffer, which holds the longest message. */
typedef char
    ilahrs_check_held[ILAHRS_MAX_MESSAGE_SIZE <= 255 && ILAHRS_FRAME_MAX_SIZE <= ILAHRS_MAX_MESSAGE_SIZE ? 1 : -1];

/*
 * How the decoder works. At each position a candidate message starts if the byte there may start
 * one (a frame's first header byte, or "$"); it is decided as valid (handed out, and decoding goes
 * on after it), invalid (the byte is discarded and decoding goes on at the next one) or undecided:
 * it needs more bytes. A decision never changes when bytes follow, so deciding late gives the same
 * messages as deciding early.
 *
 * scan() decides in place, in the caller's input (a message then points into it) or in `held`. A
 * candidate still undecided at the end of the input waits at the front of `held`, and the bytes
 * that follow reach it one at a time (ilahrs_stream_push()): a byte that cannot decide it (a
 * frame's byte short of its length, a sentence's printable character) is only stored, so each byte
 * is examined a bounded number of times however the input is cut. Once decided, the held bytes are
 * scanned in place; those after a message found there wait in held[start..start + count) for the
 * next call.
 */
#define NEED_MORE (-1)
#define INVALID 0

/* Bytes that may start a message. */
static bool may_start(uint8_t byte)
{
#if ILAHRS_STREAM_SENTENCES
    if (byte == PAHR_START) {
        return true;
    }
#endif
    return byte == ILAHRS_FRAME_HEADER_0;
}

/* The frame at p[0..n) (p[0] is the first header byte): its size if valid, INVALID, or NEED_MORE.
 * Strict, a whole frame STRICT_REFUSES is invalid. (frame_check() never answers 0: `size <= 0`
 * tells the compiler that a valid frame's size is positive, and scan() needs no test of its own.) */
static int frame_candidate(const ilahrs_stream_t *s, const uint8_t *p, size_t n, ilahrs_message_t *msg)
{
    int size = frame_check(p, n, &msg->frame);
    /* (WP in Frama-C 25 does not carry a called function's result being written; frame_check()'s
     * proof reads no value before it is written, its result included.) */
    //@ admit \initialized(&size);
    if (size <= 0 || (s->strict && STRICT_REFUSES(p))) {
        return size == -ILAHRS_ERR_TRUNCATED ? NEED_MORE : INVALID;
    }
    msg->kind = ILAHRS_MESSAGE_FRAME;
    msg->data = p;
    msg->size = (size_t)size;
    return size;
}

#if ILAHRS_STREAM_SENTENCES
/* The characters a sentence holds before its CR LF. */
static bool printable(uint8_t byte)
{
    return (unsigned)(byte - 0x20u) <= 0x7Eu - 0x20u;
}

/*
 * The sentence at p[0..n) (p[0] is "$"), of which p[0..seen) were examined before: as
 * frame_candidate(). It runs to its first LF, within the longest sentence, where pahr_body()
 * decides it as ilahrs_pahr_parse() would; before that, a byte that no sentence holds decides it.
 */
static int sentence_candidate(const uint8_t *p, size_t n, size_t seen, ilahrs_message_t *msg)
{
    size_t limit = n < ILAHRS_PAHR_MAX_LENGTH ? n : ILAHRS_PAHR_MAX_LENGTH;
    size_t i;
#if FAST
    /* The prefix, as far as it goes (cut short, nothing follows it below, and it waits). */
    for (i = 1; i < PAHR_PREFIX_LENGTH && i < n; i++) {
        if (p[i] != (uint8_t)PAHR_PREFIX[i]) {
            return INVALID;
        }
    }
    seen = seen > i ? seen : i;
    {
        /* The LF searched for from the prefix's end, bytes examined before too (they hold none):
         * a few steps of memchr(), and where the search starts is then known from n alone, which
         * Frama-C's EVA needs to bound it. */
        const uint8_t *lf = i < limit ? (const uint8_t *)memchr(p + i, PAHR_LF, limit - i) : NULL;
        i = lf != NULL ? (size_t)(lf - p) : limit;
    }
    /* (i is at most limit; ">=" also holds an analysis that loses that bound to the bytes before it.) */
    if (i >= limit) {
        for (i = seen; i < limit; i++) {
            if (!printable(p[i]) && p[i] != PAHR_CR) {
                return INVALID;
            }
        }
        return n < ILAHRS_PAHR_MAX_LENGTH ? NEED_MORE : INVALID;
    }
#else
    /* Compiled for size, one loop, the prefix's bytes included (each examined again until the
     * prefix is whole: ilahrs_stream_push() stores them unexamined): a byte before the LF that no
     * sentence holds decides it now, as pahr_body() would at the LF (only "*", the checksum digits
     * and CR stand outside the fields, and a field holds no such byte). */
    for (i = seen < PAHR_PREFIX_LENGTH ? 1 : seen; i < limit; i++) {
        if (i < PAHR_PREFIX_LENGTH) {
            if (p[i] != (uint8_t)PAHR_PREFIX[i]) {
                return INVALID;
            }
        } else if (!printable(p[i])) {
            if (p[i] == PAHR_LF) {
                break;
            }
            if (p[i] != PAHR_CR) {
                return INVALID;
            }
        }
    }
    if (i >= limit) { /* as above */
        return n < ILAHRS_PAHR_MAX_LENGTH ? NEED_MORE : INVALID;
    }
#endif
    /* The first LF ends the candidate, so the only CR LF it can hold is its last two characters:
     * what ilahrs_pahr_parse() checks before pahr_body(), which checks the CR again. */
    if (pahr_body(p, i + 1, &msg->sentence) != ILAHRS_OK) {
        return INVALID;
    }
    msg->kind = ILAHRS_MESSAGE_SENTENCE;
    msg->data = p;
    msg->size = i + 1;
    return (int)(i + 1);
}
#endif

/* The message at p[0..n), of which p[0..seen) were examined before: as frame_candidate(). */
static int candidate(const ilahrs_stream_t *s, const uint8_t *p, size_t n, size_t seen, ilahrs_message_t *msg)
{
    if (p[0] == ILAHRS_FRAME_HEADER_0) {
        return frame_candidate(s, p, n, msg);
    }
#if ILAHRS_STREAM_SENTENCES
    if (p[0] == PAHR_START) {
        return sentence_candidate(p, n, seen, msg);
    }
#else
    (void)seen;
#endif
    return INVALID;
}

/*
 * Decide on *data / *len in place (the caller's input, or the held bytes, held[start..start +
 * count)); the first candidate's first `seen` bytes were examined before. True with a message,
 * *data / *len then past it (for held bytes: start and count). False when every byte is decided, or
 * an undecided candidate waits at the front of `held` (held[0..count), shorter than the buffer;
 * ilahrs_stream_finish() decides on it).
 */
static bool scan(ilahrs_stream_t *s, const uint8_t **data, size_t *len, size_t seen, ilahrs_message_t *msg)
{
    const uint8_t *p = *data;
    size_t n = *len;
    /*@ loop invariant \base_addr(p) == \base_addr(*data) && *data <= p && p + n == *data + *len;
        loop invariant seen <= n && (seen == 0 || (p == *data && ilahrs_waiting(p, seen)));
        loop invariant ilahrs_written(p, n) && \initialized(&s->discarded);
        loop assigns p, n, seen, s->discarded, *msg; */
    for (; n != 0; p++, n--, seen = 0) {
        int r = may_start(*p) ? candidate(s, p, n, seen, msg) : INVALID;
        if (r > 0) {
            *data = p + r;
            *len = n - (size_t)r;
            return true;
        }
        if (r == NEED_MORE) {
            break;
        }
        s->discarded++;
    }
    /* (The cast states the comparison's type: left to the compiler, Frama-C casts both sides to a
     * type WP's memory model cannot relate to `held`.) */
    if (n != 0 && p != (const uint8_t *)s->held) {
        copy_forward(s->held, p, n);
    }
    s->count = (uint8_t)n;
    *data = p + n;
    *len = 0;
    return false;
}

/* scan() on the held bytes: a message is handed out from there (the bytes after it wait in
 * held[start..start + count) for the next call), else the held bytes are all decided or wait at the
 * front. */
static bool scan_held(ilahrs_stream_t *s, ilahrs_message_t *msg, size_t seen)
{
    const uint8_t *p = s->held + s->start;
    size_t n = s->count;
    s->start = 0;
    if (!scan(s, &p, &n, seen, msg)) {
        return false;
    }
    s->start = (uint8_t)(p - s->held); /* after the message: not 0 */
    s->count = (uint8_t)n;
    return true;
}

void ilahrs_stream_init(ilahrs_stream_t *stream)
{
    stream->discarded = 0;
    stream->start = 0;
    stream->count = 0;
    stream->strict = false;
}

/* A byte that may decide something: appended to the held bytes (the message handed out last
 * leaves), which are then decided. Frames only, every byte takes this way, in less code. */
#if ILAHRS_STREAM_SENTENCES
static NOINLINE bool push_decide(ilahrs_stream_t *s, uint8_t byte, ilahrs_message_t *msg)
#else
bool ilahrs_stream_push(ilahrs_stream_t *s, uint8_t byte, ilahrs_message_t *msg)
#endif
{
    size_t seen = s->count;
    if (s->start != 0) {
        copy_forward(s->held, s->held + s->start, seen); /* never examined */
        s->start = 0;
        seen = 0;
    }
    //@ assert ilahrs_written(&s->held[0], s->count);
    s->held[s->count++] = byte; /* room: the held bytes wait for a longer message, or followed one */
    //@ assert ilahrs_written(&s->held[0], s->count);
    return scan_held(s, msg, seen);
}

#if ILAHRS_STREAM_SENTENCES
bool ilahrs_stream_push(ilahrs_stream_t *s, uint8_t byte, ilahrs_message_t *msg)
{
    /* Most bytes only extend the candidate waiting in held[0..count): a frame's short of its
     * header, or of its length; a sentence's short of its prefix, or printable (not the LF). */
    const uint8_t *h = s->held;
    size_t n = s->count;
    size_t until = 0; /* bytes the candidate needs at least before it can be decided */
    if (s->start != 0 || n == 0) {
        return push_decide(s, byte, msg);
    }
    if (h[0] == ILAHRS_FRAME_HEADER_0) {
        /* The length as a length_t changes no value, and keeps GCC from folding the header size
         * into the sum of its bytes: one load. */
        until = n < ILAHRS_FRAME_PAYLOAD_OFFSET
                    ? ILAHRS_FRAME_PAYLOAD_OFFSET
                    : ILAHRS_FRAME_HEADER_SIZE
                          + (length_t)LE(h + ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, ILAHRS_FRAME_MESSAGE_LENGTH_SIZE);
    } else if (h[0] == PAHR_START) {
        until = n < PAHR_PREFIX_LENGTH ? PAHR_PREFIX_LENGTH : printable(byte) ? ILAHRS_PAHR_MAX_LENGTH : 0;
    }
    /*@ assert h[0] == ILAHRS_FRAME_HEADER_0 && n >= ILAHRS_FRAME_PAYLOAD_OFFSET
               ==> until == ilahrs_frame_size(&s->held[0]); */
    if (n + 1 >= until) {
        return push_decide(s, byte, msg);
    }
    s->held[n] = byte;
    //@ assert ilahrs_written(&s->held[0], n + 1);
    s->count = (uint8_t)(n + 1);
    return false;
}
#endif

bool ilahrs_stream_next(ilahrs_stream_t *s, const uint8_t **data, size_t *len, ilahrs_message_t *msg)
{
    /* Held bytes after a message handed out go first. Then, and after every byte pushed without a
     * message, the held bytes are a candidate waiting for input (start is 0). */
    bool found = (!ILAHRS_STREAM_SENTENCES || s->start != 0) && scan_held(s, msg, 0);
    const uint8_t *p = *data;
    size_t n = *len;
    /*@ loop invariant ilahrs_held_ok(s) && (!found ==> s->start == 0);
        loop invariant ilahrs_held_written(s);
        loop invariant \base_addr(p) == \base_addr(\at(*data, Pre)) && \at(*data, Pre) <= p;
        loop invariant p + n == \at(*data + *len, Pre);
        loop invariant n <= \at(*len, Pre);
        loop invariant ilahrs_input_written(\at(*data, Pre), \at(*data + *len, Pre));
        loop assigns found, p, n, *s, *msg; */
    while (!found && n != 0) {
        uint8_t byte;
        if (s->count == 0) {
            /* In place in the input; a candidate that waits at its end moves to `held`. */
            *data = p;
            *len = n;
            return scan(s, data, len, 0, msg);
        }
        /* A candidate waits in `held`: the input reaches it a byte at a time. */
        byte = *p;
        p++;
        n--;
        found = ilahrs_stream_push(s, byte, msg);
    }
    *data = p;
    *len = n;
    return found;
}

bool ilahrs_stream_poll(ilahrs_stream_t *s, ilahrs_message_t *msg)
{
    /* Without a message handed out, the held bytes are a candidate waiting for input (frames only,
     * in less code: scanned again, it waits again). */
    if (ILAHRS_STREAM_SENTENCES && s->start == 0) {
        return false;
    }
    return scan_held(s, msg, 0); /* a tail call */
}

bool ilahrs_stream_finish(ilahrs_stream_t *s, ilahrs_message_t *msg)
{
    /*@ loop invariant ilahrs_held_ok(s) && ilahrs_held_written(s);
        loop assigns *s, *msg; */
    while (!scan_held(s, msg, 0)) {
        if (s->count == 0) {
            return false;
        }
        /* The candidate waiting at the front is undecided, and no byte follows: invalid. In place of
         * its first byte, one that starts no message (neither the header's first byte nor "$"), which
         * scan() discards before it decides on the bytes that follow. */
        s->held[0] = ILAHRS_FRAME_HEADER_0 == 0u ? 1u : 0u;
    }
    return true;
}

#ifdef ILAHRS_IDLE_TIMEOUT_US
/* An idle line ends the input as far as the held bytes go (finish()); the next byte starts afresh. */
bool ilahrs_stream_idle(ilahrs_stream_t *s, uint32_t quiet_us, ilahrs_message_t *msg)
{
    if (quiet_us < ILAHRS_IDLE_TIMEOUT_US) {
        return false;
    }
    return ilahrs_stream_finish(s, msg);
}
#endif
