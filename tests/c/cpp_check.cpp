// The C header used from C++: it must compile warning-free, link against the C object
// (extern "C"), and its inline helpers must work. Built and run by `make lint-c`.
#include "ilahrs.h"

#include <cstdio>
#include <cstring>

int main()
{
    ilahrs_stream_t decoder = {};
    ilahrs_message_t msg;
    uint8_t frame[ILAHRS_FRAME_MAX_SIZE];
    size_t n = ilahrs_build_ahrs_cont3(frame, sizeof frame, NULL);
    const uint8_t *p = frame;
    int messages = 0;
    while (ilahrs_stream_next(&decoder, &p, &n, &msg)) {
        messages++;
    }
    ilahrs_orientation_sensors_t o;
    std::memset(&o, 0, sizeof o);
    o.heading = 9000;
    o.gyro_x = 100;
    ilahrs_usw_t usw = ilahrs_usw_decode(0x8080);
    // LoadAHRSPar and its parameter block (6.3.6), from the builders' defaults.
    ilahrs_ahrs_parameters_load_t block;
    ilahrs_payload_defaults(ILAHRS_PAYLOAD_AHRS_PARAMETERS_LOAD, &block);
    uint8_t block_frame[ILAHRS_FRAME_MAX_SIZE];
    ilahrs_frame_t parsed;
    size_t block_size = ilahrs_build_load_ahrs_par_block(&block, block_frame, sizeof block_frame, NULL);
    ilahrs_ahrs_parameters_load_t again;
    bool block_ok = block_size == ILAHRS_AHRS_PARAMETERS_LOAD_SIZE + ILAHRS_FRAME_OVERHEAD
                 && ilahrs_frame_parse(block_frame, block_size, &parsed, NULL)
                 && parsed.message_type == ILAHRS_MESSAGE_TYPE_DATA
                 && ilahrs_ahrs_parameters_load_parse(parsed.payload, parsed.payload_size, &again, NULL)
                 && std::memcmp(&block, &again, sizeof block) == 0;
    float dps = ilahrs_orientation_sensors_gyro_x_dps(&o, ILAHRS_VARIANT_G300_A2_TMGA);
    bool ok = block_ok && messages == 1 && ilahrs_orientation_sensors_heading_deg(&o) == 90.0f && dps == 1.0f
           && usw.mode == ILAHRS_USW_MODE_SLEEP && std::strcmp(ilahrs_error_kind_name(ILAHRS_ERR_TRUNCATED), "truncated") == 0;
    std::printf("cpp_check: %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
