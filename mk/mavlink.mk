# MAVLink beside us: our C stream decoder next to MAVLink's mavlink_parse_char() (bench/mavlink/).
#
#   make bench-mavlink   throughput fed whole and a byte at a time, instructions per byte (callgrind,
#                        -Os and -O2) and Cortex-M4 text and RAM of each decoder, ours / theirs
#   make test-mavlink    the same harness on 256 KiB captures, its report checked for every figure
#                        and for the decoders' message counts (tests/mavlink/check_report.py; no timing)
#   make lint-mavlink    ruff and mypy on bench/mavlink/*.py
#
# MAVLink is not kept here: pymavlink (bench/mavlink/requirements.txt, pinned) is installed into
# .venv, bench/mavlink/dialect.py writes a small dialect from the definitions it ships, and its own
# generator (mavgen, C, MAVLink 2) writes the C library into build/mavlink/c. valgrind and
# arm-none-eabi-gcc are installed with apt when missing.

MAV_OUT := $(BUILD)/mavlink
MAV_STAMP := $(VENV)/.mavlink-stamp
MAV_DIALECT := $(MAV_OUT)/bench.xml
MAV_LIB := $(MAV_OUT)/c/bench/mavlink.h
MAV_SRC := bench/mavlink/bench_mavlink.c bench/mavlink/mix.c bench/mavlink/ours.c \
           bench/mavlink/theirs_capture.c bench/mavlink/theirs_decode.c
MAV_DEPS := $(MAV_SRC) $(wildcard bench/mavlink/*.h) generated/c/ilahrs.c generated/c/ilahrs.h $(MAV_LIB)
# Our files at the C binding's warning flags; MAVLink's headers as system headers. MAVLink as one
# channel without signing, its smallest decoder.
MAV_CFLAGS := -std=c99 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror -Igenerated/c -Ibench/mavlink \
              -isystem $(MAV_OUT)/c/bench -DMAVLINK_COMM_NUM_BUFFERS=1 -DMAVLINK_NO_SIGNATURE_CHECK \
              -DMAVLINK_NO_SIGN_PACKET
# -Os as a Cortex-M firmware builds: ilahrs.c's size-optimized decoder (its default on 32-bit targets).
MAV_OS := -Os
MAV_O2 := -O2
MAV_ARM_CC ?= arm-none-eabi-gcc
MAV_ARM_FLAGS := -std=c99 -mcpu=cortex-m4 -mthumb -Os -ffunction-sections -fdata-sections


MAV_COMPARE = $(PY) bench/mavlink/compare.py --bench-o2 $(MAV_OUT)/bench_o2 --bench-os $(MAV_OUT)/bench_os \
	--ilahrs generated/c --mavlink $(MAV_OUT)/c/bench --cc $(MAV_ARM_CC) --flags "$(MAV_ARM_FLAGS)"

BENCH_TARGETS += bench-mavlink
TEST_TARGETS += test-mavlink
LINT_TARGETS += lint-mavlink

.PHONY: setup-mavlink bench-mavlink test-mavlink lint-mavlink

$(MAV_STAMP): bench/mavlink/requirements.txt $(VENV)/.stamp
	$(PIP) install --quiet --disable-pip-version-check -r bench/mavlink/requirements.txt
	touch $@

setup-mavlink: $(MAV_STAMP)
	@command -v valgrind >/dev/null || tools/need valgrind
	@command -v $(MAV_ARM_CC) >/dev/null || tools/need --tool $(MAV_ARM_CC) gcc-arm-none-eabi libnewlib-arm-none-eabi

$(MAV_DIALECT): bench/mavlink/dialect.py $(MAV_STAMP)
	@mkdir -p $(@D)
	$(PY) bench/mavlink/dialect.py $@

$(MAV_LIB): $(MAV_DIALECT)
	@rm -rf $(MAV_OUT)/c
	$(VENV)/bin/mavgen.py --lang C --wire-protocol 2.0 -o $(MAV_OUT)/c $< >/dev/null

$(MAV_OUT)/bench_o2 $(MAV_OUT)/bench_os: $(MAV_DEPS)
	gcc $(MAV_CFLAGS) $(if $(findstring _os,$@),$(MAV_OS),$(MAV_O2)) \
		-DBENCH_BUILD='"gcc $(if $(findstring _os,$@),$(MAV_OS),$(MAV_O2))"' $(MAV_SRC) generated/c/ilahrs.c -o $@

bench-mavlink: setup-mavlink $(MAV_OUT)/bench_o2 $(MAV_OUT)/bench_os
	$(MAV_COMPARE) --out $(MAV_OUT) | tee $(MAV_OUT)/report.txt

test-mavlink: setup-mavlink $(MAV_OUT)/bench_o2 $(MAV_OUT)/bench_os
	@mkdir -p $(MAV_OUT)/smoke
	$(MAV_COMPARE) --out $(MAV_OUT)/smoke --size 262144 --callgrind-size 262144 | tee $(MAV_OUT)/smoke/report.txt \
		| $(PY) tests/mavlink/check_report.py

# bench/mavlink is outside the Python lint paths of mk/python.mk (tests/mavlink is inside them).
lint-mavlink: setup
	$(VENV)/bin/ruff check bench/mavlink
	$(VENV)/bin/ruff format --check bench/mavlink
	$(VENV)/bin/mypy bench/mavlink
