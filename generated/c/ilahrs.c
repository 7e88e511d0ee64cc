/* Generated from spec/ilahrs.yaml, spec hash b29217e2acd36b99c3446f15c5c54dd170e9aaaecfe9535ae7c08a1ac85716ef.
 * Do not edit: change the spec or the generator and run `make generate`.
 */
/*
 * The library is table-driven where that keeps it small: one payload codec walks the field
 * table below, one sentence codec walks the $PAHR field table, and every name is stored once
 * in one string pool. All tables are const; nothing here is mutable after start-up.
 */
#include "ilahrs.h"

#include <string.h>

/* ---- Tables --------------------------------------------------------------------------- */

/* Every name the library hands out, NUL-separated; tables hold offsets into it. */
static const char ilahrs_strings[] =
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
    "header\000"
    "payload\000"
    "message_type\000"
    "reserved\000"
    "message_length\000"
    "checksum\000"
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
    "g300_a2_tmga\000"
    "AHRS-G300-A2-TMGA-C1-V1.1\000"
    "g300_a6_tmga\000"
    "AHRS-G300-A6-TMGA-C1-V1.1\000"
    "sn_11ac0001_0009\000"
    "AHRS s/n 11AC0001 - 11AC0009\000"
    "g300_a2_tga\000"
    "AHRS-G300-A2-TGA-C1-V1.1\000"
    "idle\000"
    "continuous\000"
    "on_request\000"
    "calibration\000"
    "sleep\000"
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
    "roll\000"
    "pitch\000"
    "heading\000"
    "temperature\000"
    "vdd\000"
    "usw\000"
    "date\000"
    "full_output\000"
    "ugyro_x\000"
    "ugyro_y\000"
    "ugyro_z\000"
    "uacc_x\000"
    "uacc_y\000"
    "uacc_z\000"
    "umag_x\000"
    "umag_y\000"
    "umag_z\000"
    "utermo\000"
    "quaternion\000"
    "lk0\000"
    "lk1\000"
    "lk2\000"
    "lk3\000"
    "orientation_sensors\000"
    "gyro_x\000"
    "gyro_y\000"
    "gyro_z\000"
    "acc_x\000"
    "acc_y\000"
    "acc_z\000"
    "mag_x\000"
    "mag_y\000"
    "mag_z\000"
    "initial_alignment\000"
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
    "ahrs_parameters_load\000"
    "update_rate\000"
    "alignment_time\000"
    "declination\000"
    "latitude\000"
    "longitude\000"
    "altitude\000"
    "alignment_angle_a1\000"
    "alignment_angle_a2\000"
    "alignment_angle_a3\000"
    "ahrs_parameters_read\000"
    "device_id\000"
    "firmware_version\000"
    "version\000"
    "bit_result\000"
    "utermo100\000"
    "calibration_parameters\000"
    "reference_azimuth\000"
    "accumulation_time\000"
    "calibration_result\000"
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
    "calibration_run_result\000"
    "run\000"
    "reserved_1\000"
    "average_pitch\000"
    "average_roll\000"
    "reserved_2\000"
    "calibration_run_parameters\000"
    "calibration_status\000"
    "acknowledgement\000";

#define NAME(offset) (ilahrs_strings + (offset))
#define NAME_FRAME_MESSAGE_TYPE 166
#define NAME_FRAME_RESERVED 179
#define NAME_FRAME_MESSAGE_LENGTH 188
#define NAME_FRAME_HEADER 151
#define NAME_FRAME_PAYLOAD 158
#define NAME_FRAME_CHECKSUM 203
#define NAME_DATE 993

static const uint16_t ilahrs_error_names[] = {
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
};

/* Command table (Table C.1): name, code, modes it is valid in, response, parameter block. */
static const struct {
    uint16_t name;
    uint8_t code;
    uint8_t valid_in;
    uint8_t response;
    int8_t parameter_block;
    int8_t response_payloads[ILAHRS_RESPONSE_PAYLOADS_MAX];
} ilahrs_commands[ILAHRS_COMMAND_COUNT] = {
    { 212, 0x80, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_ACK, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* AHRScont1 */
    { 222, 0x82, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_ACK, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* AHRScont2 */
    { 232, 0x83, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_ACK, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* AHRScont3 */
    { 242, 0x84, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_ACK, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* AHRSreq1 */
    { 251, 0x86, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_ACK, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* AHRSreq2 */
    { 260, 0x87, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_ACK, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* AHRSreq3 */
    { 269, 0x88, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_ACK, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* NMEAcont */
    { 278, 0x89, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_ACK, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* NMEAreq */
    { 286, 0xCA, ILAHRS_MODE_BIT(ILAHRS_MODE_ON_REQUEST), ILAHRS_RESPONSE_OUTPUT, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* GetDataReq */
    { 297, 0xFE, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE) | ILAHRS_MODE_BIT(ILAHRS_MODE_CONTINUOUS) | ILAHRS_MODE_BIT(ILAHRS_MODE_ON_REQUEST), ILAHRS_RESPONSE_NONE, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* Stop */
    { 302, 0x40, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_NONE, ILAHRS_PAYLOAD_AHRS_PARAMETERS_LOAD, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* LoadAHRSPar */
    { 314, 0x41, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_DATA, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_AHRS_PARAMETERS_READ, ILAHRS_PAYLOAD_NONE } }, /* ReadAHRSPar */
    { 326, 0xB0, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE) | ILAHRS_MODE_BIT(ILAHRS_MODE_CONTINUOUS) | ILAHRS_MODE_BIT(ILAHRS_MODE_ON_REQUEST), ILAHRS_RESPONSE_NONE, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* LowPowerOn */
    { 337, 0xBA, ILAHRS_MODE_BIT(ILAHRS_MODE_SLEEP), ILAHRS_RESPONSE_NONE, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* LowPowerOff */
    { 349, 0x1F, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_DATA, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_FIRMWARE_VERSION, ILAHRS_PAYLOAD_NONE } }, /* GetVerFirmware */
    { 364, 0x1A, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE) | ILAHRS_MODE_BIT(ILAHRS_MODE_ON_REQUEST), ILAHRS_RESPONSE_DATA, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_BIT_RESULT, ILAHRS_PAYLOAD_NONE } }, /* GetBIT */
    { 371, 0x21, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_NONE, ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* Start2DClb */
    { 382, 0x22, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_NONE, ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* Start2D2TClb */
    { 395, 0x23, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_NONE, ILAHRS_PAYLOAD_CALIBRATION_PARAMETERS, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* Start3DClb */
    { 406, 0x2B, ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION), ILAHRS_RESPONSE_NONE, ILAHRS_PAYLOAD_CALIBRATION_RUN_PARAMETERS, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* StartClbRun */
    { 418, 0x20, ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION), ILAHRS_RESPONSE_DATA, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_CALIBRATION_RESULT, ILAHRS_PAYLOAD_CALIBRATION_RUN_RESULT } }, /* StopClbRun */
    { 429, 0x2C, ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION), ILAHRS_RESPONSE_DATA, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_CALIBRATION_RESULT, ILAHRS_PAYLOAD_NONE } }, /* FinishClb */
    { 439, 0x2E, ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION), ILAHRS_RESPONSE_ACK, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* AcceptClb */
    { 449, 0xFE, ILAHRS_MODE_BIT(ILAHRS_MODE_CALIBRATION), ILAHRS_RESPONSE_ACK, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* ExitClb */
    { 457, 0x2F, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_ACK, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_NONE, ILAHRS_PAYLOAD_NONE } }, /* ClearClb */
    { 466, 0x2A, ILAHRS_MODE_BIT(ILAHRS_MODE_IDLE), ILAHRS_RESPONSE_DATA, ILAHRS_PAYLOAD_NONE, { ILAHRS_PAYLOAD_CALIBRATION_STATUS, ILAHRS_PAYLOAD_NONE } }, /* GetClbRes */
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

/* Variant parameters (KG, KA) and names. */
static const int32_t ilahrs_variant_values[ILAHRS_VARIANT_COUNT][2] = {
    { 100, 10000 }, /* g300_a2_tmga */
    { 100, 5000 }, /* g300_a6_tmga */
    { 50, 10000 }, /* sn_11ac0001_0009 */
    { 100, 10000 }, /* g300_a2_tga */
};

static const uint16_t ilahrs_variant_names[ILAHRS_VARIANT_COUNT][2] = {
    { 476, 489 },
    { 515, 528 },
    { 554, 571 },
    { 600, 612 },
};

/* USW flags: bit and name. */
static const struct {
    uint8_t bit;
    uint16_t name;
} ilahrs_usw_flags[14] = {
    { 0, 682 },
    { 1, 707 },
    { 2, 728 },
    { 3, 741 },
    { 4, 763 },
    { 5, 784 },
    { 6, 804 },
    { 8, 821 },
    { 9, 840 },
    { 10, 860 },
    { 11, 876 },
    { 12, 892 },
    { 13, 908 },
    { 14, 929 },
};

/* Builder checks: inclusive bounds compared as double; row 0 means "the C type is the range". */
static const double ilahrs_bounds[18][2] = {
    { 0.0, 0.0 },
    { 0.0, 35999.0 },
    { -9000.0, 9000.0 },
    { -18000.0, 18000.0 },
    { -10000.0, 10000.0 },
    { -3.4028234663852886e+38, 3.4028234663852886e+38 },
    { 0.0, 360.0 },
    { -180.0, 180.0 },
    { -90.0, 90.0 },
    { 1.0, 100.0 },
    { 1.0, 65535.0 },
    { -20000.0, 100000.0 },
    { 1900.0, 2200.001598173516 },
    { -360.0, 360.0 },
    { 1.0, 3.0 },
    { 0.0, 100.0 },
    { 2.0, 2.0 },
    { 1.0, 255.0 },
};

/* Engineering scales: raw * multiplier / divisor; divisor 0 means the variant parameter. */
static const struct {
    int32_t multiplier;
    int32_t divisor;
    uint8_t parameter;
} ilahrs_scales[8] = {
    { 1, 1, 255 },
    { 1, 100, 255 },
    { 1, 1000, 255 },
    { 1, 10000, 255 },
    { 1, 10, 255 },
    { 1, 0, 0 },
    { 1, 0, 1 },
    { 10, 1, 255 },
};

enum { ENCODING_NONE = 0, ENCODING_DECLINATION = 1 };
#define NO_PARAMETER 255

/* Every payload field, table after table, in wire order. */
static const ilahrs_field_info_t ilahrs_fields[131] = {
    /* full_output (Table 6.4) */
    { 965, 0, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_full_output_t, heading), 1, 1, ENCODING_NONE }, /* heading */
    { 959, 2, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_full_output_t, pitch), 2, 1, ENCODING_NONE }, /* pitch */
    { 954, 4, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_full_output_t, roll), 3, 1, ENCODING_NONE }, /* roll */
    { 1010, 6, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_full_output_t, ugyro_x), 0, 0, ENCODING_NONE }, /* ugyro_x */
    { 1018, 8, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_full_output_t, ugyro_y), 0, 0, ENCODING_NONE }, /* ugyro_y */
    { 1026, 10, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_full_output_t, ugyro_z), 0, 0, ENCODING_NONE }, /* ugyro_z */
    { 1034, 12, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_full_output_t, uacc_x), 0, 0, ENCODING_NONE }, /* uacc_x */
    { 1041, 14, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_full_output_t, uacc_y), 0, 0, ENCODING_NONE }, /* uacc_y */
    { 1048, 16, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_full_output_t, uacc_z), 0, 0, ENCODING_NONE }, /* uacc_z */
    { 1055, 18, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_full_output_t, umag_x), 0, 0, ENCODING_NONE }, /* umag_x */
    { 1062, 20, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_full_output_t, umag_y), 0, 0, ENCODING_NONE }, /* umag_y */
    { 1069, 22, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_full_output_t, umag_z), 0, 0, ENCODING_NONE }, /* umag_z */
    { 179, 24, 4, ILAHRS_KIND_RESERVED, offsetof(ilahrs_full_output_t, reserved), 0, 0, ENCODING_NONE }, /* reserved */
    { 989, 28, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_full_output_t, usw), 0, 0, ENCODING_NONE }, /* usw */
    { 985, 30, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_full_output_t, vdd), 0, 2, ENCODING_NONE }, /* vdd */
    { 1076, 32, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_full_output_t, utermo), 0, 0, ENCODING_NONE }, /* utermo */
    /* quaternion (Table 6.5) */
    { 965, 0, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_quaternion_t, heading), 1, 1, ENCODING_NONE }, /* heading */
    { 959, 2, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_quaternion_t, pitch), 2, 1, ENCODING_NONE }, /* pitch */
    { 954, 4, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_quaternion_t, roll), 3, 1, ENCODING_NONE }, /* roll */
    { 1094, 6, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_quaternion_t, lk0), 4, 3, ENCODING_NONE }, /* lk0 */
    { 1098, 8, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_quaternion_t, lk1), 4, 3, ENCODING_NONE }, /* lk1 */
    { 1102, 10, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_quaternion_t, lk2), 4, 3, ENCODING_NONE }, /* lk2 */
    { 1106, 12, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_quaternion_t, lk3), 4, 3, ENCODING_NONE }, /* lk3 */
    { 179, 14, 14, ILAHRS_KIND_RESERVED, offsetof(ilahrs_quaternion_t, reserved), 0, 0, ENCODING_NONE }, /* reserved */
    { 989, 28, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_quaternion_t, usw), 0, 0, ENCODING_NONE }, /* usw */
    { 985, 30, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_quaternion_t, vdd), 0, 2, ENCODING_NONE }, /* vdd */
    { 1076, 32, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_quaternion_t, utermo), 0, 4, ENCODING_NONE }, /* utermo */
    /* orientation_sensors (Table 6.6) */
    { 965, 0, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_orientation_sensors_t, heading), 1, 1, ENCODING_NONE }, /* heading */
    { 959, 2, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_orientation_sensors_t, pitch), 2, 1, ENCODING_NONE }, /* pitch */
    { 954, 4, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_orientation_sensors_t, roll), 3, 1, ENCODING_NONE }, /* roll */
    { 1130, 6, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_orientation_sensors_t, gyro_x), 0, 5, ENCODING_NONE }, /* gyro_x */
    { 1137, 8, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_orientation_sensors_t, gyro_y), 0, 5, ENCODING_NONE }, /* gyro_y */
    { 1144, 10, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_orientation_sensors_t, gyro_z), 0, 5, ENCODING_NONE }, /* gyro_z */
    { 1151, 12, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_orientation_sensors_t, acc_x), 0, 6, ENCODING_NONE }, /* acc_x */
    { 1157, 14, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_orientation_sensors_t, acc_y), 0, 6, ENCODING_NONE }, /* acc_y */
    { 1163, 16, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_orientation_sensors_t, acc_z), 0, 6, ENCODING_NONE }, /* acc_z */
    { 1169, 18, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_orientation_sensors_t, mag_x), 0, 7, ENCODING_NONE }, /* mag_x */
    { 1175, 20, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_orientation_sensors_t, mag_y), 0, 7, ENCODING_NONE }, /* mag_y */
    { 1181, 22, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_orientation_sensors_t, mag_z), 0, 7, ENCODING_NONE }, /* mag_z */
    { 179, 24, 4, ILAHRS_KIND_RESERVED, offsetof(ilahrs_orientation_sensors_t, reserved), 0, 0, ENCODING_NONE }, /* reserved */
    { 989, 28, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_orientation_sensors_t, usw), 0, 0, ENCODING_NONE }, /* usw */
    { 985, 30, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_orientation_sensors_t, vdd), 0, 2, ENCODING_NONE }, /* vdd */
    { 1076, 32, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_orientation_sensors_t, utermo), 0, 4, ENCODING_NONE }, /* utermo */
    /* initial_alignment (Table 6.8) */
    { 1205, 0, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_initial_alignment_t, gyro_bias_x), 5, 0, ENCODING_NONE }, /* gyro_bias_x */
    { 1217, 4, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_initial_alignment_t, gyro_bias_y), 5, 0, ENCODING_NONE }, /* gyro_bias_y */
    { 1229, 8, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_initial_alignment_t, gyro_bias_z), 5, 0, ENCODING_NONE }, /* gyro_bias_z */
    { 1241, 12, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_initial_alignment_t, average_acc_x), 5, 0, ENCODING_NONE }, /* average_acc_x */
    { 1255, 16, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_initial_alignment_t, average_acc_y), 5, 0, ENCODING_NONE }, /* average_acc_y */
    { 1269, 20, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_initial_alignment_t, average_acc_z), 5, 0, ENCODING_NONE }, /* average_acc_z */
    { 1283, 24, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_initial_alignment_t, average_mag_x), 5, 0, ENCODING_NONE }, /* average_mag_x */
    { 1297, 28, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_initial_alignment_t, average_mag_y), 5, 0, ENCODING_NONE }, /* average_mag_y */
    { 1311, 32, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_initial_alignment_t, average_mag_z), 5, 0, ENCODING_NONE }, /* average_mag_z */
    { 1325, 36, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_initial_alignment_t, initial_heading), 6, 0, ENCODING_NONE }, /* initial_heading */
    { 1341, 40, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_initial_alignment_t, initial_roll), 7, 0, ENCODING_NONE }, /* initial_roll */
    { 1354, 44, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_initial_alignment_t, initial_pitch), 8, 0, ENCODING_NONE }, /* initial_pitch */
    { 989, 48, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_initial_alignment_t, usw), 0, 0, ENCODING_NONE }, /* usw */
    /* ahrs_parameters_load (Table 6.9) */
    { 1389, 0, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_ahrs_parameters_load_t, update_rate), 9, 0, ENCODING_NONE }, /* update_rate */
    { 1401, 2, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_ahrs_parameters_load_t, alignment_time), 10, 0, ENCODING_NONE }, /* alignment_time */
    { 1416, 4, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_load_t, declination), 5, 0, ENCODING_DECLINATION }, /* declination */
    { 1428, 8, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_load_t, latitude), 8, 0, ENCODING_NONE }, /* latitude */
    { 1437, 12, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_load_t, longitude), 7, 0, ENCODING_NONE }, /* longitude */
    { 1447, 16, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_load_t, altitude), 11, 0, ENCODING_NONE }, /* altitude */
    { 993, 20, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_load_t, date), 12, 0, ENCODING_NONE }, /* date */
    { 1456, 24, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_load_t, alignment_angle_a1), 13, 0, ENCODING_NONE }, /* alignment_angle_a1 */
    { 1475, 28, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_load_t, alignment_angle_a2), 13, 0, ENCODING_NONE }, /* alignment_angle_a2 */
    { 1494, 32, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_load_t, alignment_angle_a3), 13, 0, ENCODING_NONE }, /* alignment_angle_a3 */
    { 179, 36, 14, ILAHRS_KIND_RESERVED, offsetof(ilahrs_ahrs_parameters_load_t, reserved), 0, 0, ENCODING_NONE }, /* reserved */
    /* ahrs_parameters_read (Table 6.10) */
    { 1389, 0, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_ahrs_parameters_read_t, update_rate), 9, 0, ENCODING_NONE }, /* update_rate */
    { 1401, 2, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_ahrs_parameters_read_t, alignment_time), 10, 0, ENCODING_NONE }, /* alignment_time */
    { 1416, 4, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_read_t, declination), 5, 0, ENCODING_DECLINATION }, /* declination */
    { 1428, 8, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_read_t, latitude), 8, 0, ENCODING_NONE }, /* latitude */
    { 1437, 12, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_read_t, longitude), 7, 0, ENCODING_NONE }, /* longitude */
    { 1447, 16, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_read_t, altitude), 11, 0, ENCODING_NONE }, /* altitude */
    { 993, 20, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_read_t, date), 12, 0, ENCODING_NONE }, /* date */
    { 1456, 24, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_read_t, alignment_angle_a1), 13, 0, ENCODING_NONE }, /* alignment_angle_a1 */
    { 1475, 28, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_read_t, alignment_angle_a2), 13, 0, ENCODING_NONE }, /* alignment_angle_a2 */
    { 1494, 32, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_ahrs_parameters_read_t, alignment_angle_a3), 13, 0, ENCODING_NONE }, /* alignment_angle_a3 */
    { 1534, 36, 8, ILAHRS_KIND_CHAR, offsetof(ilahrs_ahrs_parameters_read_t, device_id), 0, 0, ENCODING_NONE }, /* device_id */
    { 179, 44, 6, ILAHRS_KIND_RESERVED, offsetof(ilahrs_ahrs_parameters_read_t, reserved), 0, 0, ENCODING_NONE }, /* reserved */
    /* firmware_version (Table 6.11) */
    { 1561, 0, 50, ILAHRS_KIND_CHAR, offsetof(ilahrs_firmware_version_t, version), 0, 0, ENCODING_NONE }, /* version */
    /* bit_result (Table 6.12) */
    { 1580, 0, 2, ILAHRS_KIND_SIGNED, offsetof(ilahrs_bit_result_t, utermo100), 0, 1, ENCODING_NONE }, /* utermo100 */
    { 989, 2, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_bit_result_t, usw), 0, 0, ENCODING_NONE }, /* usw */
    /* calibration_parameters (Table 6.13) */
    { 1613, 0, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_parameters_t, reference_azimuth), 13, 0, ENCODING_NONE }, /* reference_azimuth */
    { 1631, 4, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_calibration_parameters_t, accumulation_time), 10, 0, ENCODING_NONE }, /* accumulation_time */
    { 1428, 6, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_parameters_t, latitude), 8, 0, ENCODING_NONE }, /* latitude */
    { 1437, 10, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_parameters_t, longitude), 7, 0, ENCODING_NONE }, /* longitude */
    { 1447, 14, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_parameters_t, altitude), 11, 0, ENCODING_NONE }, /* altitude */
    { 993, 18, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_parameters_t, date), 12, 0, ENCODING_NONE }, /* date */
    /* calibration_result (Table 6.14) */
    { 1668, 0, 1, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_calibration_result_t, calibration_type), 14, 0, ENCODING_NONE }, /* calibration_type */
    { 1685, 1, 1, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_calibration_result_t, runs_used), 0, 0, ENCODING_NONE }, /* runs_used */
    { 1695, 2, 1, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_calibration_result_t, data_used), 15, 0, ENCODING_NONE }, /* data_used */
    { 1705, 3, 1, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_calibration_result_t, success), 0, 0, ENCODING_NONE }, /* success */
    { 1713, 4, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_result_t, tm_c_11), 5, 0, ENCODING_NONE }, /* tm_c_11 */
    { 1721, 8, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_result_t, tm_c_12), 5, 0, ENCODING_NONE }, /* tm_c_12 */
    { 1729, 12, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_result_t, tm_c_13), 5, 0, ENCODING_NONE }, /* tm_c_13 */
    { 1737, 16, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_result_t, tm_c_21), 5, 0, ENCODING_NONE }, /* tm_c_21 */
    { 1745, 20, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_result_t, tm_c_22), 5, 0, ENCODING_NONE }, /* tm_c_22 */
    { 1753, 24, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_result_t, tm_c_23), 5, 0, ENCODING_NONE }, /* tm_c_23 */
    { 1761, 28, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_result_t, tm_c_31), 5, 0, ENCODING_NONE }, /* tm_c_31 */
    { 1769, 32, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_result_t, tm_c_32), 5, 0, ENCODING_NONE }, /* tm_c_32 */
    { 1777, 36, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_result_t, tm_c_33), 5, 0, ENCODING_NONE }, /* tm_c_33 */
    { 1785, 40, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_result_t, hm_0_x), 5, 0, ENCODING_NONE }, /* hm_0_x */
    { 1792, 44, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_result_t, hm_0_y), 5, 0, ENCODING_NONE }, /* hm_0_y */
    { 1799, 48, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_result_t, hm_0_z), 5, 0, ENCODING_NONE }, /* hm_0_z */
    /* calibration_run_result (Table 6.15) */
    { 1668, 0, 1, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_calibration_run_result_t, calibration_type), 16, 0, ENCODING_NONE }, /* calibration_type */
    { 1829, 1, 1, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_calibration_run_result_t, run), 17, 0, ENCODING_NONE }, /* run */
    { 1695, 2, 1, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_calibration_run_result_t, data_used), 15, 0, ENCODING_NONE }, /* data_used */
    { 1705, 3, 1, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_calibration_run_result_t, success), 0, 0, ENCODING_NONE }, /* success */
    { 1833, 4, 4, ILAHRS_KIND_RESERVED, offsetof(ilahrs_calibration_run_result_t, reserved_1), 0, 0, ENCODING_NONE }, /* reserved_1 */
    { 1844, 8, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_run_result_t, average_pitch), 8, 0, ENCODING_NONE }, /* average_pitch */
    { 1858, 12, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_run_result_t, average_roll), 7, 0, ENCODING_NONE }, /* average_roll */
    { 1871, 16, 12, ILAHRS_KIND_RESERVED, offsetof(ilahrs_calibration_run_result_t, reserved_2), 0, 0, ENCODING_NONE }, /* reserved_2 */
    { 989, 28, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_calibration_run_result_t, usw), 0, 0, ENCODING_NONE }, /* usw */
    /* calibration_run_parameters (Table 6.16) */
    { 179, 0, 6, ILAHRS_KIND_RESERVED, offsetof(ilahrs_calibration_run_parameters_t, reserved), 0, 0, ENCODING_NONE }, /* reserved */
    /* calibration_status (Table 6.17) */
    { 1668, 0, 1, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_calibration_status_t, calibration_type), 0, 0, ENCODING_NONE }, /* calibration_type */
    { 1685, 1, 1, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_calibration_status_t, runs_used), 0, 0, ENCODING_NONE }, /* runs_used */
    { 179, 2, 1, ILAHRS_KIND_RESERVED, offsetof(ilahrs_calibration_status_t, reserved), 0, 0, ENCODING_NONE }, /* reserved */
    { 1705, 3, 1, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_calibration_status_t, success), 0, 0, ENCODING_NONE }, /* success */
    { 1713, 4, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_status_t, tm_c_11), 5, 0, ENCODING_NONE }, /* tm_c_11 */
    { 1721, 8, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_status_t, tm_c_12), 5, 0, ENCODING_NONE }, /* tm_c_12 */
    { 1729, 12, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_status_t, tm_c_13), 5, 0, ENCODING_NONE }, /* tm_c_13 */
    { 1737, 16, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_status_t, tm_c_21), 5, 0, ENCODING_NONE }, /* tm_c_21 */
    { 1745, 20, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_status_t, tm_c_22), 5, 0, ENCODING_NONE }, /* tm_c_22 */
    { 1753, 24, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_status_t, tm_c_23), 5, 0, ENCODING_NONE }, /* tm_c_23 */
    { 1761, 28, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_status_t, tm_c_31), 5, 0, ENCODING_NONE }, /* tm_c_31 */
    { 1769, 32, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_status_t, tm_c_32), 5, 0, ENCODING_NONE }, /* tm_c_32 */
    { 1777, 36, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_status_t, tm_c_33), 5, 0, ENCODING_NONE }, /* tm_c_33 */
    { 1785, 40, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_status_t, hm_0_x), 5, 0, ENCODING_NONE }, /* hm_0_x */
    { 1792, 44, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_status_t, hm_0_y), 5, 0, ENCODING_NONE }, /* hm_0_y */
    { 1799, 48, 4, ILAHRS_KIND_FLOAT, offsetof(ilahrs_calibration_status_t, hm_0_z), 5, 0, ENCODING_NONE }, /* hm_0_z */
    /* acknowledgement (6.3.1 (Table 6.2 with a one-word payload)) */
    { 203, 0, 2, ILAHRS_KIND_UNSIGNED, offsetof(ilahrs_acknowledgement_t, checksum), 0, 0, ENCODING_NONE }, /* checksum */
};

static const struct {
    uint16_t name;
    uint8_t size;
    uint8_t field_count;
    uint8_t first_field;
    uint16_t struct_size;
} ilahrs_payloads[ILAHRS_PAYLOAD_COUNT] = {
    { 998, 34, 16, 0, (uint16_t)sizeof(ilahrs_full_output_t) },
    { 1083, 34, 11, 16, (uint16_t)sizeof(ilahrs_quaternion_t) },
    { 1110, 34, 16, 27, (uint16_t)sizeof(ilahrs_orientation_sensors_t) },
    { 1187, 50, 13, 43, (uint16_t)sizeof(ilahrs_initial_alignment_t) },
    { 1368, 50, 11, 56, (uint16_t)sizeof(ilahrs_ahrs_parameters_load_t) },
    { 1513, 50, 12, 67, (uint16_t)sizeof(ilahrs_ahrs_parameters_read_t) },
    { 1544, 50, 1, 79, (uint16_t)sizeof(ilahrs_firmware_version_t) },
    { 1569, 4, 2, 80, (uint16_t)sizeof(ilahrs_bit_result_t) },
    { 1590, 22, 6, 82, (uint16_t)sizeof(ilahrs_calibration_parameters_t) },
    { 1649, 52, 16, 88, (uint16_t)sizeof(ilahrs_calibration_result_t) },
    { 1806, 30, 9, 104, (uint16_t)sizeof(ilahrs_calibration_run_result_t) },
    { 1882, 6, 1, 113, (uint16_t)sizeof(ilahrs_calibration_run_parameters_t) },
    { 1909, 52, 16, 114, (uint16_t)sizeof(ilahrs_calibration_status_t) },
    { 1928, 2, 1, 130, (uint16_t)sizeof(ilahrs_acknowledgement_t) },
};

/* Spec defaults other than zero. */
static const struct {
    uint8_t field;
    uint16_t text; /* 0 with no text: numeric */
    double number;
} ilahrs_defaults[11] = {
    { 56, 0, 100.0 }, /* ahrs_parameters_load.update_rate */
    { 57, 0, 30.0 }, /* ahrs_parameters_load.alignment_time */
    { 62, 0, 1900.0 }, /* ahrs_parameters_load.date */
    { 67, 0, 1.0 }, /* ahrs_parameters_read.update_rate */
    { 68, 0, 1.0 }, /* ahrs_parameters_read.alignment_time */
    { 73, 0, 1900.0 }, /* ahrs_parameters_read.date */
    { 83, 0, 1.0 }, /* calibration_parameters.accumulation_time */
    { 87, 0, 1900.0 }, /* calibration_parameters.date */
    { 88, 0, 1.0 }, /* calibration_result.calibration_type */
    { 104, 0, 2.0 }, /* calibration_run_result.calibration_type */
    { 105, 0, 1.0 }, /* calibration_run_result.run */
};
#define DEFAULT_COUNT 11u

/* C99 compile-time checks: struct offsets fit ilahrs_field_info_t.member. */
typedef char ilahrs_check_full_output[sizeof(ilahrs_full_output_t) <= 255 ? 1 : -1];
typedef char ilahrs_check_quaternion[sizeof(ilahrs_quaternion_t) <= 255 ? 1 : -1];
typedef char ilahrs_check_orientation_sensors[sizeof(ilahrs_orientation_sensors_t) <= 255 ? 1 : -1];
typedef char ilahrs_check_initial_alignment[sizeof(ilahrs_initial_alignment_t) <= 255 ? 1 : -1];
typedef char ilahrs_check_ahrs_parameters_load[sizeof(ilahrs_ahrs_parameters_load_t) <= 255 ? 1 : -1];
typedef char ilahrs_check_ahrs_parameters_read[sizeof(ilahrs_ahrs_parameters_read_t) <= 255 ? 1 : -1];
typedef char ilahrs_check_firmware_version[sizeof(ilahrs_firmware_version_t) <= 255 ? 1 : -1];
typedef char ilahrs_check_bit_result[sizeof(ilahrs_bit_result_t) <= 255 ? 1 : -1];
typedef char ilahrs_check_calibration_parameters[sizeof(ilahrs_calibration_parameters_t) <= 255 ? 1 : -1];
typedef char ilahrs_check_calibration_result[sizeof(ilahrs_calibration_result_t) <= 255 ? 1 : -1];
typedef char ilahrs_check_calibration_run_result[sizeof(ilahrs_calibration_run_result_t) <= 255 ? 1 : -1];
typedef char ilahrs_check_calibration_run_parameters[sizeof(ilahrs_calibration_run_parameters_t) <= 255 ? 1 : -1];
typedef char ilahrs_check_calibration_status[sizeof(ilahrs_calibration_status_t) <= 255 ? 1 : -1];
typedef char ilahrs_check_acknowledgement[sizeof(ilahrs_acknowledgement_t) <= 255 ? 1 : -1];
/* The stream decoder's counters fit its buffer. */
typedef char ilahrs_check_held[ILAHRS_MAX_MESSAGE_SIZE <= 255 && ILAHRS_FRAME_MAX_SIZE <= ILAHRS_MAX_MESSAGE_SIZE ? 1 : -1];

/* ---- Helpers --------------------------------------------------------------------------- */

static bool fail(ilahrs_error_t *err, ilahrs_error_kind_t kind, size_t offset, const char *field)
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

static bool equal_name(const char *name, size_t len, uint16_t offset)
{
    const char *known = NAME(offset);
    return name != NULL && strlen(known) == len && memcmp(known, name, len) == 0;
}

/* ---- Errors ---------------------------------------------------------------------------- */

const char *ilahrs_error_kind_name(ilahrs_error_kind_t kind)
{
    if (kind == ILAHRS_OK) {
        return "ok";
    }
    if ((unsigned)kind >= ILAHRS_ERROR_KIND_COUNT) {
        return "unknown";
    }
    return NAME(ilahrs_error_names[(unsigned)kind - 1u]);
}

/* ---- Frame ----------------------------------------------------------------------------- */

uint16_t ilahrs_checksum(const uint8_t *data, size_t len)
{
    uint32_t sum = 0;
    size_t i;
    for (i = 0; i < len; i++) {
        sum += data[i];
    }
    return (uint16_t)sum;
}

static bool message_type_valid(uint32_t type)
{
    return type == ILAHRS_MESSAGE_TYPE_COMMAND || type == ILAHRS_MESSAGE_TYPE_DATA;
}

bool ilahrs_frame_parse(const uint8_t *data, size_t len, ilahrs_frame_t *frame, ilahrs_error_t *err)
{
    size_t total;
    size_t at;
    uint32_t length;
    if (len < 1u) {
        return fail(err, ILAHRS_ERR_TRUNCATED, len, NULL);
    }
    if (data[0] != ILAHRS_FRAME_HEADER_0) {
        return fail(err, ILAHRS_ERR_BAD_HEADER, 0, NAME(NAME_FRAME_HEADER));
    }
    if (len < 2u) {
        return fail(err, ILAHRS_ERR_TRUNCATED, len, NULL);
    }
    if (data[1] != ILAHRS_FRAME_HEADER_1) {
        return fail(err, ILAHRS_ERR_BAD_HEADER, 1, NAME(NAME_FRAME_HEADER));
    }
    if (len < ILAHRS_FRAME_PAYLOAD_OFFSET) {
        return fail(err, ILAHRS_ERR_TRUNCATED, len, NULL);
    }
    if (!message_type_valid(get_le(data + ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, ILAHRS_FRAME_MESSAGE_TYPE_SIZE))) {
        return fail(err, ILAHRS_ERR_BAD_MESSAGE_TYPE, ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, NAME(NAME_FRAME_MESSAGE_TYPE));
    }
    length = get_le(data + ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, ILAHRS_FRAME_MESSAGE_LENGTH_SIZE);
    if (length < ILAHRS_FRAME_MIN_LENGTH || length > ILAHRS_FRAME_MAX_LENGTH) {
        return fail(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, NAME(NAME_FRAME_MESSAGE_LENGTH));
    }
    total = ILAHRS_FRAME_HEADER_SIZE + (size_t)length;
    if (len < total) {
        return fail(err, ILAHRS_ERR_TRUNCATED, len, NULL);
    }
    at = total - ILAHRS_FRAME_CHECKSUM_SIZE;
    if (ilahrs_checksum(data + ILAHRS_FRAME_HEADER_SIZE, at - ILAHRS_FRAME_HEADER_SIZE)
        != get_le(data + at, ILAHRS_FRAME_CHECKSUM_SIZE)) {
        return fail(err, ILAHRS_ERR_BAD_CHECKSUM, at, NAME(NAME_FRAME_CHECKSUM));
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
        return fail_size(err, ILAHRS_ERR_BAD_MESSAGE_TYPE, ILAHRS_NO_OFFSET, NAME(NAME_FRAME_MESSAGE_TYPE));
    }
    if (frame->payload_size < ILAHRS_FRAME_MIN_PAYLOAD || frame->payload_size > ILAHRS_FRAME_MAX_PAYLOAD
        || frame->payload == NULL) {
        return fail_size(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_NO_OFFSET, NAME(NAME_FRAME_PAYLOAD));
    }
    if (out == NULL || cap < frame->payload_size + ILAHRS_FRAME_OVERHEAD) {
        return fail_size(err, ILAHRS_ERR_BUFFER_TOO_SMALL, ILAHRS_NO_OFFSET, NULL);
    }
    memmove(out + ILAHRS_FRAME_PAYLOAD_OFFSET, frame->payload, frame->payload_size);
    return frame_finish(out, frame, frame->payload_size);
}

/* ---- Commands -------------------------------------------------------------------------- */

const char *ilahrs_mode_name(ilahrs_mode_t mode)
{
    static const uint16_t names[ILAHRS_MODE_COUNT] = { 637, 642, 653, 664, 676 };
    return (unsigned)mode < ILAHRS_MODE_COUNT ? NAME(names[mode]) : NULL;
}

const char *ilahrs_command_name(ilahrs_command_t command)
{
    return (unsigned)command < ILAHRS_COMMAND_COUNT ? NAME(ilahrs_commands[command].name) : NULL;
}

uint8_t ilahrs_command_code(ilahrs_command_t command)
{
    return (unsigned)command < ILAHRS_COMMAND_COUNT ? ilahrs_commands[command].code : 0;
}

bool ilahrs_command_by_name(const char *name, size_t len, ilahrs_command_t *command, ilahrs_error_t *err)
{
    unsigned i;
    for (i = 0; i < ILAHRS_COMMAND_COUNT; i++) {
        if (equal_name(name, len, ilahrs_commands[i].name)) {
            *command = (ilahrs_command_t)i;
            return true;
        }
    }
    return fail(err, ILAHRS_ERR_UNKNOWN_COMMAND, ILAHRS_NO_OFFSET, NULL);
}

uint8_t ilahrs_command_valid_in(ilahrs_command_t command)
{
    return (unsigned)command < ILAHRS_COMMAND_COUNT ? ilahrs_commands[command].valid_in : 0;
}

ilahrs_response_t ilahrs_command_response(ilahrs_command_t command)
{
    return (unsigned)command < ILAHRS_COMMAND_COUNT ? (ilahrs_response_t)ilahrs_commands[command].response
                                                     : ILAHRS_RESPONSE_NONE;
}

int ilahrs_command_parameter_block(ilahrs_command_t command)
{
    return (unsigned)command < ILAHRS_COMMAND_COUNT ? ilahrs_commands[command].parameter_block : ILAHRS_PAYLOAD_NONE;
}

int ilahrs_command_response_payload(ilahrs_command_t command, size_t index)
{
    if ((unsigned)command >= ILAHRS_COMMAND_COUNT || index >= ILAHRS_RESPONSE_PAYLOADS_MAX) {
        return ILAHRS_PAYLOAD_NONE;
    }
    return ilahrs_commands[command].response_payloads[index];
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
    out[ILAHRS_FRAME_PAYLOAD_OFFSET] = ilahrs_commands[command].code;
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
        return fail(err, ILAHRS_ERR_BAD_MESSAGE_TYPE, ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, NAME(NAME_FRAME_MESSAGE_TYPE));
    }
    if (frame.payload_size != 1) {
        return fail(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_FRAME_MESSAGE_LENGTH_OFFSET, NAME(NAME_FRAME_MESSAGE_LENGTH));
    }
    code = frame.payload[0];
    match->code = code;
    match->count = 0;
    for (i = 0; i < ILAHRS_COMMAND_COUNT; i++) {
        uint8_t id = ilahrs_commands_by_code[i];
        if (ilahrs_commands[id].code == code && match->count < ILAHRS_COMMANDS_PER_CODE_MAX) {
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
    ilahrs_acknowledgement_t payload;
    size_t at;
    if (!ilahrs_frame_parse(message, len, &frame, err)) {
        return 0;
    }
    at = ILAHRS_FRAME_PAYLOAD_OFFSET + frame.payload_size;
    memset(&payload, 0, sizeof payload);
    payload.checksum = (uint16_t)get_le(message + at, ILAHRS_FRAME_CHECKSUM_SIZE);
    return ilahrs_payload_build_frame(ILAHRS_PAYLOAD_ACKNOWLEDGEMENT, &payload, out, cap, err);
}

/* ---- Variants -------------------------------------------------------------------------- */

int32_t ilahrs_variant_parameter(ilahrs_variant_t variant, ilahrs_variant_parameter_t parameter)
{
    if ((unsigned)variant >= ILAHRS_VARIANT_COUNT || (unsigned)parameter >= 2u) {
        return 0;
    }
    return ilahrs_variant_values[variant][parameter];
}

const char *ilahrs_variant_name(ilahrs_variant_t variant)
{
    return (unsigned)variant < ILAHRS_VARIANT_COUNT ? NAME(ilahrs_variant_names[variant][0]) : NULL;
}

const char *ilahrs_variant_part_number(ilahrs_variant_t variant)
{
    return (unsigned)variant < ILAHRS_VARIANT_COUNT ? NAME(ilahrs_variant_names[variant][1]) : NULL;
}

bool ilahrs_variant_by_name(const char *name, size_t len, ilahrs_variant_t *variant)
{
    unsigned i;
    for (i = 0; i < ILAHRS_VARIANT_COUNT; i++) {
        if (equal_name(name, len, ilahrs_variant_names[i][0])) {
            *variant = (ilahrs_variant_t)i;
            return true;
        }
    }
    return false;
}

/* ---- Payloads -------------------------------------------------------------------------- */

const char *ilahrs_payload_name(int payload)
{
    return payload >= 0 && payload < ILAHRS_PAYLOAD_COUNT ? NAME(ilahrs_payloads[payload].name) : NULL;
}

size_t ilahrs_payload_size(int payload)
{
    return payload >= 0 && payload < ILAHRS_PAYLOAD_COUNT ? ilahrs_payloads[payload].size : 0;
}

size_t ilahrs_payload_struct_size(int payload)
{
    return payload >= 0 && payload < ILAHRS_PAYLOAD_COUNT ? ilahrs_payloads[payload].struct_size : 0;
}

size_t ilahrs_payload_field_count(int payload)
{
    return payload >= 0 && payload < ILAHRS_PAYLOAD_COUNT ? ilahrs_payloads[payload].field_count : 0;
}

const ilahrs_field_info_t *ilahrs_payload_field(int payload, size_t index)
{
    if (payload < 0 || payload >= ILAHRS_PAYLOAD_COUNT || index >= ilahrs_payloads[payload].field_count) {
        return NULL;
    }
    return &ilahrs_fields[ilahrs_payloads[payload].first_field + index];
}

bool ilahrs_payload_by_name(const char *name, size_t len, ilahrs_payload_t *payload)
{
    int i;
    for (i = 0; i < ILAHRS_PAYLOAD_COUNT; i++) {
        if (equal_name(name, len, ilahrs_payloads[i].name)) {
            *payload = (ilahrs_payload_t)i;
            return true;
        }
    }
    return false;
}

const char *ilahrs_field_name(const ilahrs_field_info_t *field)
{
    return NAME(field->name);
}

size_t ilahrs_field_offset(const ilahrs_field_info_t *field)
{
    return field->offset;
}

size_t ilahrs_field_size(const ilahrs_field_info_t *field)
{
    return field->size;
}

ilahrs_kind_t ilahrs_field_kind(const ilahrs_field_info_t *field)
{
    return (ilahrs_kind_t)field->kind;
}

void *ilahrs_field_member(const ilahrs_field_info_t *field, void *payload)
{
    return (uint8_t *)payload + field->member;
}

const void *ilahrs_field_member_const(const ilahrs_field_info_t *field, const void *payload)
{
    return (const uint8_t *)payload + field->member;
}

static bool is_integer(const ilahrs_field_info_t *field)
{
    return field->kind == ILAHRS_KIND_UNSIGNED || field->kind == ILAHRS_KIND_SIGNED;
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
    bits = load_bits(ilahrs_field_member_const(field, payload), field->size);
    return field->kind == ILAHRS_KIND_SIGNED ? (int64_t)sign_extend(bits, field->size) : (int64_t)bits;
}

float ilahrs_field_get_float(const ilahrs_field_info_t *field, const void *payload)
{
    if (field->kind != ILAHRS_KIND_FLOAT) {
        return 0.0f;
    }
    return float_of_bits(load_bits(ilahrs_field_member_const(field, payload), 4));
}

bool ilahrs_field_set_int(const ilahrs_field_info_t *field, void *payload, int64_t value, ilahrs_error_t *err)
{
    int64_t low = 0;
    int64_t high = (int64_t)((((uint64_t)1) << (8 * field->size)) - 1u);
    if (field->kind == ILAHRS_KIND_SIGNED) {
        high = (int64_t)((((uint64_t)1) << (8 * field->size - 1)) - 1u);
        low = -high - 1;
    }
    if (!is_integer(field) || value < low || value > high) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, field->offset, NAME(field->name));
    }
    store_bits(ilahrs_field_member(field, payload), (uint32_t)(uint64_t)value, field->size);
    return true;
}

bool ilahrs_field_set_float(const ilahrs_field_info_t *field, void *payload, float value, ilahrs_error_t *err)
{
    if (field->kind != ILAHRS_KIND_FLOAT) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, field->offset, NAME(field->name));
    }
    memcpy(ilahrs_field_member(field, payload), &value, sizeof value);
    return true;
}

/*
 * The builder check of one numeric value. NaN fails every comparison. `stored`: the value is
 * a float32 already, so it is compared with the float32 roundings of the bounds (a double
 * within the bounds always rounds to a float32 within them).
 */
static bool value_ok(const ilahrs_field_info_t *field, double value, bool stored)
{
    if (field->bounds != 0) {
        double low = ilahrs_bounds[field->bounds][0];
        double high = ilahrs_bounds[field->bounds][1];
        if (stored && field->kind == ILAHRS_KIND_FLOAT) {
            low = (double)(float)low;
            high = (double)(float)high;
        }
        if (!(value >= low && value <= high)) {
            return false;
        }
    }
    if (field->encoding == ENCODING_DECLINATION) {
        return (value >= (double)ILAHRS_DECLINATION_MIN && value <= (double)ILAHRS_DECLINATION_MAX)
            || value > (double)ILAHRS_DECLINATION_COMPUTE_ABOVE;
    }
    return true;
}

bool ilahrs_field_check(const ilahrs_field_info_t *field, double value, ilahrs_error_t *err)
{
    if (field->kind == ILAHRS_KIND_CHAR || field->kind == ILAHRS_KIND_RESERVED || !value_ok(field, value, false)) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, field->offset, NAME(field->name));
    }
    return true;
}

bool ilahrs_field_scale(const ilahrs_field_info_t *field, ilahrs_variant_t variant, int32_t *multiplier, int32_t *divisor)
{
    int32_t d;
    if (field->scale == 0) {
        return false;
    }
    d = ilahrs_scales[field->scale].divisor;
    if (ilahrs_scales[field->scale].parameter != NO_PARAMETER) {
        d = ilahrs_variant_parameter(variant, (ilahrs_variant_parameter_t)ilahrs_scales[field->scale].parameter);
    }
    if (d == 0) {
        return false;
    }
    *multiplier = ilahrs_scales[field->scale].multiplier;
    *divisor = d;
    return true;
}

void ilahrs_payload_defaults(int payload, void *out)
{
    unsigned i;
    unsigned first;
    if (payload < 0 || payload >= ILAHRS_PAYLOAD_COUNT) {
        return;
    }
    memset(out, 0, ilahrs_payloads[payload].struct_size);
    first = ilahrs_payloads[payload].first_field;
    for (i = 0; i < DEFAULT_COUNT; i++) {
        const ilahrs_field_info_t *f = &ilahrs_fields[ilahrs_defaults[i].field];
        if (ilahrs_defaults[i].field < first || ilahrs_defaults[i].field >= first + ilahrs_payloads[payload].field_count) {
            continue;
        }
        if (f->kind == ILAHRS_KIND_FLOAT) {
            (void)ilahrs_field_set_float(f, out, (float)ilahrs_defaults[i].number, NULL);
        } else if (is_integer(f)) {
            (void)ilahrs_field_set_int(f, out, (int64_t)ilahrs_defaults[i].number, NULL);
        } else if (f->kind == ILAHRS_KIND_CHAR && ilahrs_defaults[i].text != 0) {
            const char *text = NAME(ilahrs_defaults[i].text);
            size_t n = strlen(text);
            memcpy(ilahrs_field_member(f, out), text, n < f->size ? n : f->size);
        }
    }
}

bool ilahrs_payload_parse(int payload, const uint8_t *data, size_t len, void *out, ilahrs_error_t *err)
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
    memset(out, 0, ilahrs_payloads[payload].struct_size);
    f = &ilahrs_fields[ilahrs_payloads[payload].first_field];
    end = f + ilahrs_payloads[payload].field_count;
    for (; f < end; f++) {
        uint8_t *member = (uint8_t *)out + f->member;
        if (f->kind == ILAHRS_KIND_CHAR || f->kind == ILAHRS_KIND_RESERVED) {
            memcpy(member, data + f->offset, f->size);
        } else {
            store_bits(member, get_le(data + f->offset, f->size), f->size);
        }
    }
    return true;
}

size_t ilahrs_payload_build(int payload, const void *in, uint8_t *out, size_t cap, ilahrs_error_t *err)
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
        const uint8_t *member = (const uint8_t *)in + f->member;
        if (f->kind == ILAHRS_KIND_CHAR || f->kind == ILAHRS_KIND_RESERVED) {
            memcpy(out + f->offset, member, f->size);
        } else {
            uint32_t bits = load_bits(member, f->size);
            if (f->bounds != 0 || f->encoding != ENCODING_NONE) {
                double value = f->kind == ILAHRS_KIND_FLOAT  ? (double)float_of_bits(bits)
                             : f->kind == ILAHRS_KIND_SIGNED ? (double)sign_extend(bits, f->size)
                                                             : (double)bits;
                if (!value_ok(f, value, true)) {
                    return fail_size(err, ILAHRS_ERR_OUT_OF_RANGE, f->offset, NAME(f->name));
                }
            }
            put_le(out + f->offset, bits, f->size);
        }
    }
    return size;
}

size_t ilahrs_payload_build_frame(int payload, const void *in, uint8_t *out, size_t cap, ilahrs_error_t *err)
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

static int days_in_month(int year, int month)
{
    static const uint8_t days[12] = { 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31 };
    bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    return month == 2 && leap ? 29 : days[month - 1];
}

/* Year + (Month - 1)/12 + Day/365, as a float. */
static double date_value(int year, int month, int day)
{
    double value = 0.0;
    value += (double)(year + 0) / 1.0;
    value += (double)(month + -1) / 12.0;
    value += (double)(day + 0) / 365.0;
    return value;
}

bool ilahrs_date_encode(int year, int month, int day, float *value, ilahrs_error_t *err)
{
    if (year < ILAHRS_DATE_YEAR_MIN || year > ILAHRS_DATE_YEAR_MAX || month < 1 || month > 12 || day < 1
        || day > days_in_month(year, month)) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NAME(NAME_DATE));
    }
    *value = (float)date_value(year, month, day);
    return true;
}

bool ilahrs_date_decode(float value, ilahrs_date_t *date, ilahrs_error_t *err)
{
    double v = (double)value;
    double best = -1.0;
    int base;
    int year;
    if (!(v >= (double)(ILAHRS_DATE_YEAR_MIN - 1) && v <= (double)(ILAHRS_DATE_YEAR_MAX + 2))) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NAME(NAME_DATE));
    }
    base = (int)v; /* floor: v is positive */
    for (year = base - 1; year <= base; year++) {
        int month;
        if (year < ILAHRS_DATE_YEAR_MIN || year > ILAHRS_DATE_YEAR_MAX) {
            continue;
        }
        for (month = 1; month <= 12; month++) {
            /* The distance is linear in the day: only the days around the nearest can win. */
            int last = days_in_month(year, month);
            double at_zero = date_value(year, month, 0);
            double per_day = date_value(year, month, 1) - at_zero;
            double guess = (v - at_zero) / per_day;
            int day = guess < 1.0 ? 1 : guess > (double)last ? last : (int)guess;
            int first = day > 1 ? day - 1 : 1;
            int stop = day < last ? day + 1 : last;
            for (day = first; day <= stop; day++) {
                double distance = date_value(year, month, day) - v;
                if (distance < 0) {
                    distance = -distance;
                }
                if (best < 0 || distance < best) {
                    best = distance;
                    date->year = (int16_t)year;
                    date->month = (uint8_t)month;
                    date->day = (uint8_t)day;
                }
            }
        }
    }
    if (best < 0) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NAME(NAME_DATE));
    }
    return true;
}

/* ---- Unit Status Word ------------------------------------------------------------------ */

const char *ilahrs_usw_flag_name(unsigned bit)
{
    unsigned i;
    for (i = 0; i < 14u; i++) {
        if (ilahrs_usw_flags[i].bit == bit) {
            return NAME(ilahrs_usw_flags[i].name);
        }
    }
    return NULL;
}

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
#define PAHR_HUGE 10000000000000ull /* any magnitude above every range */

/* One field: name, format, template width, fraction digits, struct member, range. */
static const struct {
    uint16_t name;
    uint8_t hex;
    uint8_t width;
    uint8_t decimals;
    uint8_t member;
    uint8_t size;
    uint8_t is_signed;
    uint32_t divisor;
    int32_t min;
    int32_t max;
} ilahrs_pahr_fields[ILAHRS_PAHR_FIELD_COUNT] = {
    { 954, 0, 4, 2, offsetof(ilahrs_pahr_t, roll), sizeof(((ilahrs_pahr_t *)0)->roll), 1, 100u, -18000, 18000 },
    { 959, 0, 3, 2, offsetof(ilahrs_pahr_t, pitch), sizeof(((ilahrs_pahr_t *)0)->pitch), 1, 100u, -9000, 9000 },
    { 965, 0, 3, 2, offsetof(ilahrs_pahr_t, heading), sizeof(((ilahrs_pahr_t *)0)->heading), 0, 100u, 0, 35999u },
    { 973, 0, 3, 1, offsetof(ilahrs_pahr_t, temperature), sizeof(((ilahrs_pahr_t *)0)->temperature), 1, 10u, -999, 9999 },
    { 985, 0, 1, 2, offsetof(ilahrs_pahr_t, vdd), sizeof(((ilahrs_pahr_t *)0)->vdd), 0, 100u, 0, 999 },
    { 989, 1, 4, 0, offsetof(ilahrs_pahr_t, usw), sizeof(((ilahrs_pahr_t *)0)->usw), 0, 1u, 0, 65535u },
};

const char *ilahrs_pahr_field_name(size_t index)
{
    return index < ILAHRS_PAHR_FIELD_COUNT ? NAME(ilahrs_pahr_fields[index].name) : NULL;
}

uint32_t ilahrs_pahr_field_divisor(size_t index)
{
    return index < ILAHRS_PAHR_FIELD_COUNT && !ilahrs_pahr_fields[index].hex ? ilahrs_pahr_fields[index].divisor : 0;
}

static int32_t pahr_get(const ilahrs_pahr_t *in, size_t k);

int32_t ilahrs_pahr_field_get(const ilahrs_pahr_t *sentence, size_t index)
{
    return index < ILAHRS_PAHR_FIELD_COUNT ? pahr_get(sentence, index) : 0;
}

static int hex_value(uint8_t c)
{
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'A' && c <= 'F') {
        return c - 'A' + 10;
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    return -1;
}

/* Parse p[0..n) as field `k`: false if it breaks the grammar; *value saturates at PAHR_HUGE. */
static bool pahr_value(const uint8_t *p, size_t n, size_t k, int64_t *value)
{
    uint64_t magnitude = 0;
    size_t i = 0;
    size_t digits = 0;
    bool negative = false;
    if (ilahrs_pahr_fields[k].hex) {
        if (n < 1 || n > ilahrs_pahr_fields[k].width) {
            return false;
        }
        for (; i < n; i++) {
            int h = hex_value(p[i]);
            if (h < 0) {
                return false;
            }
            magnitude = magnitude * 16u + (uint64_t)h;
        }
        *value = (int64_t)magnitude;
        return true;
    }
    if (n > 0 && p[0] == '-') {
        negative = true;
        i = 1;
    }
    for (; i < n && p[i] >= '0' && p[i] <= '9'; i++, digits++) {
        if (magnitude < PAHR_HUGE) {
            magnitude = magnitude * 10u + (uint64_t)(p[i] - '0');
        }
    }
    if (digits == 0) {
        return false;
    }
    digits = 0;
    if (i < n && p[i] == '.') {
        for (i++; i < n && p[i] >= '0' && p[i] <= '9'; i++, digits++) {
            if (magnitude < PAHR_HUGE) {
                magnitude = magnitude * 10u + (uint64_t)(p[i] - '0');
            }
        }
        if (digits == 0 || digits > ilahrs_pahr_fields[k].decimals) {
            return false;
        }
    }
    if (i != n) {
        return false;
    }
    for (; digits < ilahrs_pahr_fields[k].decimals; digits++) {
        if (magnitude < PAHR_HUGE) {
            magnitude *= 10u;
        }
    }
    if (magnitude > PAHR_HUGE) {
        magnitude = PAHR_HUGE;
    }
    *value = negative ? -(int64_t)magnitude : (int64_t)magnitude;
    return true;
}

bool ilahrs_pahr_parse(const char *text, size_t len, ilahrs_pahr_t *out, ilahrs_error_t *err)
{
    const uint8_t *p = (const uint8_t *)text;
    size_t i;
    size_t end;
    size_t star;
    size_t fields;
    size_t k;
    uint8_t sum;
    int high;
    int low;
    if (len < 1) {
        return fail(err, ILAHRS_ERR_TRUNCATED, 0, NULL);
    }
    if (p[0] != PAHR_START) {
        return fail(err, ILAHRS_ERR_BAD_HEADER, 0, NULL);
    }
    for (i = 1; i < PAHR_PREFIX_LENGTH && i < len; i++) {
        if (p[i] != (uint8_t)PAHR_PREFIX[i]) {
            return fail(err, ILAHRS_ERR_BAD_HEADER, 1, NULL);
        }
    }
    if (len < PAHR_PREFIX_LENGTH) {
        return fail(err, ILAHRS_ERR_TRUNCATED, len, NULL);
    }
    for (i = PAHR_PREFIX_LENGTH; i + 1 < len; i++) {
        if (p[i] == PAHR_CR && p[i + 1] == PAHR_LF) {
            break;
        }
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
    star = end - PAHR_TAIL; /* end >= PAHR_PREFIX_LENGTH + 2 */
    if (star < PAHR_PREFIX_LENGTH || p[star] != PAHR_STAR) {
        return fail(err, ILAHRS_ERR_MALFORMED, star, NULL);
    }
    high = hex_value(p[star + 1]);
    low = hex_value(p[star + 2]);
    if (high < 0 || low < 0) {
        return fail(err, ILAHRS_ERR_MALFORMED, star + 1, NULL);
    }
    sum = 0;
    fields = 1;
    for (i = 1; i < star; i++) {
        sum ^= p[i];
        if (i >= PAHR_PREFIX_LENGTH && p[i] == PAHR_SEPARATOR) {
            fields++;
        }
    }
    if (sum != (uint8_t)(high * 16 + low)) {
        return fail(err, ILAHRS_ERR_BAD_CHECKSUM, star + 1, NULL);
    }
    if (fields != ILAHRS_PAHR_FIELD_COUNT) {
        return fail(err, ILAHRS_ERR_MALFORMED, PAHR_PREFIX_LENGTH, NULL);
    }
    i = PAHR_PREFIX_LENGTH;
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        size_t stop = i;
        int64_t value = 0;
        while (stop < star && p[stop] != PAHR_SEPARATOR) {
            stop++;
        }
        if (!pahr_value(p + i, stop - i, k, &value)) {
            return fail(err, ILAHRS_ERR_MALFORMED, i, NAME(ilahrs_pahr_fields[k].name));
        }
        if (value < ilahrs_pahr_fields[k].min || value > ilahrs_pahr_fields[k].max) {
            return fail(err, ILAHRS_ERR_OUT_OF_RANGE, i, NAME(ilahrs_pahr_fields[k].name));
        }
        store_bits((uint8_t *)out + ilahrs_pahr_fields[k].member, (uint32_t)(int32_t)value, ilahrs_pahr_fields[k].size);
        i = stop + 1;
    }
    return true;
}

static int32_t pahr_get(const ilahrs_pahr_t *in, size_t k)
{
    uint32_t bits = load_bits((const uint8_t *)in + ilahrs_pahr_fields[k].member, ilahrs_pahr_fields[k].size);
    return ilahrs_pahr_fields[k].is_signed ? sign_extend(bits, ilahrs_pahr_fields[k].size) : (int32_t)bits;
}

/* Write `value` in `base` with at least `width` digits at out[*at], within `cap`. */
static bool put_digits(uint8_t *out, size_t cap, size_t *at, uint32_t value, uint32_t base, size_t width)
{
    static const char digits[] = "0123456789ABCDEF";
    uint8_t tmp[10];
    size_t n = 0;
    do {
        tmp[n++] = (uint8_t)digits[value % base];
        value /= base;
    } while (value != 0 && n < sizeof tmp);
    while (n < width && n < sizeof tmp) {
        tmp[n++] = '0';
    }
    if (*at + n > cap) {
        return false;
    }
    while (n > 0) {
        out[(*at)++] = tmp[--n];
    }
    return true;
}

size_t ilahrs_pahr_build(const ilahrs_pahr_t *in, char *text, size_t cap, ilahrs_error_t *err)
{
    uint8_t buf[ILAHRS_PAHR_MAX_LENGTH];
    size_t at;
    size_t k;
    size_t i;
    uint8_t sum = 0;
    bool fits = true;
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        int32_t value = pahr_get(in, k);
        if (value < ilahrs_pahr_fields[k].min || value > ilahrs_pahr_fields[k].max) {
            return fail_size(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NAME(ilahrs_pahr_fields[k].name));
        }
    }
    memcpy(buf, PAHR_PREFIX, PAHR_PREFIX_LENGTH);
    at = PAHR_PREFIX_LENGTH;
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT && fits; k++) {
        int32_t value = pahr_get(in, k);
        uint32_t magnitude = value < 0 ? 0u - (uint32_t)value : (uint32_t)value;
        size_t width = ilahrs_pahr_fields[k].width;
        if (k > 0) {
            fits = at < sizeof buf;
            if (fits) {
                buf[at++] = PAHR_SEPARATOR;
            }
        }
        if (ilahrs_pahr_fields[k].hex) {
            fits = fits && put_digits(buf, sizeof buf, &at, magnitude, 16, width);
            continue;
        }
        if (value < 0) {
            fits = fits && at < sizeof buf;
            if (fits) {
                buf[at++] = '-';
            }
            width = width > 0 ? width - 1 : 0;
        }
        fits = fits && put_digits(buf, sizeof buf, &at, magnitude / ilahrs_pahr_fields[k].divisor, 10, width);
        if (ilahrs_pahr_fields[k].decimals > 0) {
            fits = fits && at < sizeof buf;
            if (fits) {
                buf[at++] = '.';
            }
            fits = fits && put_digits(buf, sizeof buf, &at, magnitude % ilahrs_pahr_fields[k].divisor, 10,
                                      ilahrs_pahr_fields[k].decimals);
        }
    }
    for (i = 1; i < at; i++) {
        sum ^= buf[i];
    }
    if (!fits || at + PAHR_TAIL > sizeof buf) {
        return fail_size(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_NO_OFFSET, NULL);
    }
    buf[at++] = PAHR_STAR;
    (void)put_digits(buf, sizeof buf, &at, sum, 16, 2);
    buf[at++] = PAHR_CR;
    buf[at++] = PAHR_LF;
    if (text == NULL || cap < at) {
        return fail_size(err, ILAHRS_ERR_BUFFER_TOO_SMALL, ILAHRS_NO_OFFSET, NULL);
    }
    memcpy(text, buf, at);
    if (cap > at) {
        text[at] = '\0';
    }
    return at;
}

/* value * divisor rounded half away from zero, saturated far beyond every range. */
static int64_t pahr_round(double scaled)
{
    double limit = 1e15;
    if (scaled >= 0) {
        return scaled + 0.5 >= limit ? (int64_t)limit : (int64_t)(scaled + 0.5);
    }
    return -scaled + 0.5 >= limit ? -(int64_t)limit : -(int64_t)(-scaled + 0.5);
}

bool ilahrs_pahr_from_array(const double values[ILAHRS_PAHR_FIELD_COUNT], ilahrs_pahr_t *out, ilahrs_error_t *err)
{
    int64_t scaled[ILAHRS_PAHR_FIELD_COUNT];
    size_t k;
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        double value = values[k];
        if (!ilahrs_pahr_fields[k].hex) {
            if (!(value - value == 0.0)) { /* NaN or infinite */
                return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NAME(ilahrs_pahr_fields[k].name));
            }
            value *= (double)ilahrs_pahr_fields[k].divisor;
        }
        scaled[k] = pahr_round(value);
        if (ilahrs_pahr_fields[k].hex && (double)scaled[k] != value) {
            scaled[k] = (int64_t)PAHR_HUGE; /* not an integer: refused below */
        }
    }
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        if (scaled[k] < ilahrs_pahr_fields[k].min || scaled[k] > ilahrs_pahr_fields[k].max) {
            return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NAME(ilahrs_pahr_fields[k].name));
        }
    }
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        store_bits((uint8_t *)out + ilahrs_pahr_fields[k].member, (uint32_t)(int32_t)scaled[k], ilahrs_pahr_fields[k].size);
    }
    return true;
}

bool ilahrs_pahr_from_values(double roll, double pitch, double heading, double temperature, double vdd, uint16_t usw, ilahrs_pahr_t *out, ilahrs_error_t *err)
{
    double values[ILAHRS_PAHR_FIELD_COUNT];
    values[0] = (double)roll;
    values[1] = (double)pitch;
    values[2] = (double)heading;
    values[3] = (double)temperature;
    values[4] = (double)vdd;
    values[5] = (double)usw;
    return ilahrs_pahr_from_array(values, out, err);
}

/* ---- Stream decoder ------------------------------------------------------------------- */

#define NEED_MORE (-1)
#define INVALID 0

static bool may_start(uint8_t byte)
{
    return byte == ILAHRS_FRAME_HEADER_0 || byte == PAHR_START;
}

/* The message at p[0..n): its size if valid, INVALID, or NEED_MORE bytes to decide. */
static int candidate(const uint8_t *p, size_t n, ilahrs_message_t *msg)
{
    if (p[0] == ILAHRS_FRAME_HEADER_0) {
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
        if (!message_type_valid(get_le(p + ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, ILAHRS_FRAME_MESSAGE_TYPE_SIZE))) {
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
        if (ilahrs_checksum(p + ILAHRS_FRAME_HEADER_SIZE, at - ILAHRS_FRAME_HEADER_SIZE)
            != get_le(p + at, ILAHRS_FRAME_CHECKSUM_SIZE)) {
            return INVALID;
        }
        msg->kind = ILAHRS_MESSAGE_FRAME;
        msg->data = p;
        msg->size = total;
        msg->frame.message_type = (uint8_t)get_le(p + ILAHRS_FRAME_MESSAGE_TYPE_OFFSET, ILAHRS_FRAME_MESSAGE_TYPE_SIZE);
        msg->frame.reserved = (uint8_t)get_le(p + ILAHRS_FRAME_RESERVED_OFFSET, ILAHRS_FRAME_RESERVED_SIZE);
        msg->frame.payload = p + ILAHRS_FRAME_PAYLOAD_OFFSET;
        msg->frame.payload_size = at - ILAHRS_FRAME_PAYLOAD_OFFSET;
        return (int)total;
    }
    {
        size_t limit = n < ILAHRS_PAHR_MAX_LENGTH ? n : ILAHRS_PAHR_MAX_LENGTH;
        const uint8_t *lf = (const uint8_t *)memchr(p, PAHR_LF, limit);
        size_t i;
        if (lf == NULL) {
            if (n >= ILAHRS_PAHR_MAX_LENGTH) {
                return INVALID;
            }
            /* Reject now what can never become a sentence: a wrong identifier, or a byte that
             * is not printable (CR only as the last byte so far). Waiting gives the same answer. */
            for (i = 1; i < n && i < PAHR_PREFIX_LENGTH; i++) {
                if (p[i] != (uint8_t)PAHR_PREFIX[i]) {
                    return INVALID;
                }
            }
            for (; i < n; i++) {
                if ((p[i] < 0x20 || p[i] > 0x7E) && !(p[i] == PAHR_CR && i == n - 1)) {
                    return INVALID;
                }
            }
            return NEED_MORE;
        }
        i = (size_t)(lf - p) + 1;
        if (!ilahrs_pahr_parse((const char *)p, i, &msg->sentence, NULL)) {
            return INVALID;
        }
        msg->kind = ILAHRS_MESSAGE_SENTENCE;
        msg->data = p;
        msg->size = i;
        return (int)i;
    }
}

void ilahrs_stream_init(ilahrs_stream_t *stream)
{
    memset(stream, 0, sizeof *stream);
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
    size_t fresh = 0; /* of those, how many are still in buf (always its last bytes) */
    if (s->start != 0) {
        memmove(buf, buf + s->start, s->count);
        s->start = 0;
    }
    count = s->count;
    for (;;) {
        size_t add = *len - taken;
        if (add > sizeof s->held - count) {
            add = sizeof s->held - count;
        }
        if (add > 0) {
            memcpy(buf + count, *data + taken, add);
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
            memmove(buf, buf + pos, count - pos);
            s->start = 0;
            s->count = (uint8_t)(count - pos);
            if (taken > 0) {
                *data += taken;
                *len -= taken;
            }
            return false;
        }
        /* The buffer is full and the candidate at pos waits: make room, take more input. */
        memmove(buf, buf + pos, count - pos);
        count -= pos;
        if (fresh > count) {
            fresh = count;
        }
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
        memmove(s->held, s->held + s->start, s->count);
        s->start = 0;
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
