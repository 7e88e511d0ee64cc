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
