// Copied from conformance/runners/rust/session.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runner source and run `make generate`.
//! The `session` request: the crate's device state machine, driven by a list of events.

use ilahrs::state_machine::{Device, Event, Firmware};

use crate::{Answer, Refusal};

/// Runs the device state machine from its initial state: `C:HH` a command code, `D:N` a data
/// message of N payload bytes, `E:NAME` another event; one `EVENT>STATE>SENDS` step each.
pub(crate) fn run(firmware: &str, events: &str) -> Answer {
    let firmware = match firmware {
        "-" => None,
        text => Some(Firmware::parse(text)?),
    };
    let mut device = Device::new(firmware);
    let mut steps: Vec<String> = Vec::new();
    for token in events.split(',') {
        let (event, step) = match token.split_once(':') {
            Some(("C", code)) => {
                let code = u8::from_str_radix(code, 16).map_err(|_| Refusal::Unsupported)?;
                device.handle_command(code)
            }
            Some(("D", size)) => {
                let size = size.parse().map_err(|_| Refusal::Unsupported)?;
                device.handle_data(size)
            }
            Some(("E", name)) => {
                let event = Event::from_name(name).ok_or(Refusal::Unsupported)?;
                (event, device.handle(event))
            }
            _ => return Err(Refusal::Unsupported),
        };
        let sends: Vec<&str> = step
            .map(|step| step.sends)
            .unwrap_or(&[])
            .iter()
            .map(|answer| answer.name())
            .collect();
        let sends = if sends.is_empty() {
            "-".to_string()
        } else {
            sends.join("+")
        };
        let state = device.state().name();
        steps.push(format!("{}>{state}>{sends}", event.name()));
    }
    Ok(format!("ok steps={}", steps.join(",")))
}
