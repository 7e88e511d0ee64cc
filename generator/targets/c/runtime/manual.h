/**
 * Copy ilahrs.h and ilahrs.c into your project; there is nothing to configure. The library
 * needs only <stdint.h>, <stddef.h>, <stdbool.h> and <string.h>; it never allocates, holds no
 * global or static mutable state (every function is reentrant), and every function accepts
 * any input without crashing: bad input gets a typed error, never a wrapped or truncated value.
 * Compile it for size (-Os) or for speed (-O2): it is one code path, and the answers are the same.
 *
 * Conventions
 * - Functions that decode return `bool` (true on success). Functions that build return the
 *   number of bytes written, or 0 on failure; they write into a caller buffer `out` of `cap`
 *   bytes and never past it. After a failure the outputs hold nothing useful.
 * - Pointers must be valid; an input pointer may be NULL only when its length is 0.
 * - Every function that can fail takes an `ilahrs_error_t *err` last. It may be NULL. On
 *   failure it receives the error kind, the byte offset into the input the error refers to
 *   (ILAHRS_NO_OFFSET when none applies) and the name of the field at fault (NULL when none
 *   applies). On success it is left alone.
 * - Multi-byte values are little-endian on the wire; the library converts to and from host
 *   order, whatever the host's byte order and alignment rules.
 * - Payload structs hold raw wire values: integers as sent, floats as float32, char fields
 *   as the bytes received (NUL-terminated for convenience), reserved bytes verbatim. The
 *   `*_<unit>()` helpers give engineering values.
 *
 * Build switches, for a firmware short of flash (sizes measured by `make footprint-c`: Cortex-M4,
 * arm-none-eabi-gcc -Os, --gc-sections):
 * - ILAHRS_NAMES 0 (define it for ilahrs.c and for every file that includes this header): no
 *   name strings. The name accessors and by-name lookups are not declared, errors report their
 *   field as NULL (their kind and byte offset are unchanged, and the offset locates the field),
 *   and no name string is linked; ilahrs_error_kind_name() and ilahrs_variant_part_number() stay.
 *   Everything else answers exactly as in the default build. It saves about 790 bytes of flash in
 *   a firmware that decodes the stream and builds frames, commands and payloads (4,059 -> 3,272),
 *   and about 2,750 bytes in the whole library.
 * - ILAHRS_STREAM_SENTENCES 0 (for ilahrs.c): a stream decoder for a firmware that never turns
 *   on the device's NMEA output. It hands out the same frames, in the same order, and counts the
 *   bytes of $PAHR sentences as discarded; ilahrs_pahr_parse() and the other sentence functions
 *   stay. It saves about 840 bytes of the stream decoder's (1,344 -> 508).
 *
 * Decoding a byte stream (serial port, capture file):
 * @code
 *     ilahrs_stream_t decoder = {0};
 *     ilahrs_message_t msg;
 *     const uint8_t *p = chunk;
 *     size_t n = chunk_len;
 *     while (ilahrs_stream_next(&decoder, &p, &n, &msg)) {
 *         if (msg.kind == ILAHRS_MESSAGE_FRAME) {
 *             ilahrs_orientation_sensors_t o;
 *             if (ilahrs_orientation_sensors_parse(msg.frame.payload, msg.frame.payload_size, &o, NULL)) {
 *                 printf("heading %.2f deg\n", (double)ilahrs_orientation_sensors_heading_deg(&o));
 *             }
 *         } else {
 *             printf("roll %.2f deg\n", (double)ilahrs_pahr_roll_deg(&msg.sentence));
 *         }
 *     }
 * @endcode
 *
 * Sending a command:
 * @code
 *     uint8_t frame[ILAHRS_FRAME_MAX_SIZE];
 *     size_t n = ilahrs_build_ahrs_cont3(frame, sizeof frame, NULL);
 *     uart_write(frame, n);
 * @endcode
 */
