-- The stream rule every binding follows: leftmost valid message (spec/README.md). One Stream per
-- direction of a conversation; bytes are fed packet by packet, in capture order. Each held byte
-- remembers the packet it came in and its offset there, so that a message or a run of discarded
-- bytes can be shown where it lies, or reassembled when it spans packets.

local Stream = {}
Stream.__index = Stream

function Stream.new()
  return setmetatable({ buffer = "", frames = {}, offsets = {}, discarded = 0 }, Stream)
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

-- Add the bytes of packet `frame`; return what they complete, in order: messages
-- ({ kind = "message", raw, frame, offset, sentence = values or nil }), runs of discarded bytes
-- ({ kind = "discard", ... }) and damaged candidates, frames or sentences that failed only
-- their checks ({ kind = "damaged", reason, sent, computed, ... }).
function Stream:feed(data, frame, final)
  local base = #self.buffer
  self.buffer = self.buffer .. data
  for i = 1, #data do
    self.frames[base + i] = frame
    self.offsets[base + i] = i - 1
  end
  local s = self.buffer
  local out = {}
  local run -- the discard run being collected: its first position
  local function close(pos)
    if run then
      local piece = self:piece(run, pos - 1)
      piece.kind = "discard"
      table.insert(out, piece)
      self.discarded = self.discarded + #piece.raw
      run = nil
    end
  end
  local pos = 1
  while pos <= #s do
    local first = s:byte(pos)
    local used, extra, sent, computed, size
    if first == P.header:byte(1) then
      used, sent, computed, size = P.frame_at(s, pos)
    elseif first == P.SENTENCE_START then
      used, extra, sent, computed, size = P.sentence_at(s, pos)
    else
      local following = next_start(s, pos + 1)
      run = run or pos
      pos = following
      used = nil
    end
    if used == nil then
      -- skipped
    elseif used > 0 then
      close(pos)
      local piece = self:piece(pos, pos + used - 1)
      piece.kind = "message"
      piece.sentence = extra
      table.insert(out, piece)
      pos = pos + used
    elseif used == P.INVALID or final then
      local sentence = first == P.SENTENCE_START
      if size ~= nil and (sent ~= nil or s:sub(pos, pos + #P.sentence_prefix - 1) == P.sentence_prefix) then
        local damaged = self:piece(pos, pos + size - 1)
        damaged.kind = "damaged"
        damaged.reason = extra or "bad checksum"
        damaged.sent, damaged.computed = sent, computed
        damaged.sentence = sentence
        table.insert(out, damaged)
      end
      run = run or pos
      pos = pos + 1
    else
      break
    end
  end
  close(pos)
  self.buffer = s:sub(pos)
  local frames, offsets = {}, {}
  for i = pos, #s do
    frames[i - pos + 1] = self.frames[i]
    offsets[i - pos + 1] = self.offsets[i]
  end
  self.frames, self.offsets = frames, offsets
  return out
end
