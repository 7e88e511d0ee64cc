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
