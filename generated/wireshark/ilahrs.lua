-- Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
-- Do not edit: change the spec or the generator and run `make generate`.
-- SPDX-License-Identifier: MIT OR Apache-2.0
--
-- Wireshark dissector for the Inertial Labs AHRS Interface Control Document, revision 1.7
-- (spec ilahrs 1.0.0). Install: see README.md beside this file.
--
-- Part 1 is the spec as Lua tables. Part 2, after them, is the dissector: generic code that reads
-- only these tables (generator/targets/wireshark/runtime/). Tested with Wireshark 4.0 (Lua 5.2).

-- Part 1: the spec ------------------------------------------------------------------------------

local SPEC = {
  name = "ilahrs",
  version = "1.0.0",
  sha256 = "509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d",
  icd = "Inertial Labs AHRS Interface Control Document, revision 1.7",
  byte_order = "little",
  max_message_size = 82,
}

SPEC.units = {
  deg = { suffix = "deg", doc = "degrees" },
  deg_per_s = { suffix = "dps", doc = "degrees per second" },
  g = { suffix = "g", doc = "standard gravity" },
  nT = { suffix = "nt", doc = "nanotesla" },
  V = { suffix = "v", doc = "volts DC" },
  degC = { suffix = "degc", doc = "degrees Celsius" },
  one = { suffix = "value", doc = "dimensionless" },
  Hz = { suffix = "hz", doc = "hertz" },
  s = { suffix = "s", doc = "seconds" },
  m = { suffix = "m", doc = "metres" },
  adc = { suffix = "adc", doc = "ADC codes (no physical scale given by the ICD)" },
  percent = { suffix = "percent", doc = "percent" },
  year = { suffix = "year", doc = "fractional year, see encoding `date`" },
}

-- Table 6.2, Table 6.3: header, the fields up to the payload, payload, checksum.
SPEC.frame = {
  header = { 0xAA, 0x55 },
  fields = {
    { name = "message_type", icd_name = "Message type", label = "Message type", type = "u8", offset = 2, size = 1, doc = "0 for commands, 1 for data. Every AHRS output is data (Table 6.2)." },
    { name = "reserved", icd_name = "Reserved", label = "Reserved", type = "u8", offset = 3, size = 1, doc = "Not defined by rev 1.7. Decoders accept any value and expose it; builders write 0 unless told otherwise (E6). A strict decoder refuses a data frame whose value is not the one the AHRS sends (`strict`, E42)." },
    { name = "message_length", icd_name = "Message length", label = "Message length", type = "u16", offset = 4, size = 2, doc = "Number of bytes after the 2-byte header, message type through checksum (Table 6.2)." },
  },
  message_type_offset = 2,
  length_offset = 4,
  length_size = 2,
  payload_offset = 6,
  checksum = { name = "checksum", icd_name = "Check sum", label = "Check sum", type = "u16", offset = -1, size = 2, doc = "" },
  checksum_algorithm = "sum16",
  checksum_doc = "Arithmetic sum, modulo 2^16, of every byte from the message type through the last payload byte (Table 6.2: bytes 2 ... n-1); low byte first (Table 6.3) (E28).",
  message_types = {
    { name = "command", value = 0, doc = "A command from the host (one-byte payload holding the command code)." },
    { name = "data", value = 1, doc = "Data: every AHRS output, and the parameter blocks the host sends (E5)." },
  },
  command_type = 0,
  data_type = 1,
  min_length = 7,
  max_length = 58,
  length_bias = 6,
}

-- Table C.1 and sections 6.3, 6.4.
SPEC.commands = {
  { name = "AHRScont1", id = "ahrs_cont1", code = 128, icd = "6.3.1", group = "control", purpose = "Start continuous output in the Full Output Data format (Table 6.4).", valid_in = { "idle" }, response = "ack", payloads = {}, starts_output = "full_output", default_for_code = false, former_names = {} },
  { name = "AHRScont2", id = "ahrs_cont2", code = 130, icd = "6.3.1", group = "control", purpose = "Start continuous output in the Quaternion of Orientation format (Table 6.5).", valid_in = { "idle" }, response = "ack", payloads = {}, starts_output = "quaternion", default_for_code = false, former_names = {} },
  { name = "AHRScont3", id = "ahrs_cont3", code = 131, icd = "6.3.1", group = "control", purpose = "Start continuous output in the Orientation + Sensor Outputs format (Table 6.6).", valid_in = { "idle" }, response = "ack", payloads = {}, starts_output = "orientation_sensors", default_for_code = false, former_names = {} },
  { name = "AHRSreq1", id = "ahrs_req1", code = 132, icd = "6.3.2", group = "control", purpose = "Start on-request output in the Full Output Data format (Table 6.4).", valid_in = { "idle" }, response = "ack", payloads = {}, starts_output = "full_output", default_for_code = false, former_names = {} },
  { name = "AHRSreq2", id = "ahrs_req2", code = 134, icd = "6.3.2", group = "control", purpose = "Start on-request output in the Quaternion of Orientation format (Table 6.5).", valid_in = { "idle" }, response = "ack", payloads = {}, starts_output = "quaternion", default_for_code = false, former_names = {} },
  { name = "AHRSreq3", id = "ahrs_req3", code = 135, icd = "6.3.2", group = "control", purpose = "Start on-request output in the Orientation + Sensor Outputs format (Table 6.6).", valid_in = { "idle" }, response = "ack", payloads = {}, starts_output = "orientation_sensors", default_for_code = false, former_names = {} },
  { name = "NMEAcont", id = "nmea_cont", code = 136, icd = "6.3.3", group = "control", purpose = "Start continuous output of $PAHR sentences (Table 6.7), at most 50 Hz.", valid_in = { "idle" }, response = "ack", payloads = {}, starts_output = "nmea", default_for_code = false, former_names = {} },
  { name = "NMEAreq", id = "nmea_req", code = 137, icd = "6.3.3", group = "control", purpose = "Start on-request output of $PAHR sentences (Table 6.7).", valid_in = { "idle" }, response = "ack", payloads = {}, starts_output = "nmea", default_for_code = false, former_names = {} },
  { name = "GetDataReq", id = "get_data_req", code = 202, icd = "6.3.4", group = "control", purpose = "Ask for one block of the current output format in the On Request mode.", valid_in = { "on_request" }, response = "output", payloads = {}, default_for_code = false, former_names = {} },
  { name = "Stop", id = "stop", code = 254, icd = "6.3.5", group = "control", purpose = "Stop the current operating mode and go to idle.", valid_in = { "idle", "continuous", "on_request" }, response = "none", payloads = {}, default_for_code = true, former_names = {}, erratum = "E14" },
  { name = "LoadAHRSPar", id = "load_ahrs_par", code = 64, icd = "6.3.6", group = "control", purpose = "Load the user parameter block (Table 6.9) into non-volatile memory.", valid_in = { "idle" }, response = "none", payloads = {}, parameter_block = "ahrs_parameters_load", default_for_code = false, former_names = {}, erratum = "E13" },
  { name = "ReadAHRSPar", id = "read_ahrs_par", code = 65, icd = "6.3.7", group = "control", purpose = "Read the parameter block (Table 6.10) from non-volatile memory.", valid_in = { "idle" }, response = "data", payloads = { "ahrs_parameters_read" }, default_for_code = false, former_names = {} },
  { name = "LowPowerOn", id = "low_power_on", code = 176, icd = "6.3.8", group = "control", purpose = "Switch to the low-power Sleep mode.", valid_in = { "idle", "continuous", "on_request" }, response = "none", payloads = {}, default_for_code = false, former_names = {}, erratum = "E35" },
  { name = "LowPowerOff", id = "low_power_off", code = 186, icd = "6.3.9", group = "control", purpose = "Wake from Sleep mode into idle.", valid_in = { "sleep" }, response = "none", payloads = {}, default_for_code = false, former_names = {} },
  { name = "GetVerFirmware", id = "get_ver_firmware", code = 31, icd = "6.3.10", group = "control", purpose = "Read the firmware version string (Table 6.11).", valid_in = { "idle" }, response = "data", payloads = { "firmware_version" }, default_for_code = false, former_names = {} },
  { name = "GetBIT", id = "get_bit", code = 26, icd = "6.3.11", group = "control", purpose = "Read the built-in-test answer, temperature and Unit Status Word (Table 6.12).", valid_in = { "idle", "on_request" }, response = "data", payloads = { "bit_result" }, default_for_code = false, former_names = {}, erratum = "E25" },
  { name = "Start2DClb", id = "start_2d_clb", code = 33, icd = "6.4.8", group = "calibration", purpose = "Start 2D hard/soft-iron calibration; the calibration parameter block (Table 6.13) follows.", valid_in = { "idle" }, response = "none", payloads = {}, parameter_block = "calibration_parameters", default_for_code = false, former_names = {}, erratum = "E13" },
  { name = "Start2D2TClb", id = "start_2d2t_clb", code = 34, icd = "6.4.5", group = "calibration", purpose = "Start 2D-2T (multi-run) calibration; the calibration parameter block (Table 6.13) follows.", valid_in = { "idle" }, response = "none", payloads = {}, parameter_block = "calibration_parameters", default_for_code = false, former_names = {}, erratum = "E13" },
  { name = "Start3DClb", id = "start_3d_clb", code = 35, icd = "6.4.1", group = "calibration", purpose = "Start 3D calibration; the calibration parameter block (Table 6.13) follows.", valid_in = { "idle" }, response = "none", payloads = {}, parameter_block = "calibration_parameters", default_for_code = false, former_names = {}, erratum = "E13" },
  { name = "StartClbRun", id = "start_clb_run", code = 43, icd = "6.4.6", group = "calibration", purpose = "Start one run of a multi-run (2D-2T) calibration; the run parameter block (Table 6.16) follows.", valid_in = { "calibration" }, response = "none", payloads = {}, parameter_block = "calibration_run_parameters", default_for_code = false, former_names = {}, erratum = "E13" },
  { name = "StopClbRun", id = "stop_clb_run", code = 32, icd = "6.4.2", group = "calibration", purpose = "Stop data accumulation in the current calibration run before its set time.", valid_in = { "calibration" }, response = "data", payloads = { "calibration_result", "calibration_run_result" }, default_for_code = false, former_names = { "StopClb" } },
  { name = "FinishClb", id = "finish_clb", code = 44, icd = "6.4.7", group = "calibration", purpose = "Finish a multi-run (2D-2T) calibration and compute its result (Table 6.14).", valid_in = { "calibration" }, response = "data", payloads = { "calibration_result" }, default_for_code = false, former_names = {} },
  { name = "AcceptClb", id = "accept_clb", code = 46, icd = "6.4.3", group = "calibration", purpose = "Accept the calibration result and save it to non-volatile memory; go to idle.", valid_in = { "calibration" }, response = "ack", payloads = {}, default_for_code = false, former_names = {} },
  { name = "ExitClb", id = "exit_clb", code = 254, icd = "6.4.4", group = "calibration", purpose = "Leave calibration without computing or saving anything; go to idle.", valid_in = { "calibration" }, response = "ack", payloads = {}, default_for_code = false, former_names = {}, erratum = "E14" },
  { name = "ClearClb", id = "clear_clb", code = 47, icd = "6.4.9", group = "calibration", purpose = "Clear the hard/soft-iron calibration parameters from non-volatile memory.", valid_in = { "idle" }, response = "ack", payloads = {}, default_for_code = false, former_names = {} },
  { name = "GetClbRes", id = "get_clb_res", code = 42, icd = "6.4.10", group = "calibration", purpose = "Read the results of the last calibration (Table 6.17).", valid_in = { "idle" }, response = "data", payloads = { "calibration_status" }, default_for_code = false, former_names = {} },
}

SPEC.ack_payload = "acknowledgement"

SPEC.payloads = {
  {
    name = "full_output", icd = "Table 6.4", title = "Full Output Data",
    direction = "device_to_host", size = 34, erratum = nil,
    doc = "Output block after AHRScont1 / AHRSreq1.",
    fields = {
      { name = "heading", icd_name = "Heading", label = "Heading", type = "u16", offset = 0, size = 2, unit = "deg", multiplier = 1, divisor = 100, erratum = "E23", doc = "Heading angle." },
      { name = "pitch", icd_name = "Pitch", label = "Pitch", type = "s16", offset = 2, size = 2, unit = "deg", multiplier = 1, divisor = 100, doc = "Pitch angle." },
      { name = "roll", icd_name = "Roll", label = "Roll", type = "s16", offset = 4, size = 2, unit = "deg", multiplier = 1, divisor = 100, doc = "Roll angle." },
      { name = "ugyro_x", icd_name = "Ugyro", label = "Ugyro X", type = "s16", offset = 6, size = 2, unit = "adc", doc = "Raw gyro X sensor data." },
      { name = "ugyro_y", icd_name = "Ugyro", label = "Ugyro Y", type = "s16", offset = 8, size = 2, unit = "adc", doc = "Raw gyro Y sensor data." },
      { name = "ugyro_z", icd_name = "Ugyro", label = "Ugyro Z", type = "s16", offset = 10, size = 2, unit = "adc", doc = "Raw gyro Z sensor data." },
      { name = "uacc_x", icd_name = "Uacc", label = "Uacc X", type = "s16", offset = 12, size = 2, unit = "adc", doc = "Raw accelerometer X sensor data." },
      { name = "uacc_y", icd_name = "Uacc", label = "Uacc Y", type = "s16", offset = 14, size = 2, unit = "adc", doc = "Raw accelerometer Y sensor data." },
      { name = "uacc_z", icd_name = "Uacc", label = "Uacc Z", type = "s16", offset = 16, size = 2, unit = "adc", doc = "Raw accelerometer Z sensor data." },
      { name = "umag_x", icd_name = "Umag", label = "Umag X", type = "s16", offset = 18, size = 2, unit = "adc", doc = "Raw magnetometer X sensor data." },
      { name = "umag_y", icd_name = "Umag", label = "Umag Y", type = "s16", offset = 20, size = 2, unit = "adc", doc = "Raw magnetometer Y sensor data." },
      { name = "umag_z", icd_name = "Umag", label = "Umag Z", type = "s16", offset = 22, size = 2, unit = "adc", doc = "Raw magnetometer Z sensor data." },
      { name = "reserved", icd_name = "Reserved", label = "Reserved", type = "reserved", offset = 24, size = 4, doc = "" },
      { name = "usw", icd_name = "USW", label = "USW", type = "u16", offset = 28, size = 2, encoding = "usw", doc = "Unit Status Word (section 6.5)." },
      { name = "vdd", icd_name = "Vdd", label = "Vdd", type = "u16", offset = 30, size = 2, unit = "V", multiplier = 1, divisor = 1000, multiplexed = 2, erratum = "E19", doc = "Combined voltage: successive frames carry the AHRS input voltage and the stabilised sensor supply voltage in turn (Table 6.4 note 2). The frame does not say which." },
      { name = "utermo", icd_name = "Utermo", label = "Utermo", type = "s16", offset = 32, size = 2, unit = "adc", multiplexed = 7, erratum = "E19", doc = "ADC code of one of 7 temperature sensors, in turn in successive frames (Table 6.4 note 3). The frame does not say which." },
    },
  },
  {
    name = "quaternion", icd = "Table 6.5", title = "Quaternion of Orientation",
    direction = "device_to_host", size = 34, erratum = nil,
    doc = "Output block after AHRScont2 / AHRSreq2.",
    fields = {
      { name = "heading", icd_name = "Heading", label = "Heading", type = "u16", offset = 0, size = 2, unit = "deg", multiplier = 1, divisor = 100, erratum = "E23", doc = "Heading angle." },
      { name = "pitch", icd_name = "Pitch", label = "Pitch", type = "s16", offset = 2, size = 2, unit = "deg", multiplier = 1, divisor = 100, doc = "Pitch angle." },
      { name = "roll", icd_name = "Roll", label = "Roll", type = "s16", offset = 4, size = 2, unit = "deg", multiplier = 1, divisor = 100, doc = "Roll angle." },
      { name = "lk0", icd_name = "Lk0", label = "Lk0", type = "s16", offset = 6, size = 2, unit = "one", multiplier = 1, divisor = 10000, doc = "Quaternion of orientation, scalar component." },
      { name = "lk1", icd_name = "Lk1", label = "Lk1", type = "s16", offset = 8, size = 2, unit = "one", multiplier = 1, divisor = 10000, doc = "Quaternion of orientation, first vector component." },
      { name = "lk2", icd_name = "Lk2", label = "Lk2", type = "s16", offset = 10, size = 2, unit = "one", multiplier = 1, divisor = 10000, doc = "Quaternion of orientation, second vector component." },
      { name = "lk3", icd_name = "Lk3", label = "Lk3", type = "s16", offset = 12, size = 2, unit = "one", multiplier = 1, divisor = 10000, doc = "Quaternion of orientation, third vector component." },
      { name = "reserved", icd_name = "Reserved", label = "Reserved", type = "reserved", offset = 14, size = 14, doc = "" },
      { name = "usw", icd_name = "USW", label = "USW", type = "u16", offset = 28, size = 2, encoding = "usw", doc = "Unit Status Word (section 6.5)." },
      { name = "vdd", icd_name = "Vdd", label = "Vdd", type = "u16", offset = 30, size = 2, unit = "V", multiplier = 1, divisor = 1000, doc = "AHRS input voltage." },
      { name = "utermo", icd_name = "Utermo", label = "Utermo", type = "s16", offset = 32, size = 2, unit = "degC", multiplier = 1, divisor = 10, doc = "Average temperature of the 3 accelerometers." },
    },
  },
  {
    name = "orientation_sensors", icd = "Table 6.6", title = "Orientation + Sensor Outputs",
    direction = "device_to_host", size = 34, erratum = nil,
    doc = "Output block after AHRScont3 / AHRSreq3 (the default format, section 6.2).",
    fields = {
      { name = "heading", icd_name = "Heading", label = "Heading", type = "u16", offset = 0, size = 2, unit = "deg", multiplier = 1, divisor = 100, erratum = "E23", doc = "Heading angle." },
      { name = "pitch", icd_name = "Pitch", label = "Pitch", type = "s16", offset = 2, size = 2, unit = "deg", multiplier = 1, divisor = 100, doc = "Pitch angle." },
      { name = "roll", icd_name = "Roll", label = "Roll", type = "s16", offset = 4, size = 2, unit = "deg", multiplier = 1, divisor = 100, doc = "Roll angle." },
      { name = "gyro_x", icd_name = "GyroX", label = "GyroX", type = "s16", offset = 6, size = 2, unit = "deg_per_s", multiplier = 1, divisor = "KG", doc = "Angular rate about X (lateral axis)." },
      { name = "gyro_y", icd_name = "GyroY", label = "GyroY", type = "s16", offset = 8, size = 2, unit = "deg_per_s", multiplier = 1, divisor = "KG", doc = "Angular rate about Y (longitudinal axis)." },
      { name = "gyro_z", icd_name = "GyroZ", label = "GyroZ", type = "s16", offset = 10, size = 2, unit = "deg_per_s", multiplier = 1, divisor = "KG", doc = "Angular rate about Z (vertical axis)." },
      { name = "acc_x", icd_name = "AccX", label = "AccX", type = "s16", offset = 12, size = 2, unit = "g", multiplier = 1, divisor = "KA", doc = "Linear acceleration along X." },
      { name = "acc_y", icd_name = "AccY", label = "AccY", type = "s16", offset = 14, size = 2, unit = "g", multiplier = 1, divisor = "KA", doc = "Linear acceleration along Y." },
      { name = "acc_z", icd_name = "AccZ", label = "AccZ", type = "s16", offset = 16, size = 2, unit = "g", multiplier = 1, divisor = "KA", doc = "Linear acceleration along Z." },
      { name = "mag_x", icd_name = "MagX", label = "MagX", type = "s16", offset = 18, size = 2, unit = "nT", multiplier = 10, divisor = 1, doc = "Magnetic field along X." },
      { name = "mag_y", icd_name = "MagY", label = "MagY", type = "s16", offset = 20, size = 2, unit = "nT", multiplier = 10, divisor = 1, doc = "Magnetic field along Y." },
      { name = "mag_z", icd_name = "MagZ", label = "MagZ", type = "s16", offset = 22, size = 2, unit = "nT", multiplier = 10, divisor = 1, doc = "Magnetic field along Z." },
      { name = "reserved", icd_name = "Reserved", label = "Reserved", type = "reserved", offset = 24, size = 4, doc = "" },
      { name = "usw", icd_name = "USW", label = "USW", type = "u16", offset = 28, size = 2, encoding = "usw", doc = "Unit Status Word (section 6.5)." },
      { name = "vdd", icd_name = "Vdd", label = "Vdd", type = "u16", offset = 30, size = 2, unit = "V", multiplier = 1, divisor = 1000, doc = "AHRS input voltage." },
      { name = "utermo", icd_name = "Utermo", label = "Utermo", type = "s16", offset = 32, size = 2, unit = "degC", multiplier = 1, divisor = 10, doc = "Average temperature of the 3 accelerometers." },
    },
  },
  {
    name = "initial_alignment", icd = "Table 6.8", title = "Initial alignment data",
    direction = "device_to_host", size = 50, erratum = "E21",
    doc = "Sent once when initial alignment completes, before continuous / on-request output or a calibration run starts (6.3.1 - 6.3.3, 6.4). Note the ICD order: heading, roll, pitch.",
    fields = {
      { name = "gyro_bias_x", icd_name = "Gyros bias", label = "Gyros bias X", type = "f32", offset = 0, size = 4, unit = "adc", doc = "Gyro X bias." },
      { name = "gyro_bias_y", icd_name = "Gyros bias", label = "Gyros bias Y", type = "f32", offset = 4, size = 4, unit = "adc", doc = "Gyro Y bias." },
      { name = "gyro_bias_z", icd_name = "Gyros bias", label = "Gyros bias Z", type = "f32", offset = 8, size = 4, unit = "adc", doc = "Gyro Z bias." },
      { name = "average_acc_x", icd_name = "Average acceleration", label = "Average acceleration X", type = "f32", offset = 12, size = 4, unit = "adc", doc = "Average acceleration along X." },
      { name = "average_acc_y", icd_name = "Average acceleration", label = "Average acceleration Y", type = "f32", offset = 16, size = 4, unit = "adc", doc = "Average acceleration along Y." },
      { name = "average_acc_z", icd_name = "Average acceleration", label = "Average acceleration Z", type = "f32", offset = 20, size = 4, unit = "adc", doc = "Average acceleration along Z." },
      { name = "average_mag_x", icd_name = "Average magn. field", label = "Average magn. field X", type = "f32", offset = 24, size = 4, unit = "adc", doc = "Average magnetic field along X." },
      { name = "average_mag_y", icd_name = "Average magn. field", label = "Average magn. field Y", type = "f32", offset = 28, size = 4, unit = "adc", doc = "Average magnetic field along Y." },
      { name = "average_mag_z", icd_name = "Average magn. field", label = "Average magn. field Z", type = "f32", offset = 32, size = 4, unit = "adc", doc = "Average magnetic field along Z." },
      { name = "initial_heading", icd_name = "Initial Heading", label = "Initial Heading", type = "f32", offset = 36, size = 4, unit = "deg", doc = "Heading at the end of alignment." },
      { name = "initial_roll", icd_name = "Initial Roll", label = "Initial Roll", type = "f32", offset = 40, size = 4, unit = "deg", doc = "Roll at the end of alignment." },
      { name = "initial_pitch", icd_name = "Initial Pitch", label = "Initial Pitch", type = "f32", offset = 44, size = 4, unit = "deg", doc = "Pitch at the end of alignment." },
      { name = "usw", icd_name = "USW", label = "USW", type = "u16", offset = 48, size = 2, encoding = "usw", erratum = "E27", doc = "Unit Status Word: 0 after a successful alignment, non-zero otherwise." },
    },
  },
  {
    name = "ahrs_parameters_load", icd = "Table 6.9", title = "Parameters to load",
    direction = "host_to_device", size = 50, erratum = nil,
    doc = "The data message the host sends right after LoadAHRSPar (6.3.6). Read the block first (ReadAHRSPar), change it, send it back.",
    fields = {
      { name = "update_rate", icd_name = "Update rate", label = "Update rate", type = "u16", offset = 0, size = 2, unit = "Hz", erratum = "E22", doc = "Output data rate, 1 to 100 Hz (the AHRS limits NMEA output to 50 Hz)." },
      { name = "alignment_time", icd_name = "Initial alignment time", label = "Initial alignment time", type = "u16", offset = 2, size = 2, unit = "s", erratum = "E30", doc = "Initial alignment duration; default 30 s, change only in agreement with Inertial Labs." },
      { name = "declination", icd_name = "Magnetic declination, Mdec", label = "Magnetic declination, Mdec", type = "f32", offset = 4, size = 4, unit = "deg", encoding = "declination", doc = "Magnetic declination; a value above 360 asks the AHRS to compute it from position and date." },
      { name = "latitude", icd_name = "Latitude", label = "Latitude", type = "f32", offset = 8, size = 4, unit = "deg", doc = "Latitude." },
      { name = "longitude", icd_name = "Longitude", label = "Longitude", type = "f32", offset = 12, size = 4, unit = "deg", doc = "Longitude." },
      { name = "altitude", icd_name = "Altitude", label = "Altitude", type = "f32", offset = 16, size = 4, unit = "m", erratum = "E31", doc = "Altitude." },
      { name = "date", icd_name = "Date (Year, Month, Day)", label = "Date (Year, Month, Day)", type = "f32", offset = 20, size = 4, unit = "year", encoding = "date", doc = "Date as Year + (Month - 1)/12 + Day/365." },
      { name = "alignment_angle_a1", icd_name = "Alignment angle A1", label = "Alignment angle A1", type = "f32", offset = 24, size = 4, unit = "deg", erratum = "E31", doc = "Mounting angle 1: AHRS Y axis relative to the object's longitudinal axis in its horizontal plane, clockwise positive (Appendix B)." },
      { name = "alignment_angle_a2", icd_name = "Alignment angle A2", label = "Alignment angle A2", type = "f32", offset = 28, size = 4, unit = "deg", erratum = "E31", doc = "Mounting angle 2: inclination of the AHRS Y axis to the object's horizontal plane, up positive (Appendix B)." },
      { name = "alignment_angle_a3", icd_name = "Alignment angle A3", label = "Alignment angle A3", type = "f32", offset = 32, size = 4, unit = "deg", erratum = "E31", doc = "Mounting angle 3: inclination of the AHRS X axis about its Y axis, X down positive (Appendix B)." },
      { name = "reserved", icd_name = "Reserved", label = "Reserved", type = "reserved", offset = 36, size = 14, doc = "Should be all zeros." },
    },
  },
  {
    name = "ahrs_parameters_read", icd = "Table 6.10", title = "Parameters read",
    direction = "device_to_host", size = 50, erratum = nil,
    doc = "The AHRS answer to ReadAHRSPar (6.3.7).",
    fields = {
      { name = "update_rate", icd_name = "Measurement rate", label = "Measurement rate", type = "u16", offset = 0, size = 2, unit = "Hz", erratum = "E24", doc = "Output data rate." },
      { name = "alignment_time", icd_name = "Initial alignment time", label = "Initial alignment time", type = "u16", offset = 2, size = 2, unit = "s", erratum = "E30", doc = "Initial alignment duration." },
      { name = "declination", icd_name = "Magnetic declination", label = "Magnetic declination", type = "f32", offset = 4, size = 4, unit = "deg", encoding = "declination", doc = "Magnetic declination; a value above 360 means the AHRS computes it." },
      { name = "latitude", icd_name = "Latitude", label = "Latitude", type = "f32", offset = 8, size = 4, unit = "deg", doc = "Latitude." },
      { name = "longitude", icd_name = "Longitude", label = "Longitude", type = "f32", offset = 12, size = 4, unit = "deg", doc = "Longitude." },
      { name = "altitude", icd_name = "Altitude", label = "Altitude", type = "f32", offset = 16, size = 4, unit = "m", erratum = "E31", doc = "Altitude." },
      { name = "date", icd_name = "Date (Year, Month, Day)", label = "Date (Year, Month, Day)", type = "f32", offset = 20, size = 4, unit = "year", encoding = "date", doc = "Date as Year + (Month - 1)/12 + Day/365." },
      { name = "alignment_angle_a1", icd_name = "Alignment angle A1", label = "Alignment angle A1", type = "f32", offset = 24, size = 4, unit = "deg", erratum = "E31", doc = "Mounting angle 1 (Appendix B)." },
      { name = "alignment_angle_a2", icd_name = "Alignment angle A2", label = "Alignment angle A2", type = "f32", offset = 28, size = 4, unit = "deg", erratum = "E31", doc = "Mounting angle 2 (Appendix B)." },
      { name = "alignment_angle_a3", icd_name = "Alignment angle A3", label = "Alignment angle A3", type = "f32", offset = 32, size = 4, unit = "deg", erratum = "E31", doc = "Mounting angle 3 (Appendix B)." },
      { name = "device_id", icd_name = "Device ID", label = "Device ID", type = "char", offset = 36, size = 8, doc = "Device identifier (read only)." },
      { name = "reserved", icd_name = "Reserved", label = "Reserved", type = "reserved", offset = 44, size = 6, doc = "" },
    },
  },
  {
    name = "firmware_version", icd = "Table 6.11", title = "Firmware version",
    direction = "device_to_host", size = 50, erratum = nil,
    doc = "The AHRS answer to GetVerFirmware (6.3.10).",
    fields = {
      { name = "version", icd_name = "Firmware version", label = "Firmware version", type = "char", offset = 0, size = 50, doc = "Firmware version text, NUL-padded." },
    },
  },
  {
    name = "bit_result", icd = "Table 6.12", title = "Built-in test answer",
    direction = "device_to_host", size = 4, erratum = nil,
    doc = "The AHRS answer to GetBIT (6.3.11).",
    fields = {
      { name = "utermo100", icd_name = "Utermo100", label = "Utermo100", type = "s16", offset = 0, size = 2, unit = "degC", multiplier = 1, divisor = 100, erratum = "E4", doc = "AHRS temperature in 1/100 degC." },
      { name = "usw", icd_name = "USW", label = "USW", type = "u16", offset = 2, size = 2, encoding = "usw", doc = "Unit Status Word (section 6.5)." },
    },
  },
  {
    name = "calibration_parameters", icd = "Table 6.13", title = "Calibration parameters",
    direction = "host_to_device", size = 22, erratum = nil,
    doc = "The data message the host sends right after Start3DClb, Start2D2TClb or Start2DClb (6.4.1, 6.4.5, 6.4.8).",
    fields = {
      { name = "reference_azimuth", icd_name = "Reserved", label = "Reserved", type = "f32", offset = 0, size = 4, unit = "deg", erratum = "E8", doc = "Reference azimuth (6.4.8); no influence on 2D calibration." },
      { name = "accumulation_time", icd_name = "Time of data accumulation in one run", label = "Time of data accumulation in one run", type = "u16", offset = 4, size = 2, unit = "s", erratum = "E30", doc = "Data accumulation time of one run." },
      { name = "latitude", icd_name = "Latitude", label = "Latitude", type = "f32", offset = 6, size = 4, unit = "deg", doc = "Latitude." },
      { name = "longitude", icd_name = "Longitude", label = "Longitude", type = "f32", offset = 10, size = 4, unit = "deg", doc = "Longitude." },
      { name = "altitude", icd_name = "Altitude", label = "Altitude", type = "f32", offset = 14, size = 4, unit = "m", erratum = "E31", doc = "Altitude." },
      { name = "date", icd_name = "Date (Year, Month, Day)", label = "Date (Year, Month, Day)", type = "f32", offset = 18, size = 4, unit = "year", encoding = "date", doc = "Date as Year + (Month - 1)/12 + Day/365." },
    },
  },
  {
    name = "calibration_result", icd = "Table 6.14", title = "Calibration result",
    direction = "device_to_host", size = 52, erratum = "E1",
    doc = "Sent when a calibration completes (after the accumulation time, StopClbRun, or FinishClb).",
    fields = {
      { name = "calibration_type", icd_name = "Type of calibration", label = "Type of calibration", type = "u8", offset = 0, size = 1, enum = "calibration_type", doc = "1 for 2D, 2 for 2D-2T, 3 for 3D calibration." },
      { name = "runs_used", icd_name = "Number of used calibration runs", label = "Number of used calibration runs", type = "u8", offset = 1, size = 1, doc = "Number of calibration runs used." },
      { name = "data_used", icd_name = "Percent of used data points", label = "Percent of used data points", type = "u8", offset = 2, size = 1, unit = "percent", doc = "Percent of data points used (2D and 3D calibrations only)." },
      { name = "success", icd_name = "Calibration success", label = "Calibration success", type = "u8", offset = 3, size = 1, encoding = "calibration_success", erratum = "E26", doc = "0: not successful; 1..254: predicted 3-sigma heading error in deg*10; 255: successful without an estimate." },
      { name = "tm_c_11", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 11", type = "f32", offset = 4, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 1 column 1." },
      { name = "tm_c_12", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 12", type = "f32", offset = 8, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 1 column 2." },
      { name = "tm_c_13", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 13", type = "f32", offset = 12, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 1 column 3." },
      { name = "tm_c_21", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 21", type = "f32", offset = 16, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 2 column 1." },
      { name = "tm_c_22", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 22", type = "f32", offset = 20, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 2 column 2." },
      { name = "tm_c_23", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 23", type = "f32", offset = 24, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 2 column 3." },
      { name = "tm_c_31", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 31", type = "f32", offset = 28, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 3 column 1." },
      { name = "tm_c_32", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 32", type = "f32", offset = 32, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 3 column 2." },
      { name = "tm_c_33", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 33", type = "f32", offset = 36, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 3 column 3." },
      { name = "hm_0_x", icd_name = "Matrix for hard iron correction", label = "Matrix for hard iron correction X", type = "f32", offset = 40, size = 4, unit = "adc", erratum = "E1", doc = "Hard-iron vector Hm_0 component 1." },
      { name = "hm_0_y", icd_name = "Matrix for hard iron correction", label = "Matrix for hard iron correction Y", type = "f32", offset = 44, size = 4, unit = "adc", erratum = "E1", doc = "Hard-iron vector Hm_0 component 2." },
      { name = "hm_0_z", icd_name = "Matrix for hard iron correction", label = "Matrix for hard iron correction Z", type = "f32", offset = 48, size = 4, unit = "adc", erratum = "E1", doc = "Hard-iron vector Hm_0 component 3." },
    },
  },
  {
    name = "calibration_run_result", icd = "Table 6.15", title = "2D-2T calibration run result",
    direction = "device_to_host", size = 30, erratum = nil,
    doc = "Sent after each run of a 2D-2T calibration (6.4.5).",
    fields = {
      { name = "calibration_type", icd_name = "Type of calibration", label = "Type of calibration", type = "u8", offset = 0, size = 1, enum = "calibration_type", doc = "2 for 2D-2T calibration." },
      { name = "run", icd_name = "Calibration run", label = "Calibration run", type = "u8", offset = 1, size = 1, doc = "Number of this run (1, 2, ...)." },
      { name = "data_used", icd_name = "Percent of used data points", label = "Percent of used data points", type = "u8", offset = 2, size = 1, unit = "percent", doc = "Percent of data points used." },
      { name = "success", icd_name = "Calibration success", label = "Calibration success", type = "u8", offset = 3, size = 1, encoding = "calibration_success", erratum = "E26", doc = "0: run not successful (excluded); 1..254: predicted heading error in deg*10; 255: successful without an estimate." },
      { name = "reserved_1", icd_name = "Reserved", label = "Reserved 1", type = "reserved", offset = 4, size = 4, erratum = "E32", doc = "" },
      { name = "average_pitch", icd_name = "Average pitch, deg", label = "Average pitch, deg", type = "f32", offset = 8, size = 4, unit = "deg", doc = "Average pitch during the run." },
      { name = "average_roll", icd_name = "Average roll, deg", label = "Average roll, deg", type = "f32", offset = 12, size = 4, unit = "deg", doc = "Average roll during the run." },
      { name = "reserved_2", icd_name = "Reserved", label = "Reserved 2", type = "reserved", offset = 16, size = 12, erratum = "E32", doc = "" },
      { name = "usw", icd_name = "USW", label = "USW", type = "u16", offset = 28, size = 2, encoding = "usw", doc = "Unit Status Word (section 6.5)." },
    },
  },
  {
    name = "calibration_run_parameters", icd = "Table 6.16", title = "Calibration run parameters",
    direction = "host_to_device", size = 6, erratum = nil,
    doc = "The data message the host sends right after StartClbRun (6.4.6); its 6 bytes do not influence 2D-2T calibration and may be any, e.g. zeros.",
    fields = {
      { name = "reserved", icd_name = "Reserved", label = "Reserved", type = "reserved", offset = 0, size = 6, erratum = "E32", doc = "" },
    },
  },
  {
    name = "calibration_status", icd = "Table 6.17", title = "Calibration results read back",
    direction = "device_to_host", size = 52, erratum = "E2",
    doc = "The AHRS answer to GetClbRes (6.4.10).",
    fields = {
      { name = "calibration_type", icd_name = "Type of calibration performed", label = "Type of calibration performed", type = "u8", offset = 0, size = 1, enum = "calibration_status_type", doc = "0: not calibrated; 1: 2D; 2: 2D-2T; 3: 3D; above 0x80: parameters loaded by other software." },
      { name = "runs_used", icd_name = "Number of used calibration runs", label = "Number of used calibration runs", type = "u8", offset = 1, size = 1, doc = "Number of calibration runs used." },
      { name = "reserved", icd_name = "Reserved", label = "Reserved", type = "reserved", offset = 2, size = 1, erratum = "E3", doc = "" },
      { name = "success", icd_name = "Calibration success", label = "Calibration success", type = "u8", offset = 3, size = 1, encoding = "calibration_success", erratum = "E26", doc = "0: not successful; 1..254: predicted heading error in deg*10; 255: successful without an estimate." },
      { name = "tm_c_11", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 11", type = "f32", offset = 4, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 1 column 1." },
      { name = "tm_c_12", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 12", type = "f32", offset = 8, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 1 column 2." },
      { name = "tm_c_13", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 13", type = "f32", offset = 12, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 1 column 3." },
      { name = "tm_c_21", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 21", type = "f32", offset = 16, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 2 column 1." },
      { name = "tm_c_22", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 22", type = "f32", offset = 20, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 2 column 2." },
      { name = "tm_c_23", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 23", type = "f32", offset = 24, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 2 column 3." },
      { name = "tm_c_31", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 31", type = "f32", offset = 28, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 3 column 1." },
      { name = "tm_c_32", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 32", type = "f32", offset = 32, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 3 column 2." },
      { name = "tm_c_33", icd_name = "Matrix for soft iron correction", label = "Matrix for soft iron correction 33", type = "f32", offset = 36, size = 4, unit = "one", doc = "Soft-iron matrix Tm_c row 3 column 3." },
      { name = "hm_0_x", icd_name = "Matrix for hard iron correction", label = "Matrix for hard iron correction X", type = "f32", offset = 40, size = 4, unit = "adc", erratum = "E2", doc = "Hard-iron vector Hm_0 component 1." },
      { name = "hm_0_y", icd_name = "Matrix for hard iron correction", label = "Matrix for hard iron correction Y", type = "f32", offset = 44, size = 4, unit = "adc", erratum = "E2", doc = "Hard-iron vector Hm_0 component 2." },
      { name = "hm_0_z", icd_name = "Matrix for hard iron correction", label = "Matrix for hard iron correction Z", type = "f32", offset = 48, size = 4, unit = "adc", erratum = "E2", doc = "Hard-iron vector Hm_0 component 3." },
    },
  },
  {
    name = "acknowledgement", icd = "6.3.1 (Table 6.2 with a one-word payload)", title = "Acknowledgement",
    direction = "device_to_host", size = 2, erratum = nil,
    doc = "The checksum of the message the AHRS received (E12).",
    fields = {
      { name = "checksum", icd_name = "Check sum", label = "Check sum", type = "u16", offset = 0, size = 2, doc = "Checksum of the acknowledged message, message type through payload." },
    },
  },
}

SPEC.enums = {
  calibration_type = {
    external_above = nil,
    values = { [1] = "two_d", [2] = "two_d_two_t", [3] = "three_d", },
  },
  calibration_status_type = {
    external_above = 128,
    values = { [0] = "not_calibrated", [1] = "two_d", [2] = "two_d_two_t", [3] = "three_d", },
  },
}

SPEC.variant_parameters = { "KG", "KA" }
SPEC.variants = {
  { name = "g300_a2_tmga", part_number = "AHRS-G300-A2-TMGA-C1-V1.1", values = { KA = 10000, KG = 100 } },
  { name = "g300_a6_tmga", part_number = "AHRS-G300-A6-TMGA-C1-V1.1", values = { KA = 5000, KG = 100 } },
  { name = "sn_11ac0001_0009", part_number = "AHRS s/n 11AC0001 - 11AC0009", values = { KA = 10000, KG = 50 } },
  { name = "g300_a2_tga", part_number = "AHRS-G300-A2-TGA-C1-V1.1", values = { KA = 10000, KG = 100 } },
}

SPEC.encodings = { date = { terms = { { part = "year", offset = 0, divisor = 1 }, { part = "month", offset = -1, divisor = 12 }, { part = "day", offset = 0, divisor = 365 } }, year_min = 1900, year_max = 2199 }, declination = { min = -180, max = 180, compute_above = 360 }, calibration_success = { failed = 0, no_estimate = 255, accuracy_divisor = 10, accuracy_unit = "deg" } }

-- 6.5, Table 6.18, Table 6.19.
SPEC.status_word = {
  icd = "6.5, Table 6.18, Table 6.19",
  flags = {
    { bit = 0, name = "initial_alignment_failed", icd_name = "Initial Alignment", byte = "failure", doc = "Unsuccessful initial alignment (AHRS moved or the magnetic field changed)." },
    { bit = 1, name = "parameters_incorrect", icd_name = "AHRS Parameters", byte = "failure", doc = "The AHRS parameters are incorrect." },
    { bit = 2, name = "gyro_failure", icd_name = "Gyroscope Unit", byte = "failure", doc = "Gyroscope unit failure detected." },
    { bit = 3, name = "accelerometer_failure", icd_name = "Accelerometer Unit", byte = "failure", doc = "Accelerometer unit failure detected." },
    { bit = 4, name = "magnetometer_failure", icd_name = "Magnetometer Unit", byte = "failure", doc = "Magnetometer unit failure detected." },
    { bit = 5, name = "electronics_failure", icd_name = "Electronics", byte = "failure", doc = "Electronics failure detected." },
    { bit = 6, name = "software_failure", icd_name = "Software", byte = "failure", doc = "Software failure detected." },
    { bit = 8, name = "low_supply_voltage", icd_name = "Incorrect Power Supply", byte = "warning", doc = "Supply voltage below the minimum level." },
    { bit = 9, name = "high_supply_voltage", icd_name = "Incorrect Power Supply", byte = "warning", doc = "Supply voltage above the maximum level." },
    { bit = 10, name = "x_rate_exceeded", icd_name = "Angular Rate Exceeding Detect", byte = "warning", doc = "X angular rate out of range." },
    { bit = 11, name = "y_rate_exceeded", icd_name = "Angular Rate Exceeding Detect", byte = "warning", doc = "Y angular rate out of range." },
    { bit = 12, name = "z_rate_exceeded", icd_name = "Angular Rate Exceeding Detect", byte = "warning", doc = "Z angular rate out of range." },
    { bit = 13, name = "large_magnetic_field", icd_name = "Large Magnetic Field Detect", byte = "warning", doc = "Total magnetic field limit exceeded." },
    { bit = 14, name = "temperature_out_of_range", icd_name = "Environmental Temperature", byte = "warning", doc = "Temperature outside the operating range." },
  },
  mode_mask = 32896,
  modes = { { name = "readiness", pattern = 0, doc = "Normal operation." }, { name = "sleep", pattern = 32896, doc = "In the last data block the AHRS sends before it goes to Sleep mode." } },
  other_mode = "unknown",
  failure_mask = 255,
  warning_mask = 65280,
}

-- Table 6.7, section 6.2: $PAHR,RRRR.rr,PPP.pp,HHH.hh,TTT.t,V.vv,SSSS*CC<CR><LF>
SPEC.nmea = {
  identifier = "PAHR",
  max_length = 82,
  fields = {
    { name = "roll", icd_name = "RRRR.rr", label = "Roll", format = "decimal", width = 4, decimals = 2, unit = "deg", min = -18000, max = 18000, doc = "Roll, hundredths of a degree." },
    { name = "pitch", icd_name = "PPP.pp", label = "Pitch", format = "decimal", width = 3, decimals = 2, unit = "deg", min = -9000, max = 9000, doc = "Pitch, hundredths of a degree." },
    { name = "heading", icd_name = "HHH.hh", label = "Heading", format = "decimal", width = 3, decimals = 2, unit = "deg", min = 0, max = 35999, doc = "Heading, hundredths of a degree." },
    { name = "temperature", icd_name = "TTT.t", label = "Temperature", format = "decimal", width = 3, decimals = 1, unit = "degC", min = -999, max = 9999, doc = "Average accelerometer temperature, tenths of a degree Celsius." },
    { name = "vdd", icd_name = "V.vv", label = "Vdd", format = "decimal", width = 1, decimals = 2, unit = "V", min = 0, max = 999, doc = "AHRS input voltage, hundredths of a volt." },
    { name = "usw", icd_name = "SSSS", label = "USW", format = "hex", width = 4, decimals = 0, min = 0, max = 65535, encoding = "usw", doc = "Unit Status Word (section 6.5), four hex digits." },
  },
}

-- 6.1, 6.3, 6.4: the device's behaviour. A (state, event) pair without a row is ignored (E33).
SPEC.machine = {
  initial = "idle",
  parameter_block_timeout_s = 1.0,
  states = {
    { name = "idle", mode = "idle" },
    { name = "awaiting_parameters", mode = "idle", expects = "ahrs_parameters_load" },
    { name = "aligning_continuous", mode = "continuous", timer = "alignment" },
    { name = "continuous", mode = "continuous", timer = "output" },
    { name = "aligning_on_request", mode = "on_request", timer = "alignment" },
    { name = "on_request", mode = "on_request" },
    { name = "sleep", mode = "sleep" },
    { name = "calibration_awaiting_parameters", mode = "calibration", expects = "calibration_parameters" },
    { name = "calibration_aligning", mode = "calibration", timer = "alignment" },
    { name = "calibration_accumulating", mode = "calibration", timer = "accumulation" },
    { name = "calibration_deciding", mode = "calibration" },
    { name = "runs_awaiting_parameters", mode = "calibration", expects = "calibration_parameters" },
    { name = "runs_ready", mode = "calibration" },
    { name = "run_awaiting_parameters", mode = "calibration", expects = "calibration_run_parameters" },
    { name = "run_aligning", mode = "calibration", timer = "alignment" },
    { name = "run_accumulating", mode = "calibration", timer = "accumulation" },
  },
  events = { parameter_block = "parameter_block", other_message = "other_message", unknown = "unknown", block_timeout = "block_timeout", alignment_done = "alignment_done", accumulation_done = "accumulation_done", output_due = "output_due", },
  timer_events = { alignment = "alignment_done", accumulation = "accumulation_done", output = "output_due" },
  output_formats = { full_output = "full_output", quaternion = "quaternion", orientation_sensors = "orientation_sensors", nmea = false },
  answers = {
    ack = { kind = "ack" },
    ahrs_parameters_read = { kind = "payload", payload = "ahrs_parameters_read" },
    firmware_version = { kind = "payload", payload = "firmware_version" },
    bit_result = { kind = "payload", payload = "bit_result" },
    calibration_status = { kind = "payload", payload = "calibration_status" },
    initial_alignment = { kind = "payload", payload = "initial_alignment" },
    output = { kind = "output" },
    output_sleep = { kind = "output_mode", mode = "sleep" },
    calibration_result = { kind = "payload", payload = "calibration_result" },
    calibration_run_result = { kind = "payload", payload = "calibration_run_result" },
  },
  -- state, event, next state, what the device sends[, firmware older than which the row applies]
  transitions = {
    { "idle", "AHRScont1", "aligning_continuous", { "ack" } },
    { "idle", "AHRScont2", "aligning_continuous", { "ack" } },
    { "idle", "AHRScont3", "aligning_continuous", { "ack" } },
    { "idle", "NMEAcont", "aligning_continuous", { "ack" } },
    { "idle", "AHRSreq1", "aligning_on_request", { "ack" } },
    { "idle", "AHRSreq2", "aligning_on_request", { "ack" } },
    { "idle", "AHRSreq3", "aligning_on_request", { "ack" } },
    { "idle", "NMEAreq", "aligning_on_request", { "ack" } },
    { "idle", "LoadAHRSPar", "awaiting_parameters", {} },
    { "idle", "ReadAHRSPar", "idle", { "ahrs_parameters_read" } },
    { "idle", "GetVerFirmware", "idle", { "firmware_version" } },
    { "idle", "GetBIT", "idle", { "bit_result" } },
    { "on_request", "GetBIT", "on_request", { "bit_result" } },
    { "idle", "LowPowerOn", "sleep", {} },
    { "idle", "Start2DClb", "calibration_awaiting_parameters", {} },
    { "idle", "Start3DClb", "calibration_awaiting_parameters", {} },
    { "idle", "Start2D2TClb", "runs_awaiting_parameters", {} },
    { "idle", "ClearClb", "idle", { "ack" } },
    { "idle", "GetClbRes", "idle", { "calibration_status" } },
    { "idle", "Stop", "idle", {} },
    { "awaiting_parameters", "parameter_block", "idle", { "ack" } },
    { "awaiting_parameters", "unknown", "idle", {} },
    { "awaiting_parameters", "other_message", "idle", {} },
    { "awaiting_parameters", "block_timeout", "idle", {} },
    { "calibration_awaiting_parameters", "unknown", "idle", {} },
    { "calibration_awaiting_parameters", "other_message", "idle", {} },
    { "calibration_awaiting_parameters", "block_timeout", "idle", {} },
    { "runs_awaiting_parameters", "unknown", "idle", {} },
    { "runs_awaiting_parameters", "other_message", "idle", {} },
    { "runs_awaiting_parameters", "block_timeout", "idle", {} },
    { "calibration_awaiting_parameters", "ExitClb", "idle", { "ack" } },
    { "runs_awaiting_parameters", "ExitClb", "idle", { "ack" } },
    { "run_awaiting_parameters", "ExitClb", "idle", { "ack" } },
    { "run_awaiting_parameters", "unknown", "runs_ready", {} },
    { "run_awaiting_parameters", "other_message", "runs_ready", {} },
    { "run_awaiting_parameters", "block_timeout", "runs_ready", {} },
    { "aligning_continuous", "alignment_done", "continuous", { "initial_alignment" } },
    { "aligning_on_request", "alignment_done", "on_request", { "initial_alignment" } },
    { "continuous", "output_due", "continuous", { "output" } },
    { "on_request", "GetDataReq", "on_request", { "output" } },
    { "aligning_continuous", "Stop", "idle", {} },
    { "continuous", "Stop", "idle", {} },
    { "aligning_on_request", "Stop", "idle", {} },
    { "on_request", "Stop", "idle", {} },
    { "continuous", "LowPowerOn", "sleep", { "output_sleep" } },
    { "on_request", "LowPowerOn", "sleep", {} },
    { "sleep", "LowPowerOff", "idle", {} },
    { "calibration_awaiting_parameters", "parameter_block", "calibration_aligning", { "ack" } },
    { "calibration_aligning", "alignment_done", "calibration_accumulating", { "initial_alignment" } },
    { "calibration_accumulating", "accumulation_done", "calibration_deciding", { "calibration_result" } },
    { "calibration_accumulating", "StopClbRun", "calibration_deciding", { "calibration_result" } },
    { "calibration_deciding", "AcceptClb", "idle", { "ack" } },
    { "calibration_aligning", "ExitClb", "idle", { "ack" } },
    { "calibration_accumulating", "ExitClb", "idle", { "ack" } },
    { "calibration_deciding", "ExitClb", "idle", { "ack" } },
    { "runs_ready", "ExitClb", "idle", { "ack" } },
    { "run_aligning", "ExitClb", "idle", { "ack" } },
    { "run_accumulating", "ExitClb", "idle", { "ack" } },
    { "runs_awaiting_parameters", "parameter_block", "runs_ready", { "ack" } },
    { "runs_ready", "StartClbRun", "run_awaiting_parameters", {} },
    { "run_awaiting_parameters", "parameter_block", "run_aligning", { "ack" } },
    { "run_aligning", "alignment_done", "run_accumulating", { "initial_alignment" } },
    { "run_accumulating", "accumulation_done", "runs_ready", { "calibration_run_result" } },
    { "run_accumulating", "StopClbRun", "runs_ready", { "calibration_run_result" } },
    { "runs_ready", "FinishClb", "calibration_deciding", { "calibration_result" } },
    { "runs_ready", "StopClbRun", "calibration_deciding", { "calibration_result" }, "4.9.9.0" },
    { "awaiting_parameters", "AHRScont1", "idle", {} },
    { "awaiting_parameters", "AHRScont2", "idle", {} },
    { "awaiting_parameters", "AHRScont3", "idle", {} },
    { "awaiting_parameters", "AHRSreq1", "idle", {} },
    { "awaiting_parameters", "AHRSreq2", "idle", {} },
    { "awaiting_parameters", "AHRSreq3", "idle", {} },
    { "awaiting_parameters", "NMEAcont", "idle", {} },
    { "awaiting_parameters", "NMEAreq", "idle", {} },
    { "awaiting_parameters", "GetDataReq", "idle", {} },
    { "awaiting_parameters", "Stop", "idle", {} },
    { "awaiting_parameters", "LoadAHRSPar", "idle", {} },
    { "awaiting_parameters", "ReadAHRSPar", "idle", {} },
    { "awaiting_parameters", "LowPowerOn", "idle", {} },
    { "awaiting_parameters", "LowPowerOff", "idle", {} },
    { "awaiting_parameters", "GetVerFirmware", "idle", {} },
    { "awaiting_parameters", "GetBIT", "idle", {} },
    { "awaiting_parameters", "Start2DClb", "idle", {} },
    { "awaiting_parameters", "Start2D2TClb", "idle", {} },
    { "awaiting_parameters", "Start3DClb", "idle", {} },
    { "awaiting_parameters", "StartClbRun", "idle", {} },
    { "awaiting_parameters", "StopClbRun", "idle", {} },
    { "awaiting_parameters", "FinishClb", "idle", {} },
    { "awaiting_parameters", "AcceptClb", "idle", {} },
    { "awaiting_parameters", "ExitClb", "idle", {} },
    { "awaiting_parameters", "ClearClb", "idle", {} },
    { "awaiting_parameters", "GetClbRes", "idle", {} },
    { "calibration_awaiting_parameters", "AHRScont1", "idle", {} },
    { "calibration_awaiting_parameters", "AHRScont2", "idle", {} },
    { "calibration_awaiting_parameters", "AHRScont3", "idle", {} },
    { "calibration_awaiting_parameters", "AHRSreq1", "idle", {} },
    { "calibration_awaiting_parameters", "AHRSreq2", "idle", {} },
    { "calibration_awaiting_parameters", "AHRSreq3", "idle", {} },
    { "calibration_awaiting_parameters", "NMEAcont", "idle", {} },
    { "calibration_awaiting_parameters", "NMEAreq", "idle", {} },
    { "calibration_awaiting_parameters", "GetDataReq", "idle", {} },
    { "calibration_awaiting_parameters", "Stop", "idle", {} },
    { "calibration_awaiting_parameters", "LoadAHRSPar", "idle", {} },
    { "calibration_awaiting_parameters", "ReadAHRSPar", "idle", {} },
    { "calibration_awaiting_parameters", "LowPowerOn", "idle", {} },
    { "calibration_awaiting_parameters", "LowPowerOff", "idle", {} },
    { "calibration_awaiting_parameters", "GetVerFirmware", "idle", {} },
    { "calibration_awaiting_parameters", "GetBIT", "idle", {} },
    { "calibration_awaiting_parameters", "Start2DClb", "idle", {} },
    { "calibration_awaiting_parameters", "Start2D2TClb", "idle", {} },
    { "calibration_awaiting_parameters", "Start3DClb", "idle", {} },
    { "calibration_awaiting_parameters", "StartClbRun", "idle", {} },
    { "calibration_awaiting_parameters", "StopClbRun", "idle", {} },
    { "calibration_awaiting_parameters", "FinishClb", "idle", {} },
    { "calibration_awaiting_parameters", "AcceptClb", "idle", {} },
    { "calibration_awaiting_parameters", "ClearClb", "idle", {} },
    { "calibration_awaiting_parameters", "GetClbRes", "idle", {} },
    { "runs_awaiting_parameters", "AHRScont1", "idle", {} },
    { "runs_awaiting_parameters", "AHRScont2", "idle", {} },
    { "runs_awaiting_parameters", "AHRScont3", "idle", {} },
    { "runs_awaiting_parameters", "AHRSreq1", "idle", {} },
    { "runs_awaiting_parameters", "AHRSreq2", "idle", {} },
    { "runs_awaiting_parameters", "AHRSreq3", "idle", {} },
    { "runs_awaiting_parameters", "NMEAcont", "idle", {} },
    { "runs_awaiting_parameters", "NMEAreq", "idle", {} },
    { "runs_awaiting_parameters", "GetDataReq", "idle", {} },
    { "runs_awaiting_parameters", "Stop", "idle", {} },
    { "runs_awaiting_parameters", "LoadAHRSPar", "idle", {} },
    { "runs_awaiting_parameters", "ReadAHRSPar", "idle", {} },
    { "runs_awaiting_parameters", "LowPowerOn", "idle", {} },
    { "runs_awaiting_parameters", "LowPowerOff", "idle", {} },
    { "runs_awaiting_parameters", "GetVerFirmware", "idle", {} },
    { "runs_awaiting_parameters", "GetBIT", "idle", {} },
    { "runs_awaiting_parameters", "Start2DClb", "idle", {} },
    { "runs_awaiting_parameters", "Start2D2TClb", "idle", {} },
    { "runs_awaiting_parameters", "Start3DClb", "idle", {} },
    { "runs_awaiting_parameters", "StartClbRun", "idle", {} },
    { "runs_awaiting_parameters", "StopClbRun", "idle", {} },
    { "runs_awaiting_parameters", "FinishClb", "idle", {} },
    { "runs_awaiting_parameters", "AcceptClb", "idle", {} },
    { "runs_awaiting_parameters", "ClearClb", "idle", {} },
    { "runs_awaiting_parameters", "GetClbRes", "idle", {} },
    { "run_awaiting_parameters", "AHRScont1", "runs_ready", {} },
    { "run_awaiting_parameters", "AHRScont2", "runs_ready", {} },
    { "run_awaiting_parameters", "AHRScont3", "runs_ready", {} },
    { "run_awaiting_parameters", "AHRSreq1", "runs_ready", {} },
    { "run_awaiting_parameters", "AHRSreq2", "runs_ready", {} },
    { "run_awaiting_parameters", "AHRSreq3", "runs_ready", {} },
    { "run_awaiting_parameters", "NMEAcont", "runs_ready", {} },
    { "run_awaiting_parameters", "NMEAreq", "runs_ready", {} },
    { "run_awaiting_parameters", "GetDataReq", "runs_ready", {} },
    { "run_awaiting_parameters", "Stop", "runs_ready", {} },
    { "run_awaiting_parameters", "LoadAHRSPar", "runs_ready", {} },
    { "run_awaiting_parameters", "ReadAHRSPar", "runs_ready", {} },
    { "run_awaiting_parameters", "LowPowerOn", "runs_ready", {} },
    { "run_awaiting_parameters", "LowPowerOff", "runs_ready", {} },
    { "run_awaiting_parameters", "GetVerFirmware", "runs_ready", {} },
    { "run_awaiting_parameters", "GetBIT", "runs_ready", {} },
    { "run_awaiting_parameters", "Start2DClb", "runs_ready", {} },
    { "run_awaiting_parameters", "Start2D2TClb", "runs_ready", {} },
    { "run_awaiting_parameters", "Start3DClb", "runs_ready", {} },
    { "run_awaiting_parameters", "StartClbRun", "runs_ready", {} },
    { "run_awaiting_parameters", "StopClbRun", "runs_ready", {} },
    { "run_awaiting_parameters", "FinishClb", "runs_ready", {} },
    { "run_awaiting_parameters", "AcceptClb", "runs_ready", {} },
    { "run_awaiting_parameters", "ClearClb", "runs_ready", {} },
    { "run_awaiting_parameters", "GetClbRes", "runs_ready", {} },
  },
}

-- Part 2: the dissector -------------------------------------------------------------------------

-- The protocol, read from SPEC: indexes over the tables, value decoding, the frame and sentence
-- checks, the state-machine lookups. Nothing below names a command, a table or a field.

local P = {}

local FRAME = SPEC.frame
local NMEA = SPEC.nmea
local MACHINE = SPEC.machine

-- Indexes over the tables --------------------------------------------------------------------

P.payloads = {}
for _, p in ipairs(SPEC.payloads) do
  P.payloads[p.name] = p
end

P.states = {}
for _, s in ipairs(MACHINE.states) do
  P.states[s.name] = s
end

P.commands = {}
P.by_code = {} -- code -> the commands with that code, sorted by name
for _, c in ipairs(SPEC.commands) do
  P.commands[c.name] = c
  P.by_code[c.code] = P.by_code[c.code] or {}
  table.insert(P.by_code[c.code], c)
end
for _, list in pairs(P.by_code) do
  table.sort(list, function(a, b) return a.name < b.name end)
end

P.transitions = {} -- state -> event -> row
P.legacy = {} -- state -> event -> row, for firmware older than row[5]
for _, row in ipairs(MACHINE.transitions) do
  local into = row[5] and P.legacy or P.transitions
  into[row[1]] = into[row[1]] or {}
  into[row[1]][row[2]] = { to = row[3], send = row[4], firmware_before = row[5] }
end

P.message_types = {}
for _, t in ipairs(FRAME.message_types) do
  P.message_types[t.value] = t.name
end

P.header = ""
for _, byte in ipairs(FRAME.header) do
  P.header = P.header .. string.char(byte)
end

-- The field of each table that holds the Unit Status Word, and the sentence's.
P.usw_field = {}
for _, p in ipairs(SPEC.payloads) do
  for _, f in ipairs(p.fields) do
    if f.encoding == "usw" then
      P.usw_field[p.name] = f
    end
  end
end

for _, f in ipairs(SPEC.nmea.fields) do
  if f.encoding == "usw" then
    P.sentence_usw = f.name
  end
end

-- Values -------------------------------------------------------------------------------------

-- An unsigned integer of `size` bytes at `pos` (1-based) of string `s`, in the spec's byte order.
function P.uint(s, pos, size)
  local value = 0
  for i = 1, size do
    local index = SPEC.byte_order == "little" and pos + size - i or pos + i - 1
    value = value * 256 + s:byte(index)
  end
  return value
end

function P.int(s, pos, size)
  local value = P.uint(s, pos, size)
  local half = 2 ^ (8 * size - 1)
  if value >= half then
    value = value - 2 * half
  end
  return value
end

P.checksums = {
  sum16 = function(s, first, last)
    local value = 0
    for i = first, last do
      value = (value + s:byte(i)) % 65536
    end
    return value
  end,
  xor8 = function(s, first, last)
    local value = 0
    for i = first, last do
      value = bit32.bxor(value, s:byte(i))
    end
    return value
  end,
}

-- raw x multiplier / divisor; a divisor may name a variant parameter (KG, KA). nil: no scale.
function P.engineering(field, raw, variant)
  if field.multiplier == nil or type(raw) ~= "number" then
    return nil
  end
  local divisor = field.divisor
  if type(divisor) == "string" then
    divisor = variant.values[divisor]
  end
  return raw * field.multiplier / divisor
end

function P.usw_mode(value)
  local bits = bit32.band(value, SPEC.status_word.mode_mask)
  for _, mode in ipairs(SPEC.status_word.modes) do
    if mode.pattern == bits then
      return mode.name
    end
  end
  return SPEC.status_word.other_mode
end

local DAYS = { 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31 }

local function days_in_month(year, month)
  local leap = year % 4 == 0 and (year % 100 ~= 0 or year % 400 == 0)
  return (month == 2 and leap) and 29 or DAYS[month]
end

local function encode_date(date, year, month, day)
  local parts = { year = year, month = month, day = day }
  local value = 0
  for _, term in ipairs(date.terms) do
    value = value + (parts[term.part] + term.offset) / term.divisor
  end
  return value
end

-- The calendar date whose encoding is nearest the float, as "YYYY-MM-DD", or nil.
function P.decode_date(value)
  local date = SPEC.encodings.date
  if value ~= value or value < date.year_min - 1 or value > date.year_max + 2 then
    return nil
  end
  local best, text
  local base = math.floor(value)
  for year = base - 1, base do
    if year >= date.year_min and year <= date.year_max then
      for month = 1, 12 do
        for day = 1, days_in_month(year, month) do
          local distance = math.abs(encode_date(date, year, month, day) - value)
          if best == nil or distance < best then
            best, text = distance, string.format("%04d-%02d-%02d", year, month, day)
          end
        end
      end
    end
  end
  return text
end

-- Frames -------------------------------------------------------------------------------------

P.NEED_MORE = -1
P.INVALID = 0

-- Decide on a frame starting at `pos` of `s` (the stream rule's checks 2, 4, 5 and 7):
-- (total size, nil) for a valid frame, (NEED_MORE) or (INVALID[, sent, computed, total]).
function P.frame_at(s, pos)
  local available = #s - pos + 1
  for index = 2, #P.header do
    if available < index then
      return P.NEED_MORE
    end
    if s:byte(pos + index - 1) ~= P.header:byte(index) then
      return P.INVALID
    end
  end
  if available < FRAME.payload_offset then
    return P.NEED_MORE
  end
  if P.message_types[s:byte(pos + FRAME.message_type_offset)] == nil then
    return P.INVALID
  end
  local length = P.uint(s, pos + FRAME.length_offset, FRAME.length_size)
  if length < FRAME.min_length or length > FRAME.max_length then
    return P.INVALID
  end
  local total = #P.header + length
  if available < total then
    return P.NEED_MORE
  end
  local at = pos + total - FRAME.checksum.size
  local computed = P.checksums[FRAME.checksum_algorithm](s, pos + #P.header, at - 1)
  local sent = P.uint(s, at, FRAME.checksum.size)
  if sent ~= computed then
    return P.INVALID, sent, computed, total
  end
  return total
end

-- $PAHR sentences. NMEA 0183 framing: "$", the fields separated by ",", "*", the checksum (the XOR
-- of the characters between "$" and "*") as two hex digits, CR LF.

P.SENTENCE_START = 0x24 -- "$"
local LF, CR = 0x0A, 0x0D
P.sentence_prefix = "$" .. NMEA.identifier .. ","

local function decimal(text, decimals)
  local sign, whole, dot, fraction = text:match("^(%-?)(%d*)(%.?)(%d*)$")
  if whole == nil or whole == "" then
    return nil
  end
  if dot == "." and (#fraction < 1 or #fraction > decimals) then
    return nil
  end
  if dot == "" and fraction ~= "" then
    return nil
  end
  local value = tonumber(whole) * 10 ^ decimals
  if fraction ~= "" then
    value = value + tonumber(fraction .. string.rep("0", decimals - #fraction))
  end
  return sign == "-" and -value or value
end

-- The field texts of a sentence whose "*CC" CR LF tail is in place.
function P.sentence_fields(s)
  local parts = {}
  for part in (s:sub(#P.sentence_prefix + 1, #s - 5) .. ","):gmatch("([^,]*),") do
    table.insert(parts, part)
  end
  return parts
end

-- Parse one sentence ("$" through LF). Returns values (field name -> scaled integer) and the sent
-- checksum, or nil and a reason (with the sent and computed checksums when they differ).
function P.parse_sentence(s)
  local prefix = P.sentence_prefix
  if s:sub(1, #prefix) ~= prefix then
    return nil, "not a $" .. NMEA.identifier .. " sentence"
  end
  local crlf = s:find("\r\n", 1, true)
  if crlf == nil then
    return nil, "no CR LF"
  end
  local stop = crlf + 1
  if stop > NMEA.max_length then
    return nil, string.format("longer than %d characters", NMEA.max_length)
  end
  if stop < #s then
    return nil, "characters after CR LF"
  end
  local star = stop - 4
  if star < #prefix + 1 or s:sub(star, star) ~= "*" then
    return nil, "no *CC checksum before CR LF"
  end
  local digits = s:sub(star + 1, star + 2)
  if not digits:match("^%x%x$") then
    return nil, "checksum digits are not hex"
  end
  local sent = tonumber(digits, 16)
  local computed = P.checksums.xor8(s, 2, star - 1)
  if sent ~= computed then
    return nil, "bad checksum", sent, computed
  end
  local parts = P.sentence_fields(s)
  if #parts ~= #NMEA.fields then
    return nil, string.format("%d fields, expected %d", #parts, #NMEA.fields)
  end
  local values = {}
  for i, field in ipairs(NMEA.fields) do
    local part, value = parts[i], nil
    if field.format == "hex" then
      value = (#part >= 1 and #part <= field.width and part:match("^%x+$")) and tonumber(part, 16) or nil
    else
      value = decimal(part, field.decimals)
    end
    if value == nil then
      return nil, string.format("%q is not a valid %s", part, field.name)
    end
    if value < field.min or value > field.max then
      return nil, string.format("%s %s outside %d..%d", field.name, part, field.min, field.max)
    end
    values[field.name] = value
  end
  return values, sent
end

-- Decide on a sentence starting at `pos`: (size, values) for a valid one, (NEED_MORE) or
-- (INVALID[, reason, sent, computed, size]). Rejects early what can never become a sentence.
function P.sentence_at(s, pos)
  local size = #s
  local limit = math.min(size, pos + NMEA.max_length - 1)
  local stop = s:find("\n", pos, true)
  if stop == nil or stop > limit then
    if size - pos + 1 >= NMEA.max_length then
      return P.INVALID
    end
    local head = s:sub(pos, math.min(limit, pos + #P.sentence_prefix - 1))
    if P.sentence_prefix:sub(1, #head) ~= head then
      return P.INVALID
    end
    for index = pos + 1, limit do
      local byte = s:byte(index)
      if (byte < 0x20 or byte > 0x7E) and not (byte == CR and index == limit) then
        return P.INVALID
      end
    end
    return P.NEED_MORE
  end
  local raw = s:sub(pos, stop)
  local values, reason, sent, computed = P.parse_sentence(raw)
  if values == nil then
    return P.INVALID, reason, sent, computed, #raw
  end
  return #raw, values
end

-- The state machine --------------------------------------------------------------------------

-- "4.9.9.0" -> { 4, 9, 9, 0 }; non-numeric parts count as 0.
local function version(text)
  local parts = {}
  for part in (text .. "."):gmatch("([^.]*)%.") do
    table.insert(parts, tonumber(part:match("^%d+$") or "0"))
  end
  return parts
end

local function older(a, b)
  local x, y = version(a), version(b)
  for i = 1, math.max(#x, #y) do
    if x[i] == nil then
      return true
    end
    if y[i] == nil then
      return false
    end
    if x[i] ~= y[i] then
      return x[i] < y[i]
    end
  end
  return false
end

-- The transition for `event` in `state` (firmware "": current), or nil: ignored (E33).
function P.lookup(state, event, firmware)
  local legacy = P.legacy[state] and P.legacy[state][event]
  if legacy and firmware ~= nil and firmware ~= "" and older(firmware, legacy.firmware_before) then
    return legacy
  end
  return P.transitions[state] and P.transitions[state][event]
end

-- The command a code means in `state`: the one valid in the state's mode, else the code's default
-- (0xFE is ExitClb in calibration, Stop elsewhere, E14); nil for a code no command has.
function P.command_event(code, state)
  local named = P.by_code[code]
  if named == nil then
    return nil
  end
  local mode = P.states[state].mode
  for _, c in ipairs(named) do
    for _, valid in ipairs(c.valid_in) do
      if valid == mode then
        return c.name
      end
    end
  end
  for _, c in ipairs(named) do
    if c.default_for_code or #named == 1 then
      return c.name
    end
  end
  return nil
end

-- (event, transition) of the timer running in `state`, or nil.
function P.timer_transition(state)
  local timer = P.states[state].timer
  if timer == nil then
    return nil
  end
  local event = MACHINE.timer_events[timer]
  local transition = P.transitions[state] and P.transitions[state][event]
  if transition == nil then
    return nil
  end
  return event, transition
end


-- The stream rule every binding follows: leftmost valid message (spec/README.md). One Stream per
-- direction of a conversation; bytes are fed packet by packet, in capture order. Each held byte
-- remembers the packet it came in and its offset there, so that a message or a run of discarded
-- bytes can be shown where it lies, or reassembled when it spans packets.
--
-- A candidate that fails its checksum is shown as damaged, but only once the scan has passed its
-- bytes: if a valid message, or another damaged candidate, starts inside them, the candidate was
-- truncated (its rest never came, and the bytes after it are the next message's) and is shown
-- as such, up to where that message starts, never reaching into it.

local Stream = {}
Stream.__index = Stream

function Stream.new()
  return setmetatable({ buffer = "", frames = {}, offsets = {}, discarded = 0, suspect = nil }, Stream)
end

-- A piece of the held bytes, first to last (1-based): its bytes and where its first byte came from.
function Stream:piece(first, last)
  local piece = { raw = self.buffer:sub(first, last), frame = self.frames[first], offset = self.offsets[first] }
  piece.contiguous = self.frames[last] == piece.frame
  return piece
end

local function next_start(s, pos)
  local frame = s:find(P.header:sub(1, 1), pos, true)
  local sentence = s:find(string.char(P.SENTENCE_START), pos, true)
  if frame and sentence then
    return math.min(frame, sentence)
  end
  return frame or sentence or #s + 1
end

-- A candidate that failed only its own checks (a frame's checksum; a complete $PAHR sentence):
-- worth showing as damaged. Otherwise nil.
local function damaged(s, pos, reason, sent, computed, size)
  if size == nil then
    return nil
  end
  local sentence = s:byte(pos) == P.SENTENCE_START
  if sent == nil and (not sentence or s:sub(pos, pos + #P.sentence_prefix - 1) ~= P.sentence_prefix) then
    return nil
  end
  return { kind = "damaged", reason = reason or "bad checksum", sent = sent, computed = computed, size = size,
    sentence = sentence }
end

-- The damaged candidate held until the scan has passed its bytes, cut to its first `size` bytes
-- when it was truncated.
local function settle(suspect, size)
  local bad = suspect.item
  if size < #bad.raw then
    bad.truncated_from, bad.reason, bad.sent, bad.computed = #bad.raw, "truncated", nil, nil
    bad.raw = bad.raw:sub(1, size)
    bad.contiguous = suspect.frames[size] == bad.frame
  end
  return bad
end

-- Add the bytes of packet `frame`; return what they complete, in order: messages
-- ({ kind = "message", raw, frame, offset, contiguous, sentence = values or nil }), runs of
-- discarded bytes ({ kind = "discard", ... }) and damaged frames and sentences, whose bytes are
-- discarded too ({ kind = "damaged", reason, sent, computed, truncated_from, ... }). A candidate
-- that needs bytes not yet received waits for the next packet.
function Stream:feed(data, frame)
  local base = #self.buffer
  self.buffer = self.buffer .. data
  for i = 1, #data do
    self.frames[base + i] = frame
    self.offsets[base + i] = i - 1
  end
  local s = self.buffer
  local out = {}
  local run -- the first position of the discarded bytes being collected
  local function close(pos)
    if run then
      local piece = self:piece(run, pos - 1)
      piece.kind = "discard"
      table.insert(out, piece)
      self.discarded = self.discarded + #piece.raw
      run = nil
    end
  end
  -- Show the suspect once the scan is past it, or cut where a message starts inside it.
  local function decide(pos, starts)
    local suspect = self.suspect
    if suspect and (pos > suspect.last or starts) then
      table.insert(out, settle(suspect, math.min(pos - suspect.first, #suspect.item.raw)))
      self.suspect = nil
    end
  end
  local pos = 1
  while pos <= #s do
    decide(pos, false)
    local first = s:byte(pos)
    if first ~= P.header:byte(1) and first ~= P.SENTENCE_START then
      run = run or pos
      pos = next_start(s, pos + 1)
    else
      local used, extra, sent, computed, size
      if first == P.SENTENCE_START then
        used, extra, sent, computed, size = P.sentence_at(s, pos)
      else
        used, sent, computed, size = P.frame_at(s, pos)
      end
      if used == P.NEED_MORE then
        break
      elseif used == P.INVALID then
        local bad = damaged(s, pos, extra, sent, computed, size)
        if bad then
          decide(pos, true)
          local piece = self:piece(pos, pos + size - 1)
          bad.raw, bad.frame, bad.offset, bad.contiguous = piece.raw, piece.frame, piece.offset, piece.contiguous
          local frames = {}
          for i = pos, pos + size - 1 do
            frames[i - pos + 1] = self.frames[i]
          end
          self.suspect = { item = bad, first = pos, last = pos + size - 1, frames = frames }
        end
        run = run or pos
        pos = pos + 1
      else
        decide(pos, true)
        close(pos)
        local piece = self:piece(pos, pos + used - 1)
        piece.kind = "message"
        piece.sentence = extra
        table.insert(out, piece)
        pos = pos + used
      end
    end
  end
  decide(pos, false)
  close(pos)
  if self.suspect then
    self.suspect.first, self.suspect.last = self.suspect.first - pos + 1, self.suspect.last - pos + 1
  end
  self.buffer = s:sub(pos)
  local frames, offsets = {}, {}
  for i = pos, #s do
    frames[i - pos + 1] = self.frames[i]
    offsets[i - pos + 1] = self.offsets[i]
  end
  self.frames, self.offsets = frames, offsets
  return out
end


-- Decoding by context. A frame does not say which table its payload follows (E7): the context
-- does, as the host session of the Python binding (ilahrs.Host) keeps it. Host messages drive the
-- spec's state machine (the device's state, what it owes: acknowledgements carrying the checksum
-- of what they answer, data blocks, output blocks); device messages are matched, in order, against
-- what is owed, then against what the current state's timer sends (alignment blocks, output,
-- calibration results), then against output still in flight from the previous state. A message
-- nothing explains is shown as such, never guessed. Owed answers that do not come within the
-- answer timeout are reported missing on the request; only those: an answer owed to a retry sent
-- before that timeout is still owed. A capture begun mid-stream starts, as `Host.mid_stream`
-- does, in the state where the output of the start command of the preferences flows.

local Context = {}
Context.__index = Context

local MACHINE = SPEC.machine

-- The state in which the output a start command chose flows: the command's transition from the
-- initial state, then the timers' transitions (the alignment) to the state that sends output.
function Context.streaming_state(command, firmware)
  local first = P.lookup(MACHINE.initial, command, firmware)
  local state = first and first.to or MACHINE.initial
  for _ = 1, #MACHINE.states do
    local _, timed = P.timer_transition(state)
    if timed == nil or timed.to == state then
      break
    end
    state = timed.to
  end
  return state
end

-- settings: { firmware = version text or "", timeout = seconds, start = the command whose output
-- the capture begins in, or nil }
function Context.new(settings)
  local state, output = MACHINE.initial, nil
  if settings.start then
    state = Context.streaming_state(settings.start, settings.firmware)
    output = P.commands[settings.start].starts_output
  end
  return setmetatable({
    settings = settings,
    state = state, -- what the host has seen of the device's state
    target = state, -- the state once every owed answer has come
    owed = {},
    output = output, -- the output format the last start command (or the preferences) chose
    timer_index = 0,
    late_state = nil,
    late_until = 0,
  }, Context)
end

-- Message type, payload and checksum of a frame's bytes.
function Context.frame_parts(raw)
  local frame = SPEC.frame
  local size = frame.checksum.size
  local payload = raw:sub(frame.payload_offset + 1, #raw - size)
  return raw:byte(frame.message_type_offset + 1), payload, P.uint(raw, #raw - size + 1, size)
end

function Context:enter(state, time)
  local old = self.state
  if state ~= old then
    self.late_state, self.late_until = old, time + self.settings.timeout
    self.timer_index = 0
  end
  self.state, self.target = state, state
end

function Context:timer_done(state, time)
  self.timer_index = 0
  if state ~= self.state then
    self:enter(state, time)
  end
end

-- Owed answers past their deadline: reported on their request (the first one each), forgotten.
-- What is owed to a later request (a retry) keeps its own deadline.
function Context:expire(time)
  local expired = false
  while self.owed[1] and time > self.owed[1].deadline do
    local owed = table.remove(self.owed, 1)
    owed.request.missing = owed.request.missing or owed.item
    expired = true
  end
  if expired and #self.owed == 0 then
    self:enter(self.target, time)
  end
end

-- A message from the host (msg: { raw, sentence, at = the packet it completes in }): what it is and
-- what it makes the device owe.
function Context:host(msg, time)
  self:expire(time)
  local state = self.target
  local info = { frame = msg.at, answers = {} }
  if msg.sentence then
    info.kind, info.state = "other", state
    return info
  end
  local kind, payload, checksum = Context.frame_parts(msg.raw)
  local event, source
  if kind == SPEC.frame.command_type and #payload == 1 then
    info.code = payload:byte(1)
    info.command = P.command_event(info.code, state)
    info.kind = info.command and "command" or "unknown_command"
    event = info.command or MACHINE.events.unknown
    source = event
  else
    local expects = P.states[state].expects
    if expects and #payload == P.payloads[expects].size then
      info.kind, info.table = "parameter_block", expects
      event, source = MACHINE.events.parameter_block, expects
    else
      info.kind, event = "other", MACHINE.events.other_message
    end
  end
  local transition = P.lookup(state, event, self.settings.firmware)
  if transition == nil then
    info.ignored, info.state = true, state
    return info
  end
  local command = info.command and P.commands[info.command]
  if command and command.starts_output then
    self.output = command.starts_output
  end
  for _, item in ipairs(transition.send) do
    table.insert(self.owed, { item = item, source = source, checksum = checksum, request = info,
      deadline = time + self.settings.timeout })
  end
  self.target = transition.to
  if #self.owed == 0 then
    self:enter(transition.to, time)
  end
  info.state = transition.to
  return info
end

-- The output block a message is, in the current output format: { table, usw } or nil.
function Context:output_of(msg)
  if self.output == nil then
    return nil
  end
  local name = MACHINE.output_formats[self.output]
  if name == false then
    return msg.sentence and { usw = msg.sentence[P.sentence_usw] } or nil
  end
  if msg.sentence then
    return nil
  end
  local kind, payload = Context.frame_parts(msg.raw)
  local table_ = P.payloads[name]
  if kind ~= SPEC.frame.data_type or #payload ~= table_.size then
    return nil
  end
  local usw = P.usw_field[name]
  return { table = name, usw = usw and P.uint(payload, usw.offset + 1, usw.size) or 0 }
end

-- What `msg` is if it is the answer `item` (ack, output, output_<mode> or a table), else nil.
function Context:match(item, source, checksum, msg)
  local answer = MACHINE.answers[item]
  if answer.kind == "output" or answer.kind == "output_mode" then
    local out = self:output_of(msg)
    if out == nil or (answer.mode and P.usw_mode(out.usw) ~= answer.mode) then
      return nil
    end
    return { kind = "output", table = out.table, source = source }
  end
  if msg.sentence then
    return nil
  end
  local kind, payload = Context.frame_parts(msg.raw)
  if kind ~= SPEC.frame.data_type then
    return nil
  end
  if answer.kind == "ack" then
    local ack = P.payloads[SPEC.ack_payload]
    if #payload ~= ack.size then
      return nil
    end
    local value = P.uint(payload, ack.fields[1].offset + 1, ack.fields[1].size)
    local result = { kind = "ack", table = ack.name, source = source, value = value }
    if checksum and value ~= checksum then
      result.wrong, result.expected = true, checksum
    end
    return result
  end
  if #payload ~= P.payloads[answer.payload].size then
    return nil
  end
  return { kind = "data", table = answer.payload, source = source }
end

-- A message from the device: what it is, by context.
function Context:device(msg, time)
  self:expire(time)
  local result = self:explain(msg, time)
  result.state = self.state
  return result
end

function Context:explain(msg, time)
  local owed = self.owed[1]
  if owed then
    local result = self:match(owed.item, owed.source, owed.checksum, msg)
    if result then
      table.remove(self.owed, 1)
      result.request = owed.request
      if #self.owed == 0 then
        self:enter(self.target, time)
      end
      return result
    end
  end
  local event, timed = P.timer_transition(self.state)
  if event and #timed.send > 0 then
    local result = self:match(timed.send[self.timer_index + 1], event, nil, msg)
    if result then
      self.timer_index = self.timer_index + 1
      if self.timer_index == #timed.send then
        self:timer_done(timed.to, time)
      end
      return result
    end
    local next_event, following
    if timed.to ~= self.state then
      next_event, following = P.timer_transition(timed.to)
    end
    if following and #following.send > 0 and #self.owed == 0
      and self:match(following.send[1], next_event, nil, msg) then
      local missing = timed.send[self.timer_index + 1]
      self:timer_done(timed.to, time)
      result = self:explain(msg, time)
      result.missing = missing
      return result
    end
  end
  if self.late_state and time <= self.late_until then
    local late_event, late = P.timer_transition(self.late_state)
    for _, item in ipairs(late and late.send or {}) do
      local result = self:match(item, late_event, nil, msg)
      if result and result.kind == "output" then
        result.late = true
        return result
      end
    end
  end
  return { kind = "unexpected", expected = owed and owed.item, source = owed and owed.source,
    no_start = self.output == nil and Context.looks_like_output(msg) }
end

-- A $ sentence, or a data frame of the size of an output format's table: what output would be,
-- had a start command (or the preferences) chosen its format.
function Context.looks_like_output(msg)
  if msg.sentence then
    return true
  end
  local kind, payload = Context.frame_parts(msg.raw)
  if kind ~= SPEC.frame.data_type then
    return false
  end
  for _, name in pairs(MACHINE.output_formats) do
    if name and P.payloads[name].size == #payload then
      return true
    end
  end
  return false
end


-- The protocol, its preferences and display-filter fields, registered from SPEC: one field per
-- frame field, per payload field (the engineering value, with the raw value beside it when a scale
-- applies; a date as YYYY-MM-DD with the float beside it; the calibration success byte with its
-- outcome and predicted accuracy), per $PAHR field and per Unit Status Word flag; the rest is the
-- dissector's own. Labels are the spec's titles (the ICD's names); the filter names are the
-- spec's field names.

local proto = Proto(SPEC.name, SPEC.icd)
local NAME = SPEC.name

local WIRE = {
  u8 = ProtoField.uint8,
  s8 = ProtoField.int8,
  u16 = ProtoField.uint16,
  s16 = ProtoField.int16,
  u32 = ProtoField.uint32,
  s32 = ProtoField.int32,
  f32 = ProtoField.float,
  char = ProtoField.string,
  reserved = ProtoField.bytes,
}
local UINT = { [1] = ProtoField.uint8, [2] = ProtoField.uint16, [4] = ProtoField.uint32 }

local F = {} -- the dissector's own fields
F.kind = ProtoField.string(NAME .. ".kind", "Message kind",
  base.ASCII, "command, parameter_block, ack, data, output, unexpected, unknown_command or other")
F.table = ProtoField.string(NAME .. ".table", "Payload table")
F.command = ProtoField.string(NAME .. ".command", "Command", base.ASCII, "The command's name in the device's mode")
F.code = ProtoField.uint8(NAME .. ".command_code", "Command code", base.HEX)
F.source = ProtoField.string(NAME .. ".source", "Sent because of", base.ASCII,
  "The command, parameter block or timer event that made the device send this message")
F.state = ProtoField.string(NAME .. ".state", "Device state", base.ASCII,
  "The state of the device after this message, as the context follows it")
F.request = ProtoField.framenum(NAME .. ".request_in", "Answer to frame", base.NONE, frametype.REQUEST)
F.response = ProtoField.framenum(NAME .. ".response_in", "Answered in frame", base.NONE, frametype.RESPONSE)
F.ack_frame = ProtoField.framenum(NAME .. ".ack_frame", "Acknowledges frame", base.NONE, frametype.ACK)
F.late = ProtoField.bool(NAME .. ".late", "Late", base.NONE, nil, nil,
  "Output sent before the device left the state that sends it, received after")
F.starts_in = ProtoField.framenum(NAME .. ".starts_in", "Message starts in frame")
F.header = ProtoField.bytes(NAME .. ".header", "Header")
F.payload = ProtoField.bytes(NAME .. ".payload", "Payload")
F.checksum = UINT[SPEC.frame.checksum.size](NAME .. ".checksum", "Checksum", base.HEX, nil, nil, SPEC.frame.checksum_doc)
F.computed = UINT[SPEC.frame.checksum.size](NAME .. ".checksum.computed", "Computed checksum", base.HEX)
F.status = ProtoField.uint8(NAME .. ".checksum.status", "Checksum status", base.DEC, { [0] = "Bad", [1] = "Good" })
F.discarded = ProtoField.bytes(NAME .. ".discarded", "Discarded bytes", base.NONE,
  "Bytes that belong to no valid frame or sentence (the leftmost-valid-message rule)")
F.damaged = ProtoField.string(NAME .. ".damaged", "Damaged message", base.ASCII,
  "A frame or sentence that failed its checks; its bytes are discarded")
F.undecoded = ProtoField.bytes(NAME .. ".undecoded", "Undecoded payload", base.NONE,
  "A payload no context explains: which table it follows is not guessed")
F.candidates = ProtoField.string(NAME .. ".candidates", "Tables of this size")

local frame_fields = {}
for _, f in ipairs(SPEC.frame.fields) do
  local names = nil
  if f.offset == SPEC.frame.message_type_offset then
    names = {}
    for _, t in ipairs(SPEC.frame.message_types) do
      names[t.value] = t.name
    end
  end
  frame_fields[f.name] = WIRE[f.type](NAME .. "." .. f.name, f.icd_name, base.DEC, names, nil, f.doc)
  table.insert(F, frame_fields[f.name])
end

-- The Unit Status Word's flags and mode, shared by every table that carries one.
local usw_bits = 16
for _, p in ipairs(SPEC.payloads) do
  for _, f in ipairs(p.fields) do
    if f.encoding == "usw" then
      usw_bits = 8 * f.size
    end
  end
end
local USW = { flags = {} }
for _, flag in ipairs(SPEC.status_word.flags) do
  local label = flag.icd_name .. ": " .. flag.name
  USW.flags[flag.name] = ProtoField.bool(NAME .. ".usw." .. flag.name, label, usw_bits, nil, 2 ^ flag.bit, flag.doc)
end
USW.mode = ProtoField.string(NAME .. ".usw.mode", "Mode", base.ASCII, "The mode the USW's mode bits say (" .. SPEC.status_word.icd .. ")")

local function describe(f)
  local text = f.doc or ""
  if f.icd_name then
    text = "ICD: " .. f.icd_name .. (text ~= "" and ". " .. text or "")
  end
  if f.erratum then
    text = text .. " (" .. f.erratum .. ")"
  end
  return text
end

-- Payload fields: PAYLOAD_FIELDS[table][field] = { value = ProtoField, raw = ProtoField or nil }.
local PAYLOAD_FIELDS = {}
for _, p in ipairs(SPEC.payloads) do
  PAYLOAD_FIELDS[p.name] = {}
  for _, f in ipairs(p.fields) do
    local abbrev = NAME .. "." .. p.name .. "." .. f.name
    local names = f.enum and SPEC.enums[f.enum].values or nil
    -- Checksums (an acknowledgement's) in hex, as the frame's own checksum.
    local hex = f.encoding == "usw" or p.name == SPEC.ack_payload
    local display = hex and base.HEX or base.DEC
    local label = f.label
    local entry = {}
    if f.encoding == "date" then
      entry.value = ProtoField.string(abbrev, label, base.ASCII,
        "The calendar date whose encoding is nearest the float (YYYY-MM-DD). " .. describe(f))
      entry.raw = ProtoField.double(abbrev .. ".raw", label .. " (float)", nil,
        "The date float as sent, every digit of its value")
    elseif f.type == "char" then
      entry.value = ProtoField.string(abbrev, label, base.ASCII, describe(f))
    elseif f.type == "reserved" then
      entry.value = ProtoField.bytes(abbrev, label, base.NONE, describe(f))
    elseif f.type == "f32" then
      entry.value = ProtoField.float(abbrev, label, nil, describe(f))
    elseif f.multiplier ~= nil then
      entry.value = ProtoField.double(abbrev, label, nil, describe(f))
      entry.raw = WIRE[f.type](abbrev .. ".raw", label .. " (raw)", base.DEC, nil, nil, "The value as sent")
    else
      entry.value = WIRE[f.type](abbrev, label, display, names, nil, describe(f))
    end
    if f.encoding == "calibration_success" then
      entry.outcome = ProtoField.string(abbrev .. ".outcome", "Calibration outcome", base.ASCII,
        "succeeded or failed, as the success byte says")
      entry.accuracy = ProtoField.double(abbrev .. ".accuracy", "Predicted heading accuracy", nil,
        "The predicted 3-sigma heading error in " .. SPEC.encodings.calibration_success.accuracy_unit
        .. "; absent when the calibration failed or gave no estimate")
    end
    PAYLOAD_FIELDS[p.name][f.name] = entry
  end
end

-- $PAHR fields: the engineering value and the scaled integer as sent.
local SENTENCE = NAME .. "." .. SPEC.nmea.identifier:lower()
local NMEA_FIELDS = {}
for _, f in ipairs(SPEC.nmea.fields) do
  local abbrev = SENTENCE .. "." .. f.name
  local entry = {}
  if f.format == "hex" then
    entry.value = ProtoField.uint16(abbrev, f.label, base.HEX, nil, nil, describe(f))
  else
    entry.value = ProtoField.double(abbrev, f.label, nil, describe(f))
    entry.raw = ProtoField.int32(abbrev .. ".raw", f.label .. " (raw)", base.DEC, nil, nil,
      string.format("The value x %d, as the sentence carries it", 10 ^ f.decimals))
  end
  NMEA_FIELDS[f.name] = entry
end
F.sentence = ProtoField.string(SENTENCE .. ".sentence", "Sentence")
F.nmea_checksum = ProtoField.uint8(SENTENCE .. ".checksum", "Checksum", base.HEX)
F.nmea_computed = ProtoField.uint8(SENTENCE .. ".checksum.computed", "Computed checksum", base.HEX)

local all = {}
for _, field in pairs(F) do
  table.insert(all, field)
end
for _, field in pairs(USW.flags) do
  table.insert(all, field)
end
table.insert(all, USW.mode)
for _, entries in pairs(PAYLOAD_FIELDS) do
  for _, entry in pairs(entries) do
    table.insert(all, entry.value)
    all[#all + 1] = entry.raw
    all[#all + 1] = entry.outcome
    all[#all + 1] = entry.accuracy
  end
end
for _, entry in pairs(NMEA_FIELDS) do
  table.insert(all, entry.value)
  all[#all + 1] = entry.raw
end
proto.fields = all

local E = {
  checksum = ProtoExpert.new(NAME .. ".expert.bad_checksum", "Bad checksum",
    expert.group.CHECKSUM, expert.severity.WARN),
  damaged = ProtoExpert.new(NAME .. ".expert.damaged", "Damaged message",
    expert.group.MALFORMED, expert.severity.WARN),
  discarded = ProtoExpert.new(NAME .. ".expert.discarded", "Bytes discarded",
    expert.group.UNDECODED, expert.severity.NOTE),
  unexpected = ProtoExpert.new(NAME .. ".expert.unexpected", "No context explains this message",
    expert.group.SEQUENCE, expert.severity.WARN),
  wrong_ack = ProtoExpert.new(NAME .. ".expert.wrong_ack", "Acknowledgement carries another checksum",
    expert.group.SEQUENCE, expert.severity.WARN),
  missing = ProtoExpert.new(NAME .. ".expert.missing", "Answer missing",
    expert.group.SEQUENCE, expert.severity.WARN),
  ignored = ProtoExpert.new(NAME .. ".expert.ignored", "Ignored by the device in this state",
    expert.group.SEQUENCE, expert.severity.NOTE),
  unknown = ProtoExpert.new(NAME .. ".expert.unknown_command", "Unknown command code",
    expert.group.PROTOCOL, expert.severity.WARN),
  late = ProtoExpert.new(NAME .. ".expert.late", "Output from the previous state",
    expert.group.SEQUENCE, expert.severity.CHAT),
  no_start = ProtoExpert.new(NAME .. ".expert.no_start", "Output with no start command",
    expert.group.SEQUENCE, expert.severity.NOTE),
}
proto.experts = { E.checksum, E.damaged, E.discarded, E.unexpected, E.wrong_ack, E.missing, E.ignored, E.unknown,
  E.late, E.no_start }

-- Preferences.
local variants = {}
local variant_help = {}
for i, v in ipairs(SPEC.variants) do
  variants[i] = { i, v.name, i }
  local values = {}
  for _, parameter in ipairs(SPEC.variant_parameters) do
    table.insert(values, parameter .. "=" .. tostring(v.values[parameter]))
  end
  table.insert(variant_help, v.name .. ": " .. v.part_number .. " (" .. table.concat(values, ", ") .. ")")
end
proto.prefs.variant = Pref.enum("Device variant (" .. table.concat(SPEC.variant_parameters, ", ") .. ")", 1,
  "The scale factors of the variant-scaled fields. " .. table.concat(variant_help, "; "),
  variants, false)
proto.prefs.tcp_port = Pref.uint("TCP port", 0,
  "The device's TCP port (a simulator's --tcp or a serial-over-IP server); 0: none")
proto.prefs.firmware = Pref.string("Firmware version", "",
  "The device's firmware; before some versions some transitions differ. Empty: current firmware")
proto.prefs.timeout = Pref.uint("Answer timeout (ms)", 1000,
  "How long an answer the device owes may take before it is reported missing")

-- The commands that start output: a capture begun mid-stream is read as their output.
local STARTERS = {}
local starter_choices = { { "none", "none: the capture holds the start command", 0 } }
for _, c in ipairs(SPEC.commands) do
  if c.starts_output then
    table.insert(STARTERS, c.name)
    table.insert(starter_choices, { c.name, c.name .. " (" .. c.starts_output .. ")", #STARTERS })
  end
end
proto.prefs.output_format = Pref.enum("Output format (capture begun mid-stream)", 0,
  "For a capture that begins while the device is already sending output: the command that started it ("
  .. table.concat(STARTERS, ", ") .. "). The capture is read from the state where that output flows, "
  .. "in its format. none: the capture holds the start command", starter_choices, false)


-- Following a capture. Each conversation (a pcapng interface, or a TCP connection) has a stream
-- per direction and one context. The first time a packet is seen, in capture order, what it
-- completes is recorded: messages with what the context says they are, runs of discarded bytes,
-- damaged frames and sentences. Every pass draws that record, so on a second pass (tshark -2)
-- requests link forward to their answers as answers link back to their requests.

local records, conversations = {}, {}
local interface_id = Field.new("frame.interface_id")
local SIGNED = { s8 = true, s16 = true, s32 = true }
local DIRECTION = { [true] = "host > device", [false] = "device > host" }
local LABEL = SPEC.name:upper()

function proto.init()
  records, conversations = {}, {}
end

local function conversation(pinfo)
  if pinfo.src_port ~= 0 or pinfo.dst_port ~= 0 then
    local port = proto.prefs.tcp_port
    local from_host = pinfo.dst_port == port or (pinfo.src_port ~= port and pinfo.dst_port < pinfo.src_port)
    local a = tostring(pinfo.src) .. ":" .. pinfo.src_port
    local b = tostring(pinfo.dst) .. ":" .. pinfo.dst_port
    return "tcp " .. (from_host and a .. " " .. b or b .. " " .. a), from_host
  end
  local id = interface_id()
  return "link " .. tostring(id and id.value or 0), pinfo.p2p_dir == P2P_DIR_SENT
end

local function process(tvb, pinfo)
  local key, from_host = conversation(pinfo)
  local conv = conversations[key]
  if conv == nil then
    local settings = { firmware = proto.prefs.firmware, timeout = proto.prefs.timeout / 1000,
      start = STARTERS[proto.prefs.output_format] }
    conv = { host = Stream.new(), device = Stream.new(), context = Context.new(settings) }
    conversations[key] = conv
  end
  local items = (from_host and conv.host or conv.device):feed(tvb:raw(), pinfo.number)
  for _, item in ipairs(items) do
    if item.kind == "message" then
      item.at = pinfo.number
      if from_host then
        item.info = conv.context:host(item, pinfo.rel_ts)
      else
        item.info = conv.context:device(item, pinfo.rel_ts)
        if item.info.request then
          table.insert(item.info.request.answers, pinfo.number)
        end
      end
    end
  end
  return { items = items, from_host = from_host }
end

-- Drawing -------------------------------------------------------------------------------------

local function add_wire(tree, field, range)
  if SPEC.byte_order == "little" then
    return tree:add_le(field, range)
  end
  return tree:add(field, range)
end

-- Where a piece of the stream lies: in this packet, or in bytes reassembled from several.
local function locate(tvb, pinfo, piece, label)
  if piece.frame == pinfo.number and piece.contiguous then
    return tvb, piece.offset
  end
  return ByteArray.new(piece.raw, true):tvb(label), 0
end

local function latin1(text)
  return (text:gsub("[\128-\255]", function(c)
    return string.char(0xC0 + math.floor(c:byte() / 64), 0x80 + c:byte() % 64)
  end))
end

-- Text for display: bytes outside printable ASCII as \xNN.
local function printable(text)
  return (text:gsub("[^\32-\126]", function(c)
    return string.format("\\x%02X", c:byte())
  end))
end

-- The flags of a status word: from the bytes of a frame, from the parsed value of a sentence
-- (whose bytes are hex digits).
local function usw_tree(item, range, value, text)
  for _, flag in ipairs(SPEC.status_word.flags) do
    if text then
      item:add(USW.flags[flag.name], range, value)
    else
      add_wire(item, USW.flags[flag.name], range)
    end
  end
  item:add(USW.mode, range, P.usw_mode(value)):set_generated()
end

-- What an encoding, an enum or multiplexing adds to a value's text.
local function annotate(item, f, raw)
  local encodings = SPEC.encodings
  if f.encoding == "declination" and raw > encodings.declination.compute_above then
    item:append_text(" (the device computes it)")
  elseif f.encoding == "calibration_success" then
    local c = encodings.calibration_success
    if raw == c.failed then
      item:append_text(" (failed)")
    elseif raw == c.no_estimate then
      item:append_text(" (succeeded, no estimate)")
    else
      item:append_text(string.format(" (succeeded, %g %s)", raw / c.accuracy_divisor, c.accuracy_unit))
    end
  end
  local enum = f.enum and SPEC.enums[f.enum]
  if enum and enum.external_above and raw > enum.external_above then
    item:append_text(string.format(" (above 0x%X)", enum.external_above))
  end
  if f.multiplexed then
    item:append_text(string.format(" (one of %d quantities, in turn)", f.multiplexed))
  end
end

local function field_value(f, range)
  local text = range:raw()
  if f.type == "char" then
    return latin1((text:gsub("\0+$", "")))
  elseif f.type == "f32" then
    return SPEC.byte_order == "little" and range:le_float() or range:float()
  elseif f.type ~= "reserved" then
    return SIGNED[f.type] and P.int(text, 1, f.size) or P.uint(text, 1, f.size)
  end
end

local function payload_tree(tree, mtvb, offset, name)
  local payload = P.payloads[name]
  local variant = SPEC.variants[proto.prefs.variant] or SPEC.variants[1]
  local sub = tree:add(F.table, mtvb(offset, payload.size), name)
  sub:append_text(" (" .. payload.title .. ", " .. payload.icd .. ")")
  for _, f in ipairs(payload.fields) do
    local range = mtvb(offset + f.offset, f.size)
    local entry = PAYLOAD_FIELDS[name][f.name]
    local raw = field_value(f, range)
    local unit = f.unit and " " .. f.unit or ""
    local item
    if f.type == "reserved" then
      item = sub:add(entry.value, range)
    elseif f.encoding == "date" then
      -- The calendar date, the float as sent beside it; a float no date is near: the float only.
      local date = P.decode_date(raw)
      if date then
        item = sub:add(entry.value, range, date)
        item:add(entry.raw, range, raw)
      else
        item = sub:add(entry.raw, range, raw)
        item:append_text(" (not a date)")
      end
    elseif entry.raw then
      item = sub:add(entry.value, range, P.engineering(f, raw, variant))
      item:append_text(unit)
      item:add(entry.raw, range, raw)
    else
      item = sub:add(entry.value, range, raw)
      item:append_text(unit)
    end
    if type(raw) == "number" and f.encoding ~= "date" then
      annotate(item, f, raw)
    end
    if f.encoding == "usw" then
      usw_tree(item, range, raw)
    end
    if entry.outcome then
      local c = SPEC.encodings.calibration_success
      sub:add(entry.outcome, range, raw == c.failed and "failed" or "succeeded"):set_generated()
      if raw ~= c.failed and raw ~= c.no_estimate then
        local accuracy = sub:add(entry.accuracy, range, raw / c.accuracy_divisor)
        accuracy:append_text(" " .. c.accuracy_unit)
        accuracy:set_generated()
      end
    end
  end
  return sub
end

local function sentence_tree(tree, mtvb, offset, raw, values)
  tree:add(F.sentence, mtvb(offset, #raw - 2), raw:sub(1, -3))
  local pos = #P.sentence_prefix
  local star = #raw - 5
  for i, part in ipairs(P.sentence_fields(raw)) do
    local f = SPEC.nmea.fields[i]
    local entry = NMEA_FIELDS[f.name]
    local range = mtvb(offset + pos, #part)
    local value = values[f.name]
    if entry.raw then
      local item = tree:add(entry.value, range, value / 10 ^ f.decimals)
      item:append_text(f.unit and " " .. f.unit or "")
      item:add(entry.raw, range, value)
    else
      usw_tree(tree:add(entry.value, range, value), range, value, true)
    end
    pos = pos + #part + 1
  end
  local range = mtvb(offset + star + 1, 2)
  tree:add(F.nmea_checksum, range, tonumber(raw:sub(star + 2, star + 3), 16)):append_text(" [correct]")
  tree:add(F.status, range, 1):set_generated()
end

local function frame_head(tree, mtvb, offset, raw)
  local frame = SPEC.frame
  tree:add(F.header, mtvb(offset, #P.header))
  for _, f in ipairs(frame.fields) do
    add_wire(tree, frame_fields[f.name], mtvb(offset + f.offset, f.size))
  end
  return mtvb(offset + frame.payload_offset, #raw - frame.payload_offset - frame.checksum.size),
    mtvb(offset + #raw - frame.checksum.size, frame.checksum.size)
end

local function generated(tree, field, value)
  if value ~= nil then
    tree:add(field, value):set_generated()
  end
end

-- A message from the host: a command, a parameter block or something else.
local function host_body(sub, payload_range, mtvb, info)
  if info.kind == "command" then
    sub:add(F.command, payload_range, info.command):append_text(" (" .. P.commands[info.command].purpose .. ")")
    sub:add(F.code, payload_range)
  elseif info.kind == "unknown_command" then
    sub:add(F.code, payload_range):add_proto_expert_info(E.unknown)
  elseif info.kind == "parameter_block" then
    payload_tree(sub, mtvb, payload_range:offset(), info.table)
  elseif payload_range then
    sub:add(F.undecoded, payload_range)
  end
  if info.ignored then
    sub:add_proto_expert_info(E.ignored, "Ignored in state " .. info.state)
  end
  for _, frame in ipairs(info.answers) do
    sub:add(F.response, frame):set_generated()
  end
  if info.missing then
    sub:add_proto_expert_info(E.missing, "No " .. info.missing .. " within the answer timeout")
  end
end

local function candidates(size)
  local names = {}
  for _, p in ipairs(SPEC.payloads) do
    if p.size == size then
      table.insert(names, p.name)
    end
  end
  return table.concat(names, ", ")
end

-- A message from the device, as the context explains it.
local function device_body(sub, payload_range, mtvb, info)
  if info.kind == "unexpected" then
    if payload_range then
      sub:add(F.undecoded, payload_range)
      generated(sub, F.candidates, candidates(payload_range:len()))
    end
    local text = "Nothing in state " .. info.state .. " explains this message"
    sub:add_proto_expert_info(E.unexpected, text .. (info.expected and " (expected " .. info.expected .. ")" or ""))
    if info.no_start then
      sub:add_proto_expert_info(E.no_start, "Output with no start command before it: if the capture began "
        .. "mid-stream, set the preference \"Output format (capture begun mid-stream)\" (-o " .. SPEC.name
        .. ".output_format:COMMAND) to the command that started it")
    end
  elseif info.table and payload_range then
    payload_tree(sub, mtvb, payload_range:offset(), info.table)
  end
  if info.request then
    local link = info.kind == "ack" and F.ack_frame or F.request
    sub:add(link, info.request.frame):set_generated()
  end
  if info.wrong then
    sub:add_proto_expert_info(E.wrong_ack, string.format("Carries 0x%04X; the message it answers has 0x%04X",
      info.value, info.expected))
  end
  if info.late then
    sub:add(F.late, true):set_generated()
    sub:add_proto_expert_info(E.late)
  end
  if info.missing then
    sub:add_proto_expert_info(E.missing, info.missing .. " never came")
  end
end

local function summary(item, from_host)
  local info = item.info
  local what = info.command or info.table or (item.sentence and "$" .. SPEC.nmea.identifier) or ""
  if info.kind == "ack" then
    what = info.source
  end
  return info.kind .. (what ~= "" and " " .. what or "") .. (info.late and " (late)" or "")
end

local function draw_message(tree, tvb, pinfo, item, from_host)
  local mtvb, offset = locate(tvb, pinfo, item, "Reassembled message")
  local info = item.info
  local sub = tree:add(proto, mtvb(offset, #item.raw), LABEL .. ", " .. DIRECTION[from_host] .. ": "
    .. summary(item, from_host))
  if item.frame ~= pinfo.number then
    sub:add(F.starts_in, item.frame):set_generated()
  end
  generated(sub, F.kind, info.kind)
  generated(sub, F.source, not from_host and info.source or nil)
  generated(sub, F.state, info.state)
  local payload_range, checksum_range
  if item.sentence then
    sentence_tree(sub, mtvb, offset, item.raw, item.sentence)
  else
    payload_range, checksum_range = frame_head(sub, mtvb, offset, item.raw)
  end
  if from_host then
    host_body(sub, payload_range, mtvb, info)
  else
    device_body(sub, payload_range, mtvb, info)
  end
  if checksum_range then
    add_wire(sub, F.checksum, checksum_range):append_text(" [correct]")
    sub:add(F.status, checksum_range, 1):set_generated()
  end
end

-- A frame or sentence given up because the next message starts inside it: the bytes that came.
local function draw_truncated(sub, mtvb, offset, item)
  local raw = item.raw
  if item.sentence then
    sub:add(F.sentence, mtvb(offset, #raw), printable((raw:gsub("[\r\n]+$", ""))))
  else
    local frame = SPEC.frame
    sub:add(F.header, mtvb(offset, math.min(#P.header, #raw)))
    for _, f in ipairs(frame.fields) do
      if f.offset + f.size <= #raw then
        add_wire(sub, frame_fields[f.name], mtvb(offset + f.offset, f.size))
      end
    end
    if #raw > frame.payload_offset then
      sub:add(F.payload, mtvb(offset + frame.payload_offset, #raw - frame.payload_offset))
    end
  end
  local what = item.sentence and "sentence" or "frame"
  local why = item.sentence and "no CR LF before it"
    or string.format("its length field announces %d bytes", item.truncated_from)
  sub:add_proto_expert_info(E.damaged, string.format("Truncated %s: %d bytes, then the next message (%s)", what,
    #raw, why))
end

local function damage_text(item)
  return "damaged " .. (item.sentence and "sentence" or "frame") .. ": " .. printable(item.reason)
end

local function draw_damaged(tree, tvb, pinfo, item)
  local mtvb, offset = locate(tvb, pinfo, item, "Damaged message")
  local reason = printable(item.reason)
  local sub = tree:add(proto, mtvb(offset, #item.raw), LABEL .. ", " .. damage_text(item))
  generated(sub, F.damaged, reason)
  if item.truncated_from then
    draw_truncated(sub, mtvb, offset, item)
    return
  end
  local checksum_range
  if item.sentence then
    checksum_range = mtvb(offset + #item.raw - 4, 2)
    sub:add(F.sentence, mtvb(offset, #item.raw), printable((item.raw:gsub("[\r\n]+$", ""))))
  else
    local payload_range
    payload_range, checksum_range = frame_head(sub, mtvb, offset, item.raw)
    sub:add(F.payload, payload_range)
  end
  if item.sent == nil then
    sub:add_proto_expert_info(E.damaged, "Damaged sentence: " .. reason)
    return
  end
  local field, computed = F.checksum, F.computed
  if item.sentence then
    field, computed = F.nmea_checksum, F.nmea_computed
  end
  local ck = item.sentence and sub:add(field, checksum_range, item.sent) or add_wire(sub, field, checksum_range)
  ck:append_text(" [incorrect]")
  sub:add(computed, checksum_range, item.computed):set_generated()
  sub:add(F.status, checksum_range, 0):set_generated()
  ck:add_proto_expert_info(E.checksum, string.format("Bad checksum: sent 0x%X, computed 0x%X", item.sent,
    item.computed))
end

local function draw_discarded(tree, tvb, pinfo, item)
  local mtvb, offset = locate(tvb, pinfo, item, "Discarded bytes")
  local range = mtvb(offset, #item.raw)
  local sub = tree:add(proto, range, string.format("%s, %d bytes discarded", LABEL, #item.raw))
  sub:add(F.discarded, range):add_proto_expert_info(E.discarded, string.format("%d bytes discarded", #item.raw))
end

function proto.dissector(tvb, pinfo, tree)
  local record = records[pinfo.number]
  if record == nil then
    record = process(tvb, pinfo)
    records[pinfo.number] = record
  end
  pinfo.cols.protocol = LABEL
  if pinfo.src_port == 0 and pinfo.dst_port == 0 then
    pinfo.cols.src = record.from_host and "host" or "device"
    pinfo.cols.dst = record.from_host and "device" or "host"
  end
  local texts, discarded = {}, 0
  for _, item in ipairs(record.items) do
    if item.kind == "message" then
      draw_message(tree, tvb, pinfo, item, record.from_host)
      table.insert(texts, summary(item, record.from_host))
    elseif item.kind == "damaged" then
      draw_damaged(tree, tvb, pinfo, item)
      table.insert(texts, damage_text(item))
    else
      draw_discarded(tree, tvb, pinfo, item)
      discarded = discarded + #item.raw
    end
  end
  if discarded > 0 then
    table.insert(texts, discarded .. " bytes discarded")
  end
  if #texts == 0 then
    table.insert(texts, "part of a message")
  end
  pinfo.cols.info:set(DIRECTION[record.from_host] .. ": " .. table.concat(texts, "; "))
  return tvb:len()
end

-- Registration: the pcapng link type of a recorded serial line (LINKTYPE_USER0, 147), TCP on the
-- port of the preferences, and Decode As for any other TCP port.

DissectorTable.get("wtap_encap"):add(wtap.USER0, proto)
DissectorTable.get("tcp.port"):add_for_decode_as(proto)

local registered_port = 0
function proto.prefs_changed()
  local port = proto.prefs.tcp_port
  if port ~= registered_port then
    local tcp = DissectorTable.get("tcp.port")
    if registered_port ~= 0 then
      tcp:remove(registered_port, proto)
    end
    if port ~= 0 then
      tcp:add(port, proto)
    end
    registered_port = port
  end
end
