// Copied from generator/targets/c/runtime/examples/decode_capture.c for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
/*
 * decode_capture: print every message in a capture of AHRS output.
 *
 *   cc -std=c99 -I.. decode_capture.c ../ilahrs.c -o decode_capture
 *   ./decode_capture capture.bin        (or - for standard input)
 *
 * Reads the file in 4 KiB chunks, feeds them to the stream decoder and prints one line per
 * frame or $PAHR sentence, then how many bytes belonged to no message. A frame's payload is
 * printed as hex: the frame does not say which payload table it follows (E7), so decode it
 * with ilahrs_<table>_parse() once you know from the command you sent.
 */
#include "ilahrs.h"

#include <stdio.h>
#include <string.h>

static void print_hex(const uint8_t *data, size_t size)
{
    size_t i;
    for (i = 0; i < size; i++) {
        printf("%02X", data[i]);
    }
}

/* A scaled integer as a decimal number, e.g. -1234 / 100 -> -12.34. */
static void print_scaled(long value, long divisor)
{
    int decimals = 0;
    long d;
    for (d = divisor; d > 1; d /= 10) {
        decimals++;
    }
    if (value < 0) {
        putchar('-');
        value = -value;
    }
    if (decimals == 0) {
        printf("%ld", value);
    } else {
        printf("%ld.%0*ld", value / divisor, decimals, value % divisor);
    }
}

static void print_message(unsigned long index, const ilahrs_message_t *msg)
{
    printf("%6lu ", index);
    if (msg->kind == ILAHRS_MESSAGE_FRAME) {
        const ilahrs_frame_t *f = &msg->frame;
        ilahrs_command_match_t match;
        printf("frame type=%u reserved=%u payload=", (unsigned)f->message_type, (unsigned)f->reserved);
        print_hex(f->payload, f->payload_size);
        if (ilahrs_command_decode(msg->data, msg->size, &match, NULL)) {
            unsigned i;
            printf(" command=");
            for (i = 0; i < match.count; i++) {
                printf("%s%s", i > 0 ? "/" : "", ilahrs_command_name(match.commands[i]));
            }
        }
        printf("\n");
        return;
    }
    {
        /* The fields from the sentence's field table; the hex one is the Unit Status Word. */
        const ilahrs_pahr_t *s = &msg->sentence;
        uint16_t usw = 0;
        size_t k;
        printf("sentence");
        for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
            int32_t value = ilahrs_pahr_field_get(s, k);
            uint32_t divisor = ilahrs_pahr_field_divisor(k);
            printf(" %s=", ilahrs_pahr_field_name(k));
            if (divisor == 0) {
                printf("%04X", (unsigned)value);
                usw = (uint16_t)value;
            } else {
                print_scaled((long)value, (long)divisor);
            }
        }
        printf(" mode=%u", (unsigned)ilahrs_usw_decode(usw).mode);
        printf("\n");
    }
}

int main(int argc, char **argv)
{
    static uint8_t chunk[4096];
    ilahrs_stream_t decoder;
    ilahrs_message_t msg;
    unsigned long frames = 0;
    unsigned long sentences = 0;
    FILE *in;
    size_t got;

    if (argc != 2) {
        fprintf(stderr, "usage: %s CAPTURE-FILE (- for standard input)\n", argv[0]);
        return 2;
    }
    in = strcmp(argv[1], "-") == 0 ? stdin : fopen(argv[1], "rb");
    if (in == NULL) {
        perror(argv[1]);
        return 1;
    }
    ilahrs_stream_init(&decoder);
    do {
        const uint8_t *p = chunk;
        size_t n;
        got = fread(chunk, 1, sizeof chunk, in);
        n = got;
        while (got > 0 ? ilahrs_stream_next(&decoder, &p, &n, &msg) : ilahrs_stream_finish(&decoder, &msg)) {
            print_message(frames + sentences, &msg);
            if (msg.kind == ILAHRS_MESSAGE_FRAME) {
                frames++;
            } else {
                sentences++;
            }
        }
    } while (got > 0);
    if (in != stdin) {
        fclose(in);
    }
    printf("%lu frames, %lu sentences, %lu bytes discarded\n", frames, sentences, (unsigned long)decoder.discarded);
    return 0;
}
