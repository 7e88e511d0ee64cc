//! Errors as a user of the generated crate meets them, for the spec in this repository: `?`
//! into a boxed `std::error::Error`, the detail each `Display` line carries (the value, the
//! bound, the name not found: what the Python binding's messages say), and the buffer a command
//! with its parameter block needs.

use ilahrs::command::{build_command, build_load_ahrs_par, MAX_COMMAND_WITH_BLOCK_SIZE};
use ilahrs::encoding::{Date, Declination};
use ilahrs::error::{Detail, Float};
use ilahrs::frame::{FrameRepr, MAX_FRAME_SIZE};
use ilahrs::payload::AhrsParametersLoadRepr;
use ilahrs::{Command, ErrorKind, PahrSentence};

/// The `Display` line of the error `result` ends in.
fn message<T: std::fmt::Debug>(result: ilahrs::Result<T>) -> String {
    result.unwrap_err().to_string()
}

#[test]
fn load_ahrs_par_and_its_block_fit_max_command_with_block_size() {
    let block = AhrsParametersLoadRepr::default();
    assert_eq!(MAX_COMMAND_WITH_BLOCK_SIZE, 67);
    let mut buf = [0u8; MAX_COMMAND_WITH_BLOCK_SIZE];
    assert_eq!(build_load_ahrs_par(&block, &mut buf), Ok(67));
    let command = FrameRepr::parse(&buf[..9]).unwrap();
    assert_eq!(command.payload, [Command::LoadAhrsPar.code()]);
    let parameters = FrameRepr::parse(&buf[9..]).unwrap();
    assert_eq!(AhrsParametersLoadRepr::parse(parameters.payload), Ok(block));
    let error = build_load_ahrs_par(&block, &mut [0u8; MAX_FRAME_SIZE]).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::BufferTooSmall);
    assert_eq!(error.to_string(), "buffer_too_small: 60 bytes, needs 67");
    let error = build_load_ahrs_par(&block, &mut [0u8; 4]).unwrap_err();
    assert_eq!(error.to_string(), "buffer_too_small: 4 bytes, needs 67");
}

#[test]
fn question_mark_turns_an_error_into_a_boxed_std_error() {
    fn parse(data: &[u8]) -> Result<usize, Box<dyn std::error::Error + Send + Sync>> {
        Ok(FrameRepr::parse(data)?.payload.len())
    }
    let error = parse(&[0xAA, 0x54]).unwrap_err();
    assert_eq!(
        error.to_string(),
        "bad_header at byte 1 (field header): byte 0x54, expected 0x55"
    );
    let error = error.downcast::<ilahrs::Error>().unwrap();
    assert_eq!(error.kind(), ErrorKind::BadHeader);
}

#[test]
fn frame_errors_carry_what_python_says() {
    let parse = |data: &[u8]| message(FrameRepr::parse(data));
    assert_eq!(
        parse(&[0xAA, 0x55, 0x00]),
        "truncated at byte 3: 3 bytes, needs 9"
    );
    assert_eq!(
        parse(&[0xAA, 0x55, 0x07, 0x00, 0x07, 0x00]),
        "bad_message_type at byte 2 (field message_type): code 0x07"
    );
    assert_eq!(
        parse(&[0xAA, 0x55, 0x01, 0x00, 0x99, 0x00]),
        "bad_length at byte 4 (field message_length): 153 outside 7..=58"
    );
    assert_eq!(
        parse(&[0xAA, 0x55, 0x00, 0x00, 0x07, 0x00, 0x90, 0x00, 0x00]),
        "bad_checksum at byte 7 (field checksum): sent 0x0000, computed 0x0097"
    );
    let mut buf = [0u8; MAX_FRAME_SIZE + 1];
    let n = Command::ALL[0].build(&mut buf).unwrap();
    assert_eq!(
        parse(&buf[..n + 1]),
        "trailing_data at byte 9: 10 bytes, expected 9"
    );
}

#[test]
fn command_errors_name_the_name_or_the_code() {
    let mut buf = [0u8; MAX_FRAME_SIZE];
    assert_eq!(
        message(build_command("AHRSCont3", &mut buf)),
        "unknown_command: no such name \"AHRSCont3\""
    );
    let unknown = FrameRepr::new(ilahrs::MessageType::Command, &[0x01]);
    let n = unknown.build(&mut buf).unwrap();
    assert_eq!(
        message(ilahrs::decode_command(&buf[..n])),
        "unknown_command at byte 6: code 0x01"
    );
}

#[test]
fn payload_errors_give_the_value_and_the_bounds() {
    let mut buf = [0u8; 64];
    let block = AhrsParametersLoadRepr {
        update_rate: 0,
        ..AhrsParametersLoadRepr::default()
    };
    assert_eq!(
        message(block.build(&mut buf)),
        "out_of_range at byte 0 (field update_rate): 0 outside 1..=100"
    );
    let mut block = AhrsParametersLoadRepr::default();
    let error = block
        .set_declination_decoded(Declination::Degrees(200.0))
        .unwrap_err();
    let detail = Detail::FloatRange {
        value: Float(200.0),
        min: Float(-180.0),
        max: Float(180.0),
    };
    assert_eq!(error.detail(), Some(detail));
    assert!(error
        .to_string()
        .ends_with(": 200.0 outside -180.0..=180.0"));
    block.declination = 200.0;
    assert!(message(block.build(&mut buf)).ends_with(": 200.0 outside -180.0..=180.0"));
    let mut block = AhrsParametersLoadRepr::default();
    let date = Date {
        year: 2024,
        month: 2,
        day: 30,
    };
    let error = block.set_date_decoded(date).unwrap_err();
    assert!(
        error.to_string().ends_with(": 30 outside 1..=29"),
        "{error}"
    );
    assert_eq!(
        message(AhrsParametersLoadRepr::parse(&[0; 12])),
        "truncated at byte 12: 12 bytes, needs 50"
    );
}

/// The sentence `$body*CC` CR LF, its checksum right.
fn sentence(body: &str) -> String {
    let sum = body.bytes().fold(0u8, |sum, byte| sum ^ byte);
    format!("${body}*{sum:02X}\r\n")
}

#[test]
fn sentence_errors_give_the_value_and_the_bounds() {
    let parse = |text: &str| message(PahrSentence::parse(text.as_bytes()));
    let good = "PAHR,0000.00,000.00,000.00,000.0,0.00,0000";
    assert!(PahrSentence::parse(sentence(good).as_bytes()).is_ok());
    assert_eq!(
        parse(&sentence(&good.replace("0000.00,", "0200.00,"))),
        "out_of_range at byte 6 (field roll): 20000 outside -18000..=18000"
    );
    assert_eq!(
        parse(&sentence(&good.replace("0000.00,", "x,"))),
        "malformed at byte 6 (field roll): expected a decimal number"
    );
    assert_eq!(
        parse(&sentence(good.trim_end_matches(",0000"))),
        "malformed at byte 6: 5 fields, expected 6"
    );
    assert_eq!(
        parse(&format!("${good}*00\r\n")),
        "bad_checksum at byte 44: sent 0x0000, computed 0x0015"
    );
    assert_eq!(
        parse("$GPGGA,1*00\r\n"),
        "bad_header at byte 1: expected $PAHR,"
    );
    assert_eq!(parse("!"), "bad_header at byte 0: byte 0x21, expected 0x24");
    let mut buf = [0u8; 4];
    let error = PahrSentence::default().build(&mut buf).unwrap_err();
    assert_eq!(error.to_string(), "buffer_too_small: 4 bytes, needs 48");
}
