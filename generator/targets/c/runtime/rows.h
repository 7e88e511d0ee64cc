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
