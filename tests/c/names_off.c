/*
 * The C binding's name-free interface, answer by answer: built once by default and once with
 * -DILAHRS_NAMES=0 (header and ilahrs.c), it must print the same text for the same inputs
 * (tests/c/names_off.py compares them). It calls none of the functions that ILAHRS_NAMES=0
 * removes, so it compiles in both builds.
 *
 *     names_off INPUTS
 *
 * INPUTS holds one input per line as hex digits (an empty line is an empty input). For each
 * input the driver prints one block: the stream decoder over the input in chunks whose size
 * follows from the input's index, the frame, command and acknowledgement functions, every
 * payload table's parser and builder with the field reflection functions, $PAHR parse, build
 * and from_array/from_values, the date codec, firmware versions, and the device state machine
 * stepped over the frames found and over a session made of the input's bytes. Before the inputs
 * it prints the static tables (commands, variants, payload tables, sentence fields, states,
 * events, answers, transitions).
 *
 * Every error is printed as its kind and offset only. Built with ILAHRS_NAMES=0, the driver
 * also stops with a FAIL line and exit status 1 when an error's `field` is not NULL; `field`
 * is set to a non-NULL sentinel before each call, so a library that leaves it unwritten is
 * caught too.
 */
#include "ilahrs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- Output helpers ------------------------------------------------------------------ */

static unsigned long input_index;
static bool in_tables;

#if !ILAHRS_NAMES
static const char not_written[] = "field not written";
#ifdef ILAHRS_NAMES
#define NAMES_BUILD "ILAHRS_NAMES=0"
#else
#define NAMES_BUILD "ILAHRS_NAMES undefined (the header defines it)"
#endif
#endif

/* An error record to pass to the library: zeroed, and under ILAHRS_NAMES=0 with a field the
 * library must overwrite with NULL when it fails. */
static ilahrs_error_t fresh_error(void)
{
    ilahrs_error_t err;
    memset(&err, 0, sizeof err);
#if !ILAHRS_NAMES
    err.field = not_written;
#endif
    return err;
}

/* " err=KIND@OFFSET" for a failed call (OFFSET "none" for ILAHRS_NO_OFFSET). */
static void put_error(const char *what, const ilahrs_error_t *err)
{
    if (err->offset == ILAHRS_NO_OFFSET) {
        printf(" err=%d@none", (int)err->kind);
    } else {
        printf(" err=%d@%llu", (int)err->kind, (unsigned long long)err->offset);
    }
#if !ILAHRS_NAMES
    if (err->field != NULL) {
        fflush(stdout);
        if (in_tables) {
            printf("\nFAIL tables, %s: err.field is %s with " NAMES_BUILD "\n", what,
                   err->field == not_written ? "left unwritten" : "not NULL");
        } else {
            printf("\nFAIL input %lu, %s: err.field is %s with " NAMES_BUILD "\n", input_index, what,
                   err->field == not_written ? "left unwritten" : "not NULL");
        }
        exit(1);
    }
#else
    (void)what;
#endif
}

static void put_hex(const uint8_t *data, size_t len)
{
    size_t i;
    if (len == 0) {
        fputs("-", stdout);
    }
    for (i = 0; i < len; i++) {
        printf("%02X", data[i]);
    }
}

static uint32_t float_bits(float value)
{
    uint32_t bits;
    memcpy(&bits, &value, sizeof bits);
    return bits;
}

static uint64_t double_bits(double value)
{
    uint64_t bits;
    memcpy(&bits, &value, sizeof bits);
    return bits;
}

static float float_of(uint32_t bits)
{
    float value;
    memcpy(&value, &bits, sizeof value);
    return value;
}

/* ---- Input ---------------------------------------------------------------------------- */

typedef struct {
    uint8_t *data;
    size_t len;
    size_t cap;
} bytes_t;

static void bytes_add(bytes_t *b, const uint8_t *data, size_t len)
{
    if (b->len + len > b->cap) {
        size_t cap = (b->len + len) * 2 + 64;
        uint8_t *grown = (uint8_t *)realloc(b->data, cap);
        if (grown == NULL) {
            fputs("out of memory\n", stderr);
            exit(2);
        }
        b->data = grown;
        b->cap = cap;
    }
    if (len > 0) {
        memcpy(b->data + b->len, data, len);
    }
    b->len += len;
}

static int hex_digit(int c)
{
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    if (c >= 'A' && c <= 'F') {
        return c - 'A' + 10;
    }
    return -1;
}

/* One line of hex digits into `out` (emptied first); false at end of file. */
static bool read_input(FILE *in, bytes_t *out)
{
    int c;
    int high = -1;
    bool any = false;
    out->len = 0;
    while ((c = fgetc(in)) != EOF) {
        int d;
        any = true;
        if (c == '\n') {
            break;
        }
        if (c == '\r' || c == ' ') {
            continue;
        }
        d = hex_digit(c);
        if (d < 0) {
            fprintf(stderr, "input %lu: not a hex digit: %c\n", input_index, c);
            exit(2);
        }
        if (high < 0) {
            high = d;
        } else {
            uint8_t byte = (uint8_t)(high << 4 | d);
            bytes_add(out, &byte, 1);
            high = -1;
        }
    }
    if (high >= 0) {
        fprintf(stderr, "input %lu: odd number of hex digits\n", input_index);
        exit(2);
    }
    return any;
}

/* Byte `i` of the input, repeated cyclically (and a fixed byte pattern for an empty input). */
static uint8_t byte_at(const bytes_t *in, size_t i)
{
    return in->len > 0 ? in->data[i % in->len] : (uint8_t)(0x5Au + 37u * i);
}

/* ---- Static tables -------------------------------------------------------------------- */

static void put_payload_table(ilahrs_payload_t payload)
{
    printf(" payload=%d", (int)payload);
}

static void tables(void)
{
    int i;
    int j;
    printf("tables\n");
    for (i = 0; i <= ILAHRS_ERROR_KIND_COUNT; i++) {
        printf("error_kind %d %s\n", i, ilahrs_error_kind_name((ilahrs_error_kind_t)i));
    }
    for (i = 0; i <= ILAHRS_VARIANT_COUNT; i++) {
        const char *part = ilahrs_variant_part_number((ilahrs_variant_t)i);
        printf("variant %d part=%s kg=%ld ka=%ld\n", i, part != NULL ? part : "(null)",
               (long)ilahrs_variant_parameter((ilahrs_variant_t)i, ILAHRS_PARAMETER_KG),
               (long)ilahrs_variant_parameter((ilahrs_variant_t)i, ILAHRS_PARAMETER_KA));
    }
    for (i = -1; i <= ILAHRS_COMMAND_COUNT; i++) {
        ilahrs_command_t command = (ilahrs_command_t)i;
        uint8_t out[ILAHRS_FRAME_MAX_SIZE];
        ilahrs_error_t err = fresh_error();
        size_t n;
        printf("command %d code=%02X valid_in=%02X response=%d", i, ilahrs_command_code(command),
               ilahrs_command_valid_in(command), (int)ilahrs_command_response(command));
        for (j = 0; j <= ILAHRS_RESPONSE_PAYLOADS_MAX; j++) {
            put_payload_table(ilahrs_command_response_payload(command, (size_t)j));
        }
        printf(" block=%d build=", (int)ilahrs_command_parameter_block(command));
        n = ilahrs_command_build(command, out, sizeof out, &err);
        if (n > 0) {
            put_hex(out, n);
        } else {
            put_error("command_build", &err);
        }
        err = fresh_error();
        n = ilahrs_command_build(command, out, ILAHRS_FRAME_MIN_SIZE - 1, &err);
        printf(" short=%llu", (unsigned long long)n);
        if (n == 0) {
            put_error("command_build short", &err);
        }
        printf("\n");
    }
    for (i = -1; i <= ILAHRS_PAYLOAD_COUNT; i++) {
        ilahrs_payload_t payload = (ilahrs_payload_t)i;
        size_t k;
        size_t count = ilahrs_payload_field_count(payload);
        printf("payload %d size=%llu struct=%llu fields=%llu:", i, (unsigned long long)ilahrs_payload_size(payload),
               (unsigned long long)ilahrs_payload_struct_size(payload), (unsigned long long)count);
        for (k = 0; k <= count; k++) {
            const ilahrs_field_info_t *f = ilahrs_payload_field(payload, k);
            if (f == NULL) {
                printf(" (null)");
                continue;
            }
            printf(" %llu/%llu/%d", (unsigned long long)ilahrs_field_offset(f),
                   (unsigned long long)ilahrs_field_size(f), (int)ilahrs_field_kind(f));
        }
        printf("\n");
    }
    for (i = 0; i <= ILAHRS_PAHR_FIELD_COUNT; i++) {
        int32_t min = 0;
        int32_t max = 0;
        bool ok = ilahrs_pahr_field_range((size_t)i, &min, &max);
        printf("pahr_field %d range=%d %ld..%ld divisor=%lu\n", i, (int)ok, (long)min, (long)max,
               (unsigned long)ilahrs_pahr_field_divisor((size_t)i));
    }
    for (i = -1; i <= ILAHRS_STATE_COUNT; i++) {
        ilahrs_state_t state = (ilahrs_state_t)i;
        ilahrs_event_t timer = ILAHRS_EVENT_UNKNOWN;
        bool has = ilahrs_state_timer(state, &timer);
        printf("state %d mode=%d expects=%d timer=%d:%d codes=", i, (int)ilahrs_state_mode(state),
               (int)ilahrs_state_expects(state), (int)has, has ? (int)timer : -1);
        for (j = 0; j < 256; j++) {
            printf("%d%s", (int)ilahrs_event_for_code(state, (uint8_t)j), j < 255 ? "," : "");
        }
        printf(" sizes=");
        for (j = 0; j <= ILAHRS_FRAME_MAX_PAYLOAD + 1; j++) {
            printf("%d%s", (int)ilahrs_event_for_data(state, (size_t)j), j <= ILAHRS_FRAME_MAX_PAYLOAD ? "," : "");
        }
        printf("\n");
    }
    for (i = -1; i <= ILAHRS_ANSWER_COUNT; i++) {
        ilahrs_usw_mode_t mode = ILAHRS_USW_MODE_UNKNOWN;
        bool has = ilahrs_answer_usw_mode((ilahrs_answer_t)i, &mode);
        printf("answer %d payload=%d usw_mode=%d:%d\n", i, (int)ilahrs_answer_payload((ilahrs_answer_t)i), (int)has,
               has ? (int)mode : -1);
    }
    for (i = -1; i <= ILAHRS_STATE_COUNT; i++) {
        printf("transitions %d:", i);
        for (j = -1; j <= ILAHRS_EVENT_COUNT; j++) {
            int older;
            for (older = 0; older < 2; older++) {
                ilahrs_step_t step;
                bool ok;
                memset(&step, 0, sizeof step);
                ok = ilahrs_transition((ilahrs_state_t)i, (ilahrs_event_t)j, older != 0, &step);
                printf(" %d>%d/%d", (int)ok, (int)step.to, step.send_count);
                if (step.send_count > 0) {
                    printf("/%d", (int)step.send[0]);
                }
            }
        }
        printf("\n");
    }
}

/* ---- Stream decoder --------------------------------------------------------------------- */

/* Every frame the stream decoder handed out, copied (bytes, then the offsets where each starts). */
typedef struct {
    bytes_t bytes;
    size_t *starts;
    size_t count;
    size_t cap;
} frames_t;

static void frames_add(frames_t *frames, const uint8_t *data, size_t size)
{
    if (frames->count + 1 >= frames->cap) {
        size_t cap = frames->cap * 2 + 16;
        size_t *grown = (size_t *)realloc(frames->starts, cap * sizeof *grown);
        if (grown == NULL) {
            fputs("out of memory\n", stderr);
            exit(2);
        }
        frames->starts = grown;
        frames->cap = cap;
    }
    frames->starts[frames->count] = frames->bytes.len;
    bytes_add(&frames->bytes, data, size);
    frames->count++;
    frames->starts[frames->count] = frames->bytes.len;
}

static void put_usw(uint16_t usw)
{
    ilahrs_usw_t decoded = ilahrs_usw_decode(usw);
    printf(" usw=%04X/%04X/%02X/%02X/%d/%d", usw, decoded.flags, decoded.failure, decoded.warning, (int)decoded.mode,
           (int)ilahrs_usw_has_failure(usw));
}

static void put_sentence(const ilahrs_pahr_t *s)
{
    size_t k;
    printf(" fields=");
    for (k = 0; k <= ILAHRS_PAHR_FIELD_COUNT; k++) {
        printf("%ld%s", (long)ilahrs_pahr_field_get(s, k), k < ILAHRS_PAHR_FIELD_COUNT ? "," : "");
    }
    printf(" deg=%08lX,%08lX,%08lX,%08lX,%08lX", (unsigned long)float_bits(ilahrs_pahr_roll_deg(s)),
           (unsigned long)float_bits(ilahrs_pahr_pitch_deg(s)), (unsigned long)float_bits(ilahrs_pahr_heading_deg(s)),
           (unsigned long)float_bits(ilahrs_pahr_temperature_degc(s)), (unsigned long)float_bits(ilahrs_pahr_vdd_v(s)));
    put_usw(s->usw);
}

static void put_message(const char *how, size_t at, const ilahrs_message_t *msg, frames_t *frames)
{
    if (msg->kind == ILAHRS_MESSAGE_FRAME) {
        printf("  F %s at=%llu size=%llu type=%u reserved=%u payload=%llu ", how, (unsigned long long)at,
               (unsigned long long)msg->size, msg->frame.message_type, msg->frame.reserved,
               (unsigned long long)msg->frame.payload_size);
        put_hex(msg->data, msg->size);
        if (msg->frame.payload_size > 0 && memcmp(msg->frame.payload, msg->data + ILAHRS_FRAME_PAYLOAD_OFFSET,
                                                  msg->frame.payload_size) != 0) {
            printf(" PAYLOAD-MISMATCH");
        }
        frames_add(frames, msg->data, msg->size);
    } else {
        printf("  S %s at=%llu size=%llu ", how, (unsigned long long)at, (unsigned long long)msg->size);
        put_hex(msg->data, msg->size);
        put_sentence(&msg->sentence);
    }
    printf("\n");
}

/* Chunk sizes, picked by input index: one byte at a time (push and poll) or chunks (next). */
static const size_t chunk_sizes[] = {1, 3, 7, 0, 2, 64, 5, 0};

static void stream(const bytes_t *in, frames_t *frames)
{
    ilahrs_stream_t decoder;
    ilahrs_message_t msg;
    size_t chunk = chunk_sizes[input_index % (sizeof chunk_sizes / sizeof chunk_sizes[0])];
    size_t at = 0;
    memset(&decoder, 0xA5, sizeof decoder);
    ilahrs_stream_init(&decoder);
    memset(&msg, 0, sizeof msg);
    printf("stream chunk=%llu\n", (unsigned long long)chunk);
    if (chunk == 1) {
        for (at = 0; at < in->len; at++) {
            if (ilahrs_stream_push(&decoder, in->data[at], &msg)) {
                do {
                    put_message("push", at + 1, &msg, frames);
                    memset(&msg, 0, sizeof msg);
                } while (ilahrs_stream_poll(&decoder, &msg));
            }
            memset(&msg, 0, sizeof msg);
        }
    } else {
        size_t step = chunk == 0 ? (in->len > 0 ? in->len : 1) : chunk;
        while (at < in->len) {
            size_t take = in->len - at < step ? in->len - at : step;
            const uint8_t *p = in->data + at;
            size_t n = take;
            while (ilahrs_stream_next(&decoder, &p, &n, &msg)) {
                put_message("next", at + (take - n), &msg, frames);
                memset(&msg, 0, sizeof msg);
            }
            at += take;
            memset(&msg, 0, sizeof msg);
            /* No input: only messages completed earlier, which the loop above already took. */
            n = 0;
            while (ilahrs_stream_next(&decoder, &p, &n, &msg)) {
                put_message("empty", at, &msg, frames);
                memset(&msg, 0, sizeof msg);
            }
            while (ilahrs_stream_poll(&decoder, &msg)) {
                put_message("poll", at, &msg, frames);
                memset(&msg, 0, sizeof msg);
            }
        }
    }
    printf(" held=%u discarded=%llu\n", decoder.count, (unsigned long long)decoder.discarded);
    while (ilahrs_stream_finish(&decoder, &msg)) {
        put_message("finish", in->len, &msg, frames);
        memset(&msg, 0, sizeof msg);
    }
    printf(" end held=%u discarded=%llu\n", decoder.count, (unsigned long long)decoder.discarded);
}

/* ---- Frames, commands, acknowledgements --------------------------------------------------- */

static void frame_functions(const bytes_t *in, const char *label)
{
    ilahrs_frame_t frame;
    ilahrs_command_match_t match;
    ilahrs_error_t err = fresh_error();
    uint8_t out[ILAHRS_FRAME_MAX_SIZE + 8];
    size_t n;
    memset(&frame, 0, sizeof frame);
    memset(&match, 0, sizeof match);
    printf("%s checksum=%04X", label, ilahrs_checksum(in->data, in->len));
    if (ilahrs_frame_parse(in->data, in->len, &frame, &err)) {
        size_t cap;
        printf(" frame type=%u reserved=%u payload=", frame.message_type, frame.reserved);
        put_hex(frame.payload, frame.payload_size);
        printf(" rebuilt=");
        err = fresh_error();
        n = ilahrs_frame_build(&frame, out, sizeof out, &err);
        if (n > 0) {
            put_hex(out, n);
        } else {
            put_error("frame_build", &err);
        }
        /* The same frame into every buffer that is one byte short, and with each message type. */
        cap = frame.payload_size + ILAHRS_FRAME_OVERHEAD - 1;
        err = fresh_error();
        n = ilahrs_frame_build(&frame, out, cap, &err);
        printf(" short=%llu", (unsigned long long)n);
        if (n == 0) {
            put_error("frame_build short", &err);
        }
        frame.message_type = (uint8_t)(frame.message_type + 1u);
        err = fresh_error();
        n = ilahrs_frame_build(&frame, out, sizeof out, &err);
        printf(" type+1=");
        if (n > 0) {
            put_hex(out, n);
        } else {
            put_error("frame_build type", &err);
        }
    } else {
        printf(" frame");
        put_error("frame_parse", &err);
    }
    err = fresh_error();
    if (ilahrs_command_decode(in->data, in->len, &match, &err)) {
        unsigned k;
        printf(" command code=%02X count=%u", match.code, match.count);
        for (k = 0; k < match.count && k < ILAHRS_COMMANDS_PER_CODE_MAX; k++) {
            printf(" %d", (int)match.commands[k]);
        }
    } else {
        printf(" command");
        put_error("command_decode", &err);
    }
    err = fresh_error();
    n = ilahrs_ack_build(in->data, in->len, out, sizeof out, &err);
    printf(" ack=");
    if (n > 0) {
        put_hex(out, n);
        err = fresh_error();
        n = ilahrs_ack_build(in->data, in->len, out, n - 1, &err);
        printf(" short=%llu", (unsigned long long)n);
        if (n == 0) {
            put_error("ack_build short", &err);
        }
    } else {
        put_error("ack_build", &err);
    }
    printf("\n");
}

/* A frame built from the input's first bytes as message type and payload. */
static void frame_build_from(const bytes_t *in)
{
    ilahrs_frame_t frame;
    ilahrs_error_t err = fresh_error();
    uint8_t out[ILAHRS_FRAME_MAX_SIZE + 8];
    size_t n;
    memset(&frame, 0, sizeof frame);
    frame.message_type = (uint8_t)(byte_at(in, 0) % 3u);
    frame.reserved = byte_at(in, 1);
    frame.payload = in->len > 1 ? in->data + 1 : in->data;
    frame.payload_size = in->len > 1 ? in->len - 1 : 0;
    n = ilahrs_frame_build(&frame, out, sizeof out, &err);
    printf("frame_build type=%u ", frame.message_type);
    if (n > 0) {
        put_hex(out, n);
    } else {
        put_error("frame_build", &err);
    }
    printf("\n");
}

/* ---- Payload tables ------------------------------------------------------------------------ */

typedef union {
    uint64_t align_u64;
    double align_double;
    void *align_pointer;
    uint8_t bytes[512];
} payload_buffer_t;

static void build_and_put(ilahrs_payload_t payload, const payload_buffer_t *value, const char *what)
{
    uint8_t out[ILAHRS_FRAME_MAX_SIZE + 8];
    ilahrs_error_t err = fresh_error();
    size_t n = ilahrs_payload_build(payload, value, out, sizeof out, &err);
    if (n > 0) {
        printf(" ");
        put_hex(out, n);
    } else {
        put_error(what, &err);
    }
}

static const double check_values[] = {0.0, -1.0, 1.0, 0.5, 127.0, 255.0, 256.0, -32768.0, 65535.0, 65536.0,
                                      -2147483649.0, 4294967296.0, 180.0, 180.5, 360.5, 999.0, 3.5e38, -1e300};

static void field_functions(ilahrs_payload_t payload, const payload_buffer_t *parsed, size_t index)
{
    const ilahrs_field_info_t *f = ilahrs_payload_field(payload, index);
    ilahrs_kind_t kind = ilahrs_field_kind(f);
    const uint8_t *member = (const uint8_t *)ilahrs_field_member_const(f, parsed);
    payload_buffer_t changed;
    ilahrs_error_t err;
    int variant;
    size_t k;
    printf("  field %llu off=%llu size=%llu kind=%d member=%lld", (unsigned long long)index,
           (unsigned long long)ilahrs_field_offset(f), (unsigned long long)ilahrs_field_size(f), (int)kind,
           (long long)(member - parsed->bytes));
    if (member != (const uint8_t *)ilahrs_field_member(f, (void *)(uintptr_t)parsed)) {
        printf(" MEMBER-MISMATCH");
    }
    printf(" int=%lld float=%08lX bytes=", (long long)ilahrs_field_get_int(f, parsed),
           (unsigned long)float_bits(ilahrs_field_get_float(f, parsed)));
    put_hex(member, kind == ILAHRS_KIND_CHAR || kind == ILAHRS_KIND_RESERVED ? ilahrs_field_size(f) : 0);
    printf(" scale=");
    for (variant = 0; variant <= ILAHRS_VARIANT_COUNT + 1; variant++) {
        int32_t multiplier = 0;
        int32_t divisor = 0;
        bool ok = ilahrs_field_scale(f, (ilahrs_variant_t)variant, &multiplier, &divisor);
        printf("%d:%ld/%ld%s", (int)ok, (long)multiplier, (long)divisor, variant <= ILAHRS_VARIANT_COUNT ? "," : "");
    }
    if (kind == ILAHRS_KIND_UNSIGNED || kind == ILAHRS_KIND_SIGNED || kind == ILAHRS_KIND_FLOAT) {
        double own = kind == ILAHRS_KIND_FLOAT ? (double)ilahrs_field_get_float(f, parsed)
                                               : (double)ilahrs_field_get_int(f, parsed);
        printf(" check:");
        for (k = 0; k <= sizeof check_values / sizeof check_values[0] + 2; k++) {
            double value = k < sizeof check_values / sizeof check_values[0] ? check_values[k]
                           : k == sizeof check_values / sizeof check_values[0]   ? own
                           : k == sizeof check_values / sizeof check_values[0] + 1 ? (double)NAN
                                                                                   : -(double)INFINITY;
            err = fresh_error();
            if (ilahrs_field_check(f, value, &err)) {
                printf(" ok");
            } else {
                put_error("field_check", &err);
            }
        }
    }
    /* Set the field to a neighbouring and an extreme value in a copy and build the copy. */
    for (k = 0; k < 3; k++) {
        bool ok;
        memcpy(&changed, parsed, sizeof changed);
        err = fresh_error();
        if (kind == ILAHRS_KIND_FLOAT) {
            float values[3];
            values[0] = float_of(float_bits(ilahrs_field_get_float(f, parsed)) + 1u);
            values[1] = -1.0e30f;
            values[2] = (float)(180.25 + (double)index);
            ok = ilahrs_field_set_float(f, &changed, values[k], &err);
            printf(" set_float=");
        } else {
            int64_t values[3];
            values[0] = ilahrs_field_get_int(f, parsed) + 1;
            values[1] = -1 - (int64_t)index;
            values[2] = (int64_t)1 << (8 * (k + index % 3u));
            ok = ilahrs_field_set_int(f, &changed, values[k], &err);
            printf(" set_int=");
        }
        if (ok) {
            printf("%lld/%08lX", (long long)ilahrs_field_get_int(f, &changed),
                   (unsigned long)float_bits(ilahrs_field_get_float(f, &changed)));
            build_and_put(payload, &changed, "payload_build changed");
        } else {
            put_error("field_set", &err);
        }
    }
    printf("\n");
}

static void payload_functions(const uint8_t *data, size_t len, bool every_table)
{
    int t;
    for (t = -1; t <= ILAHRS_PAYLOAD_COUNT; t++) {
        ilahrs_payload_t payload = (ilahrs_payload_t)t;
        payload_buffer_t parsed;
        ilahrs_error_t err = fresh_error();
        size_t k;
        if (!every_table && ilahrs_payload_size(payload) != len) {
            continue;
        }
        if (ilahrs_payload_struct_size(payload) > sizeof parsed.bytes) {
            printf("FAIL payload %d: struct of %llu bytes\n", t,
                   (unsigned long long)ilahrs_payload_struct_size(payload));
            exit(1);
        }
        memset(&parsed, 0, sizeof parsed);
        if (!ilahrs_payload_parse(payload, data, len, &parsed, &err)) {
            printf("P%d", t);
            put_error("payload_parse", &err);
            printf("\n");
            continue;
        }
        printf("P%d ok struct=", t);
        put_hex(parsed.bytes, ilahrs_payload_struct_size(payload));
        printf(" build");
        build_and_put(payload, &parsed, "payload_build");
        {
            uint8_t out[ILAHRS_FRAME_MAX_SIZE + 8];
            size_t n;
            err = fresh_error();
            n = ilahrs_payload_build(payload, &parsed, out, len - 1, &err);
            printf(" short=%llu", (unsigned long long)n);
            if (n == 0) {
                put_error("payload_build short", &err);
            }
            err = fresh_error();
            n = ilahrs_payload_build_frame(payload, &parsed, out, sizeof out, &err);
            printf(" frame=");
            if (n > 0) {
                put_hex(out, n);
            } else {
                put_error("payload_build_frame", &err);
            }
        }
        {
            payload_buffer_t defaults;
            memset(&defaults, 0, sizeof defaults);
            ilahrs_payload_defaults(payload, &defaults);
            printf(" defaults=");
            put_hex(defaults.bytes, ilahrs_payload_struct_size(payload));
            build_and_put(payload, &defaults, "payload_build defaults");
        }
        printf("\n");
        for (k = 0; k < ilahrs_payload_field_count(payload); k++) {
            field_functions(payload, &parsed, k);
        }
    }
}

/* ---- $PAHR sentences ------------------------------------------------------------------------ */

static void build_sentence(const ilahrs_pahr_t *s, const char *what)
{
    char out[ILAHRS_PAHR_MAX_LENGTH + 1];
    ilahrs_error_t err = fresh_error();
    size_t n;
    memset(out, 0, sizeof out);
    n = ilahrs_pahr_build(s, out, sizeof out, &err);
    printf(" build=");
    if (n > 0) {
        put_hex((const uint8_t *)out, n);
        err = fresh_error();
        n = ilahrs_pahr_build(s, out, n - 1, &err);
        printf(" short=%llu", (unsigned long long)n);
        if (n == 0) {
            put_error("pahr_build short", &err);
        }
    } else {
        put_error(what, &err);
    }
}

static void sentence_functions(const bytes_t *in)
{
    ilahrs_pahr_t s;
    ilahrs_error_t err = fresh_error();
    double values[ILAHRS_PAHR_FIELD_COUNT];
    size_t k;
    memset(&s, 0, sizeof s);
    printf("pahr_parse");
    if (ilahrs_pahr_parse((const char *)in->data, in->len, &s, &err)) {
        printf(" ok");
        put_sentence(&s);
        build_sentence(&s, "pahr_build");
    } else {
        put_error("pahr_parse", &err);
    }
    printf("\n");

    /* Values from the input bytes: in and out of range, now and then not finite or not whole. */
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        uint8_t b0 = byte_at(in, 3 * k);
        uint8_t b1 = byte_at(in, 3 * k + 1);
        uint8_t b2 = byte_at(in, 3 * k + 2);
        uint32_t divisor = ilahrs_pahr_field_divisor(k);
        long raw = (long)(int16_t)(uint16_t)(b0 | b1 << 8);
        if (divisor == 0) {
            values[k] = (double)(uint16_t)raw + (b2 % 5u == 0 ? 0.5 : 0.0);
        } else if (b2 % 7u == 0) {
            values[k] = (double)raw / (double)divisor * 4.0;
        } else {
            values[k] = (double)(raw % 9000) / (double)divisor + (double)(b2 % 3u) * 0.004;
        }
        if (b2 == 0xFF) {
            values[k] = (double)NAN;
        } else if (b2 == 0xFE) {
            values[k] = -(double)INFINITY;
        }
    }
    printf("pahr_from_array values=");
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        printf("%016llX%s", (unsigned long long)double_bits(values[k]), k + 1 < ILAHRS_PAHR_FIELD_COUNT ? "," : "");
    }
    memset(&s, 0, sizeof s);
    err = fresh_error();
    if (ilahrs_pahr_from_array(values, &s, &err)) {
        printf(" ok");
        put_sentence(&s);
        build_sentence(&s, "pahr_build");
    } else {
        put_error("pahr_from_array", &err);
    }
    memset(&s, 0, sizeof s);
    err = fresh_error();
    printf(" from_values");
    if (ilahrs_pahr_from_values(values[0], values[1], values[2], values[3], values[4], (uint16_t)byte_at(in, 5), &s,
                                &err)) {
        printf(" ok");
        put_sentence(&s);
    } else {
        put_error("pahr_from_values", &err);
    }
    printf("\n");

    /* Raw fields straight from the input bytes, most of them out of range. */
    memcpy(&s, in->len >= sizeof s ? in->data : (const uint8_t *)"\x10\x27\x00\x80\x9F\x8C\x0F\x27\xE7\x03\x00\x01",
           sizeof s);
    printf("pahr_raw");
    put_sentence(&s);
    build_sentence(&s, "pahr_build raw");
    printf("\n");
}

/* ---- Dates and firmware versions ------------------------------------------------------------ */

static void date_functions(const bytes_t *in)
{
    int year = 1895 + (int)((unsigned)(byte_at(in, 0) | byte_at(in, 1) << 8) % 310u);
    int month = (int)(byte_at(in, 2) % 14u);
    int day = (int)(byte_at(in, 3) % 33u);
    float value = 0.0f;
    ilahrs_date_t date;
    ilahrs_error_t err = fresh_error();
    uint32_t bits;
    int k;
    printf("date %d-%d-%d", year, month, day);
    if (ilahrs_date_encode(year, month, day, &value, &err)) {
        printf(" encode=%08lX", (unsigned long)float_bits(value));
        memset(&date, 0, sizeof date);
        err = fresh_error();
        if (ilahrs_date_decode(value, &date, &err)) {
            printf(" decode=%d-%u-%u", date.year, date.month, date.day);
        } else {
            put_error("date_decode", &err);
        }
    } else {
        put_error("date_encode", &err);
    }
    /* Floats near the date range and the input's own bytes read as a float. */
    for (k = 0; k < 3; k++) {
        if (k == 0) {
            bits = (uint32_t)byte_at(in, 4) | (uint32_t)byte_at(in, 5) << 8 | (uint32_t)byte_at(in, 6) << 16 |
                   (uint32_t)byte_at(in, 7) << 24;
            value = float_of(bits);
        } else if (k == 1) {
            value = 1899.0f + (float)((unsigned)(byte_at(in, 8) | byte_at(in, 9) << 8) % 30500u) / 100.0f;
        } else {
            value = float_of(float_bits(2199.99f) + (uint32_t)(byte_at(in, 10) % 8u) - 4u);
        }
        memset(&date, 0, sizeof date);
        err = fresh_error();
        printf(" %08lX", (unsigned long)float_bits(value));
        if (ilahrs_date_decode(value, &date, &err)) {
            printf("=%d-%u-%u", date.year, date.month, date.day);
        } else {
            put_error("date_decode", &err);
        }
    }
    printf("\n");
}

/* The input as a version, and a version made of its bytes; the second one is returned. */
static bool firmware_functions(const bytes_t *in, ilahrs_firmware_t *made)
{
    static const char reference_text[] = "4.9.9.0";
    ilahrs_firmware_t version;
    ilahrs_firmware_t reference;
    ilahrs_error_t err = fresh_error();
    char text[64];
    int len;
    bool ok;
    unsigned k;
    memset(&version, 0, sizeof version);
    memset(&reference, 0, sizeof reference);
    memset(made, 0, sizeof *made);
    if (!ilahrs_firmware_parse(reference_text, sizeof reference_text - 1, &reference, &err)) {
        printf("FAIL firmware %s not read\n", reference_text);
        exit(1);
    }
    printf("firmware input");
    err = fresh_error();
    if (ilahrs_firmware_parse((const char *)in->data, in->len, &version, &err)) {
        printf(" ok count=%u cmp=%d", version.count, ilahrs_firmware_compare(&version, &reference));
    } else {
        put_error("firmware_parse", &err);
    }
    switch (byte_at(in, 0) % 6u) {
    case 0:
        len = snprintf(text, sizeof text, "%u.%u.%u.%u", byte_at(in, 1) % 6u, byte_at(in, 2) % 11u,
                       byte_at(in, 3) % 11u, byte_at(in, 4) % 3u);
        break;
    case 1:
        len = snprintf(text, sizeof text, "4.9.%u", byte_at(in, 1) % 12u);
        break;
    case 2:
        len = snprintf(text, sizeof text, "%u..%u", (unsigned)byte_at(in, 1), (unsigned)byte_at(in, 2));
        break;
    case 3:
        len = snprintf(text, sizeof text, "1.2.3.4.5.6.7.8.%u", (unsigned)byte_at(in, 1));
        break;
    case 4:
        len = snprintf(text, sizeof text, "4.%u%u%u%u%u%u", (unsigned)byte_at(in, 1), (unsigned)byte_at(in, 2),
                       (unsigned)byte_at(in, 3), (unsigned)byte_at(in, 4), (unsigned)byte_at(in, 5),
                       (unsigned)byte_at(in, 6));
        break;
    default:
        len = snprintf(text, sizeof text, "4.9.9.%u", byte_at(in, 1) % 2u);
        break;
    }
    printf(" made=%s", text);
    err = fresh_error();
    ok = ilahrs_firmware_parse(text, (size_t)len, made, &err);
    if (ok) {
        printf(" ok count=%u parts=", made->count);
        for (k = 0; k < made->count && k < ILAHRS_FIRMWARE_PARTS_MAX; k++) {
            printf("%lu%s", (unsigned long)made->parts[k], k + 1 < made->count ? "." : "");
        }
        printf(" cmp=%d rcmp=%d", ilahrs_firmware_compare(made, &reference), ilahrs_firmware_compare(&reference, made));
    } else {
        put_error("firmware_parse made", &err);
    }
    printf("\n");
    return ok;
}

/* ---- State machine ---------------------------------------------------------------------------- */

static void step_on(const char *how, ilahrs_state_t *state, const ilahrs_frame_t *frame,
                    const ilahrs_firmware_t *firmware)
{
    ilahrs_event_t event = ilahrs_event_for_frame(*state, frame);
    ilahrs_step_t step;
    ilahrs_step_t older;
    ilahrs_event_t timer = ILAHRS_EVENT_UNKNOWN;
    bool ok;
    bool ok_older;
    memset(&step, 0, sizeof step);
    memset(&older, 0, sizeof older);
    ok = ilahrs_transition_on(*state, event, firmware, &step);
    ok_older = ilahrs_transition(*state, event, true, &older);
    printf(" %s:%d:%d>%d", how, (int)*state, (int)event, (int)ok);
    printf("/%d/%u", (int)step.to, step.send_count);
    if (step.send_count > 0) {
        printf("/%d/%d", (int)step.send[0], (int)ilahrs_answer_payload(step.send[0]));
    }
    printf(" older=%d/%d/%u", (int)ok_older, (int)older.to, older.send_count);
    *state = step.to;
    if (ilahrs_state_timer(*state, &timer)) {
        ilahrs_step_t fired;
        memset(&fired, 0, sizeof fired);
        ok = ilahrs_transition_on(*state, timer, firmware, &fired);
        printf(" timer=%d>%d/%d/%u", (int)timer, (int)ok, (int)fired.to, fired.send_count);
        /* Let the timer fire on every other frame, so the machine also gets past alignment. */
        if ((input_index + (size_t)event) % 2u == 0) {
            *state = fired.to;
        }
    }
}

static void state_machine(const bytes_t *in, const frames_t *frames, const ilahrs_firmware_t *firmware)
{
    ilahrs_state_t state = ILAHRS_STATE_INITIAL;
    ilahrs_frame_t frame;
    ilahrs_error_t err;
    size_t k;
    printf("states");
    memset(&frame, 0, sizeof frame);
    err = fresh_error();
    if (ilahrs_frame_parse(in->data, in->len, &frame, &err)) {
        step_on("input", &state, &frame, firmware);
    }
    for (k = 0; k < frames->count; k++) {
        const uint8_t *data = frames->bytes.data + frames->starts[k];
        size_t size = frames->starts[k + 1] - frames->starts[k];
        memset(&frame, 0, sizeof frame);
        err = fresh_error();
        if (!ilahrs_frame_parse(data, size, &frame, &err)) {
            printf(" stream frame %llu", (unsigned long long)k);
            put_error("frame_parse of a stream frame", &err);
            continue;
        }
        step_on("f", &state, &frame, firmware);
    }
    printf(" final=%d mode=%d\n", (int)state, (int)ilahrs_state_mode(state));
}

/* A session made of the input's first bytes: each byte a command frame (the byte picks the
 * command) or, one byte in four, a data frame of the table the state waits for (else of a table
 * the byte picks), stepped from the initial state with the timers firing now and then. */
static void walk(const bytes_t *in, const ilahrs_firmware_t *firmware)
{
    ilahrs_state_t state = ILAHRS_STATE_INITIAL;
    size_t k;
    printf("walk");
    for (k = 0; k < in->len && k < 24; k++) {
        uint8_t b = in->data[k];
        uint8_t out[ILAHRS_FRAME_MAX_SIZE];
        ilahrs_frame_t frame;
        ilahrs_error_t err = fresh_error();
        size_t n;
        if (b % 4u == 3u) {
            payload_buffer_t block;
            ilahrs_payload_t payload = ilahrs_state_expects(state);
            if (payload == ILAHRS_PAYLOAD_NONE || b % 8u == 7u) {
                payload = (ilahrs_payload_t)(b % ILAHRS_PAYLOAD_COUNT);
            }
            memset(&block, 0, sizeof block);
            ilahrs_payload_defaults(payload, &block);
            n = ilahrs_payload_build_frame(payload, &block, out, sizeof out, &err);
        } else {
            n = ilahrs_command_build((ilahrs_command_t)(b % ILAHRS_COMMAND_COUNT), out, sizeof out, &err);
        }
        if (n == 0) {
            printf(" build");
            put_error("walk build", &err);
            continue;
        }
        memset(&frame, 0, sizeof frame);
        err = fresh_error();
        if (!ilahrs_frame_parse(out, n, &frame, &err)) {
            printf(" parse");
            put_error("walk parse", &err);
            continue;
        }
        step_on(b % 4u == 3u ? "d" : "c", &state, &frame, firmware);
    }
    printf(" final=%d mode=%d\n", (int)state, (int)ilahrs_state_mode(state));
}

/* ---- Main --------------------------------------------------------------------------------------- */

int main(int argc, char **argv)
{
    FILE *in;
    bytes_t input;
    frames_t frames;
    static char buffer[1 << 16];
    if (argc != 2) {
        fputs("usage: names_off INPUTS (one hex string per line)\n", stderr);
        return 2;
    }
    in = fopen(argv[1], "rb");
    if (in == NULL) {
        perror(argv[1]);
        return 2;
    }
    setvbuf(stdout, buffer, _IOFBF, sizeof buffer);
#ifdef ILAHRS_NAMES
    printf("ILAHRS_NAMES=%d\n", (int)ILAHRS_NAMES);
#else
    printf("ILAHRS_NAMES unset\n");
#endif
    in_tables = true;
    tables();
    in_tables = false;
    memset(&input, 0, sizeof input);
    memset(&frames, 0, sizeof frames);
    for (input_index = 0; read_input(in, &input); input_index++) {
        ilahrs_firmware_t firmware;
        bool have_firmware;
        size_t k;
        printf("input %lu len=%llu\n", input_index, (unsigned long long)input.len);
        frames.bytes.len = 0;
        frames.count = 0;
        stream(&input, &frames);
        frame_functions(&input, "input");
        frame_build_from(&input);
        payload_functions(input.data, input.len, true);
        for (k = 0; k < frames.count; k++) {
            const uint8_t *data = frames.bytes.data + frames.starts[k];
            ilahrs_frame_t frame;
            ilahrs_error_t err = fresh_error();
            memset(&frame, 0, sizeof frame);
            if (ilahrs_frame_parse(data, frames.starts[k + 1] - frames.starts[k], &frame, &err)) {
                printf("frame %llu\n", (unsigned long long)k);
                payload_functions(frame.payload, frame.payload_size, false);
            }
        }
        sentence_functions(&input);
        date_functions(&input);
        have_firmware = firmware_functions(&input, &firmware);
        state_machine(&input, &frames, have_firmware ? &firmware : NULL);
        walk(&input, have_firmware ? &firmware : NULL);
    }
    if (ferror(in)) {
        perror(argv[1]);
        return 2;
    }
    fclose(in);
    free(input.data);
    free(frames.bytes.data);
    free(frames.starts);
    printf("done %lu inputs\n", input_index);
    return 0;
}
