
/* ======================================================================================== */
/* $PAHR sentences                                                                          */
/* ======================================================================================== */

/**
 * Decode one sentence, "$" through CR LF, `len` characters at `text` (no NUL needed).
 *
 * Checks, in order: "$" (`bad_header` at 0), the identifier and "," (`bad_header` at 1), the CR
 * LF end (`truncated` at `len` if none, `bad_length` at ILAHRS_PAHR_MAX_LENGTH if it ends
 * beyond, `trailing_data` after it), "*" and two hex digits before CR LF (`malformed`), the
 * XOR checksum (`bad_checksum` at its first digit), ILAHRS_PAHR_FIELD_COUNT fields
 * (`malformed`), then each field's grammar (`malformed`) and range (`out_of_range`) at the
 * field's first character, naming it. Decimal fields accept any number of integer digits and 1
 * to `decimals` fraction digits; hex fields (the USW) 1 to their width of hex digits of either
 * case (E16).
 *
 * @code
 *     ilahrs_pahr_t s;
 *     if (ilahrs_pahr_parse(line, line_len, &s, NULL)) {
 *         int32_t roll_centideg = s.roll;
 *     }
 * @endcode
 */
bool ilahrs_pahr_parse(const char *text, size_t len, ilahrs_pahr_t *out, ilahrs_error_t *err);

/**
 * Write a sentence, "$" through CR LF, into `out` (no printf, no floating point). Integer
 * parts are zero-padded to the template width, the sign counting as one character (roll
 * -1234 is "-012.34"); the USW and the checksum are upper-case hex (E16). A NUL follows the
 * sentence if `cap` leaves room for it. Refuses a value outside its range (`out_of_range`,
 * naming the field) and a `cap` shorter than the sentence (`buffer_too_small`).
 * @return the sentence length (at most ILAHRS_PAHR_MAX_LENGTH), or 0 on failure
 */
size_t ilahrs_pahr_build(const ilahrs_pahr_t *in, char *out, size_t cap, ilahrs_error_t *err);

/**
 * ilahrs_pahr_from_values() with the values in an array, in field order (a hex field's value
 * must be an integer, else `out_of_range`).
 */
bool ilahrs_pahr_from_array(const double values[ILAHRS_PAHR_FIELD_COUNT], ilahrs_pahr_t *out, ilahrs_error_t *err);

#if ILAHRS_NAMES
/** The spec name of sentence field `index` (0..ILAHRS_PAHR_FIELD_COUNT-1); NULL otherwise. */
const char *ilahrs_pahr_field_name(size_t index);
#endif

/** The range of sentence field `index` (scaled values); false if `index` is out of range. */
bool ilahrs_pahr_field_range(size_t index, int32_t *min, int32_t *max);

/** 10^decimals of decimal sentence field `index` (engineering = value / divisor); 0 for a hex field. */
uint32_t ilahrs_pahr_field_divisor(size_t index);

/** The (scaled) value of sentence field `index`; 0 if `index` is out of range. */
int32_t ilahrs_pahr_field_get(const ilahrs_pahr_t *sentence, size_t index);
