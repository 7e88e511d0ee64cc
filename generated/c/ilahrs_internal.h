/* Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
 * Do not edit: change the spec or the generator and run `make generate`.
 *
 * Not needed to use the library: ilahrs.c holds this text. It is for the library's fixed code in
 * generator/targets/c/runtime/, whose files ilahrs.c holds one after the other without their
 * #include lines: with them, each compiles on its own against this header and ilahrs.h (an
 * editor's language server, `make lint-c`).
 */
#ifndef ILAHRS_INTERNAL_H
#define ILAHRS_INTERNAL_H

#include "ilahrs.h"

#include <string.h>

/*
 * How ilahrs.c reads its tables. The tables below this block are generated from the spec; the
 * code after them is fixed and walks them. Everything is const: nothing here is mutable.
 *
 * Names live in string pools (NUL-separated strings; tables hold offsets into them): the names
 * errors report have a pool per kind, so that a firmware links only the ones it reports; every
 * other name shares one pool, whose offsets form one table of sections, one per kind. Without
 * names (ILAHRS_NAMES 0) errors name no field and no name pool is compiled.
 */
#if ILAHRS_NAMES
#define FRAME_NAME(offset) (ilahrs_frame_names + (offset))
#define FIELD_NAME(offset) (ilahrs_field_names + (offset))
#define SENTENCE_NAME(offset) (ilahrs_sentence_names + (offset))
#define NAME_DATE (ilahrs_date_names)
#else
#define NO_NAME ((const char *)NULL)
#define FRAME_NAME(offset) NO_NAME
#define FIELD_NAME(offset) NO_NAME
#define SENTENCE_NAME(offset) NO_NAME
#define NAME_DATE NO_NAME
#endif
#define ERROR_NAME(offset) (ilahrs_error_names + (offset))
#define TEXT(offset) (ilahrs_text_names + (offset))

/*
 * A payload field (ilahrs_field_info_t) in three small numbers, each column as wide as the spec
 * needs (KIND_BITS, ENCODING_BITS, TYPE_BITS, OFFSET_BITS and BOUNDS_BITS come with the table):
 * - name_type: the name's offset in the field-name pool, above the type: the wire kind, an
 *   encoding a builder checks beyond a range, and the log2 of a number's size;
 * - place: the member's distance from the wire offset (struct padding so far), above the offset;
 * - info: an array's size (char and reserved, the last kinds), else the engineering scale (a row of
 *   ilahrs_scales) above the builder bounds (a row of ilahrs_int_bounds or ilahrs_float_bounds, by
 *   kind); row 0 of each is "none".
 * The table has one row per field, written with NUMBER() or ARRAY().
 */
#define SIZE_LOG2(size) (((size) > 1) + ((size) > 2) + ((size) > 4))
#define FIELD_NAME_TYPE(name, kind, encoding, size) \
    (((name) << TYPE_BITS) | (SIZE_LOG2(size) << (KIND_BITS + ENCODING_BITS)) | ((encoding) << KIND_BITS) | (kind))
#define FIELD_PLACE(offset, member) ((((member) - (offset)) << OFFSET_BITS) | (offset))
#define NUMBER(name, kind, encoding, size, offset, member, bounds, scale)                                \
    { FIELD_NAME_TYPE(name, ILAHRS_KIND_##kind, ENCODING_##encoding, size), FIELD_PLACE(offset, member), \
      (bounds) | ((scale) << BOUNDS_BITS) }
#define ARRAY(name, kind, size, offset, member) \
    { FIELD_NAME_TYPE(name, ILAHRS_KIND_##kind, ENCODING_NONE, 1), FIELD_PLACE(offset, member), size }

#define FIELD_KIND(f) ((unsigned)(f)->name_type & ((1u << KIND_BITS) - 1u))
#define FIELD_ENCODING(f) (((unsigned)(f)->name_type >> KIND_BITS) & ((1u << ENCODING_BITS) - 1u))
#define FIELD_NAME_AT(f) ((unsigned)(f)->name_type >> TYPE_BITS)
#define FIELD_IS_ARRAY(f) (FIELD_KIND(f) >= ILAHRS_KIND_CHAR)
#define FIELD_ARRAY_SIZE(f) ((unsigned)(f)->info)
#define FIELD_NUMBER_SIZE(f) \
    (1u << (((unsigned)(f)->name_type & ((1u << TYPE_BITS) - 1u)) >> (KIND_BITS + ENCODING_BITS)))
#define FIELD_SIZE(f) (FIELD_IS_ARRAY(f) ? FIELD_ARRAY_SIZE(f) : FIELD_NUMBER_SIZE(f))
#define FIELD_OFFSET(f) ((unsigned)(f)->place & ((1u << OFFSET_BITS) - 1u))
#define FIELD_MEMBER(f) (FIELD_OFFSET(f) + ((unsigned)(f)->place >> OFFSET_BITS))
#define FIELD_BOUNDS(f) ((unsigned)(f)->info & ((1u << BOUNDS_BITS) - 1u))
#define FIELD_SCALE(f) ((unsigned)(f)->info >> BOUNDS_BITS)

/*
 * The device state machine, if the spec has one: a distinct outcome is the next state above an
 * answer sequence (OUTCOME()), and a table cell that differs from its state's default is the
 * (state, event) pair above the cell (CELL(): the outcome's row + 1, 0 for an ignored event).
 */
#define OUTCOME(state, sequence) (((unsigned)(state) << SEQUENCE_BITS) | (sequence))
#define CELL(state, event, cell) ((((unsigned)(state) * ILAHRS_EVENT_COUNT + (unsigned)(event)) << CELL_BITS) | (cell))

/* A little-endian number of 1..4 bytes, its size known at compile time, read in place; and the
 * write the generated frame code uses (defined with the helpers). The bytes are added, not or-ed:
 * the same machine code (one load where the target allows it), and a sum WP's provers relate to
 * the stream decoder's invariant (ilahrs_frame_size() in ilahrs.h, p[4] + 256 * p[5]). */
#define LE(p, size)                                                        \
    ((uint32_t)(p)[0] + ((size) > 1 ? (uint32_t)(p)[(size) > 1] << 8 : 0u) \
     + ((size) > 2 ? (uint32_t)(p)[(size) > 2 ? 2 : 0] << 16 : 0u)         \
     + ((size) > 3 ? (uint32_t)(p)[(size) > 3 ? 3 : 0] << 24 : 0u))
static void put_le(uint8_t *p, uint32_t value, size_t size);

/* ---- Tables ---------------------------------------------------------------------------- */

/* Error kind names, the text defaults of char fields and the variants' part numbers: in every
 * build. */
static const char ilahrs_error_names[172] =
    "truncated\000"
    "bad_header\000"
    "bad_message_type\000"
    "bad_length\000"
    "bad_checksum\000"
    "trailing_data\000"
    "unknown_command\000"
    "out_of_range\000"
    "malformed\000"
    "buffer_too_small\000"
    "unexpected_message\000"
    "timeout\000"
    "bad_reserved";

static const char ilahrs_text_names[1] = "";

static const char ilahrs_part_names[106] =
    "AHRS-G300-A2-TMGA-C1-V1.1\000"
    "AHRS-G300-A6-TMGA-C1-V1.1\000"
    "AHRS s/n 11AC0001 - 11AC0009\000"
    "AHRS-G300-A2-TGA-C1-V1.1";

static const uint8_t ilahrs_error_offsets[] = {
    [ILAHRS_ERR_TRUNCATED - 1] = 0,
    [ILAHRS_ERR_BAD_HEADER - 1] = 10,
    [ILAHRS_ERR_BAD_MESSAGE_TYPE - 1] = 21,
    [ILAHRS_ERR_BAD_LENGTH - 1] = 38,
    [ILAHRS_ERR_BAD_CHECKSUM - 1] = 49,
    [ILAHRS_ERR_TRAILING_DATA - 1] = 62,
    [ILAHRS_ERR_UNKNOWN_COMMAND - 1] = 76,
    [ILAHRS_ERR_OUT_OF_RANGE - 1] = 92,
    [ILAHRS_ERR_MALFORMED - 1] = 105,
    [ILAHRS_ERR_BUFFER_TOO_SMALL - 1] = 115,
    [ILAHRS_ERR_UNEXPECTED_MESSAGE - 1] = 132,
    [ILAHRS_ERR_TIMEOUT - 1] = 151,
    [ILAHRS_ERR_BAD_RESERVED - 1] = 159,
};

static const uint8_t ilahrs_part_offsets[ILAHRS_VARIANT_COUNT] = {
    [ILAHRS_VARIANT_G300_A2_TMGA] = 0,
    [ILAHRS_VARIANT_G300_A6_TMGA] = 26,
    [ILAHRS_VARIANT_SN_11AC0001_0009] = 52,
    [ILAHRS_VARIANT_G300_A2_TGA] = 81,
};

#if ILAHRS_NAMES
static const char ilahrs_frame_names[61] =
    "header\000"
    "payload\000"
    "message_type\000"
    "reserved\000"
    "message_length\000"
    "checksum";

static const char ilahrs_field_names[662] =
    "ugyro_x\000"
    "ugyro_y\000"
    "ugyro_z\000"
    "uacc_x\000"
    "uacc_y\000"
    "uacc_z\000"
    "umag_x\000"
    "umag_y\000"
    "umag_z\000"
    "reserved\000"
    "usw\000"
    "vdd\000"
    "utermo\000"
    "lk0\000"
    "lk1\000"
    "lk2\000"
    "lk3\000"
    "gyro_bias_x\000"
    "gyro_bias_y\000"
    "gyro_bias_z\000"
    "average_acc_x\000"
    "average_acc_y\000"
    "average_acc_z\000"
    "average_mag_x\000"
    "average_mag_y\000"
    "average_mag_z\000"
    "initial_heading\000"
    "initial_roll\000"
    "initial_pitch\000"
    "update_rate\000"
    "alignment_time\000"
    "declination\000"
    "latitude\000"
    "longitude\000"
    "altitude\000"
    "date\000"
    "alignment_angle_a1\000"
    "alignment_angle_a2\000"
    "alignment_angle_a3\000"
    "device_id\000"
    "version\000"
    "utermo100\000"
    "reference_azimuth\000"
    "accumulation_time\000"
    "calibration_type\000"
    "runs_used\000"
    "data_used\000"
    "success\000"
    "tm_c_11\000"
    "tm_c_12\000"
    "tm_c_13\000"
    "tm_c_21\000"
    "tm_c_22\000"
    "tm_c_23\000"
    "tm_c_31\000"
    "tm_c_32\000"
    "tm_c_33\000"
    "hm_0_x\000"
    "hm_0_y\000"
    "hm_0_z\000"
    "run\000"
    "reserved_1\000"
    "average_pitch\000"
    "average_roll\000"
    "reserved_2\000"
    "checksum";

static const char ilahrs_sentence_names[39] =
    "roll\000"
    "pitch\000"
    "heading\000"
    "temperature\000"
    "vdd\000"
    "usw";

static const char ilahrs_date_names[5] = "date";

/* The name accessors' pool and its offsets, one section per kind in the order of its enum. */
static const char ilahrs_name_names[1208] =
    "AHRScont1\000"
    "AHRScont2\000"
    "AHRScont3\000"
    "AHRSreq1\000"
    "AHRSreq2\000"
    "AHRSreq3\000"
    "NMEAcont\000"
    "NMEAreq\000"
    "GetDataReq\000"
    "Stop\000"
    "LoadAHRSPar\000"
    "ReadAHRSPar\000"
    "LowPowerOn\000"
    "LowPowerOff\000"
    "GetVerFirmware\000"
    "GetBIT\000"
    "Start2DClb\000"
    "Start2D2TClb\000"
    "Start3DClb\000"
    "StartClbRun\000"
    "StopClbRun\000"
    "FinishClb\000"
    "AcceptClb\000"
    "ExitClb\000"
    "ClearClb\000"
    "GetClbRes\000"
    "parameter_block\000"
    "other_message\000"
    "unknown\000"
    "block_timeout\000"
    "alignment_done\000"
    "accumulation_done\000"
    "output_due\000"
    "g300_a2_tmga\000"
    "g300_a6_tmga\000"
    "sn_11ac0001_0009\000"
    "g300_a2_tga\000"
    "idle\000"
    "calibration\000"
    "full_output\000"
    "quaternion\000"
    "orientation_sensors\000"
    "initial_alignment\000"
    "ahrs_parameters_load\000"
    "ahrs_parameters_read\000"
    "firmware_version\000"
    "bit_result\000"
    "calibration_parameters\000"
    "calibration_result\000"
    "calibration_run_result\000"
    "calibration_run_parameters\000"
    "calibration_status\000"
    "acknowledgement\000"
    "initial_alignment_failed\000"
    "parameters_incorrect\000"
    "gyro_failure\000"
    "accelerometer_failure\000"
    "magnetometer_failure\000"
    "electronics_failure\000"
    "software_failure\000"
    "low_supply_voltage\000"
    "high_supply_voltage\000"
    "x_rate_exceeded\000"
    "y_rate_exceeded\000"
    "z_rate_exceeded\000"
    "large_magnetic_field\000"
    "temperature_out_of_range\000"
    "aligning_continuous\000"
    "aligning_on_request\000"
    "calibration_awaiting_parameters\000"
    "calibration_aligning\000"
    "calibration_accumulating\000"
    "calibration_deciding\000"
    "runs_awaiting_parameters\000"
    "runs_ready\000"
    "run_awaiting_parameters\000"
    "run_aligning\000"
    "run_accumulating\000"
    "ack\000"
    "output_sleep";

static const uint16_t ilahrs_name_offsets[97] = {
    /* command */ 0,
    10,
    20,
    30,
    39,
    48,
    57,
    66,
    74,
    85,
    90,
    102,
    114,
    125,
    137,
    152,
    159,
    170,
    183,
    194,
    206,
    217,
    227,
    237,
    245,
    254,
    /* event */ 264,
    280,
    294,
    302,
    316,
    331,
    349,
    /* variant */ 360,
    373,
    386,
    403,
    /* mode */ 415,
    971,
    991,
    420,
    1202,
    /* payload */ 432,
    444,
    455,
    475,
    493,
    514,
    535,
    552,
    563,
    586,
    605,
    628,
    655,
    674,
    /* flag */ 690,
    715,
    736,
    749,
    771,
    792,
    812,
    9,
    829,
    848,
    868,
    884,
    900,
    916,
    937,
    /* state */ 415,
    1014,
    962,
    971,
    982,
    991,
    1202,
    1002,
    1034,
    1055,
    1080,
    1101,
    1126,
    1137,
    1161,
    1174,
    /* answer */ 1191,
    514,
    535,
    552,
    655,
    475,
    437,
    1195,
    586,
    605,
};
#define NAMES_COMMAND 0u
#define NAMES_EVENT 26u
#define NAMES_VARIANT 33u
#define NAMES_MODE 37u
#define NAMES_PAYLOAD 42u
#define NAMES_FLAG 56u
#define NAMES_FLAG_COUNT 15u /* one per USW bit up to the last flag */
#define NAMES_STATE 71u
#define NAMES_ANSWER 87u
#endif
#define NAME_FRAME_HEADER FRAME_NAME(0)
#define NAME_FRAME_PAYLOAD FRAME_NAME(7)
#define NAME_FRAME_CHECKSUM FRAME_NAME(52)
#define NAME_FRAME_MESSAGE_TYPE FRAME_NAME(15)
#define NAME_FRAME_RESERVED FRAME_NAME(28)
#define NAME_FRAME_MESSAGE_LENGTH FRAME_NAME(37)

/* The frame (frame_get_fields() and frame_put_fields(): the fields between header and payload
 * but the length, which the library checks and writes itself). */
typedef uint16_t checksum_t;
typedef uint16_t length_t; /* what the length field holds */
static const uint8_t ilahrs_frame_header[ILAHRS_FRAME_HEADER_SIZE] = { 0xAA, 0x55 };
#define MESSAGE_TYPE_VALID(type) ((type) == ILAHRS_MESSAGE_TYPE_COMMAND || (type) == ILAHRS_MESSAGE_TYPE_DATA)

static void frame_get_fields(ilahrs_frame_t *frame, const uint8_t *p)
{
    frame->message_type = (uint8_t)LE(p + ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, ILAHRS_FRAME_MESSAGE_TYPE_SIZE);
    frame->reserved = (uint8_t)LE(p + ILAHRS_FRAME_RESERVED_OFFSET, ILAHRS_FRAME_RESERVED_SIZE);
}

static void frame_put_fields(uint8_t *out, const ilahrs_frame_t *frame)
{
    put_le(out + ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, frame->message_type, ILAHRS_FRAME_MESSAGE_TYPE_SIZE);
    put_le(out + ILAHRS_FRAME_RESERVED_OFFSET, frame->reserved, ILAHRS_FRAME_RESERVED_SIZE);
}

/* Command table (Table C.1), one array per column so that a firmware links only the columns it
 * uses. */
static const uint8_t ilahrs_command_codes[ILAHRS_COMMAND_COUNT] = {
    [ILAHRS_COMMAND_AHRS_CONT1] = ILAHRS_CODE_AHRS_CONT1,
    [ILAHRS_COMMAND_AHRS_CONT2] = ILAHRS_CODE_AHRS_CONT2,
    [ILAHRS_COMMAND_AHRS_CONT3] = ILAHRS_CODE_AHRS_CONT3,
    [ILAHRS_COMMAND_AHRS_REQ1] = ILAHRS_CODE_AHRS_REQ1,
    [ILAHRS_COMMAND_AHRS_REQ2] = ILAHRS_CODE_AHRS_REQ2,
    [ILAHRS_COMMAND_AHRS_REQ3] = ILAHRS_CODE_AHRS_REQ3,
    [ILAHRS_COMMAND_NMEA_CONT] = ILAHRS_CODE_NMEA_CONT,
    [ILAHRS_COMMAND_NMEA_REQ] = ILAHRS_CODE_NMEA_REQ,
    [ILAHRS_COMMAND_GET_DATA_REQ] = ILAHRS_CODE_GET_DATA_REQ,
    [ILAHRS_COMMAND_STOP] = ILAHRS_CODE_STOP,
    [ILAHRS_COMMAND_LOAD_AHRS_PAR] = ILAHRS_CODE_LOAD_AHRS_PAR,
    [ILAHRS_COMMAND_READ_AHRS_PAR] = ILAHRS_CODE_READ_AHRS_PAR,
    [ILAHRS_COMMAND_LOW_POWER_ON] = ILAHRS_CODE_LOW_POWER_ON,
    [ILAHRS_COMMAND_LOW_POWER_OFF] = ILAHRS_CODE_LOW_POWER_OFF,
    [ILAHRS_COMMAND_GET_VER_FIRMWARE] = ILAHRS_CODE_GET_VER_FIRMWARE,
    [ILAHRS_COMMAND_GET_BIT] = ILAHRS_CODE_GET_BIT,
    [ILAHRS_COMMAND_START_2D_CLB] = ILAHRS_CODE_START_2D_CLB,
    [ILAHRS_COMMAND_START_2D2T_CLB] = ILAHRS_CODE_START_2D2T_CLB,
    [ILAHRS_COMMAND_START_3D_CLB] = ILAHRS_CODE_START_3D_CLB,
    [ILAHRS_COMMAND_START_CLB_RUN] = ILAHRS_CODE_START_CLB_RUN,
    [ILAHRS_COMMAND_STOP_CLB_RUN] = ILAHRS_CODE_STOP_CLB_RUN,
    [ILAHRS_COMMAND_FINISH_CLB] = ILAHRS_CODE_FINISH_CLB,
    [ILAHRS_COMMAND_ACCEPT_CLB] = ILAHRS_CODE_ACCEPT_CLB,
    [ILAHRS_COMMAND_EXIT_CLB] = ILAHRS_CODE_EXIT_CLB,
    [ILAHRS_COMMAND_CLEAR_CLB] = ILAHRS_CODE_CLEAR_CLB,
    [ILAHRS_COMMAND_GET_CLB_RES] = ILAHRS_CODE_GET_CLB_RES,
};

static const uint8_t ilahrs_command_modes[ILAHRS_COMMAND_COUNT] = {
    [ILAHRS_COMMAND_AHRS_CONT1] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_AHRS_CONT2] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_AHRS_CONT3] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_AHRS_REQ1] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_AHRS_REQ2] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_AHRS_REQ3] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_NMEA_CONT] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_NMEA_REQ] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_GET_DATA_REQ] = ILAHRS_MODE_BIT(ILAHRS_MODE_ON_REQUEST),
    [ILAHRS_COMMAND_STOP] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE) | ILAHRS_MODE_BIT(ILAHRS_MODE_CONTINUOUS)
                            | ILAHRS_MODE_BIT(ILAHRS_MODE_ON_REQUEST),
    [ILAHRS_COMMAND_LOAD_AHRS_PAR] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_READ_AHRS_PAR] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_LOW_POWER_ON] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE) | ILAHRS_MODE_BIT(ILAHRS_MODE_CONTINUOUS)
                                    | ILAHRS_MODE_BIT(ILAHRS_MODE_ON_REQUEST),
    [ILAHRS_COMMAND_LOW_POWER_OFF] = ILAHRS_MODE_BIT(ILAHRS_MODE_SLEEP),
    [ILAHRS_COMMAND_GET_VER_FIRMWARE] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_GET_BIT] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE) | ILAHRS_MODE_BIT(ILAHRS_MODE_ON_REQUEST),
    [ILAHRS_COMMAND_START_2D_CLB] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_START_2D2T_CLB] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_START_3D_CLB] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_START_CLB_RUN] = ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION),
    [ILAHRS_COMMAND_STOP_CLB_RUN] = ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION),
    [ILAHRS_COMMAND_FINISH_CLB] = ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION),
    [ILAHRS_COMMAND_ACCEPT_CLB] = ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION),
    [ILAHRS_COMMAND_EXIT_CLB] = ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION),
    [ILAHRS_COMMAND_CLEAR_CLB] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
    [ILAHRS_COMMAND_GET_CLB_RES] = ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE),
};

static const uint8_t ilahrs_command_responses[ILAHRS_COMMAND_COUNT] = {
    [ILAHRS_COMMAND_AHRS_CONT1] = ILAHRS_RESPONSE_ACK,        [ILAHRS_COMMAND_AHRS_CONT2] = ILAHRS_RESPONSE_ACK,
    [ILAHRS_COMMAND_AHRS_CONT3] = ILAHRS_RESPONSE_ACK,        [ILAHRS_COMMAND_AHRS_REQ1] = ILAHRS_RESPONSE_ACK,
    [ILAHRS_COMMAND_AHRS_REQ2] = ILAHRS_RESPONSE_ACK,         [ILAHRS_COMMAND_AHRS_REQ3] = ILAHRS_RESPONSE_ACK,
    [ILAHRS_COMMAND_NMEA_CONT] = ILAHRS_RESPONSE_ACK,         [ILAHRS_COMMAND_NMEA_REQ] = ILAHRS_RESPONSE_ACK,
    [ILAHRS_COMMAND_GET_DATA_REQ] = ILAHRS_RESPONSE_OUTPUT,   [ILAHRS_COMMAND_STOP] = ILAHRS_RESPONSE_NONE,
    [ILAHRS_COMMAND_LOAD_AHRS_PAR] = ILAHRS_RESPONSE_NONE,    [ILAHRS_COMMAND_READ_AHRS_PAR] = ILAHRS_RESPONSE_DATA,
    [ILAHRS_COMMAND_LOW_POWER_ON] = ILAHRS_RESPONSE_NONE,     [ILAHRS_COMMAND_LOW_POWER_OFF] = ILAHRS_RESPONSE_NONE,
    [ILAHRS_COMMAND_GET_VER_FIRMWARE] = ILAHRS_RESPONSE_DATA, [ILAHRS_COMMAND_GET_BIT] = ILAHRS_RESPONSE_DATA,
    [ILAHRS_COMMAND_START_2D_CLB] = ILAHRS_RESPONSE_NONE,     [ILAHRS_COMMAND_START_2D2T_CLB] = ILAHRS_RESPONSE_NONE,
    [ILAHRS_COMMAND_START_3D_CLB] = ILAHRS_RESPONSE_NONE,     [ILAHRS_COMMAND_START_CLB_RUN] = ILAHRS_RESPONSE_NONE,
    [ILAHRS_COMMAND_STOP_CLB_RUN] = ILAHRS_RESPONSE_DATA,     [ILAHRS_COMMAND_FINISH_CLB] = ILAHRS_RESPONSE_DATA,
    [ILAHRS_COMMAND_ACCEPT_CLB] = ILAHRS_RESPONSE_ACK,        [ILAHRS_COMMAND_EXIT_CLB] = ILAHRS_RESPONSE_ACK,
    [ILAHRS_COMMAND_CLEAR_CLB] = ILAHRS_RESPONSE_ACK,         [ILAHRS_COMMAND_GET_CLB_RES] = ILAHRS_RESPONSE_DATA,
};

static const int8_t ilahrs_command_blocks[ILAHRS_COMMAND_COUNT] = {
    [ILAHRS_COMMAND_AHRS_CONT1] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_AHRS_CONT2] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_AHRS_CONT3] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_AHRS_REQ1] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_AHRS_REQ2] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_AHRS_REQ3] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_NMEA_CONT] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_NMEA_REQ] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_GET_DATA_REQ] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_STOP] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_LOAD_AHRS_PAR] = ILAHRS_PAYLOAD_AHRS_PARAMETERS_LOAD,
    [ILAHRS_COMMAND_READ_AHRS_PAR] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_LOW_POWER_ON] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_LOW_POWER_OFF] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_GET_VER_FIRMWARE] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_GET_BIT] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_START_2D_CLB] = ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS,
    [ILAHRS_COMMAND_START_2D2T_CLB] = ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS,
    [ILAHRS_COMMAND_START_3D_CLB] = ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS,
    [ILAHRS_COMMAND_START_CLB_RUN] = ILAHRS_PAYLOAD_CALIBRATION_RUN_PARAMETERS,
    [ILAHRS_COMMAND_STOP_CLB_RUN] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_FINISH_CLB] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_ACCEPT_CLB] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_EXIT_CLB] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_CLEAR_CLB] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_COMMAND_GET_CLB_RES] = ILAHRS_PAYLOAD_NONE,
};

static const int8_t ilahrs_command_response_payloads[ILAHRS_COMMAND_COUNT][ILAHRS_RESPONSE_PAYLOADS_MAX] = {
    [ILAHRS_COMMAND_AHRS_CONT1] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_AHRS_CONT2] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_AHRS_CONT3] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_AHRS_REQ1] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_AHRS_REQ2] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_AHRS_REQ3] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_NMEA_CONT] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_NMEA_REQ] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_GET_DATA_REQ] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_STOP] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_LOAD_AHRS_PAR] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_READ_AHRS_PAR] = { ILAHRS_PAYLOAD_AHRS_PARAMETERS_READ, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_LOW_POWER_ON] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_LOW_POWER_OFF] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_GET_VER_FIRMWARE] = { ILAHRS_PAYLOAD_FIRMWARE_VERSION, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_GET_BIT] = { ILAHRS_PAYLOAD_BIT_RESULT, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_START_2D_CLB] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_START_2D2T_CLB] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_START_3D_CLB] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_START_CLB_RUN] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_STOP_CLB_RUN] = { ILAHRS_PAYLOAD_CALIBRATION_RESULT, ILAHRS_PAYLOAD_CALIBRATION_RUN_RESULT },
    [ILAHRS_COMMAND_FINISH_CLB] = { ILAHRS_PAYLOAD_CALIBRATION_RESULT, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_ACCEPT_CLB] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_EXIT_CLB] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_CLEAR_CLB] = { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE },
    [ILAHRS_COMMAND_GET_CLB_RES] = { ILAHRS_PAYLOAD_CALIBRATION_STATUS, ILAHRS_PAYLOAD_NONE },
};

/* Commands ordered by code, then ICD name: command_decode() reports all with one code. */
static const uint8_t ilahrs_commands_by_code[ILAHRS_COMMAND_COUNT] = {
    ILAHRS_COMMAND_GET_BIT,        ILAHRS_COMMAND_GET_VER_FIRMWARE,
    ILAHRS_COMMAND_STOP_CLB_RUN,   ILAHRS_COMMAND_START_2D_CLB,
    ILAHRS_COMMAND_START_2D2T_CLB, ILAHRS_COMMAND_START_3D_CLB,
    ILAHRS_COMMAND_GET_CLB_RES,    ILAHRS_COMMAND_START_CLB_RUN,
    ILAHRS_COMMAND_FINISH_CLB,     ILAHRS_COMMAND_ACCEPT_CLB,
    ILAHRS_COMMAND_CLEAR_CLB,      ILAHRS_COMMAND_LOAD_AHRS_PAR,
    ILAHRS_COMMAND_READ_AHRS_PAR,  ILAHRS_COMMAND_AHRS_CONT1,
    ILAHRS_COMMAND_AHRS_CONT2,     ILAHRS_COMMAND_AHRS_CONT3,
    ILAHRS_COMMAND_AHRS_REQ1,      ILAHRS_COMMAND_AHRS_REQ2,
    ILAHRS_COMMAND_AHRS_REQ3,      ILAHRS_COMMAND_NMEA_CONT,
    ILAHRS_COMMAND_NMEA_REQ,       ILAHRS_COMMAND_LOW_POWER_ON,
    ILAHRS_COMMAND_LOW_POWER_OFF,  ILAHRS_COMMAND_GET_DATA_REQ,
    ILAHRS_COMMAND_EXIT_CLB,       ILAHRS_COMMAND_STOP,
};

/* The meaning of a shared code in a mode where none of its names is valid (E14). */
#define CODE_DEFAULT_COUNT 1u
static const uint8_t ilahrs_code_defaults[1] = { ILAHRS_COMMAND_STOP };

/* Variant parameters: KG, KA. */
#define VARIANT_PARAMETER_COUNT 2u
static const int32_t ilahrs_variant_values[ILAHRS_VARIANT_COUNT][VARIANT_PARAMETER_COUNT] = {
    [ILAHRS_VARIANT_G300_A2_TMGA] = { [ILAHRS_PARAMETER_KG] = 100, [ILAHRS_PARAMETER_KA] = 10000, },
    [ILAHRS_VARIANT_G300_A6_TMGA] = { [ILAHRS_PARAMETER_KG] = 100, [ILAHRS_PARAMETER_KA] = 5000, },
    [ILAHRS_VARIANT_SN_11AC0001_0009] = { [ILAHRS_PARAMETER_KG] = 50, [ILAHRS_PARAMETER_KA] = 10000, },
    [ILAHRS_VARIANT_G300_A2_TGA] = { [ILAHRS_PARAMETER_KG] = 100, [ILAHRS_PARAMETER_KA] = 10000, },
};

/* Builder checks, inclusive; row 0 of each table means "no check: the C type is the range".
 * Integer fields compare as integers; float fields compare their float32 value, by float_key(),
 * with the float32 roundings of the bounds (exact, and no floating-point code linked), and
 * ilahrs_field_check() compares a double with the exact bounds as double keys. */
static const int32_t ilahrs_int_bounds[11][2] = {
    { 0, 0 }, { 0, 35999u }, { (-9000), 9000 }, { (-18000), 18000 }, { (-10000), 10000 }, { 1, 100 }, { 1, 65535u },
    { 1, 3 }, { 0, 100 },    { 2, 2 },          { 1, 255 },
};

static const int32_t ilahrs_float_bounds[8][2] = {
    { 0, 0 },                      /* 0.0f .. 0.0f */
    { (-2139095039), 2139095039 }, /* (-3.4028234663852886e+38f) .. 3.4028234663852886e+38f */
    { 0, 1135869952 },             /* 0.0f .. 360.0f */
    { (-1127481344), 1127481344 }, /* (-180.0f) .. 180.0f */
    { (-1119092736), 1119092736 }, /* (-90.0f) .. 90.0f */
    { (-1184645120), 1203982336 }, /* (-20000.0f) .. 100000.0f */
    { 1156415510, 1158250503 },    /* 1900.002685546875f .. 2200.001708984375f */
    { (-1135869952), 1135869952 }, /* (-360.0f) .. 360.0f */
};

static const int64_t ilahrs_exact_bounds[8][2] = {
    { 0ll, 0ll },                                        /* 0.0 .. 0.0 */
    { (-5183643170566569984ll), 5183643170566569984ll }, /* (-3.4028234663852886e+38) .. 3.4028234663852886e+38 */
    { 0ll, 4645040803167600640ll },                      /* 0.0 .. 360.0 */
    { (-4640537203540230144ll), 4640537203540230144ll }, /* (-180.0) .. 180.0 */
    { (-4636033603912859648ll), 4636033603912859648ll }, /* (-90.0) .. 90.0 */
    { (-4671226772094713856ll), 4681608360884174848ll }, /* (-20000.0) .. 100000.0 */
    { 4656071115628609536ll, 4657056269994033152ll },    /* 1900.002685546875 .. 2200.001708984375 */
    { (-4645040803167600640ll), 4645040803167600640ll }, /* (-360.0) .. 360.0 */
};

/* The declination rule as float keys and as double keys of the header's float constants. */
#define DECLINATION_MIN_KEY (-1127481344)
#define DECLINATION_MAX_KEY 1127481344
#define DECLINATION_COMPUTE_ABOVE_KEY 1135869952
#define DECLINATION_MIN_DKEY (-4640537203540230144ll)
#define DECLINATION_MAX_DKEY 4640537203540230144ll
#define DECLINATION_COMPUTE_ABOVE_DKEY 4645040803167600640ll

/* Engineering scales: raw * multiplier / divisor; with a parameter, the variant's value divides. */
#define NO_PARAMETER 255
static const struct {
    uint16_t divisor;
    uint8_t multiplier;
    uint8_t parameter;
} ilahrs_scales[8] = {
    {
        .divisor = 1,
        .multiplier = 1,
        .parameter = 255,
    },
    {
        .divisor = 100,
        .multiplier = 1,
        .parameter = 255,
    },
    {
        .divisor = 1000,
        .multiplier = 1,
        .parameter = 255,
    },
    {
        .divisor = 10000,
        .multiplier = 1,
        .parameter = 255,
    },
    {
        .divisor = 10,
        .multiplier = 1,
        .parameter = 255,
    },
    {
        .divisor = 0,
        .multiplier = 1,
        .parameter = 0,
    },
    {
        .divisor = 0,
        .multiplier = 1,
        .parameter = 1,
    },
    {
        .divisor = 1,
        .multiplier = 10,
        .parameter = 255,
    },
};

/* Every payload field, table after table, in wire order (runtime/rows.h). */
#define KIND_BITS 3u
#define ENCODING_BITS 1u
#define TYPE_BITS 6u
#define OFFSET_BITS 6u
#define BOUNDS_BITS 4u
#define ENCODING_NONE 0u
#define ENCODING_DECLINATION 1u
static const ilahrs_field_info_t ilahrs_fields[131] = {
    /* NUMBER(name, kind, encoding, size, offset, member, bounds, scale); ARRAY(name, kind, size, offset, member).
     * A row's comment spells its bare numbers: name@N is the name's offset in ilahrs_field_names,
     * bounds[N] the row of ilahrs_int_bounds or ilahrs_float_bounds (by kind; "finite": every finite
     * float), scale[N] the row of ilahrs_scales (multiplier/divisor, a variant parameter as divisor),
     * then the unit. A row 0 (no check, unscaled) is not mentioned. */
    /* full_output (Table 6.4) */
    NUMBER(234, UNSIGNED, NONE, 2, 0, 0, 1, 1),  /* heading: name@234, bounds[1]=0..35999, scale[1]=1/100 deg */
    NUMBER(263, SIGNED, NONE, 2, 2, 2, 2, 1),    /* pitch: name@263, bounds[2]=-9000..9000, scale[1]=1/100 deg */
    NUMBER(250, SIGNED, NONE, 2, 4, 4, 3, 1),    /* roll: name@250, bounds[3]=-18000..18000, scale[1]=1/100 deg */
    NUMBER(0, SIGNED, NONE, 2, 6, 6, 0, 0),      /* ugyro_x: name@0, in ADC */
    NUMBER(8, SIGNED, NONE, 2, 8, 8, 0, 0),      /* ugyro_y: name@8, in ADC */
    NUMBER(16, SIGNED, NONE, 2, 10, 10, 0, 0),   /* ugyro_z: name@16, in ADC */
    NUMBER(24, SIGNED, NONE, 2, 12, 12, 0, 0),   /* uacc_x: name@24, in ADC */
    NUMBER(31, SIGNED, NONE, 2, 14, 14, 0, 0),   /* uacc_y: name@31, in ADC */
    NUMBER(38, SIGNED, NONE, 2, 16, 16, 0, 0),   /* uacc_z: name@38, in ADC */
    NUMBER(45, SIGNED, NONE, 2, 18, 18, 0, 0),   /* umag_x: name@45, in ADC */
    NUMBER(52, SIGNED, NONE, 2, 20, 20, 0, 0),   /* umag_y: name@52, in ADC */
    NUMBER(59, SIGNED, NONE, 2, 22, 22, 0, 0),   /* umag_z: name@59, in ADC */
    ARRAY(66, RESERVED, 4, 24, 24),              /* reserved: name@66 */
    NUMBER(75, UNSIGNED, NONE, 2, 28, 28, 0, 0), /* usw: name@75 */
    NUMBER(79, UNSIGNED, NONE, 2, 30, 30, 0, 2), /* vdd: name@79, scale[2]=1/1000 V */
    NUMBER(83, SIGNED, NONE, 2, 32, 32, 0, 0),   /* utermo: name@83, in ADC */
    /* quaternion (Table 6.5) */
    NUMBER(234, UNSIGNED, NONE, 2, 0, 0, 1, 1),  /* heading: name@234, bounds[1]=0..35999, scale[1]=1/100 deg */
    NUMBER(263, SIGNED, NONE, 2, 2, 2, 2, 1),    /* pitch: name@263, bounds[2]=-9000..9000, scale[1]=1/100 deg */
    NUMBER(250, SIGNED, NONE, 2, 4, 4, 3, 1),    /* roll: name@250, bounds[3]=-18000..18000, scale[1]=1/100 deg */
    NUMBER(90, SIGNED, NONE, 2, 6, 6, 4, 3),     /* lk0: name@90, bounds[4]=-10000..10000, scale[3]=1/10000 */
    NUMBER(94, SIGNED, NONE, 2, 8, 8, 4, 3),     /* lk1: name@94, bounds[4]=-10000..10000, scale[3]=1/10000 */
    NUMBER(98, SIGNED, NONE, 2, 10, 10, 4, 3),   /* lk2: name@98, bounds[4]=-10000..10000, scale[3]=1/10000 */
    NUMBER(102, SIGNED, NONE, 2, 12, 12, 4, 3),  /* lk3: name@102, bounds[4]=-10000..10000, scale[3]=1/10000 */
    ARRAY(66, RESERVED, 14, 14, 14),             /* reserved: name@66 */
    NUMBER(75, UNSIGNED, NONE, 2, 28, 28, 0, 0), /* usw: name@75 */
    NUMBER(79, UNSIGNED, NONE, 2, 30, 30, 0, 2), /* vdd: name@79, scale[2]=1/1000 V */
    NUMBER(83, SIGNED, NONE, 2, 32, 32, 0, 4),   /* utermo: name@83, scale[4]=1/10 degC */
    /* orientation_sensors (Table 6.6) */
    NUMBER(234, UNSIGNED, NONE, 2, 0, 0, 1, 1),  /* heading: name@234, bounds[1]=0..35999, scale[1]=1/100 deg */
    NUMBER(263, SIGNED, NONE, 2, 2, 2, 2, 1),    /* pitch: name@263, bounds[2]=-9000..9000, scale[1]=1/100 deg */
    NUMBER(250, SIGNED, NONE, 2, 4, 4, 3, 1),    /* roll: name@250, bounds[3]=-18000..18000, scale[1]=1/100 deg */
    NUMBER(1, SIGNED, NONE, 2, 6, 6, 0, 5),      /* gyro_x: name@1, scale[5]=1/KG deg/s */
    NUMBER(9, SIGNED, NONE, 2, 8, 8, 0, 5),      /* gyro_y: name@9, scale[5]=1/KG deg/s */
    NUMBER(17, SIGNED, NONE, 2, 10, 10, 0, 5),   /* gyro_z: name@17, scale[5]=1/KG deg/s */
    NUMBER(25, SIGNED, NONE, 2, 12, 12, 0, 6),   /* acc_x: name@25, scale[6]=1/KA g */
    NUMBER(32, SIGNED, NONE, 2, 14, 14, 0, 6),   /* acc_y: name@32, scale[6]=1/KA g */
    NUMBER(39, SIGNED, NONE, 2, 16, 16, 0, 6),   /* acc_z: name@39, scale[6]=1/KA g */
    NUMBER(46, SIGNED, NONE, 2, 18, 18, 0, 7),   /* mag_x: name@46, scale[7]=10/1 nT */
    NUMBER(53, SIGNED, NONE, 2, 20, 20, 0, 7),   /* mag_y: name@53, scale[7]=10/1 nT */
    NUMBER(60, SIGNED, NONE, 2, 22, 22, 0, 7),   /* mag_z: name@60, scale[7]=10/1 nT */
    ARRAY(66, RESERVED, 4, 24, 24),              /* reserved: name@66 */
    NUMBER(75, UNSIGNED, NONE, 2, 28, 28, 0, 0), /* usw: name@75 */
    NUMBER(79, UNSIGNED, NONE, 2, 30, 30, 0, 2), /* vdd: name@79, scale[2]=1/1000 V */
    NUMBER(83, SIGNED, NONE, 2, 32, 32, 0, 4),   /* utermo: name@83, scale[4]=1/10 degC */
    /* initial_alignment (Table 6.8) */
    NUMBER(106, FLOAT, NONE, 4, 0, 0, 1, 0),     /* gyro_bias_x: name@106, bounds[1]=finite, in ADC */
    NUMBER(118, FLOAT, NONE, 4, 4, 4, 1, 0),     /* gyro_bias_y: name@118, bounds[1]=finite, in ADC */
    NUMBER(130, FLOAT, NONE, 4, 8, 8, 1, 0),     /* gyro_bias_z: name@130, bounds[1]=finite, in ADC */
    NUMBER(142, FLOAT, NONE, 4, 12, 12, 1, 0),   /* average_acc_x: name@142, bounds[1]=finite, in ADC */
    NUMBER(156, FLOAT, NONE, 4, 16, 16, 1, 0),   /* average_acc_y: name@156, bounds[1]=finite, in ADC */
    NUMBER(170, FLOAT, NONE, 4, 20, 20, 1, 0),   /* average_acc_z: name@170, bounds[1]=finite, in ADC */
    NUMBER(184, FLOAT, NONE, 4, 24, 24, 1, 0),   /* average_mag_x: name@184, bounds[1]=finite, in ADC */
    NUMBER(198, FLOAT, NONE, 4, 28, 28, 1, 0),   /* average_mag_y: name@198, bounds[1]=finite, in ADC */
    NUMBER(212, FLOAT, NONE, 4, 32, 32, 1, 0),   /* average_mag_z: name@212, bounds[1]=finite, in ADC */
    NUMBER(226, FLOAT, NONE, 4, 36, 36, 2, 0),   /* initial_heading: name@226, bounds[2]=0..360, in deg */
    NUMBER(242, FLOAT, NONE, 4, 40, 40, 3, 0),   /* initial_roll: name@242, bounds[3]=-180..180, in deg */
    NUMBER(255, FLOAT, NONE, 4, 44, 44, 4, 0),   /* initial_pitch: name@255, bounds[4]=-90..90, in deg */
    NUMBER(75, UNSIGNED, NONE, 2, 48, 48, 0, 0), /* usw: name@75 */
    /* ahrs_parameters_load (Table 6.9) */
    NUMBER(269, UNSIGNED, NONE, 2, 0, 0, 5, 0),     /* update_rate: name@269, bounds[5]=1..100, in Hz */
    NUMBER(281, UNSIGNED, NONE, 2, 2, 2, 6, 0),     /* alignment_time: name@281, bounds[6]=1..65535, in s */
    NUMBER(296, FLOAT, DECLINATION, 4, 4, 4, 1, 0), /* declination: name@296, bounds[1]=finite, in deg */
    NUMBER(308, FLOAT, NONE, 4, 8, 8, 4, 0),        /* latitude: name@308, bounds[4]=-90..90, in deg */
    NUMBER(317, FLOAT, NONE, 4, 12, 12, 3, 0),      /* longitude: name@317, bounds[3]=-180..180, in deg */
    NUMBER(327, FLOAT, NONE, 4, 16, 16, 5, 0),      /* altitude: name@327, bounds[5]=-20000..100000, in m */
    NUMBER(336, FLOAT, NONE, 4, 20, 20, 6, 0),      /* date: name@336, bounds[6]=1900.00269..2200.00171, in year */
    NUMBER(341, FLOAT, NONE, 4, 24, 24, 7, 0),      /* alignment_angle_a1: name@341, bounds[7]=-360..360, in deg */
    NUMBER(360, FLOAT, NONE, 4, 28, 28, 7, 0),      /* alignment_angle_a2: name@360, bounds[7]=-360..360, in deg */
    NUMBER(379, FLOAT, NONE, 4, 32, 32, 7, 0),      /* alignment_angle_a3: name@379, bounds[7]=-360..360, in deg */
    ARRAY(66, RESERVED, 14, 36, 36),                /* reserved: name@66 */
    /* ahrs_parameters_read (Table 6.10) */
    NUMBER(269, UNSIGNED, NONE, 2, 0, 0, 5, 0),     /* update_rate: name@269, bounds[5]=1..100, in Hz */
    NUMBER(281, UNSIGNED, NONE, 2, 2, 2, 6, 0),     /* alignment_time: name@281, bounds[6]=1..65535, in s */
    NUMBER(296, FLOAT, DECLINATION, 4, 4, 4, 1, 0), /* declination: name@296, bounds[1]=finite, in deg */
    NUMBER(308, FLOAT, NONE, 4, 8, 8, 4, 0),        /* latitude: name@308, bounds[4]=-90..90, in deg */
    NUMBER(317, FLOAT, NONE, 4, 12, 12, 3, 0),      /* longitude: name@317, bounds[3]=-180..180, in deg */
    NUMBER(327, FLOAT, NONE, 4, 16, 16, 5, 0),      /* altitude: name@327, bounds[5]=-20000..100000, in m */
    NUMBER(336, FLOAT, NONE, 4, 20, 20, 6, 0),      /* date: name@336, bounds[6]=1900.00269..2200.00171, in year */
    NUMBER(341, FLOAT, NONE, 4, 24, 24, 7, 0),      /* alignment_angle_a1: name@341, bounds[7]=-360..360, in deg */
    NUMBER(360, FLOAT, NONE, 4, 28, 28, 7, 0),      /* alignment_angle_a2: name@360, bounds[7]=-360..360, in deg */
    NUMBER(379, FLOAT, NONE, 4, 32, 32, 7, 0),      /* alignment_angle_a3: name@379, bounds[7]=-360..360, in deg */
    ARRAY(398, CHAR, 8, 36, 36),                    /* device_id: name@398 */
    ARRAY(66, RESERVED, 6, 44, 45),                 /* reserved: name@66 */
    /* firmware_version (Table 6.11) */
    ARRAY(408, CHAR, 50, 0, 0), /* version: name@408 */
    /* bit_result (Table 6.12) */
    NUMBER(416, SIGNED, NONE, 2, 0, 0, 0, 1),  /* utermo100: name@416, scale[1]=1/100 degC */
    NUMBER(75, UNSIGNED, NONE, 2, 2, 2, 0, 0), /* usw: name@75 */
    /* calibration_parameters (Table 6.13) */
    NUMBER(426, FLOAT, NONE, 4, 0, 0, 7, 0),    /* reference_azimuth: name@426, bounds[7]=-360..360, in deg */
    NUMBER(444, UNSIGNED, NONE, 2, 4, 4, 6, 0), /* accumulation_time: name@444, bounds[6]=1..65535, in s */
    NUMBER(308, FLOAT, NONE, 4, 6, 8, 4, 0),    /* latitude: name@308, bounds[4]=-90..90, in deg */
    NUMBER(317, FLOAT, NONE, 4, 10, 12, 3, 0),  /* longitude: name@317, bounds[3]=-180..180, in deg */
    NUMBER(327, FLOAT, NONE, 4, 14, 16, 5, 0),  /* altitude: name@327, bounds[5]=-20000..100000, in m */
    NUMBER(336, FLOAT, NONE, 4, 18, 20, 6, 0),  /* date: name@336, bounds[6]=1900.00269..2200.00171, in year */
    /* calibration_result (Table 6.14) */
    NUMBER(462, UNSIGNED, NONE, 1, 0, 0, 7, 0), /* calibration_type: name@462, bounds[7]=1..3 */
    NUMBER(479, UNSIGNED, NONE, 1, 1, 1, 0, 0), /* runs_used: name@479 */
    NUMBER(489, UNSIGNED, NONE, 1, 2, 2, 8, 0), /* data_used: name@489, bounds[8]=0..100, in % */
    NUMBER(499, UNSIGNED, NONE, 1, 3, 3, 0, 0), /* success: name@499 */
    NUMBER(507, FLOAT, NONE, 4, 4, 4, 1, 0),    /* tm_c_11: name@507, bounds[1]=finite */
    NUMBER(515, FLOAT, NONE, 4, 8, 8, 1, 0),    /* tm_c_12: name@515, bounds[1]=finite */
    NUMBER(523, FLOAT, NONE, 4, 12, 12, 1, 0),  /* tm_c_13: name@523, bounds[1]=finite */
    NUMBER(531, FLOAT, NONE, 4, 16, 16, 1, 0),  /* tm_c_21: name@531, bounds[1]=finite */
    NUMBER(539, FLOAT, NONE, 4, 20, 20, 1, 0),  /* tm_c_22: name@539, bounds[1]=finite */
    NUMBER(547, FLOAT, NONE, 4, 24, 24, 1, 0),  /* tm_c_23: name@547, bounds[1]=finite */
    NUMBER(555, FLOAT, NONE, 4, 28, 28, 1, 0),  /* tm_c_31: name@555, bounds[1]=finite */
    NUMBER(563, FLOAT, NONE, 4, 32, 32, 1, 0),  /* tm_c_32: name@563, bounds[1]=finite */
    NUMBER(571, FLOAT, NONE, 4, 36, 36, 1, 0),  /* tm_c_33: name@571, bounds[1]=finite */
    NUMBER(579, FLOAT, NONE, 4, 40, 40, 1, 0),  /* hm_0_x: name@579, bounds[1]=finite, in ADC */
    NUMBER(586, FLOAT, NONE, 4, 44, 44, 1, 0),  /* hm_0_y: name@586, bounds[1]=finite, in ADC */
    NUMBER(593, FLOAT, NONE, 4, 48, 48, 1, 0),  /* hm_0_z: name@593, bounds[1]=finite, in ADC */
    /* calibration_run_result (Table 6.15) */
    NUMBER(462, UNSIGNED, NONE, 1, 0, 0, 9, 0),  /* calibration_type: name@462, bounds[9]=2..2 */
    NUMBER(600, UNSIGNED, NONE, 1, 1, 1, 10, 0), /* run: name@600, bounds[10]=1..255 */
    NUMBER(489, UNSIGNED, NONE, 1, 2, 2, 8, 0),  /* data_used: name@489, bounds[8]=0..100, in % */
    NUMBER(499, UNSIGNED, NONE, 1, 3, 3, 0, 0),  /* success: name@499 */
    ARRAY(604, RESERVED, 4, 4, 4),               /* reserved_1: name@604 */
    NUMBER(615, FLOAT, NONE, 4, 8, 8, 4, 0),     /* average_pitch: name@615, bounds[4]=-90..90, in deg */
    NUMBER(629, FLOAT, NONE, 4, 12, 12, 3, 0),   /* average_roll: name@629, bounds[3]=-180..180, in deg */
    ARRAY(642, RESERVED, 12, 16, 16),            /* reserved_2: name@642 */
    NUMBER(75, UNSIGNED, NONE, 2, 28, 28, 0, 0), /* usw: name@75 */
    /* calibration_run_parameters (Table 6.16) */
    ARRAY(66, RESERVED, 6, 0, 0), /* reserved: name@66 */
    /* calibration_status (Table 6.17) */
    NUMBER(462, UNSIGNED, NONE, 1, 0, 0, 0, 0), /* calibration_type: name@462 */
    NUMBER(479, UNSIGNED, NONE, 1, 1, 1, 0, 0), /* runs_used: name@479 */
    ARRAY(66, RESERVED, 1, 2, 2),               /* reserved: name@66 */
    NUMBER(499, UNSIGNED, NONE, 1, 3, 3, 0, 0), /* success: name@499 */
    NUMBER(507, FLOAT, NONE, 4, 4, 4, 1, 0),    /* tm_c_11: name@507, bounds[1]=finite */
    NUMBER(515, FLOAT, NONE, 4, 8, 8, 1, 0),    /* tm_c_12: name@515, bounds[1]=finite */
    NUMBER(523, FLOAT, NONE, 4, 12, 12, 1, 0),  /* tm_c_13: name@523, bounds[1]=finite */
    NUMBER(531, FLOAT, NONE, 4, 16, 16, 1, 0),  /* tm_c_21: name@531, bounds[1]=finite */
    NUMBER(539, FLOAT, NONE, 4, 20, 20, 1, 0),  /* tm_c_22: name@539, bounds[1]=finite */
    NUMBER(547, FLOAT, NONE, 4, 24, 24, 1, 0),  /* tm_c_23: name@547, bounds[1]=finite */
    NUMBER(555, FLOAT, NONE, 4, 28, 28, 1, 0),  /* tm_c_31: name@555, bounds[1]=finite */
    NUMBER(563, FLOAT, NONE, 4, 32, 32, 1, 0),  /* tm_c_32: name@563, bounds[1]=finite */
    NUMBER(571, FLOAT, NONE, 4, 36, 36, 1, 0),  /* tm_c_33: name@571, bounds[1]=finite */
    NUMBER(579, FLOAT, NONE, 4, 40, 40, 1, 0),  /* hm_0_x: name@579, bounds[1]=finite, in ADC */
    NUMBER(586, FLOAT, NONE, 4, 44, 44, 1, 0),  /* hm_0_y: name@586, bounds[1]=finite, in ADC */
    NUMBER(593, FLOAT, NONE, 4, 48, 48, 1, 0),  /* hm_0_z: name@593, bounds[1]=finite, in ADC */
    /* acknowledgement (6.3.1 (Table 6.2 with a one-word payload)) */
    NUMBER(653, UNSIGNED, NONE, 2, 0, 0, 0, 0), /* checksum: name@653 */
};

static const struct {
    uint8_t size;
    uint8_t field_count;
    uint8_t first_field;
    uint8_t struct_size;
} ilahrs_payloads[ILAHRS_PAYLOAD_COUNT] = {
    [ILAHRS_PAYLOAD_FULL_OUTPUT] = { .size = 34,
                                     .field_count = 16,
                                     .first_field = 0,
                                     .struct_size = sizeof(ilahrs_full_output_t) },
    [ILAHRS_PAYLOAD_QUATERNION] = { .size = 34,
                                    .field_count = 11,
                                    .first_field = 16,
                                    .struct_size = sizeof(ilahrs_quaternion_t) },
    [ILAHRS_PAYLOAD_ORIENTATION_SENSORS] = { .size = 34,
                                             .field_count = 16,
                                             .first_field = 27,
                                             .struct_size = sizeof(ilahrs_orientation_sensors_t) },
    [ILAHRS_PAYLOAD_INITIAL_ALIGNMENT] = { .size = 50,
                                           .field_count = 13,
                                           .first_field = 43,
                                           .struct_size = sizeof(ilahrs_initial_alignment_t) },
    [ILAHRS_PAYLOAD_AHRS_PARAMETERS_LOAD] = { .size = 50,
                                              .field_count = 11,
                                              .first_field = 56,
                                              .struct_size = sizeof(ilahrs_ahrs_parameters_load_t) },
    [ILAHRS_PAYLOAD_AHRS_PARAMETERS_READ] = { .size = 50,
                                              .field_count = 12,
                                              .first_field = 67,
                                              .struct_size = sizeof(ilahrs_ahrs_parameters_read_t) },
    [ILAHRS_PAYLOAD_FIRMWARE_VERSION] = { .size = 50,
                                          .field_count = 1,
                                          .first_field = 79,
                                          .struct_size = sizeof(ilahrs_firmware_version_t) },
    [ILAHRS_PAYLOAD_BIT_RESULT] = { .size = 4,
                                    .field_count = 2,
                                    .first_field = 80,
                                    .struct_size = sizeof(ilahrs_bit_result_t) },
    [ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS] = { .size = 22,
                                                .field_count = 6,
                                                .first_field = 82,
                                                .struct_size = sizeof(ilahrs_calibration_parameters_t) },
    [ILAHRS_PAYLOAD_CALIBRATION_RESULT] = { .size = 52,
                                            .field_count = 16,
                                            .first_field = 88,
                                            .struct_size = sizeof(ilahrs_calibration_result_t) },
    [ILAHRS_PAYLOAD_CALIBRATION_RUN_RESULT] = { .size = 30,
                                                .field_count = 9,
                                                .first_field = 104,
                                                .struct_size = sizeof(ilahrs_calibration_run_result_t) },
    [ILAHRS_PAYLOAD_CALIBRATION_RUN_PARAMETERS] = { .size = 6,
                                                    .field_count = 1,
                                                    .first_field = 113,
                                                    .struct_size = sizeof(ilahrs_calibration_run_parameters_t) },
    [ILAHRS_PAYLOAD_CALIBRATION_STATUS] = { .size = 52,
                                            .field_count = 16,
                                            .first_field = 114,
                                            .struct_size = sizeof(ilahrs_calibration_status_t) },
    [ILAHRS_PAYLOAD_ACKNOWLEDGEMENT] = { .size = 2,
                                         .field_count = 1,
                                         .first_field = 130,
                                         .struct_size = sizeof(ilahrs_acknowledgement_t) },
};

/* The acknowledgement's table (ilahrs_ack_build()). */
#define ACK_PAYLOAD ILAHRS_PAYLOAD_ACKNOWLEDGEMENT
typedef ilahrs_acknowledgement_t ack_payload_t;

/* Builder defaults other than zero (the spec default, else the lowest value the range allows):
 * the field's row, and the text pool offset of a char field's text or the bits of a number's member. */
#define DEFAULT_COUNT 11u
static const struct {
    uint32_t bits;
    uint8_t field;
    uint8_t text;
} ilahrs_defaults[11] = {
    { .field = 56, .bits = 0x00000064u },  /* ahrs_parameters_load.update_rate = 100 */
    { .field = 57, .bits = 0x0000001Eu },  /* ahrs_parameters_load.alignment_time = 30 */
    { .field = 62, .bits = 0x44ED8016u },  /* ahrs_parameters_load.date = 1900.002685546875f */
    { .field = 67, .bits = 0x00000001u },  /* ahrs_parameters_read.update_rate = 1 */
    { .field = 68, .bits = 0x00000001u },  /* ahrs_parameters_read.alignment_time = 1 */
    { .field = 73, .bits = 0x44ED8016u },  /* ahrs_parameters_read.date = 1900.002685546875f */
    { .field = 83, .bits = 0x00000001u },  /* calibration_parameters.accumulation_time = 1 */
    { .field = 87, .bits = 0x44ED8016u },  /* calibration_parameters.date = 1900.002685546875f */
    { .field = 88, .bits = 0x00000001u },  /* calibration_result.calibration_type = 1 */
    { .field = 104, .bits = 0x00000002u }, /* calibration_run_result.calibration_type = 2 */
    { .field = 105, .bits = 0x00000001u }, /* calibration_run_result.run = 1 */
};

/* C99 compile-time checks: struct sizes fit ilahrs_payloads, and each member lies where
 * ilahrs_fields says (the generator's natural alignment). */
typedef char ilahrs_check_full_output
    [sizeof(ilahrs_full_output_t) <= 255 && offsetof(ilahrs_full_output_t, heading) == 0
             && offsetof(ilahrs_full_output_t, pitch) == 2 && offsetof(ilahrs_full_output_t, roll) == 4
             && offsetof(ilahrs_full_output_t, ugyro_x) == 6 && offsetof(ilahrs_full_output_t, ugyro_y) == 8
             && offsetof(ilahrs_full_output_t, ugyro_z) == 10 && offsetof(ilahrs_full_output_t, uacc_x) == 12
             && offsetof(ilahrs_full_output_t, uacc_y) == 14 && offsetof(ilahrs_full_output_t, uacc_z) == 16
             && offsetof(ilahrs_full_output_t, umag_x) == 18 && offsetof(ilahrs_full_output_t, umag_y) == 20
             && offsetof(ilahrs_full_output_t, umag_z) == 22 && offsetof(ilahrs_full_output_t, reserved) == 24
             && offsetof(ilahrs_full_output_t, usw) == 28 && offsetof(ilahrs_full_output_t, vdd) == 30
             && offsetof(ilahrs_full_output_t, utermo) == 32
         ? 1
         : -1];
typedef char ilahrs_check_quaternion
    [sizeof(ilahrs_quaternion_t) <= 255 && offsetof(ilahrs_quaternion_t, heading) == 0
             && offsetof(ilahrs_quaternion_t, pitch) == 2 && offsetof(ilahrs_quaternion_t, roll) == 4
             && offsetof(ilahrs_quaternion_t, lk0) == 6 && offsetof(ilahrs_quaternion_t, lk1) == 8
             && offsetof(ilahrs_quaternion_t, lk2) == 10 && offsetof(ilahrs_quaternion_t, lk3) == 12
             && offsetof(ilahrs_quaternion_t, reserved) == 14 && offsetof(ilahrs_quaternion_t, usw) == 28
             && offsetof(ilahrs_quaternion_t, vdd) == 30 && offsetof(ilahrs_quaternion_t, utermo) == 32
         ? 1
         : -1];
typedef char ilahrs_check_orientation_sensors
    [sizeof(ilahrs_orientation_sensors_t) <= 255 && offsetof(ilahrs_orientation_sensors_t, heading) == 0
             && offsetof(ilahrs_orientation_sensors_t, pitch) == 2 && offsetof(ilahrs_orientation_sensors_t, roll) == 4
             && offsetof(ilahrs_orientation_sensors_t, gyro_x) == 6
             && offsetof(ilahrs_orientation_sensors_t, gyro_y) == 8
             && offsetof(ilahrs_orientation_sensors_t, gyro_z) == 10
             && offsetof(ilahrs_orientation_sensors_t, acc_x) == 12
             && offsetof(ilahrs_orientation_sensors_t, acc_y) == 14
             && offsetof(ilahrs_orientation_sensors_t, acc_z) == 16
             && offsetof(ilahrs_orientation_sensors_t, mag_x) == 18
             && offsetof(ilahrs_orientation_sensors_t, mag_y) == 20
             && offsetof(ilahrs_orientation_sensors_t, mag_z) == 22
             && offsetof(ilahrs_orientation_sensors_t, reserved) == 24
             && offsetof(ilahrs_orientation_sensors_t, usw) == 28 && offsetof(ilahrs_orientation_sensors_t, vdd) == 30
             && offsetof(ilahrs_orientation_sensors_t, utermo) == 32
         ? 1
         : -1];
typedef char ilahrs_check_initial_alignment[sizeof(ilahrs_initial_alignment_t) <= 255
                                                    && offsetof(ilahrs_initial_alignment_t, gyro_bias_x) == 0
                                                    && offsetof(ilahrs_initial_alignment_t, gyro_bias_y) == 4
                                                    && offsetof(ilahrs_initial_alignment_t, gyro_bias_z) == 8
                                                    && offsetof(ilahrs_initial_alignment_t, average_acc_x) == 12
                                                    && offsetof(ilahrs_initial_alignment_t, average_acc_y) == 16
                                                    && offsetof(ilahrs_initial_alignment_t, average_acc_z) == 20
                                                    && offsetof(ilahrs_initial_alignment_t, average_mag_x) == 24
                                                    && offsetof(ilahrs_initial_alignment_t, average_mag_y) == 28
                                                    && offsetof(ilahrs_initial_alignment_t, average_mag_z) == 32
                                                    && offsetof(ilahrs_initial_alignment_t, initial_heading) == 36
                                                    && offsetof(ilahrs_initial_alignment_t, initial_roll) == 40
                                                    && offsetof(ilahrs_initial_alignment_t, initial_pitch) == 44
                                                    && offsetof(ilahrs_initial_alignment_t, usw) == 48
                                                ? 1
                                                : -1];
typedef char
    ilahrs_check_ahrs_parameters_load[sizeof(ilahrs_ahrs_parameters_load_t) <= 255
                                              && offsetof(ilahrs_ahrs_parameters_load_t, update_rate) == 0
                                              && offsetof(ilahrs_ahrs_parameters_load_t, alignment_time) == 2
                                              && offsetof(ilahrs_ahrs_parameters_load_t, declination) == 4
                                              && offsetof(ilahrs_ahrs_parameters_load_t, latitude) == 8
                                              && offsetof(ilahrs_ahrs_parameters_load_t, longitude) == 12
                                              && offsetof(ilahrs_ahrs_parameters_load_t, altitude) == 16
                                              && offsetof(ilahrs_ahrs_parameters_load_t, date) == 20
                                              && offsetof(ilahrs_ahrs_parameters_load_t, alignment_angle_a1) == 24
                                              && offsetof(ilahrs_ahrs_parameters_load_t, alignment_angle_a2) == 28
                                              && offsetof(ilahrs_ahrs_parameters_load_t, alignment_angle_a3) == 32
                                              && offsetof(ilahrs_ahrs_parameters_load_t, reserved) == 36
                                          ? 1
                                          : -1];
typedef char
    ilahrs_check_ahrs_parameters_read[sizeof(ilahrs_ahrs_parameters_read_t) <= 255
                                              && offsetof(ilahrs_ahrs_parameters_read_t, update_rate) == 0
                                              && offsetof(ilahrs_ahrs_parameters_read_t, alignment_time) == 2
                                              && offsetof(ilahrs_ahrs_parameters_read_t, declination) == 4
                                              && offsetof(ilahrs_ahrs_parameters_read_t, latitude) == 8
                                              && offsetof(ilahrs_ahrs_parameters_read_t, longitude) == 12
                                              && offsetof(ilahrs_ahrs_parameters_read_t, altitude) == 16
                                              && offsetof(ilahrs_ahrs_parameters_read_t, date) == 20
                                              && offsetof(ilahrs_ahrs_parameters_read_t, alignment_angle_a1) == 24
                                              && offsetof(ilahrs_ahrs_parameters_read_t, alignment_angle_a2) == 28
                                              && offsetof(ilahrs_ahrs_parameters_read_t, alignment_angle_a3) == 32
                                              && offsetof(ilahrs_ahrs_parameters_read_t, device_id) == 36
                                              && offsetof(ilahrs_ahrs_parameters_read_t, reserved) == 45
                                          ? 1
                                          : -1];
typedef char ilahrs_check_firmware_version
    [sizeof(ilahrs_firmware_version_t) <= 255 && offsetof(ilahrs_firmware_version_t, version) == 0 ? 1 : -1];
typedef char ilahrs_check_bit_result[sizeof(ilahrs_bit_result_t) <= 255 && offsetof(ilahrs_bit_result_t, utermo100) == 0
                                             && offsetof(ilahrs_bit_result_t, usw) == 2
                                         ? 1
                                         : -1];
typedef char
    ilahrs_check_calibration_parameters[sizeof(ilahrs_calibration_parameters_t) <= 255
                                                && offsetof(ilahrs_calibration_parameters_t, reference_azimuth) == 0
                                                && offsetof(ilahrs_calibration_parameters_t, accumulation_time) == 4
                                                && offsetof(ilahrs_calibration_parameters_t, latitude) == 8
                                                && offsetof(ilahrs_calibration_parameters_t, longitude) == 12
                                                && offsetof(ilahrs_calibration_parameters_t, altitude) == 16
                                                && offsetof(ilahrs_calibration_parameters_t, date) == 20
                                            ? 1
                                            : -1];
typedef char ilahrs_check_calibration_result[sizeof(ilahrs_calibration_result_t) <= 255
                                                     && offsetof(ilahrs_calibration_result_t, calibration_type) == 0
                                                     && offsetof(ilahrs_calibration_result_t, runs_used) == 1
                                                     && offsetof(ilahrs_calibration_result_t, data_used) == 2
                                                     && offsetof(ilahrs_calibration_result_t, success) == 3
                                                     && offsetof(ilahrs_calibration_result_t, tm_c_11) == 4
                                                     && offsetof(ilahrs_calibration_result_t, tm_c_12) == 8
                                                     && offsetof(ilahrs_calibration_result_t, tm_c_13) == 12
                                                     && offsetof(ilahrs_calibration_result_t, tm_c_21) == 16
                                                     && offsetof(ilahrs_calibration_result_t, tm_c_22) == 20
                                                     && offsetof(ilahrs_calibration_result_t, tm_c_23) == 24
                                                     && offsetof(ilahrs_calibration_result_t, tm_c_31) == 28
                                                     && offsetof(ilahrs_calibration_result_t, tm_c_32) == 32
                                                     && offsetof(ilahrs_calibration_result_t, tm_c_33) == 36
                                                     && offsetof(ilahrs_calibration_result_t, hm_0_x) == 40
                                                     && offsetof(ilahrs_calibration_result_t, hm_0_y) == 44
                                                     && offsetof(ilahrs_calibration_result_t, hm_0_z) == 48
                                                 ? 1
                                                 : -1];
typedef char
    ilahrs_check_calibration_run_result[sizeof(ilahrs_calibration_run_result_t) <= 255
                                                && offsetof(ilahrs_calibration_run_result_t, calibration_type) == 0
                                                && offsetof(ilahrs_calibration_run_result_t, run) == 1
                                                && offsetof(ilahrs_calibration_run_result_t, data_used) == 2
                                                && offsetof(ilahrs_calibration_run_result_t, success) == 3
                                                && offsetof(ilahrs_calibration_run_result_t, reserved_1) == 4
                                                && offsetof(ilahrs_calibration_run_result_t, average_pitch) == 8
                                                && offsetof(ilahrs_calibration_run_result_t, average_roll) == 12
                                                && offsetof(ilahrs_calibration_run_result_t, reserved_2) == 16
                                                && offsetof(ilahrs_calibration_run_result_t, usw) == 28
                                            ? 1
                                            : -1];
typedef char
    ilahrs_check_calibration_run_parameters[sizeof(ilahrs_calibration_run_parameters_t) <= 255
                                                    && offsetof(ilahrs_calibration_run_parameters_t, reserved) == 0
                                                ? 1
                                                : -1];
typedef char ilahrs_check_calibration_status[sizeof(ilahrs_calibration_status_t) <= 255
                                                     && offsetof(ilahrs_calibration_status_t, calibration_type) == 0
                                                     && offsetof(ilahrs_calibration_status_t, runs_used) == 1
                                                     && offsetof(ilahrs_calibration_status_t, reserved) == 2
                                                     && offsetof(ilahrs_calibration_status_t, success) == 3
                                                     && offsetof(ilahrs_calibration_status_t, tm_c_11) == 4
                                                     && offsetof(ilahrs_calibration_status_t, tm_c_12) == 8
                                                     && offsetof(ilahrs_calibration_status_t, tm_c_13) == 12
                                                     && offsetof(ilahrs_calibration_status_t, tm_c_21) == 16
                                                     && offsetof(ilahrs_calibration_status_t, tm_c_22) == 20
                                                     && offsetof(ilahrs_calibration_status_t, tm_c_23) == 24
                                                     && offsetof(ilahrs_calibration_status_t, tm_c_31) == 28
                                                     && offsetof(ilahrs_calibration_status_t, tm_c_32) == 32
                                                     && offsetof(ilahrs_calibration_status_t, tm_c_33) == 36
                                                     && offsetof(ilahrs_calibration_status_t, hm_0_x) == 40
                                                     && offsetof(ilahrs_calibration_status_t, hm_0_y) == 44
                                                     && offsetof(ilahrs_calibration_status_t, hm_0_z) == 48
                                                 ? 1
                                                 : -1];
typedef char ilahrs_check_acknowledgement
    [sizeof(ilahrs_acknowledgement_t) <= 255 && offsetof(ilahrs_acknowledgement_t, checksum) == 0 ? 1 : -1];

/* The date (Table 6.9, Table 6.10, Table 6.13): a date scaled by DATE_SCALE, the least common multiple of the term
 * divisors, and the float keys of the dates a decoder accepts. */
#define DATE_SCALE 4380u
#define DATE_DECODE_MIN_KEY 1156415488
#define DATE_DECODE_MAX_KEY 1158254591
#define DATE_EXPONENT 137u

static int32_t date_scaled(int year, int month, int day)
{
    return (year + (0)) * 4380 + (month + (-1)) * 365 + (day + (0)) * 12;
}

/* $PAHR (Table 6.7, section 6.2): one row per field: name, hex or decimal, template width, fraction digits,
 * struct member and its size (PAHR_ROW_MEMBERS), range (scaled); the member is signed when the range
 * is. Magnitudes saturate at SATURATED, above every range. */
#define PAHR_PREFIX "$PAHR,"
#define SATURATED 0x01000000u
#define PAHR_HEX_FIELDS 1
#define PAHR_MAX_DECIMALS 2
/* Every member of ilahrs_pahr_t has the same size, in the order of the fields: compiled for size,
 * the rows leave out member and size (pahr.c: PAHR_MEMBER()). */
#define PAHR_MEMBER_SIZE sizeof(((ilahrs_pahr_t *)0)->roll)
typedef char pahr_check_members[offsetof(ilahrs_pahr_t, pitch) == 1 * PAHR_MEMBER_SIZE
                                        && offsetof(ilahrs_pahr_t, heading) == 2 * PAHR_MEMBER_SIZE
                                        && offsetof(ilahrs_pahr_t, temperature) == 3 * PAHR_MEMBER_SIZE
                                        && offsetof(ilahrs_pahr_t, vdd) == 4 * PAHR_MEMBER_SIZE
                                        && offsetof(ilahrs_pahr_t, usw) == 5 * PAHR_MEMBER_SIZE
                                        && sizeof(ilahrs_pahr_t) == 6 * PAHR_MEMBER_SIZE
                                    ? 1
                                    : -1];
#if defined(__OPTIMIZE__) && !defined(__OPTIMIZE_SIZE__)
#define PAHR_ROW_MEMBERS 1
#else
#define PAHR_ROW_MEMBERS 0
#endif
typedef struct {
    uint8_t name;
    uint8_t hex;
    uint8_t width;
    uint8_t decimals;
#if PAHR_ROW_MEMBERS
    uint8_t member;
    uint8_t size;
#endif
    int16_t min;
    uint16_t max;
} pahr_field_t;

static const pahr_field_t ilahrs_pahr_fields[ILAHRS_PAHR_FIELD_COUNT] = {
    { .name = 0,
      .hex = 0,
      .width = 4,
      .decimals = 2,
#if PAHR_ROW_MEMBERS
      .member = offsetof(ilahrs_pahr_t, roll),
      .size = sizeof(((ilahrs_pahr_t *)0)->roll),
#endif
      .min = (-18000),
      .max = 18000 },
    { .name = 5,
      .hex = 0,
      .width = 3,
      .decimals = 2,
#if PAHR_ROW_MEMBERS
      .member = offsetof(ilahrs_pahr_t, pitch),
      .size = sizeof(((ilahrs_pahr_t *)0)->pitch),
#endif
      .min = (-9000),
      .max = 9000 },
    { .name = 11,
      .hex = 0,
      .width = 3,
      .decimals = 2,
#if PAHR_ROW_MEMBERS
      .member = offsetof(ilahrs_pahr_t, heading),
      .size = sizeof(((ilahrs_pahr_t *)0)->heading),
#endif
      .min = 0,
      .max = 35999u },
    { .name = 19,
      .hex = 0,
      .width = 3,
      .decimals = 1,
#if PAHR_ROW_MEMBERS
      .member = offsetof(ilahrs_pahr_t, temperature),
      .size = sizeof(((ilahrs_pahr_t *)0)->temperature),
#endif
      .min = (-999),
      .max = 9999 },
    { .name = 31,
      .hex = 0,
      .width = 1,
      .decimals = 2,
#if PAHR_ROW_MEMBERS
      .member = offsetof(ilahrs_pahr_t, vdd),
      .size = sizeof(((ilahrs_pahr_t *)0)->vdd),
#endif
      .min = 0,
      .max = 999 },
    { .name = 35,
      .hex = 1,
      .width = 4,
      .decimals = 0,
#if PAHR_ROW_MEMBERS
      .member = offsetof(ilahrs_pahr_t, usw),
      .size = sizeof(((ilahrs_pahr_t *)0)->usw),
#endif
      .min = 0,
      .max = 65535u },
};

/* The device state machine (6.1, 6.3, 6.4): states, one array per column: mode, the parameter
 * block awaited, the event its timer fires (ILAHRS_EVENT_COUNT: none). */
static const uint8_t ilahrs_state_modes[ILAHRS_STATE_COUNT] = {
    [ILAHRS_STATE_IDLE] = ILAHRS_MODE_IDLE,
    [ILAHRS_STATE_AWAITING_PARAMETERS] = ILAHRS_MODE_IDLE,
    [ILAHRS_STATE_ALIGNING_CONTINUOUS] = ILAHRS_MODE_CONTINUOUS,
    [ILAHRS_STATE_CONTINUOUS] = ILAHRS_MODE_CONTINUOUS,
    [ILAHRS_STATE_ALIGNING_ON_REQUEST] = ILAHRS_MODE_ON_REQUEST,
    [ILAHRS_STATE_ON_REQUEST] = ILAHRS_MODE_ON_REQUEST,
    [ILAHRS_STATE_SLEEP] = ILAHRS_MODE_SLEEP,
    [ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS] = ILAHRS_MODE_CALIBRATION,
    [ILAHRS_STATE_CALIBRATION_ALIGNING] = ILAHRS_MODE_CALIBRATION,
    [ILAHRS_STATE_CALIBRATION_ACCUMULATING] = ILAHRS_MODE_CALIBRATION,
    [ILAHRS_STATE_CALIBRATION_DECIDING] = ILAHRS_MODE_CALIBRATION,
    [ILAHRS_STATE_RUNS_AWAITING_PARAMETERS] = ILAHRS_MODE_CALIBRATION,
    [ILAHRS_STATE_RUNS_READY] = ILAHRS_MODE_CALIBRATION,
    [ILAHRS_STATE_RUN_AWAITING_PARAMETERS] = ILAHRS_MODE_CALIBRATION,
    [ILAHRS_STATE_RUN_ALIGNING] = ILAHRS_MODE_CALIBRATION,
    [ILAHRS_STATE_RUN_ACCUMULATING] = ILAHRS_MODE_CALIBRATION,
};

static const int8_t ilahrs_state_blocks[ILAHRS_STATE_COUNT] = {
    [ILAHRS_STATE_IDLE] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_STATE_AWAITING_PARAMETERS] = ILAHRS_PAYLOAD_AHRS_PARAMETERS_LOAD,
    [ILAHRS_STATE_ALIGNING_CONTINUOUS] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_STATE_CONTINUOUS] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_STATE_ALIGNING_ON_REQUEST] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_STATE_ON_REQUEST] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_STATE_SLEEP] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS] = ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS,
    [ILAHRS_STATE_CALIBRATION_ALIGNING] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_STATE_CALIBRATION_ACCUMULATING] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_STATE_CALIBRATION_DECIDING] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_STATE_RUNS_AWAITING_PARAMETERS] = ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS,
    [ILAHRS_STATE_RUNS_READY] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_STATE_RUN_AWAITING_PARAMETERS] = ILAHRS_PAYLOAD_CALIBRATION_RUN_PARAMETERS,
    [ILAHRS_STATE_RUN_ALIGNING] = ILAHRS_PAYLOAD_NONE,
    [ILAHRS_STATE_RUN_ACCUMULATING] = ILAHRS_PAYLOAD_NONE,
};

static const uint8_t ilahrs_state_timers[ILAHRS_STATE_COUNT] = {
    [ILAHRS_STATE_IDLE] = ILAHRS_EVENT_COUNT,
    [ILAHRS_STATE_AWAITING_PARAMETERS] = ILAHRS_EVENT_COUNT,
    [ILAHRS_STATE_ALIGNING_CONTINUOUS] = ILAHRS_EVENT_ALIGNMENT_DONE,
    [ILAHRS_STATE_CONTINUOUS] = ILAHRS_EVENT_OUTPUT_DUE,
    [ILAHRS_STATE_ALIGNING_ON_REQUEST] = ILAHRS_EVENT_ALIGNMENT_DONE,
    [ILAHRS_STATE_ON_REQUEST] = ILAHRS_EVENT_COUNT,
    [ILAHRS_STATE_SLEEP] = ILAHRS_EVENT_COUNT,
    [ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS] = ILAHRS_EVENT_COUNT,
    [ILAHRS_STATE_CALIBRATION_ALIGNING] = ILAHRS_EVENT_ALIGNMENT_DONE,
    [ILAHRS_STATE_CALIBRATION_ACCUMULATING] = ILAHRS_EVENT_ACCUMULATION_DONE,
    [ILAHRS_STATE_CALIBRATION_DECIDING] = ILAHRS_EVENT_COUNT,
    [ILAHRS_STATE_RUNS_AWAITING_PARAMETERS] = ILAHRS_EVENT_COUNT,
    [ILAHRS_STATE_RUNS_READY] = ILAHRS_EVENT_COUNT,
    [ILAHRS_STATE_RUN_AWAITING_PARAMETERS] = ILAHRS_EVENT_COUNT,
    [ILAHRS_STATE_RUN_ALIGNING] = ILAHRS_EVENT_ALIGNMENT_DONE,
    [ILAHRS_STATE_RUN_ACCUMULATING] = ILAHRS_EVENT_ACCUMULATION_DONE,
};

/* Answers: the payload table it sends, the USW mode an output answer reports (NO_USW_MODE: none). */
#define NO_USW_MODE 0xFFu
static const struct {
    int8_t payload;
    uint8_t usw_mode;
} ilahrs_answers[ILAHRS_ANSWER_COUNT] = {
    [ILAHRS_ANSWER_ACK] = { .payload = ILAHRS_PAYLOAD_NONE, .usw_mode = NO_USW_MODE },
    [ILAHRS_ANSWER_AHRS_PARAMETERS_READ] = { .payload = ILAHRS_PAYLOAD_AHRS_PARAMETERS_READ, .usw_mode = NO_USW_MODE },
    [ILAHRS_ANSWER_FIRMWARE_VERSION] = { .payload = ILAHRS_PAYLOAD_FIRMWARE_VERSION, .usw_mode = NO_USW_MODE },
    [ILAHRS_ANSWER_BIT_RESULT] = { .payload = ILAHRS_PAYLOAD_BIT_RESULT, .usw_mode = NO_USW_MODE },
    [ILAHRS_ANSWER_CALIBRATION_STATUS] = { .payload = ILAHRS_PAYLOAD_CALIBRATION_STATUS, .usw_mode = NO_USW_MODE },
    [ILAHRS_ANSWER_INITIAL_ALIGNMENT] = { .payload = ILAHRS_PAYLOAD_INITIAL_ALIGNMENT, .usw_mode = NO_USW_MODE },
    [ILAHRS_ANSWER_OUTPUT] = { .payload = ILAHRS_PAYLOAD_NONE, .usw_mode = NO_USW_MODE },
    [ILAHRS_ANSWER_OUTPUT_SLEEP] = { .payload = ILAHRS_PAYLOAD_NONE, .usw_mode = ILAHRS_USW_MODE_SLEEP },
    [ILAHRS_ANSWER_CALIBRATION_RESULT] = { .payload = ILAHRS_PAYLOAD_CALIBRATION_RESULT, .usw_mode = NO_USW_MODE },
    [ILAHRS_ANSWER_CALIBRATION_RUN_RESULT] = { .payload = ILAHRS_PAYLOAD_CALIBRATION_RUN_RESULT,
                                               .usw_mode = NO_USW_MODE },
};

/* Answer sequences, one after the other: sequence k is ilahrs_sends[ilahrs_send_start[k] ..
 * ilahrs_send_start[k + 1]). */
static const uint8_t ilahrs_sends[10] = {
    ILAHRS_ANSWER_ACK,                    /* 0 */
                                          /* 1 */
    ILAHRS_ANSWER_AHRS_PARAMETERS_READ,   /* 2 */
    ILAHRS_ANSWER_FIRMWARE_VERSION,       /* 3 */
    ILAHRS_ANSWER_BIT_RESULT,             /* 4 */
    ILAHRS_ANSWER_CALIBRATION_STATUS,     /* 5 */
    ILAHRS_ANSWER_INITIAL_ALIGNMENT,      /* 6 */
    ILAHRS_ANSWER_OUTPUT,                 /* 7 */
    ILAHRS_ANSWER_OUTPUT_SLEEP,           /* 8 */
    ILAHRS_ANSWER_CALIBRATION_RESULT,     /* 9 */
    ILAHRS_ANSWER_CALIBRATION_RUN_RESULT, /* 10 */
};
static const uint8_t ilahrs_send_start[12] = { 0, 1, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 };

/* The distinct outcomes of the table: OUTCOME(next state, answer sequence). */
#define SEQUENCE_BITS 4u
static const uint8_t ilahrs_outcomes[27] = {
    OUTCOME(ILAHRS_STATE_ALIGNING_CONTINUOUS, 0),             /* cell 1 */
    OUTCOME(ILAHRS_STATE_ALIGNING_ON_REQUEST, 0),             /* cell 2 */
    OUTCOME(ILAHRS_STATE_AWAITING_PARAMETERS, 1),             /* cell 3 */
    OUTCOME(ILAHRS_STATE_IDLE, 2),                            /* cell 4 */
    OUTCOME(ILAHRS_STATE_IDLE, 3),                            /* cell 5 */
    OUTCOME(ILAHRS_STATE_IDLE, 4),                            /* cell 6 */
    OUTCOME(ILAHRS_STATE_ON_REQUEST, 4),                      /* cell 7 */
    OUTCOME(ILAHRS_STATE_SLEEP, 1),                           /* cell 8 */
    OUTCOME(ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS, 1), /* cell 9 */
    OUTCOME(ILAHRS_STATE_RUNS_AWAITING_PARAMETERS, 1),        /* cell 10 */
    OUTCOME(ILAHRS_STATE_IDLE, 0),                            /* cell 11 */
    OUTCOME(ILAHRS_STATE_IDLE, 5),                            /* cell 12 */
    OUTCOME(ILAHRS_STATE_IDLE, 1),                            /* cell 13 */
    OUTCOME(ILAHRS_STATE_RUNS_READY, 1),                      /* cell 14 */
    OUTCOME(ILAHRS_STATE_CONTINUOUS, 6),                      /* cell 15 */
    OUTCOME(ILAHRS_STATE_ON_REQUEST, 6),                      /* cell 16 */
    OUTCOME(ILAHRS_STATE_CONTINUOUS, 7),                      /* cell 17 */
    OUTCOME(ILAHRS_STATE_ON_REQUEST, 7),                      /* cell 18 */
    OUTCOME(ILAHRS_STATE_SLEEP, 8),                           /* cell 19 */
    OUTCOME(ILAHRS_STATE_CALIBRATION_ALIGNING, 0),            /* cell 20 */
    OUTCOME(ILAHRS_STATE_CALIBRATION_ACCUMULATING, 6),        /* cell 21 */
    OUTCOME(ILAHRS_STATE_CALIBRATION_DECIDING, 9),            /* cell 22 */
    OUTCOME(ILAHRS_STATE_RUNS_READY, 0),                      /* cell 23 */
    OUTCOME(ILAHRS_STATE_RUN_AWAITING_PARAMETERS, 1),         /* cell 24 */
    OUTCOME(ILAHRS_STATE_RUN_ALIGNING, 0),                    /* cell 25 */
    OUTCOME(ILAHRS_STATE_RUN_ACCUMULATING, 6),                /* cell 26 */
    OUTCOME(ILAHRS_STATE_RUNS_READY, 10),                     /* cell 27 */
};

/* Each state's default cell, and the cells that differ from it: CELL(state, event, outcome + 1),
 * 0 for an ignored event (E33). Events are the commands, then parameter_block, other_message, unknown, block_timeout,
 * alignment_done, accumulation_done, output_due. */
#define CELL_BITS 5u
#define CELL_COUNT 65u
static const uint8_t ilahrs_state_cells[ILAHRS_STATE_COUNT] = {
    [ILAHRS_STATE_IDLE] = 0,
    [ILAHRS_STATE_AWAITING_PARAMETERS] = 13,
    [ILAHRS_STATE_ALIGNING_CONTINUOUS] = 0,
    [ILAHRS_STATE_CONTINUOUS] = 0,
    [ILAHRS_STATE_ALIGNING_ON_REQUEST] = 0,
    [ILAHRS_STATE_ON_REQUEST] = 0,
    [ILAHRS_STATE_SLEEP] = 0,
    [ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS] = 13,
    [ILAHRS_STATE_CALIBRATION_ALIGNING] = 0,
    [ILAHRS_STATE_CALIBRATION_ACCUMULATING] = 0,
    [ILAHRS_STATE_CALIBRATION_DECIDING] = 0,
    [ILAHRS_STATE_RUNS_AWAITING_PARAMETERS] = 13,
    [ILAHRS_STATE_RUNS_READY] = 0,
    [ILAHRS_STATE_RUN_AWAITING_PARAMETERS] = 14,
    [ILAHRS_STATE_RUN_ALIGNING] = 0,
    [ILAHRS_STATE_RUN_ACCUMULATING] = 0,
};

static const uint16_t ilahrs_cells[65] = {
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_AHRS_CONT1, 1),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_AHRS_CONT2, 1),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_AHRS_CONT3, 1),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_AHRS_REQ1, 2),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_AHRS_REQ2, 2),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_AHRS_REQ3, 2),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_NMEA_CONT, 1),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_NMEA_REQ, 2),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_STOP, 13),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_LOAD_AHRS_PAR, 3),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_READ_AHRS_PAR, 4),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_LOW_POWER_ON, 8),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_GET_VER_FIRMWARE, 5),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_GET_BIT, 6),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_START_2D_CLB, 9),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_START_2D2T_CLB, 10),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_START_3D_CLB, 9),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_CLEAR_CLB, 11),
    CELL(ILAHRS_STATE_IDLE, ILAHRS_EVENT_GET_CLB_RES, 12),
    CELL(ILAHRS_STATE_AWAITING_PARAMETERS, ILAHRS_EVENT_PARAMETER_BLOCK, 11),
    CELL(ILAHRS_STATE_AWAITING_PARAMETERS, ILAHRS_EVENT_ALIGNMENT_DONE, 0),
    CELL(ILAHRS_STATE_AWAITING_PARAMETERS, ILAHRS_EVENT_ACCUMULATION_DONE, 0),
    CELL(ILAHRS_STATE_AWAITING_PARAMETERS, ILAHRS_EVENT_OUTPUT_DUE, 0),
    CELL(ILAHRS_STATE_ALIGNING_CONTINUOUS, ILAHRS_EVENT_STOP, 13),
    CELL(ILAHRS_STATE_ALIGNING_CONTINUOUS, ILAHRS_EVENT_ALIGNMENT_DONE, 15),
    CELL(ILAHRS_STATE_CONTINUOUS, ILAHRS_EVENT_STOP, 13),
    CELL(ILAHRS_STATE_CONTINUOUS, ILAHRS_EVENT_LOW_POWER_ON, 19),
    CELL(ILAHRS_STATE_CONTINUOUS, ILAHRS_EVENT_OUTPUT_DUE, 17),
    CELL(ILAHRS_STATE_ALIGNING_ON_REQUEST, ILAHRS_EVENT_STOP, 13),
    CELL(ILAHRS_STATE_ALIGNING_ON_REQUEST, ILAHRS_EVENT_ALIGNMENT_DONE, 16),
    CELL(ILAHRS_STATE_ON_REQUEST, ILAHRS_EVENT_GET_DATA_REQ, 18),
    CELL(ILAHRS_STATE_ON_REQUEST, ILAHRS_EVENT_STOP, 13),
    CELL(ILAHRS_STATE_ON_REQUEST, ILAHRS_EVENT_LOW_POWER_ON, 8),
    CELL(ILAHRS_STATE_ON_REQUEST, ILAHRS_EVENT_GET_BIT, 7),
    CELL(ILAHRS_STATE_SLEEP, ILAHRS_EVENT_LOW_POWER_OFF, 13),
    CELL(ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS, ILAHRS_EVENT_EXIT_CLB, 11),
    CELL(ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS, ILAHRS_EVENT_PARAMETER_BLOCK, 20),
    CELL(ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS, ILAHRS_EVENT_ALIGNMENT_DONE, 0),
    CELL(ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS, ILAHRS_EVENT_ACCUMULATION_DONE, 0),
    CELL(ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS, ILAHRS_EVENT_OUTPUT_DUE, 0),
    CELL(ILAHRS_STATE_CALIBRATION_ALIGNING, ILAHRS_EVENT_EXIT_CLB, 11),
    CELL(ILAHRS_STATE_CALIBRATION_ALIGNING, ILAHRS_EVENT_ALIGNMENT_DONE, 21),
    CELL(ILAHRS_STATE_CALIBRATION_ACCUMULATING, ILAHRS_EVENT_STOP_CLB_RUN, 22),
    CELL(ILAHRS_STATE_CALIBRATION_ACCUMULATING, ILAHRS_EVENT_EXIT_CLB, 11),
    CELL(ILAHRS_STATE_CALIBRATION_ACCUMULATING, ILAHRS_EVENT_ACCUMULATION_DONE, 22),
    CELL(ILAHRS_STATE_CALIBRATION_DECIDING, ILAHRS_EVENT_ACCEPT_CLB, 11),
    CELL(ILAHRS_STATE_CALIBRATION_DECIDING, ILAHRS_EVENT_EXIT_CLB, 11),
    CELL(ILAHRS_STATE_RUNS_AWAITING_PARAMETERS, ILAHRS_EVENT_EXIT_CLB, 11),
    CELL(ILAHRS_STATE_RUNS_AWAITING_PARAMETERS, ILAHRS_EVENT_PARAMETER_BLOCK, 23),
    CELL(ILAHRS_STATE_RUNS_AWAITING_PARAMETERS, ILAHRS_EVENT_ALIGNMENT_DONE, 0),
    CELL(ILAHRS_STATE_RUNS_AWAITING_PARAMETERS, ILAHRS_EVENT_ACCUMULATION_DONE, 0),
    CELL(ILAHRS_STATE_RUNS_AWAITING_PARAMETERS, ILAHRS_EVENT_OUTPUT_DUE, 0),
    CELL(ILAHRS_STATE_RUNS_READY, ILAHRS_EVENT_START_CLB_RUN, 24),
    CELL(ILAHRS_STATE_RUNS_READY, ILAHRS_EVENT_FINISH_CLB, 22),
    CELL(ILAHRS_STATE_RUNS_READY, ILAHRS_EVENT_EXIT_CLB, 11),
    CELL(ILAHRS_STATE_RUN_AWAITING_PARAMETERS, ILAHRS_EVENT_EXIT_CLB, 11),
    CELL(ILAHRS_STATE_RUN_AWAITING_PARAMETERS, ILAHRS_EVENT_PARAMETER_BLOCK, 25),
    CELL(ILAHRS_STATE_RUN_AWAITING_PARAMETERS, ILAHRS_EVENT_ALIGNMENT_DONE, 0),
    CELL(ILAHRS_STATE_RUN_AWAITING_PARAMETERS, ILAHRS_EVENT_ACCUMULATION_DONE, 0),
    CELL(ILAHRS_STATE_RUN_AWAITING_PARAMETERS, ILAHRS_EVENT_OUTPUT_DUE, 0),
    CELL(ILAHRS_STATE_RUN_ALIGNING, ILAHRS_EVENT_EXIT_CLB, 11),
    CELL(ILAHRS_STATE_RUN_ALIGNING, ILAHRS_EVENT_ALIGNMENT_DONE, 26),
    CELL(ILAHRS_STATE_RUN_ACCUMULATING, ILAHRS_EVENT_STOP_CLB_RUN, 27),
    CELL(ILAHRS_STATE_RUN_ACCUMULATING, ILAHRS_EVENT_EXIT_CLB, 11),
    CELL(ILAHRS_STATE_RUN_ACCUMULATING, ILAHRS_EVENT_ACCUMULATION_DONE, 27),
};

/* Rows that apply only to firmware before a version, and there take precedence. */
#define LEGACY_COUNT 1
static const ilahrs_firmware_t ilahrs_legacy_versions[1] = {
    { .parts = { 4, 9, 9, 0 }, .count = 4 }, /* 4.9.9.0 */
};

static const struct {
    uint8_t state;
    uint8_t event;
    uint8_t outcome;
    uint8_t version;
} ilahrs_legacy[1] = {
    { .state = ILAHRS_STATE_RUNS_READY, .event = ILAHRS_EVENT_STOP_CLB_RUN, .outcome = 21, .version = 0 }, /* E29 */
};

#endif /* ILAHRS_INTERNAL_H */
