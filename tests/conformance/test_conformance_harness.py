"""conformance/harness.py: translation, comparison, counting and the runner life cycle.

The end-to-end tests drive the harness against a scripted runner (a table of request line ->
answer line, written to a temporary directory), so every outcome is forced: pass, wrong answer,
`unsupported`, a runner that exits or hangs, a runner that does not exist.
"""

from __future__ import annotations

import io
import json
import sys
from pathlib import Path
from typing import Any

import pytest
from script_support import load_script

ROOT = Path(__file__).resolve().parents[2]


H = load_script("conformance_harness", ROOT / "conformance" / "harness.py")
RUNNER = load_script("conformance_python_runner", ROOT / "conformance" / "runners" / "python" / "python_runner.py")

SCRIPTED_RUNNER = """\
import json, sys, time
table = json.load(open(sys.argv[1]))
for line in sys.stdin:
    reply = table.get(line.rstrip("\\n"), "unsupported")
    if reply == "EXIT":
        sys.exit(3)
    if reply == "HANG":
        time.sleep(30)
    sys.stdout.write(reply + "\\n")
    sys.stdout.flush()
"""


def vector(id_: str, kind: str, input_: Any, expect: Any) -> Any:
    return H.Vector("t", id_, kind, input_, expect, None)


def check(v: Any, line: str) -> str | None:
    result: str | None = H.compare(v, H.parse_answer(line))
    return result


# --- translation ----------------------------------------------------------------------------------


def test_requests_follow_the_line_protocol() -> None:
    assert H.request(vector("a", "checksum", "aa 55", 0)) == "checksum AA55"
    assert H.request(vector("a", "checksum", "", 0)) == "checksum -"
    assert H.request(vector("a", "frame_encode", {"message_type": 0, "payload": "80", "reserved": 5}, "")) == \
        "frame_encode 0 80 5"
    assert H.request(vector("a", "payload_encode", {"type": "t", "fields": {
        "x": 1, "y": -0.5, "z": "nan", "name": "a b=%,", "r": "00ff"}}, "")) == \
        "payload_encode t - x=1 y=-0.5 z=nan name=a%20b%3D%25%2C r=00ff"
    assert H.request(vector("a", "payload_decode", {"type": "t", "hex": "01", "variant": "v"}, {})) == \
        "payload_decode t 01 v"
    assert H.request(vector("a", "nmea_decode", "$P\r\n", {})) == "nmea_decode $P%0D%0A"
    assert H.request(vector("a", "stream", {"chunks": ["aa", "", "55 00"]}, {})) == "stream AA,-,5500"


def test_bad_vectors_are_suite_errors() -> None:
    with pytest.raises(H.SuiteError):
        H.request(vector("a", "checksum", "a", 0))
    with pytest.raises(H.SuiteError):
        H.request(vector("a", "command_encode", {"command": "two words"}, ""))
    with pytest.raises(H.SuiteError):
        H.request(vector("a", "nmea_encode", {"roll": "x"}, ""))


# --- comparison -----------------------------------------------------------------------------------


def test_only_the_keys_present_are_compared() -> None:
    v = vector("a", "frame_decode", "", {"error": "truncated"})
    assert check(v, "error truncated 5 -") is None
    assert check(v, "error bad_header 0 header") == "error kind bad_header, expected truncated"
    v = vector("a", "frame_decode", "", {"error": "bad_header", "offset": 1, "field": "header"})
    assert check(v, "error bad_header 0 header") == "error offset 0, expected 1"
    assert check(v, "error bad_header 1 -") == "error field -, expected header"
    assert check(v, "ok message_type=0 reserved=0 payload=80") == "expected error bad_header, got ok"
    v = vector("a", "frame_decode", "", {"payload": "80"})
    assert check(v, "ok message_type=1 reserved=9 payload=80") is None


def test_hex_compares_bytes() -> None:
    v = vector("a", "command_encode", {"command": "X"}, "AA 55 00")
    assert check(v, "ok aa5500") is None
    assert check(v, "ok AA5501") == "bytes differ"
    assert check(v, "error unknown_command - -") == "expected a result, got error"


def test_payload_fields_compare_by_kind() -> None:
    v = vector("a", "payload_decode", {}, {"fields": {
        "i": -3, "f": 0.1, "n": "nan", "c": "4.9 x", "r": "00ff", "z": -0.0}, "values": {"e": 359.99}})
    good = "ok f.i=-3 f.f=0.10000000149011612 f.n=NaN f.c=4.9%20x f.r=00FF f.z=-0.0 v.e=359.99000000001"
    assert check(v, good) is None
    assert check(v, good.replace("f.i=-3", "f.i=-4")) == "field i differs"
    assert check(v, good.replace("0.10000000149011612", "0.1000001")) == "field f differs"
    assert check(v, good.replace("f.z=-0.0", "f.z=0.0")) == "field z differs"  # float32 bits, not ==
    assert check(v, good.replace("f.n=NaN", "f.n=1.0")) == "field n differs"
    assert check(v, good.replace("f.c=4.9%20x", "f.c=4.9x")) == "field c differs"
    assert check(v, good.replace("v.e=359.99000000001", "v.e=359.991")) == "value e differs"
    assert check(v, good.replace(" v.e=359.99000000001", "")) == "value e missing"


def test_stream_events_and_discarded() -> None:
    v = vector("a", "stream", {}, {"events": [{"frame": "AA 55"}, {"nmea": "$X\r\n"}], "discarded": 2})
    assert check(v, "ok discarded=2 events=F:AA55,N:$X%0D%0A") is None
    assert check(v, "ok discarded=3 events=F:AA55,N:$X%0D%0A") == "discarded 3, expected 2"
    assert check(v, "ok discarded=2 events=F:AA55").startswith("1 events")  # type: ignore[union-attr]
    assert check(v, "ok discarded=2 events=N:$X%0D%0A,F:AA55").startswith("event 0 differs")  # type: ignore[union-attr]
    empty = vector("a", "stream", {}, {"events": [], "discarded": 0})
    assert check(empty, "ok discarded=0 events=-") is None


def test_nmea_numbers_within_tolerance() -> None:
    v = vector("a", "nmea_decode", "", {"roll": -12.34, "usw": 255})
    assert check(v, "ok roll=-12.34 pitch=0 heading=0 temperature=0 vdd=0 usw=255") is None
    assert check(v, "ok roll=-12.35 pitch=0 heading=0 temperature=0 vdd=0 usw=255") == "roll differs"
    assert check(v, "ok roll=-12.34 pitch=0 heading=0 temperature=0 vdd=0 usw=254") == "usw differs"


# --- end to end -----------------------------------------------------------------------------------


def write_suite(directory: Path, vectors: list[dict[str, Any]]) -> Path:
    directory.mkdir(parents=True, exist_ok=True)
    (directory / "t.json").write_text(json.dumps({"suite": "t", "source": "test", "vectors": vectors}))
    return directory


def register(directory: Path, table: dict[str, str], kinds: list[str], command: list[str] | None = None) -> Path:
    """A bindings directory registering `fake`: the scripted runner with this table (kept next to it)."""
    directory.mkdir(parents=True, exist_ok=True)
    scripts = directory.parent / "scripts"
    scripts.mkdir(exist_ok=True)
    (scripts / "runner.py").write_text(SCRIPTED_RUNNER)
    (scripts / "table.json").write_text(json.dumps(table))
    cmd = command or ["{python}", str(scripts / "runner.py"), str(scripts / "table.json")]
    (directory / "fake.json").write_text(json.dumps({"name": "fake", "command": cmd, "kinds": kinds,
                                                     "build": "make build-fake"}))
    return directory


def run(*args: str) -> tuple[int, str]:
    out = io.StringIO()
    code: int = H.main(list(args), out=out)
    return code, out.getvalue()


CHECKSUMS: list[dict[str, Any]] = [
    {"id": "c/empty", "kind": "checksum", "input": "", "expect": 0},
    {"id": "c/one", "kind": "checksum", "input": "01", "expect": 1},
    {"id": "c/two", "kind": "checksum", "input": "02", "expect": 2},
    {"id": "f/x", "kind": "frame_decode", "input": "AA", "expect": {"error": "truncated", "offset": 1}},
]


def test_pass_fail_and_not_supported_are_counted(tmp_path: Path) -> None:
    vectors = write_suite(tmp_path / "v", CHECKSUMS)
    bindings = register(tmp_path / "b", {"checksum -": "ok 0", "checksum 01": "ok 7", "checksum 02": "ok 2"},
                        ["checksum"])
    code, text = run("--vectors", str(vectors), "--bindings-dir", str(bindings))
    assert code == 1
    assert "2 passed, 1 FAILED, 1 n/s" in text
    assert "FAILED fake t c/one: checksum differs" in text
    assert "request:  checksum 01" in text and "expected: 1" in text and "actual:   ok 7" in text


def test_all_passing_exits_zero_and_json_report(tmp_path: Path) -> None:
    vectors = write_suite(tmp_path / "v", CHECKSUMS[:1])
    bindings = register(tmp_path / "b", {"checksum -": "ok 0"}, ["checksum"])
    code, text = run("--vectors", str(vectors), "--bindings-dir", str(bindings), "--json", str(tmp_path / "r.json"))
    assert code == 0 and text.rstrip().endswith("PASSED")
    report = json.loads((tmp_path / "r.json").read_text())
    assert report["ok"] and report["results"] == [
        {"binding": "fake", "suite": "t", "passed": 1, "failed": 0, "unsupported": 0, "expected_failures": 0,
         "unexpected_passes": 0, "not_applicable": 0, "skipped": 0}]


def test_unsupported_for_a_listed_kind_fails(tmp_path: Path) -> None:
    vectors = write_suite(tmp_path / "v", CHECKSUMS)
    bindings = register(tmp_path / "b", {}, ["checksum", "frame_decode"])
    code, text = run("--vectors", str(vectors), "--bindings-dir", str(bindings))
    assert code == 1 and "4 FAILED" in text and "answered unsupported, but fake lists checksum" in text


def test_missing_runner_names_its_build_command(tmp_path: Path) -> None:
    vectors = write_suite(tmp_path / "v", CHECKSUMS)
    bindings = register(tmp_path / "b", {}, ["checksum"], command=["build/fake/does-not-exist"])
    code, text = run("--vectors", str(vectors), "--bindings-dir", str(bindings))
    assert code == 1
    assert "FAILED fake: runner build/fake/does-not-exist not found in " in text
    assert "; build it with `make build-fake` there" in text


def test_a_runner_that_exits_is_restarted(tmp_path: Path) -> None:
    vectors = write_suite(tmp_path / "v", CHECKSUMS[:3])
    bindings = register(tmp_path / "b", {"checksum -": "ok 0", "checksum 01": "EXIT", "checksum 02": "ok 2"},
                        ["checksum"])
    code, text = run("--vectors", str(vectors), "--bindings-dir", str(bindings))
    assert code == 1 and "2 passed, 1 FAILED" in text and "runner exited (exit status 3)" in text


def test_a_runner_that_hangs_times_out(tmp_path: Path) -> None:
    vectors = write_suite(tmp_path / "v", CHECKSUMS[:3])
    bindings = register(tmp_path / "b", {"checksum -": "ok 0", "checksum 01": "HANG", "checksum 02": "ok 2"},
                        ["checksum"])
    code, text = run("--vectors", str(vectors), "--bindings-dir", str(bindings), "--timeout", "1")
    assert code == 1 and "2 passed, 1 FAILED" in text and "no answer within 1 s" in text


def test_a_runner_that_stops_reading_times_out(tmp_path: Path) -> None:
    big = [{"id": "s/big", "kind": "stream", "input": {"chunks": ["00" * 300_000]}, "expect": {"discarded": 300_000}}]
    vectors = write_suite(tmp_path / "v", big)
    (tmp_path / "deaf.py").write_text("import time\ntime.sleep(30)\n")
    bindings = register(tmp_path / "b", {}, ["stream"], command=["{python}", str(tmp_path / "deaf.py")])
    code, text = run("--vectors", str(vectors), "--bindings-dir", str(bindings), "--timeout", "1")
    assert code == 1 and "did not read its request within 1 s" in text


def test_an_invalid_answer_is_shown_verbatim(tmp_path: Path) -> None:
    vectors = write_suite(tmp_path / "v", CHECKSUMS[:1])
    bindings = register(tmp_path / "b", {"checksum -": "crash ValueError"}, ["checksum"])
    code, text = run("--vectors", str(vectors), "--bindings-dir", str(bindings))
    assert code == 1 and "not an answer of the runner protocol" in text and "actual:   crash ValueError" in text


def test_an_ad_hoc_command_needs_no_registration(tmp_path: Path) -> None:
    vectors = write_suite(tmp_path / "v", CHECKSUMS)
    bindings = register(tmp_path / "b", {"checksum -": "ok 0", "checksum 01": "ok 1", "checksum 02": "ok 2"}, [])
    scripts = bindings.parent / "scripts"
    command = f"{sys.executable} {scripts / 'runner.py'} {scripts / 'table.json'}"
    code, text = run("--vectors", str(vectors), "--command", command, "--name", "mine")
    assert code == 0 and "3 passed, 1 n/s" in text


def test_filters_and_unknown_bindings(tmp_path: Path) -> None:
    vectors = write_suite(tmp_path / "v", CHECKSUMS)
    bindings = register(tmp_path / "b", {"checksum 02": "ok 2"}, ["checksum"])
    code, text = run("--vectors", str(vectors), "--bindings-dir", str(bindings), "-k", "two")
    assert code == 0 and "1 passed" in text
    assert run("--vectors", str(vectors), "--bindings-dir", str(bindings), "--bindings", "nope")[0] == 2
    assert run("--vectors", str(vectors), "--bindings-dir", str(bindings), "--suite", "nope")[0] == 2


def test_unreadable_suites_exit_two(tmp_path: Path) -> None:
    (tmp_path / "v").mkdir()
    (tmp_path / "v" / "bad.json").write_text("{not json")
    assert run("--vectors", str(tmp_path / "v"), "--command", "true")[0] == 2
    write_suite(tmp_path / "w", [{"id": "x", "kind": "teleport", "input": "", "expect": 0}])
    assert run("--vectors", str(tmp_path / "w"), "--command", "true")[0] == 2
    write_suite(tmp_path / "u", [CHECKSUMS[0], CHECKSUMS[0]])
    assert run("--vectors", str(tmp_path / "u"), "--command", "true")[0] == 2


OPTIONED: list[dict[str, Any]] = [
    {"id": "f/strict", "kind": "frame_decode", "input": "AA 55 01 3C 07 00 01 45 00", "options": {"strict": True},
     "expect": {"error": "bad_reserved", "offset": 3, "field": "reserved"}},
    {"id": "f/lenient", "kind": "frame_decode", "input": "AA 55 01 3C 07 00 01 45 00", "options": {"strict": False},
     "expect": {"reserved": 60}},
    {"id": "s/idle", "kind": "stream", "input": {"chunks": ["AA 55", "00"], "idle": [{"after": 0, "us": 100000}]},
     "options": {"strict": True}, "expect": {"discarded": 3}},
]


def test_options_and_idle_gaps_are_request_tokens() -> None:
    v = H.Vector("t", "a", "stream", {"chunks": ["aa", "55"], "idle": [{"after": 1, "us": 7}, {"after": 0, "us": 9}]},
                 {}, None, {"strict": True})
    assert H.request(v) == "stream AA,55 idle=1:7,0:9 strict"
    assert H.request(H.Vector("t", "a", "frame_decode", "aa", {}, None, {"strict": False})) == "frame_decode AA"
    with pytest.raises(H.SuiteError):  # an idle gap after a chunk that does not exist
        H.request(vector("a", "stream", {"chunks": ["aa"], "idle": [{"after": 1, "us": 7}]}, {}))
    with pytest.raises(H.SuiteError):
        H.request(H.Vector("t", "a", "frame_decode", "aa", {}, None, {"strict": 1}))


def test_a_vector_with_an_unknown_option_fails_and_is_not_sent(tmp_path: Path) -> None:
    unknown: list[dict[str, Any]] = [{"id": "f/x", "kind": "frame_decode", "input": "AA", "options": {"paranoid": True},
                "expect": {"error": "truncated"}},
               {"id": "c/x", "kind": "checksum", "input": "", "options": {"strict": True}, "expect": 0}]
    vectors = write_suite(tmp_path / "v", unknown)
    bindings = register(tmp_path / "b", {"frame_decode AA": "error truncated 1 -", "checksum -": "ok 0"},
                        ["frame_decode", "checksum"])
    code, text = run("--vectors", str(vectors), "--bindings-dir", str(bindings))
    assert code == 1 and "2 FAILED" in text
    assert "option paranoid unknown to this harness" in text and "option strict unknown to this harness" in text


def test_options_a_binding_does_not_list_are_not_supported(tmp_path: Path) -> None:
    vectors = write_suite(tmp_path / "v", OPTIONED)
    table = {"frame_decode AA55013C0700014500 strict": "error bad_reserved 3 reserved",
             "frame_decode AA55013C0700014500": "ok message_type=1 reserved=60 payload=01",
             "stream AA55,00 idle=0:100000 strict": "ok discarded=3 events=-"}
    bindings = register(tmp_path / "b", table, ["frame_decode", "stream"])
    code, text = run("--vectors", str(vectors), "--bindings-dir", str(bindings))
    assert code == 0 and "3 passed" in text
    code, text = run("--vectors", str(vectors), "--bindings-dir", str(bindings), "--options", "-")
    assert code == 0 and "1 passed, 2 n/s" in text
    registration = json.loads((bindings / "fake.json").read_text())
    (bindings / "fake.json").write_text(json.dumps({**registration, "options": []}))
    code, text = run("--vectors", str(vectors), "--bindings-dir", str(bindings))
    assert code == 0 and "1 passed, 2 n/s" in text
    assert run("--vectors", str(vectors), "--bindings-dir", str(bindings), "--options", "paranoid")[0] == 2


# --- the Python runner's own protocol handling ------------------------------------------------------


def test_python_runner_answers_in_protocol_forms() -> None:
    assert RUNNER.answer("checksum 00000700FE") == "ok 261"
    assert RUNNER.answer("frame_decode AA55") == "error truncated 2 -"
    assert RUNNER.answer("teleport x") == "unsupported"
    assert RUNNER.answer("payload_encode acknowledgement - checksum=65536") == "error out_of_range 0 checksum"
    assert RUNNER.answer("stream -") == "ok discarded=0 events=-"
    stale = "AA5501000F00FFFFFFFFFFF6,AA5500000700808700"  # 12 bytes of a frame, then AHRScont1
    assert RUNNER.answer(f"stream {stale} idle=0:99999") == "ok discarded=4 events=F:AA5501000F00FFFFFFFFFFF6AA55000007"
    assert RUNNER.answer(f"stream {stale} idle=0:100000") == "ok discarded=12 events=F:AA5500000700808700"
    assert RUNNER.answer("frame_decode AA55013C0700014500 strict") == "error bad_reserved 3 reserved"
    assert RUNNER.answer("frame_decode AA55013C0700014500") == "ok message_type=1 reserved=60 payload=01"
    assert RUNNER.answer("frame_decode AA55013C0700014500 paranoid").startswith("crash unknown")
    assert RUNNER.answer("stream - idle=0:1 lenient").startswith("crash unknown")


def test_python_runner_walks_the_state_machine() -> None:
    assert RUNNER.answer("session - C:80,E:output_due,E:alignment_done,E:output_due,C:FE") == (
        "ok steps=AHRScont1>aligning_continuous>ack,output_due>aligning_continuous>-,"
        "alignment_done>continuous>initial_alignment,output_due>continuous>output,Stop>idle>-")
    # A data message is the parameter block only in a state expecting a block of its size.
    assert RUNNER.answer("session - D:50,C:40,D:50,C:40,D:22") == (
        "ok steps=other_message>idle>-,LoadAHRSPar>awaiting_parameters>-,parameter_block>idle>ack,"
        "LoadAHRSPar>awaiting_parameters>-,other_message>idle>-")
    # 0xFE is ExitClb in calibration (acknowledged); firmware before 4.9.9.0 finishes 2D-2T on 0x20.
    assert RUNNER.answer("session 4.9.8.0 C:22,D:22,C:20,C:FE") == (
        "ok steps=Start2D2TClb>runs_awaiting_parameters>-,parameter_block>runs_ready>ack,"
        "StopClbRun>calibration_deciding>calibration_result,ExitClb>idle>ack")
    assert RUNNER.answer("session - C:22,D:22,C:20") == (
        "ok steps=Start2D2TClb>runs_awaiting_parameters>-,parameter_block>runs_ready>ack,StopClbRun>runs_ready>-")
    assert RUNNER.answer("session - C:00") == "ok steps=unknown>idle>-"


def test_session_requests_and_comparison() -> None:
    v = vector("a", "session", {"firmware": "4.9.8.0", "events": [
        {"command": "0xFE"}, {"command": 32}, {"data": 6}, {"event": "block_timeout"}]},
        {"steps": [{"event": "Stop"}, {"state": "idle"}, {}, {"send": []}], "state": "idle"})
    assert H.request(v) == "session 4.9.8.0 C:FE,C:20,D:6,E:block_timeout"
    assert H.request(vector("a", "session", {"events": [{"command": "fe"}]}, {})) == "session - C:FE"
    good = "ok steps=Stop>idle>-,StopClbRun>idle>-,other_message>idle>-,block_timeout>idle>-"
    assert check(v, good) is None
    assert check(v, good.replace("Stop>", "ExitClb>", 1)) == "step 0: event ExitClb, expected Stop"
    assert check(v, good.replace("block_timeout>idle>-", "block_timeout>idle>ack")) == (
        "step 3: send ['ack'], expected []")
    assert check(v, good.replace(",block_timeout>idle>-", "")) == "3 steps, expected 4"
    assert check(v, good.replace("block_timeout>idle", "block_timeout>sleep")) == "final state sleep, expected idle"
    assert check(v, "ok steps=Stop>idle") == "step 'Stop>idle' is not EVENT>STATE>SENDS"
    bad: dict[str, Any]
    for bad in ({"events": []}, {"events": [{"command": 256}]}, {"events": [{"teleport": 1}]},
                {"firmware": "new", "events": [{"data": 1}]}, {"events": [{"command": 1, "data": 2}]}):
        with pytest.raises(H.SuiteError):
            H.request(vector("a", "session", bad, {}))
