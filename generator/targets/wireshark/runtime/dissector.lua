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
