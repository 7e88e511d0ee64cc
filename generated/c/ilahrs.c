/* Generated from spec/ilahrs.yaml, spec hash 38d8054fc9091a0f2db18707b13da0eb865efacbd31314c577a8365c9c4e97c8.
 * Do not edit: change the spec or the generator and run `make generate`.
 */
/*
 * The library is table-driven where that keeps it small: one payload codec walks the field
 * table below, one sentence codec walks the $PAHR field table, and names live in string pools
 * (one for every name that only the name functions use, one per kind for the names errors
 * report). All tables are const; nothing here is mutable after start-up.
 */
#include "ilahrs.h"

#include <string.h>

/*
 * Speed or size. 64-bit hosts get word-at-a-time checksums, a zero-copy path through the
 * stream decoder for messages inside the caller's chunk and a fast path for sentences in the
 * canonical layout; 32-bit targets get the smallest code. Both give the same answers. Define
 * ILAHRS_OPTIMIZE_SIZE to 1 or 0 to choose.
 */
#ifndef ILAHRS_OPTIMIZE_SIZE
#if SIZE_MAX > 0xFFFFFFFFu
#define ILAHRS_OPTIMIZE_SIZE 0
#else
#define ILAHRS_OPTIMIZE_SIZE 1
#endif
#endif

/*
 * Sentences in the stream decoder. A firmware that never turns on the device's NMEA output can
 * define ILAHRS_STREAM_SENTENCES to 0 for the smallest decoder: it hands back frames only and
 * counts the bytes of $PAHR sentences as discarded. It finds exactly the frames the full decoder
 * finds, in the same order: a valid sentence is printable ASCII ending in CR LF, so no frame
 * starts inside one, and a frame's validity never depends on what precedes it. Only the stream
 * decoder changes; ilahrs_pahr_parse() and the other sentence functions stay.
 */
#ifndef ILAHRS_STREAM_SENTENCES
#define ILAHRS_STREAM_SENTENCES 1
#endif

/* ---- Tables --------------------------------------------------------------------------- */

/* Strings (NUL-separated pools; tables hold offsets into them). Error kind names, the text
 * defaults of char fields and the variants' part numbers are there in every build. */
static const char ilahrs_error_names[159] =
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
    "timeout";

static const char ilahrs_text_names[1] =
    "";

static const char ilahrs_part_names[106] =
    "AHRS-G300-A2-TMGA-C1-V1.1\000"
    "AHRS-G300-A6-TMGA-C1-V1.1\000"
    "AHRS s/n 11AC0001 - 11AC0009\000"
    "AHRS-G300-A2-TGA-C1-V1.1";

#define ERROR_NAME(offset) (ilahrs_error_names + (offset))
#define TEXT(offset) (ilahrs_text_names + (offset))

static const uint8_t ilahrs_error_offsets[] = {
    0, /* truncated */
    10, /* bad_header */
    21, /* bad_message_type */
    38, /* bad_length */
    49, /* bad_checksum */
    62, /* trailing_data */
    76, /* unknown_command */
    92, /* out_of_range */
    105, /* malformed */
    115, /* buffer_too_small */
    132, /* unexpected_message */
    151, /* timeout */
};

static const uint8_t ilahrs_part_offsets[ILAHRS_VARIANT_COUNT] = {
    0, /* g300_a2_tmga */
    26, /* g300_a6_tmga */
    52, /* sn_11ac0001_0009 */
    81, /* g300_a2_tga */
};

#if ILAHRS_NAMES
/* The names errors report have a pool per kind, so that a firmware links only the ones it
 * reports. */
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

static const char ilahrs_date_names[5] =
    "date";

#define FRAME_NAME(offset) (ilahrs_frame_names + (offset))
#define FIELD_NAME(offset) (ilahrs_field_names + (offset))
#define SENTENCE_NAME(offset) (ilahrs_sentence_names + (offset))
#define NAME_DATE (ilahrs_date_names + 0)

/* Every other name, for the name accessors and by-name lookups, in one pool (a name that ends
 * another is stored once, as its tail), and their offsets in one table: one section per kind, in
 * the order of the kind's enum, starting at NAMES_<kind>. A USW bit without a flag has the empty
 * name. Event names are the command names, then those of the other events. */
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
    /* command */ 0, 10, 20, 30, 39, 48, 57, 66, 74, 85, 90, 102, 114, 125, 137, 152, 159, 170, 183, 194, 206, 217, 227, 237, 245, 254,
    /* event */ 264, 280, 294, 302, 316, 331, 349,
    /* variant */ 360, 373, 386, 403,
    /* mode */ 415, 971, 991, 420, 1202,
    /* payload */ 432, 444, 455, 475, 493, 514, 535, 552, 563, 586, 605, 628, 655, 674,
    /* flag */ 690, 715, 736, 749, 771, 792, 812, 9, 829, 848, 868, 884, 900, 916, 937,
    /* state */ 415, 1014, 962, 971, 982, 991, 1202, 1002, 1034, 1055, 1080, 1101, 1126, 1137, 1161, 1174,
    /* answer */ 1191, 514, 535, 552, 655, 475, 437, 1195, 586, 605,
};
#define NAMES_COMMAND 0u
#define NAMES_EVENT 26u
#define NAMES_VARIANT 33u
#define NAMES_MODE 37u
#define NAMES_PAYLOAD 42u
#define NAMES_FLAG 56u
#define NAMES_STATE 71u
#define NAMES_ANSWER 87u
#define NAMES_FLAG_COUNT 15u /* one per USW bit up to the last flag */
typedef char ilahrs_check_event_names[NAMES_EVENT == NAMES_COMMAND + ILAHRS_COMMAND_COUNT ? 1 : -1];
#else
/* Without names, errors name no field. */
#define NO_NAME ((const char *)NULL)
#define FRAME_NAME(offset) NO_NAME
#define FIELD_NAME(offset) NO_NAME
#define SENTENCE_NAME(offset) NO_NAME
#define NAME_DATE NO_NAME
#endif
#define NAME_FRAME_MESSAGE_TYPE FRAME_NAME(15)
#define NAME_FRAME_RESERVED FRAME_NAME(28)
#define NAME_FRAME_MESSAGE_LENGTH FRAME_NAME(37)
#define NAME_FRAME_HEADER FRAME_NAME(0)
#define NAME_FRAME_PAYLOAD FRAME_NAME(7)
#define NAME_FRAME_CHECKSUM FRAME_NAME(52)

/* Command table (Table C.1), one array per column so that a firmware links only the columns it
 * uses: code, modes it is valid in, response, parameter block, payload tables of a data
 * response. */
static const uint8_t ilahrs_command_codes[ILAHRS_COMMAND_COUNT] = {
0x80, 0x82, 0x83, 0x84, 0x86, 0x87, 0x88, 0x89, 0xCA, 0xFE, 0x40, 0x41, 0xB0, 0xBA, 0x1F, 0x1A, 0x21, 0x22, 0x23, 0x2B, 0x20, 0x2C, 0x2E, 0xFE, 0x2F, 0x2A
};

static const uint8_t ilahrs_command_modes[ILAHRS_COMMAND_COUNT] = {
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* AHRScont1 */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* AHRScont2 */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* AHRScont3 */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* AHRSreq1 */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* AHRSreq2 */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* AHRSreq3 */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* NMEAcont */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* NMEAreq */
ILAHRS_MODE_BIT(ILAHRS_MODE_ON_REQUEST), /* GetDataReq */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE) | ILAHRS_MODE_BIT(ILAHRS_MODE_CONTINUOUS) | ILAHRS_MODE_BIT(ILAHRS_MODE_ON_REQUEST), /* Stop */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* LoadAHRSPar */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* ReadAHRSPar */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE) | ILAHRS_MODE_BIT(ILAHRS_MODE_CONTINUOUS) | ILAHRS_MODE_BIT(ILAHRS_MODE_ON_REQUEST), /* LowPowerOn */
ILAHRS_MODE_BIT(ILAHRS_MODE_SLEEP), /* LowPowerOff */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* GetVerFirmware */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE) | ILAHRS_MODE_BIT(ILAHRS_MODE_ON_REQUEST), /* GetBIT */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* Start2DClb */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* Start2D2TClb */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* Start3DClb */
ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION), /* StartClbRun */
ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION), /* StopClbRun */
ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION), /* FinishClb */
ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION), /* AcceptClb */
ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION), /* ExitClb */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* ClearClb */
ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), /* GetClbRes */
};

static const uint8_t ilahrs_command_responses[ILAHRS_COMMAND_COUNT] = {
ILAHRS_RESPONSE_ACK, ILAHRS_RESPONSE_ACK, ILAHRS_RESPONSE_ACK, ILAHRS_RESPONSE_ACK, ILAHRS_RESPONSE_ACK, ILAHRS_RESPONSE_ACK, ILAHRS_RESPONSE_ACK, ILAHRS_RESPONSE_ACK, ILAHRS_RESPONSE_OUTPUT, ILAHRS_RESPONSE_NONE, ILAHRS_RESPONSE_NONE, ILAHRS_RESPONSE_DATA, ILAHRS_RESPONSE_NONE, ILAHRS_RESPONSE_NONE, ILAHRS_RESPONSE_DATA, ILAHRS_RESPONSE_DATA, ILAHRS_RESPONSE_NONE, ILAHRS_RESPONSE_NONE, ILAHRS_RESPONSE_NONE, ILAHRS_RESPONSE_NONE, ILAHRS_RESPONSE_DATA, ILAHRS_RESPONSE_DATA, ILAHRS_RESPONSE_ACK, ILAHRS_RESPONSE_ACK, ILAHRS_RESPONSE_ACK, ILAHRS_RESPONSE_DATA
};

static const int8_t ilahrs_command_blocks[ILAHRS_COMMAND_COUNT] = {
ILAHRS_PAYLOAD_NONE, /* AHRScont1 */
ILAHRS_PAYLOAD_NONE, /* AHRScont2 */
ILAHRS_PAYLOAD_NONE, /* AHRScont3 */
ILAHRS_PAYLOAD_NONE, /* AHRSreq1 */
ILAHRS_PAYLOAD_NONE, /* AHRSreq2 */
ILAHRS_PAYLOAD_NONE, /* AHRSreq3 */
ILAHRS_PAYLOAD_NONE, /* NMEAcont */
ILAHRS_PAYLOAD_NONE, /* NMEAreq */
ILAHRS_PAYLOAD_NONE, /* GetDataReq */
ILAHRS_PAYLOAD_NONE, /* Stop */
ILAHRS_PAYLOAD_AHRS_PARAMETERS_LOAD, /* LoadAHRSPar */
ILAHRS_PAYLOAD_NONE, /* ReadAHRSPar */
ILAHRS_PAYLOAD_NONE, /* LowPowerOn */
ILAHRS_PAYLOAD_NONE, /* LowPowerOff */
ILAHRS_PAYLOAD_NONE, /* GetVerFirmware */
ILAHRS_PAYLOAD_NONE, /* GetBIT */
ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, /* Start2DClb */
ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, /* Start2D2TClb */
ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, /* Start3DClb */
ILAHRS_PAYLOAD_CALIBRATION_RUN_PARAMETERS, /* StartClbRun */
ILAHRS_PAYLOAD_NONE, /* StopClbRun */
ILAHRS_PAYLOAD_NONE, /* FinishClb */
ILAHRS_PAYLOAD_NONE, /* AcceptClb */
ILAHRS_PAYLOAD_NONE, /* ExitClb */
ILAHRS_PAYLOAD_NONE, /* ClearClb */
ILAHRS_PAYLOAD_NONE, /* GetClbRes */
};

static const int8_t ilahrs_command_response_payloads[ILAHRS_COMMAND_COUNT][ILAHRS_RESPONSE_PAYLOADS_MAX] = {
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* AHRScont1 */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* AHRScont2 */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* AHRScont3 */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* AHRSreq1 */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* AHRSreq2 */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* AHRSreq3 */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* NMEAcont */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* NMEAreq */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* GetDataReq */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* Stop */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* LoadAHRSPar */
    { ILAHRS_PAYLOAD_AHRS_PARAMETERS_READ, ILAHRS_PAYLOAD_NONE }, /* ReadAHRSPar */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* LowPowerOn */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* LowPowerOff */
    { ILAHRS_PAYLOAD_FIRMWARE_VERSION, ILAHRS_PAYLOAD_NONE }, /* GetVerFirmware */
    { ILAHRS_PAYLOAD_BIT_RESULT, ILAHRS_PAYLOAD_NONE }, /* GetBIT */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* Start2DClb */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* Start2D2TClb */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* Start3DClb */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* StartClbRun */
    { ILAHRS_PAYLOAD_CALIBRATION_RESULT, ILAHRS_PAYLOAD_CALIBRATION_RUN_RESULT }, /* StopClbRun */
    { ILAHRS_PAYLOAD_CALIBRATION_RESULT, ILAHRS_PAYLOAD_NONE }, /* FinishClb */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* AcceptClb */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* ExitClb */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE }, /* ClearClb */
    { ILAHRS_PAYLOAD_CALIBRATION_STATUS, ILAHRS_PAYLOAD_NONE }, /* GetClbRes */
};

/* Commands ordered by code, then ICD name: command_decode() reports all with one code. */
static const uint8_t ilahrs_commands_by_code[ILAHRS_COMMAND_COUNT] = {
    ILAHRS_COMMAND_GET_BIT, /* 0x1A GetBIT */
    ILAHRS_COMMAND_GET_VER_FIRMWARE, /* 0x1F GetVerFirmware */
    ILAHRS_COMMAND_STOP_CLB_RUN, /* 0x20 StopClbRun */
    ILAHRS_COMMAND_START_2D_CLB, /* 0x21 Start2DClb */
    ILAHRS_COMMAND_START_2D2T_CLB, /* 0x22 Start2D2TClb */
    ILAHRS_COMMAND_START_3D_CLB, /* 0x23 Start3DClb */
    ILAHRS_COMMAND_GET_CLB_RES, /* 0x2A GetClbRes */
    ILAHRS_COMMAND_START_CLB_RUN, /* 0x2B StartClbRun */
    ILAHRS_COMMAND_FINISH_CLB, /* 0x2C FinishClb */
    ILAHRS_COMMAND_ACCEPT_CLB, /* 0x2E AcceptClb */
    ILAHRS_COMMAND_CLEAR_CLB, /* 0x2F ClearClb */
    ILAHRS_COMMAND_LOAD_AHRS_PAR, /* 0x40 LoadAHRSPar */
    ILAHRS_COMMAND_READ_AHRS_PAR, /* 0x41 ReadAHRSPar */
    ILAHRS_COMMAND_AHRS_CONT1, /* 0x80 AHRScont1 */
    ILAHRS_COMMAND_AHRS_CONT2, /* 0x82 AHRScont2 */
    ILAHRS_COMMAND_AHRS_CONT3, /* 0x83 AHRScont3 */
    ILAHRS_COMMAND_AHRS_REQ1, /* 0x84 AHRSreq1 */
    ILAHRS_COMMAND_AHRS_REQ2, /* 0x86 AHRSreq2 */
    ILAHRS_COMMAND_AHRS_REQ3, /* 0x87 AHRSreq3 */
    ILAHRS_COMMAND_NMEA_CONT, /* 0x88 NMEAcont */
    ILAHRS_COMMAND_NMEA_REQ, /* 0x89 NMEAreq */
    ILAHRS_COMMAND_LOW_POWER_ON, /* 0xB0 LowPowerOn */
    ILAHRS_COMMAND_LOW_POWER_OFF, /* 0xBA LowPowerOff */
    ILAHRS_COMMAND_GET_DATA_REQ, /* 0xCA GetDataReq */
    ILAHRS_COMMAND_EXIT_CLB, /* 0xFE ExitClb */
    ILAHRS_COMMAND_STOP, /* 0xFE Stop */
};

/* The meaning of a shared code in a mode where none of its names is valid (E14). */
#define CODE_DEFAULT_COUNT 1u
static const uint8_t ilahrs_code_defaults[1] = { ILAHRS_COMMAND_STOP };

/* Variant parameters (KG, KA). */
static const int32_t ilahrs_variant_values[ILAHRS_VARIANT_COUNT][2] = {
    { 100, 10000 }, /* g300_a2_tmga */
    { 100, 5000 }, /* g300_a6_tmga */
    { 50, 10000 }, /* sn_11ac0001_0009 */
    { 100, 10000 }, /* g300_a2_tga */
};


/* Builder checks, inclusive; row 0 of each table means "no check: the C type is the range".
 * Integer fields compare as integers; float fields compare their float32 value with the
 * float32 roundings of the bounds, and ilahrs_field_check() compares a double with the exact
 * bounds (a double within them always rounds to a float32 within the rounded ones). */
static const int32_t ilahrs_int_bounds[11][2] = {
    { 0, 0 },
    { 0, 35999u },
    { (-9000), 9000 },
    { (-18000), 18000 },
    { (-10000), 10000 },
    { 1, 100 },
    { 1, 65535u },
    { 1, 3 },
    { 0, 100 },
    { 2, 2 },
    { 1, 255 },
};

/* Float bounds as the keys of their float32 roundings (float_key()), so that a builder checks a
 * float with integer compares: exact, and no floating-point code linked. */
static const int32_t ilahrs_float_bounds[8][2] = {
    { 0, 0 }, /* 0.0f .. 0.0f */
    { (-2139095039), 2139095039 }, /* (-3.4028234663852886e+38f) .. 3.4028234663852886e+38f */
    { 0, 1135869952 }, /* 0.0f .. 360.0f */
    { (-1127481344), 1127481344 }, /* (-180.0f) .. 180.0f */
    { (-1119092736), 1119092736 }, /* (-90.0f) .. 90.0f */
    { (-1184645120), 1203982336 }, /* (-20000.0f) .. 100000.0f */
    { 1156415510, 1158250503 }, /* 1900.002685546875f .. 2200.001708984375f */
    { (-1135869952), 1135869952 }, /* (-360.0f) .. 360.0f */
};


/* Engineering scales: raw * multiplier / divisor; with a parameter, the variant's value divides.
 * Each column has the smallest type that holds it. */
static const struct {
    uint16_t divisor;
    uint8_t multiplier;
    uint8_t parameter;
} ilahrs_scales[8] = {
    { 1, 1, 255 },
    { 100, 1, 255 },
    { 1000, 1, 255 },
    { 10000, 1, 255 },
    { 10, 1, 255 },
    { 0, 1, 0 },
    { 0, 1, 1 },
    { 1, 10, 255 },
};

/* ilahrs_field_info_t, unpacked. A field's type is its wire kind, an encoding a builder checks
 * beyond a range and the log2 of a number's size; char and reserved (the last kinds) are arrays,
 * whose info is their size. A number's info is its builder bounds and its engineering scale. */
#define KIND_BITS 3u
#define ENCODING_BITS 1u
#define TYPE_BITS 6u
#define OFFSET_BITS 6u
#define BOUNDS_BITS 4u
#define FIELD_KIND(f) ((unsigned)(f)->name_type & ((1u << KIND_BITS) - 1u))
#define FIELD_ENCODING(f) (((unsigned)(f)->name_type >> KIND_BITS) & ((1u << ENCODING_BITS) - 1u))
#define FIELD_NAME_AT(f) ((unsigned)(f)->name_type >> TYPE_BITS)
#define FIELD_IS_ARRAY(f) (FIELD_KIND(f) >= ILAHRS_KIND_CHAR)
#define FIELD_ARRAY_SIZE(f) ((unsigned)(f)->info)
#define FIELD_NUMBER_SIZE(f) (1u << (((unsigned)(f)->name_type & ((1u << TYPE_BITS) - 1u)) >> (KIND_BITS + ENCODING_BITS)))
#define FIELD_SIZE(f) (FIELD_IS_ARRAY(f) ? FIELD_ARRAY_SIZE(f) : FIELD_NUMBER_SIZE(f))
#define FIELD_OFFSET(f) ((unsigned)(f)->place & ((1u << OFFSET_BITS) - 1u))
#define FIELD_MEMBER(f) (FIELD_OFFSET(f) + ((unsigned)(f)->place >> OFFSET_BITS))
#define FIELD_BOUNDS(f) ((unsigned)(f)->info & ((1u << BOUNDS_BITS) - 1u))
#define FIELD_SCALE(f) ((unsigned)(f)->info >> BOUNDS_BITS)
#define ENCODING_NONE 0u
#define ENCODING_DECLINATION 1u
#define NO_PARAMETER 255

/* Every payload field, table after table, in wire order: name and type, wire offset and the
 * padding before its struct member, array size or bounds and scale. */
static const ilahrs_field_info_t ilahrs_fields[131] = {
    /* full_output (Table 6.4) */
    { (234u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 0, 1 | (1u << BOUNDS_BITS) }, /* heading */
    { (263u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 2, 2 | (1u << BOUNDS_BITS) }, /* pitch */
    { (250u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 4, 3 | (1u << BOUNDS_BITS) }, /* roll */
    { (0u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 6, 0 }, /* ugyro_x */
    { (8u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 8, 0 }, /* ugyro_y */
    { (16u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 10, 0 }, /* ugyro_z */
    { (24u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 12, 0 }, /* uacc_x */
    { (31u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 14, 0 }, /* uacc_y */
    { (38u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 16, 0 }, /* uacc_z */
    { (45u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 18, 0 }, /* umag_x */
    { (52u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 20, 0 }, /* umag_y */
    { (59u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 22, 0 }, /* umag_z */
    { (66u << TYPE_BITS) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_RESERVED, (0u << OFFSET_BITS) | 24, 4 }, /* reserved */
    { (75u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 28, 0 }, /* usw */
    { (79u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 30, 0 | (2u << BOUNDS_BITS) }, /* vdd */
    { (83u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 32, 0 }, /* utermo */
    /* quaternion (Table 6.5) */
    { (234u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 0, 1 | (1u << BOUNDS_BITS) }, /* heading */
    { (263u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 2, 2 | (1u << BOUNDS_BITS) }, /* pitch */
    { (250u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 4, 3 | (1u << BOUNDS_BITS) }, /* roll */
    { (90u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 6, 4 | (3u << BOUNDS_BITS) }, /* lk0 */
    { (94u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 8, 4 | (3u << BOUNDS_BITS) }, /* lk1 */
    { (98u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 10, 4 | (3u << BOUNDS_BITS) }, /* lk2 */
    { (102u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 12, 4 | (3u << BOUNDS_BITS) }, /* lk3 */
    { (66u << TYPE_BITS) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_RESERVED, (0u << OFFSET_BITS) | 14, 14 }, /* reserved */
    { (75u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 28, 0 }, /* usw */
    { (79u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 30, 0 | (2u << BOUNDS_BITS) }, /* vdd */
    { (83u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 32, 0 | (4u << BOUNDS_BITS) }, /* utermo */
    /* orientation_sensors (Table 6.6) */
    { (234u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 0, 1 | (1u << BOUNDS_BITS) }, /* heading */
    { (263u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 2, 2 | (1u << BOUNDS_BITS) }, /* pitch */
    { (250u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 4, 3 | (1u << BOUNDS_BITS) }, /* roll */
    { (1u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 6, 0 | (5u << BOUNDS_BITS) }, /* gyro_x */
    { (9u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 8, 0 | (5u << BOUNDS_BITS) }, /* gyro_y */
    { (17u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 10, 0 | (5u << BOUNDS_BITS) }, /* gyro_z */
    { (25u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 12, 0 | (6u << BOUNDS_BITS) }, /* acc_x */
    { (32u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 14, 0 | (6u << BOUNDS_BITS) }, /* acc_y */
    { (39u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 16, 0 | (6u << BOUNDS_BITS) }, /* acc_z */
    { (46u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 18, 0 | (7u << BOUNDS_BITS) }, /* mag_x */
    { (53u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 20, 0 | (7u << BOUNDS_BITS) }, /* mag_y */
    { (60u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 22, 0 | (7u << BOUNDS_BITS) }, /* mag_z */
    { (66u << TYPE_BITS) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_RESERVED, (0u << OFFSET_BITS) | 24, 4 }, /* reserved */
    { (75u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 28, 0 }, /* usw */
    { (79u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 30, 0 | (2u << BOUNDS_BITS) }, /* vdd */
    { (83u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 32, 0 | (4u << BOUNDS_BITS) }, /* utermo */
    /* initial_alignment (Table 6.8) */
    { (106u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 0, 1 }, /* gyro_bias_x */
    { (118u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 4, 1 }, /* gyro_bias_y */
    { (130u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 8, 1 }, /* gyro_bias_z */
    { (142u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 12, 1 }, /* average_acc_x */
    { (156u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 16, 1 }, /* average_acc_y */
    { (170u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 20, 1 }, /* average_acc_z */
    { (184u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 24, 1 }, /* average_mag_x */
    { (198u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 28, 1 }, /* average_mag_y */
    { (212u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 32, 1 }, /* average_mag_z */
    { (226u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 36, 2 }, /* initial_heading */
    { (242u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 40, 3 }, /* initial_roll */
    { (255u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 44, 4 }, /* initial_pitch */
    { (75u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 48, 0 }, /* usw */
    /* ahrs_parameters_load (Table 6.9) */
    { (269u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 0, 5 }, /* update_rate */
    { (281u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 2, 6 }, /* alignment_time */
    { (296u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_DECLINATION << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 4, 1 }, /* declination */
    { (308u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 8, 4 }, /* latitude */
    { (317u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 12, 3 }, /* longitude */
    { (327u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 16, 5 }, /* altitude */
    { (336u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 20, 6 }, /* date */
    { (341u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 24, 7 }, /* alignment_angle_a1 */
    { (360u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 28, 7 }, /* alignment_angle_a2 */
    { (379u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 32, 7 }, /* alignment_angle_a3 */
    { (66u << TYPE_BITS) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_RESERVED, (0u << OFFSET_BITS) | 36, 14 }, /* reserved */
    /* ahrs_parameters_read (Table 6.10) */
    { (269u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 0, 5 }, /* update_rate */
    { (281u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 2, 6 }, /* alignment_time */
    { (296u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_DECLINATION << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 4, 1 }, /* declination */
    { (308u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 8, 4 }, /* latitude */
    { (317u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 12, 3 }, /* longitude */
    { (327u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 16, 5 }, /* altitude */
    { (336u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 20, 6 }, /* date */
    { (341u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 24, 7 }, /* alignment_angle_a1 */
    { (360u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 28, 7 }, /* alignment_angle_a2 */
    { (379u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 32, 7 }, /* alignment_angle_a3 */
    { (398u << TYPE_BITS) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_CHAR, (0u << OFFSET_BITS) | 36, 8 }, /* device_id */
    { (66u << TYPE_BITS) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_RESERVED, (1u << OFFSET_BITS) | 44, 6 }, /* reserved */
    /* firmware_version (Table 6.11) */
    { (408u << TYPE_BITS) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_CHAR, (0u << OFFSET_BITS) | 0, 50 }, /* version */
    /* bit_result (Table 6.12) */
    { (416u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_SIGNED, (0u << OFFSET_BITS) | 0, 0 | (1u << BOUNDS_BITS) }, /* utermo100 */
    { (75u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 2, 0 }, /* usw */
    /* calibration_parameters (Table 6.13) */
    { (426u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 0, 7 }, /* reference_azimuth */
    { (444u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 4, 6 }, /* accumulation_time */
    { (308u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (2u << OFFSET_BITS) | 6, 4 }, /* latitude */
    { (317u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (2u << OFFSET_BITS) | 10, 3 }, /* longitude */
    { (327u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (2u << OFFSET_BITS) | 14, 5 }, /* altitude */
    { (336u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (2u << OFFSET_BITS) | 18, 6 }, /* date */
    /* calibration_result (Table 6.14) */
    { (462u << TYPE_BITS) | (0u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 0, 7 }, /* calibration_type */
    { (479u << TYPE_BITS) | (0u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 1, 0 }, /* runs_used */
    { (489u << TYPE_BITS) | (0u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 2, 8 }, /* data_used */
    { (499u << TYPE_BITS) | (0u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 3, 0 }, /* success */
    { (507u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 4, 1 }, /* tm_c_11 */
    { (515u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 8, 1 }, /* tm_c_12 */
    { (523u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 12, 1 }, /* tm_c_13 */
    { (531u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 16, 1 }, /* tm_c_21 */
    { (539u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 20, 1 }, /* tm_c_22 */
    { (547u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 24, 1 }, /* tm_c_23 */
    { (555u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 28, 1 }, /* tm_c_31 */
    { (563u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 32, 1 }, /* tm_c_32 */
    { (571u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 36, 1 }, /* tm_c_33 */
    { (579u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 40, 1 }, /* hm_0_x */
    { (586u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 44, 1 }, /* hm_0_y */
    { (593u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 48, 1 }, /* hm_0_z */
    /* calibration_run_result (Table 6.15) */
    { (462u << TYPE_BITS) | (0u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 0, 9 }, /* calibration_type */
    { (600u << TYPE_BITS) | (0u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 1, 10 }, /* run */
    { (489u << TYPE_BITS) | (0u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 2, 8 }, /* data_used */
    { (499u << TYPE_BITS) | (0u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 3, 0 }, /* success */
    { (604u << TYPE_BITS) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_RESERVED, (0u << OFFSET_BITS) | 4, 4 }, /* reserved_1 */
    { (615u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 8, 4 }, /* average_pitch */
    { (629u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 12, 3 }, /* average_roll */
    { (642u << TYPE_BITS) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_RESERVED, (0u << OFFSET_BITS) | 16, 12 }, /* reserved_2 */
    { (75u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 28, 0 }, /* usw */
    /* calibration_run_parameters (Table 6.16) */
    { (66u << TYPE_BITS) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_RESERVED, (0u << OFFSET_BITS) | 0, 6 }, /* reserved */
    /* calibration_status (Table 6.17) */
    { (462u << TYPE_BITS) | (0u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 0, 0 }, /* calibration_type */
    { (479u << TYPE_BITS) | (0u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 1, 0 }, /* runs_used */
    { (66u << TYPE_BITS) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_RESERVED, (0u << OFFSET_BITS) | 2, 1 }, /* reserved */
    { (499u << TYPE_BITS) | (0u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 3, 0 }, /* success */
    { (507u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 4, 1 }, /* tm_c_11 */
    { (515u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 8, 1 }, /* tm_c_12 */
    { (523u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 12, 1 }, /* tm_c_13 */
    { (531u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 16, 1 }, /* tm_c_21 */
    { (539u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 20, 1 }, /* tm_c_22 */
    { (547u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 24, 1 }, /* tm_c_23 */
    { (555u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 28, 1 }, /* tm_c_31 */
    { (563u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 32, 1 }, /* tm_c_32 */
    { (571u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 36, 1 }, /* tm_c_33 */
    { (579u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 40, 1 }, /* hm_0_x */
    { (586u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 44, 1 }, /* hm_0_y */
    { (593u << TYPE_BITS) | (2u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_FLOAT, (0u << OFFSET_BITS) | 48, 1 }, /* hm_0_z */
    /* acknowledgement (6.3.1 (Table 6.2 with a one-word payload)) */
    { (653u << TYPE_BITS) | (1u << (KIND_BITS + ENCODING_BITS)) | (ENCODING_NONE << KIND_BITS) | ILAHRS_KIND_UNSIGNED, (0u << OFFSET_BITS) | 0, 0 }, /* checksum */
};

static const struct {
    uint8_t size;
    uint8_t field_count;
    uint8_t first_field;
    uint8_t struct_size; /* checked below */
} ilahrs_payloads[ILAHRS_PAYLOAD_COUNT] = {
    { 34, 16, 0, (uint8_t)sizeof(ilahrs_full_output_t) },
    { 34, 11, 16, (uint8_t)sizeof(ilahrs_quaternion_t) },
    { 34, 16, 27, (uint8_t)sizeof(ilahrs_orientation_sensors_t) },
    { 50, 13, 43, (uint8_t)sizeof(ilahrs_initial_alignment_t) },
    { 50, 11, 56, (uint8_t)sizeof(ilahrs_ahrs_parameters_load_t) },
    { 50, 12, 67, (uint8_t)sizeof(ilahrs_ahrs_parameters_read_t) },
    { 50, 1, 79, (uint8_t)sizeof(ilahrs_firmware_version_t) },
    { 4, 2, 80, (uint8_t)sizeof(ilahrs_bit_result_t) },
    { 22, 6, 82, (uint8_t)sizeof(ilahrs_calibration_parameters_t) },
    { 52, 16, 88, (uint8_t)sizeof(ilahrs_calibration_result_t) },
    { 30, 9, 104, (uint8_t)sizeof(ilahrs_calibration_run_result_t) },
    { 6, 1, 113, (uint8_t)sizeof(ilahrs_calibration_run_parameters_t) },
    { 52, 16, 114, (uint8_t)sizeof(ilahrs_calibration_status_t) },
    { 2, 1, 130, (uint8_t)sizeof(ilahrs_acknowledgement_t) },
};

/* Builder defaults other than zero (the spec default, else the lowest value the range allows):
 * the field's row, the text pool offset of a char field's text (0 for a number), or the
 * bits of a numeric field's member. Each column has the smallest type that holds it. */
static const struct {
    uint32_t bits;
    uint8_t field;
    uint8_t text;
} ilahrs_defaults[11] = {
    { 0x00000064u, 56, 0 }, /* ahrs_parameters_load.update_rate = 100 */
    { 0x0000001Eu, 57, 0 }, /* ahrs_parameters_load.alignment_time = 30 */
    { 0x44ED8016u, 62, 0 }, /* ahrs_parameters_load.date = 1900.002685546875f */
    { 0x00000001u, 67, 0 }, /* ahrs_parameters_read.update_rate = 1 */
    { 0x00000001u, 68, 0 }, /* ahrs_parameters_read.alignment_time = 1 */
    { 0x44ED8016u, 73, 0 }, /* ahrs_parameters_read.date = 1900.002685546875f */
    { 0x00000001u, 83, 0 }, /* calibration_parameters.accumulation_time = 1 */
    { 0x44ED8016u, 87, 0 }, /* calibration_parameters.date = 1900.002685546875f */
    { 0x00000001u, 88, 0 }, /* calibration_result.calibration_type = 1 */
    { 0x00000002u, 104, 0 }, /* calibration_run_result.calibration_type = 2 */
    { 0x00000001u, 105, 0 }, /* calibration_run_result.run = 1 */
};
#define DEFAULT_COUNT 11u

/* C99 compile-time checks: struct sizes fit ilahrs_payloads, and each member lies where
 * ilahrs_fields says (the generator's natural alignment). */
typedef char ilahrs_check_full_output[sizeof(ilahrs_full_output_t) <= 255
    && offsetof(ilahrs_full_output_t, heading) == 0
    && offsetof(ilahrs_full_output_t, pitch) == 2
    && offsetof(ilahrs_full_output_t, roll) == 4
    && offsetof(ilahrs_full_output_t, ugyro_x) == 6
    && offsetof(ilahrs_full_output_t, ugyro_y) == 8
    && offsetof(ilahrs_full_output_t, ugyro_z) == 10
    && offsetof(ilahrs_full_output_t, uacc_x) == 12
    && offsetof(ilahrs_full_output_t, uacc_y) == 14
    && offsetof(ilahrs_full_output_t, uacc_z) == 16
    && offsetof(ilahrs_full_output_t, umag_x) == 18
    && offsetof(ilahrs_full_output_t, umag_y) == 20
    && offsetof(ilahrs_full_output_t, umag_z) == 22
    && offsetof(ilahrs_full_output_t, reserved) == 24
    && offsetof(ilahrs_full_output_t, usw) == 28
    && offsetof(ilahrs_full_output_t, vdd) == 30
    && offsetof(ilahrs_full_output_t, utermo) == 32
    ? 1 : -1];
typedef char ilahrs_check_quaternion[sizeof(ilahrs_quaternion_t) <= 255
    && offsetof(ilahrs_quaternion_t, heading) == 0
    && offsetof(ilahrs_quaternion_t, pitch) == 2
    && offsetof(ilahrs_quaternion_t, roll) == 4
    && offsetof(ilahrs_quaternion_t, lk0) == 6
    && offsetof(ilahrs_quaternion_t, lk1) == 8
    && offsetof(ilahrs_quaternion_t, lk2) == 10
    && offsetof(ilahrs_quaternion_t, lk3) == 12
    && offsetof(ilahrs_quaternion_t, reserved) == 14
    && offsetof(ilahrs_quaternion_t, usw) == 28
    && offsetof(ilahrs_quaternion_t, vdd) == 30
    && offsetof(ilahrs_quaternion_t, utermo) == 32
    ? 1 : -1];
typedef char ilahrs_check_orientation_sensors[sizeof(ilahrs_orientation_sensors_t) <= 255
    && offsetof(ilahrs_orientation_sensors_t, heading) == 0
    && offsetof(ilahrs_orientation_sensors_t, pitch) == 2
    && offsetof(ilahrs_orientation_sensors_t, roll) == 4
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
    && offsetof(ilahrs_orientation_sensors_t, usw) == 28
    && offsetof(ilahrs_orientation_sensors_t, vdd) == 30
    && offsetof(ilahrs_orientation_sensors_t, utermo) == 32
    ? 1 : -1];
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
    ? 1 : -1];
typedef char ilahrs_check_ahrs_parameters_load[sizeof(ilahrs_ahrs_parameters_load_t) <= 255
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
    ? 1 : -1];
typedef char ilahrs_check_ahrs_parameters_read[sizeof(ilahrs_ahrs_parameters_read_t) <= 255
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
    ? 1 : -1];
typedef char ilahrs_check_firmware_version[sizeof(ilahrs_firmware_version_t) <= 255
    && offsetof(ilahrs_firmware_version_t, version) == 0
    ? 1 : -1];
typedef char ilahrs_check_bit_result[sizeof(ilahrs_bit_result_t) <= 255
    && offsetof(ilahrs_bit_result_t, utermo100) == 0
    && offsetof(ilahrs_bit_result_t, usw) == 2
    ? 1 : -1];
typedef char ilahrs_check_calibration_parameters[sizeof(ilahrs_calibration_parameters_t) <= 255
    && offsetof(ilahrs_calibration_parameters_t, reference_azimuth) == 0
    && offsetof(ilahrs_calibration_parameters_t, accumulation_time) == 4
    && offsetof(ilahrs_calibration_parameters_t, latitude) == 8
    && offsetof(ilahrs_calibration_parameters_t, longitude) == 12
    && offsetof(ilahrs_calibration_parameters_t, altitude) == 16
    && offsetof(ilahrs_calibration_parameters_t, date) == 20
    ? 1 : -1];
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
    ? 1 : -1];
typedef char ilahrs_check_calibration_run_result[sizeof(ilahrs_calibration_run_result_t) <= 255
    && offsetof(ilahrs_calibration_run_result_t, calibration_type) == 0
    && offsetof(ilahrs_calibration_run_result_t, run) == 1
    && offsetof(ilahrs_calibration_run_result_t, data_used) == 2
    && offsetof(ilahrs_calibration_run_result_t, success) == 3
    && offsetof(ilahrs_calibration_run_result_t, reserved_1) == 4
    && offsetof(ilahrs_calibration_run_result_t, average_pitch) == 8
    && offsetof(ilahrs_calibration_run_result_t, average_roll) == 12
    && offsetof(ilahrs_calibration_run_result_t, reserved_2) == 16
    && offsetof(ilahrs_calibration_run_result_t, usw) == 28
    ? 1 : -1];
typedef char ilahrs_check_calibration_run_parameters[sizeof(ilahrs_calibration_run_parameters_t) <= 255
    && offsetof(ilahrs_calibration_run_parameters_t, reserved) == 0
    ? 1 : -1];
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
    ? 1 : -1];
typedef char ilahrs_check_acknowledgement[sizeof(ilahrs_acknowledgement_t) <= 255
    && offsetof(ilahrs_acknowledgement_t, checksum) == 0
    ? 1 : -1];
/* The stream decoder's counters fit its buffer. */
typedef char ilahrs_check_held[ILAHRS_MAX_MESSAGE_SIZE <= 255 && ILAHRS_FRAME_MAX_SIZE <= ILAHRS_MAX_MESSAGE_SIZE ? 1 : -1];

/* ---- Helpers --------------------------------------------------------------------------- */

/* Optimized for size, the library copies with plain loops rather than link memcpy, memmove and
 * memset (several hundred bytes each in a small C library). OPAQUE hides a loop counter from the
 * optimizer so that it does not turn such a loop back into a call. */
#if ILAHRS_OPTIMIZE_SIZE && defined(__GNUC__)
#define OPAQUE(x) __asm__("" : "+r"(x))
#else
#define OPAQUE(x) ((void)0)
#endif

/* NOINLINE keeps a small helper out of line in the size build, where one call is smaller than
 * the copies the compiler would inline at each use. */
#if ILAHRS_OPTIMIZE_SIZE && defined(__GNUC__)
#define NOINLINE __attribute__((noinline))
#else
#define NOINLINE
#endif

/* Copy n bytes front to back: right for separate buffers and for moves to a lower address
 * within one buffer. */
static void copy_forward(uint8_t *dst, const uint8_t *src, size_t n)
{
#if ILAHRS_OPTIMIZE_SIZE
    while (n > 0) {
        *dst++ = *src++;
        n--;
        OPAQUE(n);
    }
#else
    memmove(dst, src, n);
#endif
}

/* Copy n bytes between buffers that may overlap (memmove). */
static void move_bytes(uint8_t *dst, const uint8_t *src, size_t n)
{
#if ILAHRS_OPTIMIZE_SIZE
    if ((uintptr_t)dst <= (uintptr_t)src) {
        copy_forward(dst, src, n);
        return;
    }
    while (n > 0) {
        n--;
        OPAQUE(n);
        dst[n] = src[n];
    }
#else
    memmove(dst, src, n);
#endif
}

/* Set n bytes to zero (memset). */
static void zero_bytes(void *dst, size_t n)
{
#if ILAHRS_OPTIMIZE_SIZE
    uint8_t *p = (uint8_t *)dst;
    while (n > 0) {
        *p++ = 0;
        n--;
        OPAQUE(n);
    }
#else
    memset(dst, 0, n);
#endif
}

/* Optimized for size, every error path calls one copy of fail() rather than inline its three
 * stores (over a dozen bytes at each of some fifty call sites). */

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

/* Little-endian (byte_order: little) read and write of 1..4 bytes. */
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

/* Out of line in the size build: a call is smaller than the copy the compiler would inline into
 * each name accessor. */

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

/* The sum of the bytes, modulo 2^32 (so modulo the checksum width too). */
static inline uint32_t sum_bytes(const uint8_t *data, size_t len)
{
    uint32_t sum = 0;
    size_t i = 0;
#if !ILAHRS_OPTIMIZE_SIZE
    /* Eight bytes at a time as four 16-bit lanes. A lane gains at most 2 * 255 per word, so
     * 128 words (1 KiB) cannot overflow it before it is folded into `sum`. The last, partial
     * word is the eight bytes that end the data, less the ones already counted. */
    if (len >= 8) {
        const uint16_t one = 1;
        uint8_t little;
        memcpy(&little, &one, 1);
        while (i < len) {
            uint64_t lanes = 0;
            size_t stop = len - i >= 1024 ? i + 1024 : i + ((len - i) & ~(size_t)7);
            for (; i < stop; i += 8) {
                uint64_t word;
                memcpy(&word, data + i, 8);
                lanes += (word & 0x00FF00FF00FF00FFull) + ((word >> 8) & 0x00FF00FF00FF00FFull);
            }
            if (len - i < 8 && i < len) {
                uint64_t word;
                unsigned drop = 8u * (unsigned)(8 - (len - i));
                memcpy(&word, data + len - 8, 8);
                word = little ? word >> drop : word << drop;
                lanes += (word & 0x00FF00FF00FF00FFull) + ((word >> 8) & 0x00FF00FF00FF00FFull);
                i = len;
            }
            lanes = (lanes & 0x0000FFFF0000FFFFull) + ((lanes >> 16) & 0x0000FFFF0000FFFFull);
            sum += (uint32_t)lanes + (uint32_t)(lanes >> 32);
        }
    }
#endif
    for (; i < len; i++) {
        sum += data[i];
    }
    return sum;
}

uint16_t ilahrs_checksum(const uint8_t *data, size_t len)
{
    return (uint16_t)sum_bytes(data, len);
}

static bool message_type_valid(uint32_t type)
{
    return type == ILAHRS_MESSAGE_TYPE_COMMAND || type == ILAHRS_MESSAGE_TYPE_DATA;
}

bool ilahrs_frame_parse(const uint8_t *data, size_t len, ilahrs_frame_t *frame, ilahrs_error_t *err)
{
    static const uint8_t header[ILAHRS_FRAME_HEADER_SIZE] = { ILAHRS_FRAME_HEADER_0, ILAHRS_FRAME_HEADER_1 };
    size_t total;
    size_t at;
    uint32_t length;
    /* The header bytes that are there; a short frame is truncated just below. */
    for (at = 0; at < ILAHRS_FRAME_HEADER_SIZE && at < len; at++) {
        if (data[at] != header[at]) {
            return fail(err, ILAHRS_ERR_BAD_HEADER, at, (NAME_FRAME_HEADER));
        }
    }
    if (len < ILAHRS_FRAME_PAYLOAD_OFFSET) {
        return fail(err, ILAHRS_ERR_TRUNCATED, len, NULL);
    }
    if (!message_type_valid(get_le(data + ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, ILAHRS_FRAME_MESSAGE_TYPE_SIZE))) {
        return fail(err, ILAHRS_ERR_BAD_MESSAGE_TYPE, ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, (NAME_FRAME_MESSAGE_TYPE));
    }
    length = get_le(data + ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, ILAHRS_FRAME_MESSAGE_LENGTH_SIZE);
    if (length < ILAHRS_FRAME_MIN_LENGTH || length > ILAHRS_FRAME_MAX_LENGTH) {
        return fail(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, (NAME_FRAME_MESSAGE_LENGTH));
    }
    total = ILAHRS_FRAME_HEADER_SIZE + (size_t)length;
    if (len < total) {
        return fail(err, ILAHRS_ERR_TRUNCATED, len, NULL);
    }
    at = total - ILAHRS_FRAME_CHECKSUM_SIZE;
    if ((uint16_t)sum_bytes(data + ILAHRS_FRAME_HEADER_SIZE, at - ILAHRS_FRAME_HEADER_SIZE)
        != get_le(data + at, ILAHRS_FRAME_CHECKSUM_SIZE)) {
        return fail(err, ILAHRS_ERR_BAD_CHECKSUM, at, (NAME_FRAME_CHECKSUM));
    }
    if (len > total) {
        return fail(err, ILAHRS_ERR_TRAILING_DATA, total, NULL);
    }
    frame->message_type = (uint8_t)get_le(data + ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, ILAHRS_FRAME_MESSAGE_TYPE_SIZE);
    frame->reserved = (uint8_t)get_le(data + ILAHRS_FRAME_RESERVED_OFFSET, ILAHRS_FRAME_RESERVED_SIZE);
    frame->payload = data + ILAHRS_FRAME_PAYLOAD_OFFSET;
    frame->payload_size = at - ILAHRS_FRAME_PAYLOAD_OFFSET;
    return true;
}

/* Write header, fields, length and checksum around a payload already at out + PAYLOAD_OFFSET. */
static size_t frame_finish(uint8_t *out, const ilahrs_frame_t *frame, size_t payload_size)
{
    size_t at = ILAHRS_FRAME_PAYLOAD_OFFSET + payload_size;
    out[0] = ILAHRS_FRAME_HEADER_0;
    out[1] = ILAHRS_FRAME_HEADER_1;
    put_le(out + ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, frame->message_type, ILAHRS_FRAME_MESSAGE_TYPE_SIZE);
    put_le(out + ILAHRS_FRAME_RESERVED_OFFSET, frame->reserved, ILAHRS_FRAME_RESERVED_SIZE);
    put_le(out + ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, (uint32_t)(payload_size + ILAHRS_FRAME_LENGTH_BIAS), ILAHRS_FRAME_MESSAGE_LENGTH_SIZE);
    put_le(out + at, ilahrs_checksum(out + ILAHRS_FRAME_HEADER_SIZE, at - ILAHRS_FRAME_HEADER_SIZE), ILAHRS_FRAME_CHECKSUM_SIZE);
    return at + ILAHRS_FRAME_CHECKSUM_SIZE;
}

size_t ilahrs_frame_build(const ilahrs_frame_t *frame, uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    if (!message_type_valid(frame->message_type)) {
        return fail_size(err, ILAHRS_ERR_BAD_MESSAGE_TYPE, ILAHRS_NO_OFFSET, (NAME_FRAME_MESSAGE_TYPE));
    }
    if (frame->payload_size < ILAHRS_FRAME_MIN_PAYLOAD || frame->payload_size > ILAHRS_FRAME_MAX_PAYLOAD
        || frame->payload == NULL) {
        return fail_size(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_NO_OFFSET, (NAME_FRAME_PAYLOAD));
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
#endif

uint8_t ilahrs_command_code(ilahrs_command_t command)
{
    return (unsigned)command < ILAHRS_COMMAND_COUNT ? ilahrs_command_codes[command] : 0;
}

#if ILAHRS_NAMES
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
    return (unsigned)command < ILAHRS_COMMAND_COUNT ? (ilahrs_payload_t)ilahrs_command_blocks[command] : ILAHRS_PAYLOAD_NONE;
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
    memset(&frame, 0, sizeof frame);
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
        return fail(err, ILAHRS_ERR_BAD_MESSAGE_TYPE, ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, (NAME_FRAME_MESSAGE_TYPE));
    }
    if (frame.payload_size != 1) {
        return fail(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, (NAME_FRAME_MESSAGE_LENGTH));
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

size_t ilahrs_ack_build(const uint8_t *message, size_t len, uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    ilahrs_frame_t frame;
    size_t at;
    if (!ilahrs_frame_parse(message, len, &frame, err)) {
        return 0;
    }
    at = ILAHRS_FRAME_PAYLOAD_OFFSET + frame.payload_size;
    /* The table is the checksum alone, which needs no check: write it here (no field table). */
    if (out == NULL || cap < ILAHRS_ACKNOWLEDGEMENT_SIZE + ILAHRS_FRAME_OVERHEAD) {
        return fail_size(err, ILAHRS_ERR_BUFFER_TOO_SMALL, ILAHRS_NO_OFFSET, NULL);
    }
    put_le(out + ILAHRS_FRAME_PAYLOAD_OFFSET + ILAHRS_ACKNOWLEDGEMENT_CHECKSUM_OFFSET,
           get_le(message + at, ILAHRS_FRAME_CHECKSUM_SIZE), ILAHRS_ACKNOWLEDGEMENT_CHECKSUM_SIZE);
    memset(&frame, 0, sizeof frame);
    frame.message_type = ILAHRS_MESSAGE_TYPE_DATA;
    return frame_finish(out, &frame, ILAHRS_ACKNOWLEDGEMENT_SIZE);
}

/* ---- Variants -------------------------------------------------------------------------- */

int32_t ilahrs_variant_parameter(ilahrs_variant_t variant, ilahrs_variant_parameter_t parameter)
{
    if ((unsigned)variant >= ILAHRS_VARIANT_COUNT || (unsigned)parameter >= 2u) {
        return 0;
    }
    return ilahrs_variant_values[variant][parameter];
}

#if ILAHRS_NAMES
const char *ilahrs_variant_name(ilahrs_variant_t variant)
{
    return name_at((unsigned)variant, NAMES_VARIANT, ILAHRS_VARIANT_COUNT);
}
#endif

const char *ilahrs_variant_part_number(ilahrs_variant_t variant)
{
    return (unsigned)variant < ILAHRS_VARIANT_COUNT ? ilahrs_part_names + ilahrs_part_offsets[variant] : NULL;
}

#if ILAHRS_NAMES
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

#if ILAHRS_NAMES
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
    return FIELD_KIND(field) == ILAHRS_KIND_SIGNED ? (int64_t)sign_extend(bits, FIELD_NUMBER_SIZE(field)) : (int64_t)bits;
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
        && value == (FIELD_KIND(field) == ILAHRS_KIND_SIGNED ? (int64_t)sign_extend(bits, size)
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

/* A float32, as its bits, as an integer that orders like the float: -0 and +0 are both 0, and
 * NaNs lie beyond the infinities, so outside every finite range. */
static int32_t float_key(uint32_t bits)
{
    int32_t magnitude = (int32_t)(bits & 0x7FFFFFFFu);
    return (bits & 0x80000000u) != 0 ? -magnitude : magnitude;
}

/* The declination rule on float keys: ILAHRS_DECLINATION_MIN..MAX, or above COMPUTE_ABOVE. */
#define DECLINATION_MIN_KEY (-1127481344)
#define DECLINATION_MAX_KEY 1127481344
#define DECLINATION_COMPUTE_ABOVE_KEY 1135869952

/* The builder check of a stored value: integers against integer bounds, floats (by key) against
 * the float32 roundings of their bounds, then the encoding's rule. */
static bool stored_ok(const ilahrs_field_info_t *f, uint32_t bits)
{
    if (FIELD_KIND(f) == ILAHRS_KIND_FLOAT) {
        int32_t key = float_key(bits);
        if (key < ilahrs_float_bounds[FIELD_BOUNDS(f)][0] || key > ilahrs_float_bounds[FIELD_BOUNDS(f)][1]) {
            return false;
        }
        if (FIELD_ENCODING(f) == ENCODING_DECLINATION) {
            return (key >= DECLINATION_MIN_KEY && key <= DECLINATION_MAX_KEY) || key > DECLINATION_COMPUTE_ABOVE_KEY;
        }
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

bool ilahrs_field_scale(const ilahrs_field_info_t *field, ilahrs_variant_t variant, int32_t *multiplier, int32_t *divisor)
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
        if (ilahrs_defaults[i].field < first || ilahrs_defaults[i].field >= first + ilahrs_payloads[payload].field_count) {
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
        return fail(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_NO_OFFSET, NULL);
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
        return fail_size(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_NO_OFFSET, NULL);
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
            {
                if (!stored_ok(f, bits)) {
                    return fail_size(err, ILAHRS_ERR_OUT_OF_RANGE, FIELD_OFFSET(f), FIELD_NAME(FIELD_NAME_AT(f)));
                }
            }
            put_le(wire, bits, FIELD_NUMBER_SIZE(f));
        }
    }
    return size;
}

size_t ilahrs_payload_build_frame(ilahrs_payload_t payload, const void *in, uint8_t *out, size_t cap, ilahrs_error_t *err)
{
    ilahrs_frame_t frame;
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
    memset(&frame, 0, sizeof frame);
    frame.message_type = ILAHRS_MESSAGE_TYPE_DATA;
    return frame_finish(out, &frame, size);
}

/* ---- Date (Table 6.9, Table 6.10, Table 6.13) ---------------------------------------------------------------- */

/* Month 1..12 of a year (Gregorian). Bit m of 0x15AA is set for the months of 31 days; a year
 * divisible by 100 is leap when also by 16 (then by 400). */
static int days_in_month(int year, int month)
{
    if (month == 2) {
        return (year & 3) == 0 && (year % 100 != 0 || (year & 15) == 0) ? 29 : 28;
    }
    return 30 + (int)((0x15AAu >> month) & 1u);
}

/*
 * Year + (Month - 1)/12 + Day/365, as a float. Scaled by DATE_SCALE, the least common multiple of the divisors, a date is an
 * integer below 2^24: exact in a float32, and decoding compares integers (E15).
 */
#define DATE_SCALE 4380u
static int32_t date_scaled(int year, int month, int day)
{
    return (year + (0)) * 4380 + (month + (-1)) * 365 + (day + (0)) * 12;
}

/* The float32 nearest n / DATE_SCALE (ties to even), in integers: the quotient's bits one at a
 * time until it has 24, then rounded by the remainder. */
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

/* Date floats a decoder accepts, as float keys: from the year ILAHRS_DATE_YEAR_MIN to below
 * ILAHRS_DATE_YEAR_MAX + 2, the floats whose candidate years (below) hold a valid date.
 * DATE_EXPONENT is the biased exponent of the smallest. */
#define DATE_DECODE_MIN_KEY 1156415488
#define DATE_DECODE_MAX_KEY 1158254591
#define DATE_EXPONENT 137u
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
                int32_t at = (date_scaled(year, month, day) - base * (int32_t)DATE_SCALE) * (int32_t)(DATE_FRACTION_MASK + 1u);
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

/* ---- Unit Status Word ------------------------------------------------------------------ */

#if ILAHRS_NAMES
const char *ilahrs_usw_flag_name(unsigned bit)
{
    const char *name = name_at(bit, NAMES_FLAG, NAMES_FLAG_COUNT);
    return name != NULL && name[0] != '\0' ? name : NULL; /* empty: a bit without a flag */
}
#endif

/* ---- $PAHR sentences (Table 6.7, section 6.2) ---------------------------------------------------- */

/* The sentence grammar of NMEA 0183 (spec/README.md): "$", the identifier and ",", fields
 * separated by ",", then "*", two hex digits, CR LF. */
#define PAHR_START '$'
#define PAHR_SEPARATOR ','
#define PAHR_STAR '*'
#define PAHR_CR '\r'
#define PAHR_LF '\n'
#define PAHR_PREFIX "$PAHR,"
#define PAHR_PREFIX_LENGTH 6u
#define PAHR_TAIL 5u /* "*", two checksum digits, CR, LF */
#define PAHR_HUGE 10000000000000ull /* magnitudes saturate here: above every 32-bit range */

/* One field: name, hex (1) or decimal (0), template width, fraction digits, struct member and its
 * size, range (scaled). The member is signed when the range is. */
typedef struct {
    uint8_t name;
    uint8_t hex;
    uint8_t width;
    uint8_t decimals;
    uint8_t member;
    uint8_t size;
    int16_t min;
    uint16_t max;
} pahr_field_t;

static const pahr_field_t ilahrs_pahr_fields[ILAHRS_PAHR_FIELD_COUNT] = {
    { 0, 0, 4, 2, offsetof(ilahrs_pahr_t, roll), sizeof(((ilahrs_pahr_t *)0)->roll), (-18000), 18000 },
    { 5, 0, 3, 2, offsetof(ilahrs_pahr_t, pitch), sizeof(((ilahrs_pahr_t *)0)->pitch), (-9000), 9000 },
    { 11, 0, 3, 2, offsetof(ilahrs_pahr_t, heading), sizeof(((ilahrs_pahr_t *)0)->heading), 0, 35999u },
    { 19, 0, 3, 1, offsetof(ilahrs_pahr_t, temperature), sizeof(((ilahrs_pahr_t *)0)->temperature), (-999), 9999 },
    { 31, 0, 1, 2, offsetof(ilahrs_pahr_t, vdd), sizeof(((ilahrs_pahr_t *)0)->vdd), 0, 999 },
    { 35, 1, 4, 0, offsetof(ilahrs_pahr_t, usw), sizeof(((ilahrs_pahr_t *)0)->usw), 0, 65535u },
};

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

static int32_t pahr_get(const ilahrs_pahr_t *in, size_t k);

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

/* XOR of n bytes (eight at a time unless optimizing for size). */
static uint8_t xor_bytes(const uint8_t *p, size_t n)
{
    uint8_t x = 0;
    size_t i = 0;
#if !ILAHRS_OPTIMIZE_SIZE
    uint64_t lanes = 0;
    for (; i + 8 <= n; i += 8) {
        uint64_t word;
        memcpy(&word, p + i, 8);
        lanes ^= word;
    }
    lanes ^= lanes >> 32;
    lanes ^= lanes >> 16;
    lanes ^= lanes >> 8;
    x = (uint8_t)lanes;
#endif
    for (; i < n; i++) {
        x ^= p[i];
    }
    return x;
}

/* Magnitudes stop growing at SATURATED, above every range: m * 16 + 15 cannot overflow from below
 * it, so any number of digits reads without a wider type or a division. */
#define SATURATED 0x01000000u

/*
 * The field at *at, described by f, in one pass: its grammar, its value scaled to an integer, its
 * range. Returns ILAHRS_OK with the value stored in *out, ILAHRS_ERR_MALFORMED (also when the
 * number is not followed by a separator or by the star, star being the sentence's "*") or
 * ILAHRS_ERR_OUT_OF_RANGE, and leaves *at where the number ends.
 */
static ilahrs_error_kind_t pahr_field(const uint8_t **at, const uint8_t *star, const pahr_field_t *f, ilahrs_pahr_t *out)
{
    const uint8_t *q = *at;
    unsigned base = f->hex ? 16u : 10u;
    unsigned digits = 0; /* before the point */
    unsigned fraction = 0;
    bool point = false;
    bool negative = !f->hex && *q == '-';
    uint32_t m = 0;
    int32_t value;
    for (q += negative;; q++) {
        unsigned d = digit_value(*q);
        if (d < base) {
            if (m < SATURATED) {
                m = m * base + d;
            }
            if (point) {
                fraction++;
            } else {
                digits++;
            }
        } else if (*q == '.' && !point) {
            point = true; /* in a hex field, a point is followed by a fraction it cannot have */
        } else {
            break;
        }
    }
    *at = q;
    if (digits == 0 || (f->hex && digits > f->width) || (point && (fraction == 0 || fraction > f->decimals))
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

#if !ILAHRS_OPTIMIZE_SIZE
/*
 * Fast path for sentences in the layout the builders write (E16: every field at its template
 * width, so one length and fixed field positions): fixed-length digit runs without a branch per
 * character. It accepts only what the general path below accepts, with the same values; on
 * anything else it steps aside and the general path decides and names the error.
 */
#define PAHR_CANONICAL_LENGTH 48u

static inline int64_t canonical_decimal(const uint8_t *p, size_t width, size_t decimals, unsigned *ok)
{
    unsigned negative = p[0] == '-';
    unsigned good = 1;
    uint32_t value = 0;
    size_t j;
    for (j = 0; j < width; j++) {
        uint32_t digit = (uint32_t)p[j] - '0';
        unsigned sign = j == 0 && width > 1 ? negative : 0u; /* a sign needs a digit after it */
        good &= (unsigned)(digit <= 9u) | sign;
        value = value * 10u + (sign ? 0u : digit);
    }
    if (decimals > 0) {
        good &= (unsigned)(p[width] == '.');
        for (j = 0; j < decimals; j++) {
            uint32_t digit = (uint32_t)p[width + 1 + j] - '0';
            good &= (unsigned)(digit <= 9u);
            value = value * 10u + digit;
        }
    }
    *ok &= good;
    return negative ? -(int64_t)value : (int64_t)value;
}

static inline int64_t canonical_hex(const uint8_t *p, size_t width, unsigned *ok)
{
    unsigned good = 1;
    uint32_t value = 0;
    size_t j;
    for (j = 0; j < width; j++) {
        uint32_t digit = (uint32_t)p[j] - '0';
        uint32_t letter = ((uint32_t)p[j] | 0x20u) - 'a';
        unsigned is_digit = digit <= 9u;
        good &= is_digit | (unsigned)(letter <= 5u);
        value = value * 16u + (is_digit ? digit : letter + 10u);
    }
    *ok &= good;
    return (int64_t)value;
}

static bool pahr_canonical(const uint8_t *p, uint8_t checksum, ilahrs_pahr_t *out)
{
    unsigned ok = xor_bytes(p + 1, 43u - 1u) == checksum;
    int64_t v0 = canonical_decimal(p + 6, 4, 2, &ok);
    int64_t v1 = canonical_decimal(p + 14, 3, 2, &ok);
    int64_t v2 = canonical_decimal(p + 21, 3, 2, &ok);
    int64_t v3 = canonical_decimal(p + 28, 3, 1, &ok);
    int64_t v4 = canonical_decimal(p + 34, 1, 2, &ok);
    int64_t v5 = canonical_hex(p + 39, 4, &ok);
    ok &= (unsigned)(p[13] == PAHR_SEPARATOR);
    ok &= (unsigned)(p[20] == PAHR_SEPARATOR);
    ok &= (unsigned)(p[27] == PAHR_SEPARATOR);
    ok &= (unsigned)(p[33] == PAHR_SEPARATOR);
    ok &= (unsigned)(p[38] == PAHR_SEPARATOR);
    ok &= (unsigned)(v0 >= (-18000)) & (unsigned)(v0 <= 18000);
    ok &= (unsigned)(v1 >= (-9000)) & (unsigned)(v1 <= 9000);
    ok &= (unsigned)(v2 >= 0) & (unsigned)(v2 <= 35999u);
    ok &= (unsigned)(v3 >= (-999)) & (unsigned)(v3 <= 9999);
    ok &= (unsigned)(v4 >= 0) & (unsigned)(v4 <= 999);
    ok &= (unsigned)(v5 >= 0) & (unsigned)(v5 <= 65535u);
    if (!ok) {
        return false;
    }
    out->roll = (int16_t)v0;
    out->pitch = (int16_t)v1;
    out->heading = (uint16_t)v2;
    out->temperature = (int16_t)v3;
    out->vdd = (uint16_t)v4;
    out->usw = (uint16_t)v5;
    return true;
}
#endif

/*
 * Everything after the CR LF search: `end` is the sentence length, CR LF its last two
 * characters, and p[0..PAHR_PREFIX_LENGTH) the prefix. Returns ILAHRS_OK or the first error in
 * the order of spec/README.md, with its offset in *at and its field index in *field
 * (ILAHRS_PAHR_FIELD_COUNT for none).
 */
static ilahrs_error_kind_t pahr_body(const uint8_t *p, size_t end, ilahrs_pahr_t *out, size_t *at, size_t *field)
{
    size_t star = end - PAHR_TAIL; /* end >= PAHR_PREFIX_LENGTH + 2 */
    size_t i = PAHR_PREFIX_LENGTH;
    size_t k = 0;
    size_t error_at = 0;
    size_t error_field = 0;
    ilahrs_error_kind_t field_error = ILAHRS_OK;
    unsigned checksum;
    *field = ILAHRS_PAHR_FIELD_COUNT;
    *at = star;
    if (star < PAHR_PREFIX_LENGTH || p[star] != PAHR_STAR) {
        return ILAHRS_ERR_MALFORMED;
    }
    *at = star + 1;
    checksum = digit_value(p[star + 1]) * 16u + digit_value(p[star + 2]);
    if (checksum > 0xFFu) {
        return ILAHRS_ERR_MALFORMED;
    }
#if !ILAHRS_OPTIMIZE_SIZE
    if (end == PAHR_CANONICAL_LENGTH && pahr_canonical(p, (uint8_t)checksum, out)) {
        return ILAHRS_OK;
    }
#endif
    /* Fields, counted; the first bad one is remembered and reported after the checksum. */
    for (;;) {
        const uint8_t *q = p + i;
        if (k < ILAHRS_PAHR_FIELD_COUNT && field_error == ILAHRS_OK) {
            field_error = pahr_field(&q, p + star, &ilahrs_pahr_fields[k], out);
            error_at = i;
            error_field = k;
        }
        for (i = (size_t)(q - p); i < star && p[i] != PAHR_SEPARATOR; i++) {
        }
        k++;
        if (i >= star) {
            break;
        }
        i++; /* the separator */
    }
    if (xor_bytes(p + 1, star - 1) != checksum) {
        return ILAHRS_ERR_BAD_CHECKSUM;
    }
    *at = PAHR_PREFIX_LENGTH;
    if (k != ILAHRS_PAHR_FIELD_COUNT) {
        return ILAHRS_ERR_MALFORMED;
    }
    *at = error_at;
    *field = error_field;
    return field_error;
}

bool ilahrs_pahr_parse(const char *text, size_t len, ilahrs_pahr_t *out, ilahrs_error_t *err)
{
    const uint8_t *p = (const uint8_t *)text;
    size_t i;
    size_t end;
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
    {
        size_t at;
        size_t field;
        ilahrs_error_kind_t kind = pahr_body(p, end, out, &at, &field);
        return kind == ILAHRS_OK
            || fail(err, kind, at, field < ILAHRS_PAHR_FIELD_COUNT ? SENTENCE_NAME(ilahrs_pahr_fields[field].name) : NULL);
    }
}

static int32_t pahr_get(const ilahrs_pahr_t *in, size_t k)
{
    uint32_t bits = load_bits((const uint8_t *)in + ilahrs_pahr_fields[k].member, ilahrs_pahr_fields[k].size);
    return ilahrs_pahr_fields[k].min < 0 ? sign_extend(bits, ilahrs_pahr_fields[k].size) : (int32_t)bits;
}

static const char ilahrs_hex_digits[16] = { '0', '1', '2', '3', '4', '5', '6', '7', '8', '9', 'A', 'B', 'C', 'D', 'E', 'F' };

/*
 * Every field is range-checked before it is written, and the longest sentence of in-range values
 * is 48 characters (the generator checks it is at most ILAHRS_PAHR_MAX_LENGTH), so
 * the sentence is built without length checks. Each number is written from its last digit: at
 * least the template width (the sign counting as one character) and all its digits.
 */
size_t ilahrs_pahr_build(const ilahrs_pahr_t *in, char *text, size_t cap, ilahrs_error_t *err)
{
    uint8_t buf[ILAHRS_PAHR_MAX_LENGTH];
    size_t at = PAHR_PREFIX_LENGTH;
    size_t k;
    uint8_t sum = 0;
    copy_forward(buf, (const uint8_t *)PAHR_PREFIX, PAHR_PREFIX_LENGTH);
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

/* The exact bounds of float fields, as double keys: `value >= low && value <= high` on doubles is
 * `low_key <= key && key <= high_key` (a NaN's key is beyond every finite bound). */
static const int64_t ilahrs_exact_bounds[8][2] = {
    { 0ll, 0ll }, /* 0.0 .. 0.0 */
    { (-5183643170566569984ll), 5183643170566569984ll }, /* (-3.4028234663852886e+38) .. 3.4028234663852886e+38 */
    { 0ll, 4645040803167600640ll }, /* 0.0 .. 360.0 */
    { (-4640537203540230144ll), 4640537203540230144ll }, /* (-180.0) .. 180.0 */
    { (-4636033603912859648ll), 4636033603912859648ll }, /* (-90.0) .. 90.0 */
    { (-4671226772094713856ll), 4681608360884174848ll }, /* (-20000.0) .. 100000.0 */
    { 4656071115628609536ll, 4657056269994033152ll }, /* 1900.002685546875 .. 2200.001708984375 */
    { (-4645040803167600640ll), 4645040803167600640ll }, /* (-360.0) .. 360.0 */
};

/* The declination rule as double keys of the header's float constants. */
#define DECLINATION_MIN_DKEY (-4640537203540230144ll)
#define DECLINATION_MAX_DKEY 4640537203540230144ll
#define DECLINATION_COMPUTE_ABOVE_DKEY 4645040803167600640ll

/* value >= low && value <= high with the field's bounds (integer fields: their int bounds or
 * their C type's range, exact as doubles), then the declination rule, as compares of keys. */
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
    if (ok && FIELD_ENCODING(field) == ENCODING_DECLINATION) {
        ok = (key >= DECLINATION_MIN_DKEY && key <= DECLINATION_MAX_DKEY) || key > DECLINATION_COMPUTE_ABOVE_DKEY;
    }
    return ok || fail(err, ILAHRS_ERR_OUT_OF_RANGE, FIELD_OFFSET(field), FIELD_NAME(FIELD_NAME_AT(field)));
}

/* |value| * divisor rounded half away from zero, as the double code computed it: s = |value| *
 * divisor rounded to a double (to nearest, ties to even), then floor(s + 0.5) with s + 0.5 rounded
 * to a double too. For a hex field (whole, divisor 1): |value| if it is an integer. PAHR_HUGE,
 * beyond every range like the 1e15 the double code saturated at, for s >= 2^52 (infinities and
 * NaNs too) and for a hex field's fraction.
 *
 * Why this is exact: |value| is m * 2^e with m < 2^53, and m * divisor < 2^64 (divisors are at
 * most 100), so the product is exact; shifting it to 53 bits with a round and a sticky bit
 * rounds it as the double multiplication does (a product below the normal range rounds differently,
 * but stays far below 1/2). Shifting s to the binary point leaves floor(s), and the round bit adds
 * the 0.5. Rounding s + 0.5 to a double changes its floor only for s = 0.5 - 2^-54, whose sum rounds
 * up to 1.0: below 1/2 the sum lies in [1/2, 1), and from 1/2 to 2^52 it is a multiple of s's ulp
 * (at most 1/2), exact unless it just crossed a power of two, where it rounds to a neighbour with
 * the same integer part. */
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
        store_bits((uint8_t *)&sentence + ilahrs_pahr_fields[k].member, (uint32_t)scaled, ilahrs_pahr_fields[k].size);
    }
    *out = sentence;
    return true;
out_of_range:
    return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, SENTENCE_NAME(ilahrs_pahr_fields[k].name));
}

/* (double)n without floating-point code, for |n| < 2^53. */
static double int_double(int64_t n)
{
    int64_t key = int_key(n);
    uint64_t bits = key < 0 ? DOUBLE_SIGN | (0u - (uint64_t)key) : (uint64_t)key;
    double value;
    memcpy(&value, &bits, sizeof value);
    return value;
}

bool ilahrs_pahr_from_values(double roll, double pitch, double heading, double temperature, double vdd, uint16_t usw, ilahrs_pahr_t *out, ilahrs_error_t *err)
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
/* ---- Stream decoder ------------------------------------------------------------------- */


#define NEED_MORE (-1)
#define INVALID 0


/* The frame at p[0..n) (p[0] is the first header byte): its size if valid, INVALID, or
 * NEED_MORE bytes to decide. */
static inline int frame_candidate(const uint8_t *p, size_t n, ilahrs_message_t *msg)
{
    {
        uint32_t length;
        size_t total;
        size_t at;
        if (n < 2u) {
            return NEED_MORE;
        }
        if (p[1] != ILAHRS_FRAME_HEADER_1) {
            return INVALID;
        }
        if (n < ILAHRS_FRAME_PAYLOAD_OFFSET) {
            return NEED_MORE;
        }
        if (!message_type_valid(p[ILAHRS_FRAME_MESSAGE_TYPE_OFFSET])) {
            return INVALID;
        }
        length = get_le(p + ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, ILAHRS_FRAME_MESSAGE_LENGTH_SIZE);
        if (length < ILAHRS_FRAME_MIN_LENGTH || length > ILAHRS_FRAME_MAX_LENGTH) {
            return INVALID;
        }
        total = ILAHRS_FRAME_HEADER_SIZE + (size_t)length;
        if (n < total) {
            return NEED_MORE;
        }
        at = total - ILAHRS_FRAME_CHECKSUM_SIZE;
        if ((uint16_t)sum_bytes(p + ILAHRS_FRAME_HEADER_SIZE, at - ILAHRS_FRAME_HEADER_SIZE)
            != get_le(p + at, ILAHRS_FRAME_CHECKSUM_SIZE)) {
            return INVALID;
        }
        msg->kind = ILAHRS_MESSAGE_FRAME;
        msg->data = p;
        msg->size = total;
        msg->frame.message_type = (uint8_t)p[ILAHRS_FRAME_MESSAGE_TYPE_OFFSET];
        msg->frame.reserved = (uint8_t)p[ILAHRS_FRAME_RESERVED_OFFSET];
        msg->frame.payload = p + ILAHRS_FRAME_PAYLOAD_OFFSET;
        msg->frame.payload_size = at - ILAHRS_FRAME_PAYLOAD_OFFSET;
        return (int)total;
    }
}


#if ILAHRS_STREAM_SENTENCES
#if ILAHRS_OPTIMIZE_SIZE
/*
 * The sentence p[0..n) whose prefix matched, n its length through its first LF (n > the prefix
 * length), with its fields in *out: exactly what ilahrs_pahr_parse() accepts, decided without
 * naming the error.
 */
static bool pahr_valid(const uint8_t *p, size_t n, ilahrs_pahr_t *out)
{
    const uint8_t *star = p + n - PAHR_TAIL; /* within p: n > PAHR_PREFIX_LENGTH >= PAHR_TAIL */
    const pahr_field_t *f = ilahrs_pahr_fields;
    const uint8_t *q = p + PAHR_PREFIX_LENGTH;
    if (star < q || star[PAHR_TAIL - 2] != PAHR_CR || *star != PAHR_STAR
        || xor_bytes(p + 1, (size_t)(star - p) - 1) != digit_value(star[1]) * 16u + digit_value(star[2])) {
        return false;
    }
    for (;; q++, f++) {
        if (pahr_field(&q, star, f, out) != ILAHRS_OK) {
            return false;
        }
        if (f == &ilahrs_pahr_fields[ILAHRS_PAHR_FIELD_COUNT - 1] || q == star) {
            return f == &ilahrs_pahr_fields[ILAHRS_PAHR_FIELD_COUNT - 1] && q == star;
        }
    }
}

/* The sentence at p[0..n): as frame_candidate(). It runs to the first LF within the longest
 * sentence. */
static int sentence_candidate(const uint8_t *p, size_t n, ilahrs_message_t *msg)
{
    size_t i;
    for (i = 0; i < n && i < ILAHRS_PAHR_MAX_LENGTH; i++) {
        if (i < PAHR_PREFIX_LENGTH && p[i] != (uint8_t)PAHR_PREFIX[i]) {
            return INVALID;
        }
        if (p[i] == PAHR_LF) {
            if (!pahr_valid(p, i + 1, &msg->sentence)) {
                return INVALID;
            }
            msg->kind = ILAHRS_MESSAGE_SENTENCE;
            msg->data = p;
            msg->size = i + 1;
            return (int)(i + 1);
        }
    }
    return i == ILAHRS_PAHR_MAX_LENGTH ? INVALID : NEED_MORE;
}
#else
/* True if p[0..n) is the start of the sentence prefix. */
static bool pahr_prefix(const uint8_t *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        if (p[i] != (uint8_t)PAHR_PREFIX[i]) {
            return false;
        }
    }
    return true;
}

/* The sentence at p[0..n) (p[0] is "$"): as frame_candidate(). */
static int sentence_candidate(const uint8_t *p, size_t n, ilahrs_message_t *msg)
{
    {
        size_t limit = n < ILAHRS_PAHR_MAX_LENGTH ? n : ILAHRS_PAHR_MAX_LENGTH;
        const uint8_t *lf;
        size_t i;
        size_t at;
        size_t field;
#if !ILAHRS_OPTIMIZE_SIZE
        /* A sentence in the builders' layout needs no search for its LF: if the characters
         * before CR LF are a valid sentence, none of them is an LF. */
        if (n >= PAHR_CANONICAL_LENGTH && p[PAHR_CANONICAL_LENGTH - 1] == PAHR_LF && p[PAHR_CANONICAL_LENGTH - 2] == PAHR_CR
            && pahr_prefix(p, PAHR_PREFIX_LENGTH)
            && pahr_body(p, PAHR_CANONICAL_LENGTH, &msg->sentence, &at, &field) == ILAHRS_OK) {
            msg->kind = ILAHRS_MESSAGE_SENTENCE;
            msg->data = p;
            msg->size = PAHR_CANONICAL_LENGTH;
            return (int)PAHR_CANONICAL_LENGTH;
        }
#endif
        lf = (const uint8_t *)memchr(p, PAHR_LF, limit);
        if (lf == NULL) {
            if (n >= ILAHRS_PAHR_MAX_LENGTH) {
                return INVALID;
            }
            /* Reject now what can never become a sentence: a wrong identifier, or a byte that
             * is not printable (CR only as the last byte so far). Waiting gives the same answer. */
            if (!pahr_prefix(p, n < PAHR_PREFIX_LENGTH ? n : PAHR_PREFIX_LENGTH)) {
                return INVALID;
            }
            for (i = PAHR_PREFIX_LENGTH; i < n; i++) {
                if ((p[i] < 0x20 || p[i] > 0x7E) && !(p[i] == PAHR_CR && i == n - 1)) {
                    return INVALID;
                }
            }
            return NEED_MORE;
        }
        /* The first LF ends the candidate, so the only CR LF it can hold is its last two
         * characters: what ilahrs_pahr_parse() checks before pahr_body(). */
        i = (size_t)(lf - p) + 1;
        if (i < PAHR_PREFIX_LENGTH + 2 || !pahr_prefix(p, PAHR_PREFIX_LENGTH) || p[i - 2] != PAHR_CR
            || pahr_body(p, i, &msg->sentence, &at, &field) != ILAHRS_OK) {
            return INVALID;
        }
        msg->kind = ILAHRS_MESSAGE_SENTENCE;
        msg->data = p;
        msg->size = i;
        return (int)i;
    }
}
#endif
#endif

#if !ILAHRS_OPTIMIZE_SIZE
static bool may_start(uint8_t byte)
{
#if ILAHRS_STREAM_SENTENCES
    if (byte == PAHR_START) {
        return true;
    }
#endif
    return byte == ILAHRS_FRAME_HEADER_0;
}
#endif

/* The message at p[0..n): its size if valid, INVALID, or NEED_MORE bytes to decide. */
static int candidate(const uint8_t *p, size_t n, ilahrs_message_t *msg)
{
    if (p[0] == ILAHRS_FRAME_HEADER_0) {
        return frame_candidate(p, n, msg);
    }
#if ILAHRS_STREAM_SENTENCES
    return sentence_candidate(p, n, msg);
#else
    return INVALID;
#endif
}

void ilahrs_stream_init(ilahrs_stream_t *stream)
{
    stream->discarded = 0;
    stream->start = 0;
    stream->count = 0;
}

#if ILAHRS_OPTIMIZE_SIZE
/*
 * The smallest decoder: every byte goes through the held buffer, and the candidate at its front
 * is decided again after each byte. A message is handed out from the buffer; `start` marks its
 * end until the next call. Each round takes one byte of *data / *len, if any, then decides; so
 * ilahrs_stream_push() always takes its byte. (Taking a byte before deciding on the bytes held
 * after a message changes no answer: a decided candidate stays decided when bytes follow it.)
 * `final`: the input has ended, so a candidate that needs more bytes is discarded.
 */
static bool step(ilahrs_stream_t *s, const uint8_t **data, size_t *len, bool final, ilahrs_message_t *msg)
{
    uint8_t *h = s->held;
    size_t count = s->count;
    copy_forward(h, h + s->start, count);
    s->start = 0;
    for (;;) {
        bool took = *len != 0;
        if (took) {
            /* In bounds: a candidate that waits is shorter than the longest message, and the
             * bytes held after a message are fewer still. */
            h[count++] = **data;
            (*data)++;
            (*len)--;
        }
        while (count != 0) {
            int r = candidate(h, count, msg);
            if (r > 0) {
                s->start = (uint8_t)r;
                s->count = (uint8_t)(count - (size_t)r);
                return true;
            }
            if (r == NEED_MORE && !final) {
                break;
            }
            s->discarded++;
            count--;
            copy_forward(h, h + 1, count);
        }
        if (!took) {
            s->count = (uint8_t)count;
            return false;
        }
    }
}

bool ilahrs_stream_next(ilahrs_stream_t *s, const uint8_t **data, size_t *len, ilahrs_message_t *msg)
{
    return step(s, data, len, false, msg);
}

bool ilahrs_stream_push(ilahrs_stream_t *s, uint8_t byte, ilahrs_message_t *msg)
{
    const uint8_t *p = &byte;
    size_t one = 1;
    return step(s, &p, &one, false, msg);
}

bool ilahrs_stream_poll(ilahrs_stream_t *s, ilahrs_message_t *msg)
{
    size_t none = 0;
    return step(s, NULL, &none, false, msg);
}

bool ilahrs_stream_finish(ilahrs_stream_t *s, ilahrs_message_t *msg)
{
    size_t none = 0;
    return step(s, NULL, &none, true, msg);
}
#else
/*
 * With start 0 and bytes held, the candidate at held[0] was examined and waits for more bytes
 * (after a message, start is its end until the next call). True if `byte` cannot decide it: a
 * frame still short of its length, or a sentence still without LF within the longest sentence.
 */
static bool still_waiting(const ilahrs_stream_t *s, uint8_t byte)
{
    size_t n = s->count;
    const uint8_t *h = s->held;
    if (h[0] == ILAHRS_FRAME_HEADER_0) {
        return n >= ILAHRS_FRAME_PAYLOAD_OFFSET
            && n + 1 < ILAHRS_FRAME_HEADER_SIZE + get_le(h + ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, ILAHRS_FRAME_MESSAGE_LENGTH_SIZE);
    }
    return n >= PAHR_PREFIX_LENGTH && n + 1 < ILAHRS_PAHR_MAX_LENGTH && byte != PAHR_LF;
}

/*
 * Decide on the held bytes, topping them up from the input. True with a message; false when
 * the held bytes are gone (input may remain) or wait for more input (all input taken).
 * `final`: the input has ended, so a candidate that needs more bytes is discarded.
 */
static bool drain(ilahrs_stream_t *s, const uint8_t **data, size_t *len, bool final, ilahrs_message_t *msg)
{
    uint8_t *buf = s->held;
    size_t count;
    size_t pos = 0;
    size_t taken = 0; /* input bytes taken in this call */
    size_t fresh = 0; /* input bytes in buf, always its last ones (when fewer remain, `rest` bounds them) */
    if (s->start != 0) {
        copy_forward(buf, buf + s->start, s->count);
        s->start = 0;
    }
    count = s->count;
    for (;;) {
        size_t add = *len - taken;
        if (add > sizeof s->held - count) {
            add = sizeof s->held - count;
        }
        if (add > 0) {
            copy_forward(buf + count, *data + taken, add);
            count += add;
            taken += add;
            fresh += add;
        }
        while (pos < count) {
            int r;
            if (!may_start(buf[pos])) {
                pos++;
                s->discarded++;
                continue;
            }
            r = candidate(buf + pos, count - pos, msg);
            if (r > 0) {
                size_t rest = count - pos - (size_t)r;
                size_t back = rest < fresh ? rest : fresh;
                taken -= back;
                s->start = (uint8_t)(pos + (size_t)r);
                s->count = (uint8_t)(rest - back);
                if (taken > 0) {
                    *data += taken;
                    *len -= taken;
                }
                return true;
            }
            if (r == NEED_MORE && !final && !(pos == 0 && count == sizeof s->held)) {
                break;
            }
            pos++;
            s->discarded++;
        }
        if (pos == count || taken == *len) {
            /* Held bytes gone, or all input taken: keep what waits, return the rest. */
            copy_forward(buf, buf + pos, count - pos);
            s->start = 0;
            s->count = (uint8_t)(count - pos);
            if (taken > 0) {
                *data += taken;
                *len -= taken;
            }
            return false;
        }
        /* The buffer is full and the candidate at pos waits: make room, take more input. */
        copy_forward(buf, buf + pos, count - pos);
        count -= pos;
        pos = 0;
    }
}

bool ilahrs_stream_next(ilahrs_stream_t *s, const uint8_t **data, size_t *len, ilahrs_message_t *msg)
{
    const uint8_t *p;
    size_t n;
    size_t i = 0;
    if (s->count != 0 && drain(s, data, len, false, msg)) {
        return true;
    }
    p = *data;
    n = *len;
    if (s->count != 0 || n == 0) {
        return false;
    }
    while (i < n) {
        size_t j = i;
        int r;
        while (j < n && !may_start(p[j])) {
            j++;
        }
        s->discarded += j - i;
        if (j == n) {
            break;
        }
        r = candidate(p + j, n - j, msg);
        if (r > 0) {
            *data = p + j + (size_t)r;
            *len = n - j - (size_t)r;
            return true;
        }
        if (r == NEED_MORE) {
            /* The rest of the chunk is the start of a message: keep it (n - j < held size). */
            memcpy(s->held, p + j, n - j);
            s->start = 0;
            s->count = (uint8_t)(n - j);
            break;
        }
        s->discarded++;
        i = j + 1;
    }
    *data = p + n;
    *len = 0;
    return false;
}
bool ilahrs_stream_push(ilahrs_stream_t *s, uint8_t byte, ilahrs_message_t *msg)
{
    size_t none = 0;
    const uint8_t *nothing = &byte;
    if (s->count == 0) {
        if (!may_start(byte)) {
            s->discarded++;
            return false;
        }
        s->start = 0;
    } else if (s->start != 0) {
        copy_forward(s->held, s->held + s->start, s->count);
        s->start = 0;
    } else if (still_waiting(s, byte)) {
        s->held[s->count++] = byte;
        return false;
    }
    s->held[s->count] = byte;
    s->count++;
    return drain(s, &nothing, &none, false, msg);
}

bool ilahrs_stream_poll(ilahrs_stream_t *s, ilahrs_message_t *msg)
{
    static const uint8_t empty[1] = { 0 };
    size_t none = 0;
    const uint8_t *nothing = empty;
    return s->count != 0 && drain(s, &nothing, &none, false, msg);
}

bool ilahrs_stream_finish(ilahrs_stream_t *s, ilahrs_message_t *msg)
{
    static const uint8_t empty[1] = { 0 };
    size_t none = 0;
    const uint8_t *nothing = empty;
    if (s->count != 0 && drain(s, &nothing, &none, true, msg)) {
        return true;
    }
    s->start = 0;
    s->count = 0;
    return false;
}
#endif


/* ---- Device state machine (6.1, 6.3, 6.4) --------------------------------------- */

/* States, one array per column: mode, the parameter block awaited (payload, -1: none), the
 * event its timer fires (ILAHRS_EVENT_COUNT: none). */
static const uint8_t ilahrs_state_modes[ILAHRS_STATE_COUNT] = {
    ILAHRS_MODE_IDLE, /* idle */
    ILAHRS_MODE_IDLE, /* awaiting_parameters */
    ILAHRS_MODE_CONTINUOUS, /* aligning_continuous */
    ILAHRS_MODE_CONTINUOUS, /* continuous */
    ILAHRS_MODE_ON_REQUEST, /* aligning_on_request */
    ILAHRS_MODE_ON_REQUEST, /* on_request */
    ILAHRS_MODE_SLEEP, /* sleep */
    ILAHRS_MODE_CALIBRATION, /* calibration_awaiting_parameters */
    ILAHRS_MODE_CALIBRATION, /* calibration_aligning */
    ILAHRS_MODE_CALIBRATION, /* calibration_accumulating */
    ILAHRS_MODE_CALIBRATION, /* calibration_deciding */
    ILAHRS_MODE_CALIBRATION, /* runs_awaiting_parameters */
    ILAHRS_MODE_CALIBRATION, /* runs_ready */
    ILAHRS_MODE_CALIBRATION, /* run_awaiting_parameters */
    ILAHRS_MODE_CALIBRATION, /* run_aligning */
    ILAHRS_MODE_CALIBRATION, /* run_accumulating */
};

static const int8_t ilahrs_state_blocks[ILAHRS_STATE_COUNT] = {
ILAHRS_PAYLOAD_NONE, /* idle */
ILAHRS_PAYLOAD_AHRS_PARAMETERS_LOAD, /* awaiting_parameters */
ILAHRS_PAYLOAD_NONE, /* aligning_continuous */
ILAHRS_PAYLOAD_NONE, /* continuous */
ILAHRS_PAYLOAD_NONE, /* aligning_on_request */
ILAHRS_PAYLOAD_NONE, /* on_request */
ILAHRS_PAYLOAD_NONE, /* sleep */
ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, /* calibration_awaiting_parameters */
ILAHRS_PAYLOAD_NONE, /* calibration_aligning */
ILAHRS_PAYLOAD_NONE, /* calibration_accumulating */
ILAHRS_PAYLOAD_NONE, /* calibration_deciding */
ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, /* runs_awaiting_parameters */
ILAHRS_PAYLOAD_NONE, /* runs_ready */
ILAHRS_PAYLOAD_CALIBRATION_RUN_PARAMETERS, /* run_awaiting_parameters */
ILAHRS_PAYLOAD_NONE, /* run_aligning */
ILAHRS_PAYLOAD_NONE, /* run_accumulating */
};

static const uint8_t ilahrs_state_timers[ILAHRS_STATE_COUNT] = {
ILAHRS_EVENT_COUNT, /* idle */
ILAHRS_EVENT_COUNT, /* awaiting_parameters */
ILAHRS_EVENT_ALIGNMENT_DONE, /* aligning_continuous */
ILAHRS_EVENT_OUTPUT_DUE, /* continuous */
ILAHRS_EVENT_ALIGNMENT_DONE, /* aligning_on_request */
ILAHRS_EVENT_COUNT, /* on_request */
ILAHRS_EVENT_COUNT, /* sleep */
ILAHRS_EVENT_COUNT, /* calibration_awaiting_parameters */
ILAHRS_EVENT_ALIGNMENT_DONE, /* calibration_aligning */
ILAHRS_EVENT_ACCUMULATION_DONE, /* calibration_accumulating */
ILAHRS_EVENT_COUNT, /* calibration_deciding */
ILAHRS_EVENT_COUNT, /* runs_awaiting_parameters */
ILAHRS_EVENT_COUNT, /* runs_ready */
ILAHRS_EVENT_COUNT, /* run_awaiting_parameters */
ILAHRS_EVENT_ALIGNMENT_DONE, /* run_aligning */
ILAHRS_EVENT_ACCUMULATION_DONE, /* run_accumulating */
};

/* Answers: payload table (-1: none), USW mode of an output answer (NO_USW_MODE: none). */
#define NO_USW_MODE 0xFFu
static const struct {
    int8_t payload;
    uint8_t usw_mode;
} ilahrs_answers[ILAHRS_ANSWER_COUNT] = {
    { ILAHRS_PAYLOAD_NONE, NO_USW_MODE }, /* ack */
    { ILAHRS_PAYLOAD_AHRS_PARAMETERS_READ, NO_USW_MODE }, /* ahrs_parameters_read */
    { ILAHRS_PAYLOAD_FIRMWARE_VERSION, NO_USW_MODE }, /* firmware_version */
    { ILAHRS_PAYLOAD_BIT_RESULT, NO_USW_MODE }, /* bit_result */
    { ILAHRS_PAYLOAD_CALIBRATION_STATUS, NO_USW_MODE }, /* calibration_status */
    { ILAHRS_PAYLOAD_INITIAL_ALIGNMENT, NO_USW_MODE }, /* initial_alignment */
    { ILAHRS_PAYLOAD_NONE, NO_USW_MODE }, /* output */
    { ILAHRS_PAYLOAD_NONE, ILAHRS_USW_MODE_SLEEP }, /* output_sleep */
    { ILAHRS_PAYLOAD_CALIBRATION_RESULT, NO_USW_MODE }, /* calibration_result */
    { ILAHRS_PAYLOAD_CALIBRATION_RUN_RESULT, NO_USW_MODE }, /* calibration_run_result */
};

/* Answer sequences, one after the other; sequence k is ilahrs_sends[ilahrs_send_start[k] ..
 * ilahrs_send_start[k + 1]). */
static const uint8_t ilahrs_sends[10] = { ILAHRS_ANSWER_ACK, ILAHRS_ANSWER_AHRS_PARAMETERS_READ, ILAHRS_ANSWER_FIRMWARE_VERSION, ILAHRS_ANSWER_BIT_RESULT, ILAHRS_ANSWER_CALIBRATION_STATUS, ILAHRS_ANSWER_INITIAL_ALIGNMENT, ILAHRS_ANSWER_OUTPUT, ILAHRS_ANSWER_OUTPUT_SLEEP, ILAHRS_ANSWER_CALIBRATION_RESULT, ILAHRS_ANSWER_CALIBRATION_RUN_RESULT };
static const uint8_t ilahrs_send_start[12] = { 0, 1, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 };

/* The distinct outcomes of the table: next state << SEQUENCE_BITS | answer sequence. */
#define SEQUENCE_BITS 4u
static const uint8_t ilahrs_outcomes[27] = {
    (ILAHRS_STATE_ALIGNING_CONTINUOUS << SEQUENCE_BITS) | 0u, /* 1: aligning_continuous, 0 */
    (ILAHRS_STATE_ALIGNING_ON_REQUEST << SEQUENCE_BITS) | 0u, /* 2: aligning_on_request, 0 */
    (ILAHRS_STATE_AWAITING_PARAMETERS << SEQUENCE_BITS) | 1u, /* 3: awaiting_parameters, nothing */
    (ILAHRS_STATE_IDLE << SEQUENCE_BITS) | 2u, /* 4: idle, 1 */
    (ILAHRS_STATE_IDLE << SEQUENCE_BITS) | 3u, /* 5: idle, 2 */
    (ILAHRS_STATE_IDLE << SEQUENCE_BITS) | 4u, /* 6: idle, 3 */
    (ILAHRS_STATE_ON_REQUEST << SEQUENCE_BITS) | 4u, /* 7: on_request, 3 */
    (ILAHRS_STATE_SLEEP << SEQUENCE_BITS) | 1u, /* 8: sleep, nothing */
    (ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS << SEQUENCE_BITS) | 1u, /* 9: calibration_awaiting_parameters, nothing */
    (ILAHRS_STATE_RUNS_AWAITING_PARAMETERS << SEQUENCE_BITS) | 1u, /* 10: runs_awaiting_parameters, nothing */
    (ILAHRS_STATE_IDLE << SEQUENCE_BITS) | 0u, /* 11: idle, 0 */
    (ILAHRS_STATE_IDLE << SEQUENCE_BITS) | 5u, /* 12: idle, 4 */
    (ILAHRS_STATE_IDLE << SEQUENCE_BITS) | 1u, /* 13: idle, nothing */
    (ILAHRS_STATE_RUNS_READY << SEQUENCE_BITS) | 1u, /* 14: runs_ready, nothing */
    (ILAHRS_STATE_CONTINUOUS << SEQUENCE_BITS) | 6u, /* 15: continuous, 5 */
    (ILAHRS_STATE_ON_REQUEST << SEQUENCE_BITS) | 6u, /* 16: on_request, 5 */
    (ILAHRS_STATE_CONTINUOUS << SEQUENCE_BITS) | 7u, /* 17: continuous, 6 */
    (ILAHRS_STATE_ON_REQUEST << SEQUENCE_BITS) | 7u, /* 18: on_request, 6 */
    (ILAHRS_STATE_SLEEP << SEQUENCE_BITS) | 8u, /* 19: sleep, 7 */
    (ILAHRS_STATE_CALIBRATION_ALIGNING << SEQUENCE_BITS) | 0u, /* 20: calibration_aligning, 0 */
    (ILAHRS_STATE_CALIBRATION_ACCUMULATING << SEQUENCE_BITS) | 6u, /* 21: calibration_accumulating, 5 */
    (ILAHRS_STATE_CALIBRATION_DECIDING << SEQUENCE_BITS) | 9u, /* 22: calibration_deciding, 8 */
    (ILAHRS_STATE_RUNS_READY << SEQUENCE_BITS) | 0u, /* 23: runs_ready, 0 */
    (ILAHRS_STATE_RUN_AWAITING_PARAMETERS << SEQUENCE_BITS) | 1u, /* 24: run_awaiting_parameters, nothing */
    (ILAHRS_STATE_RUN_ALIGNING << SEQUENCE_BITS) | 0u, /* 25: run_aligning, 0 */
    (ILAHRS_STATE_RUN_ACCUMULATING << SEQUENCE_BITS) | 6u, /* 26: run_accumulating, 5 */
    (ILAHRS_STATE_RUNS_READY << SEQUENCE_BITS) | 10u, /* 27: runs_ready, 9 */
};

/* The table: state x event -> outcome + 1, 0 for an ignored event (E33). Most events do the same
 * in a state, so each state has a default cell, and ilahrs_cells lists the cells that differ from
 * their state's default, by state and event: (state * ILAHRS_EVENT_COUNT + event) << CELL_BITS |
 * cell. Events are the commands in ilahrs_command_t order, then parameter_block, other_message, unknown, block_timeout, alignment_done, accumulation_done, output_due. */
#define CELL_BITS 5u
#define CELL_COUNT 65u
static const uint8_t ilahrs_state_cells[ILAHRS_STATE_COUNT] = { 0, 13, 0, 0, 0, 0, 0, 13, 0, 0, 0, 13, 0, 14, 0, 0 };

static const uint16_t ilahrs_cells[65] = {
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 0u) << CELL_BITS) | 1u, /* idle, AHRScont1 */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 1u) << CELL_BITS) | 1u, /* idle, AHRScont2 */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 2u) << CELL_BITS) | 1u, /* idle, AHRScont3 */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 3u) << CELL_BITS) | 2u, /* idle, AHRSreq1 */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 4u) << CELL_BITS) | 2u, /* idle, AHRSreq2 */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 5u) << CELL_BITS) | 2u, /* idle, AHRSreq3 */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 6u) << CELL_BITS) | 1u, /* idle, NMEAcont */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 7u) << CELL_BITS) | 2u, /* idle, NMEAreq */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 9u) << CELL_BITS) | 13u, /* idle, Stop */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 10u) << CELL_BITS) | 3u, /* idle, LoadAHRSPar */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 11u) << CELL_BITS) | 4u, /* idle, ReadAHRSPar */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 12u) << CELL_BITS) | 8u, /* idle, LowPowerOn */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 14u) << CELL_BITS) | 5u, /* idle, GetVerFirmware */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 15u) << CELL_BITS) | 6u, /* idle, GetBIT */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 16u) << CELL_BITS) | 9u, /* idle, Start2DClb */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 17u) << CELL_BITS) | 10u, /* idle, Start2D2TClb */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 18u) << CELL_BITS) | 9u, /* idle, Start3DClb */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 24u) << CELL_BITS) | 11u, /* idle, ClearClb */
    (((ILAHRS_STATE_IDLE * ILAHRS_EVENT_COUNT) + 25u) << CELL_BITS) | 12u, /* idle, GetClbRes */
    (((ILAHRS_STATE_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 26u) << CELL_BITS) | 11u, /* awaiting_parameters, parameter_block */
    (((ILAHRS_STATE_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 30u) << CELL_BITS) | 0u, /* awaiting_parameters, alignment_done */
    (((ILAHRS_STATE_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 31u) << CELL_BITS) | 0u, /* awaiting_parameters, accumulation_done */
    (((ILAHRS_STATE_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 32u) << CELL_BITS) | 0u, /* awaiting_parameters, output_due */
    (((ILAHRS_STATE_ALIGNING_CONTINUOUS * ILAHRS_EVENT_COUNT) + 9u) << CELL_BITS) | 13u, /* aligning_continuous, Stop */
    (((ILAHRS_STATE_ALIGNING_CONTINUOUS * ILAHRS_EVENT_COUNT) + 30u) << CELL_BITS) | 15u, /* aligning_continuous, alignment_done */
    (((ILAHRS_STATE_CONTINUOUS * ILAHRS_EVENT_COUNT) + 9u) << CELL_BITS) | 13u, /* continuous, Stop */
    (((ILAHRS_STATE_CONTINUOUS * ILAHRS_EVENT_COUNT) + 12u) << CELL_BITS) | 19u, /* continuous, LowPowerOn */
    (((ILAHRS_STATE_CONTINUOUS * ILAHRS_EVENT_COUNT) + 32u) << CELL_BITS) | 17u, /* continuous, output_due */
    (((ILAHRS_STATE_ALIGNING_ON_REQUEST * ILAHRS_EVENT_COUNT) + 9u) << CELL_BITS) | 13u, /* aligning_on_request, Stop */
    (((ILAHRS_STATE_ALIGNING_ON_REQUEST * ILAHRS_EVENT_COUNT) + 30u) << CELL_BITS) | 16u, /* aligning_on_request, alignment_done */
    (((ILAHRS_STATE_ON_REQUEST * ILAHRS_EVENT_COUNT) + 8u) << CELL_BITS) | 18u, /* on_request, GetDataReq */
    (((ILAHRS_STATE_ON_REQUEST * ILAHRS_EVENT_COUNT) + 9u) << CELL_BITS) | 13u, /* on_request, Stop */
    (((ILAHRS_STATE_ON_REQUEST * ILAHRS_EVENT_COUNT) + 12u) << CELL_BITS) | 8u, /* on_request, LowPowerOn */
    (((ILAHRS_STATE_ON_REQUEST * ILAHRS_EVENT_COUNT) + 15u) << CELL_BITS) | 7u, /* on_request, GetBIT */
    (((ILAHRS_STATE_SLEEP * ILAHRS_EVENT_COUNT) + 13u) << CELL_BITS) | 13u, /* sleep, LowPowerOff */
    (((ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 23u) << CELL_BITS) | 11u, /* calibration_awaiting_parameters, ExitClb */
    (((ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 26u) << CELL_BITS) | 20u, /* calibration_awaiting_parameters, parameter_block */
    (((ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 30u) << CELL_BITS) | 0u, /* calibration_awaiting_parameters, alignment_done */
    (((ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 31u) << CELL_BITS) | 0u, /* calibration_awaiting_parameters, accumulation_done */
    (((ILAHRS_STATE_CALIBRATION_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 32u) << CELL_BITS) | 0u, /* calibration_awaiting_parameters, output_due */
    (((ILAHRS_STATE_CALIBRATION_ALIGNING * ILAHRS_EVENT_COUNT) + 23u) << CELL_BITS) | 11u, /* calibration_aligning, ExitClb */
    (((ILAHRS_STATE_CALIBRATION_ALIGNING * ILAHRS_EVENT_COUNT) + 30u) << CELL_BITS) | 21u, /* calibration_aligning, alignment_done */
    (((ILAHRS_STATE_CALIBRATION_ACCUMULATING * ILAHRS_EVENT_COUNT) + 20u) << CELL_BITS) | 22u, /* calibration_accumulating, StopClbRun */
    (((ILAHRS_STATE_CALIBRATION_ACCUMULATING * ILAHRS_EVENT_COUNT) + 23u) << CELL_BITS) | 11u, /* calibration_accumulating, ExitClb */
    (((ILAHRS_STATE_CALIBRATION_ACCUMULATING * ILAHRS_EVENT_COUNT) + 31u) << CELL_BITS) | 22u, /* calibration_accumulating, accumulation_done */
    (((ILAHRS_STATE_CALIBRATION_DECIDING * ILAHRS_EVENT_COUNT) + 22u) << CELL_BITS) | 11u, /* calibration_deciding, AcceptClb */
    (((ILAHRS_STATE_CALIBRATION_DECIDING * ILAHRS_EVENT_COUNT) + 23u) << CELL_BITS) | 11u, /* calibration_deciding, ExitClb */
    (((ILAHRS_STATE_RUNS_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 23u) << CELL_BITS) | 11u, /* runs_awaiting_parameters, ExitClb */
    (((ILAHRS_STATE_RUNS_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 26u) << CELL_BITS) | 23u, /* runs_awaiting_parameters, parameter_block */
    (((ILAHRS_STATE_RUNS_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 30u) << CELL_BITS) | 0u, /* runs_awaiting_parameters, alignment_done */
    (((ILAHRS_STATE_RUNS_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 31u) << CELL_BITS) | 0u, /* runs_awaiting_parameters, accumulation_done */
    (((ILAHRS_STATE_RUNS_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 32u) << CELL_BITS) | 0u, /* runs_awaiting_parameters, output_due */
    (((ILAHRS_STATE_RUNS_READY * ILAHRS_EVENT_COUNT) + 19u) << CELL_BITS) | 24u, /* runs_ready, StartClbRun */
    (((ILAHRS_STATE_RUNS_READY * ILAHRS_EVENT_COUNT) + 21u) << CELL_BITS) | 22u, /* runs_ready, FinishClb */
    (((ILAHRS_STATE_RUNS_READY * ILAHRS_EVENT_COUNT) + 23u) << CELL_BITS) | 11u, /* runs_ready, ExitClb */
    (((ILAHRS_STATE_RUN_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 23u) << CELL_BITS) | 11u, /* run_awaiting_parameters, ExitClb */
    (((ILAHRS_STATE_RUN_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 26u) << CELL_BITS) | 25u, /* run_awaiting_parameters, parameter_block */
    (((ILAHRS_STATE_RUN_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 30u) << CELL_BITS) | 0u, /* run_awaiting_parameters, alignment_done */
    (((ILAHRS_STATE_RUN_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 31u) << CELL_BITS) | 0u, /* run_awaiting_parameters, accumulation_done */
    (((ILAHRS_STATE_RUN_AWAITING_PARAMETERS * ILAHRS_EVENT_COUNT) + 32u) << CELL_BITS) | 0u, /* run_awaiting_parameters, output_due */
    (((ILAHRS_STATE_RUN_ALIGNING * ILAHRS_EVENT_COUNT) + 23u) << CELL_BITS) | 11u, /* run_aligning, ExitClb */
    (((ILAHRS_STATE_RUN_ALIGNING * ILAHRS_EVENT_COUNT) + 30u) << CELL_BITS) | 26u, /* run_aligning, alignment_done */
    (((ILAHRS_STATE_RUN_ACCUMULATING * ILAHRS_EVENT_COUNT) + 20u) << CELL_BITS) | 27u, /* run_accumulating, StopClbRun */
    (((ILAHRS_STATE_RUN_ACCUMULATING * ILAHRS_EVENT_COUNT) + 23u) << CELL_BITS) | 11u, /* run_accumulating, ExitClb */
    (((ILAHRS_STATE_RUN_ACCUMULATING * ILAHRS_EVENT_COUNT) + 31u) << CELL_BITS) | 27u, /* run_accumulating, accumulation_done */
};

/* Rows that apply only to firmware before a version, and there take precedence. */
#define LEGACY_COUNT 1u
static const ilahrs_firmware_t ilahrs_legacy_versions[1] = {
    { { 4u, 9u, 9u, 0u }, 4 }, /* 4.9.9.0 */
};

static const struct {
    uint8_t state;
    uint8_t event;
    uint8_t outcome;
    uint8_t version;
} ilahrs_legacy[LEGACY_COUNT] = {
    { ILAHRS_STATE_RUNS_READY, ILAHRS_EVENT_STOP_CLB_RUN, 21, 0 }, /* E29 */
};

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

#if ILAHRS_NAMES
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

ilahrs_payload_t ilahrs_answer_payload(ilahrs_answer_t answer)
{
    return (unsigned)answer < ILAHRS_ANSWER_COUNT ? (ilahrs_payload_t)ilahrs_answers[answer].payload : ILAHRS_PAYLOAD_NONE;
}

bool ilahrs_answer_usw_mode(ilahrs_answer_t answer, ilahrs_usw_mode_t *mode)
{
    if ((unsigned)answer >= ILAHRS_ANSWER_COUNT || ilahrs_answers[answer].usw_mode == NO_USW_MODE) {
        return false;
    }
    *mode = (ilahrs_usw_mode_t)ilahrs_answers[answer].usw_mode;
    return true;
}

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
    return expects != ILAHRS_PAYLOAD_NONE && payload_size == ilahrs_payloads[expects].size ? ILAHRS_EVENT_PARAMETER_BLOCK
                                                                                            : ILAHRS_EVENT_OTHER_MESSAGE;
}

ilahrs_event_t ilahrs_event_for_frame(ilahrs_state_t state, const ilahrs_frame_t *frame)
{
    if (frame->message_type == ILAHRS_MESSAGE_TYPE_COMMAND && frame->payload_size == 1) {
        return ilahrs_event_for_code(state, frame->payload[0]);
    }
    return ilahrs_event_for_data(state, frame->payload_size);
}

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

/* The legacy row for (state, event) that applies to `firmware` (NULL with `any`: every legacy
 * row applies), or -1. */
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
        if (firmware != NULL && ilahrs_firmware_compare(firmware, &ilahrs_legacy_versions[ilahrs_legacy[i].version]) < 0) {
            return (int)i;
        }
    }
    return -1;
}

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
    return transition(state, event, older_firmware ? legacy_row((unsigned)state, (unsigned)event, NULL, true) : -1, out);
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
