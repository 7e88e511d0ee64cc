#!/usr/bin/env node
// A conformance runner for a foreign implementation: the Inertial Labs AHRS frame written from
// the ICD in plain JavaScript (Node 20, no packages), answering the runner protocol of the ilahrs
// conformance suite for four kinds: checksum, frame_decode, frame_encode and ack. Every other
// request is answered `unsupported`.
//
//   ilahrs conformance --command "node runner.mjs" --kinds checksum,frame_decode,frame_encode,ack
//
// The implementation (the first half) knows nothing of the suite; the second half turns request
// lines into calls and results into answer lines.

import { createInterface } from "node:readline";

// --- the implementation: ICD rev 1.7, Table 6.2 ----------------------------------------------------

const HEADER = [0xaa, 0x55];
const MIN_LENGTH = 7; // message length counts type, reserved, length, payload, checksum: 1-byte payload
const MAX_LENGTH = 58; // 52-byte payload

class ProtocolError extends Error {
  constructor(kind, offset, field) {
    super(`${kind} at ${offset} (${field})`);
    this.kind = kind;
    this.offset = offset;
    this.field = field;
  }
}

/** The frame checksum: the sum of the bytes from the message type through the payload, mod 2^16. */
export function checksum(bytes) {
  return bytes.reduce((sum, b) => (sum + b) & 0xffff, 0);
}

/** One whole frame -> {messageType, reserved, payload}; the checks in the order the spec gives. */
export function decodeFrame(data) {
  for (let i = 0; i < HEADER.length; i++) {
    if (data.length <= i) throw new ProtocolError("truncated", i, null);
    if (data[i] !== HEADER[i]) throw new ProtocolError("bad_header", i, "header");
  }
  if (data.length < 6) throw new ProtocolError("truncated", data.length, null);
  const messageType = data[2];
  if (messageType !== 0 && messageType !== 1) throw new ProtocolError("bad_message_type", 2, "message_type");
  const length = data[4] | (data[5] << 8);
  if (length < MIN_LENGTH || length > MAX_LENGTH) throw new ProtocolError("bad_length", 4, "message_length");
  if (data.length < length + 2) throw new ProtocolError("truncated", data.length, null);
  const sent = data[length] | (data[length + 1] << 8);
  if (sent !== checksum(data.subarray(2, length))) throw new ProtocolError("bad_checksum", length, "checksum");
  if (data.length > length + 2) throw new ProtocolError("trailing_data", length + 2, null);
  return { messageType, reserved: data[3], payload: data.subarray(6, length) };
}

/** A frame's bytes; the builder fills the length and the checksum. */
export function encodeFrame(messageType, payload, reserved = 0) {
  if (messageType !== 0 && messageType !== 1) throw new ProtocolError("bad_message_type", null, "message_type");
  if (reserved < 0 || reserved > 0xff) throw new ProtocolError("out_of_range", null, "reserved");
  if (payload.length < MIN_LENGTH - 6 || payload.length > MAX_LENGTH - 6) {
    throw new ProtocolError("bad_length", null, "payload");
  }
  const length = payload.length + 6;
  const body = Uint8Array.from([messageType, reserved, length & 0xff, length >> 8, ...payload]);
  const sum = checksum(body);
  return Uint8Array.from([...HEADER, ...body, sum & 0xff, sum >> 8]);
}

/** The device's acknowledgement of a message: a data frame carrying the message's checksum (E12). */
export function acknowledge(message) {
  decodeFrame(message);
  const length = message[4] | (message[5] << 8);
  return encodeFrame(1, message.subarray(length, length + 2));
}

// --- the runner protocol -------------------------------------------------------------------------

const readHex = (token) => (token === "-" ? new Uint8Array() : Uint8Array.from(Buffer.from(token, "hex")));
const writeHex = (bytes) => (bytes.length ? Buffer.from(bytes).toString("hex").toUpperCase() : "-");

const KINDS = {
  checksum: ([hex]) => `ok ${checksum(readHex(hex))}`,
  frame_decode: ([hex]) => {
    const frame = decodeFrame(readHex(hex));
    return `ok message_type=${frame.messageType} reserved=${frame.reserved} payload=${writeHex(frame.payload)}`;
  },
  frame_encode: ([type, hex, reserved]) =>
    `ok ${writeHex(encodeFrame(Number(type), readHex(hex), reserved === undefined ? 0 : Number(reserved)))}`,
  ack: ([hex]) => `ok ${writeHex(acknowledge(readHex(hex)))}`,
};

function answer(line) {
  const [kind, ...args] = line.split(" ");
  const handler = KINDS[kind];
  if (handler === undefined) return "unsupported";
  try {
    return handler(args);
  } catch (err) {
    if (err instanceof ProtocolError) return `error ${err.kind} ${err.offset ?? "-"} ${err.field ?? "-"}`;
    return `crash ${String(err).replace(/\s+/g, "_")}`;
  }
}

// One answer line per request line, written before the next line is read; exit when input closes.
for await (const line of createInterface({ input: process.stdin, crlfDelay: Infinity })) {
  process.stdout.write(answer(line) + "\n");
}
