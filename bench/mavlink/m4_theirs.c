/*
 * The same firmware as m4_ours.c with MAVLink's decoder: each byte of the UART data register
 * through mavlink_parse_char() on channel 0 (MAVLINK_COMM_NUM_BUFFERS 1: one channel's static
 * parse buffer and status). Built by bench/mavlink/compare.py for the size comparison only.
 */
#include <mavlink.h>

#define UART_DATA (*(volatile const uint8_t *)0x40004000u)

volatile uint32_t sink;

int main(void);

int main(void)
{
    for (;;) {
        mavlink_message_t msg;
        mavlink_status_t status;
        if (mavlink_parse_char(MAVLINK_COMM_0, UART_DATA, &msg, &status)) {
            sink += (uint32_t)msg.len;
        }
    }
}
