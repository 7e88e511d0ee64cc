
/* ======================================================================================== */
/* Device state machine                                                                     */
/* ======================================================================================== */

/*
 * What the AHRS does with each input in each state: the `state_machine` of the spec as a const
 * table (spec/README.md, "The device state machine"). A device firmware steps it on every
 * message and timer; a host uses it to know which answer to expect. A (state, event) pair with
 * no transition is ignored: no answer, no change of state (E33).
 *
 * @code
 *     ilahrs_state_t state = ILAHRS_STATE_INITIAL;
 *     ilahrs_frame_t frame;                 // a message received, e.g. from the stream decoder
 *     ilahrs_step_t step;
 *     ilahrs_event_t event = ilahrs_event_for_frame(state, &frame);
 *     if (ilahrs_transition(state, event, false, &step)) {
 *         for (unsigned i = 0; i < step.send_count; i++) {
 *             send_answer(step.send[i]);      // ack, output, or a payload table
 *         }
 *     }
 *     state = step.to;                      // also right when the event was ignored
 * @endcode
 */

/** One transition: the next state and what the device sends, in order. */
typedef struct ilahrs_step {
    ilahrs_state_t to;                          /**< The state after the event. */
    uint8_t send_count;                         /**< Entries in `send` (0: nothing). */
    ilahrs_answer_t send[ILAHRS_STEP_SEND_MAX]; /**< What the device sends. */
} ilahrs_step_t;

#if ILAHRS_NAMES
/** The spec name of a state ("idle"); NULL for a value outside ilahrs_state_t. */
const char *ilahrs_state_name(ilahrs_state_t state);
/** Find a state by its spec name, `len` characters at `name`. */
bool ilahrs_state_by_name(const char *name, size_t len, ilahrs_state_t *state);
#endif
/** The operating mode of a state; ILAHRS_MODE_COUNT for a value outside ilahrs_state_t. */
ilahrs_mode_t ilahrs_state_mode(ilahrs_state_t state);
/** The payload table of the parameter block a state waits for (E34), or ILAHRS_PAYLOAD_NONE. */
ilahrs_payload_t ilahrs_state_expects(ilahrs_state_t state);
/** The event the timer of a state fires (see ilahrs_event_t); false if the state runs no timer. */
bool ilahrs_state_timer(ilahrs_state_t state, ilahrs_event_t *event);

#if ILAHRS_NAMES
/** The name of an event: the ICD name of a command ("AHRScont1"), else the spec name ("unknown"); NULL if out of
 * range. */
const char *ilahrs_event_name(ilahrs_event_t event);
/** Find an event by its name (a command's ICD name or an event's spec name). */
bool ilahrs_event_by_name(const char *name, size_t len, ilahrs_event_t *event);

/** The spec name of an answer ("ack"); NULL for a value outside ilahrs_answer_t. */
const char *ilahrs_answer_name(ilahrs_answer_t answer);
#endif
/** The payload table an answer sends, or ILAHRS_PAYLOAD_NONE (ack and the output answers). */
ilahrs_payload_t ilahrs_answer_payload(ilahrs_answer_t answer);
#ifdef ILAHRS_USW_FLAGS_MASK
/**
 * The USW mode an output answer reports in place of the device's own (see ilahrs_answer_t, E35);
 * false for every other answer.
 */
bool ilahrs_answer_usw_mode(ilahrs_answer_t answer, ilahrs_usw_mode_t *mode);
#endif

/**
 * The event of a command frame with code `code` in `state`: of the commands sharing the code, the
 * one valid in the state's mode, else the code's default (0xFE: ExitClb in calibration, Stop
 * elsewhere, E14); ILAHRS_EVENT_UNKNOWN for a code no command has.
 */
ilahrs_event_t ilahrs_event_for_code(ilahrs_state_t state, uint8_t code);

/**
 * The event of a data message with a `payload_size`-byte payload in `state`:
 * ILAHRS_EVENT_PARAMETER_BLOCK if the state waits for a parameter block of that size, else
 * ILAHRS_EVENT_OTHER_MESSAGE.
 */
ilahrs_event_t ilahrs_event_for_data(ilahrs_state_t state, size_t payload_size);

/**
 * The event of a received frame in `state`: a command-type frame with a one-byte payload is
 * ilahrs_event_for_code(), any other frame ilahrs_event_for_data() (a parameter block may come
 * with either message type, E5).
 */
ilahrs_event_t ilahrs_event_for_frame(ilahrs_state_t state, const ilahrs_frame_t *frame);

/**
 * Look a (state, event) pair up. `older_firmware`: the device runs firmware older than the
 * version of the rows marked `firmware_before` (listed with ilahrs_answer_t above); those rows
 * then take precedence. ilahrs_transition_on() compares a version for you.
 *
 * @return true with `*out` filled; false if the device ignores the event (E33), or `state` or
 *         `event` is out of range, with `*out` set to (`state`, nothing), so that a caller may
 *         apply `*out` either way
 */
bool ilahrs_transition(ilahrs_state_t state, ilahrs_event_t event, bool older_firmware, ilahrs_step_t *out);

/** A firmware version such as 4.9.9.0: numeric parts compared in order. */
typedef struct ilahrs_firmware {
    uint32_t parts[ILAHRS_FIRMWARE_PARTS_MAX]; /**< The parts, most significant first. */
    uint8_t count;                             /**< Number of parts (1..ILAHRS_FIRMWARE_PARTS_MAX). */
} ilahrs_firmware_t;

/**
 * Read a version, decimal numbers separated by ".", `len` characters at `text`. Refuses
 * (`malformed` at the first character of the bad part) an empty or non-numeric part, a part above
 * 2^32 - 1 and more than ILAHRS_FIRMWARE_PARTS_MAX parts.
 */
bool ilahrs_firmware_parse(const char *text, size_t len, ilahrs_firmware_t *firmware, ilahrs_error_t *err);

/**
 * Compare two versions part by part as numbers (4.10.0.0 is after 4.9.9.0; a version that another
 * one extends is the older: 4.9 is before 4.9.0). Negative, zero or positive as `a` is before,
 * equal to or after `b`.
 */
int ilahrs_firmware_compare(const ilahrs_firmware_t *a, const ilahrs_firmware_t *b);

/**
 * ilahrs_transition() for a device running `firmware` (NULL: current firmware): a row marked
 * `firmware_before` applies when `firmware` is before its version.
 */
bool ilahrs_transition_on(ilahrs_state_t state, ilahrs_event_t event, const ilahrs_firmware_t *firmware,
                          ilahrs_step_t *out);
