/* Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
 * Do not edit: change the spec or the generator and run `make generate`.
 * SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * The spec's tables, then the library's fixed code, which walks them (generator/targets/c/runtime/).
 */
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

/* ---- Date ------------------------------------------------------------------------------ */

/* Month 1..12 of a year (Gregorian). Bit m of 0x15AA is set for the months of 31 days; a year
 * divisible by 100 is leap when also by 16 (then by 400). */
static int days_in_month(int year, int month)
{
    if (month == 2) {
        return (year & 3) == 0 && (year % 100 != 0 || (year & 15) == 0) ? 29 : 28;
    }
    return 30 + (int)((0x15AAu >> month) & 1u);
}

/* The float32 nearest n / DATE_SCALE (ties to even), in integers: the quotient's bits one at a
 * time until it has 24, then rounded by the remainder. A date scaled by DATE_SCALE (date_scaled())
 * is an integer below 2^24: exact in a float32, and decoding compares integers. */
static float date_float(uint32_t n)
{
    uint32_t m = n / DATE_SCALE;
    uint32_t r = n % DATE_SCALE;
    uint32_t exponent = 150u;
    uint32_t bits;
    float value;
    while (m < 0x800000u) {
        r <<= 1;
        m <<= 1;
        if (r >= DATE_SCALE) {
            r -= DATE_SCALE;
            m |= 1u;
        }
        exponent--;
    }
    if (2u * r > DATE_SCALE || (2u * r == DATE_SCALE && (m & 1u) != 0)) {
        m++; /* 2^24 carries into the exponent, as it should */
    }
    bits = (exponent << 23) + m - 0x800000u;
    memcpy(&value, &bits, sizeof value);
    return value;
}

bool ilahrs_date_encode(int year, int month, int day, float *value, ilahrs_error_t *err)
{
    if (year < ILAHRS_DATE_YEAR_MIN || year > ILAHRS_DATE_YEAR_MAX || month < 1 || month > 12 || day < 1
        || day > days_in_month(year, month)) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NAME_DATE);
    }
    /* The generator checked that this equals the double-precision formula rounded to float32. */
    *value = date_float((uint32_t)date_scaled(year, month, day));
    return true;
}

/* Date floats a decoder accepts, as float keys (DATE_DECODE_MIN_KEY..DATE_DECODE_MAX_KEY): from
 * the year ILAHRS_DATE_YEAR_MIN to below ILAHRS_DATE_YEAR_MAX + 2, the floats whose candidate years
 * (below) hold a valid date. DATE_EXPONENT is the biased exponent of the smallest. */
#define DATE_FRACTION_BITS (150u - DATE_EXPONENT)
#define DATE_FRACTION_MASK ((1u << DATE_FRACTION_BITS) - 1u)

bool ilahrs_date_decode(float value, ilahrs_date_t *date, ilahrs_error_t *err)
{
    uint32_t bits;
    uint32_t fixed;
    int32_t target;
    uint32_t best = 0xFFFFFFFFu;
    int base;
    int year;
    memcpy(&bits, &value, sizeof bits);
    if (float_key(bits) < DATE_DECODE_MIN_KEY || float_key(bits) > DATE_DECODE_MAX_KEY) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NAME_DATE);
    }
    /* value = mantissa * 2^(exponent - 150): in units of 2^-DATE_FRACTION_BITS it is the integer
     * `fixed`. Distances are measured from the year `base` in units of 1 / (DATE_SCALE *
     * 2^DATE_FRACTION_BITS), where value and every date are integers (the generator checked that
     * they fit an int32). */
    fixed = ((bits & 0x7FFFFFu) | 0x800000u) << (((bits >> 23) & 0xFFu) - DATE_EXPONENT);
    base = (int)(fixed >> DATE_FRACTION_BITS); /* floor(value) */
    target = (int32_t)(fixed & DATE_FRACTION_MASK) * (int32_t)DATE_SCALE;
    for (year = base - 1; year <= base; year++) {
        int month;
        if (year < ILAHRS_DATE_YEAR_MIN || year > ILAHRS_DATE_YEAR_MAX) {
            continue;
        }
        for (month = 1; month <= 12; month++) {
            int day;
            for (day = 1; day <= days_in_month(year, month); day++) {
                int32_t at =
                    (date_scaled(year, month, day) - base * (int32_t)DATE_SCALE) * (int32_t)(DATE_FRACTION_MASK + 1u);
                uint32_t distance = at > target ? (uint32_t)(at - target) : (uint32_t)(target - at);
                if (distance < best) {
                    best = distance;
                    date->year = (int16_t)year;
                    date->month = (uint8_t)month;
                    date->day = (uint8_t)day;
                }
            }
        }
    }
    return true;
}

/* ---- Engineering values as doubles ------------------------------------------------------ */

/* These take doubles but compute on their IEEE 754 binary64 bits with integers only (no
 * floating-point code linked), and give for every double the answers of the double-precision
 * expressions they replace, quoted below. A double is a sign, an 11-bit exponent e and a 52-bit
 * fraction: (2^52 + fraction) * 2^(e - 1075), or fraction * 2^-1074 if e is 0. */

#define DOUBLE_SIGN ((uint64_t)1 << 63)
#define DOUBLE_ONE ((uint64_t)1 << 52) /* the implicit leading bit */

static uint64_t double_bits(double value)
{
    uint64_t bits;
    memcpy(&bits, &value, sizeof bits);
    return bits;
}

/* float_key() for a double: the magnitude bits, negated if the sign is set. Doubles order like
 * their keys, -0.0 and 0.0 are both 0, and NaNs lie beyond the infinities, outside every range. */
static int64_t double_key(uint64_t bits)
{
    int64_t magnitude = (int64_t)(bits & ~DOUBLE_SIGN);
    return (bits & DOUBLE_SIGN) != 0 ? -magnitude : magnitude;
}

/* double_key() of (double)n, exact for |n| < 2^53 (every integer bound and C type limit here). */
static int64_t int_key(int64_t n)
{
    uint64_t m = n < 0 ? 0u - (uint64_t)n : (uint64_t)n;
    uint64_t exponent = 1074; /* 2^52's (1075), less the 1 that m's leading bit adds below */
    int64_t magnitude;
    if (m == 0) {
        return 0;
    }
    while (m < DOUBLE_ONE) {
        m <<= 1;
        exponent--;
    }
    magnitude = (int64_t)((exponent << 52) + m);
    return n < 0 ? -magnitude : magnitude;
}

/* value >= low && value <= high with the field's bounds (float fields: ilahrs_exact_bounds, the
 * exact bounds as double keys; integer fields: their int bounds or their C type's range, exact as
 * doubles), then the declination rule, as compares of keys. */
bool ilahrs_field_check(const ilahrs_field_info_t *field, double value, ilahrs_error_t *err)
{
    int64_t key = double_key(double_bits(value));
    int64_t low;
    int64_t high;
    bool ok;
    switch (FIELD_KIND(field)) {
    case ILAHRS_KIND_FLOAT:
        low = ilahrs_exact_bounds[FIELD_BOUNDS(field)][0];
        high = ilahrs_exact_bounds[FIELD_BOUNDS(field)][1];
        break;
    case ILAHRS_KIND_UNSIGNED:
    case ILAHRS_KIND_SIGNED: {
        bool is_signed = FIELD_KIND(field) == ILAHRS_KIND_SIGNED;
        uint32_t top = 0xFFFFFFFFu >> (32 - 8 * FIELD_NUMBER_SIZE(field) + is_signed); /* the C type's maximum */
        low = FIELD_BOUNDS(field) != 0 ? ilahrs_int_bounds[FIELD_BOUNDS(field)][0] : is_signed ? -(int64_t)top - 1 : 0;
        high = FIELD_BOUNDS(field) != 0 ? ilahrs_int_bounds[FIELD_BOUNDS(field)][1] : (int64_t)top;
        low = int_key(low);
        high = int_key(high);
        break;
    }
    default:
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, FIELD_OFFSET(field), FIELD_NAME(FIELD_NAME_AT(field)));
    }
    ok = key >= low && key <= high;
#ifdef ILAHRS_DECLINATION_MIN
    if (ok && FIELD_ENCODING(field) == ENCODING_DECLINATION) {
        ok = (key >= DECLINATION_MIN_DKEY && key <= DECLINATION_MAX_DKEY) || key > DECLINATION_COMPUTE_ABOVE_DKEY;
    }
#endif
    return ok || fail(err, ILAHRS_ERR_OUT_OF_RANGE, FIELD_OFFSET(field), FIELD_NAME(FIELD_NAME_AT(field)));
}

/* ---- $PAHR sentences ------------------------------------------------------------------- */

/* The sentence grammar of NMEA 0183 (spec/README.md): "$", the identifier and "," (PAHR_PREFIX),
 * fields separated by ",", then "*", two hex digits, CR LF. */
#define PAHR_START '$'
#define PAHR_SEPARATOR ','
#define PAHR_STAR '*'
#define PAHR_CR '\r'
#define PAHR_LF '\n'
#define PAHR_PREFIX_LENGTH (sizeof PAHR_PREFIX - 1u)
#define PAHR_TAIL 5u                /* "*", two checksum digits, CR, LF */
#define PAHR_HUGE 10000000000000ull /* magnitudes saturate here: above every 32-bit range */

/* Field k's struct member (its offset) and its size: from its row, or, where the rows leave them
 * out (every member the same size, PAHR_MEMBER_SIZE, in the order of the fields; compiled for
 * size), from k. */
#if PAHR_ROW_MEMBERS
#define PAHR_MEMBER(k) ilahrs_pahr_fields[k].member
#define PAHR_SIZE(k) ilahrs_pahr_fields[k].size
#else
#define PAHR_MEMBER(k) ((size_t)(k) * PAHR_MEMBER_SIZE)
#define PAHR_SIZE(k) PAHR_MEMBER_SIZE
#endif

/* 10^decimals of field k. */
static uint32_t pahr_divisor(size_t k)
{
    uint32_t divisor = 1;
    unsigned i;
    for (i = 0; i < ilahrs_pahr_fields[k].decimals; i++) {
        divisor *= 10u;
    }
    return divisor;
}

#if ILAHRS_NAMES
const char *ilahrs_pahr_field_name(size_t index)
{
    return index < ILAHRS_PAHR_FIELD_COUNT ? SENTENCE_NAME(ilahrs_pahr_fields[index].name) : NULL;
}
#endif

bool ilahrs_pahr_field_range(size_t index, int32_t *min, int32_t *max)
{
    if (index >= ILAHRS_PAHR_FIELD_COUNT) {
        return false;
    }
    *min = ilahrs_pahr_fields[index].min;
    *max = ilahrs_pahr_fields[index].max;
    return true;
}

uint32_t ilahrs_pahr_field_divisor(size_t index)
{
    return index < ILAHRS_PAHR_FIELD_COUNT && !ilahrs_pahr_fields[index].hex ? pahr_divisor(index) : 0;
}

static int32_t pahr_get(const ilahrs_pahr_t *in, size_t k)
{
    uint32_t bits = load_bits((const uint8_t *)in + PAHR_MEMBER(k), PAHR_SIZE(k));
    return ilahrs_pahr_fields[k].min < 0 ? sign_extend(bits, PAHR_SIZE(k)) : (int32_t)bits;
}

int32_t ilahrs_pahr_field_get(const ilahrs_pahr_t *sentence, size_t index)
{
    return index < ILAHRS_PAHR_FIELD_COUNT ? pahr_get(sentence, index) : 0;
}

/* The character classes of the grammar: a hex digit's value (0..15, either case), NOT_DIGIT for
 * any other character. Decimal fields take the values below 10. */
#define NOT_DIGIT 0x100u

static unsigned digit_value(uint8_t c)
{
    unsigned letter = (unsigned)(c | 0x20u) - 'a';
    if ((unsigned)(c - '0') <= 9u) {
        return (unsigned)(c - '0');
    }
    return letter <= 5u ? letter + 10u : NOT_DIGIT;
}

/*
 * The field at *at, described by f, in one pass: its grammar, its value scaled to an integer, its
 * range; the characters it takes are XORed into *sum. Returns ILAHRS_OK with the value stored in
 * *out, ILAHRS_ERR_MALFORMED (also when the number is not followed by a separator or by the star,
 * star being the sentence's "*") or ILAHRS_ERR_OUT_OF_RANGE, and leaves *at where the number ends.
 * Magnitudes stop growing at SATURATED, above every range: m * 16 + 15 cannot overflow from below
 * it, so any number of digits reads without a wider type or a division.
 */
#if FAST
/* The digits of a number in base 10 or 16 from q, with at most one point among them: its
 * magnitude in *m (stopping at SATURATED), the point in *point (NULL without one), the characters
 * XORed into *sum. Returns where the number ends: at the star at the latest, which is no digit. */
static inline const uint8_t *pahr_digits(const uint8_t *q, const uint8_t *star, unsigned base, uint32_t *m,
                                         const uint8_t **point, unsigned *sum)
{
    unsigned x = *sum;
    uint32_t v = 0;
    for (; q < star; q++) {
        unsigned c = *q;
        unsigned d = c - '0';
        if (d > 9u) {
            d = (c | 0x20u) - ('a' - 10u); /* a hex letter, either case: 10..15 */
            if (d < 10u || d >= base) {
                if (c != '.' || *point != NULL) {
                    break;
                }
                *point = q; /* in a hex field, a point is followed by a fraction it cannot have */
                x ^= c;
                continue;
            }
        }
        x ^= c;
        if (v < SATURATED) {
            v = v * base + d;
        }
    }
    *m = v;
    *sum = x;
    return q;
}

static ilahrs_error_kind_t pahr_field(const uint8_t **at, const uint8_t *star, const pahr_field_t *f,
                                      ilahrs_pahr_t *out, unsigned *sum)
{
    const uint8_t *q = *at;
    const uint8_t *digits;
    const uint8_t *point = NULL;
    bool negative = !f->hex && *q == '-';
    uint32_t m;
    size_t whole;
    size_t fraction = 0;
    int32_t value;
    *sum ^= negative ? (unsigned)'-' : 0u;
    digits = q + negative;
    /* The base as a constant: a multiplication by 10 or 16 is a shift and an add. */
    q = f->hex ? pahr_digits(digits, star, 16u, &m, &point, sum) : pahr_digits(digits, star, 10u, &m, &point, sum);
    *at = q;
    whole = (size_t)((point != NULL ? point : q) - digits);
    if (point != NULL) {
        fraction = (size_t)(q - point) - 1u;
    }
    if (whole == 0 || (f->hex && whole > f->width) || (point != NULL && (fraction == 0 || fraction > f->decimals))
        || (q != star && *q != PAHR_SEPARATOR)) {
        return ILAHRS_ERR_MALFORMED;
    }
    for (; fraction < f->decimals; fraction++) {
        if (m < SATURATED) {
            m *= 10u;
        }
    }
    value = negative ? -(int32_t)m : (int32_t)m;
    if (value < f->min || value > f->max) {
        return ILAHRS_ERR_OUT_OF_RANGE;
    }
    store_bits((uint8_t *)out + f->member, (uint32_t)value, f->size);
    return ILAHRS_OK;
}
#else
/* (A field's digits leave room for more fraction digits than any field has.) */
typedef char pahr_check_room[PAHR_MAX_DECIMALS < PAHR_PREFIX_LENGTH + PAHR_TAIL ? 1 : -1];
/* Compiled for size, the same checks with the same answers in less code, for field k: pahr_body()
 * has summed the characters already, reads *at only after a good field, and reports any bad one
 * at its start, so a check may answer as soon as it fails. `room` counts the digits the
 * part being read may still take: a hex field's width of whole digits (a decimal field's, as many
 * as a sentence has characters, are not limited: a field holds fewer, and room stays above the
 * fraction digits), then after a point the fraction digits, which leave room of them missing. So
 * a point has been read if room is at most the fraction digits (or, in a hex field, which takes no
 * point, the width is used up: then a point ends the number as a second point does, and either is
 * malformed), and the value lacks the smaller of the two: read as zero digits at the end. */
static ilahrs_error_kind_t pahr_field(const uint8_t **at, const uint8_t *star, size_t k, ilahrs_pahr_t *out)
{
    const pahr_field_t *f = &ilahrs_pahr_fields[k];
    const uint8_t *q = *at;
    const uint8_t *part; /* the first digit of the part being read: whole, then fraction */
    unsigned base = f->hex ? 16u : 10u;
    /* Every read of the field below the star (pahr_body() never starts one past it, but Frama-C's
     * EVA cannot tell: the separators it counted are what stop a field short of the star). */
    bool negative = base == 10u && q < star && *q == '-';
    unsigned room = f->hex ? f->width : ILAHRS_PAHR_MAX_LENGTH;
    uint32_t m = 0;
    int32_t value;
    for (part = q += negative;; q++) {
        unsigned c = q < star ? *q : PAHR_SEPARATOR; /* the star ends the last field as a separator */
        unsigned d = c - '0';
        if (d > 9u) {
            d = (c | 0x20u) - ('a' - 10u); /* a hex letter, either case: 10..15 */
            if (d < 10u || d >= base) {
                if (c != '.' || room <= f->decimals || q == part) {
                    if (c != PAHR_SEPARATOR || q == part) {
                        return ILAHRS_ERR_MALFORMED; /* the number ends at a separator or at the star */
                    }
                    /* The fraction digits missing, read as zeros (without a point, all of them),
                     * the end read again after each. */
                    room = room < f->decimals ? room : f->decimals;
                    if (room == 0) {
                        break;
                    }
                    d = 0;
                    q--;
                } else {
                    part = q + 1; /* in a hex field, a point is followed by a fraction it cannot have */
                    room = f->decimals;
                    continue;
                }
            }
        }
        if (room-- == 0) {
            return ILAHRS_ERR_MALFORMED; /* a digit too many */
        }
        if (m < SATURATED) {
            m = m * base + d;
        }
    }
    *at = q;
    value = negative ? -(int32_t)m : (int32_t)m;
    if (value < f->min || value > f->max) {
        return ILAHRS_ERR_OUT_OF_RANGE;
    }
    store_bits((uint8_t *)out + PAHR_MEMBER(k), (uint32_t)value, PAHR_SIZE(k));
    return ILAHRS_OK;
}
#endif

#if FAST
/* Compiled for speed, a decimal field has a path of its own, with the same answers as pahr_field():
 * the whole digits, then the fraction digits after a point, each in a loop of its own; the missing
 * fraction digits scale the magnitude in one multiplication (10^decimals < 2^11, checked by the
 * generator), and the sign and the range in 64 bits. */
static const uint16_t pahr_scale[4] = { 1u, 10u, 100u, 1000u };

/* The XOR of the characters in [q, end), 8 at a time: the field paths below leave it to this. */
static unsigned pahr_xor(const uint8_t *q, const uint8_t *end)
{
    uint64_t x = 0;
    uint64_t w;
    size_t n = (size_t)(end - q);
    if (n < 8u) {
        for (; q < end; q++) {
            x ^= *q;
        }
        return (unsigned)x;
    }
    for (; n > 8u; n -= 8u, q += 8) {
        memcpy(&w, q, 8);
        x ^= w;
    }
    {
        /* The last 8 characters, of which the first 8 - n are counted already. */
        const uint16_t one = 1;
        uint8_t little; /* the host's byte order: 1 if little-endian */
        unsigned drop = 8u * (8u - (unsigned)n);
        memcpy(&little, &one, 1);
        memcpy(&w, end - 8, 8);
        x ^= little ? w >> drop : w << drop;
    }
    x ^= x >> 32;
    x ^= x >> 16;
    x ^= x >> 8;
    return (unsigned)x & 0xFFu;
}

static ilahrs_error_kind_t pahr_decimal(const uint8_t **at, const uint8_t *star, const pahr_field_t *f,
                                        ilahrs_pahr_t *out, unsigned *sum)
{
    const uint8_t *q = *at;
    const uint8_t *digits;
    unsigned negative = *q == '-';
    unsigned scale = f->decimals;
    uint32_t v = 0;
    unsigned d;
    bool bad;
    int64_t value;
    q += negative;
    digits = q;
    /* Each loop stops at the star, which is no digit, and says so in its condition too: every read
     * is then below the star or at it, which Frama-C's EVA can tell (prove/README.md). */
    for (; q < star && (d = (unsigned)*q - '0') <= 9u; q++) {
        v = v * 10u + d;
    }
    if (q - digits > 6) {
        return pahr_field(at, star, f, out, sum); /* v could wrap: the long way, which saturates */
    }
    bad = q == digits;
    if (*q == '.') {
        const uint8_t *point = q++;
        unsigned i;
        /* At most the field's fraction digits (a loop the same length every time); a digit after
         * them is one too many. */
        for (i = 0; i < scale && q < star && (d = (unsigned)*q - '0') <= 9u; i++, q++) {
            v = v * 10u + d;
        }
        bad |= q == point + 1 || (unsigned)*q - '0' <= 9u;
        scale -= i;
    }
    *at = q;
    if (bad || (q != star && *q != PAHR_SEPARATOR)) {
        return ILAHRS_ERR_MALFORMED;
    }
    value = (int64_t)((uint64_t)v * pahr_scale[scale]); /* below 10^6 * 10^3 */
    value = negative ? -value : value;
    if (value < f->min || value > f->max) {
        return ILAHRS_ERR_OUT_OF_RANGE;
    }
    store_bits((uint8_t *)out + f->member, (uint32_t)value, f->size);
    return ILAHRS_OK;
}

/* And a hex field: 1 to 8 digits, no sign and no point (pahr_field() decides the rest). */
static ilahrs_error_kind_t pahr_hex(const uint8_t **at, const uint8_t *star, const pahr_field_t *f, ilahrs_pahr_t *out,
                                    unsigned *sum)
{
    const uint8_t *q = *at;
    uint32_t v = 0;
    size_t whole;
    for (; q < star; q++) {
        unsigned c = *q;
        unsigned d = c - '0';
        if (d > 9u) {
            d = (c | 0x20u) - ('a' - 10u); /* a hex letter, either case: 10..15 */
            if (d - 10u > 5u) {
                break;
            }
        }
        v = v * 16u + d;
    }
    whole = (size_t)(q - *at);
    if (*q == '.' || whole > 8u) {
        return pahr_field(at, star, f, out, sum);
    }
    *at = q;
    if (whole == 0 || whole > f->width || (q != star && *q != PAHR_SEPARATOR)) {
        return ILAHRS_ERR_MALFORMED;
    }
    if ((int64_t)v < f->min || (int64_t)v > f->max) {
        return ILAHRS_ERR_OUT_OF_RANGE;
    }
    store_bits((uint8_t *)out + f->member, v, f->size);
    return ILAHRS_OK;
}
#endif

/* pahr_body()'s answer to an error, in one word, which the stream decoder only compares with 0
 * (ILAHRS_OK): its kind, and where it lies: the index of the field at fault (the error is at the
 * field's first character, after as many separators as fields precede it), or for an error outside
 * the fields, at the prefix's end (the field count), at the star, or at the checksum's first digit.
 * ilahrs_pahr_parse() turns that into the offset. */
#define PAHR_ERROR(kind, where) ((uint32_t)(kind) | (uint32_t)(where) << 4)
#define PAHR_AT_PREFIX ILAHRS_PAHR_FIELD_COUNT
#define PAHR_AT_STAR (ILAHRS_PAHR_FIELD_COUNT + 1u)
#define PAHR_AT_CHECKSUM (ILAHRS_PAHR_FIELD_COUNT + 2u)
#define PAHR_ERROR_KIND(answer) ((ilahrs_error_kind_t)((answer) & 0xFu))
#define PAHR_ERROR_WHERE(answer) ((size_t)((answer) >> 4))
/* (The kinds it answers fit in 4 bits: the answers before the fields fit in one byte.) */
typedef char
    pahr_check_kinds[(ILAHRS_ERR_MALFORMED | ILAHRS_ERR_OUT_OF_RANGE | ILAHRS_ERR_BAD_CHECKSUM) <= 0xF ? 1 : -1];

/*
 * The sentence scanner, for ilahrs_pahr_parse() and the stream decoder alike: everything after the
 * CR LF search. `end` is the sentence length, LF its last character (the stream decoder leaves the
 * CR before it to this, with the star), and p[0..PAHR_PREFIX_LENGTH) the prefix. Returns ILAHRS_OK
 * (0) or the first error in the order of spec/README.md as PAHR_ERROR(kind, field index or
 * PAHR_AT_*).
 */
static uint32_t pahr_body(const uint8_t *p, size_t end, ilahrs_pahr_t *out)
{
    const uint8_t *star = p + end - PAHR_TAIL; /* end > PAHR_PREFIX_LENGTH: an LF follows the prefix */
    const uint8_t *q = p + PAHR_PREFIX_LENGTH;
    size_t k = 0;
#if FAST
    size_t error_field = 0;
#endif
    ilahrs_error_kind_t field_error = ILAHRS_OK;
    unsigned checksum;
    unsigned sum = 0;
    if (star < q || *star != PAHR_STAR || star[PAHR_TAIL - 2u] != PAHR_CR) {
        return PAHR_ERROR(ILAHRS_ERR_MALFORMED, PAHR_AT_STAR);
    }
    checksum = 0;
    for (k = 1; k <= 2u; k++) {
        unsigned d = digit_value(star[k]);
        OPAQUE(k); /* a loop, not two copies */
        if (d > 0xFu) {
            return PAHR_ERROR(ILAHRS_ERR_MALFORMED, PAHR_AT_CHECKSUM);
        }
        checksum = checksum << 4 | d;
    }
    for (k = 1; k < PAHR_PREFIX_LENGTH; k++) {
        sum ^= (uint8_t)PAHR_PREFIX[k]; /* p[k], which the callers checked */
    }
#if FAST
    /* Fields, counted; the first bad one is remembered and reported after the checksum. */
    k = 0;
    /* Compiled for speed, the fields go by while they are good, each ending at a separator or at
     * the star; the loop below takes over from the first bad one or from a field too many. */
#if defined(__GNUC__)
#pragma GCC unroll 64 /* each field's row then folds into its code */
#endif
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        const pahr_field_t *f = &ilahrs_pahr_fields[k];
        field_error = f->hex ? pahr_hex(&q, star, f, out, &sum) : pahr_decimal(&q, star, f, out, &sum);
        if (field_error != ILAHRS_OK) {
            error_field = k;
            break;
        }
        if (q >= star) {
            goto counted;
        }
        q++; /* the separator */
    }
    for (;; k++) {
        if (k < ILAHRS_PAHR_FIELD_COUNT && field_error == ILAHRS_OK) {
            error_field = k;
            field_error = pahr_field(&q, star, &ilahrs_pahr_fields[k], out, &sum);
        }
        for (; q < star && *q != PAHR_SEPARATOR; q++) {
        }
        if (q >= star) {
            break;
        }
        q++; /* the separator */
    }
counted:
    sum = pahr_xor(p + 1, star); /* the field paths leave it out */
    if (sum != checksum) {
        return PAHR_ERROR(ILAHRS_ERR_BAD_CHECKSUM, PAHR_AT_CHECKSUM);
    }
    if (k + 1 != ILAHRS_PAHR_FIELD_COUNT) {
        return PAHR_ERROR(ILAHRS_ERR_MALFORMED, PAHR_AT_PREFIX);
    }
    return field_error == ILAHRS_OK ? ILAHRS_OK : PAHR_ERROR(field_error, error_field);
#else
    /* Compiled for size, the checksum and the field count first, in one pass over the characters
     * (the separators: the fields and their count), then the fields up to the first bad one. */
    k = 0;
    for (; q < star; q++) {
        sum ^= *q;
        k += *q == PAHR_SEPARATOR;
    }
    if (sum != checksum) {
        return PAHR_ERROR(ILAHRS_ERR_BAD_CHECKSUM, PAHR_AT_CHECKSUM);
    }
    if (k + 1 != ILAHRS_PAHR_FIELD_COUNT) {
        return PAHR_ERROR(ILAHRS_ERR_MALFORMED, PAHR_AT_PREFIX);
    }
    /* Each field but the last ends at a separator (as many as fields follow it), or is bad. */
    q = p + PAHR_PREFIX_LENGTH;
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        field_error = pahr_field(&q, star, k, out);
        if (field_error != ILAHRS_OK) {
            return PAHR_ERROR(field_error, k);
        }
        q++; /* the separator, or past the star after the last field */
    }
    return ILAHRS_OK;
#endif
}

bool ilahrs_pahr_parse(const char *text, size_t len, ilahrs_pahr_t *out, ilahrs_error_t *err)
{
    const uint8_t *p = (const uint8_t *)text;
    size_t i;
    size_t end;
    size_t where;
    size_t at;
    uint32_t answer;
    /* "$" (a wrong one at 0), then the identifier and "," (a wrong one at 1), as far as they go. */
    for (i = 0; i < PAHR_PREFIX_LENGTH && i < len; i++) {
        if (p[i] != (uint8_t)PAHR_PREFIX[i]) {
            return fail(err, ILAHRS_ERR_BAD_HEADER, i != 0, NULL);
        }
    }
    if (len < PAHR_PREFIX_LENGTH) {
        return fail(err, ILAHRS_ERR_TRUNCATED, len, NULL);
    }
    /* The first CR LF. */
    for (i = PAHR_PREFIX_LENGTH; i + 1 < len && !(p[i] == PAHR_CR && p[i + 1] == PAHR_LF); i++) {
    }
    if (i + 1 >= len) {
        if (len > ILAHRS_PAHR_MAX_LENGTH) {
            return fail(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_PAHR_MAX_LENGTH, NULL);
        }
        return fail(err, ILAHRS_ERR_TRUNCATED, len, NULL);
    }
    end = i + 2;
    if (end > ILAHRS_PAHR_MAX_LENGTH) {
        return fail(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_PAHR_MAX_LENGTH, NULL);
    }
    if (end < len) {
        return fail(err, ILAHRS_ERR_TRAILING_DATA, end, NULL);
    }
    answer = pahr_body(p, end, out);
    where = PAHR_ERROR_WHERE(answer);
    at = PAHR_PREFIX_LENGTH;
    for (i = where < ILAHRS_PAHR_FIELD_COUNT ? where : 0; i != 0 && at < end; at++) {
        i -= p[at] == PAHR_SEPARATOR; /* the field's first character follows its i-th separator */
    }
    if (where > PAHR_AT_PREFIX) {
        at = end - PAHR_TAIL + (where - PAHR_AT_STAR);
    }
    return answer == ILAHRS_OK
           || fail(err, PAHR_ERROR_KIND(answer), at,
                   where < ILAHRS_PAHR_FIELD_COUNT ? SENTENCE_NAME(ilahrs_pahr_fields[where].name) : NULL);
}

static const char ilahrs_hex_digits[16] = { '0', '1', '2', '3', '4', '5', '6', '7',
                                            '8', '9', 'A', 'B', 'C', 'D', 'E', 'F' };

/*
 * Every field is range-checked before it is written, and the longest sentence of in-range values
 * is at most ILAHRS_PAHR_MAX_LENGTH characters (the generator checks it), so the sentence is built
 * without length checks. Each number is written from its last digit: at least the template width
 * (the sign counting as one character) and all its digits.
 */
size_t ilahrs_pahr_build(const ilahrs_pahr_t *in, char *text, size_t cap, ilahrs_error_t *err)
{
    /* Cleared first, though every byte up to `at` is written before it is read: a static analysis
     * (Frama-C EVA, prove/) joins fields of different lengths and cannot follow which bytes were
     * written; cleared, no byte of the sentence is ever uninitialised. */
    uint8_t buf[ILAHRS_PAHR_MAX_LENGTH] = { 0 };
    size_t at = PAHR_PREFIX_LENGTH;
    size_t k;
    uint8_t sum = 0;
    copy_forward(buf, (const uint8_t *)PAHR_PREFIX, PAHR_PREFIX_LENGTH);
    /* (For Frama-C: each field, and each digit count below, analysed on its own.) */
    /*@ loop unroll ILAHRS_PAHR_FIELD_COUNT; */
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        const pahr_field_t *f = &ilahrs_pahr_fields[k];
        int32_t value = pahr_get(in, k);
        uint32_t m = value < 0 ? 0u - (uint32_t)value : (uint32_t)value;
        unsigned base = f->hex ? 16u : 10u;
        unsigned n = f->width > 1u ? f->width : 1u; /* digits before the point, at least */
        unsigned i;
        uint32_t rest;
        uint8_t *w;
        if (value < f->min || value > f->max) {
            return fail_size(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, SENTENCE_NAME(f->name));
        }
        if (value < 0) {
            buf[at++] = '-';
            n -= n > 1u;
        }
        n += f->decimals;
        /*@ loop unroll 10; */ /* a 32-bit magnitude has at most 10 digits */
        for (i = 1, rest = m / base; rest != 0; rest /= base) {
            i++; /* digits of m */
        }
        n = i > n ? i : n;
        at += n + (f->decimals != 0);
        w = buf + at;
        for (i = 0; i < n; i++) {
            if (i == f->decimals && i != 0) {
                *--w = '.';
            }
            *--w = (uint8_t)ilahrs_hex_digits[m % base];
            m /= base;
        }
        buf[at++] = k + 1 < ILAHRS_PAHR_FIELD_COUNT ? PAHR_SEPARATOR : PAHR_STAR;
    }
    for (k = 1; k + 1 < at; k++) {
        sum ^= buf[k];
    }
    buf[at++] = (uint8_t)ilahrs_hex_digits[sum >> 4];
    buf[at++] = (uint8_t)ilahrs_hex_digits[sum & 0xFu];
    buf[at++] = PAHR_CR;
    buf[at++] = PAHR_LF;
    if (text == NULL || cap < at) {
        return fail_size(err, ILAHRS_ERR_BUFFER_TOO_SMALL, ILAHRS_NO_OFFSET, NULL);
    }
    copy_forward((uint8_t *)text, buf, at);
    if (cap > at) {
        text[at] = '\0';
    }
    return at;
}

/* |value| * divisor rounded half away from zero, as the double code computed it: s = |value| *
 * divisor rounded to a double (to nearest, ties to even), then floor(s + 0.5) with s + 0.5 rounded
 * to a double too. For a hex field (whole, divisor 1): |value| if it is an integer. PAHR_HUGE,
 * beyond every range like the 1e15 the double code saturated at, for s >= 2^52 (infinities and
 * NaNs too) and for a hex field's fraction.
 *
 * Why this is exact: |value| is m * 2^e with m < 2^53, and m * divisor < 2^64 (the generator
 * refuses a divisor from 2^11), so the product is exact; shifting it to 53 bits with a round and a
 * sticky bit rounds it as the double multiplication does (a product below the normal range rounds
 * differently, but stays far below 1/2). Shifting s to the binary point leaves floor(s), and the
 * round bit adds the 0.5. Rounding s + 0.5 to a double changes its floor only for s = 0.5 - 2^-54,
 * whose sum rounds up to 1.0: below 1/2 the sum lies in [1/2, 1), and from 1/2 to 2^52 it is a
 * multiple of s's ulp (at most 1/2), exact unless it just crossed a power of two, where it rounds
 * to a neighbour with the same integer part. */
static uint64_t pahr_magnitude(uint64_t bits, uint32_t divisor, bool whole)
{
    uint64_t m = bits & (DOUBLE_ONE - 1u);
    int exponent = (int)((bits >> 52) & 0x7FFu);
    unsigned round = 0;  /* the last bit shifted out of m */
    unsigned sticky = 0; /* whether any bit before it was 1 */
    if (exponent != 0) {
        m |= DOUBLE_ONE;
    } else {
        exponent = 1; /* subnormal */
    }
    exponent -= 1075;
    m *= divisor;
    while (m >= 2 * DOUBLE_ONE) { /* round to 53 bits, to nearest even */
        sticky |= round;
        round = (unsigned)m & 1u;
        m >>= 1;
        exponent++;
    }
    m += round & (sticky | (unsigned)m) & 1u;
    if (exponent >= 0) {
        return PAHR_HUGE; /* m >= 2^52 here: s >= 2^52 */
    }
    if (m == 2 * DOUBLE_ONE - 1u && exponent == -54) {
        m++; /* 0.49999999999999994 + 0.5 rounds to 1.0, as 0.5 + 0.5 */
    }
    if (exponent < -60) { /* s <= 2^-8: keep only whether it is 0 */
        m = m != 0 ? 1u : 0u;
        exponent = -60;
    }
    round = 0;
    sticky = 0;
    while (exponent < 0) { /* floor(s + 0.5): the integer part, plus 1 if the first bit after it is */
        sticky |= round;
        round = (unsigned)m & 1u;
        m >>= 1;
        exponent++;
    }
    if (whole && (round | sticky) != 0) {
        return PAHR_HUGE; /* a fraction: not an integer */
    }
    return m + round;
}

bool ilahrs_pahr_from_array(const double values[ILAHRS_PAHR_FIELD_COUNT], ilahrs_pahr_t *out, ilahrs_error_t *err)
{
    ilahrs_pahr_t sentence; /* written to *out only if every field is in range */
    size_t k;
    /* A NaN or an infinity in a decimal field is reported before any field out of range. */
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        if (!ilahrs_pahr_fields[k].hex && ((double_bits(values[k]) >> 52) & 0x7FFu) == 0x7FFu) {
            goto out_of_range;
        }
    }
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        uint64_t bits = double_bits(values[k]);
        bool hex = ilahrs_pahr_fields[k].hex != 0;
        uint64_t magnitude = pahr_magnitude(bits, hex ? 1u : pahr_divisor(k), hex);
        int32_t scaled;
        if (magnitude >= SATURATED) {
            goto out_of_range; /* every range lies below SATURATED (checked by the generator) */
        }
        scaled = (bits & DOUBLE_SIGN) != 0 ? -(int32_t)magnitude : (int32_t)magnitude;
        if (scaled < ilahrs_pahr_fields[k].min || scaled > ilahrs_pahr_fields[k].max) {
            goto out_of_range;
        }
        store_bits((uint8_t *)&sentence + PAHR_MEMBER(k), (uint32_t)scaled, PAHR_SIZE(k));
    }
    *out = sentence;
    return true;
out_of_range:
    return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, SENTENCE_NAME(ilahrs_pahr_fields[k].name));
}

#if PAHR_HEX_FIELDS
/* (double)n without floating-point code, for |n| < 2^53: for the hex fields of
 * ilahrs_pahr_from_values(). */
static double int_double(int64_t n)
{
    int64_t key = int_key(n);
    uint64_t bits = key < 0 ? DOUBLE_SIGN | (0u - (uint64_t)key) : (uint64_t)key;
    double value;
    memcpy(&value, &bits, sizeof value);
    return value;
}
#endif

bool ilahrs_pahr_from_values(double roll, double pitch, double heading, double temperature, double vdd, uint16_t usw,
                             ilahrs_pahr_t *out, ilahrs_error_t *err)
{
    double values[ILAHRS_PAHR_FIELD_COUNT];
    values[0] = roll;
    values[1] = pitch;
    values[2] = heading;
    values[3] = temperature;
    values[4] = vdd;
    values[5] = int_double(usw);
    return ilahrs_pahr_from_array(values, out, err);
}

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

/* ---- Device state machine -------------------------------------------------------------- */

#if ILAHRS_NAMES
const char *ilahrs_state_name(ilahrs_state_t state)
{
    return name_at((unsigned)state, NAMES_STATE, ILAHRS_STATE_COUNT);
}

bool ilahrs_state_by_name(const char *name, size_t len, ilahrs_state_t *state)
{
    int i = name_index(name, len, NAMES_STATE, ILAHRS_STATE_COUNT);
    if (i < 0) {
        return false;
    }
    *state = (ilahrs_state_t)i;
    return true;
}

const char *ilahrs_event_name(ilahrs_event_t event)
{
    return name_at((unsigned)event, NAMES_COMMAND, ILAHRS_EVENT_COUNT); /* commands, then the other events */
}

bool ilahrs_event_by_name(const char *name, size_t len, ilahrs_event_t *event)
{
    int i = name_index(name, len, NAMES_COMMAND, ILAHRS_EVENT_COUNT);
    if (i < 0) {
        return false;
    }
    *event = (ilahrs_event_t)i;
    return true;
}

const char *ilahrs_answer_name(ilahrs_answer_t answer)
{
    return name_at((unsigned)answer, NAMES_ANSWER, ILAHRS_ANSWER_COUNT);
}
#endif

ilahrs_mode_t ilahrs_state_mode(ilahrs_state_t state)
{
    return (ilahrs_mode_t)((unsigned)state < ILAHRS_STATE_COUNT ? ilahrs_state_modes[state] : ILAHRS_MODE_COUNT);
}

ilahrs_payload_t ilahrs_state_expects(ilahrs_state_t state)
{
    return (unsigned)state < ILAHRS_STATE_COUNT ? (ilahrs_payload_t)ilahrs_state_blocks[state] : ILAHRS_PAYLOAD_NONE;
}

bool ilahrs_state_timer(ilahrs_state_t state, ilahrs_event_t *event)
{
    if ((unsigned)state >= ILAHRS_STATE_COUNT || ilahrs_state_timers[state] == ILAHRS_EVENT_COUNT) {
        return false;
    }
    *event = (ilahrs_event_t)ilahrs_state_timers[state];
    return true;
}

ilahrs_payload_t ilahrs_answer_payload(ilahrs_answer_t answer)
{
    return (unsigned)answer < ILAHRS_ANSWER_COUNT ? (ilahrs_payload_t)ilahrs_answers[answer].payload
                                                  : ILAHRS_PAYLOAD_NONE;
}

#ifdef ILAHRS_USW_FLAGS_MASK
bool ilahrs_answer_usw_mode(ilahrs_answer_t answer, ilahrs_usw_mode_t *mode)
{
    if ((unsigned)answer >= ILAHRS_ANSWER_COUNT || ilahrs_answers[answer].usw_mode == NO_USW_MODE) {
        return false;
    }
    *mode = (ilahrs_usw_mode_t)ilahrs_answers[answer].usw_mode;
    return true;
}
#endif

ilahrs_event_t ilahrs_event_for_code(ilahrs_state_t state, uint8_t code)
{
    unsigned modes = (unsigned)state < ILAHRS_STATE_COUNT ? ILAHRS_MODE_BIT(ilahrs_state_modes[state]) : 0u;
    unsigned named = 0;
    unsigned only = 0;
    unsigned i;
    for (i = 0; i < ILAHRS_COMMAND_COUNT; i++) {
        unsigned id = ilahrs_commands_by_code[i];
        if (ilahrs_command_codes[id] != code) {
            continue;
        }
        if ((ilahrs_command_modes[id] & modes) != 0) {
            return (ilahrs_event_t)id; /* the name valid in this mode */
        }
        named++;
        only = id;
    }
    if (named == 1) {
        return (ilahrs_event_t)only;
    }
    /* A shared code where no name is valid: the name marked default_for_code (E14). */
    for (i = 0; i < CODE_DEFAULT_COUNT; i++) {
        if (ilahrs_command_codes[ilahrs_code_defaults[i]] == code) {
            return (ilahrs_event_t)ilahrs_code_defaults[i];
        }
    }
    return ILAHRS_EVENT_UNKNOWN;
}

ilahrs_event_t ilahrs_event_for_data(ilahrs_state_t state, size_t payload_size)
{
    ilahrs_payload_t expects = ilahrs_state_expects(state);
    return expects != ILAHRS_PAYLOAD_NONE && payload_size == ilahrs_payloads[expects].size
               ? ILAHRS_EVENT_PARAMETER_BLOCK
               : ILAHRS_EVENT_OTHER_MESSAGE;
}

ilahrs_event_t ilahrs_event_for_frame(ilahrs_state_t state, const ilahrs_frame_t *frame)
{
    if (frame->message_type == ILAHRS_MESSAGE_TYPE_COMMAND && frame->payload_size == 1) {
        return ilahrs_event_for_code(state, frame->payload[0]);
    }
    return ilahrs_event_for_data(state, frame->payload_size);
}

/* Outcome k (a row of ilahrs_outcomes): the next state and the answers of its sequence. */
static bool outcome(unsigned k, ilahrs_step_t *out)
{
    unsigned sends = ilahrs_outcomes[k] & ((1u << SEQUENCE_BITS) - 1u);
    unsigned from = ilahrs_send_start[sends];
    unsigned n = ilahrs_send_start[sends + 1u] - from;
    unsigned i;
    out->to = (ilahrs_state_t)(ilahrs_outcomes[k] >> SEQUENCE_BITS);
    out->send_count = (uint8_t)n;
    for (i = 0; i < n && i < ILAHRS_STEP_SEND_MAX; i++) {
        out->send[i] = (ilahrs_answer_t)ilahrs_sends[from + i];
    }
    return true;
}

/* The row of ilahrs_legacy (rows that apply only to firmware before a version, and there take
 * precedence) for (state, event) that applies to `firmware` (NULL with `any`: every legacy row
 * applies), or -1. */
static int legacy_row(unsigned state, unsigned event, const ilahrs_firmware_t *firmware, bool any)
{
    unsigned i;
    for (i = 0; i < LEGACY_COUNT; i++) {
        if (ilahrs_legacy[i].state != state || ilahrs_legacy[i].event != event) {
            continue;
        }
        if (any) {
            return (int)i;
        }
        if (firmware != NULL
            && ilahrs_firmware_compare(firmware, &ilahrs_legacy_versions[ilahrs_legacy[i].version]) < 0) {
            return (int)i;
        }
    }
    return -1;
}

/* The table: state x event -> outcome + 1, 0 for an ignored event (E33). Each state has a default
 * cell (ilahrs_state_cells), and ilahrs_cells lists the cells that differ from their state's
 * default (CELL()). */
static bool transition(ilahrs_state_t state, ilahrs_event_t event, int legacy, ilahrs_step_t *out)
{
    unsigned cell;
    unsigned key;
    unsigned i;
    out->to = state;
    out->send_count = 0;
    if ((unsigned)state >= ILAHRS_STATE_COUNT || (unsigned)event >= ILAHRS_EVENT_COUNT) {
        return false;
    }
    if (legacy >= 0) {
        return outcome(ilahrs_legacy[legacy].outcome, out);
    }
    cell = ilahrs_state_cells[state];
    key = (unsigned)state * ILAHRS_EVENT_COUNT + (unsigned)event;
    for (i = 0; i < CELL_COUNT; i++) {
        if (ilahrs_cells[i] >> CELL_BITS == key) {
            cell = ilahrs_cells[i] & ((1u << CELL_BITS) - 1u);
            break;
        }
    }
    return cell != 0 && outcome(cell - 1u, out);
}

bool ilahrs_transition(ilahrs_state_t state, ilahrs_event_t event, bool older_firmware, ilahrs_step_t *out)
{
    return transition(state, event, older_firmware ? legacy_row((unsigned)state, (unsigned)event, NULL, true) : -1,
                      out);
}

bool ilahrs_transition_on(ilahrs_state_t state, ilahrs_event_t event, const ilahrs_firmware_t *firmware,
                          ilahrs_step_t *out)
{
    return transition(state, event, legacy_row((unsigned)state, (unsigned)event, firmware, false), out);
}

bool ilahrs_firmware_parse(const char *text, size_t len, ilahrs_firmware_t *firmware, ilahrs_error_t *err)
{
    size_t i = 0;
    zero_bytes(firmware, sizeof *firmware);
    for (;;) {
        size_t start = i;
        uint32_t part = 0;
        while (i < len && text[i] >= '0' && text[i] <= '9') {
            uint32_t digit = (uint32_t)(text[i] - '0');
            if (part > (0xFFFFFFFFu - digit) / 10u) {
                return fail(err, ILAHRS_ERR_MALFORMED, start, NULL);
            }
            part = part * 10u + digit;
            i++;
        }
        if (i == start || (i < len && text[i] != '.') || firmware->count == ILAHRS_FIRMWARE_PARTS_MAX) {
            return fail(err, ILAHRS_ERR_MALFORMED, start, NULL);
        }
        firmware->parts[firmware->count++] = part;
        if (i == len) {
            return true;
        }
        i++; /* the "." */
    }
}

int ilahrs_firmware_compare(const ilahrs_firmware_t *a, const ilahrs_firmware_t *b)
{
    unsigned i;
    for (i = 0; i < a->count && i < b->count && i < ILAHRS_FIRMWARE_PARTS_MAX; i++) {
        if (a->parts[i] != b->parts[i]) {
            return a->parts[i] < b->parts[i] ? -1 : 1;
        }
    }
    return a->count < b->count ? -1 : a->count > b->count ? 1 : 0;
}
