# Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the spec or the generator and run `make generate`.
#
# Kaitai Struct description of the Inertial Labs AHRS Interface Control Document, revision 1.7
# (2014-03-11), spec ilahrs 1.0.0. The top-level type is one binary frame, `capture` a recording
# of many (E40); each payload table is a type of its own, to parse a frame's payload with once the
# context says which table it follows (E7). Every type but the capture's stays within what both
# the python and the construct targets of ksc 0.11 translate (those carry -ilahrs-not-for:
# construct, which has no stream position): no switch, no parameters on types that are parsed, no
# enums on value instances. Keys starting with "-ilahrs-" are ignored by the compiler: they name
# the spec's error kind for a failing `valid` or `contents` check.
meta:
  id: ilahrs
  title: 'Inertial Labs AHRS Interface Control Document rev 1.7, binary frame'
  application: Inertial Labs AHRS
  license: MIT OR Apache-2.0
  ks-version: '0.11'
  endian: le
doc: |
  One binary frame (Table 6.2, Table 6.3): the header, message_type, reserved, message_length, the
  payload and the checksum. The checks run in the order of spec/README (frame decode): each header
  byte, then, once the 6 bytes before the payload are there, the message type and the message
  length (7 to 58, E17), then the checksum. Parse from the frame's first byte; bytes after the
  checksum belong to the next message. The reserved byte is accepted whatever its value (E6). The
  payload stays raw: nothing in a frame says which table it follows (E7); parse it with the
  table's type (command_payload for a command frame).
doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.2, Table 6.3'
seq:
  - id: header_0
    contents: [0xAA]
    -ilahrs-error: {kind: bad_header, field: header}
    doc: |
      Header byte 0. One attribute per byte, so that a wrong first byte is reported before the
      second is needed.
  - id: header_1
    contents: [0x55]
    -ilahrs-error: {kind: bad_header, field: header}
    doc: |
      Header byte 1. One attribute per byte, so that a wrong first byte is reported before the
      second is needed.
  - id: message_type
    -orig-id: Message type
    type: u1
    enum: message_type
    valid:
      expr: '_io.size - _io.pos < 3 or _ == message_type::command or _ == message_type::data'
    -ilahrs-error: {kind: bad_message_type, field: message_type}
    doc: |
      0 for commands, 1 for data. Every AHRS output is data (Table 6.2). Checked once the fixed
      part of the frame has arrived (until then, a short input is truncated).
  - id: reserved
    -orig-id: Reserved
    type: u1
    doc: |
      Not defined by rev 1.7. Decoders accept any value and expose it; builders write 0 unless
      told otherwise (E6). A strict decoder refuses a data frame whose value is not the one the
      AHRS sends (`strict`, E42).
  - id: message_length
    -orig-id: Message length
    type: u2
    valid:
      min: 7
      max: 58
    -ilahrs-error: {kind: bad_length, field: message_length}
    doc: |
      Number of bytes after the 2-byte header, message type through checksum (Table 6.2). Accepted
      from 7 to 58 (E17).
  - id: payload
    size: message_length - 6
    doc: |
      The payload, 1 to 52 bytes: message length minus the 6 bytes of message type, reserved,
      length and checksum.
  - id: checksum
    -orig-id: Check sum
    type: u2
    valid:
      expr: _ == checksum_computed
    -ilahrs-error: {kind: bad_checksum, field: checksum}
    doc: |
      Arithmetic sum, modulo 2^16, of every byte from the message type through the last payload
      byte (Table 6.2: bytes 2 ... n-1); low byte first (Table 6.3) (E28).
instances:
  checked_bytes:
    pos: 2
    size: message_length - 2
    type: byte_sum
    doc: The bytes the checksum covers, message type through payload.
  checksum_computed:
    value: checked_bytes.total % 65536
    doc: The checksum computed over the received bytes (E28).
types:
  byte_sum:
    doc: |
      The sum of the bytes of its stream: the first byte plus the sum of the rest, read as another
      byte_sum until the stream ends. Kaitai expressions have no sum over an array, so the sum is
      a recursive type (at most 56 levels in a frame).
    seq:
      - id: first
        type: u1
      - id: rest
        type: byte_sum
        repeat: eos
        doc: The rest of the bytes (zero or one byte_sum).
    instances:
      total:
        value: 'first + (rest.size > 0 ? rest[0].total.as<u4> : 0)'
  command_payload:
    doc: |
      The payload of a command frame (message type 0): the command code of Appendix C, Table C.1.
    seq:
      - id: code
        type: u1
        enum: command
  capture:
    doc: |
      A capture: the messages of a serial line as recorded, to the end of the stream. At each
      position, a binary frame whose every check passes (header, message type, length, checksum,
      as the top-level type checks them) is read as one; any other byte is skipped, one at a time
      (the leftmost-valid-message rule of spec/README). $PAHR sentences and a frame cut off by the
      end of the capture are skipped as bytes: what Kaitai cannot express is in E40.
    -ilahrs-not-for: [construct]
    seq:
      - id: messages
        type: capture_message
        repeat: eos
  capture_message:
    doc: |
      One frame (`frame`, with its payload decoded where the message length alone decides the
      table) or one skipped byte (`skipped`).
    -ilahrs-not-for: [construct]
    seq:
      - id: frame
        size: head.message_length + 2
        type: ilahrs
        if: is_frame
      - id: skipped
        type: u1
        if: not is_frame
    instances:
      start:
        value: _io.pos
        doc: Where this message starts (read before anything of it is).
      head:
        pos: start
        type: capture_head
        if: _io.size - start >= 6
      plausible:
        value: >-
          _io.size - start >= 6 and head.header_0 == 0xAA and head.header_1 == 0x55
          and (head.message_type == 0 or head.message_type == 1)
          and head.message_length >= 7 and head.message_length <= 58
          and _io.size - start >= head.message_length + 2
      checked_bytes:
        pos: start + 2
        size: head.message_length - 2
        type: byte_sum
        if: plausible
      sent_checksum:
        pos: start + head.message_length
        type: u2
        if: plausible
      is_frame:
        value: plausible and sent_checksum == checked_bytes.total % 65536
      command:
        pos: start + 6
        type: command_payload
        if: is_frame and head.message_type == 0 and head.message_length == 7
      bit_result:
        pos: start + 6
        size: 4
        type: bit_result
        if: is_frame and head.message_type == 1 and head.message_length == 10
      calibration_parameters:
        pos: start + 6
        size: 22
        type: calibration_parameters
        if: is_frame and head.message_type == 1 and head.message_length == 28
      calibration_run_result:
        pos: start + 6
        size: 30
        type: calibration_run_result
        if: is_frame and head.message_type == 1 and head.message_length == 36
      calibration_run_parameters:
        pos: start + 6
        size: 6
        type: calibration_run_parameters
        if: is_frame and head.message_type == 1 and head.message_length == 12
      acknowledgement:
        pos: start + 6
        size: 2
        type: acknowledgement
        if: is_frame and head.message_type == 1 and head.message_length == 8
  capture_head:
    doc: |
      The fixed part of a frame before the payload, unchecked: what `capture_message` looks at to
      decide.
    seq:
      - id: header_0
        type: u1
      - id: header_1
        type: u1
      - id: message_type
        type: u1
      - id: reserved
        type: u1
      - id: message_length
        type: u2
  status_word:
    doc: |
      The Unit Status Word (6.5, Table 6.18, Table 6.19). Failure flags in the low byte, warnings
      in the high byte; the mode bits 7 and 15 say readiness or sleep, any other combination is
      unknown (E18).
    seq:
      - id: value
        type: u2
        doc: The word as transmitted.
    instances:
      initial_alignment_failed:
        value: 'value & 0x0001 != 0'
        -orig-id: Initial Alignment
        doc: |
          Bit 0 (failure byte): Unsuccessful initial alignment (AHRS moved or the magnetic field
          changed).
      parameters_incorrect:
        value: 'value & 0x0002 != 0'
        -orig-id: AHRS Parameters
        doc: 'Bit 1 (failure byte): The AHRS parameters are incorrect.'
      gyro_failure:
        value: 'value & 0x0004 != 0'
        -orig-id: Gyroscope Unit
        doc: 'Bit 2 (failure byte): Gyroscope unit failure detected.'
      accelerometer_failure:
        value: 'value & 0x0008 != 0'
        -orig-id: Accelerometer Unit
        doc: 'Bit 3 (failure byte): Accelerometer unit failure detected.'
      magnetometer_failure:
        value: 'value & 0x0010 != 0'
        -orig-id: Magnetometer Unit
        doc: 'Bit 4 (failure byte): Magnetometer unit failure detected.'
      electronics_failure:
        value: 'value & 0x0020 != 0'
        -orig-id: Electronics
        doc: 'Bit 5 (failure byte): Electronics failure detected.'
      software_failure:
        value: 'value & 0x0040 != 0'
        -orig-id: Software
        doc: 'Bit 6 (failure byte): Software failure detected.'
      low_supply_voltage:
        value: 'value & 0x0100 != 0'
        -orig-id: Incorrect Power Supply
        doc: 'Bit 8 (warning byte): Supply voltage below the minimum level.'
      high_supply_voltage:
        value: 'value & 0x0200 != 0'
        -orig-id: Incorrect Power Supply
        doc: 'Bit 9 (warning byte): Supply voltage above the maximum level.'
      x_rate_exceeded:
        value: 'value & 0x0400 != 0'
        -orig-id: Angular Rate Exceeding Detect
        doc: 'Bit 10 (warning byte): X angular rate out of range.'
      y_rate_exceeded:
        value: 'value & 0x0800 != 0'
        -orig-id: Angular Rate Exceeding Detect
        doc: 'Bit 11 (warning byte): Y angular rate out of range.'
      z_rate_exceeded:
        value: 'value & 0x1000 != 0'
        -orig-id: Angular Rate Exceeding Detect
        doc: 'Bit 12 (warning byte): Z angular rate out of range.'
      large_magnetic_field:
        value: 'value & 0x2000 != 0'
        -orig-id: Large Magnetic Field Detect
        doc: 'Bit 13 (warning byte): Total magnetic field limit exceeded.'
      temperature_out_of_range:
        value: 'value & 0x4000 != 0'
        -orig-id: Environmental Temperature
        doc: 'Bit 14 (warning byte): Temperature outside the operating range.'
      any_failure:
        value: 'value & 0x007F != 0'
        doc: Any failure flag is set (the mode bits do not count).
      any_warning:
        value: 'value & 0x7F00 != 0'
        doc: Any warning flag is set (the mode bits do not count).
      mode_readiness:
        value: 'value & 0x8080 == 0x0000'
        doc: 'Mode bits say readiness: Normal operation.'
      mode_sleep:
        value: 'value & 0x8080 == 0x8080'
        doc: |
          Mode bits say sleep: In the last data block the AHRS sends before it goes to Sleep mode.
  full_output:
    doc: |
      Full Output Data (Table 6.4), 34 bytes, device to host. Output block after AHRScont1 /
      AHRSreq1.
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.4'
    seq:
      - id: heading
        -orig-id: Heading
        type: u2
        doc: |
          Heading angle. Payload bytes 0-1. Unit: degrees. Engineering value = raw/100 (instance
          heading_deg). Builders accept raw 0 to 35999. See erratum E23.
      - id: pitch
        -orig-id: Pitch
        type: s2
        doc: |
          Pitch angle. Payload bytes 2-3. Unit: degrees. Engineering value = raw/100 (instance
          pitch_deg). Builders accept raw -9000 to 9000.
      - id: roll
        -orig-id: Roll
        type: s2
        doc: |
          Roll angle. Payload bytes 4-5. Unit: degrees. Engineering value = raw/100 (instance
          roll_deg). Builders accept raw -18000 to 18000.
      - id: ugyro_x
        -orig-id: Ugyro
        type: s2
        doc: |
          Raw gyro X sensor data. Payload bytes 6-7. Unit: ADC codes (no physical scale given by
          the ICD).
      - id: ugyro_y
        -orig-id: Ugyro
        type: s2
        doc: |
          Raw gyro Y sensor data. Payload bytes 8-9. Unit: ADC codes (no physical scale given by
          the ICD).
      - id: ugyro_z
        -orig-id: Ugyro
        type: s2
        doc: |
          Raw gyro Z sensor data. Payload bytes 10-11. Unit: ADC codes (no physical scale given by
          the ICD).
      - id: uacc_x
        -orig-id: Uacc
        type: s2
        doc: |
          Raw accelerometer X sensor data. Payload bytes 12-13. Unit: ADC codes (no physical scale
          given by the ICD).
      - id: uacc_y
        -orig-id: Uacc
        type: s2
        doc: |
          Raw accelerometer Y sensor data. Payload bytes 14-15. Unit: ADC codes (no physical scale
          given by the ICD).
      - id: uacc_z
        -orig-id: Uacc
        type: s2
        doc: |
          Raw accelerometer Z sensor data. Payload bytes 16-17. Unit: ADC codes (no physical scale
          given by the ICD).
      - id: umag_x
        -orig-id: Umag
        type: s2
        doc: |
          Raw magnetometer X sensor data. Payload bytes 18-19. Unit: ADC codes (no physical scale
          given by the ICD).
      - id: umag_y
        -orig-id: Umag
        type: s2
        doc: |
          Raw magnetometer Y sensor data. Payload bytes 20-21. Unit: ADC codes (no physical scale
          given by the ICD).
      - id: umag_z
        -orig-id: Umag
        type: s2
        doc: |
          Raw magnetometer Z sensor data. Payload bytes 22-23. Unit: ADC codes (no physical scale
          given by the ICD).
      - id: reserved
        -orig-id: Reserved
        size: 4
        doc: 'Payload bytes 24-27. Reserved: kept verbatim.'
      - id: usw
        -orig-id: USW
        type: status_word
        doc: |
          Unit Status Word (section 6.5). Payload bytes 28-29. Unit Status Word: see the type
          status_word.
      - id: vdd
        -orig-id: Vdd
        type: u2
        doc: |
          Combined voltage: successive frames carry the AHRS input voltage and the stabilised
          sensor supply voltage in turn (Table 6.4 note 2). The frame does not say which. Payload
          bytes 30-31. Unit: volts DC. Engineering value = raw/1000 (instance vdd_v). Multiplexed:
          2 quantities in turn (AHRS input voltage; stabilised voltage supplied to the sensors).
          See erratum E19.
      - id: utermo
        -orig-id: Utermo
        type: s2
        doc: |
          ADC code of one of 7 temperature sensors, in turn in successive frames (Table 6.4 note
          3). The frame does not say which. Payload bytes 32-33. Unit: ADC codes (no physical
          scale given by the ICD). Multiplexed: 7 quantities in turn (temperature sensors 1-7
          inside the gyros; accelerometers and magnetometers). See erratum E19.
    instances:
      heading_deg:
        value: 'heading / 100.0'
        doc: 'heading in degrees: raw/100.'
      pitch_deg:
        value: 'pitch / 100.0'
        doc: 'pitch in degrees: raw/100.'
      roll_deg:
        value: 'roll / 100.0'
        doc: 'roll in degrees: raw/100.'
      vdd_v:
        value: 'vdd / 1000.0'
        doc: 'vdd in volts DC: raw/1000.'
  quaternion:
    doc: |
      Quaternion of Orientation (Table 6.5), 34 bytes, device to host. Output block after
      AHRScont2 / AHRSreq2.
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.5'
    seq:
      - id: heading
        -orig-id: Heading
        type: u2
        doc: |
          Heading angle. Payload bytes 0-1. Unit: degrees. Engineering value = raw/100 (instance
          heading_deg). Builders accept raw 0 to 35999. See erratum E23.
      - id: pitch
        -orig-id: Pitch
        type: s2
        doc: |
          Pitch angle. Payload bytes 2-3. Unit: degrees. Engineering value = raw/100 (instance
          pitch_deg). Builders accept raw -9000 to 9000.
      - id: roll
        -orig-id: Roll
        type: s2
        doc: |
          Roll angle. Payload bytes 4-5. Unit: degrees. Engineering value = raw/100 (instance
          roll_deg). Builders accept raw -18000 to 18000.
      - id: lk0
        -orig-id: Lk0
        type: s2
        doc: |
          Quaternion of orientation, scalar component. Payload bytes 6-7. Unit: dimensionless.
          Engineering value = raw/10000 (instance lk0_value). Builders accept raw -10000 to 10000.
      - id: lk1
        -orig-id: Lk1
        type: s2
        doc: |
          Quaternion of orientation, first vector component. Payload bytes 8-9. Unit:
          dimensionless. Engineering value = raw/10000 (instance lk1_value). Builders accept raw
          -10000 to 10000.
      - id: lk2
        -orig-id: Lk2
        type: s2
        doc: |
          Quaternion of orientation, second vector component. Payload bytes 10-11. Unit:
          dimensionless. Engineering value = raw/10000 (instance lk2_value). Builders accept raw
          -10000 to 10000.
      - id: lk3
        -orig-id: Lk3
        type: s2
        doc: |
          Quaternion of orientation, third vector component. Payload bytes 12-13. Unit:
          dimensionless. Engineering value = raw/10000 (instance lk3_value). Builders accept raw
          -10000 to 10000.
      - id: reserved
        -orig-id: Reserved
        size: 14
        doc: 'Payload bytes 14-27. Reserved: kept verbatim.'
      - id: usw
        -orig-id: USW
        type: status_word
        doc: |
          Unit Status Word (section 6.5). Payload bytes 28-29. Unit Status Word: see the type
          status_word.
      - id: vdd
        -orig-id: Vdd
        type: u2
        doc: |
          AHRS input voltage. Payload bytes 30-31. Unit: volts DC. Engineering value = raw/1000
          (instance vdd_v).
      - id: utermo
        -orig-id: Utermo
        type: s2
        doc: |
          Average temperature of the 3 accelerometers. Payload bytes 32-33. Unit: degrees Celsius.
          Engineering value = raw/10 (instance utermo_degc).
    instances:
      heading_deg:
        value: 'heading / 100.0'
        doc: 'heading in degrees: raw/100.'
      pitch_deg:
        value: 'pitch / 100.0'
        doc: 'pitch in degrees: raw/100.'
      roll_deg:
        value: 'roll / 100.0'
        doc: 'roll in degrees: raw/100.'
      lk0_value:
        value: 'lk0 / 10000.0'
        doc: 'lk0 in dimensionless: raw/10000.'
      lk1_value:
        value: 'lk1 / 10000.0'
        doc: 'lk1 in dimensionless: raw/10000.'
      lk2_value:
        value: 'lk2 / 10000.0'
        doc: 'lk2 in dimensionless: raw/10000.'
      lk3_value:
        value: 'lk3 / 10000.0'
        doc: 'lk3 in dimensionless: raw/10000.'
      vdd_v:
        value: 'vdd / 1000.0'
        doc: 'vdd in volts DC: raw/1000.'
      utermo_degc:
        value: 'utermo / 10.0'
        doc: 'utermo in degrees Celsius: raw/10.'
  orientation_sensors:
    doc: |
      Orientation + Sensor Outputs (Table 6.6), 34 bytes, device to host. Output block after
      AHRScont3 / AHRSreq3 (the default format, section 6.2).
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.6'
    seq:
      - id: heading
        -orig-id: Heading
        type: u2
        doc: |
          Heading angle. Payload bytes 0-1. Unit: degrees. Engineering value = raw/100 (instance
          heading_deg). Builders accept raw 0 to 35999. See erratum E23.
      - id: pitch
        -orig-id: Pitch
        type: s2
        doc: |
          Pitch angle. Payload bytes 2-3. Unit: degrees. Engineering value = raw/100 (instance
          pitch_deg). Builders accept raw -9000 to 9000.
      - id: roll
        -orig-id: Roll
        type: s2
        doc: |
          Roll angle. Payload bytes 4-5. Unit: degrees. Engineering value = raw/100 (instance
          roll_deg). Builders accept raw -18000 to 18000.
      - id: gyro_x
        -orig-id: GyroX
        type: s2
        doc: |
          Angular rate about X (lateral axis). Payload bytes 6-7. Unit: degrees per second.
          Engineering value = raw/KG (instance gyro_x_dps of the type orientation_sensors_scaled).
      - id: gyro_y
        -orig-id: GyroY
        type: s2
        doc: |
          Angular rate about Y (longitudinal axis). Payload bytes 8-9. Unit: degrees per second.
          Engineering value = raw/KG (instance gyro_y_dps of the type orientation_sensors_scaled).
      - id: gyro_z
        -orig-id: GyroZ
        type: s2
        doc: |
          Angular rate about Z (vertical axis). Payload bytes 10-11. Unit: degrees per second.
          Engineering value = raw/KG (instance gyro_z_dps of the type orientation_sensors_scaled).
      - id: acc_x
        -orig-id: AccX
        type: s2
        doc: |
          Linear acceleration along X. Payload bytes 12-13. Unit: standard gravity. Engineering
          value = raw/KA (instance acc_x_g of the type orientation_sensors_scaled).
      - id: acc_y
        -orig-id: AccY
        type: s2
        doc: |
          Linear acceleration along Y. Payload bytes 14-15. Unit: standard gravity. Engineering
          value = raw/KA (instance acc_y_g of the type orientation_sensors_scaled).
      - id: acc_z
        -orig-id: AccZ
        type: s2
        doc: |
          Linear acceleration along Z. Payload bytes 16-17. Unit: standard gravity. Engineering
          value = raw/KA (instance acc_z_g of the type orientation_sensors_scaled).
      - id: mag_x
        -orig-id: MagX
        type: s2
        doc: |
          Magnetic field along X. Payload bytes 18-19. Unit: nanotesla. Engineering value = raw*10
          (instance mag_x_nt).
      - id: mag_y
        -orig-id: MagY
        type: s2
        doc: |
          Magnetic field along Y. Payload bytes 20-21. Unit: nanotesla. Engineering value = raw*10
          (instance mag_y_nt).
      - id: mag_z
        -orig-id: MagZ
        type: s2
        doc: |
          Magnetic field along Z. Payload bytes 22-23. Unit: nanotesla. Engineering value = raw*10
          (instance mag_z_nt).
      - id: reserved
        -orig-id: Reserved
        size: 4
        doc: 'Payload bytes 24-27. Reserved: kept verbatim.'
      - id: usw
        -orig-id: USW
        type: status_word
        doc: |
          Unit Status Word (section 6.5). Payload bytes 28-29. Unit Status Word: see the type
          status_word.
      - id: vdd
        -orig-id: Vdd
        type: u2
        doc: |
          AHRS input voltage. Payload bytes 30-31. Unit: volts DC. Engineering value = raw/1000
          (instance vdd_v).
      - id: utermo
        -orig-id: Utermo
        type: s2
        doc: |
          Average temperature of the 3 accelerometers. Payload bytes 32-33. Unit: degrees Celsius.
          Engineering value = raw/10 (instance utermo_degc).
    instances:
      heading_deg:
        value: 'heading / 100.0'
        doc: 'heading in degrees: raw/100.'
      pitch_deg:
        value: 'pitch / 100.0'
        doc: 'pitch in degrees: raw/100.'
      roll_deg:
        value: 'roll / 100.0'
        doc: 'roll in degrees: raw/100.'
      mag_x_nt:
        value: 'mag_x * 10.0'
        doc: 'mag_x in nanotesla: raw*10.'
      mag_y_nt:
        value: 'mag_y * 10.0'
        doc: 'mag_y in nanotesla: raw*10.'
      mag_z_nt:
        value: 'mag_z * 10.0'
        doc: 'mag_z in nanotesla: raw*10.'
      vdd_v:
        value: 'vdd / 1000.0'
        doc: 'vdd in volts DC: raw/1000.'
      utermo_degc:
        value: 'utermo / 10.0'
        doc: 'utermo in degrees Celsius: raw/10.'
  orientation_sensors_scaled:
    doc: |
      The engineering values of orientation_sensors fields whose scale depends on the device
      variant (KG, KA). Not parsed from bytes: instantiate it with a parsed orientation_sensors
      and the variant's parameters.
    params:
      - id: payload
        type: orientation_sensors
        doc: The parsed payload.
      - id: kg
        type: f8
        doc: |
          Gyro scale factor of Table 6.6, LSB per deg/s. By variant: g300_a2_tmga 100;
          g300_a6_tmga 100; sn_11ac0001_0009 50; g300_a2_tga 100.
      - id: ka
        type: f8
        doc: |
          Accelerometer scale factor of Table 6.6, LSB per g. By variant: g300_a2_tmga 10000;
          g300_a6_tmga 5000; sn_11ac0001_0009 10000; g300_a2_tga 10000.
    instances:
      gyro_x_dps:
        value: 'payload.gyro_x / kg'
        doc: 'gyro_x in degrees per second: raw/KG.'
      gyro_y_dps:
        value: 'payload.gyro_y / kg'
        doc: 'gyro_y in degrees per second: raw/KG.'
      gyro_z_dps:
        value: 'payload.gyro_z / kg'
        doc: 'gyro_z in degrees per second: raw/KG.'
      acc_x_g:
        value: 'payload.acc_x / ka'
        doc: 'acc_x in standard gravity: raw/KA.'
      acc_y_g:
        value: 'payload.acc_y / ka'
        doc: 'acc_y in standard gravity: raw/KA.'
      acc_z_g:
        value: 'payload.acc_z / ka'
        doc: 'acc_z in standard gravity: raw/KA.'
  initial_alignment:
    doc: |
      Initial alignment data (Table 6.8), 50 bytes, device to host. Sent once when initial
      alignment completes, before continuous / on-request output or a calibration run starts
      (6.3.1 - 6.3.3, 6.4). Note the ICD order: heading, roll, pitch. See erratum E21.
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.8'
    seq:
      - id: gyro_bias_x
        -orig-id: Gyros bias
        type: f4
        doc: |
          Gyro X bias. Payload bytes 0-3. Unit: ADC codes (no physical scale given by the ICD).
      - id: gyro_bias_y
        -orig-id: Gyros bias
        type: f4
        doc: |
          Gyro Y bias. Payload bytes 4-7. Unit: ADC codes (no physical scale given by the ICD).
      - id: gyro_bias_z
        -orig-id: Gyros bias
        type: f4
        doc: |
          Gyro Z bias. Payload bytes 8-11. Unit: ADC codes (no physical scale given by the ICD).
      - id: average_acc_x
        -orig-id: Average acceleration
        type: f4
        doc: |
          Average acceleration along X. Payload bytes 12-15. Unit: ADC codes (no physical scale
          given by the ICD).
      - id: average_acc_y
        -orig-id: Average acceleration
        type: f4
        doc: |
          Average acceleration along Y. Payload bytes 16-19. Unit: ADC codes (no physical scale
          given by the ICD).
      - id: average_acc_z
        -orig-id: Average acceleration
        type: f4
        doc: |
          Average acceleration along Z. Payload bytes 20-23. Unit: ADC codes (no physical scale
          given by the ICD).
      - id: average_mag_x
        -orig-id: Average magn. field
        type: f4
        doc: |
          Average magnetic field along X. Payload bytes 24-27. Unit: ADC codes (no physical scale
          given by the ICD).
      - id: average_mag_y
        -orig-id: Average magn. field
        type: f4
        doc: |
          Average magnetic field along Y. Payload bytes 28-31. Unit: ADC codes (no physical scale
          given by the ICD).
      - id: average_mag_z
        -orig-id: Average magn. field
        type: f4
        doc: |
          Average magnetic field along Z. Payload bytes 32-35. Unit: ADC codes (no physical scale
          given by the ICD).
      - id: initial_heading
        -orig-id: Initial Heading
        type: f4
        doc: |
          Heading at the end of alignment. Payload bytes 36-39. Unit: degrees. Builders accept raw
          0 to 360.
      - id: initial_roll
        -orig-id: Initial Roll
        type: f4
        doc: |
          Roll at the end of alignment. Payload bytes 40-43. Unit: degrees. Builders accept raw
          -180 to 180.
      - id: initial_pitch
        -orig-id: Initial Pitch
        type: f4
        doc: |
          Pitch at the end of alignment. Payload bytes 44-47. Unit: degrees. Builders accept raw
          -90 to 90.
      - id: usw
        -orig-id: USW
        type: status_word
        doc: |
          Unit Status Word: 0 after a successful alignment, non-zero otherwise. Payload bytes
          48-49. Unit Status Word: see the type status_word. See erratum E27.
  ahrs_parameters_load:
    doc: |
      Parameters to load (Table 6.9), 50 bytes, host to device. The data message the host sends
      right after LoadAHRSPar (6.3.6). Read the block first (ReadAHRSPar), change it, send it
      back.
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.9'
    seq:
      - id: update_rate
        -orig-id: Update rate
        type: u2
        doc: |
          Output data rate, 1 to 100 Hz (the AHRS limits NMEA output to 50 Hz). Payload bytes 0-1.
          Unit: hertz. Builders accept raw 1 to 100. Default 100. See erratum E22.
      - id: alignment_time
        -orig-id: Initial alignment time
        type: u2
        doc: |
          Initial alignment duration; default 30 s, change only in agreement with Inertial Labs.
          Payload bytes 2-3. Unit: seconds. Builders accept raw 1 to 65535. Default 30. See
          erratum E30.
      - id: declination
        -orig-id: Magnetic declination, Mdec
        type: f4
        doc: |
          Magnetic declination; a value above 360 asks the AHRS to compute it from position and
          date. Payload bytes 4-7. Unit: degrees. Encoding declination: -180 to 180 deg, or above
          360 (builders write 999) to have the AHRS compute it.
      - id: latitude
        -orig-id: Latitude
        type: f4
        doc: 'Latitude. Payload bytes 8-11. Unit: degrees. Builders accept raw -90 to 90.'
      - id: longitude
        -orig-id: Longitude
        type: f4
        doc: 'Longitude. Payload bytes 12-15. Unit: degrees. Builders accept raw -180 to 180.'
      - id: altitude
        -orig-id: Altitude
        type: f4
        doc: |
          Altitude. Payload bytes 16-19. Unit: metres. Builders accept raw -20000 to 100000. See
          erratum E31.
      - id: date
        -orig-id: Date (Year, Month, Day)
        type: f4
        doc: |
          Date as Year + (Month - 1)/12 + Day/365. Payload bytes 20-23. Unit: fractional year, see
          encoding `date`. Builders accept raw 1900.002685546875 to 2200.001708984375. Encoding
          date: years 1900 to 2199.
      - id: alignment_angle_a1
        -orig-id: Alignment angle A1
        type: f4
        doc: |
          Mounting angle 1: AHRS Y axis relative to the object's longitudinal axis in its
          horizontal plane, clockwise positive (Appendix B). Payload bytes 24-27. Unit: degrees.
          Builders accept raw -360 to 360. See erratum E31.
      - id: alignment_angle_a2
        -orig-id: Alignment angle A2
        type: f4
        doc: |
          Mounting angle 2: inclination of the AHRS Y axis to the object's horizontal plane, up
          positive (Appendix B). Payload bytes 28-31. Unit: degrees. Builders accept raw -360 to
          360. See erratum E31.
      - id: alignment_angle_a3
        -orig-id: Alignment angle A3
        type: f4
        doc: |
          Mounting angle 3: inclination of the AHRS X axis about its Y axis, X down positive
          (Appendix B). Payload bytes 32-35. Unit: degrees. Builders accept raw -360 to 360. See
          erratum E31.
      - id: reserved
        -orig-id: Reserved
        size: 14
        doc: 'Should be all zeros. Payload bytes 36-49. Reserved: kept verbatim.'
  ahrs_parameters_read:
    doc: |
      Parameters read (Table 6.10), 50 bytes, device to host. The AHRS answer to ReadAHRSPar
      (6.3.7).
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.10'
    seq:
      - id: update_rate
        -orig-id: Measurement rate
        type: u2
        doc: |
          Output data rate. Payload bytes 0-1. Unit: hertz. Builders accept raw 1 to 100. See
          erratum E24.
      - id: alignment_time
        -orig-id: Initial alignment time
        type: u2
        doc: |
          Initial alignment duration. Payload bytes 2-3. Unit: seconds. Builders accept raw 1 to
          65535. See erratum E30.
      - id: declination
        -orig-id: Magnetic declination
        type: f4
        doc: |
          Magnetic declination; a value above 360 means the AHRS computes it. Payload bytes 4-7.
          Unit: degrees. Encoding declination: -180 to 180 deg, or above 360 (builders write 999)
          to have the AHRS compute it.
      - id: latitude
        -orig-id: Latitude
        type: f4
        doc: 'Latitude. Payload bytes 8-11. Unit: degrees. Builders accept raw -90 to 90.'
      - id: longitude
        -orig-id: Longitude
        type: f4
        doc: 'Longitude. Payload bytes 12-15. Unit: degrees. Builders accept raw -180 to 180.'
      - id: altitude
        -orig-id: Altitude
        type: f4
        doc: |
          Altitude. Payload bytes 16-19. Unit: metres. Builders accept raw -20000 to 100000. See
          erratum E31.
      - id: date
        -orig-id: Date (Year, Month, Day)
        type: f4
        doc: |
          Date as Year + (Month - 1)/12 + Day/365. Payload bytes 20-23. Unit: fractional year, see
          encoding `date`. Builders accept raw 1900.002685546875 to 2200.001708984375. Encoding
          date: years 1900 to 2199.
      - id: alignment_angle_a1
        -orig-id: Alignment angle A1
        type: f4
        doc: |
          Mounting angle 1 (Appendix B). Payload bytes 24-27. Unit: degrees. Builders accept raw
          -360 to 360. See erratum E31.
      - id: alignment_angle_a2
        -orig-id: Alignment angle A2
        type: f4
        doc: |
          Mounting angle 2 (Appendix B). Payload bytes 28-31. Unit: degrees. Builders accept raw
          -360 to 360. See erratum E31.
      - id: alignment_angle_a3
        -orig-id: Alignment angle A3
        type: f4
        doc: |
          Mounting angle 3 (Appendix B). Payload bytes 32-35. Unit: degrees. Builders accept raw
          -360 to 360. See erratum E31.
      - id: device_id
        -orig-id: Device ID
        type: str
        size: 8
        encoding: ISO-8859-1
        pad-right: 0
        doc: |
          Device identifier (read only). Payload bytes 36-43. ISO-8859-1, trailing NULs removed.
      - id: reserved
        -orig-id: Reserved
        size: 6
        doc: 'Payload bytes 44-49. Reserved: kept verbatim.'
  firmware_version:
    doc: |
      Firmware version (Table 6.11), 50 bytes, device to host. The AHRS answer to GetVerFirmware
      (6.3.10).
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.11'
    seq:
      - id: version
        -orig-id: Firmware version
        type: str
        size: 50
        encoding: ISO-8859-1
        pad-right: 0
        doc: |
          Firmware version text, NUL-padded. Payload bytes 0-49. ISO-8859-1, trailing NULs
          removed.
  bit_result:
    doc: |
      Built-in test answer (Table 6.12), 4 bytes, device to host. The AHRS answer to GetBIT
      (6.3.11).
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.12'
    seq:
      - id: utermo100
        -orig-id: Utermo100
        type: s2
        doc: |
          AHRS temperature in 1/100 degC. Payload bytes 0-1. Unit: degrees Celsius. Engineering
          value = raw/100 (instance utermo100_degc). See erratum E4.
      - id: usw
        -orig-id: USW
        type: status_word
        doc: |
          Unit Status Word (section 6.5). Payload bytes 2-3. Unit Status Word: see the type
          status_word.
    instances:
      utermo100_degc:
        value: 'utermo100 / 100.0'
        doc: 'utermo100 in degrees Celsius: raw/100.'
  calibration_parameters:
    doc: |
      Calibration parameters (Table 6.13), 22 bytes, host to device. The data message the host
      sends right after Start3DClb, Start2D2TClb or Start2DClb (6.4.1, 6.4.5, 6.4.8).
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.13'
    seq:
      - id: reference_azimuth
        -orig-id: Reserved
        type: f4
        doc: |
          Reference azimuth (6.4.8); no influence on 2D calibration. Payload bytes 0-3. Unit:
          degrees. Builders accept raw -360 to 360. Default 0. See erratum E8.
      - id: accumulation_time
        -orig-id: Time of data accumulation in one run
        type: u2
        doc: |
          Data accumulation time of one run. Payload bytes 4-5. Unit: seconds. Builders accept raw
          1 to 65535. See erratum E30.
      - id: latitude
        -orig-id: Latitude
        type: f4
        doc: 'Latitude. Payload bytes 6-9. Unit: degrees. Builders accept raw -90 to 90.'
      - id: longitude
        -orig-id: Longitude
        type: f4
        doc: 'Longitude. Payload bytes 10-13. Unit: degrees. Builders accept raw -180 to 180.'
      - id: altitude
        -orig-id: Altitude
        type: f4
        doc: |
          Altitude. Payload bytes 14-17. Unit: metres. Builders accept raw -20000 to 100000. See
          erratum E31.
      - id: date
        -orig-id: Date (Year, Month, Day)
        type: f4
        doc: |
          Date as Year + (Month - 1)/12 + Day/365. Payload bytes 18-21. Unit: fractional year, see
          encoding `date`. Builders accept raw 1900.002685546875 to 2200.001708984375. Encoding
          date: years 1900 to 2199.
  calibration_result:
    doc: |
      Calibration result (Table 6.14), 52 bytes, device to host. Sent when a calibration completes
      (after the accumulation time, StopClbRun, or FinishClb). See erratum E1.
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.14'
    seq:
      - id: calibration_type
        -orig-id: Type of calibration
        type: u1
        enum: calibration_type
        doc: |
          1 for 2D, 2 for 2D-2T, 3 for 3D calibration. Payload byte 0. Builders accept raw 1 to 3.
          Enum calibration_type (Table 6.14, Table 6.15).
      - id: runs_used
        -orig-id: Number of used calibration runs
        type: u1
        doc: Number of calibration runs used. Payload byte 1.
      - id: data_used
        -orig-id: Percent of used data points
        type: u1
        doc: |
          Percent of data points used (2D and 3D calibrations only). Payload byte 2. Unit:
          percent. Builders accept raw 0 to 100.
      - id: success
        -orig-id: Calibration success
        type: u1
        doc: |
          0: not successful; 1..254: predicted 3-sigma heading error in deg*10; 255: successful
          without an estimate. Payload byte 3. Encoding calibration_success: 0: not successful;
          1..254: predicted maximum (3 sigma) heading error, deg*10 (since firmware 4.9.9.0); 255:
          successful, no estimate. See erratum E26.
      - id: tm_c_11
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 1 column 1. Payload bytes 4-7. Unit: dimensionless.'
      - id: tm_c_12
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 1 column 2. Payload bytes 8-11. Unit: dimensionless.'
      - id: tm_c_13
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 1 column 3. Payload bytes 12-15. Unit: dimensionless.'
      - id: tm_c_21
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 2 column 1. Payload bytes 16-19. Unit: dimensionless.'
      - id: tm_c_22
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 2 column 2. Payload bytes 20-23. Unit: dimensionless.'
      - id: tm_c_23
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 2 column 3. Payload bytes 24-27. Unit: dimensionless.'
      - id: tm_c_31
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 3 column 1. Payload bytes 28-31. Unit: dimensionless.'
      - id: tm_c_32
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 3 column 2. Payload bytes 32-35. Unit: dimensionless.'
      - id: tm_c_33
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 3 column 3. Payload bytes 36-39. Unit: dimensionless.'
      - id: hm_0_x
        -orig-id: Matrix for hard iron correction
        type: f4
        doc: |
          Hard-iron vector Hm_0 component 1. Payload bytes 40-43. Unit: ADC codes (no physical
          scale given by the ICD). See erratum E1.
      - id: hm_0_y
        -orig-id: Matrix for hard iron correction
        type: f4
        doc: |
          Hard-iron vector Hm_0 component 2. Payload bytes 44-47. Unit: ADC codes (no physical
          scale given by the ICD). See erratum E1.
      - id: hm_0_z
        -orig-id: Matrix for hard iron correction
        type: f4
        doc: |
          Hard-iron vector Hm_0 component 3. Payload bytes 48-51. Unit: ADC codes (no physical
          scale given by the ICD). See erratum E1.
  calibration_run_result:
    doc: |
      2D-2T calibration run result (Table 6.15), 30 bytes, device to host. Sent after each run of
      a 2D-2T calibration (6.4.5).
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.15'
    seq:
      - id: calibration_type
        -orig-id: Type of calibration
        type: u1
        enum: calibration_type
        doc: |
          2 for 2D-2T calibration. Payload byte 0. Builders accept raw 2 to 2. Enum
          calibration_type (Table 6.14, Table 6.15).
      - id: run
        -orig-id: Calibration run
        type: u1
        doc: Number of this run (1, 2, ...). Payload byte 1. Builders accept raw 1 to 255.
      - id: data_used
        -orig-id: Percent of used data points
        type: u1
        doc: |
          Percent of data points used. Payload byte 2. Unit: percent. Builders accept raw 0 to
          100.
      - id: success
        -orig-id: Calibration success
        type: u1
        doc: |
          0: run not successful (excluded); 1..254: predicted heading error in deg*10; 255:
          successful without an estimate. Payload byte 3. Encoding calibration_success: 0: not
          successful; 1..254: predicted maximum (3 sigma) heading error, deg*10 (since firmware
          4.9.9.0); 255: successful, no estimate. See erratum E26.
      - id: reserved_1
        -orig-id: Reserved
        size: 4
        doc: 'Payload bytes 4-7. Reserved: kept verbatim. See erratum E32.'
      - id: average_pitch
        -orig-id: Average pitch, deg
        type: f4
        doc: |
          Average pitch during the run. Payload bytes 8-11. Unit: degrees. Builders accept raw -90
          to 90.
      - id: average_roll
        -orig-id: Average roll, deg
        type: f4
        doc: |
          Average roll during the run. Payload bytes 12-15. Unit: degrees. Builders accept raw
          -180 to 180.
      - id: reserved_2
        -orig-id: Reserved
        size: 12
        doc: 'Payload bytes 16-27. Reserved: kept verbatim. See erratum E32.'
      - id: usw
        -orig-id: USW
        type: status_word
        doc: |
          Unit Status Word (section 6.5). Payload bytes 28-29. Unit Status Word: see the type
          status_word.
  calibration_run_parameters:
    doc: |
      Calibration run parameters (Table 6.16), 6 bytes, host to device. The data message the host
      sends right after StartClbRun (6.4.6); its 6 bytes do not influence 2D-2T calibration and
      may be any, e.g. zeros.
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.16'
    seq:
      - id: reserved
        -orig-id: Reserved
        size: 6
        doc: 'Payload bytes 0-5. Reserved: kept verbatim. See erratum E32.'
  calibration_status:
    doc: |
      Calibration results read back (Table 6.17), 52 bytes, device to host. The AHRS answer to
      GetClbRes (6.4.10). See erratum E2.
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, Table 6.17'
    seq:
      - id: calibration_type
        -orig-id: Type of calibration performed
        type: u1
        enum: calibration_status_type
        doc: |
          0: not calibrated; 1: 2D; 2: 2D-2T; 3: 3D; above 0x80: parameters loaded by other
          software. Payload byte 0. Enum calibration_status_type (Table 6.17). Values above 0x80
          mean parameters loaded by other software and have no name in the enum.
      - id: runs_used
        -orig-id: Number of used calibration runs
        type: u1
        doc: Number of calibration runs used. Payload byte 1.
      - id: reserved
        -orig-id: Reserved
        size: 1
        doc: 'Payload byte 2. Reserved: kept verbatim. See erratum E3.'
      - id: success
        -orig-id: Calibration success
        type: u1
        doc: |
          0: not successful; 1..254: predicted heading error in deg*10; 255: successful without an
          estimate. Payload byte 3. Encoding calibration_success: 0: not successful; 1..254:
          predicted maximum (3 sigma) heading error, deg*10 (since firmware 4.9.9.0); 255:
          successful, no estimate. See erratum E26.
      - id: tm_c_11
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 1 column 1. Payload bytes 4-7. Unit: dimensionless.'
      - id: tm_c_12
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 1 column 2. Payload bytes 8-11. Unit: dimensionless.'
      - id: tm_c_13
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 1 column 3. Payload bytes 12-15. Unit: dimensionless.'
      - id: tm_c_21
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 2 column 1. Payload bytes 16-19. Unit: dimensionless.'
      - id: tm_c_22
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 2 column 2. Payload bytes 20-23. Unit: dimensionless.'
      - id: tm_c_23
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 2 column 3. Payload bytes 24-27. Unit: dimensionless.'
      - id: tm_c_31
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 3 column 1. Payload bytes 28-31. Unit: dimensionless.'
      - id: tm_c_32
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 3 column 2. Payload bytes 32-35. Unit: dimensionless.'
      - id: tm_c_33
        -orig-id: Matrix for soft iron correction
        type: f4
        doc: 'Soft-iron matrix Tm_c row 3 column 3. Payload bytes 36-39. Unit: dimensionless.'
      - id: hm_0_x
        -orig-id: Matrix for hard iron correction
        type: f4
        doc: |
          Hard-iron vector Hm_0 component 1. Payload bytes 40-43. Unit: ADC codes (no physical
          scale given by the ICD). See erratum E2.
      - id: hm_0_y
        -orig-id: Matrix for hard iron correction
        type: f4
        doc: |
          Hard-iron vector Hm_0 component 2. Payload bytes 44-47. Unit: ADC codes (no physical
          scale given by the ICD). See erratum E2.
      - id: hm_0_z
        -orig-id: Matrix for hard iron correction
        type: f4
        doc: |
          Hard-iron vector Hm_0 component 3. Payload bytes 48-51. Unit: ADC codes (no physical
          scale given by the ICD). See erratum E2.
  acknowledgement:
    doc: |
      Acknowledgement (6.3.1 (Table 6.2 with a one-word payload)), 2 bytes, device to host. The
      checksum of the message the AHRS received (E12).
    doc-ref: 'Inertial Labs AHRS Interface Control Document rev 1.7, 6.3.1 (Table 6.2 with a one-word payload)'
    seq:
      - id: checksum
        -orig-id: Check sum
        type: u2
        doc: |
          Checksum of the acknowledged message, message type through payload. Payload bytes 0-1.
enums:
  message_type:
    0:
      id: command
      doc: A command from the host (one-byte payload holding the command code).
    1:
      id: data
      doc: 'Data: every AHRS output, and the parameter blocks the host sends (E5).'
  command:
    0x1A:
      id: get_bit
      -orig-id: GetBIT
      doc: |
        GetBIT (6.3.11): Read the built-in-test answer, temperature and Unit Status Word (Table
        6.12). Valid in idle, on_request.
    0x1F:
      id: get_ver_firmware
      -orig-id: GetVerFirmware
      doc: |
        GetVerFirmware (6.3.10): Read the firmware version string (Table 6.11). Valid in idle.
    0x20:
      id: stop_clb_run
      -orig-id: StopClbRun
      doc: |
        StopClbRun (6.4.2): Stop data accumulation in the current calibration run before its set
        time. Valid in calibration.
    0x21:
      id: start_2d_clb
      -orig-id: Start2DClb
      doc: |
        Start2DClb (6.4.8): Start 2D hard/soft-iron calibration; the calibration parameter block
        (Table 6.13) follows. Valid in idle.
    0x22:
      id: start_2d2t_clb
      -orig-id: Start2D2TClb
      doc: |
        Start2D2TClb (6.4.5): Start 2D-2T (multi-run) calibration; the calibration parameter block
        (Table 6.13) follows. Valid in idle.
    0x23:
      id: start_3d_clb
      -orig-id: Start3DClb
      doc: |
        Start3DClb (6.4.1): Start 3D calibration; the calibration parameter block (Table 6.13)
        follows. Valid in idle.
    0x2A:
      id: get_clb_res
      -orig-id: GetClbRes
      doc: |
        GetClbRes (6.4.10): Read the results of the last calibration (Table 6.17). Valid in idle.
    0x2B:
      id: start_clb_run
      -orig-id: StartClbRun
      doc: |
        StartClbRun (6.4.6): Start one run of a multi-run (2D-2T) calibration; the run parameter
        block (Table 6.16) follows. Valid in calibration.
    0x2C:
      id: finish_clb
      -orig-id: FinishClb
      doc: |
        FinishClb (6.4.7): Finish a multi-run (2D-2T) calibration and compute its result (Table
        6.14). Valid in calibration.
    0x2E:
      id: accept_clb
      -orig-id: AcceptClb
      doc: |
        AcceptClb (6.4.3): Accept the calibration result and save it to non-volatile memory; go to
        idle. Valid in calibration.
    0x2F:
      id: clear_clb
      -orig-id: ClearClb
      doc: |
        ClearClb (6.4.9): Clear the hard/soft-iron calibration parameters from non-volatile
        memory. Valid in idle.
    0x40:
      id: load_ahrs_par
      -orig-id: LoadAHRSPar
      doc: |
        LoadAHRSPar (6.3.6): Load the user parameter block (Table 6.9) into non-volatile memory.
        Valid in idle.
    0x41:
      id: read_ahrs_par
      -orig-id: ReadAHRSPar
      doc: |
        ReadAHRSPar (6.3.7): Read the parameter block (Table 6.10) from non-volatile memory. Valid
        in idle.
    0x80:
      id: ahrs_cont1
      -orig-id: AHRScont1
      doc: |
        AHRScont1 (6.3.1): Start continuous output in the Full Output Data format (Table 6.4).
        Valid in idle.
    0x82:
      id: ahrs_cont2
      -orig-id: AHRScont2
      doc: |
        AHRScont2 (6.3.1): Start continuous output in the Quaternion of Orientation format (Table
        6.5). Valid in idle.
    0x83:
      id: ahrs_cont3
      -orig-id: AHRScont3
      doc: |
        AHRScont3 (6.3.1): Start continuous output in the Orientation + Sensor Outputs format
        (Table 6.6). Valid in idle.
    0x84:
      id: ahrs_req1
      -orig-id: AHRSreq1
      doc: |
        AHRSreq1 (6.3.2): Start on-request output in the Full Output Data format (Table 6.4).
        Valid in idle.
    0x86:
      id: ahrs_req2
      -orig-id: AHRSreq2
      doc: |
        AHRSreq2 (6.3.2): Start on-request output in the Quaternion of Orientation format (Table
        6.5). Valid in idle.
    0x87:
      id: ahrs_req3
      -orig-id: AHRSreq3
      doc: |
        AHRSreq3 (6.3.2): Start on-request output in the Orientation + Sensor Outputs format
        (Table 6.6). Valid in idle.
    0x88:
      id: nmea_cont
      -orig-id: NMEAcont
      doc: |
        NMEAcont (6.3.3): Start continuous output of $PAHR sentences (Table 6.7), at most 50 Hz.
        Valid in idle.
    0x89:
      id: nmea_req
      -orig-id: NMEAreq
      doc: |
        NMEAreq (6.3.3): Start on-request output of $PAHR sentences (Table 6.7). Valid in idle.
    0xB0:
      id: low_power_on
      -orig-id: LowPowerOn
      doc: |
        LowPowerOn (6.3.8): Switch to the low-power Sleep mode. Valid in idle, continuous,
        on_request.
    0xBA:
      id: low_power_off
      -orig-id: LowPowerOff
      doc: 'LowPowerOff (6.3.9): Wake from Sleep mode into idle. Valid in sleep.'
    0xCA:
      id: get_data_req
      -orig-id: GetDataReq
      doc: |
        GetDataReq (6.3.4): Ask for one block of the current output format in the On Request mode.
        Valid in on_request.
    0xFE:
      id: stop
      -orig-id: [Stop, ExitClb]
      doc: |
        Stop (6.3.5): Stop the current operating mode and go to idle. Valid in idle, continuous,
        on_request. Alias, same code: ExitClb (6.4.4): Leave calibration without computing or
        saving anything; go to idle. Valid in calibration. Kaitai holds a value once, so the enum
        names the code stop; the device tells the commands apart by its mode (E14).
  calibration_type:
    1:
      id: two_d
      doc: 2D calibration (Table 6.14, Table 6.15).
    2:
      id: two_d_two_t
      doc: 2D-2T calibration (Table 6.14, Table 6.15).
    3:
      id: three_d
      doc: 3D calibration (Table 6.14, Table 6.15).
  calibration_status_type:
    0:
      id: not_calibrated
      doc: The AHRS is not calibrated (Table 6.17).
    1:
      id: two_d
      doc: 2D calibration (Table 6.17).
    2:
      id: two_d_two_t
      doc: 2D-2T calibration (Table 6.17).
    3:
      id: three_d
      doc: 3D calibration (Table 6.17).
