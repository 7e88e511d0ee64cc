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
