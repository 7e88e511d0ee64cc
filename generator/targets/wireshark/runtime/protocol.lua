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
