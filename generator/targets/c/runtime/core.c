/* On its own (an editor, `make lint-c`), this file includes what precedes it in ilahrs.c:
 * the tables. ilahrs.c holds it without this include. */
#include "ilahrs_internal.h"

/* ---- Helpers --------------------------------------------------------------------------- */

/* NOINLINE keeps a small helper called from many places out of line: one call is smaller than
 * the copies a compiler optimizing for size would otherwise inline. */
#if defined(__GNUC__)
#define NOINLINE __attribute__((noinline))
#else
#define NOINLINE
#endif

/* Optimizing for size, a compiler may turn a copy loop into a call of memcpy, memmove or memset,
 * which a small C library implements in hundreds of bytes: OPAQUE hides the loop counter from it. */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__)
#define OPAQUE(x) __asm__("" : "+r"(x))
#else
#define OPAQUE(x) ((void)0)
#endif

/* FAST: compiled for speed (optimizing, not for size). A few hot loops then take a word at a time;
 * compiled for size they take a byte at a time, in less code. The answers are the same. */
#if defined(__OPTIMIZE__) && !defined(__OPTIMIZE_SIZE__)
#define FAST 1
#else
#define FAST 0
#endif

/* Copy n bytes front to back: right for separate buffers and for moves to a lower address
 * within one buffer. */
static void copy_forward(uint8_t *dst, const uint8_t *src, size_t n)
{
    size_t i;
    /*@ loop invariant i <= n;
        loop invariant \forall integer k; 0 <= k < i ==> dst[k] == \at(src[k], Pre);
        loop invariant \forall integer k; i <= k < n ==> src[k] == \at(src[k], Pre);
        loop invariant ilahrs_written(dst, i);
        loop invariant \forall integer k; i <= k < n ==> \initialized(src + k);
        loop assigns i, dst[0 .. n - 1]; */
    for (i = 0; i < n; i++) {
        OPAQUE(i);
        dst[i] = src[i];
    }
}

/* Copy n bytes between buffers that may overlap. */
static void move_bytes(uint8_t *dst, const uint8_t *src, size_t n)
{
    if ((uintptr_t)dst <= (uintptr_t)src) {
        copy_forward(dst, src, n);
        return;
    }
    while (n > 0) {
        n--;
        OPAQUE(n);
        dst[n] = src[n];
    }
}

/* Set n bytes to zero. */
static void zero_bytes(void *dst, size_t n)
{
    uint8_t *p = (uint8_t *)dst;
    size_t i;
    for (i = 0; i < n; i++) {
        OPAQUE(i);
        p[i] = 0;
    }
}

/* Every error path calls this one copy rather than inline its three stores. */
static NOINLINE bool fail(ilahrs_error_t *err, ilahrs_error_kind_t kind, size_t offset, const char *field)
{
    if (err != NULL) {
        err->kind = kind;
        err->offset = offset;
        err->field = field;
    }
    return false;
}

static size_t fail_size(ilahrs_error_t *err, ilahrs_error_kind_t kind, size_t offset, const char *field)
{
    (void)fail(err, kind, offset, field);
    return 0;
}

/* Little-endian read and write of 1..4 bytes. */
static uint32_t get_le(const uint8_t *p, size_t size)
{
    uint32_t value = 0;
    while (size > 0) {
        size--;
        value = (value << 8) | p[size];
    }
    return value;
}

static void put_le(uint8_t *p, uint32_t value, size_t size)
{
    size_t i;
    for (i = 0; i < size; i++) {
        p[i] = (uint8_t)(value >> (8 * i));
    }
}

/* Host-order load and store of a 1, 2 or 4-byte struct member, as raw bits. */
static uint32_t load_bits(const void *member, size_t size)
{
    if (size == 1) {
        uint8_t v;
        memcpy(&v, member, 1);
        return v;
    }
    if (size == 2) {
        uint16_t v;
        memcpy(&v, member, 2);
        return v;
    }
    {
        uint32_t v;
        memcpy(&v, member, 4);
        return v;
    }
}

static void store_bits(void *member, uint32_t bits, size_t size)
{
    if (size == 1) {
        uint8_t v = (uint8_t)bits;
        memcpy(member, &v, 1);
    } else if (size == 2) {
        uint16_t v = (uint16_t)bits;
        memcpy(member, &v, 2);
    } else {
        memcpy(member, &bits, 4);
    }
}

/* The signed value of the low `size` bytes of `bits` (two's complement). */
static int32_t sign_extend(uint32_t bits, size_t size)
{
    uint32_t sign = (uint32_t)1 << (8 * size - 1);
    uint32_t mask = size >= 4 ? 0xFFFFFFFFu : (sign << 1) - 1u;
    bits &= mask;
    if ((bits & sign) != 0) {
        return -(int32_t)(~bits & mask) - 1;
    }
    return (int32_t)bits;
}

/* A float32, as its bits, as an integer that orders like the float: -0 and +0 are both 0, and
 * NaNs lie beyond the infinities, so outside every finite range. */
static int32_t float_key(uint32_t bits)
{
    int32_t magnitude = (int32_t)(bits & 0x7FFFFFFFu);
    return (bits & 0x80000000u) != 0 ? -magnitude : magnitude;
}

#if ILAHRS_NAMES
static bool equal_name(const char *name, size_t len, const char *known)
{
    size_t i;
    if (name == NULL) {
        return false;
    }
    for (i = 0; i < len; i++) {
        if (known[i] == '\0' || known[i] != name[i]) {
            return false;
        }
    }
    return known[len] == '\0';
}

/* Entry `index` of the `count` names of the section at `first` of ilahrs_name_offsets, NULL
 * when out of range. Every name accessor but the error kind's is this one call. */
static NOINLINE const char *name_at(unsigned index, unsigned first, unsigned count)
{
    return index < count ? ilahrs_name_names + ilahrs_name_offsets[first + index] : NULL;
}

/* The index of the `len` characters at `name` among the `count` names of the section at `first`,
 * or -1. */
static int name_index(const char *name, size_t len, unsigned first, unsigned count)
{
    unsigned i;
    for (i = 0; i < count; i++) {
        if (equal_name(name, len, ilahrs_name_names + ilahrs_name_offsets[first + i])) {
            return (int)i;
        }
    }
    return -1;
}
#endif

/* ---- Errors ---------------------------------------------------------------------------- */

const char *ilahrs_error_kind_name(ilahrs_error_kind_t kind)
{
    if (kind == ILAHRS_OK) {
        return "ok";
    }
    if ((unsigned)kind >= ILAHRS_ERROR_KIND_COUNT) {
        return "unknown";
    }
    return ERROR_NAME(ilahrs_error_offsets[(unsigned)kind - 1u]);
}

/* ---- Frame ----------------------------------------------------------------------------- */

/* The sum of the bytes, modulo 2^32 (so modulo the checksum's width too). Compiled for speed,
 * eight bytes at a time: the even and the odd bytes of each word add up in four 16-bit lanes, which
 * 128 words (2 * 128 * 255 < 2^16: 127 whole words and a last partial one) cannot overflow; a sum of
 * bytes does not depend on their order, so neither does it on the host's byte order. */
static uint32_t sum_bytes(const uint8_t *data, size_t len)
{
    uint32_t sum = 0;
    size_t i = 0;
#if FAST
    const uint64_t lanes = 0x00FF00FF00FF00FFull;
    const uint16_t one = 1;
    uint8_t little; /* the host's byte order: 1 if little-endian */
    memcpy(&little, &one, 1);
    if (len >= 8) {
        /* Each word is compared with the offset of the last whole word (not counted ahead), so
         * that every read is bounded by the loop's own condition. */
        const size_t last = len - 8;
        while (i <= last) {
            uint64_t acc = 0;
            uint64_t w;
            unsigned words;
            for (words = 0; words < 127u && i <= last; words++, i += 8) {
                memcpy(&w, data + i, 8);
                acc += (w & lanes) + ((w >> 8) & lanes);
            }
            if (i > last) {
                if (i != len) {
                    /* The last 8 bytes, of which the first i - last (1 to 7) are summed already;
                     * `& 7` changes no value, and bounds the shift for an analysis that does not
                     * keep i - last <= 8. */
                    unsigned drop = 8u * ((unsigned)(i - last) & 7u);
                    memcpy(&w, data + last, 8);
                    w = little ? w >> drop : w << drop;
                    acc += (w & lanes) + ((w >> 8) & lanes);
                }
                i = len;
            }
            acc = (acc & 0x0000FFFF0000FFFFull) + ((acc >> 16) & 0x0000FFFF0000FFFFull);
            sum += (uint32_t)acc + (uint32_t)(acc >> 32);
        }
    }
#else
    /* (The loop invariant is WP's, on this path: prove/wp_frame.c.) */
    /*@ loop invariant i <= len;
        loop assigns i, sum; */
#endif
    for (; i < len; i++) {
        sum += data[i];
    }
    return sum;
}

checksum_t ilahrs_checksum(const uint8_t *data, size_t len)
{
    return (checksum_t)sum_bytes(data, len);
}

/* frame_check()'s answer to an error: minus its kind. Compiled for size, each error's path only sets
 * the kind, and one negation serves them all. */
#if FAST
#define FRAME_ERROR(k) return -(k)
#else
#define FRAME_ERROR(k) \
    do {               \
        kind = (k);    \
        goto fail;     \
    } while (0)
#endif

/*
 * The frame at the start of p[0..n): its size, with *frame filled; or minus the kind of the first
 * error (ilahrs_frame_parse() finds its offset). The checks of ilahrs_frame_parse(), in its order:
 * a frame cut short is ILAHRS_ERR_TRUNCATED, which the stream decoder reads as "wait for more".
 */
static int frame_check(const uint8_t *p, size_t n, ilahrs_frame_t *frame)
{
    size_t at;
    size_t size;
#if !FAST
    int kind; /* of the error */
#endif
    /*@ loop invariant at <= ILAHRS_FRAME_HEADER_SIZE && (at <= n || n == 0);
        loop assigns at; */
    for (at = 0; at < ILAHRS_FRAME_HEADER_SIZE && at < n; at++) {
        if (p[at] != ilahrs_frame_header[at]) {
            FRAME_ERROR(ILAHRS_ERR_BAD_HEADER);
        }
    }
    if (n < ILAHRS_FRAME_PAYLOAD_OFFSET) {
        FRAME_ERROR(ILAHRS_ERR_TRUNCATED);
    }
    if (!MESSAGE_TYPE_VALID(LE(p + ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, ILAHRS_FRAME_MESSAGE_TYPE_SIZE))) {
        FRAME_ERROR(ILAHRS_ERR_BAD_MESSAGE_TYPE);
    }
    size = LE(p + ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, ILAHRS_FRAME_MESSAGE_LENGTH_SIZE);
    //@ assert size + ILAHRS_FRAME_HEADER_SIZE == ilahrs_frame_size(p);
    if (size < ILAHRS_FRAME_MIN_LENGTH || size > ILAHRS_FRAME_MAX_LENGTH) {
        FRAME_ERROR(ILAHRS_ERR_BAD_LENGTH);
    }
    size += ILAHRS_FRAME_HEADER_SIZE;
    if (n < size) {
        FRAME_ERROR(ILAHRS_ERR_TRUNCATED);
    }
    at = size - ILAHRS_FRAME_CHECKSUM_SIZE;
    if ((checksum_t)sum_bytes(p + ILAHRS_FRAME_HEADER_SIZE, at - ILAHRS_FRAME_HEADER_SIZE)
        != LE(p + at, ILAHRS_FRAME_CHECKSUM_SIZE)) {
        FRAME_ERROR(ILAHRS_ERR_BAD_CHECKSUM);
    }
    frame_get_fields(frame, p);
    frame->payload = p + ILAHRS_FRAME_PAYLOAD_OFFSET;
    frame->payload_size = at - ILAHRS_FRAME_PAYLOAD_OFFSET;
    return (int)size;
#if !FAST
fail:
    OPAQUE(kind);
    return -kind;
#endif
}

bool ilahrs_frame_parse(const uint8_t *data, size_t len, ilahrs_frame_t *frame, ilahrs_error_t *err)
{
    int size = frame_check(data, len, frame);
    size_t at = len; /* truncated */
    const char *part = NULL;
    if (size == -ILAHRS_ERR_BAD_HEADER) {
        /* The first header byte that differs: the last one if every one before it matches. */
        for (at = 0; at + 1u < ILAHRS_FRAME_HEADER_SIZE && data[at] == ilahrs_frame_header[at]; at++) {
        }
        part = NAME_FRAME_HEADER;
    } else if (size == -ILAHRS_ERR_BAD_MESSAGE_TYPE) {
        at = ILAHRS_FRAME_MESSAGE_TYPE_OFFSET;
        part = NAME_FRAME_MESSAGE_TYPE;
    } else if (size == -ILAHRS_ERR_BAD_LENGTH) {
        at = ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET;
        part = NAME_FRAME_MESSAGE_LENGTH;
    } else if (size == -ILAHRS_ERR_BAD_CHECKSUM) {
        at = ILAHRS_FRAME_HEADER_SIZE - ILAHRS_FRAME_CHECKSUM_SIZE
             + LE(data + ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, ILAHRS_FRAME_MESSAGE_LENGTH_SIZE);
        part = NAME_FRAME_CHECKSUM;
    }
    if (size < 0) {
        return fail(err, (ilahrs_error_kind_t)-size, at, part);
    }
    return len == (size_t)size || fail(err, ILAHRS_ERR_TRAILING_DATA, (size_t)size, NULL);
}

/* Strict decoding (E42): the valid frame at p is one the AHRS cannot have sent, its reserved byte
 * changed. */
#ifdef ILAHRS_STRICT_RESERVED
#define STRICT_REFUSES(p)                                                                                     \
    (LE((p) + ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, ILAHRS_FRAME_MESSAGE_TYPE_SIZE) == ILAHRS_STRICT_MESSAGE_TYPE \
     && LE((p) + ILAHRS_FRAME_RESERVED_OFFSET, ILAHRS_FRAME_RESERVED_SIZE) != ILAHRS_STRICT_RESERVED)
#else
#define STRICT_REFUSES(p) false
#endif

bool ilahrs_frame_parse_strict(const uint8_t *data, size_t len, ilahrs_frame_t *frame, ilahrs_error_t *err)
{
    if (!ilahrs_frame_parse(data, len, frame, err)) {
        return false;
    }
#ifdef ILAHRS_STRICT_RESERVED
    if (STRICT_REFUSES(data)) {
        return fail(err, ILAHRS_ERR_BAD_RESERVED, ILAHRS_FRAME_RESERVED_OFFSET, NAME_FRAME_RESERVED);
    }
#endif
    return true;
}

/* Write header, fields, length and checksum around a payload already at out + PAYLOAD_OFFSET. */
static size_t frame_finish(uint8_t *out, const ilahrs_frame_t *frame, size_t payload_size)
{
    size_t at = ILAHRS_FRAME_PAYLOAD_OFFSET + payload_size;
    copy_forward(out, ilahrs_frame_header, ILAHRS_FRAME_HEADER_SIZE);
    frame_put_fields(out, frame);
    put_le(out + ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, (uint32_t)(payload_size + ILAHRS_FRAME_LENGTH_BIAS),
           ILAHRS_FRAME_MESSAGE_LENGTH_SIZE);
    put_le(out + at, ilahrs_checksum(out + ILAHRS_FRAME_HEADER_SIZE, at - ILAHRS_FRAME_HEADER_SIZE),
           ILAHRS_FRAME_CHECKSUM_SIZE);
    return at + ILAHRS_FRAME_CHECKSUM_SIZE;
}

/* A frame of message type data around a payload already at out + PAYLOAD_OFFSET. */
static size_t data_frame_finish(uint8_t *out, size_t payload_size)
{
    ilahrs_frame_t frame;
    zero_bytes(&frame, sizeof frame);
    frame.message_type = ILAHRS_MESSAGE_TYPE_DATA;
    return frame_finish(out, &frame, payload_size);
}

size_t ilahrs_frame_build(const ilahrs_frame_t *frame, uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    if (!MESSAGE_TYPE_VALID(frame->message_type)) {
        return fail_size(err, ILAHRS_ERR_BAD_MESSAGE_TYPE, ILAHRS_NO_OFFSET, NAME_FRAME_MESSAGE_TYPE);
    }
    if (frame->payload_size < ILAHRS_FRAME_MIN_PAYLOAD || frame->payload_size > ILAHRS_FRAME_MAX_PAYLOAD
        || frame->payload == NULL) {
        return fail_size(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_NO_OFFSET, NAME_FRAME_PAYLOAD);
    }
    if (out == NULL || cap < frame->payload_size + ILAHRS_FRAME_OVERHEAD) {
        return fail_size(err, ILAHRS_ERR_BUFFER_TOO_SMALL, ILAHRS_NO_OFFSET, NULL);
    }
    move_bytes(out + ILAHRS_FRAME_PAYLOAD_OFFSET, frame->payload, frame->payload_size);
    return frame_finish(out, frame, frame->payload_size);
}

/* ---- Commands -------------------------------------------------------------------------- */

#if ILAHRS_NAMES
const char *ilahrs_mode_name(ilahrs_mode_t mode)
{
    return name_at((unsigned)mode, NAMES_MODE, ILAHRS_MODE_COUNT);
}

const char *ilahrs_command_name(ilahrs_command_t command)
{
    return name_at((unsigned)command, NAMES_COMMAND, ILAHRS_COMMAND_COUNT);
}

bool ilahrs_command_by_name(const char *name, size_t len, ilahrs_command_t *command, ilahrs_error_t *err)
{
    int i = name_index(name, len, NAMES_COMMAND, ILAHRS_COMMAND_COUNT);
    if (i < 0) {
        return fail(err, ILAHRS_ERR_UNKNOWN_COMMAND, ILAHRS_NO_OFFSET, NULL);
    }
    *command = (ilahrs_command_t)i;
    return true;
}
#endif

uint8_t ilahrs_command_code(ilahrs_command_t command)
{
    return (unsigned)command < ILAHRS_COMMAND_COUNT ? ilahrs_command_codes[command] : 0;
}

uint8_t ilahrs_command_valid_in(ilahrs_command_t command)
{
    return (unsigned)command < ILAHRS_COMMAND_COUNT ? ilahrs_command_modes[command] : 0;
}

ilahrs_response_t ilahrs_command_response(ilahrs_command_t command)
{
    return (unsigned)command < ILAHRS_COMMAND_COUNT ? (ilahrs_response_t)ilahrs_command_responses[command]
                                                    : ILAHRS_RESPONSE_NONE;
}

ilahrs_payload_t ilahrs_command_parameter_block(ilahrs_command_t command)
{
    return (unsigned)command < ILAHRS_COMMAND_COUNT ? (ilahrs_payload_t)ilahrs_command_blocks[command]
                                                    : ILAHRS_PAYLOAD_NONE;
}

ilahrs_payload_t ilahrs_command_response_payload(ilahrs_command_t command, size_t index)
{
    if ((unsigned)command >= ILAHRS_COMMAND_COUNT || index >= ILAHRS_RESPONSE_PAYLOADS_MAX) {
        return ILAHRS_PAYLOAD_NONE;
    }
    return (ilahrs_payload_t)ilahrs_command_response_payloads[command][index];
}

size_t ilahrs_command_build(ilahrs_command_t command, uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    ilahrs_frame_t frame;
    if ((unsigned)command >= ILAHRS_COMMAND_COUNT) {
        return fail_size(err, ILAHRS_ERR_UNKNOWN_COMMAND, ILAHRS_NO_OFFSET, NULL);
    }
    if (out == NULL || cap < 1u + ILAHRS_FRAME_OVERHEAD) {
        return fail_size(err, ILAHRS_ERR_BUFFER_TOO_SMALL, ILAHRS_NO_OFFSET, NULL);
    }
    zero_bytes(&frame, sizeof frame);
    frame.message_type = ILAHRS_MESSAGE_TYPE_COMMAND;
    out[ILAHRS_FRAME_PAYLOAD_OFFSET] = ilahrs_command_codes[command];
    return frame_finish(out, &frame, 1);
}

bool ilahrs_command_decode(const uint8_t *data, size_t len, ilahrs_command_match_t *match, ilahrs_error_t *err)
{
    ilahrs_frame_t frame;
    unsigned i;
    uint8_t code;
    if (!ilahrs_frame_parse(data, len, &frame, err)) {
        return false;
    }
    if (frame.message_type != ILAHRS_MESSAGE_TYPE_COMMAND) {
        return fail(err, ILAHRS_ERR_BAD_MESSAGE_TYPE, ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, NAME_FRAME_MESSAGE_TYPE);
    }
    if (frame.payload_size != 1) {
        return fail(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, NAME_FRAME_MESSAGE_LENGTH);
    }
    code = frame.payload[0];
    match->code = code;
    match->count = 0;
    for (i = 0; i < ILAHRS_COMMAND_COUNT; i++) {
        uint8_t id = ilahrs_commands_by_code[i];
        if (ilahrs_command_codes[id] == code && match->count < ILAHRS_COMMANDS_PER_CODE_MAX) {
            match->commands[match->count] = (ilahrs_command_t)id;
            match->count++;
        }
    }
    if (match->count == 0) {
        return fail(err, ILAHRS_ERR_UNKNOWN_COMMAND, ILAHRS_FRAME_PAYLOAD_OFFSET, NULL);
    }
    return true;
}

/* ---- Variants -------------------------------------------------------------------------- */

int32_t ilahrs_variant_parameter(ilahrs_variant_t variant, ilahrs_variant_parameter_t parameter)
{
    if ((unsigned)variant >= ILAHRS_VARIANT_COUNT || (unsigned)parameter >= VARIANT_PARAMETER_COUNT) {
        return 0;
    }
    return ilahrs_variant_values[variant][parameter];
}

const char *ilahrs_variant_part_number(ilahrs_variant_t variant)
{
    return (unsigned)variant < ILAHRS_VARIANT_COUNT ? ilahrs_part_names + ilahrs_part_offsets[variant] : NULL;
}

#if ILAHRS_NAMES
const char *ilahrs_variant_name(ilahrs_variant_t variant)
{
    return name_at((unsigned)variant, NAMES_VARIANT, ILAHRS_VARIANT_COUNT);
}

bool ilahrs_variant_by_name(const char *name, size_t len, ilahrs_variant_t *variant)
{
    int i = name_index(name, len, NAMES_VARIANT, ILAHRS_VARIANT_COUNT);
    if (i < 0) {
        return false;
    }
    *variant = (ilahrs_variant_t)i;
    return true;
}
#endif

/* ---- Payloads -------------------------------------------------------------------------- */

#if ILAHRS_NAMES
const char *ilahrs_payload_name(ilahrs_payload_t payload)
{
    return name_at((unsigned)payload, NAMES_PAYLOAD, ILAHRS_PAYLOAD_COUNT); /* ILAHRS_PAYLOAD_NONE: out of range */
}

bool ilahrs_payload_by_name(const char *name, size_t len, ilahrs_payload_t *payload)
{
    int i = name_index(name, len, NAMES_PAYLOAD, ILAHRS_PAYLOAD_COUNT);
    if (i < 0) {
        return false;
    }
    *payload = (ilahrs_payload_t)i;
    return true;
}

const char *ilahrs_field_name(const ilahrs_field_info_t *field)
{
    return FIELD_NAME(FIELD_NAME_AT(field));
}
#endif

size_t ilahrs_payload_size(ilahrs_payload_t payload)
{
    return payload >= 0 && payload < ILAHRS_PAYLOAD_COUNT ? ilahrs_payloads[payload].size : 0;
}

size_t ilahrs_payload_struct_size(ilahrs_payload_t payload)
{
    return payload >= 0 && payload < ILAHRS_PAYLOAD_COUNT ? ilahrs_payloads[payload].struct_size : 0;
}

size_t ilahrs_payload_field_count(ilahrs_payload_t payload)
{
    return payload >= 0 && payload < ILAHRS_PAYLOAD_COUNT ? ilahrs_payloads[payload].field_count : 0;
}

const ilahrs_field_info_t *ilahrs_payload_field(ilahrs_payload_t payload, size_t index)
{
    if (payload < 0 || payload >= ILAHRS_PAYLOAD_COUNT || index >= ilahrs_payloads[payload].field_count) {
        return NULL;
    }
    return &ilahrs_fields[ilahrs_payloads[payload].first_field + index];
}

size_t ilahrs_field_offset(const ilahrs_field_info_t *field)
{
    return FIELD_OFFSET(field);
}

size_t ilahrs_field_size(const ilahrs_field_info_t *field)
{
    return FIELD_SIZE(field);
}

ilahrs_kind_t ilahrs_field_kind(const ilahrs_field_info_t *field)
{
    return (ilahrs_kind_t)FIELD_KIND(field);
}

void *ilahrs_field_member(const ilahrs_field_info_t *field, void *payload)
{
    return (uint8_t *)payload + FIELD_MEMBER(field);
}

const void *ilahrs_field_member_const(const ilahrs_field_info_t *field, const void *payload)
{
    return (const uint8_t *)payload + FIELD_MEMBER(field);
}

static bool is_integer(const ilahrs_field_info_t *field)
{
    return FIELD_KIND(field) == ILAHRS_KIND_UNSIGNED || FIELD_KIND(field) == ILAHRS_KIND_SIGNED;
}

static float float_of_bits(uint32_t bits)
{
    float value;
    memcpy(&value, &bits, sizeof value);
    return value;
}

int64_t ilahrs_field_get_int(const ilahrs_field_info_t *field, const void *payload)
{
    uint32_t bits;
    if (!is_integer(field)) {
        return 0;
    }
    bits = load_bits(ilahrs_field_member_const(field, payload), FIELD_NUMBER_SIZE(field));
    return FIELD_KIND(field) == ILAHRS_KIND_SIGNED ? (int64_t)sign_extend(bits, FIELD_NUMBER_SIZE(field))
                                                   : (int64_t)bits;
}

float ilahrs_field_get_float(const ilahrs_field_info_t *field, const void *payload)
{
    if (FIELD_KIND(field) != ILAHRS_KIND_FLOAT) {
        return 0.0f;
    }
    return float_of_bits(load_bits(ilahrs_field_member_const(field, payload), 4));
}

bool ilahrs_field_set_int(const ilahrs_field_info_t *field, void *payload, int64_t value, ilahrs_error_t *err)
{
    /* The value fits the field if its low bytes, read back as the field's type, give it again. */
    uint32_t bits = (uint32_t)(uint64_t)value;
    unsigned size = FIELD_NUMBER_SIZE(field);
    if (is_integer(field)
        && value
               == (FIELD_KIND(field) == ILAHRS_KIND_SIGNED ? (int64_t)sign_extend(bits, size)
                                                           : (int64_t)(bits & (0xFFFFFFFFu >> (32 - 8 * size))))) {
        store_bits(ilahrs_field_member(field, payload), bits, size);
        return true;
    }
    return fail(err, ILAHRS_ERR_OUT_OF_RANGE, FIELD_OFFSET(field), FIELD_NAME(FIELD_NAME_AT(field)));
}

bool ilahrs_field_set_float(const ilahrs_field_info_t *field, void *payload, float value, ilahrs_error_t *err)
{
    if (FIELD_KIND(field) != ILAHRS_KIND_FLOAT) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, FIELD_OFFSET(field), FIELD_NAME(FIELD_NAME_AT(field)));
    }
    memcpy(ilahrs_field_member(field, payload), &value, sizeof value);
    return true;
}

/* The builder check of a stored value: integers against integer bounds, floats (by key) against
 * the float32 roundings of their bounds, then the encoding's rule. */
static bool stored_ok(const ilahrs_field_info_t *f, uint32_t bits)
{
    if (FIELD_KIND(f) == ILAHRS_KIND_FLOAT) {
        int32_t key = float_key(bits);
        if (key < ilahrs_float_bounds[FIELD_BOUNDS(f)][0] || key > ilahrs_float_bounds[FIELD_BOUNDS(f)][1]) {
            return false;
        }
#ifdef ILAHRS_DECLINATION_MIN
        if (FIELD_ENCODING(f) == ENCODING_DECLINATION) {
            return (key >= DECLINATION_MIN_KEY && key <= DECLINATION_MAX_KEY) || key > DECLINATION_COMPUTE_ABOVE_KEY;
        }
#endif
        return true;
    }
    if (FIELD_BOUNDS(f) != 0) {
        int32_t value = FIELD_KIND(f) == ILAHRS_KIND_SIGNED ? sign_extend(bits, FIELD_NUMBER_SIZE(f)) : (int32_t)bits;
        if (FIELD_KIND(f) == ILAHRS_KIND_UNSIGNED && bits > 0x7FFFFFFFu) {
            return false; /* above every int32 bound */
        }
        return value >= ilahrs_int_bounds[FIELD_BOUNDS(f)][0] && value <= ilahrs_int_bounds[FIELD_BOUNDS(f)][1];
    }
    return true;
}

bool ilahrs_field_scale(const ilahrs_field_info_t *field, ilahrs_variant_t variant, int32_t *multiplier,
                        int32_t *divisor)
{
    int32_t d;
    if (FIELD_IS_ARRAY(field) || FIELD_SCALE(field) == 0) {
        return false;
    }
    d = ilahrs_scales[FIELD_SCALE(field)].divisor;
    if (ilahrs_scales[FIELD_SCALE(field)].parameter != NO_PARAMETER) {
        d = ilahrs_variant_parameter(variant, (ilahrs_variant_parameter_t)ilahrs_scales[FIELD_SCALE(field)].parameter);
    }
    if (d == 0) {
        return false;
    }
    *multiplier = ilahrs_scales[FIELD_SCALE(field)].multiplier;
    *divisor = d;
    return true;
}

void ilahrs_payload_defaults(ilahrs_payload_t payload, void *out)
{
    unsigned i;
    unsigned first;
    if (payload < 0 || payload >= ILAHRS_PAYLOAD_COUNT) {
        return;
    }
    zero_bytes(out, ilahrs_payloads[payload].struct_size);
    first = ilahrs_payloads[payload].first_field;
    for (i = 0; i < DEFAULT_COUNT; i++) {
        const ilahrs_field_info_t *f = &ilahrs_fields[ilahrs_defaults[i].field];
        if (ilahrs_defaults[i].field < first
            || ilahrs_defaults[i].field >= first + ilahrs_payloads[payload].field_count) {
            continue;
        }
        if (FIELD_KIND(f) == ILAHRS_KIND_CHAR) {
            const char *text = TEXT(ilahrs_defaults[i].text);
            char *member = (char *)ilahrs_field_member(f, out);
            size_t n;
            for (n = 0; n < FIELD_ARRAY_SIZE(f) && text[n] != '\0'; n++) {
                member[n] = text[n];
            }
        } else {
            store_bits(ilahrs_field_member(f, out), ilahrs_defaults[i].bits, FIELD_NUMBER_SIZE(f));
        }
    }
}

bool ilahrs_payload_parse(ilahrs_payload_t payload, const uint8_t *data, size_t len, void *out, ilahrs_error_t *err)
{
    size_t size;
    const ilahrs_field_info_t *f;
    const ilahrs_field_info_t *end;
    if (payload < 0 || payload >= ILAHRS_PAYLOAD_COUNT) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NULL);
    }
    size = ilahrs_payloads[payload].size;
    if (len < size) {
        return fail(err, ILAHRS_ERR_TRUNCATED, len, NULL);
    }
    if (len > size) {
        return fail(err, ILAHRS_ERR_TRAILING_DATA, size, NULL);
    }
    zero_bytes(out, ilahrs_payloads[payload].struct_size);
    f = &ilahrs_fields[ilahrs_payloads[payload].first_field];
    end = f + ilahrs_payloads[payload].field_count;
    for (; f < end; f++) {
        uint8_t *member = (uint8_t *)out + FIELD_MEMBER(f);
        const uint8_t *wire = data + FIELD_OFFSET(f);
        if (FIELD_IS_ARRAY(f)) {
            copy_forward(member, wire, FIELD_ARRAY_SIZE(f));
        } else {
            store_bits(member, get_le(wire, FIELD_NUMBER_SIZE(f)), FIELD_NUMBER_SIZE(f));
        }
    }
    return true;
}

size_t ilahrs_payload_build(ilahrs_payload_t payload, const void *in, uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    size_t size;
    const ilahrs_field_info_t *f;
    const ilahrs_field_info_t *end;
    if (payload < 0 || payload >= ILAHRS_PAYLOAD_COUNT) {
        return fail_size(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NULL);
    }
    size = ilahrs_payloads[payload].size;
    if (out == NULL || cap < size) {
        return fail_size(err, ILAHRS_ERR_BUFFER_TOO_SMALL, ILAHRS_NO_OFFSET, NULL);
    }
    f = &ilahrs_fields[ilahrs_payloads[payload].first_field];
    end = f + ilahrs_payloads[payload].field_count;
    for (; f < end; f++) {
        const uint8_t *member = (const uint8_t *)in + FIELD_MEMBER(f);
        uint8_t *wire = out + FIELD_OFFSET(f);
        if (FIELD_IS_ARRAY(f)) {
            copy_forward(wire, member, FIELD_ARRAY_SIZE(f));
        } else {
            uint32_t bits = load_bits(member, FIELD_NUMBER_SIZE(f));
            if (!stored_ok(f, bits)) {
                return fail_size(err, ILAHRS_ERR_OUT_OF_RANGE, FIELD_OFFSET(f), FIELD_NAME(FIELD_NAME_AT(f)));
            }
            put_le(wire, bits, FIELD_NUMBER_SIZE(f));
        }
    }
    return size;
}

size_t ilahrs_payload_build_frame(ilahrs_payload_t payload, const void *in, uint8_t *out, size_t cap,
                                  ilahrs_error_t *err)
{
    size_t size;
    if (out == NULL || cap < ILAHRS_FRAME_PAYLOAD_OFFSET) {
        return fail_size(err, ILAHRS_ERR_BUFFER_TOO_SMALL, ILAHRS_NO_OFFSET, NULL);
    }
    size = ilahrs_payload_build(payload, in, out + ILAHRS_FRAME_PAYLOAD_OFFSET, cap - ILAHRS_FRAME_PAYLOAD_OFFSET, err);
    if (size == 0) {
        return 0;
    }
    if (cap < size + ILAHRS_FRAME_OVERHEAD) {
        return fail_size(err, ILAHRS_ERR_BUFFER_TOO_SMALL, ILAHRS_NO_OFFSET, NULL);
    }
    return data_frame_finish(out, size);
}

/* The acknowledgement is a data frame of the acknowledgement table, whose one field is the
 * checksum of the message acknowledged (E12). */
size_t ilahrs_ack_build(const uint8_t *message, size_t len, uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    const ilahrs_field_info_t *f = &ilahrs_fields[ilahrs_payloads[ACK_PAYLOAD].first_field];
    ilahrs_frame_t frame;
    ack_payload_t payload;
    if (!ilahrs_frame_parse(message, len, &frame, err)) {
        return 0;
    }
    zero_bytes(&payload, sizeof payload);
    store_bits(ilahrs_field_member(f, &payload), get_le(frame.payload + frame.payload_size, ILAHRS_FRAME_CHECKSUM_SIZE),
               FIELD_NUMBER_SIZE(f));
    return ilahrs_payload_build_frame(ACK_PAYLOAD, &payload, out, cap, err);
}

/* ---- Unit Status Word ------------------------------------------------------------------ */

#if ILAHRS_NAMES && defined(ILAHRS_USW_FLAGS_MASK)
const char *ilahrs_usw_flag_name(unsigned bit)
{
    const char *name = name_at(bit, NAMES_FLAG, NAMES_FLAG_COUNT);
    return name != NULL && name[0] != '\0' ? name : NULL; /* empty: a bit without a flag */
}
#endif
