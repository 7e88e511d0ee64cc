
/* ======================================================================================== */
/* Stream decoder                                                                           */
/* ======================================================================================== */

/** What a stream message is. */
typedef enum ilahrs_message_kind {
    ILAHRS_MESSAGE_FRAME = 1,    /**< A frame: `frame` is valid. */
    ILAHRS_MESSAGE_SENTENCE = 2, /**< A $PAHR sentence: `sentence` is valid. */
} ilahrs_message_kind_t;

/** A message the stream decoder accepted. */
typedef struct ilahrs_message {
    ilahrs_message_kind_t kind; /**< Frame or sentence. */
    /**
     * The message bytes as received (a frame from its header through its checksum, a
     * sentence from "$" through CR LF). They lie in the input or in the decoder state and stay
     * valid until the next call on the decoder or until the input buffer changes.
     */
    const uint8_t *data;
    size_t size;            /**< Number of bytes at `data`. */
    ilahrs_frame_t frame;   /**< The decoded frame (kind ILAHRS_MESSAGE_FRAME). */
    ilahrs_pahr_t sentence; /**< The decoded sentence (kind ILAHRS_MESSAGE_SENTENCE). */
} ilahrs_message_t;

/**
 * Stream decoder state: the bytes of a message that has not ended yet, at most
 * ILAHRS_MAX_MESSAGE_SIZE. Owned by the caller; all zeros is the empty state (`= {0}` or
 * ilahrs_stream_init()). One decoder per byte stream; no other state exists.
 *
 * Semantics (spec/README.md, "leftmost valid message"): at each position a valid frame or
 * valid sentence is accepted and consumed; anything else costs exactly one byte, counted in
 * `discarded`, and decoding resumes at the next byte. So a false AA 55, an absurd length or a
 * corrupted frame never costs a following good message, whatever the chunk boundaries. Each
 * byte is examined a bounded number of times, however the input is cut (see "Build switches"
 * for a decoder without sentences).
 *
 * Strict decoding (E42): set `strict` (after ilahrs_stream_init(), before the first byte) and a
 * frame that ilahrs_frame_parse_strict() refuses is no message (one byte discarded, as for any
 * other invalid frame). `= {0}` is the lenient decoder.
 */
typedef struct ilahrs_stream {
    uint64_t discarded;                    /**< Input bytes that belong to no accepted message. */
    bool strict;                           /**< Strict decoding (E42); false (zero) by default. */
    uint8_t start;                         /**< First held byte. */
    uint8_t count;                         /**< Number of held bytes. */
    uint8_t held[ILAHRS_MAX_MESSAGE_SIZE]; /**< Bytes kept while a message is incomplete. */
} ilahrs_stream_t;

/*@ // The decoder's invariant, in ACSL (make prove-wp proves every function keeps it): the held
    // bytes held[start .. start + count) lie within the buffer, and those waiting at its front
    // (start 0) are an undecided candidate: shorter than the buffer, a sentence shorter than the
    // longest, a frame whose length field is read shorter than that length, itself within the
    // longest frame (held_ok); and they have been written, as have the other fields, so that no
    // byte of the state is read before it is written (held_written). frame_size() reads the
    // length field as the decoder does.
    logic integer ilahrs_frame_size(uint8_t *p) = ILAHRS_FRAME_HEADER_SIZE
        + p[ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET] + 256 * p[ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET + 1];
    predicate ilahrs_waiting(uint8_t *p, integer n) =
        0 < n < ILAHRS_MAX_MESSAGE_SIZE
        && (p[0] == ILAHRS_FRAME_HEADER_0 && n >= ILAHRS_FRAME_PAYLOAD_OFFSET
            ==> n < ilahrs_frame_size(p) <= ILAHRS_FRAME_MAX_SIZE)
        && (p[0] == '$' ==> n < ILAHRS_PAHR_MAX_LENGTH);
    predicate ilahrs_held_ok(ilahrs_stream_t *s) =
        s->start + s->count <= ILAHRS_MAX_MESSAGE_SIZE
        && (s->start == 0 && s->count != 0 ==> ilahrs_waiting(&s->held[0], s->count));
    predicate ilahrs_input_written(uint8_t *p, uint8_t *end) =
        \forall uint8_t *q; \base_addr(q) == \base_addr(p) && p <= q < end ==> \initialized(q);
    predicate ilahrs_written(uint8_t *p, integer n) = ilahrs_input_written(p, p + n);
    predicate ilahrs_state_written(ilahrs_stream_t *s) =
        \initialized(&s->discarded) && \initialized(&s->strict)
        && \initialized(&s->start) && \initialized(&s->count);
    predicate ilahrs_held_written(ilahrs_stream_t *s) =
        ilahrs_state_written(s) && (s->count != 0 ==> ilahrs_written(&s->held[s->start], s->count));
*/

/** Empty the decoder (`discarded` back to 0, `strict` off). Same as zero-initialising it. */
void ilahrs_stream_init(ilahrs_stream_t *stream);

/**
 * Decode input in chunks of any size. Takes bytes from `*data` / `*len`, advancing both past
 * what it consumed, until it has a message (returns true, `*msg` filled) or has taken every
 * byte (returns false; bytes of an incomplete message are kept in the decoder). Call it in a
 * loop until it returns false, then read the next chunk. With `*len` 0 it still hands out
 * messages completed earlier.
 *
 * When a whole message lies in the caller's chunk, `msg->data` and `msg->frame.payload`
 * point into that chunk (no copy).
 *
 * @code
 *     const uint8_t *p = buf;
 *     size_t n = got;
 *     ilahrs_message_t msg;
 *     while (ilahrs_stream_next(&decoder, &p, &n, &msg)) {
 *         handle(&msg);
 *     }
 * @endcode
 */
bool ilahrs_stream_next(ilahrs_stream_t *stream, const uint8_t **data, size_t *len, ilahrs_message_t *msg);

/**
 * Decode one byte (e.g. from a UART interrupt). Returns true with `*msg` when the byte
 * completes a message. Rarely one byte releases several messages (the bytes after a
 * corrupted frame): call ilahrs_stream_poll() after a true return to get the others.
 *
 * @code
 *     void uart_rx_isr(uint8_t byte)
 *     {
 *         ilahrs_message_t msg;
 *         if (ilahrs_stream_push(&decoder, byte, &msg)) {
 *             do {
 *                 queue_message(&msg);
 *             } while (ilahrs_stream_poll(&decoder, &msg));
 *         }
 *     }
 * @endcode
 */
bool ilahrs_stream_push(ilahrs_stream_t *stream, uint8_t byte, ilahrs_message_t *msg);

/** A message already complete inside the decoder, without new input; false if none. */
bool ilahrs_stream_poll(ilahrs_stream_t *stream, ilahrs_message_t *msg);

/**
 * The input has ended: decide on every byte still held. Incomplete messages are discarded a
 * byte at a time, still handing out any valid message behind them. Call until it returns
 * false; the decoder is then empty (`discarded` keeps counting).
 */
bool ilahrs_stream_finish(ilahrs_stream_t *stream, ilahrs_message_t *msg);

#ifdef ILAHRS_IDLE_TIMEOUT_US
/**
 * The line has been quiet for `quiet_us` microseconds since the last byte. A message never spans
 * an idle line (E41): from ILAHRS_IDLE_TIMEOUT_US (ILAHRS_IDLE_BYTE_TIMES byte times) on, the
 * decoder decides on every byte it holds exactly as ilahrs_stream_finish() does (the start of a
 * frame left by a sender cut off mid-write is discarded a byte at a time, any valid message behind
 * it handed out), then goes on with the next byte as usual. Below that it changes nothing and
 * returns false. Call it until it returns false. UINT32_MAX says "the line is idle" without a time.
 *
 * Call it from the code that feeds the decoder, never concurrently with it. A UART whose receive
 * interrupt only queues bytes, drained by a periodic timer task:
 * @code
 *     void every_10_ms(void)
 *     {
 *         static uint32_t last_byte_us;
 *         uint32_t now = micros();
 *         uint8_t byte;
 *         ilahrs_message_t msg;
 *         while (rx_queue_get(&byte)) {
 *             last_byte_us = now;
 *             if (ilahrs_stream_push(&decoder, byte, &msg)) {
 *                 do {
 *                     handle(&msg);
 *                 } while (ilahrs_stream_poll(&decoder, &msg));
 *             }
 *         }
 *         while (ilahrs_stream_idle(&decoder, now - last_byte_us, &msg)) {
 *             handle(&msg);
 *         }
 *     }
 * @endcode
 * (After 71 minutes without a byte `now - last_byte_us` wraps around, by then with nothing held.)
 * An RTOS task that reads the UART with a timeout of ILAHRS_IDLE_TIMEOUT_US calls it with
 * ILAHRS_IDLE_TIMEOUT_US whenever a read returns nothing.
 */
bool ilahrs_stream_idle(ilahrs_stream_t *stream, uint32_t quiet_us, ilahrs_message_t *msg);
#endif
