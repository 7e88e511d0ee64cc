/* Builds a command frame through the installed library and prints its length. */
#include <stdio.h>

#include "ilahrs.h"

int main(void) {
    uint8_t frame[64];
    ilahrs_error_t err;
    size_t length = ilahrs_command_build(ILAHRS_COMMAND_STOP, frame, sizeof frame, &err);
    if (length == 0) {
        return 1;
    }
    printf("%lu\n", (unsigned long)length);
    return 0;
}
