// Copied from generator/targets/rust/runtime/crate/state_machine/device.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! What the state machine does with its table: look a (state, event) pair up, compare firmware
//! versions, and hold a device's state. No allocation, no I/O.

use super::{Answer, Event, State, MAX_FIRMWARE_PARTS, OLDER_FIRMWARE, TRANSITIONS};
use crate::command::Command;
use crate::error::{Detail, Error, ErrorKind, Result};

impl State {
    /// The state whose spec name is `name`.
    pub fn from_name(name: &str) -> Option<State> {
        State::ALL.into_iter().find(|state| state.name() == name)
    }
}

impl Event {
    /// The event whose table name is `name`.
    pub fn from_name(name: &str) -> Option<Event> {
        Event::ALL.into_iter().find(|event| event.name() == name)
    }

    /// The event of receiving a data message whose payload is `payload_size` bytes in `state`:
    /// `parameter_block` when the state expects a block of that size, else `other_message`.
    pub const fn for_data(payload_size: usize, state: State) -> Event {
        match state.expects() {
            Some(block) if block.size() == payload_size => Event::ParameterBlock,
            _ => Event::OtherMessage,
        }
    }
}

impl From<Command> for Event {
    fn from(command: Command) -> Event {
        Event::from_command(command)
    }
}

/// One cell of the table: the state to go to and what to send, in order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Transition {
    /// The state after the event.
    pub next: State,
    /// What the device sends (none: nothing).
    pub sends: &'static [Answer],
}

/// One row of the table: in `state`, on `event`, take `transition`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Row {
    /// The state the row applies in.
    pub state: State,
    /// The event it applies to.
    pub event: Event,
    /// What the device does.
    pub transition: Transition,
}

/// A row of the table.
pub(super) const fn row(state: State, event: Event, next: State, sends: &'static [Answer]) -> Row {
    Row {
        state,
        event,
        transition: Transition { next, sends },
    }
}

/// What the device does on `event` in `state`, running `firmware` (`None`: current firmware);
/// `None` if it ignores the event.
pub fn transition(state: State, event: Event, firmware: Option<Firmware>) -> Option<Transition> {
    if let Some(firmware) = firmware {
        let older = OLDER_FIRMWARE.iter().find(|(before, row)| {
            row.state == state && row.event == event && firmware.parts() < *before
        });
        if let Some((_, row)) = older {
            return Some(row.transition);
        }
    }
    let at = TRANSITIONS.partition_point(|row| (row.state, row.event) < (state, event));
    TRANSITIONS
        .get(at)
        .filter(|row| row.state == state && row.event == event)
        .map(|row| row.transition)
}

/// A firmware version such as `4.9.9.0`: numeric parts, compared in order (a version that
/// another one extends is the older: 4.9 is before 4.9.0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Firmware {
    parts: [u32; MAX_FIRMWARE_PARTS],
    len: usize,
}

impl Firmware {
    /// The version with these parts, or `None` for none or more than [`MAX_FIRMWARE_PARTS`].
    pub fn new(parts: &[u32]) -> Option<Firmware> {
        let mut version = Firmware {
            parts: [0; MAX_FIRMWARE_PARTS],
            len: parts.len(),
        };
        if parts.is_empty() {
            return None;
        }
        version.parts.get_mut(..parts.len())?.copy_from_slice(parts);
        Some(version)
    }

    /// Parses a version: decimal numbers separated by `.`. Errors: `malformed` (at the offset
    /// of the bad part) for an empty or non-numeric part, a number above `u32::MAX` or more than
    /// [`MAX_FIRMWARE_PARTS`] parts.
    pub fn parse(text: &str) -> Result<Firmware> {
        let mut parts = [0u32; MAX_FIRMWARE_PARTS];
        let mut len = 0;
        let mut at = 0;
        for part in text.split('.') {
            let digits = part.bytes().all(|byte| byte.is_ascii_digit());
            let value = part.parse::<u32>().ok().filter(|_| digits);
            let expected = match (value, parts.get_mut(len)) {
                (Some(value), Some(slot)) => {
                    *slot = value;
                    None
                }
                (None, _) => Some("a decimal number up to 4294967295"),
                (Some(_), None) => Some("the end of the version"),
            };
            if let Some(expected) = expected {
                let error = Error::at(ErrorKind::Malformed, at);
                return Err(error.with_detail(Detail::Expected(expected)));
            }
            len += 1;
            at += part.len() + 1;
        }
        Ok(Firmware { parts, len })
    }

    /// The numeric parts.
    pub fn parts(&self) -> &[u32] {
        self.parts.get(..self.len).unwrap_or(&self.parts)
    }
}

impl PartialOrd for Firmware {
    fn partial_cmp(&self, other: &Firmware) -> Option<core::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Firmware {
    fn cmp(&self, other: &Firmware) -> core::cmp::Ordering {
        self.parts().cmp(other.parts())
    }
}

/// A device's state machine: its state and firmware. Events go in; the transition taken (what
/// to send) comes out.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Device {
    state: State,
    firmware: Option<Firmware>,
}

impl Device {
    /// A device in its initial state, running `firmware` (`None`: current firmware).
    pub const fn new(firmware: Option<Firmware>) -> Device {
        Device {
            state: State::INITIAL,
            firmware,
        }
    }

    /// The current state.
    pub const fn state(&self) -> State {
        self.state
    }

    /// Applies `event`: the transition taken, or `None` if the device ignores it (the state
    /// stays).
    pub fn handle(&mut self, event: Event) -> Option<Transition> {
        let step = transition(self.state, event, self.firmware);
        if let Some(step) = step {
            self.state = step.next;
        }
        step
    }

    /// Applies a received command frame with `code`: its event and the transition taken.
    pub fn handle_command(&mut self, code: u8) -> (Event, Option<Transition>) {
        let event = Event::for_code(code, self.state);
        (event, self.handle(event))
    }

    /// Applies a received data message whose payload is `payload_size` bytes: its event and the
    /// transition taken.
    pub fn handle_data(&mut self, payload_size: usize) -> (Event, Option<Transition>) {
        let event = Event::for_data(payload_size, self.state);
        (event, self.handle(event))
    }
}

#[cfg(test)]
mod tests {
    use crate::command::Command;
    use crate::error::ErrorKind;
    use crate::frame;

    #[test]
    fn the_lookup_finds_every_row_and_nothing_else() {
        use super::{transition, Event, State, TRANSITIONS};
        let mut found = 0;
        for state in State::ALL {
            for event in Event::ALL {
                let row = TRANSITIONS
                    .iter()
                    .find(|row| row.state == state && row.event == event);
                assert_eq!(
                    transition(state, event, None),
                    row.map(|row| row.transition)
                );
                found += usize::from(row.is_some());
            }
        }
        assert_eq!(found, TRANSITIONS.len());
        assert!(TRANSITIONS
            .windows(2)
            .all(|pair| (pair[0].state, pair[0].event) < (pair[1].state, pair[1].event)));
    }

    #[test]
    fn older_firmware_rows_apply_only_below_their_version() {
        use super::{transition, Firmware, OLDER_FIRMWARE};
        let oldest = Firmware::new(&[0]).unwrap();
        for (before, row) in OLDER_FIRMWARE {
            let at = Firmware::new(before).unwrap();
            let current = transition(row.state, row.event, None);
            assert_eq!(
                transition(row.state, row.event, Some(oldest)),
                Some(row.transition)
            );
            assert_eq!(transition(row.state, row.event, Some(at)), current);
        }
    }

    #[test]
    fn firmware_versions_parse_and_compare_part_by_part() {
        use super::{Firmware, MAX_FIRMWARE_PARTS};
        let parse =
            |text: &str| Firmware::parse(text).map_err(|error| (error.kind(), error.offset()));
        assert_eq!(parse("4.9.9.0").unwrap().parts(), &[4, 9, 9, 0]);
        assert!(parse("4.9").unwrap() < parse("4.9.0").unwrap());
        assert!(parse("4.10").unwrap() > parse("4.9.9.0").unwrap());
        assert_eq!(parse(""), Err((ErrorKind::Malformed, Some(0))));
        assert_eq!(parse("4..1"), Err((ErrorKind::Malformed, Some(2))));
        assert_eq!(parse("4.x"), Err((ErrorKind::Malformed, Some(2))));
        assert_eq!(parse("4.99999999999"), Err((ErrorKind::Malformed, Some(2))));
        let long = [1u32; MAX_FIRMWARE_PARTS + 1];
        assert!(Firmware::new(&long).is_none());
        assert!(Firmware::new(&long[1..]).is_some());
        assert!(Firmware::new(&[]).is_none());
    }

    #[test]
    fn wire_input_maps_to_events_by_mode_and_size() {
        use super::{Event, State};
        for state in State::ALL {
            for code in 0..=255u8 {
                let event = Event::for_code(code, state);
                match event.command() {
                    Some(command) => {
                        assert_eq!(command.code(), code);
                        let valid = Command::with_code(code)
                            .iter()
                            .any(|named| named.valid_in().contains(&state.mode()));
                        assert!(!valid || command.valid_in().contains(&state.mode()));
                    }
                    None => assert!(Command::with_code(code).is_empty()),
                }
            }
            for size in 0..=frame::MAX_PAYLOAD {
                let event = Event::for_data(size, state);
                let fits = state.expects().is_some_and(|block| block.size() == size);
                assert_eq!(event == Event::for_data(usize::MAX, state), !fits);
            }
        }
    }
}
