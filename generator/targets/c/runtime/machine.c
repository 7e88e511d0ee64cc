/* On its own (an editor, `make lint-c`), this file includes what precedes it in ilahrs.c:
 * the helpers. ilahrs.c holds it without this include. */
#include "core.c"

/* ---- Device state machine -------------------------------------------------------------- */

#if ILAHRS_NAMES
const char *ilahrs_state_name(ilahrs_state_t state)
{
    return name_at((unsigned)state, NAMES_STATE, ILAHRS_STATE_COUNT);
}

bool ilahrs_state_by_name(const char *name, size_t len, ilahrs_state_t *state)
{
    int i = name_index(name, len, NAMES_STATE, ILAHRS_STATE_COUNT);
    if (i < 0) {
        return false;
    }
    *state = (ilahrs_state_t)i;
    return true;
}

const char *ilahrs_event_name(ilahrs_event_t event)
{
    return name_at((unsigned)event, NAMES_COMMAND, ILAHRS_EVENT_COUNT); /* commands, then the other events */
}

bool ilahrs_event_by_name(const char *name, size_t len, ilahrs_event_t *event)
{
    int i = name_index(name, len, NAMES_COMMAND, ILAHRS_EVENT_COUNT);
    if (i < 0) {
        return false;
    }
    *event = (ilahrs_event_t)i;
    return true;
}

const char *ilahrs_answer_name(ilahrs_answer_t answer)
{
    return name_at((unsigned)answer, NAMES_ANSWER, ILAHRS_ANSWER_COUNT);
}
#endif

ilahrs_mode_t ilahrs_state_mode(ilahrs_state_t state)
{
    return (ilahrs_mode_t)((unsigned)state < ILAHRS_STATE_COUNT ? ilahrs_state_modes[state] : ILAHRS_MODE_COUNT);
}

ilahrs_payload_t ilahrs_state_expects(ilahrs_state_t state)
{
    return (unsigned)state < ILAHRS_STATE_COUNT ? (ilahrs_payload_t)ilahrs_state_blocks[state] : ILAHRS_PAYLOAD_NONE;
}

bool ilahrs_state_timer(ilahrs_state_t state, ilahrs_event_t *event)
{
    if ((unsigned)state >= ILAHRS_STATE_COUNT || ilahrs_state_timers[state] == ILAHRS_EVENT_COUNT) {
        return false;
    }
    *event = (ilahrs_event_t)ilahrs_state_timers[state];
    return true;
}

ilahrs_payload_t ilahrs_answer_payload(ilahrs_answer_t answer)
{
    return (unsigned)answer < ILAHRS_ANSWER_COUNT ? (ilahrs_payload_t)ilahrs_answers[answer].payload
                                                  : ILAHRS_PAYLOAD_NONE;
}

#ifdef ILAHRS_USW_FLAGS_MASK
bool ilahrs_answer_usw_mode(ilahrs_answer_t answer, ilahrs_usw_mode_t *mode)
{
    if ((unsigned)answer >= ILAHRS_ANSWER_COUNT || ilahrs_answers[answer].usw_mode == NO_USW_MODE) {
        return false;
    }
    *mode = (ilahrs_usw_mode_t)ilahrs_answers[answer].usw_mode;
    return true;
}
#endif

ilahrs_event_t ilahrs_event_for_code(ilahrs_state_t state, uint8_t code)
{
    unsigned modes = (unsigned)state < ILAHRS_STATE_COUNT ? ILAHRS_MODE_BIT(ilahrs_state_modes[state]) : 0u;
    unsigned named = 0;
    unsigned only = 0;
    unsigned i;
    for (i = 0; i < ILAHRS_COMMAND_COUNT; i++) {
        unsigned id = ilahrs_commands_by_code[i];
        if (ilahrs_command_codes[id] != code) {
            continue;
        }
        if ((ilahrs_command_modes[id] & modes) != 0) {
            return (ilahrs_event_t)id; /* the name valid in this mode */
        }
        named++;
        only = id;
    }
    if (named == 1) {
        return (ilahrs_event_t)only;
    }
    /* A shared code where no name is valid: the name marked default_for_code (E14). */
    for (i = 0; i < CODE_DEFAULT_COUNT; i++) {
        if (ilahrs_command_codes[ilahrs_code_defaults[i]] == code) {
            return (ilahrs_event_t)ilahrs_code_defaults[i];
        }
    }
    return ILAHRS_EVENT_UNKNOWN;
}

ilahrs_event_t ilahrs_event_for_data(ilahrs_state_t state, size_t payload_size)
{
    ilahrs_payload_t expects = ilahrs_state_expects(state);
    return expects != ILAHRS_PAYLOAD_NONE && payload_size == ilahrs_payloads[expects].size
               ? ILAHRS_EVENT_PARAMETER_BLOCK
               : ILAHRS_EVENT_OTHER_MESSAGE;
}

ilahrs_event_t ilahrs_event_for_frame(ilahrs_state_t state, const ilahrs_frame_t *frame)
{
    if (frame->message_type == ILAHRS_MESSAGE_TYPE_COMMAND && frame->payload_size == 1) {
        return ilahrs_event_for_code(state, frame->payload[0]);
    }
    return ilahrs_event_for_data(state, frame->payload_size);
}

/* Outcome k (a row of ilahrs_outcomes): the next state and the answers of its sequence. */
static bool outcome(unsigned k, ilahrs_step_t *out)
{
    unsigned sends = ilahrs_outcomes[k] & ((1u << SEQUENCE_BITS) - 1u);
    unsigned from = ilahrs_send_start[sends];
    unsigned n = ilahrs_send_start[sends + 1u] - from;
    unsigned i;
    out->to = (ilahrs_state_t)(ilahrs_outcomes[k] >> SEQUENCE_BITS);
    out->send_count = (uint8_t)n;
    for (i = 0; i < n && i < ILAHRS_STEP_SEND_MAX; i++) {
        out->send[i] = (ilahrs_answer_t)ilahrs_sends[from + i];
    }
    return true;
}

/* The row of ilahrs_legacy (rows that apply only to firmware before a version, and there take
 * precedence) for (state, event) that applies to `firmware` (NULL with `any`: every legacy row
 * applies), or -1. */
static int legacy_row(unsigned state, unsigned event, const ilahrs_firmware_t *firmware, bool any)
{
    unsigned i;
    for (i = 0; i < LEGACY_COUNT; i++) {
        if (ilahrs_legacy[i].state != state || ilahrs_legacy[i].event != event) {
            continue;
        }
        if (any) {
            return (int)i;
        }
        if (firmware != NULL
            && ilahrs_firmware_compare(firmware, &ilahrs_legacy_versions[ilahrs_legacy[i].version]) < 0) {
            return (int)i;
        }
    }
    return -1;
}

/* The table: state x event -> outcome + 1, 0 for an ignored event (E33). Each state has a default
 * cell (ilahrs_state_cells), and ilahrs_cells lists the cells that differ from their state's
 * default (CELL()). */
static bool transition(ilahrs_state_t state, ilahrs_event_t event, int legacy, ilahrs_step_t *out)
{
    unsigned cell;
    unsigned key;
    unsigned i;
    out->to = state;
    out->send_count = 0;
    if ((unsigned)state >= ILAHRS_STATE_COUNT || (unsigned)event >= ILAHRS_EVENT_COUNT) {
        return false;
    }
    if (legacy >= 0) {
        return outcome(ilahrs_legacy[legacy].outcome, out);
    }
    cell = ilahrs_state_cells[state];
    key = (unsigned)state * ILAHRS_EVENT_COUNT + (unsigned)event;
    for (i = 0; i < CELL_COUNT; i++) {
        if (ilahrs_cells[i] >> CELL_BITS == key) {
            cell = ilahrs_cells[i] & ((1u << CELL_BITS) - 1u);
            break;
        }
    }
    return cell != 0 && outcome(cell - 1u, out);
}

bool ilahrs_transition(ilahrs_state_t state, ilahrs_event_t event, bool older_firmware, ilahrs_step_t *out)
{
    return transition(state, event, older_firmware ? legacy_row((unsigned)state, (unsigned)event, NULL, true) : -1,
                      out);
}

bool ilahrs_transition_on(ilahrs_state_t state, ilahrs_event_t event, const ilahrs_firmware_t *firmware,
                          ilahrs_step_t *out)
{
    return transition(state, event, legacy_row((unsigned)state, (unsigned)event, firmware, false), out);
}

bool ilahrs_firmware_parse(const char *text, size_t len, ilahrs_firmware_t *firmware, ilahrs_error_t *err)
{
    size_t i = 0;
    zero_bytes(firmware, sizeof *firmware);
    for (;;) {
        size_t start = i;
        uint32_t part = 0;
        while (i < len && text[i] >= '0' && text[i] <= '9') {
            uint32_t digit = (uint32_t)(text[i] - '0');
            if (part > (0xFFFFFFFFu - digit) / 10u) {
                return fail(err, ILAHRS_ERR_MALFORMED, start, NULL);
            }
            part = part * 10u + digit;
            i++;
        }
        if (i == start || (i < len && text[i] != '.') || firmware->count == ILAHRS_FIRMWARE_PARTS_MAX) {
            return fail(err, ILAHRS_ERR_MALFORMED, start, NULL);
        }
        firmware->parts[firmware->count++] = part;
        if (i == len) {
            return true;
        }
        i++; /* the "." */
    }
}

int ilahrs_firmware_compare(const ilahrs_firmware_t *a, const ilahrs_firmware_t *b)
{
    unsigned i;
    for (i = 0; i < a->count && i < b->count && i < ILAHRS_FIRMWARE_PARTS_MAX; i++) {
        if (a->parts[i] != b->parts[i]) {
            return a->parts[i] < b->parts[i] ? -1 : 1;
        }
    }
    return a->count < b->count ? -1 : a->count > b->count ? 1 : 0;
}
