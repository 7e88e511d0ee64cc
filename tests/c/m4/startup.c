/*
 * Reset and fault vectors for running the C tests on an emulated Cortex-M4: qemu-system-arm's
 * MPS2 AN386 board (make test-c-m4). newlib's rdimon crt0 (_start) does the rest: it zeroes
 * .bss, takes argc/argv from the host by semihosting, calls main() and hands the exit status back
 * to qemu. A fault (an unaligned multi-word access, a bad pointer...) ends the run with status 98
 * instead of hanging it.
 */
#include <stdlib.h>

extern void _start(void);
extern void __stack(void); /* the linker script's stack top; declared as a function for the table */

static void fault(void)
{
    _Exit(98);
}

__attribute__((section(".vectors"), used)) static void (*const vectors[16])(void) = {
    __stack, _start, fault, fault, fault, fault, fault, 0, 0, 0, 0, fault, fault, 0, fault, fault,
};
