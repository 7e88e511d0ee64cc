/* ======================================================================================== */
/* Error reports                                                                            */
/* ======================================================================================== */

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
/* Frames: decoding and building                                                           */
/* ======================================================================================== */

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
/* Commands: names, properties, frames                                                      */
/* ======================================================================================== */

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

/* ======================================================================================== */
/* Device variants: parameters and names                                                    */
/* ======================================================================================== */

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
/* Payload tables: the generic interface                                                    */
/* ======================================================================================== */

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
