/* Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
 * Do not edit: change the spec or the generator and run `make generate`.
 * SPDX-License-Identifier: MIT OR Apache-2.0
 */
/**
 * @file ilahrs.h
 * @brief Inertial Labs AHRS Interface Control Document, revision 1.7: frames, commands, payload
 * tables, the Unit Status Word, $PAHR sentences and a stream decoder, in C99.
 *
 * Spec ilahrs 1.0.0; every protocol fact below comes from spec/ilahrs.yaml
 * (errata E1-E43 there explain each choice where the ICD is unclear).
 */
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

#ifndef ILAHRS_H
#define ILAHRS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Version of the spec this file was generated from. */
#define ILAHRS_SPEC_VERSION "1.0.0"
/** SHA-256 of the spec this file was generated from. */
#define ILAHRS_SPEC_HASH "509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d"
/** What a device and a host must agree on (codes, payload layouts, frame, state-machine answers; not
 * docs or names), hashed to 64 bits: two builds with equal fingerprints speak the same bytes. */
#define ILAHRS_WIRE_FINGERPRINT UINT64_C(0x0d3ab4a6e6f066a7)
/** Revision of the ICD the spec describes. */
#define ILAHRS_ICD_REVISION "1.7"

/** 1 (the default): names and by-name lookups; 0: none (see "Build switches" above). */
#ifndef ILAHRS_NAMES
#define ILAHRS_NAMES 1
#endif

/*
 * Contents, a topic at a time (its types and constants, then its functions): errors, the
 * frame, device variants, payload tables, commands, named values and encodings, the Unit
 * Status Word, the date, $PAHR sentences, the stream decoder, the device state machine.
 */

/* ======================================================================================== */
/* Errors                                                                                   */
/* ======================================================================================== */

/** What went wrong. The names (ilahrs_error_kind_name()) are the spec's `errors` list. */
typedef enum ilahrs_error_kind {
    ILAHRS_OK = 0, /**< No error. */
    /** The input ends before the frame, payload or sentence does. */
    ILAHRS_ERR_TRUNCATED = 1,
    /** The frame does not start with AA 55, or a sentence does not start with the $PAHR
     *  identifier. */
    ILAHRS_ERR_BAD_HEADER = 2,
    /** The message type byte is neither 0 (command) nor 1 (data) (Table 6.2). */
    ILAHRS_ERR_BAD_MESSAGE_TYPE = 3,
    /** The message length is outside the bounds the spec accepts, or a payload is not the size
     *  its table defines. */
    ILAHRS_ERR_BAD_LENGTH = 4,
    /** The transmitted checksum does not match the one computed over the received bytes. */
    ILAHRS_ERR_BAD_CHECKSUM = 5,
    /** Bytes follow the end of a complete frame, payload or sentence where none are allowed. */
    ILAHRS_ERR_TRAILING_DATA = 6,
    /** A command code or command name that Table C.1 does not define. */
    ILAHRS_ERR_UNKNOWN_COMMAND = 7,
    /** A value outside the range the spec allows for its field (refused by builders, never
     *  wrapped or truncated). */
    ILAHRS_ERR_OUT_OF_RANGE = 8,
    /** Text that does not follow the sentence grammar (missing or extra fields, a bad number). */
    ILAHRS_ERR_MALFORMED = 9,
    /** The caller's output buffer cannot hold the message being built. */
    ILAHRS_ERR_BUFFER_TOO_SMALL = 10,
    /** The peer sent a message that the protocol state does not allow (host session and device
     *  model). */
    ILAHRS_ERR_UNEXPECTED_MESSAGE = 11,
    /** An answer the protocol requires did not arrive in time (host session). */
    ILAHRS_ERR_TIMEOUT = 12,
    /** Strict decoding only - a data frame's reserved byte is not the value the AHRS sends
     *  (E42). */
    ILAHRS_ERR_BAD_RESERVED = 13,
} ilahrs_error_kind_t;

/** Number of error kinds, ILAHRS_OK included. */
#define ILAHRS_ERROR_KIND_COUNT 14

/** `offset` of an error that refers to no particular byte. */
#define ILAHRS_NO_OFFSET ((size_t)-1)

/** A refused input: what, where and which field. */
typedef struct ilahrs_error {
    ilahrs_error_kind_t kind; /**< What went wrong. */
    size_t offset;            /**< Byte offset into the input, or ILAHRS_NO_OFFSET. */
    const char *field;        /**< Field at fault (spec name, e.g. "heading"), or NULL (always
                                   NULL when ILAHRS_NAMES is 0). */
} ilahrs_error_t;

/**
 * The spec name of an error kind ("truncated", "bad_checksum", ...), "ok" for ILAHRS_OK,
 * "unknown" for a value outside the enum. Never NULL.
 */
const char *ilahrs_error_kind_name(ilahrs_error_kind_t kind);

/* ======================================================================================== */
/* Frame (Table 6.2, Table 6.3)                                                             */
/* ======================================================================================== */

/** Size of the header every frame starts with. */
#define ILAHRS_FRAME_HEADER_SIZE 2
#define ILAHRS_FRAME_HEADER_0 0xAAu                   /**< Header byte 0. */
#define ILAHRS_FRAME_HEADER_1 0x55u                   /**< Header byte 1. */
#define ILAHRS_FRAME_MESSAGE_TYPE_OFFSET 2            /**< Offset of `message_type` in a frame (Message type). */
#define ILAHRS_FRAME_MESSAGE_TYPE_SIZE 1              /**< Size of `message_type`. */
#define ILAHRS_FRAME_MESSAGE_TYPE_NAME "message_type" /**< Name of `message_type` in error reports. */
#define ILAHRS_FRAME_RESERVED_OFFSET 3                /**< Offset of `reserved` in a frame (Reserved). */
#define ILAHRS_FRAME_RESERVED_SIZE 1                  /**< Size of `reserved`. */
#define ILAHRS_FRAME_RESERVED_NAME "reserved"         /**< Name of `reserved` in error reports. */
#define ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET 4          /**< Offset of `message_length` in a frame (Message length). */
#define ILAHRS_FRAME_MESSAGE_LENGTH_SIZE 2            /**< Size of `message_length`. */
#define ILAHRS_FRAME_MESSAGE_LENGTH_NAME "message_length" /**< Name of `message_length` in error reports. */
#define ILAHRS_FRAME_PAYLOAD_OFFSET 6                     /**< Offset of the payload in a frame. */
#define ILAHRS_FRAME_CHECKSUM_SIZE 2                      /**< Size of the checksum that ends a frame. */
#define ILAHRS_FRAME_OVERHEAD 8                           /**< Bytes in a frame besides the payload. */
#define ILAHRS_FRAME_LENGTH_BIAS 6  /**< message_length = payload size + ILAHRS_FRAME_LENGTH_BIAS. */
#define ILAHRS_FRAME_MIN_LENGTH 7   /**< Smallest message length a decoder accepts (E17). */
#define ILAHRS_FRAME_MAX_LENGTH 58  /**< Largest message length a decoder accepts (E17). */
#define ILAHRS_FRAME_MIN_PAYLOAD 1  /**< Smallest payload a frame carries. */
#define ILAHRS_FRAME_MAX_PAYLOAD 52 /**< Largest payload a frame carries. */
#define ILAHRS_FRAME_MIN_SIZE 9     /**< Size of the shortest frame. */
#define ILAHRS_FRAME_MAX_SIZE 60    /**< Size of the longest frame: a buffer of this size holds any frame. */
#define ILAHRS_MAX_MESSAGE_SIZE 82  /**< The longest message on the wire, frame or sentence. */

/** The message type byte (Table 6.2, Table 6.3). */
typedef enum ilahrs_message_type {
    /** A command from the host (one-byte payload holding the command code). */
    ILAHRS_MESSAGE_TYPE_COMMAND = 0,
    /** Data: every AHRS output, and the parameter blocks the host sends (E5). */
    ILAHRS_MESSAGE_TYPE_DATA = 1,
} ilahrs_message_type_t;

/** Strict decoding (E42): a frame of this message type whose reserved byte is not
 * ILAHRS_STRICT_RESERVED is refused. */
#define ILAHRS_STRICT_MESSAGE_TYPE ILAHRS_MESSAGE_TYPE_DATA
/** The reserved byte the AHRS sends in a frame of type ILAHRS_STRICT_MESSAGE_TYPE. */
#define ILAHRS_STRICT_RESERVED 0u

/**
 * A frame: the fields between header and payload, and the payload. The message length and
 * the checksum are not stored: ilahrs_frame_parse() checks them, ilahrs_frame_build() fills
 * them in.
 */
typedef struct ilahrs_frame {
    /** 0 for commands, 1 for data. Every AHRS output is data (Table 6.2). */
    uint8_t message_type;
    /** Not defined by rev 1.7. Decoders accept any value and expose it; builders write 0 unless
     *  told otherwise (E6). A strict decoder refuses a data frame whose value is not the one the
     *  AHRS sends (`strict`, E42). */
    uint8_t reserved;
    /** The payload. After ilahrs_frame_parse() it points into the parsed bytes. */
    const uint8_t *payload;
    /** Number of payload bytes. */
    size_t payload_size;
} ilahrs_frame_t;

/**
 * The frame checksum of `len` bytes at `data`: their sum modulo 2^16 (E28). A frame's
 * checksum covers the message type through the last payload byte. `data` may be NULL when
 * `len` is 0.
 */
uint16_t ilahrs_checksum(const uint8_t *data, size_t len);

/**
 * Decode exactly one frame from `len` bytes at `data`.
 *
 * Checks run in this order; the first failure is the error (offsets into `data`):
 * header bytes (`truncated` / `bad_header`), at least ILAHRS_FRAME_PAYLOAD_OFFSET bytes
 * (`truncated`), message type (`bad_message_type`), message length within
 * ILAHRS_FRAME_MIN_LENGTH..ILAHRS_FRAME_MAX_LENGTH (`bad_length`), the whole frame present
 * (`truncated`), checksum (`bad_checksum`), nothing after the frame (`trailing_data`). The
 * reserved byte may have any value (E6).
 *
 * @param data   the frame bytes (may be NULL when `len` is 0)
 * @param frame  receives the frame; `frame->payload` points into `data`
 * @param err    receives the error on failure (may be NULL)
 * @return true if `data` is exactly one valid frame
 *
 * @code
 *     ilahrs_frame_t frame;
 *     ilahrs_error_t err;
 *     if (!ilahrs_frame_parse(buf, n, &frame, &err)) {
 *         printf("%s at byte %u\n", ilahrs_error_kind_name(err.kind), (unsigned)err.offset);
 *     }
 * @endcode
 */
bool ilahrs_frame_parse(const uint8_t *data, size_t len, ilahrs_frame_t *frame, ilahrs_error_t *err);

/**
 * ilahrs_frame_parse() with strict decoding (E42), one check after all of its others: a frame of
 * message type ILAHRS_STRICT_MESSAGE_TYPE (data) whose reserved byte is not ILAHRS_STRICT_RESERVED
 * (what the AHRS sends) is refused with `bad_reserved` at ILAHRS_FRAME_RESERVED_OFFSET (field
 * "reserved"). The 16-bit sum misses two bytes changed by opposite amounts; when one of them is
 * the reserved byte, this refuses the frame. Without a strict rule in the spec it is
 * ilahrs_frame_parse().
 */
bool ilahrs_frame_parse_strict(const uint8_t *data, size_t len, ilahrs_frame_t *frame, ilahrs_error_t *err);

/**
 * Encode a frame into `out`, filling in the header, the message length and the checksum.
 *
 * Refuses a message type that is not in ilahrs_message_type_t (`bad_message_type`, field
 * "message_type"), a payload outside ILAHRS_FRAME_MIN_PAYLOAD..ILAHRS_FRAME_MAX_PAYLOAD bytes
 * (`bad_length`, field "payload"), and an `out` smaller than payload_size +
 * ILAHRS_FRAME_OVERHEAD (`buffer_too_small`). `frame->payload` may point anywhere, including
 * into `out` itself (e.g. a payload already written at out + ILAHRS_FRAME_PAYLOAD_OFFSET).
 *
 * @return the frame size, or 0 on failure
 */
size_t ilahrs_frame_build(const ilahrs_frame_t *frame, uint8_t *out, size_t cap, ilahrs_error_t *err);

/* ======================================================================================== */
/* Device variants (Table 6.6 note 1) and engineering scales                                */
/* ======================================================================================== */

/** Device variants: scale factors that depend on the part number. */
typedef enum ilahrs_variant {
    /** AHRS-G300-A2-TMGA-C1-V1.1 (Table 6.6 note 1): KG = 100, KA = 10000. */
    ILAHRS_VARIANT_G300_A2_TMGA = 0,
    /** AHRS-G300-A6-TMGA-C1-V1.1 (Table 6.6 note 1): KG = 100, KA = 5000. */
    ILAHRS_VARIANT_G300_A6_TMGA = 1,
    /** AHRS s/n 11AC0001 - 11AC0009 (Table 6.6 note 1): KG = 50, KA = 10000. */
    ILAHRS_VARIANT_SN_11AC0001_0009 = 2,
    /** AHRS-G300-A2-TGA-C1-V1.1 (Table 3.1, erratum E11): KG = 100, KA = 10000. */
    ILAHRS_VARIANT_G300_A2_TGA = 3,
    /** No variant: scales that need one are unavailable. */
    ILAHRS_VARIANT_NONE = 4,
} ilahrs_variant_t;

/** Number of variants (ILAHRS_VARIANT_NONE excluded). */
#define ILAHRS_VARIANT_COUNT 4

/** Variant parameters. */
typedef enum ilahrs_variant_parameter {
    ILAHRS_PARAMETER_KG = 0, /**< Gyro scale factor of Table 6.6, LSB per deg/s. */
    ILAHRS_PARAMETER_KA = 1, /**< Accelerometer scale factor of Table 6.6, LSB per g. */
} ilahrs_variant_parameter_t;

/** The value of a variant parameter; 0 for an unknown variant or parameter. */
int32_t ilahrs_variant_parameter(ilahrs_variant_t variant, ilahrs_variant_parameter_t parameter);

#if ILAHRS_NAMES
/** The spec name of a variant ("g300_a2_tmga"); NULL if unknown. */
const char *ilahrs_variant_name(ilahrs_variant_t variant);

/** Find a variant by its spec name, `len` characters at `name`. */
bool ilahrs_variant_by_name(const char *name, size_t len, ilahrs_variant_t *variant);
#endif

/** The part number of a variant ("AHRS-G300-A2-TMGA-C1-V1.1"); NULL if unknown. */
const char *ilahrs_variant_part_number(ilahrs_variant_t variant);

/* ======================================================================================== */
/* Payload tables                                                                           */
/* ======================================================================================== */

/**
 * Every payload table. A frame does not say which table its payload follows (E7): the
 * caller knows from the command it sent or the output format it selected.
 */
typedef enum ilahrs_payload {
    ILAHRS_PAYLOAD_NONE = -1,                       /**< No payload table (e.g. a command without a parameter block). */
    ILAHRS_PAYLOAD_FULL_OUTPUT = 0,                 /**< Full Output Data (Table 6.4), 34 bytes. */
    ILAHRS_PAYLOAD_QUATERNION = 1,                  /**< Quaternion of Orientation (Table 6.5), 34 bytes. */
    ILAHRS_PAYLOAD_ORIENTATION_SENSORS = 2,         /**< Orientation + Sensor Outputs (Table 6.6), 34 bytes. */
    ILAHRS_PAYLOAD_INITIAL_ALIGNMENT = 3,           /**< Initial alignment data (Table 6.8), 50 bytes. */
    ILAHRS_PAYLOAD_AHRS_PARAMETERS_LOAD = 4,        /**< Parameters to load (Table 6.9), 50 bytes. */
    ILAHRS_PAYLOAD_AHRS_PARAMETERS_READ = 5,        /**< Parameters read (Table 6.10), 50 bytes. */
    ILAHRS_PAYLOAD_FIRMWARE_VERSION = 6,            /**< Firmware version (Table 6.11), 50 bytes. */
    ILAHRS_PAYLOAD_BIT_RESULT = 7,                  /**< Built-in test answer (Table 6.12), 4 bytes. */
    ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS = 8,      /**< Calibration parameters (Table 6.13), 22 bytes. */
    ILAHRS_PAYLOAD_CALIBRATION_RESULT = 9,          /**< Calibration result (Table 6.14), 52 bytes. */
    ILAHRS_PAYLOAD_CALIBRATION_RUN_RESULT = 10,     /**< 2D-2T calibration run result (Table 6.15), 30 bytes. */
    ILAHRS_PAYLOAD_CALIBRATION_RUN_PARAMETERS = 11, /**< Calibration run parameters (Table 6.16), 6 bytes. */
    ILAHRS_PAYLOAD_CALIBRATION_STATUS = 12,         /**< Calibration results read back (Table 6.17), 52 bytes. */
    ILAHRS_PAYLOAD_ACKNOWLEDGEMENT = 13, /**< Acknowledgement (6.3.1 (Table 6.2 with a one-word payload)), 2 bytes. */
} ilahrs_payload_t;

/** Number of payload tables. */
#define ILAHRS_PAYLOAD_COUNT 14

/** Wire kinds of payload fields. */
typedef enum ilahrs_kind {
    ILAHRS_KIND_UNSIGNED = 0,
    ILAHRS_KIND_SIGNED = 1,
    ILAHRS_KIND_FLOAT = 2,
    ILAHRS_KIND_CHAR = 3,
    ILAHRS_KIND_RESERVED = 4,
} ilahrs_kind_t;

/**
 * Where and what a payload field is. Read it through the ilahrs_field_*() functions; the
 * layout of this struct is not part of the interface.
 */
typedef struct ilahrs_field_info {
    uint16_t name_type; /* name pool offset, type (kind, encoding, log2 of a number's size) */
    uint8_t place;      /* struct padding before the member, wire offset */
    uint8_t info;       /* char, reserved: wire size; numbers: scale and bounds rows */
} ilahrs_field_info_t;

#if ILAHRS_NAMES
/** Spec name of a payload table ("full_output"); NULL if unknown. */
const char *ilahrs_payload_name(ilahrs_payload_t payload);
#endif
/** Wire size of a payload table; 0 if unknown. */
size_t ilahrs_payload_size(ilahrs_payload_t payload);
/** sizeof the C struct of a payload table; 0 if unknown. */
size_t ilahrs_payload_struct_size(ilahrs_payload_t payload);
/** Number of fields of a payload table; 0 if unknown. */
size_t ilahrs_payload_field_count(ilahrs_payload_t payload);
/** Field `index` of a payload table, in wire order; NULL if out of range. */
const ilahrs_field_info_t *ilahrs_payload_field(ilahrs_payload_t payload, size_t index);
#if ILAHRS_NAMES
/** Find a payload table by its spec name, `len` characters at `name`. */
bool ilahrs_payload_by_name(const char *name, size_t len, ilahrs_payload_t *payload);

/** Spec name of a field ("heading"). */
const char *ilahrs_field_name(const ilahrs_field_info_t *field);
#endif
/** Wire offset of a field in its payload. */
size_t ilahrs_field_offset(const ilahrs_field_info_t *field);
/** Wire size of a field. */
size_t ilahrs_field_size(const ilahrs_field_info_t *field);
/** Wire kind of a field. */
ilahrs_kind_t ilahrs_field_kind(const ilahrs_field_info_t *field);
/** The field's member inside a payload struct (`payload` points at the struct). */
void *ilahrs_field_member(const ilahrs_field_info_t *field, void *payload);
/** The field's member inside a payload struct, read-only. */
const void *ilahrs_field_member_const(const ilahrs_field_info_t *field, const void *payload);

/** An integer field's value (ILAHRS_KIND_UNSIGNED / ILAHRS_KIND_SIGNED); 0 for other kinds. */
int64_t ilahrs_field_get_int(const ilahrs_field_info_t *field, const void *payload);
/** A float field's value (ILAHRS_KIND_FLOAT); 0 for other kinds. */
float ilahrs_field_get_float(const ilahrs_field_info_t *field, const void *payload);
/**
 * Store an integer field's value; false (`out_of_range` at the field's offset) if the
 * field's C type cannot hold it or the field is not an integer. The builder's range check
 * still applies when the payload is built.
 */
bool ilahrs_field_set_int(const ilahrs_field_info_t *field, void *payload, int64_t value, ilahrs_error_t *err);
/** Store a float field's value (any float; the builder checks it). False if not a float field. */
bool ilahrs_field_set_float(const ilahrs_field_info_t *field, void *payload, float value, ilahrs_error_t *err);

/**
 * Would a builder accept `value` for this numeric field? The check builders make (range,
 * finite, within float32, the declination rule), on a double: hosts that read numbers from
 * text use it before rounding to the field's C type. `out_of_range` at the field's offset.
 */
bool ilahrs_field_check(const ilahrs_field_info_t *field, double value, ilahrs_error_t *err);

/**
 * The engineering scale of a field: engineering value = raw * `*multiplier` / `*divisor`.
 * False if the field has no scale, or its divisor is a variant parameter (KG, KA) and
 * `variant` is ILAHRS_VARIANT_NONE or unknown.
 */
bool ilahrs_field_scale(const ilahrs_field_info_t *field, ilahrs_variant_t variant, int32_t *multiplier,
                        int32_t *divisor);

/**
 * Set every field of the struct at `out` (of table `payload`'s type) to the builders'
 * default: the field's spec default, else zero when its range allows, else the lowest value of
 * its range (the defaults that are not zero are listed with the payload tables below). Start
 * every payload you build from this.
 */
void ilahrs_payload_defaults(ilahrs_payload_t payload, void *out);

/**
 * Decode a payload of table `payload` into the struct at `out` (of that table's type).
 * Needs exactly the table's size: fewer bytes is `truncated` at `len`, more is
 * `trailing_data` at the size. No range checks: every byte string of the right size decodes.
 * A `payload` that is not a table (ILAHRS_PAYLOAD_NONE) is `out_of_range`, with no offset or field.
 */
bool ilahrs_payload_parse(ilahrs_payload_t payload, const uint8_t *data, size_t len, void *out, ilahrs_error_t *err);

/**
 * Encode the struct at `in` (of table `payload`'s type) into `out`. Checks the fields in
 * table order and refuses the first bad one with `out_of_range` at the field's wire offset,
 * naming the field: an integer outside its range, a float that is NaN, infinite or outside
 * its range, a declination that is neither in range nor the compute request. Values are never
 * wrapped, clamped or truncated. `buffer_too_small` if `cap` is less than the table's size;
 * `out_of_range`, with no offset or field, if `payload` is not a table (ILAHRS_PAYLOAD_NONE).
 * @return the payload size, or 0 on failure
 */
size_t ilahrs_payload_build(ilahrs_payload_t payload, const void *in, uint8_t *out, size_t cap, ilahrs_error_t *err);

/**
 * ilahrs_payload_build() wrapped in a data frame (message type data, reserved 0): what the
 * AHRS sends, and what the host sends as a parameter block (E5).
 * @return the frame size, or 0 on failure
 */
size_t ilahrs_payload_build_frame(ilahrs_payload_t payload, const void *in, uint8_t *out, size_t cap,
                                  ilahrs_error_t *err);

/*
 * The builders' defaults that are not zero (ilahrs_payload_defaults()):
 * ahrs_parameters_load.update_rate = 100,
 * ahrs_parameters_load.alignment_time = 30,
 * ahrs_parameters_load.date = 1900.002685546875,
 * ahrs_parameters_read.update_rate = 1,
 * ahrs_parameters_read.alignment_time = 1,
 * ahrs_parameters_read.date = 1900.002685546875,
 * calibration_parameters.accumulation_time = 1,
 * calibration_parameters.date = 1900.002685546875,
 * calibration_result.calibration_type = 1,
 * calibration_run_result.calibration_type = 2,
 * calibration_run_result.run = 1.
 */

/* ---- Full Output Data (Table 6.4) ---- */

#define ILAHRS_FULL_OUTPUT_SIZE 34            /**< Size of a full_output payload. */
#define ILAHRS_FULL_OUTPUT_HEADING_OFFSET 0   /**< Offset of full_output.heading. */
#define ILAHRS_FULL_OUTPUT_HEADING_SIZE 2     /**< Size of full_output.heading. */
#define ILAHRS_FULL_OUTPUT_PITCH_OFFSET 2     /**< Offset of full_output.pitch. */
#define ILAHRS_FULL_OUTPUT_PITCH_SIZE 2       /**< Size of full_output.pitch. */
#define ILAHRS_FULL_OUTPUT_ROLL_OFFSET 4      /**< Offset of full_output.roll. */
#define ILAHRS_FULL_OUTPUT_ROLL_SIZE 2        /**< Size of full_output.roll. */
#define ILAHRS_FULL_OUTPUT_UGYRO_X_OFFSET 6   /**< Offset of full_output.ugyro_x. */
#define ILAHRS_FULL_OUTPUT_UGYRO_X_SIZE 2     /**< Size of full_output.ugyro_x. */
#define ILAHRS_FULL_OUTPUT_UGYRO_Y_OFFSET 8   /**< Offset of full_output.ugyro_y. */
#define ILAHRS_FULL_OUTPUT_UGYRO_Y_SIZE 2     /**< Size of full_output.ugyro_y. */
#define ILAHRS_FULL_OUTPUT_UGYRO_Z_OFFSET 10  /**< Offset of full_output.ugyro_z. */
#define ILAHRS_FULL_OUTPUT_UGYRO_Z_SIZE 2     /**< Size of full_output.ugyro_z. */
#define ILAHRS_FULL_OUTPUT_UACC_X_OFFSET 12   /**< Offset of full_output.uacc_x. */
#define ILAHRS_FULL_OUTPUT_UACC_X_SIZE 2      /**< Size of full_output.uacc_x. */
#define ILAHRS_FULL_OUTPUT_UACC_Y_OFFSET 14   /**< Offset of full_output.uacc_y. */
#define ILAHRS_FULL_OUTPUT_UACC_Y_SIZE 2      /**< Size of full_output.uacc_y. */
#define ILAHRS_FULL_OUTPUT_UACC_Z_OFFSET 16   /**< Offset of full_output.uacc_z. */
#define ILAHRS_FULL_OUTPUT_UACC_Z_SIZE 2      /**< Size of full_output.uacc_z. */
#define ILAHRS_FULL_OUTPUT_UMAG_X_OFFSET 18   /**< Offset of full_output.umag_x. */
#define ILAHRS_FULL_OUTPUT_UMAG_X_SIZE 2      /**< Size of full_output.umag_x. */
#define ILAHRS_FULL_OUTPUT_UMAG_Y_OFFSET 20   /**< Offset of full_output.umag_y. */
#define ILAHRS_FULL_OUTPUT_UMAG_Y_SIZE 2      /**< Size of full_output.umag_y. */
#define ILAHRS_FULL_OUTPUT_UMAG_Z_OFFSET 22   /**< Offset of full_output.umag_z. */
#define ILAHRS_FULL_OUTPUT_UMAG_Z_SIZE 2      /**< Size of full_output.umag_z. */
#define ILAHRS_FULL_OUTPUT_RESERVED_OFFSET 24 /**< Offset of full_output.reserved. */
#define ILAHRS_FULL_OUTPUT_RESERVED_SIZE 4    /**< Size of full_output.reserved. */
#define ILAHRS_FULL_OUTPUT_USW_OFFSET 28      /**< Offset of full_output.usw. */
#define ILAHRS_FULL_OUTPUT_USW_SIZE 2         /**< Size of full_output.usw. */
#define ILAHRS_FULL_OUTPUT_VDD_OFFSET 30      /**< Offset of full_output.vdd. */
#define ILAHRS_FULL_OUTPUT_VDD_SIZE 2         /**< Size of full_output.vdd. */
#define ILAHRS_FULL_OUTPUT_UTERMO_OFFSET 32   /**< Offset of full_output.utermo. */
#define ILAHRS_FULL_OUTPUT_UTERMO_SIZE 2      /**< Size of full_output.utermo. */

/** Full Output Data (Table 6.4), 34 bytes, device to host. Output block after AHRScont1 /
 *  AHRSreq1. */
typedef struct ilahrs_full_output {
    /** Heading angle. (degrees = raw / 100; builders accept 0..35999; ICD: Heading; erratum E23) */
    uint16_t heading;
    /** Pitch angle. (degrees = raw / 100; builders accept -9000..9000; ICD: Pitch) */
    int16_t pitch;
    /** Roll angle. (degrees = raw / 100; builders accept -18000..18000; ICD: Roll) */
    int16_t roll;
    /** Raw gyro X sensor data. (ADC codes (no physical scale given by the ICD); ICD: Ugyro) */
    int16_t ugyro_x;
    /** Raw gyro Y sensor data. (ADC codes (no physical scale given by the ICD); ICD: Ugyro) */
    int16_t ugyro_y;
    /** Raw gyro Z sensor data. (ADC codes (no physical scale given by the ICD); ICD: Ugyro) */
    int16_t ugyro_z;
    /** Raw accelerometer X sensor data. (ADC codes (no physical scale given by the ICD); ICD:
     *  Uacc) */
    int16_t uacc_x;
    /** Raw accelerometer Y sensor data. (ADC codes (no physical scale given by the ICD); ICD:
     *  Uacc) */
    int16_t uacc_y;
    /** Raw accelerometer Z sensor data. (ADC codes (no physical scale given by the ICD); ICD:
     *  Uacc) */
    int16_t uacc_z;
    /** Raw magnetometer X sensor data. (ADC codes (no physical scale given by the ICD); ICD:
     *  Umag) */
    int16_t umag_x;
    /** Raw magnetometer Y sensor data. (ADC codes (no physical scale given by the ICD); ICD:
     *  Umag) */
    int16_t umag_y;
    /** Raw magnetometer Z sensor data. (ADC codes (no physical scale given by the ICD); ICD:
     *  Umag) */
    int16_t umag_z;
    /** (4 reserved bytes, kept verbatim; ICD: Reserved) */
    uint8_t reserved[4];
    /** Unit Status Word (section 6.5). (encoding usw; ICD: USW) */
    uint16_t usw;
    /** Combined voltage: successive frames carry the AHRS input voltage and the stabilised
     *  sensor supply voltage in turn (Table 6.4 note 2). The frame does not say which. (volts DC
     *  = raw / 1000; multiplexed: 2 quantities in successive frames; ICD: Vdd; erratum E19) */
    uint16_t vdd;
    /** ADC code of one of 7 temperature sensors, in turn in successive frames (Table 6.4 note
     *  3). The frame does not say which. (ADC codes (no physical scale given by the ICD);
     *  multiplexed: 7 quantities in successive frames; ICD: Utermo; erratum E19) */
    int16_t utermo;
} ilahrs_full_output_t;

/** Decode a 34-byte full_output payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_full_output_parse(const uint8_t *data, size_t len, ilahrs_full_output_t *out,
                                            ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_FULL_OUTPUT, data, len, out, err);
}

/** Encode a full_output payload (34 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_full_output_build(const ilahrs_full_output_t *in, uint8_t *out, size_t cap,
                                              ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_FULL_OUTPUT, in, out, cap, err);
}

/** Encode a full_output payload in a data frame (34 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_full_output_build_frame(const ilahrs_full_output_t *in, uint8_t *out, size_t cap,
                                                    ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_FULL_OUTPUT, in, out, cap, err);
}

/** full_output.heading in degrees: raw / 100. */
static inline float ilahrs_full_output_heading_deg(const ilahrs_full_output_t *m)
{
    return (float)m->heading / 100.0f;
}

/** full_output.pitch in degrees: raw / 100. */
static inline float ilahrs_full_output_pitch_deg(const ilahrs_full_output_t *m)
{
    return (float)m->pitch / 100.0f;
}

/** full_output.roll in degrees: raw / 100. */
static inline float ilahrs_full_output_roll_deg(const ilahrs_full_output_t *m)
{
    return (float)m->roll / 100.0f;
}

/** full_output.vdd in volts DC: raw / 1000. */
static inline float ilahrs_full_output_vdd_v(const ilahrs_full_output_t *m)
{
    return (float)m->vdd / 1000.0f;
}

/* ---- Quaternion of Orientation (Table 6.5) ---- */

#define ILAHRS_QUATERNION_SIZE 34            /**< Size of a quaternion payload. */
#define ILAHRS_QUATERNION_HEADING_OFFSET 0   /**< Offset of quaternion.heading. */
#define ILAHRS_QUATERNION_HEADING_SIZE 2     /**< Size of quaternion.heading. */
#define ILAHRS_QUATERNION_PITCH_OFFSET 2     /**< Offset of quaternion.pitch. */
#define ILAHRS_QUATERNION_PITCH_SIZE 2       /**< Size of quaternion.pitch. */
#define ILAHRS_QUATERNION_ROLL_OFFSET 4      /**< Offset of quaternion.roll. */
#define ILAHRS_QUATERNION_ROLL_SIZE 2        /**< Size of quaternion.roll. */
#define ILAHRS_QUATERNION_LK0_OFFSET 6       /**< Offset of quaternion.lk0. */
#define ILAHRS_QUATERNION_LK0_SIZE 2         /**< Size of quaternion.lk0. */
#define ILAHRS_QUATERNION_LK1_OFFSET 8       /**< Offset of quaternion.lk1. */
#define ILAHRS_QUATERNION_LK1_SIZE 2         /**< Size of quaternion.lk1. */
#define ILAHRS_QUATERNION_LK2_OFFSET 10      /**< Offset of quaternion.lk2. */
#define ILAHRS_QUATERNION_LK2_SIZE 2         /**< Size of quaternion.lk2. */
#define ILAHRS_QUATERNION_LK3_OFFSET 12      /**< Offset of quaternion.lk3. */
#define ILAHRS_QUATERNION_LK3_SIZE 2         /**< Size of quaternion.lk3. */
#define ILAHRS_QUATERNION_RESERVED_OFFSET 14 /**< Offset of quaternion.reserved. */
#define ILAHRS_QUATERNION_RESERVED_SIZE 14   /**< Size of quaternion.reserved. */
#define ILAHRS_QUATERNION_USW_OFFSET 28      /**< Offset of quaternion.usw. */
#define ILAHRS_QUATERNION_USW_SIZE 2         /**< Size of quaternion.usw. */
#define ILAHRS_QUATERNION_VDD_OFFSET 30      /**< Offset of quaternion.vdd. */
#define ILAHRS_QUATERNION_VDD_SIZE 2         /**< Size of quaternion.vdd. */
#define ILAHRS_QUATERNION_UTERMO_OFFSET 32   /**< Offset of quaternion.utermo. */
#define ILAHRS_QUATERNION_UTERMO_SIZE 2      /**< Size of quaternion.utermo. */

/** Quaternion of Orientation (Table 6.5), 34 bytes, device to host. Output block after AHRScont2
 *  / AHRSreq2. */
typedef struct ilahrs_quaternion {
    /** Heading angle. (degrees = raw / 100; builders accept 0..35999; ICD: Heading; erratum E23) */
    uint16_t heading;
    /** Pitch angle. (degrees = raw / 100; builders accept -9000..9000; ICD: Pitch) */
    int16_t pitch;
    /** Roll angle. (degrees = raw / 100; builders accept -18000..18000; ICD: Roll) */
    int16_t roll;
    /** Quaternion of orientation, scalar component. (dimensionless = raw / 10000; builders
     *  accept -10000..10000; ICD: Lk0) */
    int16_t lk0;
    /** Quaternion of orientation, first vector component. (dimensionless = raw / 10000; builders
     *  accept -10000..10000; ICD: Lk1) */
    int16_t lk1;
    /** Quaternion of orientation, second vector component. (dimensionless = raw / 10000;
     *  builders accept -10000..10000; ICD: Lk2) */
    int16_t lk2;
    /** Quaternion of orientation, third vector component. (dimensionless = raw / 10000; builders
     *  accept -10000..10000; ICD: Lk3) */
    int16_t lk3;
    /** (14 reserved bytes, kept verbatim; ICD: Reserved) */
    uint8_t reserved[14];
    /** Unit Status Word (section 6.5). (encoding usw; ICD: USW) */
    uint16_t usw;
    /** AHRS input voltage. (volts DC = raw / 1000; ICD: Vdd) */
    uint16_t vdd;
    /** Average temperature of the 3 accelerometers. (degrees Celsius = raw / 10; ICD: Utermo) */
    int16_t utermo;
} ilahrs_quaternion_t;

/** Decode a 34-byte quaternion payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_quaternion_parse(const uint8_t *data, size_t len, ilahrs_quaternion_t *out,
                                           ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_QUATERNION, data, len, out, err);
}

/** Encode a quaternion payload (34 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_quaternion_build(const ilahrs_quaternion_t *in, uint8_t *out, size_t cap,
                                             ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_QUATERNION, in, out, cap, err);
}

/** Encode a quaternion payload in a data frame (34 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_quaternion_build_frame(const ilahrs_quaternion_t *in, uint8_t *out, size_t cap,
                                                   ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_QUATERNION, in, out, cap, err);
}

/** quaternion.heading in degrees: raw / 100. */
static inline float ilahrs_quaternion_heading_deg(const ilahrs_quaternion_t *m)
{
    return (float)m->heading / 100.0f;
}

/** quaternion.pitch in degrees: raw / 100. */
static inline float ilahrs_quaternion_pitch_deg(const ilahrs_quaternion_t *m)
{
    return (float)m->pitch / 100.0f;
}

/** quaternion.roll in degrees: raw / 100. */
static inline float ilahrs_quaternion_roll_deg(const ilahrs_quaternion_t *m)
{
    return (float)m->roll / 100.0f;
}

/** quaternion.lk0 in dimensionless: raw / 10000. */
static inline float ilahrs_quaternion_lk0_value(const ilahrs_quaternion_t *m)
{
    return (float)m->lk0 / 10000.0f;
}

/** quaternion.lk1 in dimensionless: raw / 10000. */
static inline float ilahrs_quaternion_lk1_value(const ilahrs_quaternion_t *m)
{
    return (float)m->lk1 / 10000.0f;
}

/** quaternion.lk2 in dimensionless: raw / 10000. */
static inline float ilahrs_quaternion_lk2_value(const ilahrs_quaternion_t *m)
{
    return (float)m->lk2 / 10000.0f;
}

/** quaternion.lk3 in dimensionless: raw / 10000. */
static inline float ilahrs_quaternion_lk3_value(const ilahrs_quaternion_t *m)
{
    return (float)m->lk3 / 10000.0f;
}

/** quaternion.vdd in volts DC: raw / 1000. */
static inline float ilahrs_quaternion_vdd_v(const ilahrs_quaternion_t *m)
{
    return (float)m->vdd / 1000.0f;
}

/** quaternion.utermo in degrees Celsius: raw / 10. */
static inline float ilahrs_quaternion_utermo_degc(const ilahrs_quaternion_t *m)
{
    return (float)m->utermo / 10.0f;
}

/* ---- Orientation + Sensor Outputs (Table 6.6) ---- */

#define ILAHRS_ORIENTATION_SENSORS_SIZE 34            /**< Size of a orientation_sensors payload. */
#define ILAHRS_ORIENTATION_SENSORS_HEADING_OFFSET 0   /**< Offset of orientation_sensors.heading. */
#define ILAHRS_ORIENTATION_SENSORS_HEADING_SIZE 2     /**< Size of orientation_sensors.heading. */
#define ILAHRS_ORIENTATION_SENSORS_PITCH_OFFSET 2     /**< Offset of orientation_sensors.pitch. */
#define ILAHRS_ORIENTATION_SENSORS_PITCH_SIZE 2       /**< Size of orientation_sensors.pitch. */
#define ILAHRS_ORIENTATION_SENSORS_ROLL_OFFSET 4      /**< Offset of orientation_sensors.roll. */
#define ILAHRS_ORIENTATION_SENSORS_ROLL_SIZE 2        /**< Size of orientation_sensors.roll. */
#define ILAHRS_ORIENTATION_SENSORS_GYRO_X_OFFSET 6    /**< Offset of orientation_sensors.gyro_x. */
#define ILAHRS_ORIENTATION_SENSORS_GYRO_X_SIZE 2      /**< Size of orientation_sensors.gyro_x. */
#define ILAHRS_ORIENTATION_SENSORS_GYRO_Y_OFFSET 8    /**< Offset of orientation_sensors.gyro_y. */
#define ILAHRS_ORIENTATION_SENSORS_GYRO_Y_SIZE 2      /**< Size of orientation_sensors.gyro_y. */
#define ILAHRS_ORIENTATION_SENSORS_GYRO_Z_OFFSET 10   /**< Offset of orientation_sensors.gyro_z. */
#define ILAHRS_ORIENTATION_SENSORS_GYRO_Z_SIZE 2      /**< Size of orientation_sensors.gyro_z. */
#define ILAHRS_ORIENTATION_SENSORS_ACC_X_OFFSET 12    /**< Offset of orientation_sensors.acc_x. */
#define ILAHRS_ORIENTATION_SENSORS_ACC_X_SIZE 2       /**< Size of orientation_sensors.acc_x. */
#define ILAHRS_ORIENTATION_SENSORS_ACC_Y_OFFSET 14    /**< Offset of orientation_sensors.acc_y. */
#define ILAHRS_ORIENTATION_SENSORS_ACC_Y_SIZE 2       /**< Size of orientation_sensors.acc_y. */
#define ILAHRS_ORIENTATION_SENSORS_ACC_Z_OFFSET 16    /**< Offset of orientation_sensors.acc_z. */
#define ILAHRS_ORIENTATION_SENSORS_ACC_Z_SIZE 2       /**< Size of orientation_sensors.acc_z. */
#define ILAHRS_ORIENTATION_SENSORS_MAG_X_OFFSET 18    /**< Offset of orientation_sensors.mag_x. */
#define ILAHRS_ORIENTATION_SENSORS_MAG_X_SIZE 2       /**< Size of orientation_sensors.mag_x. */
#define ILAHRS_ORIENTATION_SENSORS_MAG_Y_OFFSET 20    /**< Offset of orientation_sensors.mag_y. */
#define ILAHRS_ORIENTATION_SENSORS_MAG_Y_SIZE 2       /**< Size of orientation_sensors.mag_y. */
#define ILAHRS_ORIENTATION_SENSORS_MAG_Z_OFFSET 22    /**< Offset of orientation_sensors.mag_z. */
#define ILAHRS_ORIENTATION_SENSORS_MAG_Z_SIZE 2       /**< Size of orientation_sensors.mag_z. */
#define ILAHRS_ORIENTATION_SENSORS_RESERVED_OFFSET 24 /**< Offset of orientation_sensors.reserved. */
#define ILAHRS_ORIENTATION_SENSORS_RESERVED_SIZE 4    /**< Size of orientation_sensors.reserved. */
#define ILAHRS_ORIENTATION_SENSORS_USW_OFFSET 28      /**< Offset of orientation_sensors.usw. */
#define ILAHRS_ORIENTATION_SENSORS_USW_SIZE 2         /**< Size of orientation_sensors.usw. */
#define ILAHRS_ORIENTATION_SENSORS_VDD_OFFSET 30      /**< Offset of orientation_sensors.vdd. */
#define ILAHRS_ORIENTATION_SENSORS_VDD_SIZE 2         /**< Size of orientation_sensors.vdd. */
#define ILAHRS_ORIENTATION_SENSORS_UTERMO_OFFSET 32   /**< Offset of orientation_sensors.utermo. */
#define ILAHRS_ORIENTATION_SENSORS_UTERMO_SIZE 2      /**< Size of orientation_sensors.utermo. */

/** Orientation + Sensor Outputs (Table 6.6), 34 bytes, device to host. Output block after
 *  AHRScont3 / AHRSreq3 (the default format, section 6.2). */
typedef struct ilahrs_orientation_sensors {
    /** Heading angle. (degrees = raw / 100; builders accept 0..35999; ICD: Heading; erratum E23) */
    uint16_t heading;
    /** Pitch angle. (degrees = raw / 100; builders accept -9000..9000; ICD: Pitch) */
    int16_t pitch;
    /** Roll angle. (degrees = raw / 100; builders accept -18000..18000; ICD: Roll) */
    int16_t roll;
    /** Angular rate about X (lateral axis). (degrees per second = raw / KG; ICD: GyroX) */
    int16_t gyro_x;
    /** Angular rate about Y (longitudinal axis). (degrees per second = raw / KG; ICD: GyroY) */
    int16_t gyro_y;
    /** Angular rate about Z (vertical axis). (degrees per second = raw / KG; ICD: GyroZ) */
    int16_t gyro_z;
    /** Linear acceleration along X. (standard gravity = raw / KA; ICD: AccX) */
    int16_t acc_x;
    /** Linear acceleration along Y. (standard gravity = raw / KA; ICD: AccY) */
    int16_t acc_y;
    /** Linear acceleration along Z. (standard gravity = raw / KA; ICD: AccZ) */
    int16_t acc_z;
    /** Magnetic field along X. (nanotesla = raw x 10; ICD: MagX) */
    int16_t mag_x;
    /** Magnetic field along Y. (nanotesla = raw x 10; ICD: MagY) */
    int16_t mag_y;
    /** Magnetic field along Z. (nanotesla = raw x 10; ICD: MagZ) */
    int16_t mag_z;
    /** (4 reserved bytes, kept verbatim; ICD: Reserved) */
    uint8_t reserved[4];
    /** Unit Status Word (section 6.5). (encoding usw; ICD: USW) */
    uint16_t usw;
    /** AHRS input voltage. (volts DC = raw / 1000; ICD: Vdd) */
    uint16_t vdd;
    /** Average temperature of the 3 accelerometers. (degrees Celsius = raw / 10; ICD: Utermo) */
    int16_t utermo;
} ilahrs_orientation_sensors_t;

/** Decode a 34-byte orientation_sensors payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_orientation_sensors_parse(const uint8_t *data, size_t len, ilahrs_orientation_sensors_t *out,
                                                    ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_ORIENTATION_SENSORS, data, len, out, err);
}

/** Encode a orientation_sensors payload (34 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_orientation_sensors_build(const ilahrs_orientation_sensors_t *in, uint8_t *out, size_t cap,
                                                      ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_ORIENTATION_SENSORS, in, out, cap, err);
}

/** Encode a orientation_sensors payload in a data frame (34 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_orientation_sensors_build_frame(const ilahrs_orientation_sensors_t *in, uint8_t *out,
                                                            size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_ORIENTATION_SENSORS, in, out, cap, err);
}

/** orientation_sensors.heading in degrees: raw / 100. */
static inline float ilahrs_orientation_sensors_heading_deg(const ilahrs_orientation_sensors_t *m)
{
    return (float)m->heading / 100.0f;
}

/** orientation_sensors.pitch in degrees: raw / 100. */
static inline float ilahrs_orientation_sensors_pitch_deg(const ilahrs_orientation_sensors_t *m)
{
    return (float)m->pitch / 100.0f;
}

/** orientation_sensors.roll in degrees: raw / 100. */
static inline float ilahrs_orientation_sensors_roll_deg(const ilahrs_orientation_sensors_t *m)
{
    return (float)m->roll / 100.0f;
}

/** orientation_sensors.gyro_x in degrees per second: raw / KG of `variant` (0 if `variant` is unknown). */
static inline float ilahrs_orientation_sensors_gyro_x_dps(const ilahrs_orientation_sensors_t *m,
                                                          ilahrs_variant_t variant)
{
    int32_t k = ilahrs_variant_parameter(variant, ILAHRS_PARAMETER_KG);
    return k != 0 ? (float)m->gyro_x / (float)k : 0.0f;
}

/** orientation_sensors.gyro_y in degrees per second: raw / KG of `variant` (0 if `variant` is unknown). */
static inline float ilahrs_orientation_sensors_gyro_y_dps(const ilahrs_orientation_sensors_t *m,
                                                          ilahrs_variant_t variant)
{
    int32_t k = ilahrs_variant_parameter(variant, ILAHRS_PARAMETER_KG);
    return k != 0 ? (float)m->gyro_y / (float)k : 0.0f;
}

/** orientation_sensors.gyro_z in degrees per second: raw / KG of `variant` (0 if `variant` is unknown). */
static inline float ilahrs_orientation_sensors_gyro_z_dps(const ilahrs_orientation_sensors_t *m,
                                                          ilahrs_variant_t variant)
{
    int32_t k = ilahrs_variant_parameter(variant, ILAHRS_PARAMETER_KG);
    return k != 0 ? (float)m->gyro_z / (float)k : 0.0f;
}

/** orientation_sensors.acc_x in standard gravity: raw / KA of `variant` (0 if `variant` is unknown). */
static inline float ilahrs_orientation_sensors_acc_x_g(const ilahrs_orientation_sensors_t *m, ilahrs_variant_t variant)
{
    int32_t k = ilahrs_variant_parameter(variant, ILAHRS_PARAMETER_KA);
    return k != 0 ? (float)m->acc_x / (float)k : 0.0f;
}

/** orientation_sensors.acc_y in standard gravity: raw / KA of `variant` (0 if `variant` is unknown). */
static inline float ilahrs_orientation_sensors_acc_y_g(const ilahrs_orientation_sensors_t *m, ilahrs_variant_t variant)
{
    int32_t k = ilahrs_variant_parameter(variant, ILAHRS_PARAMETER_KA);
    return k != 0 ? (float)m->acc_y / (float)k : 0.0f;
}

/** orientation_sensors.acc_z in standard gravity: raw / KA of `variant` (0 if `variant` is unknown). */
static inline float ilahrs_orientation_sensors_acc_z_g(const ilahrs_orientation_sensors_t *m, ilahrs_variant_t variant)
{
    int32_t k = ilahrs_variant_parameter(variant, ILAHRS_PARAMETER_KA);
    return k != 0 ? (float)m->acc_z / (float)k : 0.0f;
}

/** orientation_sensors.mag_x in nanotesla: raw x 10. */
static inline float ilahrs_orientation_sensors_mag_x_nt(const ilahrs_orientation_sensors_t *m)
{
    return (float)m->mag_x * 10.0f;
}

/** orientation_sensors.mag_y in nanotesla: raw x 10. */
static inline float ilahrs_orientation_sensors_mag_y_nt(const ilahrs_orientation_sensors_t *m)
{
    return (float)m->mag_y * 10.0f;
}

/** orientation_sensors.mag_z in nanotesla: raw x 10. */
static inline float ilahrs_orientation_sensors_mag_z_nt(const ilahrs_orientation_sensors_t *m)
{
    return (float)m->mag_z * 10.0f;
}

/** orientation_sensors.vdd in volts DC: raw / 1000. */
static inline float ilahrs_orientation_sensors_vdd_v(const ilahrs_orientation_sensors_t *m)
{
    return (float)m->vdd / 1000.0f;
}

/** orientation_sensors.utermo in degrees Celsius: raw / 10. */
static inline float ilahrs_orientation_sensors_utermo_degc(const ilahrs_orientation_sensors_t *m)
{
    return (float)m->utermo / 10.0f;
}

/* ---- Initial alignment data (Table 6.8, erratum E21) ---- */

#define ILAHRS_INITIAL_ALIGNMENT_SIZE 50                   /**< Size of a initial_alignment payload. */
#define ILAHRS_INITIAL_ALIGNMENT_GYRO_BIAS_X_OFFSET 0      /**< Offset of initial_alignment.gyro_bias_x. */
#define ILAHRS_INITIAL_ALIGNMENT_GYRO_BIAS_X_SIZE 4        /**< Size of initial_alignment.gyro_bias_x. */
#define ILAHRS_INITIAL_ALIGNMENT_GYRO_BIAS_Y_OFFSET 4      /**< Offset of initial_alignment.gyro_bias_y. */
#define ILAHRS_INITIAL_ALIGNMENT_GYRO_BIAS_Y_SIZE 4        /**< Size of initial_alignment.gyro_bias_y. */
#define ILAHRS_INITIAL_ALIGNMENT_GYRO_BIAS_Z_OFFSET 8      /**< Offset of initial_alignment.gyro_bias_z. */
#define ILAHRS_INITIAL_ALIGNMENT_GYRO_BIAS_Z_SIZE 4        /**< Size of initial_alignment.gyro_bias_z. */
#define ILAHRS_INITIAL_ALIGNMENT_AVERAGE_ACC_X_OFFSET 12   /**< Offset of initial_alignment.average_acc_x. */
#define ILAHRS_INITIAL_ALIGNMENT_AVERAGE_ACC_X_SIZE 4      /**< Size of initial_alignment.average_acc_x. */
#define ILAHRS_INITIAL_ALIGNMENT_AVERAGE_ACC_Y_OFFSET 16   /**< Offset of initial_alignment.average_acc_y. */
#define ILAHRS_INITIAL_ALIGNMENT_AVERAGE_ACC_Y_SIZE 4      /**< Size of initial_alignment.average_acc_y. */
#define ILAHRS_INITIAL_ALIGNMENT_AVERAGE_ACC_Z_OFFSET 20   /**< Offset of initial_alignment.average_acc_z. */
#define ILAHRS_INITIAL_ALIGNMENT_AVERAGE_ACC_Z_SIZE 4      /**< Size of initial_alignment.average_acc_z. */
#define ILAHRS_INITIAL_ALIGNMENT_AVERAGE_MAG_X_OFFSET 24   /**< Offset of initial_alignment.average_mag_x. */
#define ILAHRS_INITIAL_ALIGNMENT_AVERAGE_MAG_X_SIZE 4      /**< Size of initial_alignment.average_mag_x. */
#define ILAHRS_INITIAL_ALIGNMENT_AVERAGE_MAG_Y_OFFSET 28   /**< Offset of initial_alignment.average_mag_y. */
#define ILAHRS_INITIAL_ALIGNMENT_AVERAGE_MAG_Y_SIZE 4      /**< Size of initial_alignment.average_mag_y. */
#define ILAHRS_INITIAL_ALIGNMENT_AVERAGE_MAG_Z_OFFSET 32   /**< Offset of initial_alignment.average_mag_z. */
#define ILAHRS_INITIAL_ALIGNMENT_AVERAGE_MAG_Z_SIZE 4      /**< Size of initial_alignment.average_mag_z. */
#define ILAHRS_INITIAL_ALIGNMENT_INITIAL_HEADING_OFFSET 36 /**< Offset of initial_alignment.initial_heading. */
#define ILAHRS_INITIAL_ALIGNMENT_INITIAL_HEADING_SIZE 4    /**< Size of initial_alignment.initial_heading. */
#define ILAHRS_INITIAL_ALIGNMENT_INITIAL_ROLL_OFFSET 40    /**< Offset of initial_alignment.initial_roll. */
#define ILAHRS_INITIAL_ALIGNMENT_INITIAL_ROLL_SIZE 4       /**< Size of initial_alignment.initial_roll. */
#define ILAHRS_INITIAL_ALIGNMENT_INITIAL_PITCH_OFFSET 44   /**< Offset of initial_alignment.initial_pitch. */
#define ILAHRS_INITIAL_ALIGNMENT_INITIAL_PITCH_SIZE 4      /**< Size of initial_alignment.initial_pitch. */
#define ILAHRS_INITIAL_ALIGNMENT_USW_OFFSET 48             /**< Offset of initial_alignment.usw. */
#define ILAHRS_INITIAL_ALIGNMENT_USW_SIZE 2                /**< Size of initial_alignment.usw. */

/** Initial alignment data (Table 6.8), 50 bytes, device to host. Sent once when initial
 *  alignment completes, before continuous / on-request output or a calibration run starts (6.3.1
 *  - 6.3.3, 6.4). Note the ICD order: heading, roll, pitch. */
typedef struct ilahrs_initial_alignment {
    /** Gyro X bias. (ADC codes (no physical scale given by the ICD); ICD: Gyros bias) */
    float gyro_bias_x;
    /** Gyro Y bias. (ADC codes (no physical scale given by the ICD); ICD: Gyros bias) */
    float gyro_bias_y;
    /** Gyro Z bias. (ADC codes (no physical scale given by the ICD); ICD: Gyros bias) */
    float gyro_bias_z;
    /** Average acceleration along X. (ADC codes (no physical scale given by the ICD); ICD:
     *  Average acceleration) */
    float average_acc_x;
    /** Average acceleration along Y. (ADC codes (no physical scale given by the ICD); ICD:
     *  Average acceleration) */
    float average_acc_y;
    /** Average acceleration along Z. (ADC codes (no physical scale given by the ICD); ICD:
     *  Average acceleration) */
    float average_acc_z;
    /** Average magnetic field along X. (ADC codes (no physical scale given by the ICD); ICD:
     *  Average magn. field) */
    float average_mag_x;
    /** Average magnetic field along Y. (ADC codes (no physical scale given by the ICD); ICD:
     *  Average magn. field) */
    float average_mag_y;
    /** Average magnetic field along Z. (ADC codes (no physical scale given by the ICD); ICD:
     *  Average magn. field) */
    float average_mag_z;
    /** Heading at the end of alignment. (degrees; builders accept 0..360; ICD: Initial Heading) */
    float initial_heading;
    /** Roll at the end of alignment. (degrees; builders accept -180..180; ICD: Initial Roll) */
    float initial_roll;
    /** Pitch at the end of alignment. (degrees; builders accept -90..90; ICD: Initial Pitch) */
    float initial_pitch;
    /** Unit Status Word: 0 after a successful alignment, non-zero otherwise. (encoding usw; ICD:
     *  USW; erratum E27) */
    uint16_t usw;
} ilahrs_initial_alignment_t;

/** Decode a 50-byte initial_alignment payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_initial_alignment_parse(const uint8_t *data, size_t len, ilahrs_initial_alignment_t *out,
                                                  ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_INITIAL_ALIGNMENT, data, len, out, err);
}

/** Encode a initial_alignment payload (50 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_initial_alignment_build(const ilahrs_initial_alignment_t *in, uint8_t *out, size_t cap,
                                                    ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_INITIAL_ALIGNMENT, in, out, cap, err);
}

/** Encode a initial_alignment payload in a data frame (50 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_initial_alignment_build_frame(const ilahrs_initial_alignment_t *in, uint8_t *out,
                                                          size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_INITIAL_ALIGNMENT, in, out, cap, err);
}

/* ---- Parameters to load (Table 6.9) ---- */

#define ILAHRS_AHRS_PARAMETERS_LOAD_SIZE 50                 /**< Size of a ahrs_parameters_load payload. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_UPDATE_RATE_OFFSET 0    /**< Offset of ahrs_parameters_load.update_rate. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_UPDATE_RATE_SIZE 2      /**< Size of ahrs_parameters_load.update_rate. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_ALIGNMENT_TIME_OFFSET 2 /**< Offset of ahrs_parameters_load.alignment_time. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_ALIGNMENT_TIME_SIZE 2   /**< Size of ahrs_parameters_load.alignment_time. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_DECLINATION_OFFSET 4    /**< Offset of ahrs_parameters_load.declination. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_DECLINATION_SIZE 4      /**< Size of ahrs_parameters_load.declination. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_LATITUDE_OFFSET 8       /**< Offset of ahrs_parameters_load.latitude. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_LATITUDE_SIZE 4         /**< Size of ahrs_parameters_load.latitude. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_LONGITUDE_OFFSET 12     /**< Offset of ahrs_parameters_load.longitude. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_LONGITUDE_SIZE 4        /**< Size of ahrs_parameters_load.longitude. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_ALTITUDE_OFFSET 16      /**< Offset of ahrs_parameters_load.altitude. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_ALTITUDE_SIZE 4         /**< Size of ahrs_parameters_load.altitude. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_DATE_OFFSET 20          /**< Offset of ahrs_parameters_load.date. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_DATE_SIZE 4             /**< Size of ahrs_parameters_load.date. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_ALIGNMENT_ANGLE_A1_OFFSET \
    24                                                        /**< Offset of ahrs_parameters_load.alignment_angle_a1. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_ALIGNMENT_ANGLE_A1_SIZE 4 /**< Size of ahrs_parameters_load.alignment_angle_a1. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_ALIGNMENT_ANGLE_A2_OFFSET \
    28                                                        /**< Offset of ahrs_parameters_load.alignment_angle_a2. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_ALIGNMENT_ANGLE_A2_SIZE 4 /**< Size of ahrs_parameters_load.alignment_angle_a2. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_ALIGNMENT_ANGLE_A3_OFFSET \
    32                                                        /**< Offset of ahrs_parameters_load.alignment_angle_a3. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_ALIGNMENT_ANGLE_A3_SIZE 4 /**< Size of ahrs_parameters_load.alignment_angle_a3. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_RESERVED_OFFSET 36        /**< Offset of ahrs_parameters_load.reserved. */
#define ILAHRS_AHRS_PARAMETERS_LOAD_RESERVED_SIZE 14          /**< Size of ahrs_parameters_load.reserved. */

/** Parameters to load (Table 6.9), 50 bytes, host to device. The data message the host sends
 *  right after LoadAHRSPar (6.3.6). Read the block first (ReadAHRSPar), change it, send it back. */
typedef struct ilahrs_ahrs_parameters_load {
    /** Output data rate, 1 to 100 Hz (the AHRS limits NMEA output to 50 Hz). (hertz; builders
     *  accept 1..100; ICD: Update rate; erratum E22) */
    uint16_t update_rate;
    /** Initial alignment duration; default 30 s, change only in agreement with Inertial Labs.
     *  (seconds; builders accept 1..65535; ICD: Initial alignment time; erratum E30) */
    uint16_t alignment_time;
    /** Magnetic declination; a value above 360 asks the AHRS to compute it from position and
     *  date. (degrees; encoding declination; ICD: Magnetic declination, Mdec) */
    float declination;
    /** Latitude. (degrees; builders accept -90..90; ICD: Latitude) */
    float latitude;
    /** Longitude. (degrees; builders accept -180..180; ICD: Longitude) */
    float longitude;
    /** Altitude. (metres; builders accept -20000..100000; ICD: Altitude; erratum E31) */
    float altitude;
    /** Date as Year + (Month - 1)/12 + Day/365. (fractional year, see encoding `date`; builders
     *  accept 1900..2200; encoding date; ICD: Date (Year, Month, Day)) */
    float date;
    /** Mounting angle 1: AHRS Y axis relative to the object's longitudinal axis in its
     *  horizontal plane, clockwise positive (Appendix B). (degrees; builders accept -360..360;
     *  ICD: Alignment angle A1; erratum E31) */
    float alignment_angle_a1;
    /** Mounting angle 2: inclination of the AHRS Y axis to the object's horizontal plane, up
     *  positive (Appendix B). (degrees; builders accept -360..360; ICD: Alignment angle A2;
     *  erratum E31) */
    float alignment_angle_a2;
    /** Mounting angle 3: inclination of the AHRS X axis about its Y axis, X down positive
     *  (Appendix B). (degrees; builders accept -360..360; ICD: Alignment angle A3; erratum E31) */
    float alignment_angle_a3;
    /** Should be all zeros. (14 reserved bytes, kept verbatim; ICD: Reserved) */
    uint8_t reserved[14];
} ilahrs_ahrs_parameters_load_t;

/** Decode a 50-byte ahrs_parameters_load payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_ahrs_parameters_load_parse(const uint8_t *data, size_t len,
                                                     ilahrs_ahrs_parameters_load_t *out, ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_AHRS_PARAMETERS_LOAD, data, len, out, err);
}

/** Encode a ahrs_parameters_load payload (50 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_ahrs_parameters_load_build(const ilahrs_ahrs_parameters_load_t *in, uint8_t *out,
                                                       size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_AHRS_PARAMETERS_LOAD, in, out, cap, err);
}

/** Encode a ahrs_parameters_load payload in a data frame (50 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_ahrs_parameters_load_build_frame(const ilahrs_ahrs_parameters_load_t *in, uint8_t *out,
                                                             size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_AHRS_PARAMETERS_LOAD, in, out, cap, err);
}

/* ---- Parameters read (Table 6.10) ---- */

#define ILAHRS_AHRS_PARAMETERS_READ_SIZE 50                 /**< Size of a ahrs_parameters_read payload. */
#define ILAHRS_AHRS_PARAMETERS_READ_UPDATE_RATE_OFFSET 0    /**< Offset of ahrs_parameters_read.update_rate. */
#define ILAHRS_AHRS_PARAMETERS_READ_UPDATE_RATE_SIZE 2      /**< Size of ahrs_parameters_read.update_rate. */
#define ILAHRS_AHRS_PARAMETERS_READ_ALIGNMENT_TIME_OFFSET 2 /**< Offset of ahrs_parameters_read.alignment_time. */
#define ILAHRS_AHRS_PARAMETERS_READ_ALIGNMENT_TIME_SIZE 2   /**< Size of ahrs_parameters_read.alignment_time. */
#define ILAHRS_AHRS_PARAMETERS_READ_DECLINATION_OFFSET 4    /**< Offset of ahrs_parameters_read.declination. */
#define ILAHRS_AHRS_PARAMETERS_READ_DECLINATION_SIZE 4      /**< Size of ahrs_parameters_read.declination. */
#define ILAHRS_AHRS_PARAMETERS_READ_LATITUDE_OFFSET 8       /**< Offset of ahrs_parameters_read.latitude. */
#define ILAHRS_AHRS_PARAMETERS_READ_LATITUDE_SIZE 4         /**< Size of ahrs_parameters_read.latitude. */
#define ILAHRS_AHRS_PARAMETERS_READ_LONGITUDE_OFFSET 12     /**< Offset of ahrs_parameters_read.longitude. */
#define ILAHRS_AHRS_PARAMETERS_READ_LONGITUDE_SIZE 4        /**< Size of ahrs_parameters_read.longitude. */
#define ILAHRS_AHRS_PARAMETERS_READ_ALTITUDE_OFFSET 16      /**< Offset of ahrs_parameters_read.altitude. */
#define ILAHRS_AHRS_PARAMETERS_READ_ALTITUDE_SIZE 4         /**< Size of ahrs_parameters_read.altitude. */
#define ILAHRS_AHRS_PARAMETERS_READ_DATE_OFFSET 20          /**< Offset of ahrs_parameters_read.date. */
#define ILAHRS_AHRS_PARAMETERS_READ_DATE_SIZE 4             /**< Size of ahrs_parameters_read.date. */
#define ILAHRS_AHRS_PARAMETERS_READ_ALIGNMENT_ANGLE_A1_OFFSET \
    24                                                        /**< Offset of ahrs_parameters_read.alignment_angle_a1. */
#define ILAHRS_AHRS_PARAMETERS_READ_ALIGNMENT_ANGLE_A1_SIZE 4 /**< Size of ahrs_parameters_read.alignment_angle_a1. */
#define ILAHRS_AHRS_PARAMETERS_READ_ALIGNMENT_ANGLE_A2_OFFSET \
    28                                                        /**< Offset of ahrs_parameters_read.alignment_angle_a2. */
#define ILAHRS_AHRS_PARAMETERS_READ_ALIGNMENT_ANGLE_A2_SIZE 4 /**< Size of ahrs_parameters_read.alignment_angle_a2. */
#define ILAHRS_AHRS_PARAMETERS_READ_ALIGNMENT_ANGLE_A3_OFFSET \
    32                                                        /**< Offset of ahrs_parameters_read.alignment_angle_a3. */
#define ILAHRS_AHRS_PARAMETERS_READ_ALIGNMENT_ANGLE_A3_SIZE 4 /**< Size of ahrs_parameters_read.alignment_angle_a3. */
#define ILAHRS_AHRS_PARAMETERS_READ_DEVICE_ID_OFFSET 36       /**< Offset of ahrs_parameters_read.device_id. */
#define ILAHRS_AHRS_PARAMETERS_READ_DEVICE_ID_SIZE 8          /**< Size of ahrs_parameters_read.device_id. */
#define ILAHRS_AHRS_PARAMETERS_READ_RESERVED_OFFSET 44        /**< Offset of ahrs_parameters_read.reserved. */
#define ILAHRS_AHRS_PARAMETERS_READ_RESERVED_SIZE 6           /**< Size of ahrs_parameters_read.reserved. */

/** Parameters read (Table 6.10), 50 bytes, device to host. The AHRS answer to ReadAHRSPar
 *  (6.3.7). */
typedef struct ilahrs_ahrs_parameters_read {
    /** Output data rate. (hertz; builders accept 1..100; ICD: Measurement rate; erratum E24) */
    uint16_t update_rate;
    /** Initial alignment duration. (seconds; builders accept 1..65535; ICD: Initial alignment
     *  time; erratum E30) */
    uint16_t alignment_time;
    /** Magnetic declination; a value above 360 means the AHRS computes it. (degrees; encoding
     *  declination; ICD: Magnetic declination) */
    float declination;
    /** Latitude. (degrees; builders accept -90..90; ICD: Latitude) */
    float latitude;
    /** Longitude. (degrees; builders accept -180..180; ICD: Longitude) */
    float longitude;
    /** Altitude. (metres; builders accept -20000..100000; ICD: Altitude; erratum E31) */
    float altitude;
    /** Date as Year + (Month - 1)/12 + Day/365. (fractional year, see encoding `date`; builders
     *  accept 1900..2200; encoding date; ICD: Date (Year, Month, Day)) */
    float date;
    /** Mounting angle 1 (Appendix B). (degrees; builders accept -360..360; ICD: Alignment angle
     *  A1; erratum E31) */
    float alignment_angle_a1;
    /** Mounting angle 2 (Appendix B). (degrees; builders accept -360..360; ICD: Alignment angle
     *  A2; erratum E31) */
    float alignment_angle_a2;
    /** Mounting angle 3 (Appendix B). (degrees; builders accept -360..360; ICD: Alignment angle
     *  A3; erratum E31) */
    float alignment_angle_a3;
    /** Device identifier (read only). (8 bytes, NUL-padded on the wire; ICD: Device ID) */
    char device_id[8 + 1];
    /** (6 reserved bytes, kept verbatim; ICD: Reserved) */
    uint8_t reserved[6];
} ilahrs_ahrs_parameters_read_t;

/** Decode a 50-byte ahrs_parameters_read payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_ahrs_parameters_read_parse(const uint8_t *data, size_t len,
                                                     ilahrs_ahrs_parameters_read_t *out, ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_AHRS_PARAMETERS_READ, data, len, out, err);
}

/** Encode a ahrs_parameters_read payload (50 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_ahrs_parameters_read_build(const ilahrs_ahrs_parameters_read_t *in, uint8_t *out,
                                                       size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_AHRS_PARAMETERS_READ, in, out, cap, err);
}

/** Encode a ahrs_parameters_read payload in a data frame (50 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_ahrs_parameters_read_build_frame(const ilahrs_ahrs_parameters_read_t *in, uint8_t *out,
                                                             size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_AHRS_PARAMETERS_READ, in, out, cap, err);
}

/* ---- Firmware version (Table 6.11) ---- */

#define ILAHRS_FIRMWARE_VERSION_SIZE 50          /**< Size of a firmware_version payload. */
#define ILAHRS_FIRMWARE_VERSION_VERSION_OFFSET 0 /**< Offset of firmware_version.version. */
#define ILAHRS_FIRMWARE_VERSION_VERSION_SIZE 50  /**< Size of firmware_version.version. */

/** Firmware version (Table 6.11), 50 bytes, device to host. The AHRS answer to GetVerFirmware
 *  (6.3.10). */
typedef struct ilahrs_firmware_version {
    /** Firmware version text, NUL-padded. (50 bytes, NUL-padded on the wire; ICD: Firmware
     *  version) */
    char version[50 + 1];
} ilahrs_firmware_version_t;

/** Decode a 50-byte firmware_version payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_firmware_version_parse(const uint8_t *data, size_t len, ilahrs_firmware_version_t *out,
                                                 ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_FIRMWARE_VERSION, data, len, out, err);
}

/** Encode a firmware_version payload (50 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_firmware_version_build(const ilahrs_firmware_version_t *in, uint8_t *out, size_t cap,
                                                   ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_FIRMWARE_VERSION, in, out, cap, err);
}

/** Encode a firmware_version payload in a data frame (50 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_firmware_version_build_frame(const ilahrs_firmware_version_t *in, uint8_t *out, size_t cap,
                                                         ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_FIRMWARE_VERSION, in, out, cap, err);
}

/* ---- Built-in test answer (Table 6.12) ---- */

#define ILAHRS_BIT_RESULT_SIZE 4             /**< Size of a bit_result payload. */
#define ILAHRS_BIT_RESULT_UTERMO100_OFFSET 0 /**< Offset of bit_result.utermo100. */
#define ILAHRS_BIT_RESULT_UTERMO100_SIZE 2   /**< Size of bit_result.utermo100. */
#define ILAHRS_BIT_RESULT_USW_OFFSET 2       /**< Offset of bit_result.usw. */
#define ILAHRS_BIT_RESULT_USW_SIZE 2         /**< Size of bit_result.usw. */

/** Built-in test answer (Table 6.12), 4 bytes, device to host. The AHRS answer to GetBIT
 *  (6.3.11). */
typedef struct ilahrs_bit_result {
    /** AHRS temperature in 1/100 degC. (degrees Celsius = raw / 100; ICD: Utermo100; erratum E4) */
    int16_t utermo100;
    /** Unit Status Word (section 6.5). (encoding usw; ICD: USW) */
    uint16_t usw;
} ilahrs_bit_result_t;

/** Decode a 4-byte bit_result payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_bit_result_parse(const uint8_t *data, size_t len, ilahrs_bit_result_t *out,
                                           ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_BIT_RESULT, data, len, out, err);
}

/** Encode a bit_result payload (4 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_bit_result_build(const ilahrs_bit_result_t *in, uint8_t *out, size_t cap,
                                             ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_BIT_RESULT, in, out, cap, err);
}

/** Encode a bit_result payload in a data frame (4 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_bit_result_build_frame(const ilahrs_bit_result_t *in, uint8_t *out, size_t cap,
                                                   ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_BIT_RESULT, in, out, cap, err);
}

/** bit_result.utermo100 in degrees Celsius: raw / 100. */
static inline float ilahrs_bit_result_utermo100_degc(const ilahrs_bit_result_t *m)
{
    return (float)m->utermo100 / 100.0f;
}

/* ---- Calibration parameters (Table 6.13) ---- */

#define ILAHRS_CALIBRATION_PARAMETERS_SIZE 22 /**< Size of a calibration_parameters payload. */
#define ILAHRS_CALIBRATION_PARAMETERS_REFERENCE_AZIMUTH_OFFSET \
    0 /**< Offset of calibration_parameters.reference_azimuth. */
#define ILAHRS_CALIBRATION_PARAMETERS_REFERENCE_AZIMUTH_SIZE 4 /**< Size of calibration_parameters.reference_azimuth. \
                                                                */
#define ILAHRS_CALIBRATION_PARAMETERS_ACCUMULATION_TIME_OFFSET \
    4 /**< Offset of calibration_parameters.accumulation_time. */
#define ILAHRS_CALIBRATION_PARAMETERS_ACCUMULATION_TIME_SIZE 2 /**< Size of calibration_parameters.accumulation_time. \
                                                                */
#define ILAHRS_CALIBRATION_PARAMETERS_LATITUDE_OFFSET 6        /**< Offset of calibration_parameters.latitude. */
#define ILAHRS_CALIBRATION_PARAMETERS_LATITUDE_SIZE 4          /**< Size of calibration_parameters.latitude. */
#define ILAHRS_CALIBRATION_PARAMETERS_LONGITUDE_OFFSET 10      /**< Offset of calibration_parameters.longitude. */
#define ILAHRS_CALIBRATION_PARAMETERS_LONGITUDE_SIZE 4         /**< Size of calibration_parameters.longitude. */
#define ILAHRS_CALIBRATION_PARAMETERS_ALTITUDE_OFFSET 14       /**< Offset of calibration_parameters.altitude. */
#define ILAHRS_CALIBRATION_PARAMETERS_ALTITUDE_SIZE 4          /**< Size of calibration_parameters.altitude. */
#define ILAHRS_CALIBRATION_PARAMETERS_DATE_OFFSET 18           /**< Offset of calibration_parameters.date. */
#define ILAHRS_CALIBRATION_PARAMETERS_DATE_SIZE 4              /**< Size of calibration_parameters.date. */

/** Calibration parameters (Table 6.13), 22 bytes, host to device. The data message the host
 *  sends right after Start3DClb, Start2D2TClb or Start2DClb (6.4.1, 6.4.5, 6.4.8). */
typedef struct ilahrs_calibration_parameters {
    /** Reference azimuth (6.4.8); no influence on 2D calibration. (degrees; builders accept
     *  -360..360; ICD: Reserved; erratum E8) */
    float reference_azimuth;
    /** Data accumulation time of one run. (seconds; builders accept 1..65535; ICD: Time of data
     *  accumulation in one run; erratum E30) */
    uint16_t accumulation_time;
    /** Latitude. (degrees; builders accept -90..90; ICD: Latitude) */
    float latitude;
    /** Longitude. (degrees; builders accept -180..180; ICD: Longitude) */
    float longitude;
    /** Altitude. (metres; builders accept -20000..100000; ICD: Altitude; erratum E31) */
    float altitude;
    /** Date as Year + (Month - 1)/12 + Day/365. (fractional year, see encoding `date`; builders
     *  accept 1900..2200; encoding date; ICD: Date (Year, Month, Day)) */
    float date;
} ilahrs_calibration_parameters_t;

/** Decode a 22-byte calibration_parameters payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_calibration_parameters_parse(const uint8_t *data, size_t len,
                                                       ilahrs_calibration_parameters_t *out, ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, data, len, out, err);
}

/** Encode a calibration_parameters payload (22 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_calibration_parameters_build(const ilahrs_calibration_parameters_t *in, uint8_t *out,
                                                         size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, in, out, cap, err);
}

/** Encode a calibration_parameters payload in a data frame (22 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_calibration_parameters_build_frame(const ilahrs_calibration_parameters_t *in, uint8_t *out,
                                                               size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, in, out, cap, err);
}

/* ---- Calibration result (Table 6.14, erratum E1) ---- */

#define ILAHRS_CALIBRATION_RESULT_SIZE 52                   /**< Size of a calibration_result payload. */
#define ILAHRS_CALIBRATION_RESULT_CALIBRATION_TYPE_OFFSET 0 /**< Offset of calibration_result.calibration_type. */
#define ILAHRS_CALIBRATION_RESULT_CALIBRATION_TYPE_SIZE 1   /**< Size of calibration_result.calibration_type. */
#define ILAHRS_CALIBRATION_RESULT_RUNS_USED_OFFSET 1        /**< Offset of calibration_result.runs_used. */
#define ILAHRS_CALIBRATION_RESULT_RUNS_USED_SIZE 1          /**< Size of calibration_result.runs_used. */
#define ILAHRS_CALIBRATION_RESULT_DATA_USED_OFFSET 2        /**< Offset of calibration_result.data_used. */
#define ILAHRS_CALIBRATION_RESULT_DATA_USED_SIZE 1          /**< Size of calibration_result.data_used. */
#define ILAHRS_CALIBRATION_RESULT_SUCCESS_OFFSET 3          /**< Offset of calibration_result.success. */
#define ILAHRS_CALIBRATION_RESULT_SUCCESS_SIZE 1            /**< Size of calibration_result.success. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_11_OFFSET 4          /**< Offset of calibration_result.tm_c_11. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_11_SIZE 4            /**< Size of calibration_result.tm_c_11. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_12_OFFSET 8          /**< Offset of calibration_result.tm_c_12. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_12_SIZE 4            /**< Size of calibration_result.tm_c_12. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_13_OFFSET 12         /**< Offset of calibration_result.tm_c_13. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_13_SIZE 4            /**< Size of calibration_result.tm_c_13. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_21_OFFSET 16         /**< Offset of calibration_result.tm_c_21. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_21_SIZE 4            /**< Size of calibration_result.tm_c_21. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_22_OFFSET 20         /**< Offset of calibration_result.tm_c_22. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_22_SIZE 4            /**< Size of calibration_result.tm_c_22. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_23_OFFSET 24         /**< Offset of calibration_result.tm_c_23. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_23_SIZE 4            /**< Size of calibration_result.tm_c_23. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_31_OFFSET 28         /**< Offset of calibration_result.tm_c_31. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_31_SIZE 4            /**< Size of calibration_result.tm_c_31. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_32_OFFSET 32         /**< Offset of calibration_result.tm_c_32. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_32_SIZE 4            /**< Size of calibration_result.tm_c_32. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_33_OFFSET 36         /**< Offset of calibration_result.tm_c_33. */
#define ILAHRS_CALIBRATION_RESULT_TM_C_33_SIZE 4            /**< Size of calibration_result.tm_c_33. */
#define ILAHRS_CALIBRATION_RESULT_HM_0_X_OFFSET 40          /**< Offset of calibration_result.hm_0_x. */
#define ILAHRS_CALIBRATION_RESULT_HM_0_X_SIZE 4             /**< Size of calibration_result.hm_0_x. */
#define ILAHRS_CALIBRATION_RESULT_HM_0_Y_OFFSET 44          /**< Offset of calibration_result.hm_0_y. */
#define ILAHRS_CALIBRATION_RESULT_HM_0_Y_SIZE 4             /**< Size of calibration_result.hm_0_y. */
#define ILAHRS_CALIBRATION_RESULT_HM_0_Z_OFFSET 48          /**< Offset of calibration_result.hm_0_z. */
#define ILAHRS_CALIBRATION_RESULT_HM_0_Z_SIZE 4             /**< Size of calibration_result.hm_0_z. */

/** Calibration result (Table 6.14), 52 bytes, device to host. Sent when a calibration completes
 *  (after the accumulation time, StopClbRun, or FinishClb). */
typedef struct ilahrs_calibration_result {
    /** 1 for 2D, 2 for 2D-2T, 3 for 3D calibration. (builders accept 1..3; ICD: Type of
     *  calibration) */
    uint8_t calibration_type;
    /** Number of calibration runs used. (ICD: Number of used calibration runs) */
    uint8_t runs_used;
    /** Percent of data points used (2D and 3D calibrations only). (percent; builders accept
     *  0..100; ICD: Percent of used data points) */
    uint8_t data_used;
    /** 0: not successful; 1..254: predicted 3-sigma heading error in deg*10; 255: successful
     *  without an estimate. (encoding calibration_success; ICD: Calibration success; erratum
     *  E26) */
    uint8_t success;
    /** Soft-iron matrix Tm_c row 1 column 1. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_11;
    /** Soft-iron matrix Tm_c row 1 column 2. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_12;
    /** Soft-iron matrix Tm_c row 1 column 3. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_13;
    /** Soft-iron matrix Tm_c row 2 column 1. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_21;
    /** Soft-iron matrix Tm_c row 2 column 2. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_22;
    /** Soft-iron matrix Tm_c row 2 column 3. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_23;
    /** Soft-iron matrix Tm_c row 3 column 1. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_31;
    /** Soft-iron matrix Tm_c row 3 column 2. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_32;
    /** Soft-iron matrix Tm_c row 3 column 3. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_33;
    /** Hard-iron vector Hm_0 component 1. (ADC codes (no physical scale given by the ICD); ICD:
     *  Matrix for hard iron correction; erratum E1) */
    float hm_0_x;
    /** Hard-iron vector Hm_0 component 2. (ADC codes (no physical scale given by the ICD); ICD:
     *  Matrix for hard iron correction; erratum E1) */
    float hm_0_y;
    /** Hard-iron vector Hm_0 component 3. (ADC codes (no physical scale given by the ICD); ICD:
     *  Matrix for hard iron correction; erratum E1) */
    float hm_0_z;
} ilahrs_calibration_result_t;

/** Decode a 52-byte calibration_result payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_calibration_result_parse(const uint8_t *data, size_t len, ilahrs_calibration_result_t *out,
                                                   ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_CALIBRATION_RESULT, data, len, out, err);
}

/** Encode a calibration_result payload (52 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_calibration_result_build(const ilahrs_calibration_result_t *in, uint8_t *out, size_t cap,
                                                     ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_CALIBRATION_RESULT, in, out, cap, err);
}

/** Encode a calibration_result payload in a data frame (52 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_calibration_result_build_frame(const ilahrs_calibration_result_t *in, uint8_t *out,
                                                           size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_CALIBRATION_RESULT, in, out, cap, err);
}

/* ---- 2D-2T calibration run result (Table 6.15) ---- */

#define ILAHRS_CALIBRATION_RUN_RESULT_SIZE 30 /**< Size of a calibration_run_result payload. */
#define ILAHRS_CALIBRATION_RUN_RESULT_CALIBRATION_TYPE_OFFSET \
    0                                                         /**< Offset of calibration_run_result.calibration_type. */
#define ILAHRS_CALIBRATION_RUN_RESULT_CALIBRATION_TYPE_SIZE 1 /**< Size of calibration_run_result.calibration_type. */
#define ILAHRS_CALIBRATION_RUN_RESULT_RUN_OFFSET 1            /**< Offset of calibration_run_result.run. */
#define ILAHRS_CALIBRATION_RUN_RESULT_RUN_SIZE 1              /**< Size of calibration_run_result.run. */
#define ILAHRS_CALIBRATION_RUN_RESULT_DATA_USED_OFFSET 2      /**< Offset of calibration_run_result.data_used. */
#define ILAHRS_CALIBRATION_RUN_RESULT_DATA_USED_SIZE 1        /**< Size of calibration_run_result.data_used. */
#define ILAHRS_CALIBRATION_RUN_RESULT_SUCCESS_OFFSET 3        /**< Offset of calibration_run_result.success. */
#define ILAHRS_CALIBRATION_RUN_RESULT_SUCCESS_SIZE 1          /**< Size of calibration_run_result.success. */
#define ILAHRS_CALIBRATION_RUN_RESULT_RESERVED_1_OFFSET 4     /**< Offset of calibration_run_result.reserved_1. */
#define ILAHRS_CALIBRATION_RUN_RESULT_RESERVED_1_SIZE 4       /**< Size of calibration_run_result.reserved_1. */
#define ILAHRS_CALIBRATION_RUN_RESULT_AVERAGE_PITCH_OFFSET 8  /**< Offset of calibration_run_result.average_pitch. */
#define ILAHRS_CALIBRATION_RUN_RESULT_AVERAGE_PITCH_SIZE 4    /**< Size of calibration_run_result.average_pitch. */
#define ILAHRS_CALIBRATION_RUN_RESULT_AVERAGE_ROLL_OFFSET 12  /**< Offset of calibration_run_result.average_roll. */
#define ILAHRS_CALIBRATION_RUN_RESULT_AVERAGE_ROLL_SIZE 4     /**< Size of calibration_run_result.average_roll. */
#define ILAHRS_CALIBRATION_RUN_RESULT_RESERVED_2_OFFSET 16    /**< Offset of calibration_run_result.reserved_2. */
#define ILAHRS_CALIBRATION_RUN_RESULT_RESERVED_2_SIZE 12      /**< Size of calibration_run_result.reserved_2. */
#define ILAHRS_CALIBRATION_RUN_RESULT_USW_OFFSET 28           /**< Offset of calibration_run_result.usw. */
#define ILAHRS_CALIBRATION_RUN_RESULT_USW_SIZE 2              /**< Size of calibration_run_result.usw. */

/** 2D-2T calibration run result (Table 6.15), 30 bytes, device to host. Sent after each run of a
 *  2D-2T calibration (6.4.5). */
typedef struct ilahrs_calibration_run_result {
    /** 2 for 2D-2T calibration. (builders accept 2..2; ICD: Type of calibration) */
    uint8_t calibration_type;
    /** Number of this run (1, 2, ...). (builders accept 1..255; ICD: Calibration run) */
    uint8_t run;
    /** Percent of data points used. (percent; builders accept 0..100; ICD: Percent of used data
     *  points) */
    uint8_t data_used;
    /** 0: run not successful (excluded); 1..254: predicted heading error in deg*10; 255:
     *  successful without an estimate. (encoding calibration_success; ICD: Calibration success;
     *  erratum E26) */
    uint8_t success;
    /** (4 reserved bytes, kept verbatim; ICD: Reserved; erratum E32) */
    uint8_t reserved_1[4];
    /** Average pitch during the run. (degrees; builders accept -90..90; ICD: Average pitch, deg) */
    float average_pitch;
    /** Average roll during the run. (degrees; builders accept -180..180; ICD: Average roll, deg) */
    float average_roll;
    /** (12 reserved bytes, kept verbatim; ICD: Reserved; erratum E32) */
    uint8_t reserved_2[12];
    /** Unit Status Word (section 6.5). (encoding usw; ICD: USW) */
    uint16_t usw;
} ilahrs_calibration_run_result_t;

/** Decode a 30-byte calibration_run_result payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_calibration_run_result_parse(const uint8_t *data, size_t len,
                                                       ilahrs_calibration_run_result_t *out, ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_CALIBRATION_RUN_RESULT, data, len, out, err);
}

/** Encode a calibration_run_result payload (30 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_calibration_run_result_build(const ilahrs_calibration_run_result_t *in, uint8_t *out,
                                                         size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_CALIBRATION_RUN_RESULT, in, out, cap, err);
}

/** Encode a calibration_run_result payload in a data frame (30 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_calibration_run_result_build_frame(const ilahrs_calibration_run_result_t *in, uint8_t *out,
                                                               size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_CALIBRATION_RUN_RESULT, in, out, cap, err);
}

/* ---- Calibration run parameters (Table 6.16) ---- */

#define ILAHRS_CALIBRATION_RUN_PARAMETERS_SIZE 6            /**< Size of a calibration_run_parameters payload. */
#define ILAHRS_CALIBRATION_RUN_PARAMETERS_RESERVED_OFFSET 0 /**< Offset of calibration_run_parameters.reserved. */
#define ILAHRS_CALIBRATION_RUN_PARAMETERS_RESERVED_SIZE 6   /**< Size of calibration_run_parameters.reserved. */

/** Calibration run parameters (Table 6.16), 6 bytes, host to device. The data message the host
 *  sends right after StartClbRun (6.4.6); its 6 bytes do not influence 2D-2T calibration and may
 *  be any, e.g. zeros. */
typedef struct ilahrs_calibration_run_parameters {
    /** (6 reserved bytes, kept verbatim; ICD: Reserved; erratum E32) */
    uint8_t reserved[6];
} ilahrs_calibration_run_parameters_t;

/** Decode a 6-byte calibration_run_parameters payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_calibration_run_parameters_parse(const uint8_t *data, size_t len,
                                                           ilahrs_calibration_run_parameters_t *out,
                                                           ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_CALIBRATION_RUN_PARAMETERS, data, len, out, err);
}

/** Encode a calibration_run_parameters payload (6 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_calibration_run_parameters_build(const ilahrs_calibration_run_parameters_t *in,
                                                             uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_CALIBRATION_RUN_PARAMETERS, in, out, cap, err);
}

/** Encode a calibration_run_parameters payload in a data frame (6 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_calibration_run_parameters_build_frame(const ilahrs_calibration_run_parameters_t *in,
                                                                   uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_CALIBRATION_RUN_PARAMETERS, in, out, cap, err);
}

/* ---- Calibration results read back (Table 6.17, erratum E2) ---- */

#define ILAHRS_CALIBRATION_STATUS_SIZE 52                   /**< Size of a calibration_status payload. */
#define ILAHRS_CALIBRATION_STATUS_CALIBRATION_TYPE_OFFSET 0 /**< Offset of calibration_status.calibration_type. */
#define ILAHRS_CALIBRATION_STATUS_CALIBRATION_TYPE_SIZE 1   /**< Size of calibration_status.calibration_type. */
#define ILAHRS_CALIBRATION_STATUS_RUNS_USED_OFFSET 1        /**< Offset of calibration_status.runs_used. */
#define ILAHRS_CALIBRATION_STATUS_RUNS_USED_SIZE 1          /**< Size of calibration_status.runs_used. */
#define ILAHRS_CALIBRATION_STATUS_RESERVED_OFFSET 2         /**< Offset of calibration_status.reserved. */
#define ILAHRS_CALIBRATION_STATUS_RESERVED_SIZE 1           /**< Size of calibration_status.reserved. */
#define ILAHRS_CALIBRATION_STATUS_SUCCESS_OFFSET 3          /**< Offset of calibration_status.success. */
#define ILAHRS_CALIBRATION_STATUS_SUCCESS_SIZE 1            /**< Size of calibration_status.success. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_11_OFFSET 4          /**< Offset of calibration_status.tm_c_11. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_11_SIZE 4            /**< Size of calibration_status.tm_c_11. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_12_OFFSET 8          /**< Offset of calibration_status.tm_c_12. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_12_SIZE 4            /**< Size of calibration_status.tm_c_12. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_13_OFFSET 12         /**< Offset of calibration_status.tm_c_13. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_13_SIZE 4            /**< Size of calibration_status.tm_c_13. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_21_OFFSET 16         /**< Offset of calibration_status.tm_c_21. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_21_SIZE 4            /**< Size of calibration_status.tm_c_21. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_22_OFFSET 20         /**< Offset of calibration_status.tm_c_22. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_22_SIZE 4            /**< Size of calibration_status.tm_c_22. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_23_OFFSET 24         /**< Offset of calibration_status.tm_c_23. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_23_SIZE 4            /**< Size of calibration_status.tm_c_23. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_31_OFFSET 28         /**< Offset of calibration_status.tm_c_31. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_31_SIZE 4            /**< Size of calibration_status.tm_c_31. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_32_OFFSET 32         /**< Offset of calibration_status.tm_c_32. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_32_SIZE 4            /**< Size of calibration_status.tm_c_32. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_33_OFFSET 36         /**< Offset of calibration_status.tm_c_33. */
#define ILAHRS_CALIBRATION_STATUS_TM_C_33_SIZE 4            /**< Size of calibration_status.tm_c_33. */
#define ILAHRS_CALIBRATION_STATUS_HM_0_X_OFFSET 40          /**< Offset of calibration_status.hm_0_x. */
#define ILAHRS_CALIBRATION_STATUS_HM_0_X_SIZE 4             /**< Size of calibration_status.hm_0_x. */
#define ILAHRS_CALIBRATION_STATUS_HM_0_Y_OFFSET 44          /**< Offset of calibration_status.hm_0_y. */
#define ILAHRS_CALIBRATION_STATUS_HM_0_Y_SIZE 4             /**< Size of calibration_status.hm_0_y. */
#define ILAHRS_CALIBRATION_STATUS_HM_0_Z_OFFSET 48          /**< Offset of calibration_status.hm_0_z. */
#define ILAHRS_CALIBRATION_STATUS_HM_0_Z_SIZE 4             /**< Size of calibration_status.hm_0_z. */

/** Calibration results read back (Table 6.17), 52 bytes, device to host. The AHRS answer to
 *  GetClbRes (6.4.10). */
typedef struct ilahrs_calibration_status {
    /** 0: not calibrated; 1: 2D; 2: 2D-2T; 3: 3D; above 0x80: parameters loaded by other
     *  software. (ICD: Type of calibration performed) */
    uint8_t calibration_type;
    /** Number of calibration runs used. (ICD: Number of used calibration runs) */
    uint8_t runs_used;
    /** (1 reserved bytes, kept verbatim; ICD: Reserved; erratum E3) */
    uint8_t reserved[1];
    /** 0: not successful; 1..254: predicted heading error in deg*10; 255: successful without an
     *  estimate. (encoding calibration_success; ICD: Calibration success; erratum E26) */
    uint8_t success;
    /** Soft-iron matrix Tm_c row 1 column 1. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_11;
    /** Soft-iron matrix Tm_c row 1 column 2. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_12;
    /** Soft-iron matrix Tm_c row 1 column 3. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_13;
    /** Soft-iron matrix Tm_c row 2 column 1. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_21;
    /** Soft-iron matrix Tm_c row 2 column 2. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_22;
    /** Soft-iron matrix Tm_c row 2 column 3. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_23;
    /** Soft-iron matrix Tm_c row 3 column 1. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_31;
    /** Soft-iron matrix Tm_c row 3 column 2. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_32;
    /** Soft-iron matrix Tm_c row 3 column 3. (dimensionless; ICD: Matrix for soft iron
     *  correction) */
    float tm_c_33;
    /** Hard-iron vector Hm_0 component 1. (ADC codes (no physical scale given by the ICD); ICD:
     *  Matrix for hard iron correction; erratum E2) */
    float hm_0_x;
    /** Hard-iron vector Hm_0 component 2. (ADC codes (no physical scale given by the ICD); ICD:
     *  Matrix for hard iron correction; erratum E2) */
    float hm_0_y;
    /** Hard-iron vector Hm_0 component 3. (ADC codes (no physical scale given by the ICD); ICD:
     *  Matrix for hard iron correction; erratum E2) */
    float hm_0_z;
} ilahrs_calibration_status_t;

/** Decode a 52-byte calibration_status payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_calibration_status_parse(const uint8_t *data, size_t len, ilahrs_calibration_status_t *out,
                                                   ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_CALIBRATION_STATUS, data, len, out, err);
}

/** Encode a calibration_status payload (52 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_calibration_status_build(const ilahrs_calibration_status_t *in, uint8_t *out, size_t cap,
                                                     ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_CALIBRATION_STATUS, in, out, cap, err);
}

/** Encode a calibration_status payload in a data frame (52 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_calibration_status_build_frame(const ilahrs_calibration_status_t *in, uint8_t *out,
                                                           size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_CALIBRATION_STATUS, in, out, cap, err);
}

/* ---- Acknowledgement (6.3.1 (Table 6.2 with a one-word payload)) ---- */

#define ILAHRS_ACKNOWLEDGEMENT_SIZE 2            /**< Size of a acknowledgement payload. */
#define ILAHRS_ACKNOWLEDGEMENT_CHECKSUM_OFFSET 0 /**< Offset of acknowledgement.checksum. */
#define ILAHRS_ACKNOWLEDGEMENT_CHECKSUM_SIZE 2   /**< Size of acknowledgement.checksum. */

/** Acknowledgement (6.3.1 (Table 6.2 with a one-word payload)), 2 bytes, device to host. The
 *  checksum of the message the AHRS received (E12). */
typedef struct ilahrs_acknowledgement {
    /** Checksum of the acknowledged message, message type through payload. (ICD: Check sum) */
    uint16_t checksum;
} ilahrs_acknowledgement_t;

/** Decode a 2-byte acknowledgement payload. See ilahrs_payload_parse(). */
static inline bool ilahrs_acknowledgement_parse(const uint8_t *data, size_t len, ilahrs_acknowledgement_t *out,
                                                ilahrs_error_t *err)
{
    return ilahrs_payload_parse(ILAHRS_PAYLOAD_ACKNOWLEDGEMENT, data, len, out, err);
}

/** Encode a acknowledgement payload (2 bytes). See ilahrs_payload_build(). */
static inline size_t ilahrs_acknowledgement_build(const ilahrs_acknowledgement_t *in, uint8_t *out, size_t cap,
                                                  ilahrs_error_t *err)
{
    return ilahrs_payload_build(ILAHRS_PAYLOAD_ACKNOWLEDGEMENT, in, out, cap, err);
}

/** Encode a acknowledgement payload in a data frame (2 + ILAHRS_FRAME_OVERHEAD bytes). */
static inline size_t ilahrs_acknowledgement_build_frame(const ilahrs_acknowledgement_t *in, uint8_t *out, size_t cap,
                                                        ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_ACKNOWLEDGEMENT, in, out, cap, err);
}

/* ======================================================================================== */
/* Commands (Appendix C, Table C.1)                                                         */
/* ======================================================================================== */

/** The operating modes (section 6.1). */
typedef enum ilahrs_mode {
    /** All sensors powered; the AHRS waits for a command. Indicator red. The mode after power-up
     *  (6.3). (6.1 (1)) */
    ILAHRS_MODE_IDLE = 0,
    /** Endless output of data blocks at the configured update rate. Indicator green. (6.1 (2)) */
    ILAHRS_MODE_CONTINUOUS = 1,
    /** One data block after each GetDataReq. Indicator green. (6.1 (3)) */
    ILAHRS_MODE_ON_REQUEST = 2,
    /** Embedded hard- and soft-iron calibration procedure. (6.1 (4), 6.4) */
    ILAHRS_MODE_CALIBRATION = 3,
    /** Low-power mode; no output; the AHRS waits for LowPowerOff. Indicator off. (6.1 (5)) */
    ILAHRS_MODE_SLEEP = 4,
} ilahrs_mode_t;

/** Number of operating modes. */
#define ILAHRS_MODE_COUNT 5
/** The bit of `mode` in a mode set (ilahrs_command_valid_in()). */
#define ILAHRS_MODE_BIT(mode) (1u << (unsigned)(mode))

/** Every command of Table C.1, in the table's order. */
typedef enum ilahrs_command {
    /** AHRScont1 (0x80, 6.3.1): Start continuous output in the Full Output Data format (Table 6.4). */
    ILAHRS_COMMAND_AHRS_CONT1 = 0,
    /** AHRScont2 (0x82, 6.3.1): Start continuous output in the Quaternion of Orientation format (Table 6.5). */
    ILAHRS_COMMAND_AHRS_CONT2 = 1,
    /** AHRScont3 (0x83, 6.3.1): Start continuous output in the Orientation + Sensor Outputs format (Table 6.6). */
    ILAHRS_COMMAND_AHRS_CONT3 = 2,
    /** AHRSreq1 (0x84, 6.3.2): Start on-request output in the Full Output Data format (Table 6.4). */
    ILAHRS_COMMAND_AHRS_REQ1 = 3,
    /** AHRSreq2 (0x86, 6.3.2): Start on-request output in the Quaternion of Orientation format (Table 6.5). */
    ILAHRS_COMMAND_AHRS_REQ2 = 4,
    /** AHRSreq3 (0x87, 6.3.2): Start on-request output in the Orientation + Sensor Outputs format (Table 6.6). */
    ILAHRS_COMMAND_AHRS_REQ3 = 5,
    /** NMEAcont (0x88, 6.3.3): Start continuous output of $PAHR sentences (Table 6.7), at most 50 Hz. */
    ILAHRS_COMMAND_NMEA_CONT = 6,
    /** NMEAreq (0x89, 6.3.3): Start on-request output of $PAHR sentences (Table 6.7). */
    ILAHRS_COMMAND_NMEA_REQ = 7,
    /** GetDataReq (0xCA, 6.3.4): Ask for one block of the current output format in the On Request mode. */
    ILAHRS_COMMAND_GET_DATA_REQ = 8,
    /** Stop (0xFE, 6.3.5): Stop the current operating mode and go to idle. */
    ILAHRS_COMMAND_STOP = 9,
    /** LoadAHRSPar (0x40, 6.3.6): Load the user parameter block (Table 6.9) into non-volatile memory. */
    ILAHRS_COMMAND_LOAD_AHRS_PAR = 10,
    /** ReadAHRSPar (0x41, 6.3.7): Read the parameter block (Table 6.10) from non-volatile memory. */
    ILAHRS_COMMAND_READ_AHRS_PAR = 11,
    /** LowPowerOn (0xB0, 6.3.8): Switch to the low-power Sleep mode. */
    ILAHRS_COMMAND_LOW_POWER_ON = 12,
    /** LowPowerOff (0xBA, 6.3.9): Wake from Sleep mode into idle. */
    ILAHRS_COMMAND_LOW_POWER_OFF = 13,
    /** GetVerFirmware (0x1F, 6.3.10): Read the firmware version string (Table 6.11). */
    ILAHRS_COMMAND_GET_VER_FIRMWARE = 14,
    /** GetBIT (0x1A, 6.3.11): Read the built-in-test answer, temperature and Unit Status Word (Table 6.12). */
    ILAHRS_COMMAND_GET_BIT = 15,
    /** Start2DClb (0x21, 6.4.8): Start 2D hard/soft-iron calibration; the calibration parameter block (Table 6.13)
     * follows. */
    ILAHRS_COMMAND_START_2D_CLB = 16,
    /** Start2D2TClb (0x22, 6.4.5): Start 2D-2T (multi-run) calibration; the calibration parameter block (Table 6.13)
     * follows. */
    ILAHRS_COMMAND_START_2D2T_CLB = 17,
    /** Start3DClb (0x23, 6.4.1): Start 3D calibration; the calibration parameter block (Table 6.13) follows. */
    ILAHRS_COMMAND_START_3D_CLB = 18,
    /** StartClbRun (0x2B, 6.4.6): Start one run of a multi-run (2D-2T) calibration; the run parameter block
     * (Table 6.16) follows. */
    ILAHRS_COMMAND_START_CLB_RUN = 19,
    /** StopClbRun (0x20, 6.4.2): Stop data accumulation in the current calibration run before its set time. */
    ILAHRS_COMMAND_STOP_CLB_RUN = 20,
    /** FinishClb (0x2C, 6.4.7): Finish a multi-run (2D-2T) calibration and compute its result (Table 6.14). */
    ILAHRS_COMMAND_FINISH_CLB = 21,
    /** AcceptClb (0x2E, 6.4.3): Accept the calibration result and save it to non-volatile memory; go to idle. */
    ILAHRS_COMMAND_ACCEPT_CLB = 22,
    /** ExitClb (0xFE, 6.4.4): Leave calibration without computing or saving anything; go to idle. */
    ILAHRS_COMMAND_EXIT_CLB = 23,
    /** ClearClb (0x2F, 6.4.9): Clear the hard/soft-iron calibration parameters from non-volatile memory. */
    ILAHRS_COMMAND_CLEAR_CLB = 24,
    /** GetClbRes (0x2A, 6.4.10): Read the results of the last calibration (Table 6.17). */
    ILAHRS_COMMAND_GET_CLB_RES = 25,
} ilahrs_command_t;

/** Number of commands. */
#define ILAHRS_COMMAND_COUNT 26
/** Most commands that share one code (0xFE is both Stop and ExitClb, E14). */
#define ILAHRS_COMMANDS_PER_CODE_MAX 2
#define ILAHRS_CODE_AHRS_CONT1 0x80u       /**< Code of AHRScont1. */
#define ILAHRS_CODE_AHRS_CONT2 0x82u       /**< Code of AHRScont2. */
#define ILAHRS_CODE_AHRS_CONT3 0x83u       /**< Code of AHRScont3. */
#define ILAHRS_CODE_AHRS_REQ1 0x84u        /**< Code of AHRSreq1. */
#define ILAHRS_CODE_AHRS_REQ2 0x86u        /**< Code of AHRSreq2. */
#define ILAHRS_CODE_AHRS_REQ3 0x87u        /**< Code of AHRSreq3. */
#define ILAHRS_CODE_NMEA_CONT 0x88u        /**< Code of NMEAcont. */
#define ILAHRS_CODE_NMEA_REQ 0x89u         /**< Code of NMEAreq. */
#define ILAHRS_CODE_GET_DATA_REQ 0xCAu     /**< Code of GetDataReq. */
#define ILAHRS_CODE_STOP 0xFEu             /**< Code of Stop. */
#define ILAHRS_CODE_LOAD_AHRS_PAR 0x40u    /**< Code of LoadAHRSPar. */
#define ILAHRS_CODE_READ_AHRS_PAR 0x41u    /**< Code of ReadAHRSPar. */
#define ILAHRS_CODE_LOW_POWER_ON 0xB0u     /**< Code of LowPowerOn. */
#define ILAHRS_CODE_LOW_POWER_OFF 0xBAu    /**< Code of LowPowerOff. */
#define ILAHRS_CODE_GET_VER_FIRMWARE 0x1Fu /**< Code of GetVerFirmware. */
#define ILAHRS_CODE_GET_BIT 0x1Au          /**< Code of GetBIT. */
#define ILAHRS_CODE_START_2D_CLB 0x21u     /**< Code of Start2DClb. */
#define ILAHRS_CODE_START_2D2T_CLB 0x22u   /**< Code of Start2D2TClb. */
#define ILAHRS_CODE_START_3D_CLB 0x23u     /**< Code of Start3DClb. */
#define ILAHRS_CODE_START_CLB_RUN 0x2Bu    /**< Code of StartClbRun. */
#define ILAHRS_CODE_STOP_CLB_RUN 0x20u     /**< Code of StopClbRun. */
#define ILAHRS_CODE_FINISH_CLB 0x2Cu       /**< Code of FinishClb. */
#define ILAHRS_CODE_ACCEPT_CLB 0x2Eu       /**< Code of AcceptClb. */
#define ILAHRS_CODE_EXIT_CLB 0xFEu         /**< Code of ExitClb. */
#define ILAHRS_CODE_CLEAR_CLB 0x2Fu        /**< Code of ClearClb. */
#define ILAHRS_CODE_GET_CLB_RES 0x2Au      /**< Code of GetClbRes. */

/** What the AHRS sends back to a command. */
typedef enum ilahrs_response {
    ILAHRS_RESPONSE_NONE = 0, /**< Nothing. */
    ILAHRS_RESPONSE_ACK =
        1, /**< An acknowledgement: a data frame carrying the checksum of the received message (ilahrs_ack_build()). */
    ILAHRS_RESPONSE_OUTPUT = 2, /**< One block of the current output format. */
    ILAHRS_RESPONSE_DATA = 3,   /**< A data block of a payload table (ilahrs_command_response_payload()). */
} ilahrs_response_t;

/** Most payload tables a command's data response may follow. */
#define ILAHRS_RESPONSE_PAYLOADS_MAX 2

/** A decoded command frame: its code and every command with that code, sorted by name. */
typedef struct ilahrs_command_match {
    uint8_t code;                                            /**< The command code. */
    uint8_t count;                                           /**< Entries in `commands`. */
    ilahrs_command_t commands[ILAHRS_COMMANDS_PER_CODE_MAX]; /**< Sorted by ICD name. */
} ilahrs_command_match_t;

#if ILAHRS_NAMES
/** The spec name of a mode ("idle"); NULL for a value outside ilahrs_mode_t. */
const char *ilahrs_mode_name(ilahrs_mode_t mode);

/** The ICD name of a command ("AHRScont1"); NULL for a value outside ilahrs_command_t. */
const char *ilahrs_command_name(ilahrs_command_t command);

/**
 * Find a command by its ICD name (exact spelling, e.g. "GetBIT"), `len` characters at `name`.
 * @return true and `*command` set if found; false (`unknown_command`) otherwise
 */
bool ilahrs_command_by_name(const char *name, size_t len, ilahrs_command_t *command, ilahrs_error_t *err);
#endif

/** The code of a command; 0 for a value outside ilahrs_command_t. */
uint8_t ilahrs_command_code(ilahrs_command_t command);

/** The modes in which the AHRS accepts a command, as ILAHRS_MODE_BIT()s; 0 for an unknown command. */
uint8_t ilahrs_command_valid_in(ilahrs_command_t command);

/** What the AHRS answers to a command. */
ilahrs_response_t ilahrs_command_response(ilahrs_command_t command);

/**
 * Payload table `index` (0..ILAHRS_RESPONSE_PAYLOADS_MAX-1) a data response to `command` may
 * follow (StopClbRun: a calibration result or a run result), or ILAHRS_PAYLOAD_NONE.
 */
ilahrs_payload_t ilahrs_command_response_payload(ilahrs_command_t command, size_t index);

/**
 * The payload table of the parameter block the host sends right after `command`
 * (LoadAHRSPar, Start*Clb, StartClbRun), or ILAHRS_PAYLOAD_NONE.
 */
ilahrs_payload_t ilahrs_command_parameter_block(ilahrs_command_t command);

/**
 * The command frame of `command` (message type command, reserved 0, a one-byte payload
 * holding the code).
 * @return the frame size (ILAHRS_FRAME_MIN_SIZE), or 0 (`unknown_command`, `buffer_too_small`)
 */
size_t ilahrs_command_build(ilahrs_command_t command, uint8_t *out, size_t cap, ilahrs_error_t *err);

/**
 * Decode a command frame: the frame checks of ilahrs_frame_parse(), then message type
 * command (`bad_message_type` at ILAHRS_FRAME_MESSAGE_TYPE_OFFSET), a one-byte payload
 * (`bad_length` at ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET) and a known code (`unknown_command` at
 * ILAHRS_FRAME_PAYLOAD_OFFSET). 0xFE gives two commands, ExitClb and Stop (E14).
 */
bool ilahrs_command_decode(const uint8_t *data, size_t len, ilahrs_command_match_t *match, ilahrs_error_t *err);

/**
 * The acknowledgement the AHRS sends for a host message (E12): a data frame whose payload, the
 * acknowledgement table, is the received message's checksum. `message` must be one valid frame
 * (the checks of ilahrs_frame_parse()).
 * @return the acknowledgement size, or 0 on failure
 */
size_t ilahrs_ack_build(const uint8_t *message, size_t len, uint8_t *out, size_t cap, ilahrs_error_t *err);

/* ---- Commands, one by one ---- */

/** The frame of AHRScont1 (0x80). See ilahrs_command_build(). */
static inline size_t ilahrs_build_ahrs_cont1(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_AHRS_CONT1, out, cap, err);
}

/** The frame of AHRScont2 (0x82). See ilahrs_command_build(). */
static inline size_t ilahrs_build_ahrs_cont2(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_AHRS_CONT2, out, cap, err);
}

/** The frame of AHRScont3 (0x83). See ilahrs_command_build(). */
static inline size_t ilahrs_build_ahrs_cont3(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_AHRS_CONT3, out, cap, err);
}

/** The frame of AHRSreq1 (0x84). See ilahrs_command_build(). */
static inline size_t ilahrs_build_ahrs_req1(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_AHRS_REQ1, out, cap, err);
}

/** The frame of AHRSreq2 (0x86). See ilahrs_command_build(). */
static inline size_t ilahrs_build_ahrs_req2(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_AHRS_REQ2, out, cap, err);
}

/** The frame of AHRSreq3 (0x87). See ilahrs_command_build(). */
static inline size_t ilahrs_build_ahrs_req3(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_AHRS_REQ3, out, cap, err);
}

/** The frame of NMEAcont (0x88). See ilahrs_command_build(). */
static inline size_t ilahrs_build_nmea_cont(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_NMEA_CONT, out, cap, err);
}

/** The frame of NMEAreq (0x89). See ilahrs_command_build(). */
static inline size_t ilahrs_build_nmea_req(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_NMEA_REQ, out, cap, err);
}

/** The frame of GetDataReq (0xCA). See ilahrs_command_build(). */
static inline size_t ilahrs_build_get_data_req(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_GET_DATA_REQ, out, cap, err);
}

/** The frame of Stop (0xFE). See ilahrs_command_build(). */
static inline size_t ilahrs_build_stop(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_STOP, out, cap, err);
}

/** The frame of LoadAHRSPar (0x40). See ilahrs_command_build(). */
static inline size_t ilahrs_build_load_ahrs_par(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_LOAD_AHRS_PAR, out, cap, err);
}

/** The frame of ReadAHRSPar (0x41). See ilahrs_command_build(). */
static inline size_t ilahrs_build_read_ahrs_par(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_READ_AHRS_PAR, out, cap, err);
}

/** The frame of LowPowerOn (0xB0). See ilahrs_command_build(). */
static inline size_t ilahrs_build_low_power_on(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_LOW_POWER_ON, out, cap, err);
}

/** The frame of LowPowerOff (0xBA). See ilahrs_command_build(). */
static inline size_t ilahrs_build_low_power_off(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_LOW_POWER_OFF, out, cap, err);
}

/** The frame of GetVerFirmware (0x1F). See ilahrs_command_build(). */
static inline size_t ilahrs_build_get_ver_firmware(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_GET_VER_FIRMWARE, out, cap, err);
}

/** The frame of GetBIT (0x1A). See ilahrs_command_build(). */
static inline size_t ilahrs_build_get_bit(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_GET_BIT, out, cap, err);
}

/** The frame of Start2DClb (0x21). See ilahrs_command_build(). */
static inline size_t ilahrs_build_start_2d_clb(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_START_2D_CLB, out, cap, err);
}

/** The frame of Start2D2TClb (0x22). See ilahrs_command_build(). */
static inline size_t ilahrs_build_start_2d2t_clb(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_START_2D2T_CLB, out, cap, err);
}

/** The frame of Start3DClb (0x23). See ilahrs_command_build(). */
static inline size_t ilahrs_build_start_3d_clb(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_START_3D_CLB, out, cap, err);
}

/** The frame of StartClbRun (0x2B). See ilahrs_command_build(). */
static inline size_t ilahrs_build_start_clb_run(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_START_CLB_RUN, out, cap, err);
}

/** The frame of StopClbRun (0x20). See ilahrs_command_build(). */
static inline size_t ilahrs_build_stop_clb_run(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_STOP_CLB_RUN, out, cap, err);
}

/** The frame of FinishClb (0x2C). See ilahrs_command_build(). */
static inline size_t ilahrs_build_finish_clb(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_FINISH_CLB, out, cap, err);
}

/** The frame of AcceptClb (0x2E). See ilahrs_command_build(). */
static inline size_t ilahrs_build_accept_clb(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_ACCEPT_CLB, out, cap, err);
}

/** The frame of ExitClb (0xFE). See ilahrs_command_build(). */
static inline size_t ilahrs_build_exit_clb(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_EXIT_CLB, out, cap, err);
}

/** The frame of ClearClb (0x2F). See ilahrs_command_build(). */
static inline size_t ilahrs_build_clear_clb(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_CLEAR_CLB, out, cap, err);
}

/** The frame of GetClbRes (0x2A). See ilahrs_command_build(). */
static inline size_t ilahrs_build_get_clb_res(uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    return ilahrs_command_build(ILAHRS_COMMAND_GET_CLB_RES, out, cap, err);
}

/* ---- Parameter blocks: the data message that must follow a command ---- */

/**
 * The parameter block that must follow LoadAHRSPar without pause (Parameters to load, Table 6.9):
 * a data frame (E5) carrying `block`, checked as ilahrs_payload_build() checks it. Start `block`
 * from ilahrs_payload_defaults(); send ilahrs_build_load_ahrs_par() first.
 * @return the frame size (50 + ILAHRS_FRAME_OVERHEAD), or 0 on failure
 */
static inline size_t ilahrs_build_load_ahrs_par_block(const ilahrs_ahrs_parameters_load_t *block, uint8_t *out,
                                                      size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_AHRS_PARAMETERS_LOAD, block, out, cap, err);
}

/**
 * The parameter block that must follow Start2DClb without pause (Calibration parameters, Table 6.13):
 * a data frame (E5) carrying `block`, checked as ilahrs_payload_build() checks it. Start `block`
 * from ilahrs_payload_defaults(); send ilahrs_build_start_2d_clb() first.
 * @return the frame size (22 + ILAHRS_FRAME_OVERHEAD), or 0 on failure
 */
static inline size_t ilahrs_build_start_2d_clb_block(const ilahrs_calibration_parameters_t *block, uint8_t *out,
                                                     size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, block, out, cap, err);
}

/**
 * The parameter block that must follow Start2D2TClb without pause (Calibration parameters, Table 6.13):
 * a data frame (E5) carrying `block`, checked as ilahrs_payload_build() checks it. Start `block`
 * from ilahrs_payload_defaults(); send ilahrs_build_start_2d2t_clb() first.
 * @return the frame size (22 + ILAHRS_FRAME_OVERHEAD), or 0 on failure
 */
static inline size_t ilahrs_build_start_2d2t_clb_block(const ilahrs_calibration_parameters_t *block, uint8_t *out,
                                                       size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, block, out, cap, err);
}

/**
 * The parameter block that must follow Start3DClb without pause (Calibration parameters, Table 6.13):
 * a data frame (E5) carrying `block`, checked as ilahrs_payload_build() checks it. Start `block`
 * from ilahrs_payload_defaults(); send ilahrs_build_start_3d_clb() first.
 * @return the frame size (22 + ILAHRS_FRAME_OVERHEAD), or 0 on failure
 */
static inline size_t ilahrs_build_start_3d_clb_block(const ilahrs_calibration_parameters_t *block, uint8_t *out,
                                                     size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, block, out, cap, err);
}

/**
 * The parameter block that must follow StartClbRun without pause (Calibration run parameters, Table 6.16):
 * a data frame (E5) carrying `block`, checked as ilahrs_payload_build() checks it. Start `block`
 * from ilahrs_payload_defaults(); send ilahrs_build_start_clb_run() first.
 * @return the frame size (6 + ILAHRS_FRAME_OVERHEAD), or 0 on failure
 */
static inline size_t ilahrs_build_start_clb_run_block(const ilahrs_calibration_run_parameters_t *block, uint8_t *out,
                                                      size_t cap, ilahrs_error_t *err)
{
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_CALIBRATION_RUN_PARAMETERS, block, out, cap, err);
}

/* ======================================================================================== */
/* Named values and encodings                                                               */
/* ======================================================================================== */

/** Values of `calibration_type` (Table 6.14, Table 6.15). */
typedef enum ilahrs_calibration_type {
    ILAHRS_CALIBRATION_TYPE_TWO_D = 1,       /**< 2D calibration */
    ILAHRS_CALIBRATION_TYPE_TWO_D_TWO_T = 2, /**< 2D-2T calibration */
    ILAHRS_CALIBRATION_TYPE_THREE_D = 3,     /**< 3D calibration */
} ilahrs_calibration_type_t;

/** Values of `calibration_status_type` (Table 6.17). */
typedef enum ilahrs_calibration_status_type {
    ILAHRS_CALIBRATION_STATUS_TYPE_NOT_CALIBRATED = 0, /**< The AHRS is not calibrated */
    ILAHRS_CALIBRATION_STATUS_TYPE_TWO_D = 1,          /**< 2D calibration */
    ILAHRS_CALIBRATION_STATUS_TYPE_TWO_D_TWO_T = 2,    /**< 2D-2T calibration */
    ILAHRS_CALIBRATION_STATUS_TYPE_THREE_D = 3,        /**< 3D calibration */
} ilahrs_calibration_status_type_t;
/** `calibration_status_type` values above this mean parameters loaded by other software. */
#define ILAHRS_CALIBRATION_STATUS_TYPE_EXTERNAL_ABOVE 0x80u

/* Declination (Table 6.9): Magnetic declination in degrees; any value greater than 360 asks the
 * AHRS to compute it. */

#define ILAHRS_DECLINATION_MIN (-180.0f) /**< Smallest declination, degrees. */
#define ILAHRS_DECLINATION_MAX 180.0f    /**< Largest declination, degrees. */
/** A declination above this asks the AHRS to compute it from position and date. */
#define ILAHRS_DECLINATION_COMPUTE_ABOVE 360.0f
/** The declination to send for "compute it". */
#define ILAHRS_DECLINATION_COMPUTE 999.0f

/** True if the declination asks the AHRS to compute it. */
static inline bool ilahrs_declination_is_computed(float value)
{
    return value > ILAHRS_DECLINATION_COMPUTE_ABOVE;
}

/* Calibration success (Tables 6.14, 6.15, 6.17 and the notes below them, erratum E26): 0: not
 * successful; 1..254: predicted maximum (3 sigma) heading error, deg*10 (since firmware
 * 4.9.9.0); 255: successful, no estimate. */

#define ILAHRS_CALIBRATION_FAILED 0u /**< "Calibration success" value of a failed calibration. */
/** "Calibration success" value of a success without an accuracy estimate. */
#define ILAHRS_CALIBRATION_NO_ESTIMATE 255u
/** Divisor from the "Calibration success" value to degrees. */
#define ILAHRS_CALIBRATION_ACCURACY_DIVISOR 10

/** True if the calibration (or run) succeeded. */
static inline bool ilahrs_calibration_succeeded(uint8_t success)
{
    return success != ILAHRS_CALIBRATION_FAILED;
}

/** The predicted 3-sigma heading error in degrees; false if failed or without an estimate. */
static inline bool ilahrs_calibration_accuracy_deg(uint8_t success, float *degrees)
{
    if (success == ILAHRS_CALIBRATION_FAILED || success == ILAHRS_CALIBRATION_NO_ESTIMATE) {
        return false;
    }
    *degrees = (float)success / (float)ILAHRS_CALIBRATION_ACCURACY_DIVISOR;
    return true;
}

/* ======================================================================================== */
/* Unit Status Word (6.5, Table 6.18, Table 6.19)                                           */
/* ======================================================================================== */

/** Bit 0, failure byte (Initial Alignment): Unsuccessful initial alignment (AHRS moved or the magnetic field changed).
 */
#define ILAHRS_USW_INITIAL_ALIGNMENT_FAILED 0x0001u
/** Bit 1, failure byte (AHRS Parameters): The AHRS parameters are incorrect. */
#define ILAHRS_USW_PARAMETERS_INCORRECT 0x0002u
/** Bit 2, failure byte (Gyroscope Unit): Gyroscope unit failure detected. */
#define ILAHRS_USW_GYRO_FAILURE 0x0004u
/** Bit 3, failure byte (Accelerometer Unit): Accelerometer unit failure detected. */
#define ILAHRS_USW_ACCELEROMETER_FAILURE 0x0008u
/** Bit 4, failure byte (Magnetometer Unit): Magnetometer unit failure detected. */
#define ILAHRS_USW_MAGNETOMETER_FAILURE 0x0010u
/** Bit 5, failure byte (Electronics): Electronics failure detected. */
#define ILAHRS_USW_ELECTRONICS_FAILURE 0x0020u
/** Bit 6, failure byte (Software): Software failure detected. */
#define ILAHRS_USW_SOFTWARE_FAILURE 0x0040u
/** Bit 8, warning byte (Incorrect Power Supply): Supply voltage below the minimum level. */
#define ILAHRS_USW_LOW_SUPPLY_VOLTAGE 0x0100u
/** Bit 9, warning byte (Incorrect Power Supply): Supply voltage above the maximum level. */
#define ILAHRS_USW_HIGH_SUPPLY_VOLTAGE 0x0200u
/** Bit 10, warning byte (Angular Rate Exceeding Detect): X angular rate out of range. */
#define ILAHRS_USW_X_RATE_EXCEEDED 0x0400u
/** Bit 11, warning byte (Angular Rate Exceeding Detect): Y angular rate out of range. */
#define ILAHRS_USW_Y_RATE_EXCEEDED 0x0800u
/** Bit 12, warning byte (Angular Rate Exceeding Detect): Z angular rate out of range. */
#define ILAHRS_USW_Z_RATE_EXCEEDED 0x1000u
/** Bit 13, warning byte (Large Magnetic Field Detect): Total magnetic field limit exceeded. */
#define ILAHRS_USW_LARGE_MAGNETIC_FIELD 0x2000u
/** Bit 14, warning byte (Environmental Temperature): Temperature outside the operating range. */
#define ILAHRS_USW_TEMPERATURE_OUT_OF_RANGE 0x4000u
#define ILAHRS_USW_FLAGS_MASK 0x7F7Fu /**< Every flag bit (the mode bits excluded). */
/** The failure byte: non-zero failure flags mean a failure (Table 6.18). */
#define ILAHRS_USW_FAILURE_MASK 0x00FFu
#define ILAHRS_USW_WARNING_MASK 0xFF00u /**< The warning byte. */
#define ILAHRS_USW_MODE_MASK 0x8080u    /**< The mode bits (Table 6.19). */
/** Mode bits of `readiness`: Normal operation. */
#define ILAHRS_USW_MODE_READINESS_BITS 0x0000u
/** Mode bits of `sleep`: In the last data block the AHRS sends before it goes to Sleep mode. */
#define ILAHRS_USW_MODE_SLEEP_BITS 0x8080u

/** The mode the USW reports (E18: combinations the ICD does not define are "unknown"). */
typedef enum ilahrs_usw_mode {
    ILAHRS_USW_MODE_READINESS = 0, /**< Normal operation. */
    ILAHRS_USW_MODE_SLEEP = 1,     /**< In the last data block the AHRS sends before it goes to Sleep mode. */
    ILAHRS_USW_MODE_UNKNOWN = 2,   /**< Mode bits the ICD does not define (E18). */
} ilahrs_usw_mode_t;

/** The mode a USW reports. */
static inline ilahrs_usw_mode_t ilahrs_usw_mode(uint16_t usw)
{
    switch (usw & ILAHRS_USW_MODE_MASK) {
    case ILAHRS_USW_MODE_READINESS_BITS:
        return ILAHRS_USW_MODE_READINESS;
    case ILAHRS_USW_MODE_SLEEP_BITS:
        return ILAHRS_USW_MODE_SLEEP;
    default:
        return ILAHRS_USW_MODE_UNKNOWN;
    }
}

/** A decoded Unit Status Word. */
typedef struct ilahrs_usw {
    uint16_t flags;         /**< The flag bits that are set (ILAHRS_USW_FLAGS_MASK). */
    uint8_t failure;        /**< The failure byte, as sent. */
    uint8_t warning;        /**< The warning byte, as sent. */
    ilahrs_usw_mode_t mode; /**< The mode bits, decoded. */
} ilahrs_usw_t;

/** Split a USW into flags, failure and warning bytes and mode. */
static inline ilahrs_usw_t ilahrs_usw_decode(uint16_t usw)
{
    ilahrs_usw_t out;
    out.flags = (uint16_t)(usw & ILAHRS_USW_FLAGS_MASK);
    /* A byte of the word is its bits divided by its mask's lowest bit. */
    out.failure =
        (uint8_t)((usw & ILAHRS_USW_FAILURE_MASK) / (ILAHRS_USW_FAILURE_MASK & (0u - ILAHRS_USW_FAILURE_MASK)));
    out.warning =
        (uint8_t)((usw & ILAHRS_USW_WARNING_MASK) / (ILAHRS_USW_WARNING_MASK & (0u - ILAHRS_USW_WARNING_MASK)));
    out.mode = ilahrs_usw_mode(usw);
    return out;
}

/** True if any failure flag is set. */
static inline bool ilahrs_usw_has_failure(uint16_t usw)
{
    return (usw & ILAHRS_USW_FLAGS_MASK & ILAHRS_USW_FAILURE_MASK) != 0;
}

#if ILAHRS_NAMES
/** The spec name of the flag at bit `bit` ("gyro_failure"); NULL for a bit that is no flag. */
const char *ilahrs_usw_flag_name(unsigned bit);
#endif

/* ======================================================================================== */
/* Date (Table 6.9, Table 6.10, Table 6.13, erratum E15)                                    */
/* ======================================================================================== */

/* Year + (Month - 1)/12 + Day/365, as a float. */

/** First year a date may have. */
#define ILAHRS_DATE_YEAR_MIN 1900
/** Last year a date may have. */
#define ILAHRS_DATE_YEAR_MAX 2199

/** A calendar date. */
typedef struct ilahrs_date {
    int16_t year;  /**< ILAHRS_DATE_YEAR_MIN..ILAHRS_DATE_YEAR_MAX. */
    uint8_t month; /**< 1..12. */
    uint8_t day;   /**< 1..31. */
} ilahrs_date_t;

/**
 * The date float of a calendar date (the encoding above). Refuses (`out_of_range`, field "date")
 * a date that is not a real calendar date within ILAHRS_DATE_YEAR_MIN..ILAHRS_DATE_YEAR_MAX.
 */
bool ilahrs_date_encode(int year, int month, int day, float *value, ilahrs_error_t *err);

/**
 * The calendar date whose encoding is nearest `value` (E15: not floor arithmetic, which is
 * wrong for day 31). False (`out_of_range`, field "date") for NaN, infinities and values
 * outside the years ILAHRS_DATE_YEAR_MIN..ILAHRS_DATE_YEAR_MAX.
 */
bool ilahrs_date_decode(float value, ilahrs_date_t *date, ilahrs_error_t *err);

/* ======================================================================================== */
/* $PAHR sentences (Table 6.7, section 6.2): $PAHR,RRRR.rr,PPP.pp,HHH.hh,TTT.t,V.vv,SSSS*CC<CR><LF> */
/* ======================================================================================== */

/** Longest sentence, "$" through CR LF (E16). */
#define ILAHRS_PAHR_MAX_LENGTH 82
/** Number of fields in a sentence. */
#define ILAHRS_PAHR_FIELD_COUNT 6
/** The AHRS sends at most this many sentences per second. */
#define ILAHRS_PAHR_MAX_RATE_HZ 50
#define ILAHRS_PAHR_ROLL_MIN (-18000)      /**< Smallest `roll` (scaled by 100). */
#define ILAHRS_PAHR_ROLL_MAX 18000         /**< Largest `roll`. */
#define ILAHRS_PAHR_ROLL_DIVISOR 100       /**< `roll` is held in units of 1/100 deg. */
#define ILAHRS_PAHR_PITCH_MIN (-9000)      /**< Smallest `pitch` (scaled by 100). */
#define ILAHRS_PAHR_PITCH_MAX 9000         /**< Largest `pitch`. */
#define ILAHRS_PAHR_PITCH_DIVISOR 100      /**< `pitch` is held in units of 1/100 deg. */
#define ILAHRS_PAHR_HEADING_MIN 0          /**< Smallest `heading` (scaled by 100). */
#define ILAHRS_PAHR_HEADING_MAX 35999u     /**< Largest `heading`. */
#define ILAHRS_PAHR_HEADING_DIVISOR 100    /**< `heading` is held in units of 1/100 deg. */
#define ILAHRS_PAHR_TEMPERATURE_MIN (-999) /**< Smallest `temperature` (scaled by 10). */
#define ILAHRS_PAHR_TEMPERATURE_MAX 9999   /**< Largest `temperature`. */
#define ILAHRS_PAHR_TEMPERATURE_DIVISOR 10 /**< `temperature` is held in units of 1/10 degc. */
#define ILAHRS_PAHR_VDD_MIN 0              /**< Smallest `vdd` (scaled by 100). */
#define ILAHRS_PAHR_VDD_MAX 999            /**< Largest `vdd`. */
#define ILAHRS_PAHR_VDD_DIVISOR 100        /**< `vdd` is held in units of 1/100 v. */
#define ILAHRS_PAHR_USW_MIN 0              /**< Smallest `usw`. */
#define ILAHRS_PAHR_USW_MAX 65535u         /**< Largest `usw`. */

/**
 * One $PAHR sentence. Decimal fields are integers scaled by 10^decimals (roll 12.34 deg is
 * 1234), so parsing and formatting need no floating point and are exact.
 */
typedef struct ilahrs_pahr {
    int16_t roll;        /**< Roll, hundredths of a degree. (RRRR.rr) */
    int16_t pitch;       /**< Pitch, hundredths of a degree. (PPP.pp) */
    uint16_t heading;    /**< Heading, hundredths of a degree. (HHH.hh) */
    int16_t temperature; /**< Average accelerometer temperature, tenths of a degree Celsius. (TTT.t) */
    uint16_t vdd;        /**< AHRS input voltage, hundredths of a volt. (V.vv) */
    uint16_t usw;        /**< Unit Status Word (section 6.5), four hex digits. (SSSS) */
} ilahrs_pahr_t;

/**
 * Decode one sentence, "$" through CR LF, `len` characters at `text` (no NUL needed).
 *
 * Checks, in order: "$" (`bad_header` at 0), the identifier and "," (`bad_header` at 1), the CR
 * LF end (`truncated` at `len` if none, `bad_length` at ILAHRS_PAHR_MAX_LENGTH if it ends
 * beyond, `trailing_data` after it), "*" and two hex digits before CR LF (`malformed`), the
 * XOR checksum (`bad_checksum` at its first digit), ILAHRS_PAHR_FIELD_COUNT fields
 * (`malformed`), then each field's grammar (`malformed`) and range (`out_of_range`) at the
 * field's first character, naming it. Decimal fields accept any number of integer digits and 1
 * to `decimals` fraction digits; hex fields (the USW) 1 to their width of hex digits of either
 * case (E16).
 *
 * @code
 *     ilahrs_pahr_t s;
 *     if (ilahrs_pahr_parse(line, line_len, &s, NULL)) {
 *         int32_t roll_centideg = s.roll;
 *     }
 * @endcode
 */
bool ilahrs_pahr_parse(const char *text, size_t len, ilahrs_pahr_t *out, ilahrs_error_t *err);

/**
 * Write a sentence, "$" through CR LF, into `out` (no printf, no floating point). Integer
 * parts are zero-padded to the template width, the sign counting as one character (roll
 * -1234 is "-012.34"); the USW and the checksum are upper-case hex (E16). A NUL follows the
 * sentence if `cap` leaves room for it. Refuses a value outside its range (`out_of_range`,
 * naming the field) and a `cap` shorter than the sentence (`buffer_too_small`).
 * @return the sentence length (at most ILAHRS_PAHR_MAX_LENGTH), or 0 on failure
 */
size_t ilahrs_pahr_build(const ilahrs_pahr_t *in, char *out, size_t cap, ilahrs_error_t *err);

/**
 * ilahrs_pahr_from_values() with the values in an array, in field order (a hex field's value
 * must be an integer, else `out_of_range`).
 */
bool ilahrs_pahr_from_array(const double values[ILAHRS_PAHR_FIELD_COUNT], ilahrs_pahr_t *out, ilahrs_error_t *err);

#if ILAHRS_NAMES
/** The spec name of sentence field `index` (0..ILAHRS_PAHR_FIELD_COUNT-1); NULL otherwise. */
const char *ilahrs_pahr_field_name(size_t index);
#endif

/** The range of sentence field `index` (scaled values); false if `index` is out of range. */
bool ilahrs_pahr_field_range(size_t index, int32_t *min, int32_t *max);

/** 10^decimals of decimal sentence field `index` (engineering = value / divisor); 0 for a hex field. */
uint32_t ilahrs_pahr_field_divisor(size_t index);

/** The (scaled) value of sentence field `index`; 0 if `index` is out of range. */
int32_t ilahrs_pahr_field_get(const ilahrs_pahr_t *sentence, size_t index);

/**
 * Fill a sentence from engineering values (roll in deg, pitch in deg, heading in deg, temperature in degc, vdd in v,
 * usw), rounding half away from zero. Refuses (`out_of_range`, naming the field) NaN and infinities first, then values
 * outside their ranges, each pass in field order. The double is scaled and rounded exactly as double arithmetic would
 * (value * 10^decimals, then + 0.5 and floor), in integers: no floating-point code is linked.
 */
bool ilahrs_pahr_from_values(double roll, double pitch, double heading, double temperature, double vdd, uint16_t usw,
                             ilahrs_pahr_t *out, ilahrs_error_t *err);

/** `roll` of a sentence in deg. */
static inline float ilahrs_pahr_roll_deg(const ilahrs_pahr_t *s)
{
    return (float)s->roll / 100.0f;
}

/** `pitch` of a sentence in deg. */
static inline float ilahrs_pahr_pitch_deg(const ilahrs_pahr_t *s)
{
    return (float)s->pitch / 100.0f;
}

/** `heading` of a sentence in deg. */
static inline float ilahrs_pahr_heading_deg(const ilahrs_pahr_t *s)
{
    return (float)s->heading / 100.0f;
}

/** `temperature` of a sentence in degc. */
static inline float ilahrs_pahr_temperature_degc(const ilahrs_pahr_t *s)
{
    return (float)s->temperature / 10.0f;
}

/** `vdd` of a sentence in v. */
static inline float ilahrs_pahr_vdd_v(const ilahrs_pahr_t *s)
{
    return (float)s->vdd / 100.0f;
}

/* ======================================================================================== */
/* Stream decoder                                                                           */
/* ======================================================================================== */

/** A message never spans an idle line: after this many byte times of quiet (10 bits a byte at
 * 115200 baud), ilahrs_stream_idle() gives up what the stream decoder holds. */
#define ILAHRS_IDLE_BYTE_TIMES 1152
/** ILAHRS_IDLE_BYTE_TIMES in microseconds (rounded up): the quiet time ilahrs_stream_idle() acts on. */
#define ILAHRS_IDLE_TIMEOUT_US 100000u

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

/* ======================================================================================== */
/* Device state machine (6.1, 6.3, 6.4)                                                     */
/* ======================================================================================== */

/** The states of the device; each has an operating mode (ilahrs_state_mode()). */
typedef enum ilahrs_state {
    /** Waiting for a command (6.1). Mode idle. */
    ILAHRS_STATE_IDLE = 0,
    /** LoadAHRSPar received; the parameter block must follow without pause (6.3.6). Mode idle.
     *  Waits for the parameter block ahrs_parameters_load. */
    ILAHRS_STATE_AWAITING_PARAMETERS = 1,
    /** Initial alignment before continuous output (6.3.1, 6.3.3). Mode continuous. Timer:
     *  alignment. */
    ILAHRS_STATE_ALIGNING_CONTINUOUS = 2,
    /** Output of the chosen format at the update rate (6.3.1). Mode continuous. Timer: output. */
    ILAHRS_STATE_CONTINUOUS = 3,
    /** Initial alignment before on-request output (6.3.2, 6.3.3). Mode on_request. Timer:
     *  alignment. */
    ILAHRS_STATE_ALIGNING_ON_REQUEST = 4,
    /** One block of the chosen format per GetDataReq (6.3.2, 6.3.4). Mode on_request. */
    ILAHRS_STATE_ON_REQUEST = 5,
    /** Low-power mode; only LowPowerOff is heard (6.3.8). Mode sleep. */
    ILAHRS_STATE_SLEEP = 6,
    /** Start2DClb or Start3DClb received; the calibration parameter block must follow (6.4.1,
     *  6.4.8). Mode calibration. Waits for the parameter block calibration_parameters. */
    ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS = 7,
    /** Initial alignment before the single calibration run (6.4.1, 6.4.8). Mode calibration.
     *  Timer: alignment. */
    ILAHRS_STATE_CALIBRATION_ALIGNING = 8,
    /** Accumulating data while the object turns (6.4.1, 6.4.8). Mode calibration. Timer:
     *  accumulation. */
    ILAHRS_STATE_CALIBRATION_ACCUMULATING = 9,
    /** Result sent; waiting for AcceptClb or ExitClb (6.4.1, 6.4.7). Mode calibration. */
    ILAHRS_STATE_CALIBRATION_DECIDING = 10,
    /** Start2D2TClb received; the calibration parameter block must follow (6.4.5). Mode
     *  calibration. Waits for the parameter block calibration_parameters. */
    ILAHRS_STATE_RUNS_AWAITING_PARAMETERS = 11,
    /** 2D-2T calibration between runs: waiting for StartClbRun, FinishClb or ExitClb (6.4.5).
     *  Mode calibration. Erratum E36. */
    ILAHRS_STATE_RUNS_READY = 12,
    /** StartClbRun received; the run parameter block must follow (6.4.6). Mode calibration.
     *  Waits for the parameter block calibration_run_parameters. */
    ILAHRS_STATE_RUN_AWAITING_PARAMETERS = 13,
    /** Initial alignment before a 2D-2T run (6.4.5). Mode calibration. Timer: alignment. */
    ILAHRS_STATE_RUN_ALIGNING = 14,
    /** Accumulating data during a 2D-2T run (6.4.5). Mode calibration. Timer: accumulation. */
    ILAHRS_STATE_RUN_ACCUMULATING = 15,
} ilahrs_state_t;

/** Number of states. */
#define ILAHRS_STATE_COUNT 16
/** The state after power-up (the value 0, so a zeroed state is at power-up). */
#define ILAHRS_STATE_INITIAL ILAHRS_STATE_IDLE

/**
 * What happens to a device: every command of Table C.1 (with the value of its
 * ilahrs_command_t, so ILAHRS_EVENT_OF_COMMAND() is a cast), then the other events. The timers
 * fire accumulation_done (accumulation), alignment_done (alignment), output_due (output).
 */
typedef enum ilahrs_event {
    ILAHRS_EVENT_AHRS_CONT1 = ILAHRS_COMMAND_AHRS_CONT1,             /**< The command AHRScont1 (0x80). */
    ILAHRS_EVENT_AHRS_CONT2 = ILAHRS_COMMAND_AHRS_CONT2,             /**< The command AHRScont2 (0x82). */
    ILAHRS_EVENT_AHRS_CONT3 = ILAHRS_COMMAND_AHRS_CONT3,             /**< The command AHRScont3 (0x83). */
    ILAHRS_EVENT_AHRS_REQ1 = ILAHRS_COMMAND_AHRS_REQ1,               /**< The command AHRSreq1 (0x84). */
    ILAHRS_EVENT_AHRS_REQ2 = ILAHRS_COMMAND_AHRS_REQ2,               /**< The command AHRSreq2 (0x86). */
    ILAHRS_EVENT_AHRS_REQ3 = ILAHRS_COMMAND_AHRS_REQ3,               /**< The command AHRSreq3 (0x87). */
    ILAHRS_EVENT_NMEA_CONT = ILAHRS_COMMAND_NMEA_CONT,               /**< The command NMEAcont (0x88). */
    ILAHRS_EVENT_NMEA_REQ = ILAHRS_COMMAND_NMEA_REQ,                 /**< The command NMEAreq (0x89). */
    ILAHRS_EVENT_GET_DATA_REQ = ILAHRS_COMMAND_GET_DATA_REQ,         /**< The command GetDataReq (0xCA). */
    ILAHRS_EVENT_STOP = ILAHRS_COMMAND_STOP,                         /**< The command Stop (0xFE). */
    ILAHRS_EVENT_LOAD_AHRS_PAR = ILAHRS_COMMAND_LOAD_AHRS_PAR,       /**< The command LoadAHRSPar (0x40). */
    ILAHRS_EVENT_READ_AHRS_PAR = ILAHRS_COMMAND_READ_AHRS_PAR,       /**< The command ReadAHRSPar (0x41). */
    ILAHRS_EVENT_LOW_POWER_ON = ILAHRS_COMMAND_LOW_POWER_ON,         /**< The command LowPowerOn (0xB0). */
    ILAHRS_EVENT_LOW_POWER_OFF = ILAHRS_COMMAND_LOW_POWER_OFF,       /**< The command LowPowerOff (0xBA). */
    ILAHRS_EVENT_GET_VER_FIRMWARE = ILAHRS_COMMAND_GET_VER_FIRMWARE, /**< The command GetVerFirmware (0x1F). */
    ILAHRS_EVENT_GET_BIT = ILAHRS_COMMAND_GET_BIT,                   /**< The command GetBIT (0x1A). */
    ILAHRS_EVENT_START_2D_CLB = ILAHRS_COMMAND_START_2D_CLB,         /**< The command Start2DClb (0x21). */
    ILAHRS_EVENT_START_2D2T_CLB = ILAHRS_COMMAND_START_2D2T_CLB,     /**< The command Start2D2TClb (0x22). */
    ILAHRS_EVENT_START_3D_CLB = ILAHRS_COMMAND_START_3D_CLB,         /**< The command Start3DClb (0x23). */
    ILAHRS_EVENT_START_CLB_RUN = ILAHRS_COMMAND_START_CLB_RUN,       /**< The command StartClbRun (0x2B). */
    ILAHRS_EVENT_STOP_CLB_RUN = ILAHRS_COMMAND_STOP_CLB_RUN,         /**< The command StopClbRun (0x20). */
    ILAHRS_EVENT_FINISH_CLB = ILAHRS_COMMAND_FINISH_CLB,             /**< The command FinishClb (0x2C). */
    ILAHRS_EVENT_ACCEPT_CLB = ILAHRS_COMMAND_ACCEPT_CLB,             /**< The command AcceptClb (0x2E). */
    ILAHRS_EVENT_EXIT_CLB = ILAHRS_COMMAND_EXIT_CLB,                 /**< The command ExitClb (0xFE). */
    ILAHRS_EVENT_CLEAR_CLB = ILAHRS_COMMAND_CLEAR_CLB,               /**< The command ClearClb (0x2F). */
    ILAHRS_EVENT_GET_CLB_RES = ILAHRS_COMMAND_GET_CLB_RES,           /**< The command GetClbRes (0x2A). */
    /** A data message whose payload has the size of the table the current state expects. */
    ILAHRS_EVENT_PARAMETER_BLOCK = 26,
    /** A data message of any other size. */
    ILAHRS_EVENT_OTHER_MESSAGE = 27,
    /** A command frame whose code no command of Table C.1 has. */
    ILAHRS_EVENT_UNKNOWN = 28,
    /** No parameter block within parameter_block_timeout_s of the command (E34). */
    ILAHRS_EVENT_BLOCK_TIMEOUT = 29,
    /** The initial alignment time (Table 6.9, 30 s by default) has elapsed. */
    ILAHRS_EVENT_ALIGNMENT_DONE = 30,
    /** The accumulation time of the calibration run (Table 6.13) has elapsed. */
    ILAHRS_EVENT_ACCUMULATION_DONE = 31,
    /** One output period has elapsed: 1 / update rate, at most 50 Hz for NMEA (E22). */
    ILAHRS_EVENT_OUTPUT_DUE = 32,
} ilahrs_event_t;

/** Number of events. */
#define ILAHRS_EVENT_COUNT 33
/** The event of a command (ilahrs_command_t). */
#define ILAHRS_EVENT_OF_COMMAND(command) ((ilahrs_event_t)(command))

/** What the device sends in a transition. */
typedef enum ilahrs_answer {
    ILAHRS_ANSWER_ACK = 0, /**< The acknowledgement of the message just received (ilahrs_ack_build(), E12). */
    ILAHRS_ANSWER_AHRS_PARAMETERS_READ = 1, /**< One ahrs_parameters_read data block (Parameters read, Table 6.10). */
    ILAHRS_ANSWER_FIRMWARE_VERSION = 2,     /**< One firmware_version data block (Firmware version, Table 6.11). */
    ILAHRS_ANSWER_BIT_RESULT = 3,           /**< One bit_result data block (Built-in test answer, Table 6.12). */
    ILAHRS_ANSWER_CALIBRATION_STATUS =
        4, /**< One calibration_status data block (Calibration results read back, Table 6.17). */
    ILAHRS_ANSWER_INITIAL_ALIGNMENT = 5, /**< One initial_alignment data block (Initial alignment data, Table 6.8). */
    ILAHRS_ANSWER_OUTPUT =
        6, /**< One block of the output format the start command chose (a frame, or a $PAHR sentence). */
    ILAHRS_ANSWER_OUTPUT_SLEEP =
        7, /**< One output block whose USW reports mode sleep (E35). Its USW reports the mode sleep (E35). */
    ILAHRS_ANSWER_CALIBRATION_RESULT = 8, /**< One calibration_result data block (Calibration result, Table 6.14). */
    ILAHRS_ANSWER_CALIBRATION_RUN_RESULT =
        9, /**< One calibration_run_result data block (2D-2T calibration run result, Table 6.15). */
} ilahrs_answer_t;

/** Number of answer kinds. */
#define ILAHRS_ANSWER_COUNT 10
/** Most answers one transition sends. */
#define ILAHRS_STEP_SEND_MAX 1
/** Most numeric parts a firmware version holds. */
#define ILAHRS_FIRMWARE_PARTS_MAX 8

/*
 * Rows of the table that apply only to firmware older than a version (`firmware_before` in the
 * spec; ilahrs_transition(), ilahrs_transition_on()): runs_ready on StopClbRun before 4.9.9.0 (E29).
 */

/*
 * What the AHRS does with each input in each state: the `state_machine` of the spec as a const
 * table (spec/README.md, "The device state machine"). A device firmware steps it on every
 * message and timer; a host uses it to know which answer to expect. A (state, event) pair with
 * no transition is ignored: no answer, no change of state (E33).
 *
 * @code
 *     ilahrs_state_t state = ILAHRS_STATE_INITIAL;
 *     ilahrs_frame_t frame;                 // a message received, e.g. from the stream decoder
 *     ilahrs_step_t step;
 *     ilahrs_event_t event = ilahrs_event_for_frame(state, &frame);
 *     if (ilahrs_transition(state, event, false, &step)) {
 *         for (unsigned i = 0; i < step.send_count; i++) {
 *             send_answer(step.send[i]);      // ack, output, or a payload table
 *         }
 *     }
 *     state = step.to;                      // also right when the event was ignored
 * @endcode
 */

/** One transition: the next state and what the device sends, in order. */
typedef struct ilahrs_step {
    ilahrs_state_t to;                          /**< The state after the event. */
    uint8_t send_count;                         /**< Entries in `send` (0: nothing). */
    ilahrs_answer_t send[ILAHRS_STEP_SEND_MAX]; /**< What the device sends. */
} ilahrs_step_t;

#if ILAHRS_NAMES
/** The spec name of a state ("idle"); NULL for a value outside ilahrs_state_t. */
const char *ilahrs_state_name(ilahrs_state_t state);
/** Find a state by its spec name, `len` characters at `name`. */
bool ilahrs_state_by_name(const char *name, size_t len, ilahrs_state_t *state);
#endif
/** The operating mode of a state; ILAHRS_MODE_COUNT for a value outside ilahrs_state_t. */
ilahrs_mode_t ilahrs_state_mode(ilahrs_state_t state);
/** The payload table of the parameter block a state waits for (E34), or ILAHRS_PAYLOAD_NONE. */
ilahrs_payload_t ilahrs_state_expects(ilahrs_state_t state);
/** The event the timer of a state fires (see ilahrs_event_t); false if the state runs no timer. */
bool ilahrs_state_timer(ilahrs_state_t state, ilahrs_event_t *event);

#if ILAHRS_NAMES
/** The name of an event: the ICD name of a command ("AHRScont1"), else the spec name ("unknown"); NULL if out of
 * range. */
const char *ilahrs_event_name(ilahrs_event_t event);
/** Find an event by its name (a command's ICD name or an event's spec name). */
bool ilahrs_event_by_name(const char *name, size_t len, ilahrs_event_t *event);

/** The spec name of an answer ("ack"); NULL for a value outside ilahrs_answer_t. */
const char *ilahrs_answer_name(ilahrs_answer_t answer);
#endif
/** The payload table an answer sends, or ILAHRS_PAYLOAD_NONE (ack and the output answers). */
ilahrs_payload_t ilahrs_answer_payload(ilahrs_answer_t answer);
#ifdef ILAHRS_USW_FLAGS_MASK
/**
 * The USW mode an output answer reports in place of the device's own (see ilahrs_answer_t, E35);
 * false for every other answer.
 */
bool ilahrs_answer_usw_mode(ilahrs_answer_t answer, ilahrs_usw_mode_t *mode);
#endif

/**
 * The event of a command frame with code `code` in `state`: of the commands sharing the code, the
 * one valid in the state's mode, else the code's default (0xFE: ExitClb in calibration, Stop
 * elsewhere, E14); ILAHRS_EVENT_UNKNOWN for a code no command has.
 */
ilahrs_event_t ilahrs_event_for_code(ilahrs_state_t state, uint8_t code);

/**
 * The event of a data message with a `payload_size`-byte payload in `state`:
 * ILAHRS_EVENT_PARAMETER_BLOCK if the state waits for a parameter block of that size, else
 * ILAHRS_EVENT_OTHER_MESSAGE.
 */
ilahrs_event_t ilahrs_event_for_data(ilahrs_state_t state, size_t payload_size);

/**
 * The event of a received frame in `state`: a command-type frame with a one-byte payload is
 * ilahrs_event_for_code(), any other frame ilahrs_event_for_data() (a parameter block may come
 * with either message type, E5).
 */
ilahrs_event_t ilahrs_event_for_frame(ilahrs_state_t state, const ilahrs_frame_t *frame);

/**
 * Look a (state, event) pair up. `older_firmware`: the device runs firmware older than the
 * version of the rows marked `firmware_before` (listed with ilahrs_answer_t above); those rows
 * then take precedence. ilahrs_transition_on() compares a version for you.
 *
 * @return true with `*out` filled; false if the device ignores the event (E33), or `state` or
 *         `event` is out of range, with `*out` set to (`state`, nothing), so that a caller may
 *         apply `*out` either way
 */
bool ilahrs_transition(ilahrs_state_t state, ilahrs_event_t event, bool older_firmware, ilahrs_step_t *out);

/** A firmware version such as 4.9.9.0: numeric parts compared in order. */
typedef struct ilahrs_firmware {
    uint32_t parts[ILAHRS_FIRMWARE_PARTS_MAX]; /**< The parts, most significant first. */
    uint8_t count;                             /**< Number of parts (1..ILAHRS_FIRMWARE_PARTS_MAX). */
} ilahrs_firmware_t;

/**
 * Read a version, decimal numbers separated by ".", `len` characters at `text`. Refuses
 * (`malformed` at the first character of the bad part) an empty or non-numeric part, a part above
 * 2^32 - 1 and more than ILAHRS_FIRMWARE_PARTS_MAX parts.
 */
bool ilahrs_firmware_parse(const char *text, size_t len, ilahrs_firmware_t *firmware, ilahrs_error_t *err);

/**
 * Compare two versions part by part as numbers (4.10.0.0 is after 4.9.9.0; a version that another
 * one extends is the older: 4.9 is before 4.9.0). Negative, zero or positive as `a` is before,
 * equal to or after `b`.
 */
int ilahrs_firmware_compare(const ilahrs_firmware_t *a, const ilahrs_firmware_t *b);

/**
 * ilahrs_transition() for a device running `firmware` (NULL: current firmware): a row marked
 * `firmware_before` applies when `firmware` is before its version.
 */
bool ilahrs_transition_on(ilahrs_state_t state, ilahrs_event_t event, const ilahrs_firmware_t *firmware,
                          ilahrs_step_t *out);

#ifdef __cplusplus
}
#endif

#endif /* ILAHRS_H */
