/*
 * The smallest firmware that decodes the AHRS stream on a Cortex-M4: a loop that reads a UART
 * data register and feeds each byte to the stream decoder, as an interrupt handler would. Linked
 * with --gc-sections and nothing else, its image is the decoder's closure plus this loop; the
 * decoder state is static, so the image's RAM is everything the decoder keeps per channel.
 * Built by bench/mavlink/compare.py for the size comparison only (never run).
 */
#include "ilahrs.h"

#define UART_DATA (*(volatile const uint8_t *)0x40004000u)

volatile uint32_t sink;

int main(void);

int main(void)
{
    static ilahrs_stream_t decoder;
    ilahrs_stream_init(&decoder);
    for (;;) {
        ilahrs_message_t msg;
        if (ilahrs_stream_push(&decoder, UART_DATA, &msg)) {
            do {
                sink += (uint32_t)msg.size;
            } while (ilahrs_stream_poll(&decoder, &msg));
        }
    }
}
